// All-or-nothing outputs: a run's files appear together or not at all, a killed run is finished or
// discarded by the next, and two runs cannot write one folder at once.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>

#include "util/atomic_file.h"
#include "util/staged_output.h"
#include "util/utf8.h"

using namespace villa;
namespace fs = std::filesystem;

TEST_CASE("staged outputs move into place together, under a lock, and a killed run is finished or discarded", "[staged]") {
  const fs::path dir = fs::temp_directory_path() / ("villa_staged_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  {
    auto stage = StagedOutput::Open(dir);
    REQUIRE(stage.ok());
    // A second writer is refused while the first holds the folder.
    auto second = StagedOutput::Open(dir);
    REQUIRE_FALSE(second.ok());
    CHECK(second.error() == "busy: " + dir.string() + ": another villa run is writing into this folder now");
    REQUIRE(WriteFileAtomic((*stage)->path() / "a.txt", "new a").ok());
    fs::create_directories((*stage)->path() / "rooms");
    REQUIRE(WriteFileAtomic((*stage)->path() / "rooms/r.png", "new r").ok());
    CHECK_FALSE(fs::exists(dir / "a.txt"));  // nothing in place before the commit
    REQUIRE((*stage)->Commit({"a.txt", "rooms"}).ok());
    CHECK(*ReadFile(dir / "a.txt") == "new a");
    CHECK(*ReadFile(dir / "rooms/r.png") == "new r");
    CHECK_FALSE(fs::exists(dir / StagedOutput::kStagingName));
  }
  {
    // A run that fails before its commit leaves the folder as it was.
    auto stage = StagedOutput::Open(dir);
    REQUIRE(stage.ok());
    REQUIRE(WriteFileAtomic((*stage)->path() / "a.txt", "half").ok());
  }
  CHECK(*ReadFile(dir / "a.txt") == "new a");
  CHECK_FALSE(fs::exists(dir / StagedOutput::kStagingName));
  // A run killed before its marker: its staging folder is discarded by the next run.
  const fs::path staging = dir / StagedOutput::kStagingName;
  fs::create_directories(staging);
  REQUIRE(WriteFileAtomic(staging / "a.txt", "killed early").ok());
  REQUIRE(StagedOutput::Open(dir).ok());
  CHECK(*ReadFile(dir / "a.txt") == "new a");
  // A run killed after its marker, with one file moved: the next run finishes the move.
  fs::create_directories(staging / "rooms");
  REQUIRE(WriteFileAtomic(staging / "rooms/r.png", "killed late r").ok());
  REQUIRE(WriteFileAtomic(staging / ".commit", "a.txt\nrooms\n").ok());
  REQUIRE(WriteFileAtomic(dir / "a.txt", "killed late a").ok());  // moved before the kill
  REQUIRE(StagedOutput::Open(dir).ok());
  CHECK(*ReadFile(dir / "a.txt") == "killed late a");
  CHECK(*ReadFile(dir / "rooms/r.png") == "killed late r");
  fs::remove_all(dir);
}

TEST_CASE("UTF-8 is checked byte by byte", "[utf8]") {
  CHECK_FALSE(FirstInvalidUtf8("a cosy living room, café, 居间").has_value());
  CHECK(FirstInvalidUtf8("ab\xff") == std::optional<std::size_t>(2));
  CHECK(FirstInvalidUtf8("a\xc0\xaf") == std::optional<std::size_t>(1));      // overlong '/'
  CHECK(FirstInvalidUtf8("\xed\xa0\x80") == std::optional<std::size_t>(0));   // a surrogate
  CHECK(FirstInvalidUtf8("ok\xe2\x82") == std::optional<std::size_t>(2));     // cut short
}
