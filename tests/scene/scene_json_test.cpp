#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <regex>

#include "scene/file_digest.h"
#include "scene/scene.h"
#include "scene/strict_json.h"
#include "util/atomic_file.h"

using namespace villa;
using namespace villa::scene;

namespace {

const std::string kHash = std::string(64, 'a');

// A scene in SCENE.md's shape: one solved living room with a sofa, a book inside a bookcase, a painting.
std::string SampleText() {
  return R"({"format": "villa-scene/1",
 "layout": {"file": "layout.json", "sha256": ")" + kHash + R"("},
 "library": {"file": "assets.jsonl", "sha256": ")" + kHash + R"("},
 "build": {"slab_thickness": 0.175, "exterior_wall_thickness": 0.25, "interior_wall_thickness": 0.12},
 "rooms": {"living-room_0/0": {"graph": {"planner": "priors", "seed": 7, "text": "a sofa", "notes": ["no room for a piano"],
                                          "edges_sem": [{"source": "living-room_0/0/painting-0", "relation": "centered",
                                                         "target": "living-room_0/0/sofa-0", "params": {"max_offset": 0.1}},
                                                        {"source": "living-room_0/0/sofa-0", "relation": "face_to",
                                                         "target": "living-room_0/0/bookcase-0"}]},
                                "solve": {"outcome": "converged", "iterations": 12, "energy": 0.4, "removed": [],
                                          "actions": [{"action": "update_pose"}]},
                                "metrics": {"CR": 0, "NO": 4}},
           "kitchen_0/0": {"graph": {"edges_sem": []}, "solve": {"outcome": "infeasible", "iterations": 0,
                                     "energy": 0, "note": "no free floor"}}},
 "objects": {
  "living-room_0/0/sofa-0": {"asset": "sh3d:BlendSwap-CC-0#couch", "category": "sofa", "room": "living-room_0/0",
     "level": 0, "pose": {"x": 0.71, "y": 3.99, "z": 0.175, "yaw": 90.0}, "scale": [1.0, 1.0, 1.0],
     "size": [2.074, 0.876, 0.856], "affordances": ["V_con", "V_pro", "V_int"], "parent": "floor",
     "relation": "against_wall", "wall": {"edge": 3, "gap": 0.02},
     "interaction_zone": {"side": "front", "depth": 0.45, "exempt": ["living-room_0/0/bookcase-0"]},
     "origin": "prompt", "hints": ["far_from_door"]},
  "living-room_0/0/bookcase-0": {"asset": "proc:bookcase?cols=2&rows=5&seed=3", "category": "bookcase",
     "room": "living-room_0/0", "level": 0, "pose": {"x": 3, "y": 0.4, "z": 0.175, "yaw": -90.0},
     "size": [1.0, 0.35, 1.8], "affordances": ["V_con", "V_pro", "V_int"], "parent": "floor",
     "relation": "against_wall", "wall": {"edge": 0, "gap": 0.02}, "origin": "prior"},
  "living-room_0/0/books-0": {"asset": "proc:books?n=8&seed=1", "category": "books", "room": "living-room_0/0",
     "level": 0, "pose": {"x": 3, "y": 0.4, "z": 0.5, "yaw": -90.0}, "size": [0.3, 0.2, 0.25],
     "affordances": ["V_con"], "parent": "living-room_0/0/bookcase-0", "relation": "inside", "cavity": 2,
     "origin": "prior"},
  "living-room_0/0/painting-0": {"asset": "proc:frame?w=0.8", "category": "painting", "room": "living-room_0/0",
     "level": 0, "pose": {"x": 0.3, "y": 3.99, "z": 1.5, "yaw": 90.0}, "size": [0.8, 0.03, 0.6],
     "affordances": ["V_con"], "parent": "wall", "relation": "on_wall", "wall": {"edge": 3, "gap": 0},
     "origin": "prior"}},
 "metrics": {"CR": 0.0, "FR": 0.0}})";
}

