// ValidateLayout: one fixture per rule that breaks exactly that rule, the valid fixtures, the paper's own
// example, and the edge cases of each rule on layouts changed in code.
#include <catch2/catch.hpp>

#include <cmath>

#include "layout/geometry.h"
#include "test_support.h"

using namespace villa;
using namespace villa::test;

TEST_CASE("valid fixtures pass every rule", "[validate]") {
  for (const char* name : {"house_one_floor.json", "house_two_floors.json", "bungalow_angled.json", "villa_three_floors.json"}) {
    Layout layout = Fixture(name);
    ValidationReport report = ValidateLayout(layout);
    INFO(name << "\n" << Describe(report));
    CHECK(report.valid());
    CHECK(report.geometric_ok());
  }
}

TEST_CASE("valid fixtures: each floor is one polygon without holes by Boost.Geometry's union too", "[validate]") {
  for (const char* name : {"house_one_floor.json", "house_two_floors.json", "bungalow_angled.json", "villa_three_floors.json"}) {
    Layout layout = Fixture(name);
    double lower_area = INFINITY;
    for (int level = 0; level < layout.LevelCount(); ++level) {
      std::vector<Ring> rings;
      double sum = 0;
      for (int r : layout.RoomsOnLevel(level)) rings.push_back(layout.rooms[r].polygon), sum += Area(layout.rooms[r].polygon);
      auto footprint = UnionOfRings(rings);
      INFO(name << " level " << level);
      REQUIRE(footprint.size() == 1);
      CHECK(footprint[0].holes.empty());
      CHECK(Area(footprint[0].outer) == Approx(sum));
      CHECK(sum <= lower_area);
      lower_area = sum;
    }
  }
}

TEST_CASE("the villa fixture has three floors and angled walls", "[validate]") {
  Layout villa = Fixture("villa_three_floors.json");
  CHECK(villa.LevelCount() == 3);
  int angled = 0;
  for (const auto& room : villa.rooms) angled += !IsAxisAlignedBox(room.polygon, kTolerance) && room.polygon.size() != 6;
  CHECK(angled >= 3);  // the kitchen's chamfer and two triangular balconies
  Layout bungalow = Fixture("bungalow_angled.json");
  CHECK_FALSE(IsAxisAlignedBox(RoomNamed(bungalow, "living-room_0/0").polygon, kTolerance));
}

namespace {
struct RuleFixture {
  const char* file;
  int rule;
  std::vector<std::string> messages;
  std::vector<double> figures;
};
}  // namespace

