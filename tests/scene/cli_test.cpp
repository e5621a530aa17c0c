#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "assets/procedural.h"
#include "layout/layout_io.h"
#include "scene/file_digest.h"
#include "scene/scene.h"
#include "scene/validate.h"
#include "villa_cli.h"

using namespace villa;
using namespace villa::scene;
namespace fs = std::filesystem;

namespace {

using Run = testing::CliRun;
Run Villa(const std::string& args) { return testing::RunVilla(args); }

std::string Quote(const std::string& s) { return "'" + s + "'"; }

struct TempDir {
  fs::path path = fs::temp_directory_path() / ("villa_scene_cli_" + std::to_string(::getpid()));
  TempDir() {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
};

const std::string kExample = std::string(VILLA_SOURCE_DIR) + "/examples/l-shaped-house.json";

}  // namespace

TEST_CASE("villa scene plan writes a plan that reads back, validates and names its layout", "[scene][cli]") {
  TempDir dir;
  fs::path out = dir.path / "graph.json";
  Run run = Villa("scene plan " + kExample + " --room living-room_0/0 --seed 4 --procedural --text " +
                  Quote("two armchairs and bookshelves full of books") + " -o " + out.string());
  INFO(run.out);
  REQUIRE(run.status == 0);
  CHECK(run.out.find("living-room_0/0 (living-room, 49.0 m2") != std::string::npos);
  CHECK(run.out.find("armchair-1") != std::string::npos);
  CHECK(run.out.find("procedural assets only") != std::string::npos);
  auto scene = ReadScene(out);
  REQUIRE(scene.ok());
  REQUIRE(scene->rooms.size() == 1);
  REQUIRE(scene->rooms[0].plan);
  CHECK(scene->rooms[0].plan->planner == "priors");
  CHECK(scene->rooms[0].plan->seed == 4);
  CHECK(scene->rooms[0].plan->text == "two armchairs and bookshelves full of books");
  CHECK(scene->objects.size() >= 22);
  // Every object has an asset (procedural here: --procedural), whose size it carries; no poses yet.
  for (const SceneObject& o : scene->objects) {
    INFO(o.id);
    REQUIRE(o.asset.rfind("proc:", 0) == 0);
    auto made = MakeProceduralAsset(o.asset);
    REQUIRE(made.ok());
    CHECK(made->record.category == o.category);
    CHECK(o.size == made->record.size);
    CHECK_FALSE(o.pose);
  }
  CHECK_FALSE(scene->library);
  // The layout by a path relative to the plan's folder, with its hash.
  CHECK(fs::weakly_canonical(dir.path / scene->layout.file) == fs::weakly_canonical(kExample));
  CHECK(scene->layout.sha256 == *FileSha256(kExample));
  auto layout = LoadLayout(kExample);
  REQUIRE(layout.ok());
  ValidateOptions plan;
  plan.all_rooms = false;
  CHECK(ValidateScene(*scene, *layout, nullptr, plan).empty());
  std::vector<AssetRecord> records;
  for (const SceneObject& o : scene->objects) records.push_back(MakeProceduralAsset(o.asset)->record);
  const AssetLookup lookup = [&](std::string_view id) -> const AssetRecord* {
    for (const AssetRecord& r : records)
      if (r.id == id) return &r;
    return nullptr;
  };
  CHECK(ValidateScene(*scene, *layout, lookup, plan).empty());

  // The same seed writes the same bytes.
  fs::path again = dir.path / "again.json";
  REQUIRE(Villa("scene plan " + kExample + " --room living-room_0/0 --seed 4 --procedural --text " +
                Quote("two armchairs and bookshelves full of books") + " -q -o " + again.string())
              .status == 0);
  std::ifstream a(out), b(again);
  CHECK(std::string((std::istreambuf_iterator<char>(a)), {}) == std::string((std::istreambuf_iterator<char>(b)), {}));
}

TEST_CASE("villa scene plan: usage errors exit 2, bad layouts exit 1, nothing is overwritten", "[scene][cli]") {
  TempDir dir;
  fs::path out = dir.path / "graph.json";
  Run unknown = Villa("scene plan " + kExample + " --room garage_0/0 -o " + out.string());
  CHECK(unknown.status == 2);
  CHECK(unknown.out.find("--room garage_0/0: no such room") != std::string::npos);
  CHECK(unknown.out.find("living-room_0/0") != std::string::npos);
  CHECK_FALSE(fs::exists(out));
  Run missing = Villa("scene plan " + (dir.path / "nope.json").string() + " --room living-room_0/0 -o " + out.string());
  CHECK(missing.status == 2);
  CHECK(missing.out.find("nope.json: no such file") != std::string::npos);
  CHECK(Villa("scene plan " + kExample + " -o " + out.string()).status == 2);  // --room is required
  CHECK(Villa("scene plan " + kExample + " --room living-room_0/0 --seed x -o " + out.string()).status == 2);
  CHECK(Villa("scene plan " + kExample + " --room living-room_0/0 --floor-share 2 -o " + out.string()).status == 2);

  // An existing output stays unless --force.
  { std::ofstream(out) << "mine"; }
  Run exists = Villa("scene plan " + kExample + " --room living-room_0/0 -o " + out.string());
  CHECK(exists.status == 2);
  CHECK(exists.out.find("--force") != std::string::npos);
  std::ifstream kept(out);
  CHECK(std::string((std::istreambuf_iterator<char>(kept)), {}) == "mine");
  CHECK(Villa("scene plan " + kExample + " --room living-room_0/0 --force -q -o " + out.string()).status == 0);
  CHECK(ReadScene(out).ok());

  // A layout breaking the geometric rules is refused (exit 1), and one that does not parse names its path.
  fs::path broken = fs::path(VILLA_FIXTURE_DIR) / "layouts/rule3_door_off_boundary.json";
  fs::path other = dir.path / "other.json";
  Run invalid = Villa("scene plan " + broken.string() + " --room living-room_0/0 -o " + other.string());
  CHECK(invalid.status == 1);
  CHECK(invalid.out.find("rule 3") != std::string::npos);
  CHECK_FALSE(fs::exists(other));
  fs::path garbage = dir.path / "garbage.json";
  { std::ofstream(garbage) << "{\"rooms\": 3}"; }
  Run unreadable = Villa("scene plan " + garbage.string() + " --room living-room_0/0 -o " + other.string());
  CHECK(unreadable.status == 1);
  CHECK(unreadable.out.find(garbage.string()) != std::string::npos);
  CHECK_FALSE(fs::exists(other));

  // A request that is not UTF-8 is planned and written (the bad bytes replaced), not a crash.
  Run latin1 = Villa("scene plan " + kExample + " --room living-room_0/0 -q --text " + Quote("two armchairs \xe9t\xe9") +
                     " -o " + other.string());
  CHECK(latin1.status == 0);
  auto written = ReadScene(other);
  REQUIRE(written.ok());
  CHECK(written->rooms[0].plan->text.find("\xef\xbf\xbd") != std::string::npos);

  // A --library that holds no library is a failure naming the folder; nothing is written.
  fs::path third = dir.path / "third.json";
  Run no_library = Villa("scene plan " + kExample + " --room living-room_0/0 --library " + (dir.path / "empty").string() +
                         " -o " + third.string());
  CHECK(no_library.status == 1);
  CHECK(no_library.out.find((dir.path / "empty").string()) != std::string::npos);
  CHECK_FALSE(fs::exists(third));

  Run help = Villa("scene plan --help");
  CHECK(help.status == 0);
  CHECK(help.out.find("--text") != std::string::npos);
}
