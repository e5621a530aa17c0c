// The micro evaluation (`villa eval --scenes`, generator/scene_eval.h): the paper's room types, averaging
// per scene, then over a layout's scenes, then over layouts; the inputs (prompts, prompts with a layout,
// layout records, layout files); and the command end to end.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <set>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "generator/scene_eval.h"
#include "layout/layout_io.h"
#include "test_files.h"
#include "villa_cli.h"

using namespace villa;
namespace fs = std::filesystem;

namespace {

using testing::TempDir;

RoomScore Score(int layout, int scene, Category c, int objects, int colliding, int consumers, int floating, int inside,
                int contained) {
  RoomScore r;
  r.layout = layout;
  r.scene = scene;
  r.room = std::string(CategoryName(c)) + "_0/" + std::to_string(scene);
  r.category = c;
  r.objects = objects;
  r.colliding = colliding;
  r.consumers = consumers;
  r.floating = floating;
  r.inside_edges = inside;
  r.contained = contained;
  return r;
}

const MicroRow* Row(const MicroTable& t, const std::string& type) {
  for (const MicroRow& r : t.rows)
    if (r.type == type) return &r;
  return nullptr;
}

const std::string kHouse = std::string(VILLA_FIXTURE_DIR) + "/layouts/house_one_floor.json";

}  // namespace

TEST_CASE("The paper's nine room types are our categories, balconies and unlabelled rooms are not among them", "[generator][eval]") {
  CHECK(PaperRoomType(Category::kLivingRoom) == "Living Room");
  CHECK(PaperRoomType(Category::kChildrenRoom) == "Childroom");
  CHECK(PaperRoomType(Category::kUtilityRoom) == "Utility Room");
  CHECK(PaperRoomType(Category::kMeetingRoom) == "Meeting Room");
  int nine = 0;
  for (int c = 0; c < kCategoryCount; ++c) nine += !PaperRoomType(static_cast<Category>(c)).empty();
  CHECK(nine == 9);
  CHECK(PaperRoomType(Category::kBalcony).empty());
  CHECK(PaperRoomType(Category::kRoom).empty());
}

TEST_CASE("Micro table: pooled per scene, averaged over a layout's scenes, then over layouts", "[generator][eval]") {
  std::vector<RoomScore> rooms{
      // Layout 0, scene 0: CR 0.1, FR 0.25, CSR 0.75, NO 10; scene 1: CR 0, FR 0, no inside edge, NO 20.
      Score(0, 0, Category::kLivingRoom, 10, 1, 8, 2, 4, 3),
      Score(0, 1, Category::kLivingRoom, 20, 0, 10, 0, 0, 0),
      // Layout 1, one scene with two living rooms pooled: CR 0, FR 0, CSR 1, NO 20.
      Score(1, 0, Category::kLivingRoom, 30, 0, 25, 0, 2, 2),
      Score(1, 0, Category::kLivingRoom, 10, 0, 8, 0, 0, 0),
      // A staircase room with nothing in it and a balcony (outside the nine).
      Score(1, 0, Category::kUtilityRoom, 0, 0, 0, 0, 0, 0),
      Score(1, 0, Category::kBalcony, 5, 5, 5, 0, 0, 0),
  };
  rooms[0].out_of_bounds = 2;
  rooms[0].reachable = 1.0;
  rooms[1].reachable = 0.0;
  rooms[0].access = {0.5, 1.0};
  const MicroTable t = MicroTableOf(rooms);
  REQUIRE(t.rows.size() == 3);
  CHECK(t.rows[0].type == "Living Room");
  CHECK(t.rows[1].type == "Utility Room");
  CHECK(t.rows[2].type == "Balcony");
  CHECK_FALSE(t.rows[2].in_paper);
  const MicroValues& living = Row(t, "Living Room")->values;
  CHECK(living.rooms == 4);
  CHECK(living.layouts == 2);
  CHECK(*living.cr == Approx((0.05 + 0.0) / 2));
  CHECK(*living.fr == Approx((0.125 + 0.0) / 2));
  CHECK(*living.obr == Approx((0.1 + 0.0) / 2));  // layout 0: (0.2 + 0) / 2
  CHECK(*living.csr == Approx((0.75 + 1.0) / 2));
  CHECK(*living.no == Approx((15.0 + 20.0) / 2));
  CHECK(*living.rch == Approx(0.5));  // only layout 0 measured it: (1 + 0) / 2
  CHECK(*living.acc == Approx(0.75));
  // No object: nothing collides, floats or leaves the room; no inside edge: no CSR.
  const MicroValues& utility = Row(t, "Utility Room")->values;
  CHECK(*utility.cr == 0.0);
  CHECK(*utility.no == 0.0);
  CHECK_FALSE(utility.csr);
  CHECK_FALSE(utility.rch);
  // The average is over the nine types only (the colliding balcony is left out).
  CHECK(*t.average.cr == Approx(*living.cr / 2));
  CHECK(*t.average.no == Approx(*living.no / 2));
  CHECK(*t.average.csr == Approx(*living.csr));
  CHECK(*t.rich_no == Approx(*living.no));
  // The three outputs carry the rows.
  CHECK(MicroTableText(t).find("Balcony *") != std::string::npos);
  CHECK(MicroTableMarkdown(t).find("| Living Room | 2 | 4 | 2.5 | 6.2 | 5.0 | 87.5 | 17.5 | 50.0 | 75.0 |") != std::string::npos);
  const auto j = MicroTableJson(t);
  CHECK(j["rows"][0]["NO"] == 17.5);
  CHECK(j["rows"][1]["CSR"].is_null());
}