// The sample with one substring replaced (the error paths below break one thing each).
std::string With(const std::string& from, const std::string& to) {
  std::string text = SampleText();
  size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

std::string ErrorOf(const std::string& text) {
  auto scene = ParseSceneText(text, "scene.json");
  REQUIRE_FALSE(scene.ok());
  return scene.error();
}

}  // namespace

TEST_CASE("a scene file reads into the model of SCENE.md", "[scene][json]") {
  auto scene = ParseSceneText(SampleText(), "scene.json");
  REQUIRE(scene.ok());
  REQUIRE(scene->objects.size() == 4);
  REQUIRE(scene->rooms.size() == 2);
  const SceneObject& sofa = scene->objects[0];
  CHECK(sofa.id == "living-room_0/0/sofa-0");
  REQUIRE(sofa.pose);
  CHECK(sofa.pose->yaw == Approx(std::numbers::pi / 2));  // 90 degrees in the file, radians in code
  CHECK(sofa.affordances == (kConsumer | kProvider | kInteractor));
  CHECK(sofa.relation == Relation::kAgainstWall);
  REQUIRE(sofa.wall);
  CHECK(sofa.wall->edge == 3);
  REQUIRE(sofa.interaction_zone);
  CHECK(sofa.interaction_zone->exempt == std::vector<std::string>{"living-room_0/0/bookcase-0"});
  CHECK(sofa.origin == Origin::kPrompt);
  CHECK(sofa.hints == std::vector<std::string>{"far_from_door"});
  CHECK(scene->objects[2].cavity == 2);
  CHECK(scene->objects[1].scale == std::array<double, 3>{1.0, 1.0, 1.0});  // default when absent
  const RoomEntry& living = scene->rooms[0];
  REQUIRE(living.plan);
  CHECK(living.plan->seed == 7);
  CHECK(living.plan->notes.size() == 1);
  REQUIRE(living.edges_sem.size() == 2);
  CHECK(living.edges_sem[0].relation == SemanticRelation::kCentered);
  CHECK(living.edges_sem[0].params.max_offset == 0.1);
  REQUIRE(living.solve);
  CHECK(living.solve->actions.size() == 1);
  CHECK(scene->rooms[1].solve->outcome == SolveOutcome::kInfeasible);
  CHECK(scene->rooms[1].solve->note == "no free floor");
}

TEST_CASE("scene files round-trip: read, write, read gives the same model and the same text", "[scene][json]") {
  auto first = ParseSceneText(SampleText(), "scene.json");
  REQUIRE(first.ok());
  std::string written = SceneToText(*first);
  auto second = ParseSceneText(written, "written");
  REQUIRE(second.ok());
  CHECK(*second == *first);
  CHECK(SceneToText(*second) == written);
  // Through a file too (atomic write, then read back).
  auto dir = std::filesystem::temp_directory_path() / "villa_scene_json_test";
  std::filesystem::create_directories(dir);
  REQUIRE(WriteScene(*first, dir / "scene.json").ok());
  auto third = ReadScene(dir / "scene.json");
  REQUIRE(third.ok());
  CHECK(*third == *first);
  std::filesystem::remove_all(dir);
}

