#include "scene/file_digest.h"

#include <openssl/evp.h>

#include "util/atomic_file.h"

namespace villa::scene {

std::string Sha256Hex(std::string_view bytes) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  // EVP_Digest is one call: context, update and final inside; it fails only when out of memory.
  if (EVP_Digest(bytes.data(), bytes.size(), digest, &length, EVP_sha256(), nullptr) != 1) return "";
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  out.reserve(2 * length);
  for (unsigned int i = 0; i < length; ++i) {
    out.push_back(kHex[digest[i] >> 4]);
    out.push_back(kHex[digest[i] & 15]);
  }
  return out;
}

Result<std::string> FileSha256(const std::filesystem::path& path) {
  auto bytes = ReadFile(path);
  if (!bytes) return Error{bytes.error()};
  std::string hex = Sha256Hex(*bytes);
  if (hex.empty()) return Error{path.string() + ": SHA-256 failed (out of memory?)"};
  return hex;
}

}  // namespace villa::scene
