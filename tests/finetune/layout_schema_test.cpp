// The layout JSON Schema given to constrained decoders: accepts every canonical answer, refuses what the
// format forbids, and is shaped as the servers expect.
#include <catch2/catch.hpp>

#include "finetune/layout_schema.h"
#include "finetune_test_util.h"
#include "layout/layout_io.h"

using namespace villa;
using namespace villa::testing;

namespace {
Json CanonicalFixture(const std::string& name) { return Json::parse(LayoutToString(LoadFixture(name), -1)); }
}  // namespace

TEST_CASE("The schema accepts the canonical text of valid layouts", "[finetune][schema]") {
  CHECK(MatchLayoutJsonSchema(CanonicalFixture("one_floor.json")).ok());
  CHECK(MatchLayoutJsonSchema(CanonicalFixture("two_floors.json")).ok());
  // Decimals and negative coordinates as the canonical writer prints them.
  Json moved = Json::parse(LayoutToString(Moved(LoadFixture("two_floors.json"), -3.25, 0.5), -1));
  CHECK(MatchLayoutJsonSchema(moved).ok());
}

TEST_CASE("The schema refuses what the format forbids", "[finetune][schema]") {
  const Json good = CanonicalFixture("two_floors.json");
  auto refuses = [&](const std::function<void(Json&)>& plant, const std::string& expect_in_message) {
    Json bad = good;
    plant(bad);
    Status s = MatchLayoutJsonSchema(bad);
    REQUIRE_FALSE(s.ok());
    INFO(s.error());
    CHECK(s.error().find(expect_in_message) != std::string::npos);
  };
  refuses([](Json& j) { j.erase("opens"); }, "missing key \"opens\"");
  refuses([](Json& j) { j["extra"] = Json::object(); }, "[\"extra\"]: unexpected key");
  refuses([](Json& j) { j["rooms"]["kitchen_3/0"] = j["rooms"]["kitchen_0/0"]; }, "[\"rooms\"][\"kitchen_3/0\"]: name does not match");
  refuses([](Json& j) { j["rooms"]["garage_0/0"] = j["rooms"]["kitchen_0/0"]; }, "[\"garage_0/0\"]: name does not match");
  refuses([](Json& j) { j["rooms"]["kitchen_0/0"]["shape"] = "shapely.box(4, 0, 8, 4.125)"; }, "does not match");
  refuses([](Json& j) { j["rooms"]["kitchen_0/0"]["shape"] = "shapely.box(4e0, 0, 8, 4)"; }, "does not match");
  refuses([](Json& j) { j["rooms"]["kitchen_0/0"]["shape"] = "shapely.Polygon([(0, 0), (1, 0)])"; }, "does not match");
  refuses([](Json& j) { j["rooms"]["kitchen_0/0"]["shape"] = "shapely.LineString([(0, 0), (1, 0)])"; }, "does not match");
  refuses([](Json& j) { j["doors"]["living0_kitchen0"].erase("level"); }, "missing key \"level\"");
  refuses([](Json& j) { j["doors"]["living0_kitchen0"]["level"] = 3; }, "is not one of");
  refuses([](Json& j) { j["entrance"]["main_door"]["level"] = 1; }, "is not one of [0]");
  refuses([](Json& j) { j["windows"]["kitchen0_window"]["is_panoramic"] = 2; }, "is not one of");
  refuses([](Json& j) { j["windows"]["kitchen0_window"]["is_panoramic"] = true; }, "expected integer");
  refuses([](Json& j) { j["doors"]["living0_kitchen0"]["shape"] = "shapely.box(0, 0, 1, 1)"; }, "does not match");
  refuses([](Json& j) { j["doors"]["a door"] = j["doors"]["living0_kitchen0"]; }, "name does not match");
}

TEST_CASE("The schema is shaped for OpenAI-style response_format", "[finetune][schema]") {
  const Json& format = LayoutResponseFormat();
  CHECK(format["type"] == "json_schema");
  CHECK(format["json_schema"]["name"] == "villa_layout");
  CHECK(format["json_schema"]["strict"] == true);
  CHECK(format["json_schema"]["schema"] == LayoutJsonSchema());
  const Json& schema = LayoutJsonSchema();
  CHECK(schema["type"] == "object");
  CHECK(schema["additionalProperties"] == false);
  CHECK(schema["required"] == Json::array({"rooms", "entrance", "doors", "opens", "windows", "interiors"}));
  // Properties in canonical order (grammar engines fix the key order to the schema's).
  std::vector<std::string> order;
  for (const auto& [key, value] : schema["properties"].items()) order.push_back(key);
  CHECK(order == std::vector<std::string>{"rooms", "entrance", "doors", "opens", "windows", "interiors"});
  std::vector<std::string> window_keys;
  for (const auto& [key, value] : schema["properties"]["windows"]["additionalProperties"]["properties"].items()) window_keys.push_back(key);
  CHECK(window_keys == std::vector<std::string>{"shape", "is_panoramic", "level"});
  for (const auto& [key, group] : schema["properties"].items()) {
    INFO(key);
    CHECK(group["type"] == "object");
    CHECK(group["propertyNames"].contains("pattern"));
    CHECK(group["additionalProperties"]["additionalProperties"] == false);
  }
}