TEST_CASE("Scene requests: prompts, prompts with a layout, layout records and layout files, errors name the line",
          "[generator][eval]") {
  TempDir dir("seval_read");
  const fs::path jsonl = dir.path / "requests.jsonl";
  fs::copy_file(kHouse, dir.path / "house.json");
  const std::string house_text = [] {
    std::ifstream in(kHouse);
    std::string s((std::istreambuf_iterator<char>(in)), {});
    return nlohmann::json::parse(s).dump();
  }();
  {
    std::ofstream out(jsonl);
    out << "{\"id\": \"a\", \"text\": \"a bungalow with a kitchen\"}\n";
    out << "{\"text\": \"a TV in the living room\", \"layout\": \"house.json\"}\n";
    out << house_text << "\n";
  }
  auto r = ReadSceneRequests({jsonl, kHouse});
  INFO((r.ok() ? "" : r.error()));
  REQUIRE(r.ok());
  REQUIRE(r->size() == 4);
  CHECK((*r)[0].id == "a");
  CHECK_FALSE((*r)[0].layout);
  CHECK((*r)[1].text == "a TV in the living room");
  REQUIRE((*r)[1].layout);
  CHECK((*r)[1].layout->rooms.size() == 6);
  CHECK((*r)[1].id == jsonl.string() + ":2");
  REQUIRE((*r)[2].layout);
  CHECK((*r)[2].text.empty());
  REQUIRE((*r)[3].layout);
  CHECK((*r)[3].source == kHouse);
  CHECK(ReadSceneRequests({jsonl}, 2)->size() == 2);

  {
    std::ofstream out(jsonl, std::ios::app);
    out << "{\"what\": 1}\n";
  }
  auto bad = ReadSceneRequests({jsonl});
  REQUIRE_FALSE(bad.ok());
  CHECK(bad.error().find(jsonl.string() + ":4: neither a request") == 0);
  CHECK_FALSE(ReadSceneRequests({dir.path / "missing.jsonl"}).ok());
}

