#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "building/export.h"
#include "layout/layout_io.h"
#include "test_layouts.h"

using namespace villa;
namespace fs = std::filesystem;

namespace {

int Villa(const std::string& args) {
  int status = std::system((std::string(VILLA_BINARY) + " " + args + " > /dev/null 2>&1").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string Slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

}  // namespace

TEST_CASE("villa build writes the .glb and the preview, refuses to overwrite without --force") {
  fs::path dir = fs::temp_directory_path() / ("villa_build_cli_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::path layout = dir / "layout.json";
  std::ofstream(layout) << testing::kThreeFloorVilla;
  fs::path glb = dir / "building.glb";
  fs::path png = dir / "preview.png";
  REQUIRE(Villa("build " + layout.string() + " -o " + glb.string() + " --preview " + png.string()) == 0);
  REQUIRE(fs::exists(glb));
  REQUIRE(fs::exists(png));
  auto scene = ReadSceneInfo(glb);
  REQUIRE(scene);
  CHECK(scene->Find("level_2"));
  std::string before = Slurp(glb);
  CHECK(Villa("build " + layout.string() + " -o " + glb.string()) == 2);  // exists
  CHECK(Slurp(glb) == before);
  CHECK(Villa("build " + layout.string() + " -o " + glb.string() + " --force") == 0);
  // OBJ by flag; usage errors; an unreadable layout fails with 1 and writes nothing.
  CHECK(Villa("build " + layout.string() + " -o " + (dir / "b.obj").string() + " --format obj") == 0);
  CHECK(fs::exists(dir / "b.mtl"));
  CHECK(Villa("build " + (dir / "missing.json").string() + " -o " + (dir / "x.glb").string()) == 2);
  CHECK(Villa("build " + layout.string() + " -o " + (dir / "x.glb").string() + " --format fbx") == 2);
  std::ofstream(dir / "broken.json") << "{\"rooms\": ";
  CHECK(Villa("build " + (dir / "broken.json").string() + " -o " + (dir / "x.glb").string()) == 1);
  CHECK_FALSE(fs::exists(dir / "x.glb"));
  // A layout breaking rule 1 (a courtyard hole) is refused unless --allow-invalid; even then it cannot be built.
  std::string hole = std::string(VILLA_FIXTURE_DIR) + "/layouts/rule1_courtyard_hole.json";
  CHECK(Villa("build " + hole + " -o " + (dir / "x.glb").string()) == 1);
  CHECK_FALSE(fs::exists(dir / "x.glb"));
  fs::remove_all(dir);
}

TEST_CASE("villa generate --no-furnish plans and builds: layout, plan, building, preview and report in one folder") {
  fs::path dir = fs::temp_directory_path() / ("villa_generate_cli_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  // The main job's request (scripts/main-job.sh).
  const std::string request =
      "\"I want a three-story L-shaped villa with a living room, an open-plan kitchen and a dining room on the "
      "ground floor, two bedrooms and a bathroom upstairs, and a children's room with a balcony with panoramic "
      "windows on the top floor.\"";
  REQUIRE(Villa("generate " + request + " -o " + dir.string() + " --seed 7 --no-furnish") == 0);
  for (const char* f : {"layout.json", "plan.png", "building.glb", "preview.png", "report.json"}) {
    INFO(f);
    CHECK(fs::exists(dir / f));
  }
  auto layout = LoadLayout(dir / "layout.json");
  REQUIRE(layout);
  CHECK(layout->LevelCount() == 3);
  auto report = nlohmann::json::parse(Slurp(dir / "report.json"));
  CHECK(report["building"]["levels"] == 3);
  CHECK(report["building"]["vcr"]["floor_pairs"] == 2);
  CHECK(report["building"]["vcr"]["connected"] == 2);
  CHECK(report["problems"].empty());
  auto scene = ReadSceneInfo(dir / "building.glb");
  REQUIRE(scene);
  for (const Room& r : layout->rooms) CHECK(scene->Find(r.name()));
  // Outputs are never overwritten without --force.
  std::string before = Slurp(dir / "building.glb");
  CHECK(Villa("generate " + request + " -o " + dir.string() + " --no-furnish") == 2);
  CHECK(Slurp(dir / "building.glb") == before);
  CHECK(Villa("generate \"  \" -o " + dir.string() + " --force") == 2);  // empty request
  fs::remove_all(dir);
}
