// The door-swing rule keeps the floor a leaf stands on walkable (issue 13, layout/door_swing.h): a door off a
// narrow corridor opens into the room; a door between two narrow halls opens flat against the wall.
#include <catch2/catch.hpp>

#include <cmath>

#include "layout/door_swing.h"
#include "layout/geometry.h"
#include "layout/layout_io.h"

namespace villa {
namespace {

Layout Parse(const char* text) {
  auto layout = ParseLayoutText(text, "test layout");
  if (!layout.ok()) FAIL(layout.error());
  return *layout;
}

// Two halls 1.2 m wide side by side, 6 m long, a 1 m door between them: a leaf standing at 90 degrees in
// either leaves 0.89 - 1.0 < 0 m between its tip and the far wall.
constexpr const char* kTwoHalls = R"json({
  "rooms": {
    "room_0/0": {"shape": "shapely.box(0, 0, 6, 1.2)"},
    "room_0/1": {"shape": "shapely.box(0, 1.2, 6, 2.4)"}
  },
  "entrance": {"main_door": {"shape": "shapely.LineString([(0, 0.1), (0, 1.1)])", "level": 0}},
  "doors": {"room0_room0-1": {"shape": "shapely.LineString([(2.5, 1.2), (3.5, 1.2)])", "level": 0}},
  "opens": {}, "windows": {},
  "interiors": {"wall_room0_room0-1": {"shape": "shapely.LineString([(0, 1.2), (6, 1.2)])", "level": 0}}
})json";

TEST_CASE("a door between two narrow halls opens 180 degrees, flat against the wall", "[layout][door]") {
  const Layout l = Parse(kTwoHalls);
  const DoorSwing w = SwingOfDoor(l, l.doors[0], 0);
  CHECK(w.flat);
  CHECK(w.open_angle() == Approx(M_PI));
  // The smaller-room rule's tie goes to the room left of the segment (north, room_0/1); the leaf lies on
  // the door's line, one width beyond the hinge, away from the opening.
  CHECK(w.into == l.FindRoom("room_0/1"));
  CHECK(w.leaf_side.y == Approx(1.0));
  CHECK(w.leaf_end.y == Approx(1.2));
  CHECK(Distance(w.hinge, w.leaf_end) == Approx(1.0));
  CHECK(Distance(w.free_end, w.leaf_end) == Approx(2.0));
  // The sweep holds the half disc: over the opening and the wall it folds onto, one width deep.
  CHECK(std::abs(Area(w.sweep)) == Approx(2.0));
  const auto arc = w.SwingArc(8);
  REQUIRE(arc.size() == 9);
  CHECK(Distance(arc.front(), w.leaf_end) == Approx(0.0).margin(1e-9));
  CHECK(Distance(arc.back(), w.free_end) == Approx(0.0).margin(1e-9));
  CHECK(arc[4].y == Approx(2.2));  // half way the tip stands straight out into the room
}

TEST_CASE("a door off a narrow hall opens into the room beyond, though the hall is the smaller", "[layout][door]") {
  // The north room 3 m deep: the size rule prefers the 1.2 m hall (7.2 m2 against 18), whose leaf would
  // close it with either hinge; the leaf opens into the north room at 90 degrees instead.
  Layout l = Parse(kTwoHalls);
  l.rooms[1].polygon = {{0, 1.2}, {6, 1.2}, {6, 4.2}, {0, 4.2}};
  const DoorSwing w = SwingOfDoor(l, l.doors[0], 0);
  CHECK_FALSE(w.flat);
  CHECK(w.into == l.FindRoom("room_0/1"));
  CHECK(w.other == l.FindRoom("room_0/0"));
  CHECK(w.leaf_end.y == Approx(2.2));
  // A wide hall keeps the size rule's choice: with the south room 3 m deep too, the leaf opens into the
  // smaller of the two, at 90 degrees.
  l.rooms[0].polygon = {{0, -1.8}, {6, -1.8}, {6, 1.2}, {0, 1.2}};
  l.rooms[1].polygon = {{0, 1.2}, {6, 1.2}, {6, 4.4}, {0, 4.4}};
  const DoorSwing wide = SwingOfDoor(l, l.doors[0], 0);
  CHECK_FALSE(wide.flat);
  CHECK(wide.into == l.FindRoom("room_0/0"));
  CHECK(wide.leaf_end.y == Approx(0.2));
}

}  // namespace
}  // namespace villa
