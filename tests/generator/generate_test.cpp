// `villa generate` end to end: text -> layout -> building -> every room furnished, with the request's
// furniture wishes in the rooms they name, the pictures, the report's macro and micro metrics, the .glb
// read back by assimp agreeing with scene.json, the same bytes whatever --jobs, and the usage rules.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "building/export.h"
#include "furnished_glb.h"
#include "layout/layout_io.h"
#include "render/plan_render.h"
#include "scene/scene.h"
#include "solver/furnish.h"
#include "test_files.h"
#include "villa_cli.h"

using namespace villa;
namespace fs = std::filesystem;

namespace {

using testing::TempDir;
std::string Read(const fs::path& p) { return testing::ReadFile(p); }

// Two floors with a meeting room and a study (an office), and the two furniture sentences of the issue.
const std::string kRequest =
    "\"A two-story house with a living room, a kitchen, a dining room and a meeting room on the ground floor, and "
    "two bedrooms, a bathroom and a study upstairs. Put a TV in the meeting room and bookshelves full of books in "
    "the study.\"";

}  // namespace

TEST_CASE("villa generate plans, builds and furnishes: files, wishes in their rooms, report, .glb, same bytes for any --jobs",
          "[generator][generate]") {
  TempDir one("gen_jobs1"), two("gen_jobs2");
  const testing::CliRun run = testing::RunVilla("generate " + kRequest + " --seed 3 --procedural --jobs 1 -o " + one.path.string());
  INFO(run.out);
  REQUIRE(run.status == 0);
  CHECK(run.out.find("rooms furnished") != std::string::npos);
  for (const char* f : {"layout.json", "plan.png", "scene.json", "furnished.glb", "CREDITS", "preview.png", "report.json"}) {
    INFO(f);
    CHECK(fs::file_size(one.path / f) > 100);
  }
  CHECK_FALSE(fs::exists(one.path / "building.glb"));  // the building is in furnished.glb

  auto layout = LoadLayout(one.path / "layout.json");
  REQUIRE(layout.ok());
  CHECK(layout->LevelCount() == 2);
  auto s = scene::ReadScene(one.path / "scene.json");
  REQUIRE(s.ok());
  CHECK(s->layout.file == "layout.json");
  REQUIRE(s->rooms.size() == layout->rooms.size());

  // The wishes went to the rooms they name, and only there: the TV onto something in the meeting room,
  // bookcases with books inside them in the study (an office).
  std::map<std::string, std::multiset<std::string>> named;  // room category -> categories the request named
  for (const scene::SceneObject& o : s->objects) {
    REQUIRE(o.pose);
    if (o.origin != scene::Origin::kPrompt) continue;
    named[o.room.substr(0, o.room.find('_'))].insert(o.category);
    if (o.category == "books") {
      CHECK(o.relation == scene::Relation::kInside);
      const scene::SceneObject* parent = s->FindObject(o.parent);
      REQUIRE(parent);
      CHECK(parent->category == "bookcase");
      CHECK(parent->origin == scene::Origin::kPrompt);
    }
  }
  CHECK(named.size() == 2);
  CHECK(named["meeting-room"].count("tv") == 1);
  CHECK(named["office"].count("bookcase") >= 1);
  CHECK(named["office"].count("books") >= 4);

  // The report: the plan's macro metrics, the micro ones (RCH and ACC only when reachability measured
  // them), every room's furnishing, the files.
  const auto report = nlohmann::json::parse(Read(one.path / "report.json"));
  CHECK(report["metrics"]["fsr"] == 1.0);
  CHECK(report["metrics"]["vcr"] == 1.0);
  const auto& micro = report["micro"];
  CHECK(micro["rooms"] == static_cast<int>(layout->rooms.size()));
  CHECK(micro["objects"] == static_cast<int>(s->objects.size()));
  CHECK(micro["CR"] == 0.0);
  CHECK(micro["FR"] == 0.0);
  CHECK(micro["OBR"] == 0.0);
  CHECK(micro["CSR"] == 1.0);
  CHECK(micro["NO"].get<double>() > 10.0);
  CHECK((micro["RCH"].is_null() || (micro["RCH"].get<double>() >= 0.0 && micro["RCH"].get<double>() <= 1.0)));
  REQUIRE(report["furnish"]["rooms"].size() == layout->rooms.size());
  CHECK(report["furnish"]["layout"] == "layout.json");
  // The offline critic reviewed the rooms, as `villa furnish` does by default.
  CHECK(report["furnish"]["totals"]["critic"]["critic"] == "offline");
  CHECK(report["furnish"]["totals"]["critic"]["rounds"].get<int>() >= static_cast<int>(layout->rooms.size()) / 2);
  CHECK(report["problems"].empty());
  nlohmann::json files = {"layout.json", "plan.png", "scene.json", "furnished.glb", "CREDITS"};
  for (const Room& room : layout->rooms) {
    files.push_back(solver::RoomPictureName(room.name()));  // a picture per room, in layout order
    CHECK(fs::file_size(one.path / solver::RoomPictureName(room.name())) > 1000);
  }
  files.push_back("preview.png");
  CHECK(report["files"] == files);

  // plan.png is the floor plan with the furniture on it, not the bare plan.
  auto bare = RenderPlanPng(*layout);
  REQUIRE(bare.ok());
  CHECK(Read(one.path / "plan.png") != *bare);

  // Another reader finds every object where scene.json puts it.
  auto glb = ReadSceneInfo(one.path / "furnished.glb");
  REQUIRE(glb.ok());
  testing::CheckGlbAgreesWithScene(*glb, *s);
  for (const Room& r : layout->rooms) CHECK(glb->Find(r.name()));

  // Two jobs: the same bytes (report.json differs only in its times).
  const testing::CliRun again = testing::RunVilla("generate " + kRequest + " --seed 3 --procedural --jobs 2 -q -o " + two.path.string());
  REQUIRE(again.status == 0);
  CHECK(again.out.empty());
  for (const char* f : {"layout.json", "plan.png", "scene.json", "furnished.glb", "CREDITS", "preview.png"}) {
    INFO(f);
    CHECK(Read(one.path / f) == Read(two.path / f));
  }
  for (const Room& room : layout->rooms) {
    INFO(room.name());
    CHECK(Read(one.path / solver::RoomPictureName(room.name())) == Read(two.path / solver::RoomPictureName(room.name())));
  }

  // The .glb scored by `villa eval --scenes --glb` agrees with the report, room by room.
  const testing::CliRun scored = testing::RunVilla("eval --scenes --glb " + (one.path / "furnished.glb").string() + " --scene " +
                                                   (one.path / "scene.json").string() + " --json");
  INFO(scored.out);
  REQUIRE(scored.status == 0);
  const auto j = nlohmann::json::parse(scored.out);
  std::map<std::string, nlohmann::json> expected;
  for (const auto& r : report["furnish"]["rooms"]) expected[r["room"].get<std::string>()] = r["metrics"];
  REQUIRE(j["files"].size() == 1);
  CHECK(j["files"][0]["frame"].get<std::string>().rfind("layout", 0) == 0);
  for (const auto& r : j["files"][0]["rooms"]) {
    INFO(r["room"]);
    const auto& e = expected.at(r["room"].get<std::string>());
    CHECK(r["NO"] == e["NO"]);
    CHECK(r["CR"] == 0.0);
    CHECK(r["FR"] == 0.0);
    CHECK(r["OBR"] == 0.0);
  }
}

