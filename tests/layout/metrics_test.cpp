// FSR, RR (per floor and from the entrance) and VCR on fixtures, each computed by hand below.
#include <catch2/catch.hpp>

#include "layout/metrics.h"
#include "layout/topology.h"
#include "test_support.h"

using namespace villa;
using namespace villa::test;

TEST_CASE("metrics of the valid two-floor house: everything reached, stairs stacked", "[metrics]") {
  // Floor 0 from utility-room_0/0: open to the living room, which opens to the dining room (and on to the
  // kitchen) and has the bathroom door: 5 of 5. Floor 1 from utility-room_1/0: open to the upper living
  // room, doors to bedroom, children's room (then the balcony) and bathroom: 6 of 6.
  LayoutMetrics m = MeasureLayout(Fixture("house_two_floors.json"));
  CHECK(m.parsed);
  CHECK(m.format_success);
  CHECK(m.rooms == 11);
  CHECK(m.rooms_reached_per_floor == 11);
  CHECK(m.rooms_reached_from_entrance == 11);
  CHECK(m.floor_pairs == 1);
  CHECK(m.floor_pairs_connected == 1);
}

TEST_CASE("metrics when a door is missing: the children's room and its balcony are cut off", "[metrics]") {
  // Floor 0: 5 of 5. Floor 1: utility, living room, bedroom, bathroom = 4 of 6. Both searches: 9 of 11.
  LayoutMetrics m = MeasureLayout(Fixture("rule8_unreachable_room.json"));
  CHECK(m.format_success);  // rule 8 is not a geometric rule
  CHECK(m.rooms == 11);
  CHECK(m.rooms_reached_per_floor == 9);
  CHECK(m.rooms_reached_from_entrance == 9);
  CHECK(m.floor_pairs_connected == 1);
}

TEST_CASE("metrics of the paper's example", "[metrics][paper]") {
  // Floor 0 from utility-room_0/0: its open at y=4 lies on the utility room only, so it connects nothing:
  // 1 of 5. Floor 1: utility -open- meeting room -doors- bedroom (-door- balcony) and office: 5 of 5.
  // Floor 2: utility -open- children's room -doors- bathroom and balcony: 4 of 4. Per floor 10 of 14.
  // The entrance (0,5)-(0,7) lies in the gap between the ground-floor pieces: it touches no room, 0 of 14.
  // The utility rooms are box(0, 0, 4, 4) on all three floors: 2 of 2 floor pairs connected.
  Layout layout = Fixture("paper_example.json");
  LayoutMetrics m = MeasureLayout(layout);
  CHECK_FALSE(m.format_success);
  CHECK(m.rooms == 14);
  CHECK(m.rooms_reached_per_floor == 10);
  CHECK(m.rooms_reached_from_entrance == 0);
  CHECK(m.floor_pairs == 2);
  CHECK(m.floor_pairs_connected == 2);
  CHECK(EntranceRooms(layout).empty());
  // Connections: 5 of the 7 doors, 3 of the 4 opens, 2 staircase links.
  auto connections = RoomConnections(layout);
  int doors = 0, opens = 0, stairs = 0;
  for (const auto& c : connections) doors += c.via == Via::kDoor, opens += c.via == Via::kOpen, stairs += c.via == Via::kStair;
  CHECK(doors == 5);
  CHECK(opens == 3);
  CHECK(stairs == 2);
}

TEST_CASE("one floor without a utility room: RR searches from the entrance room", "[metrics]") {
  // Courtyard house: living room (entrance) -open- dining -open- kitchen; living -door- bedroom -door-
  // bathroom: 5 of 5 both ways. No floor pairs: VCR undefined. The hole fails rule 1: no format success.
  LayoutMetrics m = MeasureLayout(Fixture("rule1_courtyard_hole.json"));
  CHECK_FALSE(m.format_success);
  CHECK(m.rooms == 5);
  CHECK(m.rooms_reached_per_floor == 5);
  CHECK(m.rooms_reached_from_entrance == 5);
  CHECK(m.floor_pairs == 0);
}

TEST_CASE("VCR: staircase rooms that only touch do not connect the floors", "[metrics]") {
  Layout layout = Fixture("house_two_floors.json");
  RoomNamed(layout, "utility-room_1/0").polygon = {{4, 6}, {8, 6}, {8, 10}, {4, 10}};
  RoomNamed(layout, "bathroom_1/0").polygon = {{0, 6}, {4, 6}, {4, 10}, {0, 10}};
  LayoutMetrics m = MeasureLayout(layout);
  CHECK(m.floor_pairs == 1);
  CHECK(m.floor_pairs_connected == 0);  // box(0,6,4,10) and box(4,6,8,10) share an edge, area 0
  // Without a staircase link the whole upper floor is out of reach from the entrance: 5 of 11.
  CHECK(m.rooms_reached_from_entrance == 5);
  // Shifted by 1 m the boxes overlap by 3 x 4 = 12 m2: connected (but no stair link, rule 7 fails).
  RoomNamed(layout, "utility-room_1/0").polygon = {{1, 6}, {5, 6}, {5, 10}, {1, 10}};
  CHECK(MeasureLayout(layout).floor_pairs_connected == 1);
}

TEST_CASE("MetricsSummary pools outputs, an unparsed one counting against FSR", "[metrics]") {
  MetricsSummary summary;
  CHECK_FALSE(summary.fsr().has_value());
  for (const char* name : {"house_two_floors.json", "rule8_unreachable_room.json", "paper_example.json", "rule1_courtyard_hole.json"})
    summary.Add(MeasureLayout(Fixture(name)));
  LayoutMetrics unparsed;
  unparsed.parsed = false;
  summary.Add(unparsed);
  // FSR: the two-floor house and the rule-8 house pass rules 1-5: 2 of 5.
  CHECK(summary.outputs == 5);
  REQUIRE(summary.fsr().has_value());
  CHECK(*summary.fsr() == Approx(0.4));
  // Rooms 11 + 11 + 14 + 5 = 41; per floor 11 + 9 + 10 + 5 = 35; from the entrance 11 + 9 + 0 + 5 = 25.
  CHECK(summary.rooms == 41);
  CHECK(*summary.rr() == Approx(35.0 / 41));
  CHECK(*summary.rr_entrance() == Approx(25.0 / 41));
  // Floor pairs 1 + 1 + 2 + 0, all connected.
  CHECK(summary.floor_pairs == 4);
  CHECK(*summary.vcr() == Approx(1.0));
}

TEST_CASE("MeasureLayout with a report already made gives the same figures", "[metrics]") {
  for (const char* name : {"house_two_floors.json", "paper_example.json", "rule5_narrow_door.json", "rule9_kitchen_without_window.json"}) {
    Layout layout = Fixture(name);
    LayoutMetrics a = MeasureLayout(layout);
    LayoutMetrics b = MeasureLayout(layout, ValidateLayout(layout));
    INFO(name);
    CHECK(a.format_success == b.format_success);
    CHECK(a.rooms_reached_per_floor == b.rooms_reached_per_floor);
    CHECK(a.rooms_reached_from_entrance == b.rooms_reached_from_entrance);
    CHECK(a.floor_pairs_connected == b.floor_pairs_connected);
  }
  CHECK_FALSE(MeasureLayout(Fixture("rule5_narrow_door.json")).format_success);
  CHECK(MeasureLayout(Fixture("rule9_kitchen_without_window.json")).format_success);
}