TEST_CASE("villa eval --scenes furnishes every layout three times and prints the micro and macro tables", "[generator][eval]") {
  TempDir dir("seval_cli");
  const fs::path prompts = dir.path / "prompts.jsonl";
  {
    std::ofstream out(prompts);
    out << "{\"id\": \"cottage\", \"text\": \"A single-storey house with a living room, a kitchen, a bathroom, a bedroom and a "
           "utility room.\"}\n";
  }
  const testing::CliRun run = testing::RunVilla("eval --scenes " + prompts.string() + " " + kHouse + " --procedural --json");
  INFO(run.out);
  REQUIRE(run.status == 0);
  const auto j = nlohmann::json::parse(run.out);
  CHECK(j["format"] == "villa-scene-eval/1");
  REQUIRE(j["layouts"].size() == 2);
  CHECK(j["layouts"][0]["planned"] == true);
  CHECK(j["layouts"][1]["planned"] == false);
  REQUIRE(j["scenes"].size() == 6);
  for (const auto& s : j["scenes"]) {
    CHECK_FALSE(s.contains("error"));
    CHECK(s["CR"] == 0.0);
    CHECK(s["objects"].get<int>() > 30);
  }
  CHECK(j["scenes"][0]["seed"] != j["scenes"][1]["seed"]);
  std::set<std::string> types;
  for (const auto& row : j["micro"]["rows"]) {
    types.insert(row["type"].get<std::string>());
    CHECK(row["CR"] == 0.0);
    CHECK(row["FR"] == 0.0);
    CHECK(row["OBR"] == 0.0);
  }
  for (const char* t : {"Living Room", "Kitchen", "Bathroom", "Bedroom", "Utility Room", "Office", "Dining Room"}) CHECK(types.count(t));
  CHECK(j["micro"]["rows"][0]["layouts"] == 2);
  CHECK(j["macro"]["FSR"] == 1.0);
  CHECK(j["reach"].is_string());
  CHECK(j["seconds"]["per_room"].get<double>() > 0.0);
  // Issue 28: every scene settled in Bullet, summed per room type.
  CHECK(j["physics"]["all"]["free"].get<int>() > 90);
  CHECK(j["physics"]["all"]["loose_share"].get<double>() >= 0.98);
  CHECK(j["physics"]["by_room_type"].contains("kitchen"));
  // Issue 27's functional checks per room type and over all rooms: the same rooms as the micro table, every
  // room's essentials there, every desk with its chair, nightstands and pillows at the bed's head, nothing
  // odd (these small houses hold them all), and each failing room listed with what fails.
  const auto& f = j["functional"];
  int rooms = 0, micro_rooms = 0;
  for (const auto& [type, t] : f["by_room_type"].items()) rooms += t["rooms"].get<int>();
  for (const auto& row : j["micro"]["rows"]) micro_rooms += row["rooms"].get<int>();
  CHECK(rooms == micro_rooms);
  CHECK(f["all"]["rooms"].get<int>() == micro_rooms);
  const auto all_ok = [&](const char* what) {
    INFO(what << ": " << f["all"][what].dump());
    CHECK(f["all"][what][1].get<int>() > 0);
    CHECK(f["all"][what][0] == f["all"][what][1]);
  };
  for (const char* what : {"essentials", "desks", "nightstands", "pillows"}) all_ok(what);
  CHECK(f["by_room_type"]["Utility Room"]["essentials"][1] == 0);  // no essentials asked of a utility room
  CHECK(f["all"]["odd"] == 0);
  if (f["all"]["groups"][0] < f["all"]["groups"][1]) CHECK_FALSE(f["failing"].empty());
  for (const auto& line : f["failing"]) {
    const std::string l = line.get<std::string>();
    INFO(l);
    CHECK((l.rfind("cottage scene ", 0) == 0 || l.rfind(kHouse + " scene ", 0) == 0));
    CHECK((l.find(": [") != std::string::npos || l.find(": missing") != std::string::npos || l.find(": floor:") != std::string::npos ||
           l.find(": wish") != std::string::npos || l.find(": odd:") != std::string::npos));
  }

  const testing::CliRun text = testing::RunVilla("eval --scenes " + kHouse + " --procedural --scenes-per-layout 1");
  REQUIRE(text.status == 0);
  for (const char* word : {"Living Room", "Average (the nine)", "FSR", "the paper: ~15 min", "Rooms as rooms", "nightstands", "\nAll "})
    CHECK(text.out.find(word) != std::string::npos);
  const testing::CliRun md = testing::RunVilla("eval --scenes " + kHouse + " --procedural --scenes-per-layout 1 --markdown");
  REQUIRE(md.status == 0);
  CHECK(md.out.find("| Living Room | 1 | 1 |") != std::string::npos);
  CHECK(md.out.find("| room type | rooms | essentials | table chairs |") != std::string::npos);

  CHECK(testing::RunVilla("eval --scenes").status == 2);
  CHECK(testing::RunVilla("eval --scenes " + kHouse + " --json --markdown").status == 2);
  CHECK(testing::RunVilla("eval --scenes --glb " + (dir.path / "none.glb").string()).status == 2);
  CHECK(testing::RunVilla("eval --scenes " + kHouse + " --scenes-per-layout 0").status == 2);
  CHECK(testing::RunVilla("eval --glb " + kHouse).status == 2);
}