TEST_CASE("written numbers have at most 4 decimals and yaw lies in -180 exclusive to 180 inclusive", "[scene][json]") {
  SceneFile scene;
  scene.layout = {"layout.json", kHash};
  scene.rooms.push_back({"bedroom_0/0", std::nullopt, {}, std::nullopt, std::nullopt});
  SceneObject bed;
  bed.id = "bedroom_0/0/bed-0";
  bed.category = "bed";
  bed.room = "bedroom_0/0";
  bed.size = {1.6, 2.0, 0.5};
  bed.parent = "floor";
  bed.pose = Pose{1.0 / 3.0, 2.000049, 0.175, -std::numbers::pi};  // -180 degrees is written as 180
  scene.objects.push_back(bed);
  SceneObject lamp = bed;
  lamp.id = "bedroom_0/0/bed-1";
  lamp.pose = Pose{0.00001, -0.00004, 0, 3.0 * std::numbers::pi + 0.1};  // wraps to -180 + 5.73 degrees
  scene.objects.push_back(lamp);
  Json j = SceneToJson(scene);
  CHECK(j["objects"]["bedroom_0/0/bed-0"]["pose"]["x"].get<double>() == 0.3333);
  CHECK(j["objects"]["bedroom_0/0/bed-0"]["pose"]["y"].get<double>() == 2.0);
  CHECK(j["objects"]["bedroom_0/0/bed-0"]["pose"]["yaw"].get<double>() == 180.0);
  CHECK(j["objects"]["bedroom_0/0/bed-1"]["pose"]["x"].get<double>() == 0.0);
  CHECK(j["objects"]["bedroom_0/0/bed-1"]["pose"]["yaw"].get<double>() == Approx(-174.2704).margin(1e-9));
  std::string text = SceneToText(scene);
  CHECK_FALSE(std::regex_search(text, std::regex("[0-9][eE][-+]?[0-9]")));  // no exponent anywhere
  CHECK(text.find("-0.0") == std::string::npos);
  // What was written reads back (strictly).
  CHECK(ParseSceneText(text, "written").ok());
  CHECK(WrapYaw(std::numbers::pi) == Approx(std::numbers::pi));
  CHECK(WrapYaw(-std::numbers::pi) == Approx(std::numbers::pi));
  CHECK(WrapYaw(7.0) == Approx(7.0 - 2 * std::numbers::pi));
}

TEST_CASE("malformed JSON names the line and column", "[scene][json]") {
  std::string e = ErrorOf("{\"format\": \"villa-scene/1\",\n \"layout\": {\"file\": }\n}");
  CHECK(e.rfind("scene.json: line 2, column ", 0) == 0);
}