TEST_CASE("villa generate: usage errors exit 2, a bad library exits 1, --no-furnish stops at the building", "[generator][generate]") {
  TempDir dir("gen_usage");
  const fs::path out = dir.path / "out";
  const std::string request = "\"A single-storey house with a living room, a kitchen, a bathroom and a bedroom.\"";
  CHECK(testing::RunVilla("generate " + request + " --jobs -1 -o " + out.string()).status == 2);
  CHECK_FALSE(fs::exists(out / "layout.json"));
  const testing::CliRun library = testing::RunVilla("generate " + request + " --library " + (dir.path / "none").string() + " -o " + out.string());
  CHECK(library.status == 1);
  CHECK(library.out.find((dir.path / "none").string()) != std::string::npos);
  CHECK_FALSE(fs::exists(out / "layout.json"));

  REQUIRE(testing::RunVilla("generate " + request + " --procedural -q -o " + out.string()).status == 0);
  const std::string before = Read(out / "scene.json");
  { std::ofstream(out / "notes.txt") << "mine"; }
  const testing::CliRun refused = testing::RunVilla("generate " + request + " --procedural --seed 9 -o " + out.string());
  CHECK(refused.status == 2);
  CHECK(refused.out.find("--force") != std::string::npos);
  CHECK(Read(out / "scene.json") == before);
  CHECK(testing::RunVilla("generate " + request + " --procedural --seed 9 --force --critic mllm -o " + out.string()).status == 2);
  REQUIRE(testing::RunVilla("generate " + request + " --procedural --seed 9 --force --critic none -q -o " + out.string()).status == 0);
  CHECK(Read(out / "notes.txt") == "mine");
  CHECK(nlohmann::json::parse(Read(out / "report.json"))["furnish"]["totals"]["critic"].is_null());  // --critic none: the solver's rooms

  const fs::path bare = dir.path / "bare";
  REQUIRE(testing::RunVilla("generate " + request + " --no-furnish -q -o " + bare.string()).status == 0);
  for (const char* f : {"layout.json", "plan.png", "building.glb", "preview.png", "report.json"}) CHECK(fs::exists(bare / f));
  CHECK_FALSE(fs::exists(bare / "scene.json"));
  CHECK(nlohmann::json::parse(Read(bare / "report.json"))["micro"].is_null());

  const testing::CliRun help = testing::RunVilla("generate --help");
  for (const char* word : {"furnished.glb", "scene.json", "--jobs", "--library", "--procedural", "--no-furnish", "--critic"}) CHECK(help.out.find(word) != std::string::npos);
}
