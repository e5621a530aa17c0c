#include "assets/zip_archive.h"

#include <algorithm>
#include <cctype>

#include <zlib.h>

#include "util/atomic_file.h"

namespace villa {
namespace {

constexpr std::uint32_t kEndOfCentralDirectory = 0x06054b50;
constexpr std::uint32_t kCentralHeader = 0x02014b50;
constexpr std::uint32_t kLocalHeader = 0x04034b50;
constexpr std::size_t kEndRecordSize = 22;
// An entry may not claim more than this once inflated: a guard against zip bombs and corrupt sizes.
constexpr std::uint64_t kMaxEntrySize = std::uint64_t{1} << 31;

std::uint32_t U16(const std::string& b, std::size_t at) {
  return static_cast<std::uint32_t>(static_cast<unsigned char>(b[at])) |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 1])) << 8;
}
std::uint32_t U32(const std::string& b, std::size_t at) { return U16(b, at) | U16(b, at + 2) << 16; }

std::string StripSlash(std::string_view name) {
  while (!name.empty() && name.front() == '/') name.remove_prefix(1);
  return std::string(name);
}

bool EqualIgnoringCase(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

}  // namespace

std::uint32_t ZipCrc32(std::string_view data) {
  uLong crc = crc32(0L, Z_NULL, 0);
  // zlib takes uInt lengths: feed large inputs in pieces.
  while (!data.empty()) {
    std::size_t n = std::min<std::size_t>(data.size(), 1u << 30);
    crc = crc32(crc, reinterpret_cast<const Bytef*>(data.data()), static_cast<uInt>(n));
    data.remove_prefix(n);
  }
  return static_cast<std::uint32_t>(crc);
}

Result<ZipArchive> ZipArchive::Open(const std::filesystem::path& path) {
  Result<std::string> bytes = ReadFile(path);
  if (!bytes.ok()) return Error{bytes.error()};
  return FromBytes(std::move(*bytes), path.string());
}

Result<ZipArchive> ZipArchive::FromBytes(std::string bytes, std::string name) {
  auto fail = [&](const std::string& what) { return Error{name + ": not a readable zip archive: " + what}; };
  if (bytes.size() < kEndRecordSize) return fail("only " + std::to_string(bytes.size()) + " bytes");
  // The end record sits at the end, followed by a comment of at most 65535 bytes.
  std::size_t lowest = bytes.size() > kEndRecordSize + 65535 ? bytes.size() - kEndRecordSize - 65535 : 0;
  std::size_t end = std::string::npos;
  for (std::size_t at = bytes.size() - kEndRecordSize + 1; at-- > lowest;) {
    if (U32(bytes, at) == kEndOfCentralDirectory && at + kEndRecordSize + U16(bytes, at + 20) == bytes.size()) {
      end = at;
      break;
    }
  }
  if (end == std::string::npos) return fail("no end-of-central-directory record");
  if (U16(bytes, end + 4) != 0 || U16(bytes, end + 6) != 0) return fail("split across several disks");
  std::uint32_t count = U16(bytes, end + 10);
  std::uint64_t directory_size = U32(bytes, end + 12);
  std::uint64_t directory_offset = U32(bytes, end + 16);
  if (count == 0xFFFF || directory_offset == 0xFFFFFFFFu) return fail("zip64 archives are not supported");
  if (directory_offset + directory_size > end) return fail("central directory runs past its end record");

  ZipArchive archive;
  archive.name_ = std::move(name);
  archive.entries_.reserve(count);
  std::size_t at = directory_offset;
  for (std::uint32_t i = 0; i < count; ++i) {
    if (at + 46 > end || U32(bytes, at) != kCentralHeader)
      return fail("central directory entry " + std::to_string(i) + " is damaged");
    ZipEntry entry;
    entry.flags = static_cast<std::uint16_t>(U16(bytes, at + 8));
    entry.method = static_cast<std::uint16_t>(U16(bytes, at + 10));
    entry.crc32 = U32(bytes, at + 16);
    entry.compressed_size = U32(bytes, at + 20);
    entry.size = U32(bytes, at + 24);
    std::size_t name_length = U16(bytes, at + 28);
    std::size_t extra_length = U16(bytes, at + 30);
    std::size_t comment_length = U16(bytes, at + 32);
    entry.local_header_offset = U32(bytes, at + 42);
    if (at + 46 + name_length + extra_length + comment_length > end)
      return fail("central directory entry " + std::to_string(i) + " runs past the directory");
    entry.name = bytes.substr(at + 46, name_length);
    if (entry.size == 0xFFFFFFFFu || entry.compressed_size == 0xFFFFFFFFu || entry.local_header_offset == 0xFFFFFFFFu)
      return fail(entry.name + ": zip64 entries are not supported");
    at += 46 + name_length + extra_length + comment_length;
    archive.entries_.push_back(std::move(entry));
  }
  archive.bytes_ = std::make_shared<const std::string>(std::move(bytes));
  return archive;
}

