// What the validator says about faults the format can express (issue 17): a bow-tie room names its
// crossing, a room without width says so, and an element within the rounding of two decimals (0.01 m) of
// a wall at any angle lies on it; numbers with more decimals are read with a note, not a violation.
#include <catch2/catch.hpp>

#include <algorithm>

#include "layout/geometry.h"
#include "layout/topology.h"
#include "test_support.h"

using namespace villa;
using namespace villa::test;

namespace {

// One room with a slanted north wall from (9, 4.37) to (0, 6.91) (164.24 degrees), an entrance on its
// south wall and the window given.
std::string SlantedRoom(const std::string& window) {
  return R"J({"rooms": {"living-room_0/0": {"shape": "shapely.Polygon([(0, 0), (9, 0), (9, 4.37), (0, 6.91)])"}},
  "entrance": {"main": {"shape": "shapely.LineString([(1, 0), (2.2, 0)])", "level": 0}},
  "doors": {}, "opens": {},
  "windows": {"w": {"shape": "shapely.LineString()J" + window + R"J()", "is_panoramic": 0, "level": 0}},
  "interiors": {}})J";
}

}  // namespace

TEST_CASE("a bow-tie room is self-intersecting at its crossing point, clockwise rooms stay valid", "[validate][rule1]") {
  Layout layout = Fixture("house_one_floor.json");
  RoomNamed(layout, "office_0/0").polygon = {{8, 5}, {12, 9}, {12, 5}, {8, 9}};  // crosses at (10, 7)
  ValidationReport report = ValidateLayout(layout);
  INFO(Describe(report));
  CHECK(Find(report, "office_0/0 is not a valid polygon: self-intersecting at (10, 7)"));
  CHECK(RingProblem({{0, 0}, {4, 4}, {4, 0}, {0, 4}}) == "self-intersecting at (2, 2)");
  // A figure eight whose lobes differ (Boost.Geometry called this "wrong orientation" too).
  CHECK(RingProblem({{0, 0}, {6, 3}, {6, 0}, {0, 2}}) == "self-intersecting at (2.4, 1.2)");
  // Clockwise is the same room walked the other way.
  Layout clockwise = Fixture("house_one_floor.json");
  Ring& office = RoomNamed(clockwise, "office_0/0").polygon;
  std::reverse(office.begin(), office.end());
  CHECK(RingProblem(office).empty());
  CHECK(ValidateLayout(clockwise).valid());
}

TEST_CASE("a room without width is reported as zero width, naming it", "[validate][rule1]") {
  Layout layout = Fixture("house_one_floor.json");
  RoomNamed(layout, "office_0/0").polygon = {{8, 5}, {8, 5}, {8, 9}, {8, 9}};  // shapely.box(8, 5, 8, 9)
  ValidationReport report = ValidateLayout(layout);
  INFO(Describe(report));
  CHECK(Find(report, "office_0/0 is not a valid polygon: zero width (every corner at x = 8)"));
  CHECK(RingProblem({{0, 0}, {2, 2}, {5, 5}}) == "zero width (every corner on one line)");
}

TEST_CASE("a window 0.25 mm off a slanted wall lies on it, one 2 cm off does not", "[validate][rule3][tolerance]") {
  // (6.06, 5.2) and (4.43, 5.66) are the two-decimal points nearest the wall there: 0.257 and 0.235 mm off.
  Layout on = FromText(SlantedRoom("[(6.06, 5.2), (4.43, 5.66)]"));
  ValidationReport report = ValidateLayout(on);
  INFO(Describe(report));
  CHECK(report.valid());
  CHECK(report.notes.empty());
  CHECK(PointSegmentDistance({6.06, 5.2}, {{9, 4.37}, {0, 6.91}}) == Approx(0.000257).margin(1e-6));
  // The floor plan, the annotator and the furnishing ask the same question through layout/topology.h.
  CHECK(RoomsHolding(on, on.windows[0]) == std::vector<int>{0});

  Layout off = FromText(SlantedRoom("[(6.06, 5.18), (4.43, 5.64)]"));
  ValidationReport far = ValidateLayout(off);
  REQUIRE(far.violations.size() == 1);
  CHECK(far.violations[0].rule == 3);
  CHECK_THAT(far.violations[0].message, Catch::Contains("0.02 m off the nearest outside wall"));
}

TEST_CASE("an interior wall on a slanted shared boundary covers it within the tolerance", "[validate][rule4][tolerance]") {
  // Two rooms split by a slanted wall from (4, 0) to (5.5, 6); the interior wall and the door run along it
  // with rounded points (the door 2.4 mm off) and the wall stops 4 mm short of both ends.
  Layout layout = FromText(R"J({"rooms": {
      "living-room_0/0": {"shape": "shapely.Polygon([(0, 0), (4, 0), (5.5, 6), (0, 6)])"},
      "bedroom_0/0": {"shape": "shapely.Polygon([(4, 0), (9, 0), (9, 6), (5.5, 6)])"}},
    "entrance": {"main": {"shape": "shapely.LineString([(1, 0), (2.2, 0)])", "level": 0}},
    "doors": {"d": {"shape": "shapely.LineString([(4.51, 2.05), (4.77, 3.09)])", "level": 0}},
    "opens": {},
    "windows": {},
    "interiors": {"wall": {"shape": "shapely.LineString([(4.001, 0.004), (5.499, 5.996)])", "level": 0}}})J");
  ValidationReport report = ValidateLayout(layout);
  INFO(Describe(report));
  CHECK(report.valid());
  // The interior wall's points have three decimals: read, with a note.
  REQUIRE(report.notes.size() == 1);
  CHECK(report.notes[0] == "4 numbers have more than two decimals (the first: interiors[\"wall\"] x = 4.001); read as "
                           "written, and anything within 0.01 m of a wall lies on it");
}

TEST_CASE("the on-wall tolerance is the format's rounding, and only there", "[validate][tolerance]") {
  CHECK(kOnWallTolerance == 0.01);
  CHECK(ValidateOptions{}.on_wall_tolerance == kOnWallTolerance);
  CHECK(kTolerance == 1e-6);  // lengths, areas and room geometry stay exact
}