TEST_CASE("each rule fixture breaks exactly its rule, with the expected message and figure", "[validate]") {
  const std::vector<RuleFixture> fixtures = {
      {"rule1_courtyard_hole.json", 1,
       {"level 0 footprint has a hole of 16.00 m2 enclosed by living-room_0/0, dining-room_0/0, kitchen_0/0, bathroom_0/0, bedroom_0/0"},
       {16.0}},
      {"rule2_upper_floor_overhang.json", 2,
       {"level 1 footprint reaches 2.25 m2 beyond level 0's footprint (balcony_1/0)"},
       {2.25}},
      {"rule3_door_off_boundary.json", 3,
       {"door living0_dining0 touches no room of level 0; it is 0.40 m off the nearest shared boundary, of living-room_0/0 and dining-room_0/0"},
       {0.4}},
      {"rule4_missing_wall.json", 4,
       {"the boundary between bathroom_0/0 and office_0/0 has no interior wall or open for 4.00 m (first gap from (8, 5) to (8, 9))"},
       {4.0}},
      {"rule5_narrow_door.json", 5, {"door living0_bathroom0 is 0.60 m wide; doors need at least 0.80 m"}, {0.6}},
      {"rule5_narrow_room.json", 5, {"office_0/0 is 0.90 m wide at its narrowest; rooms need at least 1.00 m"}, {0.9}},
      {"rule6_seven_rooms.json", 6, {"level 0 has 7 rooms; at most 6 a floor"}, {7}},
      {"rule7_staircase_not_square.json", 7,
       {"utility-room_0/0 is 4.00 x 3.50 m; the staircase room is 4 x 4 m",
        "utility-room_1/0 is 4.00 x 3.50 m; the staircase room is 4 x 4 m"},
       {0.5, 0.5}},
      {"rule8_unreachable_room.json", 8,
       {"children-room_1/0 is not reachable from the entrance", "balcony_1/0 is not reachable from the entrance"},
       {0, 0}},
      {"rule9_kitchen_without_window.json", 9, {"kitchen_0/0 has no window"}, {0}},
      {"rule10_nested_room_open.json", 10,
       {"bathroom_0/0 is reached only from living-room_0/0, through open living0_bathroom0; a nested room needs a door"},
       {0}},
  };
  for (const auto& f : fixtures) {
    ValidationReport report = ValidateLayout(Fixture(f.file));
    INFO(f.file << "\n" << Describe(report));
    CHECK(RulesOf(report) == std::set<int>{f.rule});
    REQUIRE(report.violations.size() == f.messages.size());
    for (std::size_t i = 0; i < f.messages.size(); ++i) {
      CHECK(report.violations[i].message == f.messages[i]);
      CHECK(report.violations[i].figure == Approx(f.figures[i]).margin(1e-9));
    }
    CHECK(report.geometric_ok() == (f.rule > 5));
  }
}

TEST_CASE("the paper's own example is invalid: split ground floor, doors on one room", "[validate][paper]") {
  ValidationReport report = ValidateLayout(Fixture("paper_example.json"));
  INFO(Describe(report));
  CHECK_FALSE(report.valid());
  CHECK_FALSE(report.geometric_ok());
  // The ground floor falls apart: the kitchen row (y 0..4) and the living room (y 8..16) never touch.
  const Violation* split = Find(report,
                                "level 0 rooms do not form one footprint: 2 separate pieces, utility-room_0/0 + kitchen_0/0 + "
                                "dining-room_0/0 (44.00 m2) and living-room_0/0 + bathroom_0/0 (172.00 m2)");
  REQUIRE(split);
  CHECK(split->rule == 1);
  CHECK(split->figure == Approx(44.0));  // 16 + 16 + 12 (the dining trapezoid (4 + 2) / 2 * 4)
  // Two doors lie on a single room's wall: living0_kitchen0 on the kitchen's top edge y=4 (the living room
  // starts at y=8), living0_bathroom0 on the bathroom's west edge x=10 (nothing west of it).
  const Violation* kitchen_door = Find(report,
                                       "door living0_kitchen0 touches only kitchen_0/0; it is 3.00 m off the nearest shared "
                                       "boundary, of utility-room_0/0 and kitchen_0/0");
  const Violation* bathroom_door = Find(report,
                                        "door living0_bathroom0 touches only bathroom_0/0; it is 3.00 m off the nearest "
                                        "shared boundary, of living-room_0/0 and bathroom_0/0");
  REQUIRE(kitchen_door);
  REQUIRE(bathroom_door);
  CHECK(kitchen_door->rule == 3);
  CHECK(kitchen_door->elements == std::vector<std::string>{"living0_kitchen0", "kitchen_0/0"});
  CHECK(bathroom_door->elements == std::vector<std::string>{"living0_bathroom0", "bathroom_0/0"});
  // The other doors of the example are in place: exactly these two door violations.
  int door_violations = 0;
  for (const auto& v : report.violations) door_violations += v.message.rfind("door ", 0) == 0;
  CHECK(door_violations == 2);
  // Everything else it breaks follows from the same mistakes or from the truncated interiors:
  // the upper floors overhang the gap (2), the entrance and the open/walls at y=4 touch one room (3),
  // the cut-off interiors list leaves walls uncovered (4), nothing is reachable (8), and the living
  // room reaches neither kitchen nor dining room (10).
  CHECK(RulesOf(report) == std::set<int>{1, 2, 3, 4, 8, 10});
  CHECK(report.CountRule(1) == 1);
  CHECK(report.CountRule(2) == 1);
}

