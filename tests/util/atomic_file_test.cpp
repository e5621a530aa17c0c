// Atomic writes replace regular files only: a device, pipe, folder or link at the target stays as it was.
#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "util/atomic_file.h"

using namespace villa;
namespace fs = std::filesystem;

namespace {

struct TempDir {
  fs::path path;
  TempDir() {
    std::string pattern = (fs::temp_directory_path() / "villa-atomic-XXXXXX").string();
    REQUIRE(mkdtemp(pattern.data()) != nullptr);
    path = pattern;
  }
  ~TempDir() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

// No temporary is left beside the target.
int FilesIn(const fs::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++n;
  return n;
}

}  // namespace

TEST_CASE("an atomic write replaces a regular file whole and creates a missing one", "[util][atomic]") {
  TempDir dir;
  const fs::path file = dir.path / "out.txt";
  REQUIRE(WriteFileAtomic(file, "first").ok());
  REQUIRE(WriteFileAtomic(file, "second").ok());
  CHECK(*ReadFile(file) == "second");
  CHECK(FilesIn(dir.path) == 1);
}

TEST_CASE("an atomic write refuses to replace a named pipe, naming it", "[util][atomic]") {
  TempDir dir;
  const fs::path pipe = dir.path / "pipe";
  REQUIRE(mkfifo(pipe.c_str(), 0600) == 0);
  Status s = WriteFileAtomic(pipe, "data");
  REQUIRE_FALSE(s.ok());
  CHECK(s.error() == pipe.string() + ": is a named pipe, not a regular file: refusing to replace it");
  CHECK(fs::is_fifo(fs::symlink_status(pipe)));
  CHECK(FilesIn(dir.path) == 1);
}

TEST_CASE("an atomic write refuses to replace a symbolic link or a folder", "[util][atomic]") {
  TempDir dir;
  const fs::path target = dir.path / "target.txt";
  REQUIRE(WriteFileAtomic(target, "kept").ok());
  const fs::path link = dir.path / "link.txt";
  fs::create_symlink(target, link);
  Status s = WriteFileAtomic(link, "new");
  REQUIRE_FALSE(s.ok());
  CHECK(s.error().find(link.string() + ": is a symbolic link") == 0);
  CHECK(fs::is_symlink(fs::symlink_status(link)));
  CHECK(*ReadFile(target) == "kept");

  const fs::path folder = dir.path / "folder";
  fs::create_directory(folder);
  AtomicFileWriter writer(folder);
  CHECK_FALSE(writer.ok());
  CHECK(writer.error() == folder.string() + ": is a folder, not a regular file: refusing to replace it");
  CHECK(fs::is_directory(folder));
  CHECK(FilesIn(dir.path) == 3);
}

TEST_CASE("readers take regular files only, up to a size, and say what they found instead", "[issue33]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("villa_read_cap_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "folder");
  REQUIRE(::mkfifo((dir / "fifo").c_str(), 0644) == 0);
  REQUIRE(WriteFileAtomic(dir / "ten.txt", "0123456789").ok());
  CHECK(CheckReadable(dir / "fifo").error() == (dir / "fifo").string() + ": a FIFO, not a regular file");  // no hang
  CHECK(CheckReadable(dir / "folder").error() == (dir / "folder").string() + ": a folder, not a regular file");
  CHECK(CheckReadable("/dev/zero").error() == "/dev/zero: a character device, not a regular file");
  CHECK(CheckReadable(dir / "none").error() == (dir / "none").string() + ": no such file");
  CHECK(ReadFile(dir / "ten.txt", 9).error() == (dir / "ten.txt").string() + ": 10 bytes, more than the 9 bytes this reader takes");
  CHECK(*ReadFile(dir / "ten.txt", 10) == "0123456789");
  fs::remove_all(dir);
}
