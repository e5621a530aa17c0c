#pragma once
// Reading zip archives (Sweet Home 3D's .sh3f furniture libraries are zip files): the central directory,
// and entries stored or deflated (raw deflate through zlib), checked against their CRC-32. Zip64, split
// archives and encrypted entries are refused with a message naming the archive and the entry.
//
// The archive is read into memory once; reading entries is const and safe from several threads.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "util/result.h"

namespace villa {

struct ZipEntry {
  std::string name;                 // path inside the archive, '/' separated, as stored
  std::uint16_t method = 0;         // 0 stored, 8 deflated (others are refused on Read)
  std::uint16_t flags = 0;          // general-purpose bits (bit 0: encrypted)
  std::uint32_t crc32 = 0;
  std::uint64_t compressed_size = 0;
  std::uint64_t size = 0;           // uncompressed, bytes
  std::uint64_t local_header_offset = 0;
  bool IsDirectory() const { return !name.empty() && name.back() == '/'; }
};

class ZipArchive {
 public:
  // Reads the file and its central directory. The error names the file and what is wrong with it.
  static Result<ZipArchive> Open(const std::filesystem::path& path);
  // An archive held in memory (`name` is used in messages).
  static Result<ZipArchive> FromBytes(std::string bytes, std::string name);

  const std::string& name() const { return name_; }
  const std::vector<ZipEntry>& entries() const { return entries_; }
  // By exact name; a leading '/' is ignored. nullptr when absent.
  const ZipEntry* Find(std::string_view name) const;
  // The same, ignoring ASCII case (model files name their textures with the wrong case now and then).
  const ZipEntry* FindIgnoringCase(std::string_view name) const;

  // The uncompressed bytes of an entry. Errors read "<archive>: <entry>: <problem>".
  Result<std::string> Read(const ZipEntry& entry) const;
  Result<std::string> Read(std::string_view name) const;

 private:
  std::string name_;
  std::shared_ptr<const std::string> bytes_;
  std::vector<ZipEntry> entries_;
};

// The zip format's CRC-32 (zlib's), for tests that write archives.
std::uint32_t ZipCrc32(std::string_view data);

}  // namespace villa