// ---- edge cases on layouts changed in code ----

TEST_CASE("rule 1: overlapping rooms are reported with their overlap area", "[validate][rule1]") {
  Layout layout = Fixture("house_one_floor.json");
  RoomNamed(layout, "office_0/0").polygon = {{7.5, 5}, {12, 5}, {12, 9}, {7.5, 9}};
  ValidationReport report = ValidateLayout(layout);
  INFO(Describe(report));
  const Violation* v = Find(report, "rooms bathroom_0/0 and office_0/0 overlap by 2.00 m2");
  REQUIRE(v);
  CHECK(v->rule == 1);
  CHECK(v->figure == Approx(2.0));
  CHECK(v->elements == std::vector<std::string>{"bathroom_0/0", "office_0/0"});
}

TEST_CASE("rule 1: overlap of angled rooms is measured exactly", "[validate][rule1]") {
  // Two triangles crossing: a square of side 2 split along both diagonals differently.
  CHECK(IntersectionArea({{0, 0}, {2, 0}, {0, 2}}, {{0, 0}, {2, 0}, {2, 2}}) == Approx(1.0));
  // Non-convex against convex goes through Boost.Geometry: L-shape and a box over its notch.
  Ring l_shape{{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}};
  CHECK(IntersectionArea(l_shape, {{1, 1}, {3, 1}, {3, 3}, {1, 3}}) == Approx(3.0));
  CHECK(IntersectionArea(l_shape, {{2, 2}, {4, 2}, {4, 4}, {2, 4}}) == Approx(0.0).margin(1e-12));
}

TEST_CASE("rule 1: invalid polygons, empty levels and bad element levels", "[validate][rule1]") {
  Layout layout = Fixture("house_one_floor.json");
  RoomNamed(layout, "office_0/0").polygon = {{8, 5}, {12, 9}, {12, 5}, {8, 9}};  // a bow tie
  layout.doors.push_back({"ghost", ElementKind::kDoor, {{0, 0}, {1, 0}}, 4});
  Room upper = RoomNamed(layout, "bedroom_0/0");
  upper.level = 2;  // level 1 left empty
  layout.rooms.push_back(upper);
  ValidationReport report = ValidateLayout(layout);
  INFO(Describe(report));
  bool bow_tie = false;
  for (const auto& v : report.violations) bow_tie = bow_tie || (v.rule == 1 && v.message.rfind("office_0/0 is not a valid polygon: ", 0) == 0);
  CHECK(bow_tie);
  CHECK(Find(report, "level 1 has no rooms (levels must be 0..2 with rooms on each)"));
  CHECK(Find(report, "door ghost is on level 4, but the layout has levels 0..2"));
}

TEST_CASE("rule 1: a hole touching the outline at one point is still a hole", "[validate][rule1]") {
  // A 6 x 6 block of 2 m cells without its centre cell (the hole) and its top-right cell (a notch): the two
  // missing cells meet at the point (4, 4).
  std::vector<Ring> rooms = {{{0, 0}, {6, 0}, {6, 2}, {0, 2}},
                             {{0, 2}, {2, 2}, {2, 6}, {0, 6}},
                             {{2, 4}, {4, 4}, {4, 6}, {2, 6}},
                             {{4, 2}, {6, 2}, {6, 4}, {4, 4}}};
  ExteriorBoundary boundary = ExteriorBoundaryOf(rooms, kTolerance);
  CHECK(boundary.closed);
  int holes = 0;
  double outer = 0;
  for (const auto& ring : boundary.rings) {
    if (ring.signed_area < 0) {
      ++holes;
      CHECK(ring.signed_area == Approx(-4.0));
    } else {
      outer += ring.signed_area;
    }
  }
  CHECK(holes == 1);
  CHECK(outer == Approx(32.0));  // 36 - the 4 m2 notch
  // Boost.Geometry agrees: one polygon with one hole.
  auto footprint = UnionOfRings(rooms);
  REQUIRE(footprint.size() == 1);
  CHECK(footprint[0].holes.size() == 1);
}