const ZipEntry* ZipArchive::Find(std::string_view name) const {
  std::string wanted = StripSlash(name);
  for (const ZipEntry& e : entries_)
    if (e.name == wanted) return &e;
  return nullptr;
}

const ZipEntry* ZipArchive::FindIgnoringCase(std::string_view name) const {
  if (const ZipEntry* exact = Find(name)) return exact;
  std::string wanted = StripSlash(name);
  for (const ZipEntry& e : entries_)
    if (EqualIgnoringCase(e.name, wanted)) return &e;
  return nullptr;
}

Result<std::string> ZipArchive::Read(std::string_view name) const {
  const ZipEntry* entry = Find(name);
  if (!entry) return Error{name_ + ": " + StripSlash(name) + ": no such entry"};
  return Read(*entry);
}

Result<std::string> ZipArchive::Read(const ZipEntry& entry) const {
  auto fail = [&](const std::string& what) { return Error{name_ + ": " + entry.name + ": " + what}; };
  const std::string& b = *bytes_;
  if (entry.flags & 1u) return fail("encrypted entries are not supported");
  if (entry.size > kMaxEntrySize) return fail("declares " + std::to_string(entry.size) + " bytes, more than allowed");
  std::uint64_t at = entry.local_header_offset;
  if (at + 30 > b.size() || U32(b, at) != kLocalHeader) return fail("local header missing or damaged");
  std::uint64_t data = at + 30 + U16(b, at + 26) + U16(b, at + 28);
  if (data + entry.compressed_size > b.size()) return fail("data runs past the end of the archive");
  std::string_view packed(b.data() + data, entry.compressed_size);

  std::string out;
  if (entry.method == 0) {
    if (entry.compressed_size != entry.size) return fail("stored entry with different packed and unpacked sizes");
    out.assign(packed);
  } else if (entry.method == 8) {
    out.resize(entry.size);
    z_stream z{};
    if (inflateInit2(&z, -MAX_WBITS) != Z_OK) return fail("zlib could not start inflating");
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(packed.data()));
    z.avail_in = static_cast<uInt>(packed.size());
    z.next_out = reinterpret_cast<Bytef*>(out.data());
    z.avail_out = static_cast<uInt>(out.size());
    int rc = inflate(&z, Z_FINISH);
    std::uint64_t produced = z.total_out;
    inflateEnd(&z);
    if (rc != Z_STREAM_END) {
      std::string why = rc == Z_DATA_ERROR ? "corrupt deflate data" : rc == Z_BUF_ERROR ? "deflate data longer or shorter than declared"
                                                                                      : "inflate failed (zlib code " + std::to_string(rc) + ")";
      return fail(why);
    }
    if (produced != entry.size) return fail("inflated to " + std::to_string(produced) + " bytes, declared " + std::to_string(entry.size));
  } else {
    return fail("compression method " + std::to_string(entry.method) + " is not supported (only stored and deflated)");
  }
  if (ZipCrc32(out) != entry.crc32) return fail("CRC-32 mismatch (the archive is damaged)");
  return out;
}

}  // namespace villa
