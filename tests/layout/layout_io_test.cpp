// Reading whole layouts: strictness, and error messages that name the source, the JSON path and the value.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "layout/layout_io.h"
#include "test_support.h"

using namespace villa;
using villa::test::LayoutError;

namespace {
const char* kMinimal = R"json({
  "rooms": {"kitchen_0/0": {"shape": "shapely.box(0, 0, 4, 4)"},
            "staircase-room_0/0": {"shape": "shapely.box(4, 0, 8, 4)"}},
  "entrance": {"main": {"shape": "shapely.LineString([(1, 0), (3, 0)])", "level": 0}},
  "doors": {},
  "opens": {"k_u": {"shape": "shapely.LineString([(4, 1), (4, 3)])"}},
  "windows": {"w": {"shape": "shapely.LineString([(0, 1), (0, 2)])", "is_panoramic": 1, "level": 0}},
  "interiors": {}
})json";

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}
}  // namespace

TEST_CASE("a layout reads into rooms and elements, aliases and missing levels resolved", "[io]") {
  auto r = ParseLayoutText(kMinimal, "layout.json");
  INFO((r ? "" : r.error()));
  REQUIRE(r.ok());
  const Layout& layout = *r;
  REQUIRE(layout.rooms.size() == 2);
  CHECK(layout.rooms[1].category == Category::kUtilityRoom);  // staircase-room alias
  CHECK(layout.rooms[1].name() == "utility-room_0/0");
  REQUIRE(layout.opens.size() == 1);
  CHECK(layout.opens[0].level == kAllLevels);
  REQUIRE(layout.windows.size() == 1);
  CHECK(layout.windows[0].panoramic);
  // Written canonically and read back: the same layout.
  auto again = ParseLayoutText(LayoutToString(*r), "again");
  REQUIRE(again.ok());
  CHECK(LayoutToString(*again) == LayoutToString(*r));
}

TEST_CASE("layout errors name the JSON path and the bad value", "[io]") {
  std::string text = kMinimal;
  CHECK(LayoutError(Replace(text, "shapely.box(0, 0, 4, 4)", "shapely.box(0, 0, 4")) ==
        "layout.json: rooms[\"kitchen_0/0\"].shape: expected ',' at the end of \"shapely.box(0, 0, 4\"");
  CHECK_THAT(LayoutError(Replace(text, "\"kitchen_0/0\"", "\"kitchen_0\"")),
             Catch::StartsWith("layout.json: rooms[\"kitchen_0\"]: bad room name \"kitchen_0\""));
  CHECK_THAT(LayoutError(Replace(text, "\"kitchen_0/0\"", "\"pantry_0/0\"")),
             Catch::StartsWith("layout.json: rooms[\"pantry_0/0\"]: bad room name"));
  CHECK(LayoutError(Replace(text, "\"is_panoramic\": 1, \"level\": 0", "\"is_panoramic\": 1, \"level\": -1")) ==
        "layout.json: windows[\"w\"].level: expected an integer >= 0, got -1");
  CHECK(LayoutError(Replace(text, "\"is_panoramic\": 1, \"level\": 0", "\"is_panoramic\": 1, \"level\": \"one\"")) ==
        "layout.json: windows[\"w\"].level: expected an integer >= 0, got \"one\"");
  CHECK(LayoutError(Replace(text, "[(1, 0), (3, 0)])\", \"level\": 0", "[(1, 0), (3, 0)])\", \"level\": 1")) ==
        "layout.json: entrance[\"main\"].level: the entrance is on level 0, got 1");
  CHECK(LayoutError(Replace(text, "\"is_panoramic\": 1", "\"is_panoramic\": 2")) ==
        "layout.json: windows[\"w\"].is_panoramic: expected 0 or 1, got 2");
}

TEST_CASE("unknown and missing top-level keys are errors", "[io]") {
  std::string text = kMinimal;
  CHECK(LayoutError(Replace(text, "\"doors\": {},", "\"doors\": {}, \"stairs\": {},")) ==
        "layout.json: unknown key \"stairs\" (a layout has exactly rooms, entrance, doors, opens, windows, interiors)");
  CHECK(LayoutError(Replace(text, "\"doors\": {},", "")) ==
        "layout.json: missing key \"doors\" (a layout has exactly rooms, entrance, doors, opens, windows, interiors)");
  CHECK_THAT(LayoutError("[1, 2]"), Catch::StartsWith("layout.json: expected a JSON object"));
  CHECK_THAT(LayoutError("{\"rooms\": "), Catch::StartsWith("layout.json: not valid JSON"));
}

TEST_CASE("JSONL errors carry file and line numbers", "[io]") {
  auto dir = std::filesystem::temp_directory_path() / ("villa_layout_io_test_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  auto path = dir / "stream.jsonl";
  std::string one_line = kMinimal;
  std::erase(one_line, '\n');
  {
    std::ofstream out(path);
    out << one_line << "\n\n{not json}\n"
        << "{\"id\": \"b\", \"layout\": " << Replace(one_line, "shapely.box(4, 0, 8, 4)", "shapely.box(4, 0, 8)") << "}\n";
  }
  std::vector<std::string> bad;
  std::vector<int> lines;
  std::vector<std::string> errors;
  Status status = ReadJsonl(
      path,
      [&](const Json& record, int line) {
        lines.push_back(line);
        auto layout = LayoutFromRecord(record, path.string() + ":" + std::to_string(line));
        if (!layout) errors.push_back(layout.error());
        return true;
      },
      [&](const std::string& message) { bad.push_back(message); });
  REQUIRE(status.ok());
  CHECK(lines == std::vector<int>{1, 4});
  REQUIRE(bad.size() == 1);
  CHECK_THAT(bad[0], Catch::StartsWith(path.string() + ":3: not valid JSON"));
  REQUIRE(errors.size() == 1);
  CHECK(errors[0] == path.string() + ":4: layout: rooms[\"staircase-room_0/0\"].shape: expected ',' at column 20 of \"shapely.box(4, 0, 8)\"");
  // Without on_bad_line the first bad line stops the read with its line number.
  Status stopped = ReadJsonl(path, [](const Json&, int) { return true; });
  REQUIRE_FALSE(stopped.ok());
  CHECK_THAT(stopped.error(), Catch::StartsWith(path.string() + ":3: "));
  std::filesystem::remove_all(dir);
}