TEST_CASE("rule 1: the footprint outline of a valid floor is one counter-clockwise ring", "[validate][rule1]") {
  Layout layout = Fixture("villa_three_floors.json");
  std::vector<Ring> rings;
  for (int r : layout.RoomsOnLevel(0)) rings.push_back(layout.rooms[r].polygon);
  ExteriorBoundary boundary = ExteriorBoundaryOf(rings, kTolerance);
  REQUIRE(boundary.rings.size() == 1);
  CHECK(boundary.rings[0].signed_area == Approx(16 * 10 - 4.5));  // 16 x 10 less the 3 x 3 / 2 chamfer
}

TEST_CASE("rule 2: an upper floor larger than the one below", "[validate][rule2]") {
  Layout layout = Fixture("house_two_floors.json");
  // Stretch the upper bedroom west by 2 m over the garden.
  RoomNamed(layout, "bedroom_1/0").polygon = {{-2, 0}, {5, 0}, {5, 3.5}, {-2, 3.5}};
  ValidationReport report = ValidateLayout(layout);
  INFO(Describe(report));
  REQUIRE(report.CountRule(2) == 1);
  const Violation* v = Find(report, "level 1 footprint reaches 7.00 m2 beyond level 0's footprint (bedroom_1/0)");
  REQUIRE(v);
  CHECK(v->figure == Approx(7.0));
}

TEST_CASE("rule 3: windows, entrances and doors in the wrong place", "[validate][rule3]") {
  Layout layout = Fixture("house_one_floor.json");
  // A window on the wall between the bedroom and the bathroom.
  layout.windows.push_back({"inner_window", ElementKind::kWindow, {{5, 6}, {5, 7}}, 0});
  // A door on the outside wall of the office only.
  layout.doors.push_back({"garden_door", ElementKind::kDoor, {{12, 6}, {12, 7}}, 0});
  // A door that runs 0.5 m past the living-office wall (x 8..12) into the bathroom's.
  layout.doors.push_back({"long_door", ElementKind::kDoor, {{7.5, 5}, {8.5, 5}}, 0});
  // A second entrance.
  layout.entrances.push_back({"back_door", ElementKind::kEntrance, {{0, 6}, {0, 7}}, 0});
  ValidationReport report = ValidateLayout(layout);
  INFO(Describe(report));
  CHECK(Find(report, "window inner_window lies on the wall between bedroom_0/0 and bathroom_0/0 for 1.00 m, not on an outside wall"));
  CHECK(Find(report, "door garden_door touches only office_0/0; it is 2.00 m off the nearest shared boundary, of living-room_0/0 and office_0/0"));
  const Violation* long_door = Find(report, "door long_door runs 0.50 m past the shared boundary of living-room_0/0 and bathroom_0/0");
  REQUIRE(long_door);
  CHECK(long_door->figure == Approx(0.5));
  CHECK(Find(report, "the layout has 2 entrances (main_door, back_door); it has exactly one"));
  CHECK(RulesOf(report) == std::set<int>{3});
}

TEST_CASE("rule 3: an element without a level is checked on every level", "[validate][rule3]") {
  Layout layout = Fixture("house_two_floors.json");
  // Only the upper floor has a wall at y = 3.5 (living room / bedroom); on the ground floor it is mid-room.
  layout.doors.push_back({"everywhere", ElementKind::kDoor, {{1.5, 3.5}, {2.5, 3.5}}, kAllLevels});
  ValidationReport report = ValidateLayout(layout);
  INFO(Describe(report));
  REQUIRE(report.CountRule(3) == 1);
  CHECK(report.violations[0].message ==
        "door everywhere touches no room of level 0; it is 2.50 m off the nearest shared boundary, of living-room_0/0 and "
        "utility-room_0/0 (no level given: checked on level 0)");
}