TEST_CASE("every error of a scene file names the path and the bad value", "[scene][json]") {
  struct Case {
    std::string from, to, expect;
  };
  const std::vector<Case> cases = {
      {"\"villa-scene/1\"", "\"villa-scene/2\"", "format: \"villa-scene/2\": expected \"villa-scene/1\""},
      {"\"x\": 0.71", "\"x\": 0.71234", "objects[\"living-room_0/0/sofa-0\"].pose.x: 0.71234: numbers have at most 4 decimals"},
      {"\"x\": 0.71", "\"x\": 7.1e-1", "pose.x: 7.1e-1: numbers are written without an exponent"},
      {"\"x\": 0.71", "\"x\": \"0.71\"", "pose.x: expected a number, got \"0.71\""},
      {"\"yaw\": 90.0", "\"yaw\": 270", "pose.yaw: 270: yaw is in (-180, 180] degrees"},
      {"\"yaw\": 90.0", "\"yaw\": -180", "pose.yaw: -180: yaw is in (-180, 180] degrees"},
      {"\"relation\": \"against_wall\"", "\"relation\": \"beside\"",
       "sofa-0\"].relation: \"beside\": expected one of ontop, inside, against_wall, on_wall, hanging"},
      {"\"relation\": \"centered\"", "\"relation\": \"above\"", "edges_sem[0].relation: \"above\": expected one of face_to"},
      {"\"params\": {\"max_offset\": 0.1}", "\"params\": {\"max_deg\": 10}", "edges_sem[0].params.max_deg: centered takes no max_deg"},
      {"\"affordances\": [\"V_con\", \"V_pro\", \"V_int\"]", "\"affordances\": [\"V_con\", \"V_con\"]",
       "sofa-0\"].affordances: [\"V_con\",\"V_con\"]: expected distinct V_con, V_pro, V_int"},
      {"\"origin\": \"prompt\"", "\"origin\": \"user\"", "origin: \"user\": expected one of prompt, prior, critic"},
      {"\"hints\": [\"far_from_door\"]", "\"hints\": [\"by_the_fire\"]", "hints[0]: \"by_the_fire\": expected one of far_from_door"},
      {"\"size\": [2.074, 0.876, 0.856]", "\"size\": [2.074, 0, 0.856]", "sofa-0\"].size[1]: 0: a size is > 0"},
      {"\"size\": [2.074, 0.876, 0.856]", "\"size\": [2.074, 0.876]", "sofa-0\"].size: expected 3 numbers, got [2.074,0.876]"},
      {"\"scale\": [1.0, 1.0, 1.0]", "\"scale\": [1.0, -1.0, 1.0]", "scale[1]: -1.0: a scale is > 0"},
      {"\"level\": 0, \"pose\": {\"x\": 0.71", "\"level\": -1, \"pose\": {\"x\": 0.71", "sofa-0\"].level: -1: levels count from 0"},
      {"\"level\": 0, \"pose\": {\"x\": 0.71", "\"level\": 0.5, \"pose\": {\"x\": 0.71", "sofa-0\"].level: expected an integer, got 0.5"},
      {"\"cavity\": 2", "\"cavity\": -2", "books-0\"].cavity: -2: an index is >= 0"},
      {"\"wall\": {\"edge\": 3, \"gap\": 0.02}", "\"wall\": {\"edge\": 3, \"gap\": -0.02}", "wall.gap: -0.02: must be >= 0"},
      {"\"wall\": {\"edge\": 3, \"gap\": 0.02}", "\"wall\": {\"side\": 3}", "sofa-0\"].wall.edge: missing"},
      {"\"depth\": 0.45", "\"depth\": 0.45, \"width\": 1", "interaction_zone.width: unknown key"},
      {"\"side\": \"front\"", "\"side\": \"top\"", "interaction_zone.side: \"top\": expected one of front, back, left, right, sides"},
      {"\"origin\": \"prompt\", \"hints\"", "\"origin\": \"prompt\", \"colour\": \"red\", \"hints\"", "sofa-0\"].colour: unknown key"},
      {"\"sha256\": \"" + kHash + "\"}", "\"sha256\": \"ABC\"}", "layout.sha256: \"ABC\": expected 64 lowercase hex digits"},
      {"\"slab_thickness\": 0.175", "\"slab_thickness\": 0", "build.slab_thickness: 0: must be in (0, 1] m"},
      {"\"metrics\": {\"CR\": 0, \"NO\": 4}", "\"metrics\": {\"CR\": 0, \"XX\": 4}", "rooms[\"living-room_0/0\"].metrics.XX: unknown metric"},
      {"\"outcome\": \"converged\"", "\"outcome\": \"done\"", "solve.outcome: \"done\": expected one of converged, budget, infeasible"},
      {"\"actions\": [{\"action\": \"update_pose\"}]", "\"actions\": [3]", "solve.actions[0]: expected an object, got 3"},
      {"\"seed\": 7", "\"seed\": -7", "graph.seed: expected an integer >= 0, got -7"},
      {"\"category\": \"sofa\", \"room\"", "\"category\": \"sofa\", \"category\": \"couch\", \"room\"",
       "objects[\"living-room_0/0/sofa-0\"].category: duplicate key"},
      {"\"edges_sem\": []", "\"edges_sem\": {}", "rooms[\"kitchen_0/0\"].graph.edges_sem: expected an array, got {}"},
      {"\"params\": {\"max_offset\": 0.1}", "\"params\": {\"max_offset\": 0.1, \"max_offset\": 0.2}", "params.max_offset: duplicate key"},
  };
  for (const Case& c : cases) {
    INFO(c.to);
    std::string e = ErrorOf(With(c.from, c.to));
    INFO(e);
    CHECK(e.rfind("scene.json: ", 0) == 0);
    CHECK(e.find(c.expect) != std::string::npos);
  }
  // A long bad value is cut, not repeated whole.
  std::string e = ErrorOf(With("\"origin\": \"prompt\"", "\"origin\": \"" + std::string(300, 'x') + "\""));
  CHECK(e.size() < 250);
  CHECK(e.find("...") != std::string::npos);
}

