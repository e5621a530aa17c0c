#include "util/folder_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace villa {

Result<std::unique_ptr<FolderLock>> FolderLock::Take(const std::filesystem::path& dir) {
  const std::filesystem::path path = dir / kFileName;
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) return Error{path.string() + ": cannot open the lock file (is the folder writable?)"};
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd);
    return Error{"busy: " + dir.string() + ": another villa run is writing into this folder now"};
  }
  return std::unique_ptr<FolderLock>(new FolderLock(fd));
}

bool FolderLock::HeldElsewhere(const std::filesystem::path& dir) {
  const int fd = ::open((dir / kFileName).c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool held = ::flock(fd, LOCK_EX | LOCK_NB) != 0;
  ::close(fd);
  return held;
}

FolderLock::~FolderLock() {
  if (fd_ >= 0) ::close(fd_);
}

}  // namespace villa