TEST_CASE("rule 5: room width is the narrowest of hull caliper and thin arms", "[validate][rule5]") {
  // The paper's triangular balcony: 4 m base, 2 m deep; its sharp corners do not make it narrow.
  CHECK(RoomWidth({{8, 0}, {10, 2}, {8, 4}}, kTolerance) == Approx(2.0));
  // A sliver triangle is narrow: its smallest height is 0.5 m.
  CHECK(RoomWidth({{0, 0}, {6, 0}, {6, 0.5}}, kTolerance) == Approx(6 * 0.5 / std::hypot(6, 0.5)));
  // An L with a 0.8 m arm: the hull is wide, the arm is not.
  CHECK(RoomWidth({{0, 0}, {5, 0}, {5, 0.8}, {0.8, 0.8}, {0.8, 5}, {0, 5}}, kTolerance) == Approx(0.8));
  // A U with 1.5 m arms around a 1 m slot: the slot is outside, not a narrow part.
  CHECK(RoomWidth({{0, 0}, {4, 0}, {4, 4}, {2.5, 4}, {2.5, 1.5}, {1.5, 1.5}, {1.5, 4}, {0, 4}}, kTolerance) == Approx(1.5));
  // A thin rotated parallelogram.
  CHECK(RoomWidth({{0, 0}, {4, 4}, {4, 4.9}, {0, 0.9}}, kTolerance) == Approx(0.9 / std::sqrt(2.0)));
}

TEST_CASE("rule 6: a fourth floor", "[validate][rule6]") {
  Layout layout = Fixture("villa_three_floors.json");
  for (const Room& room : std::vector<Room>(layout.rooms))
    if (room.level == 2) {
      Room copy = room;
      copy.level = 3;
      layout.rooms.push_back(copy);
    }
  ValidationReport report = ValidateLayout(layout);
  INFO(Describe(report));
  CHECK(Find(report, "the building has 4 floors; at most 3"));
}

TEST_CASE("rule 7: missing, misplaced and centred staircases", "[validate][rule7]") {
  SECTION("the upper floor has no utility room") {
    Layout layout = Fixture("house_two_floors.json");
    RoomNamed(layout, "utility-room_1/0").category = Category::kOffice;
    ValidationReport report = ValidateLayout(layout);
    INFO(Describe(report));
    CHECK(Find(report, "level 1 has no utility-room; a multi-story building has a 4 x 4 m staircase room on every floor"));
  }
  SECTION("the staircase moves between floors") {
    Layout layout = Fixture("house_two_floors.json");
    // Swap the upper utility room and the upper bathroom's west part: a 4 x 4 at (4, 6).
    RoomNamed(layout, "utility-room_1/0").polygon = {{4, 6}, {8, 6}, {8, 10}, {4, 10}};
    RoomNamed(layout, "bathroom_1/0").polygon = {{0, 6}, {4, 6}, {4, 10}, {0, 10}};
    ValidationReport report = ValidateLayout(layout);
    INFO(Describe(report));
    const Violation* v = Find(report,
                              "utility-room_1/0 is not at the place of utility-room_0/0 (4.00 m off): the staircase rises "
                              "through the same 4 x 4 m on every floor");
    REQUIRE(v);
    CHECK(v->figure == Approx(4.0));
  }
  SECTION("the staircase in the exact centre") {
    Layout layout = FromText(R"json({"rooms": {
      "utility-room_0/0": {"shape": "shapely.box(4, 4, 8, 8)"},
      "living-room_0/0": {"shape": "shapely.box(0, 0, 12, 4)"},
      "kitchen_0/0": {"shape": "shapely.box(0, 8, 12, 12)"},
      "bedroom_0/0": {"shape": "shapely.box(0, 4, 4, 8)"},
      "office_0/0": {"shape": "shapely.box(8, 4, 12, 8)"},
      "utility-room_1/0": {"shape": "shapely.box(4, 4, 8, 8)"},
      "bedroom_1/0": {"shape": "shapely.Polygon([(0, 0), (12, 0), (12, 4), (8, 4), (8, 8), (4, 8), (4, 4), (0, 4)])"}},
      "entrance": {}, "doors": {}, "opens": {}, "windows": {}, "interiors": {}})json");
    ValidationReport report = ValidateLayout(layout);
    INFO(Describe(report));
    CHECK(Find(report, "utility-room_0/0 sits at the exact centre (6, 6) of level 0's footprint; the staircase goes off centre"));
    // Level 1's footprint (12 x 8 less nothing) has its centroid elsewhere.
    CHECK(report.CountRule(7) == 1);
  }
}

