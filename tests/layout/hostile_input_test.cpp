// Layout files written to break the reader (issue 17): coordinates far outside any building, rooms without
// width, nesting that overflows a recursive walk, absurd counts, duplicate keys, values echoed at length,
// and the one rule for "is_panoramic". Each is refused with a message naming the room or element and the
// value, before any geometry work.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "layout/validate_files.h"
#include "test_support.h"

using namespace villa;
using namespace villa::test;

namespace {

// A valid one-room layout whose room shape, window and door line are filled in by the test.
std::string OneRoom(const std::string& room_shape, const std::string& window = "shapely.LineString([(0, 1), (0, 2)])",
                    const std::string& window_extra = ", \"is_panoramic\": 0") {
  return R"J({"rooms": {"living-room_0/0": {"shape": ")J" + room_shape + R"J("}},
  "entrance": {"main": {"shape": "shapely.LineString([(1, 0), (2, 0)])", "level": 0}},
  "doors": {}, "opens": {},
  "windows": {"w": {"shape": ")J" + window + R"J(", "level": 0)J" + window_extra + R"J(}},
  "interiors": {}})J";
}

}  // namespace

TEST_CASE("coordinates outside the building extent are refused naming the room or element and the value", "[io][extent]") {
  CHECK(LayoutError(OneRoom("shapely.box(0, 0, 1e12, 4)")) ==
        "layout.json: rooms[\"living-room_0/0\"].shape: x = 1e+12 is outside the building extent "
        "(|x| and |y| at most 10000 m)");
  CHECK(LayoutError(OneRoom("shapely.box(0, 0, 4, 4)", "shapely.LineString([(0, 1), (-1000000000000, 2)])")) ==
        "layout.json: windows[\"w\"].shape: x = -1e+12 is outside the building extent (|x| and |y| at most 10000 m)");
  CHECK(LayoutError(OneRoom("shapely.Polygon([(0, 0), (4, 0), (4, 10000.5)])")) ==
        "layout.json: rooms[\"living-room_0/0\"].shape: y = 10000.5 is outside the building extent "
        "(|x| and |y| at most 10000 m)");
  // The extent itself is fine.
  CHECK(ParseLayoutText(OneRoom("shapely.box(-10000, -10000, 10000, 10000)"), "ok").ok());
}

TEST_CASE("a room narrower than 1 cm is refused, a zero-width box as zero width", "[io][extent]") {
  CHECK(LayoutError(OneRoom("shapely.box(0, 0, 1e-320, 4)")) ==
        "layout.json: rooms[\"living-room_0/0\"].shape: 9.99989e-321 m wide (x from 0 to 9.99989e-321); a room is at least 0.01 m "
        "wide and deep");
  CHECK(LayoutError(OneRoom("shapely.box(3, 0, 3, 4)")) ==
        "layout.json: rooms[\"living-room_0/0\"].shape: zero width (every corner at x = 3)");
  CHECK(LayoutError(OneRoom("shapely.box(0, 2, 5, 2.004)")) ==
        "layout.json: rooms[\"living-room_0/0\"].shape: 0.004 m deep (y from 2 to 2.004); a room is at least 0.01 m "
        "wide and deep");
}

TEST_CASE("JSON nested deeper than the limit is refused, never a crash", "[io][depth]") {
  CHECK(LayoutError(std::string(100000, '[')) == "layout.json: line 1, column 65: nested deeper than 64 levels");
  const std::string deep_room = R"({"rooms": {"kitchen_0/0": )" + std::string(200000, '[') + std::string(200000, ']') +
                                R"(}, "entrance": {}, "doors": {}, "opens": {}, "windows": {}, "interiors": {}})";
  CHECK(LayoutError(deep_room) == "layout.json: line 1, column 89: nested deeper than 64 levels");
  // A JSONL record and a .json file through the files `villa validate` reads.
  auto dir = std::filesystem::temp_directory_path() / ("villa_hostile_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  {
    std::ofstream(dir / "deep.jsonl") << "{\"layout\": " << std::string(100000, '[') << "\n";
    std::ofstream(dir / "deep.json") << deep_room;
  }
  ValidateFilesSummary summary = ValidateFiles({(dir / "deep.jsonl").string(), (dir / "deep.json").string()});
  REQUIRE(summary.count() == 2);
  CHECK(summary.layouts[0].parse_error == (dir / "deep.jsonl").string() + ":1: line 1, column 75: nested deeper than 64 levels");
  CHECK(summary.layouts[1].parse_error == (dir / "deep.json").string() + ": line 1, column 89: nested deeper than 64 levels");
  std::filesystem::remove_all(dir);
}

