#pragma once
// Writing files so that a reader never sees half of one: write a temporary beside the target, fsync,
// then rename over it. A crash leaves either the old file or the new one.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "util/result.h"

namespace villa {

// Writes `content` to `path` atomically (temporary file in the same folder, fsync, rename). Only a missing
// path or a regular file is replaced: a folder, a device (/dev/null), a pipe or a symbolic link at `path` is
// an error naming it, and nothing is written.
Status WriteFileAtomic(const std::filesystem::path& path, std::string_view content);

// What a reader may read (issue 33): a regular file (a FIFO would block, /dev/zero never ends, a folder
// reads as empty) of at most `max_bytes`. The error names the file and what it is: "x.json: a FIFO, not a
// regular file", "x.glb: 3.2 GB, more than the 1 GB this reader takes".
inline constexpr std::uintmax_t kReadCap = std::uintmax_t{1} << 30;  // 1 GiB
Status CheckReadable(const std::filesystem::path& path, std::uintmax_t max_bytes = kReadCap);

// Reads a whole file (CheckReadable first); the error names the file.
Result<std::string> ReadFile(const std::filesystem::path& path, std::uintmax_t max_bytes = kReadCap);

// A file written piece by piece (a JSONL stream) that appears under its final name only on Commit().
// Destroying it without Commit() removes the temporary.
class AtomicFileWriter {
 public:
  explicit AtomicFileWriter(std::filesystem::path path);
  ~AtomicFileWriter();
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

  bool ok() const { return file_ != nullptr; }
  const std::string& error() const { return error_; }
  void Write(std::string_view data);
  Status Commit();

 private:
  std::filesystem::path path_;
  std::filesystem::path temp_;
  std::FILE* file_ = nullptr;
  std::string error_;
};

}  // namespace villa