TEST_CASE("params bounds: min_gap above max_gap is an error", "[scene][json]") {
  std::string e = ErrorOf(With("\"relation\": \"face_to\",\n                                                         \"target\": \"living-room_0/0/bookcase-0\"}",
                               "\"relation\": \"near\", \"target\": \"living-room_0/0/bookcase-0\", \"params\": {\"min_gap\": 2, \"max_gap\": 1}}"));
  INFO(e);
  CHECK(e.find("edges_sem[1].params: min_gap 2 is above max_gap 1") != std::string::npos);
}

TEST_CASE("effective parameters carry SCENE.md's defaults", "[scene][json]") {
  CHECK(EffectiveParams(SemanticRelation::kFaceTo, {}).max_deg == 30.0);
  CHECK(EffectiveParams(SemanticRelation::kAlign, {}).max_deg == 5.0);
  CHECK(EffectiveParams(SemanticRelation::kCentered, {}).max_offset == 0.05);
  CHECK(EffectiveParams(SemanticRelation::kNextTo, {}).max_gap == 0.5);
  CHECK(EffectiveParams(SemanticRelation::kNear, {}).min_gap == 0.5);
  CHECK(EffectiveParams(SemanticRelation::kNear, {}).max_gap == 1.5);
  CHECK(EffectiveParams(SemanticRelation::kFar, {}).min_gap == 1.5);
  EdgeParams given;
  given.max_gap = 0.1;
  CHECK(EffectiveParams(SemanticRelation::kNextTo, given).max_gap == 0.1);
  for (int r = 0; r < kSemanticRelationCount; ++r) {
    auto relation = static_cast<SemanticRelation>(r);
    CHECK(ParseSemanticRelation(SemanticRelationName(relation)) == relation);
  }
}

TEST_CASE("file SHA-256 matches the standard test vectors", "[scene][json]") {
  CHECK(Sha256Hex("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  CHECK(Sha256Hex("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  auto path = std::filesystem::temp_directory_path() / "villa_scene_sha_test.txt";
  REQUIRE(WriteFileAtomic(path, "abc").ok());
  auto hash = FileSha256(path);
  REQUIRE(hash.ok());
  CHECK(*hash == Sha256Hex("abc"));
  std::filesystem::remove(path);
  auto missing = FileSha256(path);
  REQUIRE_FALSE(missing.ok());
  CHECK(missing.error().find(path.string()) != std::string::npos);
}

TEST_CASE("the strict reader builds the document itself: members in file order, duplicates named, nesting kept", "[scene][json][issue33]") {
  const std::string text = R"({"b":1,"a":{"y":[1,2.5,{"k":"v"}],"x":null},"c":[[],{}],"d":true})";
  auto j = ParseStrictJson(text, "t.json");
  REQUIRE(j.ok());
  CHECK(j->dump() == text);  // appended members keep the file's order
  auto dup = ParseStrictJson(R"({"a":{"x":1,"y":2,"x":3}})", "t.json");
  REQUIRE_FALSE(dup.ok());
  CHECK(dup.error() == "t.json: a.x: duplicate key");
  auto spelled = ParseStrictJson(R"({"a":[1,2,1e3]})", "t.json");
  REQUIRE_FALSE(spelled.ok());
  CHECK(spelled.error() == "t.json: a[2]: 1e3: numbers are written without an exponent");
  // One object of many members (a scene of 20,000 objects is keyed by id) reads whole and in order.
  std::string many = "{";
  for (int i = 0; i < 20000; ++i) many += (i ? ",\"" : "\"") + std::to_string(i) + "\":" + std::to_string(i);
  many += "}";
  auto big = ParseStrictJson(many, "many.json");
  REQUIRE(big.ok());
  REQUIRE(big->size() == 20000);
  CHECK(big->begin().key() == "0");
  CHECK((*big)["19999"] == 19999);
}