TEST_CASE("absurd room, element and corner counts are refused before any shape is read", "[io][counts]") {
  // Built in streams: GCC 12 warns (-Wrestrict, a false alarm) on "text" + std::to_string(i) in loops here.
  std::ostringstream rooms_text;
  for (int i = 0; i <= kMaxRooms; ++i) rooms_text << (i ? "," : "") << "\"bedroom_0/" << i << "\": {\"shape\": \"x\"}";
  const std::string rooms = rooms_text.str();
  CHECK(LayoutError("{\"rooms\": {" + rooms + R"(}, "entrance": {}, "doors": {}, "opens": {}, "windows": {}, "interiors": {}})") ==
        "layout.json: rooms: 1001 rooms; a layout has at most 1000 (docs/RULES.md)");
  std::ostringstream doors_text;
  for (int i = 0; i < kMaxElements / 2 + 1; ++i) doors_text << (i ? "," : "") << "\"d" << i << "\": {}";
  const std::string doors = doors_text.str();
  CHECK(LayoutError(R"({"rooms": {}, "entrance": {}, "doors": {)" + doors + R"(}, "opens": {}, "windows": {)" + doors +
                R"(}, "interiors": {}})") ==
        "layout.json: 100002 elements (entrance, doors, opens, windows, interiors); a layout has at most 100000 "
        "(docs/RULES.md)");
  std::ostringstream corners_text;
  for (int i = 0; i <= kMaxRingCorners; ++i) corners_text << (i ? ", (" : "(") << i % 2 << ", " << i << ")";
  const std::string corners = corners_text.str();
  CHECK(LayoutError(OneRoom("shapely.Polygon([" + corners + "])")) ==
        "layout.json: rooms[\"living-room_0/0\"].shape: 1001 corners; a room has at most 1000 (docs/RULES.md)");
}

TEST_CASE("a duplicate room key is an error naming the key and both lines", "[io][duplicates]") {
  const std::string text =
      "{\"rooms\": {\n"
      "  \"kitchen_0/0\": {\"shape\": \"shapely.box(0, 0, 4, 4)\"},\n"
      "  \"kitchen_0/0\": {\"shape\": \"shapely.box(4, 0, 8, 4)\"}},\n"
      " \"entrance\": {}, \"doors\": {}, \"opens\": {}, \"windows\": {}, \"interiors\": {}}";
  CHECK(LayoutError(text) == "layout.json: rooms: duplicate key \"kitchen_0/0\" on lines 2 and 3");
}

TEST_CASE("is_panoramic: missing means 0, a number equal to 0 or 1 or a boolean is read, anything else names the value", "[io][panoramic]") {
  auto read = [](const std::string& extra) { return ParseLayoutText(OneRoom("shapely.box(0, 0, 4, 4)", "shapely.LineString([(0, 1), (0, 2)])", extra), "layout.json"); };
  REQUIRE(read("").ok());
  CHECK_FALSE(read("")->windows[0].panoramic);
  for (const char* yes : {", \"is_panoramic\": 1", ", \"is_panoramic\": 1.0", ", \"is_panoramic\": true"}) {
    auto r = read(yes);
    INFO(yes << (r ? "" : ": " + r.error()));
    REQUIRE(r.ok());
    CHECK(r->windows[0].panoramic);
  }
  for (const char* no : {", \"is_panoramic\": 0", ", \"is_panoramic\": 0.0", ", \"is_panoramic\": false"}) {
    auto r = read(no);
    REQUIRE(r.ok());
    CHECK_FALSE(r->windows[0].panoramic);
  }
  CHECK(read(", \"is_panoramic\": \"1\"").error() == "layout.json: windows[\"w\"].is_panoramic: expected 0 or 1, got \"1\"");
  CHECK(read(", \"is_panoramic\": 0.5").error() == "layout.json: windows[\"w\"].is_panoramic: expected 0 or 1, got 0.5");
  CHECK(read(", \"is_panoramic\": null").error() == "layout.json: windows[\"w\"].is_panoramic: expected 0 or 1, got null");
}

TEST_CASE("values quoted in errors are cut to 80 characters", "[io][excerpt]") {
  const std::string huge(10000000, 'q');
  // A 10 MB room name and a 10 MB shape string: each appears once, cut.
  std::string name_error = LayoutError(R"J({"rooms": {")J" + huge + R"J(": {"shape": "shapely.box(0, 0, 4, 4)"}}, "entrance": {},
      "doors": {}, "opens": {}, "windows": {}, "interiors": {}})J");
  CHECK(name_error.size() < 600);
  CHECK_THAT(name_error, Catch::StartsWith("layout.json: rooms[\"" + std::string(77, 'q') + "...\"]: bad room name \"" +
                                           std::string(77, 'q') + "...\""));
  std::string shape_error = LayoutError(OneRoom("shapely.box(0, 0, 4, 4" + huge + ")"));
  CHECK(shape_error.size() < 400);
  CHECK(shape_error == "layout.json: rooms[\"living-room_0/0\"].shape: expected ')' at column 23 of \"shapely.box(0, 0, 4, 4" +
                           std::string(55, 'q') + "...\"");
  // An element name and an unknown key.
  std::string key_error = LayoutError(R"J({"rooms": {}, "entrance": {}, "doors": {"d": {"shape": "shapely.LineString([(0, 0), (1, 0)])", ")J" +
                                  huge + R"J(": 1}}, "opens": {}, "windows": {}, "interiors": {}})J");
  CHECK(key_error.size() < 400);
  CHECK_THAT(key_error, Catch::StartsWith("layout.json: doors[\"d\"]: unknown key \"" + std::string(77, 'q') + "...\""));
}
