// Wall pieces (layout/walls.h) and door swings (layout/door_swing.h): the plan geometry the floor plan,
// the building and the furnishing share.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>

#include "layout/door_swing.h"
#include "layout/footprint.h"
#include "layout/layout_io.h"
#include "layout/walls.h"
#include "test_support.h"

using namespace villa;
using namespace villa::test;

namespace {
Layout Load(const std::string& name) {
  auto layout = LoadLayout(std::string(VILLA_FIXTURE_DIR) + "/finetune/" + name);
  REQUIRE(layout.ok());
  return *layout;
}
double Perimeter(const Ring& ring) {
  double total = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) total += Length({ring[i], ring[(i + 1) % ring.size()]});
  return total;
}
}  // namespace

TEST_CASE("wall pieces cut every room outline into exterior and shared stretches", "[layout][walls]") {
  const Layout l = Load("one_floor.json");  // an L-shaped living room, a kitchen and a bathroom beside it
  const auto pieces = LevelWallPieces(l, 0);
  std::map<int, double> outline;
  double exterior = 0;
  std::map<std::pair<int, int>, double> shared;
  for (const WallPiece& p : pieces) {
    outline[p.room] += Length(p.segment);
    CHECK(Length(p.segment) == Approx(p.along.second - p.along.first));
    if (p.exterior()) exterior += Length(p.segment);
    else shared[{p.room, p.neighbour}] += Length(p.segment);
  }
  for (int r = 0; r < 3; ++r) CHECK(outline[r] == Approx(Perimeter(l.rooms[r].polygon)));
  // The exterior pieces add up to the footprint's perimeter.
  const auto footprint = LevelFootprint(l, 0);
  REQUIRE(footprint.size() == 1);
  CHECK(exterior == Approx(Perimeter(footprint[0].outer)));
  // Each shared stretch is seen from both sides, as long.
  CHECK(shared[{0, 1}] == Approx(3.0));
  CHECK(shared[{1, 0}] == Approx(3.0));
  CHECK(shared[{0, 2}] == Approx(3.0));
  CHECK(shared[{1, 2}] == Approx(4.0));
  CHECK(shared[{2, 1}] == Approx(4.0));
  // Ring order: the pieces of one room follow its edges, and along each edge from its first corner.
  const auto living = RoomWallPieces(l, 0);
  for (std::size_t i = 1; i < living.size(); ++i)
    CHECK((living[i].edge > living[i - 1].edge ||
           (living[i].edge == living[i - 1].edge && living[i].along.first >= living[i - 1].along.second - kTolerance)));
}

TEST_CASE("a neighbour's collinear corner does not split the shared wall", "[layout][walls]") {
  // Room 1's bottom edge has a collinear corner at (2, 4): still one piece shared with room 0.
  Layout l;
  l.rooms.push_back({Category::kLivingRoom, 0, 0, {{0, 0}, {4, 0}, {4, 4}, {0, 4}}});
  l.rooms.push_back({Category::kBedroom, 0, 0, {{0, 4}, {2, 4}, {4, 4}, {4, 7}, {0, 7}}});
  int shared = 0;
  for (const WallPiece& p : RoomWallPieces(l, 0))
    if (p.neighbour == 1) {
      ++shared;
      CHECK(Length(p.segment) == Approx(4.0));
    }
  CHECK(shared == 1);
}

TEST_CASE("a door swings into the room one enters from the common spaces", "[layout][door]") {
  const Layout l = Load("one_floor.json");
  const auto swings = DoorSwings(l, 0);
  REQUIRE(swings.size() == 3);  // the entrance first, then the two doors
  // The entrance opens into the building: into the living room, not outside.
  CHECK(swings[0].element->kind == ElementKind::kEntrance);
  CHECK(swings[0].into == l.FindRoom("living-room_0/0"));
  CHECK(swings[0].other == -1);
  CHECK(swings[0].leaf_side.y == Approx(1.0));
  // Living room (rank 1) to kitchen or bathroom (rank 0): into the kitchen and the bathroom.
  CHECK(swings[1].into == l.FindRoom("kitchen_0/0"));
  CHECK(swings[1].other == l.FindRoom("living-room_0/0"));
  CHECK(swings[2].into == l.FindRoom("bathroom_0/0"));
  for (const DoorSwing& s : swings) {
    const double w = s.width();
    CHECK(Area(s.sweep) == Approx(w * w));
    CHECK(SignedArea(s.sweep) > 0);
    CHECK(Area(s.strip) == Approx(w * kDoorStripDepth));
    CHECK(Distance(s.hinge, s.leaf_end) == Approx(w));
    // The leaf, the sweep and the strip stand on the two sides of the opening.
    const Point mid{(s.hinge.x + s.free_end.x) / 2, (s.hinge.y + s.free_end.y) / 2};
    CHECK(PointInRing({mid.x + 0.1 * s.leaf_side.x, mid.y + 0.1 * s.leaf_side.y}, s.sweep, 0));
    CHECK(PointInRing({mid.x - 0.1 * s.leaf_side.x, mid.y - 0.1 * s.leaf_side.y}, s.strip, 0));
    CHECK(PointInRing({mid.x + 0.1 * s.leaf_side.x, mid.y + 0.1 * s.leaf_side.y}, l.rooms[s.into].polygon, 0));
  }
  // The kitchen door (6,1)-(6,2): both ends are 1 m from a kitchen corner, so the hinge stays at the first.
  CHECK(swings[1].hinge == Point{6, 1});
  CHECK(swings[1].free_end == Point{6, 2});
}

TEST_CASE("doors never swing onto a balcony nor into a staircase hall", "[layout][door]") {
  Layout l;
  l.rooms.push_back({Category::kBedroom, 0, 0, {{0, 0}, {4, 0}, {4, 4}, {0, 4}}});
  l.rooms.push_back({Category::kBalcony, 0, 0, {{4, 0}, {6, 0}, {6, 4}, {4, 4}}});
  l.rooms.push_back({Category::kUtilityRoom, 0, 0, {{0, 4}, {4, 4}, {4, 8}, {0, 8}}});
  l.rooms.push_back({Category::kUtilityRoom, 1, 0, {{0, 4}, {4, 4}, {4, 8}, {0, 8}}});
  l.doors.push_back({"bed_balcony", ElementKind::kDoor, {{4, 1}, {4, 2}}, 0, false});
  l.doors.push_back({"stair_bed", ElementKind::kDoor, {{1, 4}, {2, 4}}, 0, false});
  const DoorSwing balcony = SwingOfDoor(l, l.doors[0], 0);
  CHECK(balcony.into == 0);  // the balcony is the smaller room, yet the door opens into the bedroom
  CHECK(balcony.other == 1);
  const DoorSwing stair = SwingOfDoor(l, l.doors[1], 0);
  CHECK(stair.into == 0);  // a utility room of a building with several floors holds the staircase
  // On one floor the utility room is an ordinary small room: the door opens into the smaller one.
  l.rooms.pop_back();
  l.rooms[2].polygon = {{0, 4}, {4, 4}, {4, 6}, {0, 6}};
  CHECK(SwingOfDoor(l, l.doors[1], 0).into == 2);
}