TEST_CASE("rule 8: a layout without an entrance reaches nothing", "[validate][rule8]") {
  Layout layout = Fixture("house_one_floor.json");
  layout.entrances.clear();
  ValidationReport report = ValidateLayout(layout);
  INFO(Describe(report));
  CHECK(RulesOf(report) == std::set<int>{8});
  CHECK(report.violations.size() == 1);
  CHECK(report.violations[0].message == "the layout has no entrance, so no room is reachable");
  CHECK(report.geometric_ok());
}

TEST_CASE("rule 9: balconies need a panoramic window and doors only", "[validate][rule9]") {
  Layout layout = Fixture("house_two_floors.json");
  for (auto& w : layout.windows) w.panoramic = false;
  Element door = layout.doors.back();  // children1_balcony1
  REQUIRE(door.name == "children1_balcony1");
  layout.doors.pop_back();
  door.kind = ElementKind::kOpen;
  layout.opens.push_back(door);
  ValidationReport report = ValidateLayout(layout);
  INFO(Describe(report));
  CHECK(Find(report, "balcony_1/0 has no panoramic window"));
  CHECK(Find(report, "balcony_1/0 connects through open children1_balcony1; a balcony connects through doors"));
  CHECK(Find(report, "balcony_1/0 has no door"));
  CHECK(RulesOf(report) == std::set<int>{9});
}

TEST_CASE("rule 10: kitchen to dining room, living room to either", "[validate][rule10]") {
  Layout layout = Fixture("house_one_floor.json");
  // Close the kitchen-dining open and the living-kitchen open: the kitchen is cut off from both.
  // (the interior walls already run the full length of both boundaries).
  layout.opens.clear();
  ValidationReport report = ValidateLayout(layout);
  INFO(Describe(report));
  CHECK(Find(report, "kitchen_0/0 does not connect to a dining room of level 0"));
  CHECK(Find(report, "kitchen_0/0 is not reachable from the entrance"));
  // The living room still reaches the dining room through its door.
  CHECK(report.CountRule(10) == 1);
}

TEST_CASE("geometric-only validation skips the architecture rules", "[validate]") {
  ValidateOptions options;
  options.check_architecture = false;
  CHECK(ValidateLayout(Fixture("rule9_kitchen_without_window.json"), options).valid());
  CHECK_FALSE(ValidateLayout(Fixture("rule4_missing_wall.json"), options).valid());
}

TEST_CASE("rule 10: a private room with two connections is not nested", "[validate][rule10]") {
  Layout layout = Fixture("rule10_nested_room_open.json");
  REQUIRE(ValidateLayout(layout).CountRule(10) == 1);
  // A second way into the bathroom, a door from the bedroom: it is no longer nested, its open is fine.
  layout.doors.push_back({"bedroom0_bathroom0", ElementKind::kDoor, {{5, 6}, {5, 7}}, 0});
  ValidationReport report = ValidateLayout(layout);
  INFO(Describe(report));
  CHECK(report.valid());
}