TEST_CASE("villa eval --scenes --keep DIR keeps every scene's files under DIR/<request>/<seed>/", "[generator][eval]") {
  CHECK(KeptLayoutName(0, "cottage") == "001-cottage");
  CHECK(KeptLayoutName(41, "/some/where/villa one.json") == "042-villa_one.json");
  CHECK(KeptLayoutName(999, std::string(100, 'x')) == "1000-" + std::string(60, 'x'));

  TempDir dir("seval_keep");
  const fs::path keep = dir.path / "kept";
  const testing::CliRun run =
      testing::RunVilla("eval --scenes " + kHouse + " --procedural --no-reach --scenes-per-layout 2 --json --keep " + keep.string());
  INFO(run.out);
  REQUIRE(run.status == 0);
  const auto j = nlohmann::json::parse(run.out);
  REQUIRE(j["scenes"].size() == 2);
  CHECK(j["kept"] == 2);
  const fs::path layout_dir = keep / "001-house_one_floor.json";
  std::set<std::string> seeds, listed;
  for (const auto& s : j["scenes"]) seeds.insert(std::to_string(s["seed"].get<uint64_t>()));
  for (const auto& e : fs::directory_iterator(layout_dir)) listed.insert(e.path().filename().string());
  CHECK(listed == seeds);  // one folder a scene, named by its seed; no .partial folder left
  for (const std::string& seed : seeds) {
    const fs::path d = layout_dir / seed;
    for (const char* f : {"layout.json", "scene.json", "furnished.glb", "report.json", "CREDITS"}) CHECK(fs::is_regular_file(d / f));
    CHECK_FALSE(fs::exists(d / "plan.png"));
    // The scene and the report are the ones scored: the report names the seed, both hold its objects.
    const auto report = nlohmann::json::parse(std::ifstream(d / "report.json"));
    CHECK(std::to_string(report["seed"].get<uint64_t>()) == seed);
    const auto scene = nlohmann::json::parse(std::ifstream(d / "scene.json"));
    for (const auto& s : j["scenes"])
      if (std::to_string(s["seed"].get<uint64_t>()) == seed) CHECK(scene["objects"].size() == s["objects"].get<size_t>());
    // It names the layout beside it, so `villa reach` on the kept scene works.
    CHECK(scene["layout"]["file"] == "layout.json");
    CHECK(testing::RunVilla("reach " + (d / "scene.json").string()).status == 0);
    const auto layout = LoadLayout((d / "layout.json").string());
    REQUIRE(layout.ok());
    CHECK(layout->rooms.size() == LoadLayout(kHouse)->rooms.size());
    std::ifstream glb(d / "furnished.glb", std::ios::binary);
    char magic[4] = {};
    glb.read(magic, 4);
    CHECK(std::string(magic, 4) == "glTF");
  }
  // The folder is no longer empty: a second run is refused before anything is furnished or replaced.
  const testing::CliRun again = testing::RunVilla("eval --scenes " + kHouse + " --procedural --keep " + keep.string());
  CHECK(again.status == 2);
  CHECK(again.out.find("--keep") != std::string::npos);
  CHECK(testing::RunVilla("eval --scenes --glb " + kHouse + " --keep " + (dir.path / "k2").string()).status == 2);
}
