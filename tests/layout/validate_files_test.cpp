// ValidateFiles (the library behind `villa validate`): the record formats it reads, the counts per rule,
// and the report JSON.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "layout/validate_files.h"
#include "test_support.h"

using namespace villa;
using namespace villa::test;

namespace {
std::string Compact(const std::string& fixture) {
  std::ifstream in(FixturePath(fixture));
  return Json::parse(std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>())).dump();
}
}  // namespace

TEST_CASE("a layout is read from every record format a fine-tune or a model answer comes in", "[validate_files]") {
  const std::string valid = Compact("house_one_floor.json");
  const Json as_text = valid;  // the layout as a JSON string
  const std::vector<Json> records = {
      Json::parse(valid),
      Json{{"id", "x"}, {"layout", Json::parse(valid)}},
      Json{{"layout", as_text}},
      Json{{"messages", {Json{{"role", "user"}, {"content", "a house"}}, Json{{"role", "assistant"}, {"content", as_text}}}}},
      Json{{"conversations", {Json{{"from", "human"}, {"value", "a house"}}, Json{{"from", "gpt"}, {"value", as_text}}}}},
      Json{{"instruction", "a house"}, {"output", as_text}},
  };
  for (const Json& record : records) {
    INFO(record.dump().substr(0, 80));
    auto layout = LayoutOfRecord(record, "f.jsonl:1");
    REQUIRE(layout.ok());
    CHECK(layout->rooms.size() == 6);  // the fixture's rooms
  }
  auto no_answer = LayoutOfRecord(Json{{"messages", {Json{{"role", "user"}, {"content", "a house"}}}}}, "f.jsonl:2");
  REQUIRE_FALSE(no_answer.ok());
  CHECK(no_answer.error() == "f.jsonl:2: messages: no assistant answer");
  auto bad_answer = LayoutOfRecord(Json{{"output", "{\"rooms\": 3}"}}, "f.jsonl:3");
  REQUIRE_FALSE(bad_answer.ok());
  CHECK_THAT(bad_answer.error(), Catch::StartsWith("f.jsonl:3: output"));
  auto neither = LayoutOfRecord(Json{{"id", "y"}}, "f.jsonl:4");
  REQUIRE_FALSE(neither.ok());
  CHECK_THAT(neither.error(), Catch::Contains("a record needs the layout keys"));
}

TEST_CASE("files are checked in order, with violations counted per rule", "[validate_files]") {
  const auto dir = std::filesystem::temp_directory_path() / ("villa_validate_files_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const auto stream = dir / "outputs.jsonl";
  {
    std::ofstream out(stream);
    out << "{\"id\": \"a\", \"layout\": " << Compact("house_one_floor.json") << "}\n"
        << "{\"id\": \"b\", \"layout\": {\"rooms\": \n"
        << "{\"id\": \"c\", \"layout\": " << Compact("rule9_kitchen_without_window.json") << "}\n";
  }
  const ValidateFilesSummary summary = ValidateFiles({FixturePath("villa_three_floors.json"), stream.string()});
  REQUIRE(summary.count() == 4);
  CHECK(summary.layouts[0].source == FixturePath("villa_three_floors.json"));
  CHECK(summary.layouts[1].id == "a");
  CHECK(summary.layouts[2].parse_error.has_value());
  CHECK(summary.layouts[2].source == stream.string() + ":2");
  CHECK(summary.layouts[3].id == "c");
  CHECK(summary.valid == 2);
  CHECK(summary.unparsable == 1);
  CHECK_FALSE(summary.all_valid());
  CHECK(summary.layouts_by_rule[9] == 1);
  CHECK(summary.violations_by_rule[9] >= 1);
  CHECK(summary.metrics.outputs == 4);
  CHECK(summary.metrics.format_successes == 3);  // the unparsable one counts against FSR
  const Json report = ValidateFilesReportJson(summary);
  REQUIRE(report["layouts"].size() == 4);
  CHECK(report["layouts"][3]["violations"][0]["rule"] == 9);
  CHECK(report["summary"]["count"] == 4);
  CHECK(report["summary"]["unparsable"] == 1);
  CHECK(report["summary"]["rules"]["9"]["layouts"] == 1);
  std::filesystem::remove_all(dir);
}
