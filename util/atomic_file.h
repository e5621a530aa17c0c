#pragma once
// Writing files so that a reader never sees half of one: write a temporary beside the target, fsync,
// then rename over it. A crash leaves either the old file or the new one.
#include <filesystem>
#include <string>
#include <string_view>

#include "util/result.h"

namespace villa {

// Writes `content` to `path` atomically (temporary file in the same folder, fsync, rename). Only a missing
// path or a regular file is replaced: a folder, a device (/dev/null), a pipe or a symbolic link at `path` is
// an error naming it, and nothing is written.
Status WriteFileAtomic(const std::filesystem::path& path, std::string_view content);

// Reads a whole file; the error names the file.
Result<std::string> ReadFile(const std::filesystem::path& path);

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
