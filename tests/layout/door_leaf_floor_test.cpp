// The door-swing rule keeps the floor a leaf stands on walkable (issue 13, layout/door_swing.h): a door off a
// narrow corridor opens into the room; a door between two narrow halls opens flat against the wall.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "layout/door_swing.h"
#include "layout/geometry.h"
#include "layout/layout_io.h"

namespace villa {
namespace {

// Two halls 1.5 m wide side by side, 6 m long, a 1 m door between them (tests/fixtures/layouts/two_halls.json):
// 1.19 m between the walls' faces, so a leaf can swing, but standing at 90 degrees in either hall it leaves
// 0.19 m beside its tip, less than the person's 0.4 m.
Layout TwoHalls() {
  auto layout = LoadLayout(std::string(VILLA_FIXTURE_DIR) + "/layouts/two_halls.json");
  if (!layout.ok()) FAIL(layout.error());
  return *layout;
}

TEST_CASE("a door between two narrow halls opens 180 degrees, flat against the wall", "[layout][door]") {
  const Layout l = TwoHalls();
  const DoorSwing w = SwingOfDoor(l, l.doors[0], 0);
  CHECK(w.flat);
  CHECK(w.open_angle() == Approx(M_PI));
  // The smaller-room rule's tie goes to the room left of the segment (north, office_0/1); the leaf lies on
  // the door's line, one width beyond the hinge, away from the opening.
  CHECK(w.into == l.FindRoom("office_0/1"));
  CHECK(w.leaf_side.y == Approx(1.0));
  CHECK(w.leaf_end.y == Approx(1.5));
  CHECK(Distance(w.hinge, w.leaf_end) == Approx(1.0));
  CHECK(Distance(w.free_end, w.leaf_end) == Approx(2.0));
  // The sweep holds the half disc: over the opening and the wall it folds onto, one width deep.
  CHECK(std::abs(Area(w.sweep)) == Approx(2.0));
  const auto arc = w.SwingArc(8);
  REQUIRE(arc.size() == 9);
  CHECK(Distance(arc.front(), w.leaf_end) == Approx(0.0).margin(1e-9));
  CHECK(Distance(arc.back(), w.free_end) == Approx(0.0).margin(1e-9));
  CHECK(arc[4].y == Approx(2.5));  // half way the tip stands straight out into the room
}

TEST_CASE("a door off a narrow hall opens into the room beyond, though the hall is the smaller", "[layout][door]") {
  // The north room 3 m deep: the size rule prefers the 1.5 m hall (9 m2 against 18), whose leaf would
  // close it with either hinge; the leaf opens into the north room at 90 degrees instead.
  Layout l = TwoHalls();
  l.rooms[1].polygon = {{0, 1.5}, {6, 1.5}, {6, 4.5}, {0, 4.5}};
  const DoorSwing w = SwingOfDoor(l, l.doors[0], 0);
  CHECK_FALSE(w.flat);
  CHECK(w.into == l.FindRoom("office_0/1"));
  CHECK(w.other == l.FindRoom("office_0/0"));
  CHECK(w.leaf_end.y == Approx(2.5));
  // A wide hall keeps the size rule's choice: with the south room 3 m deep too, the leaf opens into the
  // smaller of the two, at 90 degrees.
  l.rooms[0].polygon = {{0, -1.5}, {6, -1.5}, {6, 1.5}, {0, 1.5}};
  l.rooms[1].polygon = {{0, 1.5}, {6, 1.5}, {6, 4.6}, {0, 4.6}};
  const DoorSwing wide = SwingOfDoor(l, l.doors[0], 0);
  CHECK_FALSE(wide.flat);
  CHECK(wide.into == l.FindRoom("office_0/0"));
  CHECK(wide.leaf_end.y == Approx(0.5));
}

}  // namespace
}  // namespace villa
