#pragma once
// An exclusive, non-blocking lock on a folder (flock on DIR/.villa.lock), held while the object lives: two
// runs writing one output folder (a resubmitted cluster task while the first still runs, two `villa
// furnish` into one DIR) cannot interleave; the second is refused. The kernel drops it when the process
// dies, so a killed run leaves no stale lock.
#include <filesystem>
#include <memory>

#include "util/result.h"

namespace villa {

class FolderLock {
 public:
  // Takes the lock of `dir` (which must exist); an error starting "busy: " when another process holds it.
  static Result<std::unique_ptr<FolderLock>> Take(const std::filesystem::path& dir);
  // Whether another process holds `dir`'s lock now (a probe: nothing is held afterwards).
  static bool HeldElsewhere(const std::filesystem::path& dir);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

  static constexpr const char* kFileName = ".villa.lock";

 private:
  explicit FolderLock(int fd) : fd_(fd) {}
  int fd_ = -1;
};

}  // namespace villa
