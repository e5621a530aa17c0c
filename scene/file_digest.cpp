#include "scene/file_digest.h"

#include <openssl/evp.h>

#include <fstream>
#include <limits>
#include <memory>
#include <vector>

#include "util/atomic_file.h"

namespace villa::scene {

namespace {
std::string Hex(const unsigned char* digest, unsigned int length) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  out.reserve(2 * length);
  for (unsigned int i = 0; i < length; ++i) {
    out.push_back(kHex[digest[i] >> 4]);
    out.push_back(kHex[digest[i] & 15]);
  }
  return out;
}
}  // namespace

std::string Sha256Hex(std::string_view bytes) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  // EVP_Digest is one call: context, update and final inside; it fails only when out of memory.
  if (EVP_Digest(bytes.data(), bytes.size(), digest, &length, EVP_sha256(), nullptr) != 1) return "";
  return Hex(digest, length);
}

Result<std::string> FileSha256(const std::filesystem::path& path) {
  // Streamed (a dataset's files run to gigabytes): a regular file of any size.
  if (Status s = CheckReadable(path, std::numeric_limits<std::uintmax_t>::max()); !s) return Error{s.error()};
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{path.string() + ": cannot open"};
  std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> ctx(EVP_MD_CTX_new(), EVP_MD_CTX_free);
  if (!ctx || EVP_DigestInit_ex(ctx.get(), EVP_sha256(), nullptr) != 1) return Error{path.string() + ": SHA-256 failed (out of memory?)"};
  std::vector<char> buffer(1 << 20);
  while (in) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    if (in.gcount() > 0 && EVP_DigestUpdate(ctx.get(), buffer.data(), static_cast<size_t>(in.gcount())) != 1)
      return Error{path.string() + ": SHA-256 failed"};
  }
  if (in.bad()) return Error{path.string() + ": read error"};
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  if (EVP_DigestFinal_ex(ctx.get(), digest, &length) != 1) return Error{path.string() + ": SHA-256 failed"};
  return Hex(digest, length);
}

}  // namespace villa::scene
