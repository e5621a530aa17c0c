#include <catch2/catch.hpp>

#include <cmath>

#include "layout/geometry.h"
#include "layout/layout_io.h"
#include "mesh/geometry2d.h"
#include "scene/door_swing.h"
#include "scene/room_context.h"
#include "scene_test_support.h"

using namespace villa;
using namespace villa::scene;
using namespace villa::scene::testing;

namespace {

double TotalArea(const std::vector<Ring>& rings) {
  double a = 0.0;
  for (const Ring& r : rings) a += Area(r);
  return a;
}

// The inset of a CONVEX room by an independent route: the polygon clipped by each edge's inset half-plane
// (for convex polygons the mitred inset is exactly that intersection), then the level's inner outline of
// the exterior walls clipped to it (Sutherland-Hodgman: one piece for these rooms).
double ConvexInsetArea(const Ring& polygon, const std::vector<EdgePiece>& pieces, const Ring& wall_inner) {
  Ring clipped = polygon;
  for (const EdgePiece& p : pieces) {
    Point a = polygon[p.edge], b = polygon[(p.edge + 1) % polygon.size()];
    Point in = geo::Left(geo::Unit(geo::Sub(b, a)));
    clipped = geo::ClipHalfPlane(clipped, geo::Add(a, geo::Scale(in, p.depth)), in);
  }
  return Area(geo::ClipConvex(wall_inner, clipped));
}

bool Contains(const std::vector<KeepOut>& zones, KeepOutKind kind, const std::string& element) {
  for (const KeepOut& z : zones)
    if (z.kind == kind && z.element == element) return true;
  return false;
}

}  // namespace

TEST_CASE("free floor of an L-shaped room is the room inset by its walls", "[scene][context]") {
  BuiltLayout b = LoadBuilt("tests/fixtures/layouts/house_one_floor.json");
  RoomContext c = ContextOf(b, "living-room_0/0");
  // Polygon (0,0) (6,0) (6,3) (12,3) (12,5) (0,5): exterior walls on x = 0, y = 0 and x = 12 (0.25 m),
  // interior walls elsewhere (0.06 m). The inset L: 11.5 x 4.69 minus the notch 5.81 x 2.81.
  REQUIRE(c.free_floor.size() == 1);
  CHECK(c.free_area == Approx(11.5 * 4.69 - 5.81 * 2.81).margin(1e-6));
  CHECK(c.free_floor[0].size() == 6);
  CHECK(c.area == Approx(42.0));
  CHECK(c.floor_z == Approx(0.175));
  CHECK(c.clear_height == Approx(2.625));
  // The reflex corner of the free floor sits 0.06 m from both interior walls of the notch.
  bool reflex_corner = false;
  for (Point p : c.free_floor[0]) reflex_corner = reflex_corner || (std::abs(p.x - 5.94) < 1e-9 && std::abs(p.y - 3.06) < 1e-9);
  CHECK(reflex_corner);
}

TEST_CASE("free floor of an angled room follows the slanted wall", "[scene][context]") {
  BuiltLayout b = LoadBuilt("tests/fixtures/layouts/bungalow_angled.json");
  RoomContext c = ContextOf(b, "living-room_0/0");
  // (4,0) (10,0) (14,4) (14,5) (4,5): exterior along y = 0, the 45-degree edge and x = 14; interior on
  // y = 5 and x = 4. The slanted wall's inner face is the line y = x - 10 + 0.25 sqrt 2.
  const double r2 = std::sqrt(2.0);
  Ring expected = {{4.06, 0.25}, {10.25 - 0.25 * r2, 0.25}, {13.75, 3.75 + 0.25 * r2}, {13.75, 4.94}, {4.06, 4.94}};
  REQUIRE(c.free_floor.size() == 1);
  CHECK(c.free_area == Approx(Area(expected)).margin(1e-6));
  CHECK(c.free_area == Approx(38.0212).margin(1e-4));
  // Its slanted wall: inner segment parallel to the room edge, 0.25 m in.
  int slanted = 0;
  for (const WallEdge& w : c.walls) {
    if (w.edge != 1) continue;
    ++slanted;
    CHECK(w.exterior);
    CHECK(w.thickness == Approx(0.25));
    CHECK(PointSegmentDistance(w.inner.a, {{10, 0}, {14, 4}}) == Approx(0.25).margin(1e-9));
    CHECK(PointSegmentDistance(w.inner.b, {{10, 0}, {14, 4}}) == Approx(0.25).margin(1e-9));
    // The panoramic window on it blocks the wall for floor objects (its sill is 0.05 m).
    REQUIRE(w.windows.size() == 1);
    CHECK(w.windows[0].panoramic);
    CHECK(TotalLength(w.free) < w.length() - 4.0);
  }
  CHECK(slanted == 1);
}

TEST_CASE("free floor keeps out of an exterior wall that crosses the room's corner", "[scene][context]") {
  // The footprint turns 45 degrees at (2,0), the square room's corner, where an interior wall meets it:
  // the slanted wall's inner face (x + y = 2 + 0.25 sqrt 2) cuts a triangle off the room's square corner
  // (legs of a few cm between the interior wall's face and the bottom wall's face). A washer pushed into
  // that corner started 2.8 mm inside the built wall (issue 28).
  auto layout = ParseLayoutText(R"json({"rooms": {
      "living-room_0/0": {"shape": "shapely.Polygon([(0, 2), (2, 0), (2, 4), (0, 4)])"},
      "kitchen_0/0": {"shape": "shapely.box(2, 0, 6, 4)"}},
    "entrance": {"main_door": {"shape": "shapely.LineString([(0, 3), (0, 2.5)])", "level": 0}},
    "doors": {}, "opens": {"living0_kitchen0": {"shape": "shapely.LineString([(2, 3.5), (2, 2.5)])", "level": 0}},
    "windows": {}, "interiors": {"wall_0": {"shape": "shapely.LineString([(2, 0), (2, 4)])", "level": 0}}})json",
                                "inline");
  REQUIRE(layout.ok());
  BuiltLayout b = Built(std::move(*layout));
  REQUIRE(b.building.wall_inner.size() == 1);
  RoomContext c = ContextOf(b, "kitchen_0/0");
  const double half = b.options.interior_wall_thickness / 2.0, t = b.options.exterior_wall_thickness;
  const double diagonal = 2.0 + t * std::sqrt(2.0);  // x + y on the slanted wall's inner face
  // The bands alone leave the square corner (2 + half, t); the wall takes the triangle beyond its face.
  const double leg = diagonal - (2.0 + half) - t;
  REQUIRE(leg > 0.02);
  std::vector<EdgePiece> pieces = WallPieces(c.polygon, ExteriorBoundaryOf({b.layout.rooms[0].polygon, b.layout.rooms[1].polygon}, kTolerance).pieces, b.options);
  const double banded = TotalArea(FreeFloor(c.polygon, pieces));
  CHECK(c.free_area == Approx(banded - leg * leg / 2.0).margin(1e-9));
  for (const Ring& ring : c.free_floor)
    for (Point p : ring) CHECK(p.x + p.y >= diagonal - 1e-9);
  // A room whose corners the exterior walls do not cross keeps the bands' floor exactly.
  RoomContext living = ContextOf(b, "living-room_0/0");
  std::vector<EdgePiece> living_pieces = WallPieces(living.polygon, ExteriorBoundaryOf({b.layout.rooms[0].polygon, b.layout.rooms[1].polygon}, kTolerance).pieces, b.options);
  CHECK(living.free_area == Approx(TotalArea(FreeFloor(living.polygon, living_pieces))).margin(1e-12));
}

TEST_CASE("free floor of every convex fixture room matches the half-plane inset", "[scene][context]") {
  for (const char* file : {"tests/fixtures/layouts/villa_three_floors.json", "tests/fixtures/layouts/bungalow_angled.json",
                           "examples/three-floor-villa.json", "examples/l-shaped-house.json"}) {
    BuiltLayout b = LoadBuilt(file);
    auto contexts = RoomContexts(b.layout, b.building, b.options);
    REQUIRE(contexts.ok());
    int convex = 0;
    for (const RoomContext& c : *contexts) {
      INFO(file << " " << c.name);
      CHECK(c.free_area < c.area);
      CHECK(c.free_area > 0.5 * c.area);
      if (!IsConvex(c.polygon)) continue;
      std::vector<Ring> level;
      for (int i : b.layout.RoomsOnLevel(c.level)) level.push_back(b.layout.rooms[i].polygon);
      auto pieces = WallPieces(c.polygon, ExteriorBoundaryOf(level, kTolerance).pieces, b.options);
      // An edge half exterior, half interior steps; half-planes cannot say that.
      if (pieces.size() != c.polygon.size()) continue;
      ++convex;
      CHECK(c.free_area == Approx(ConvexInsetArea(c.polygon, pieces, b.building.wall_inner[c.level])).margin(1e-6));
    }
    CHECK(convex > 0);
  }
}

TEST_CASE("wall pieces split an edge where it leaves the footprint", "[scene][context]") {
  // The dining room of the L-shaped house: its top edge y = 7 from x = 7 to 11 is exterior (the notch),
  // its left edge x = 7 is shared with the living room (interior).
  BuiltLayout b = LoadBuilt("examples/l-shaped-house.json");
  RoomContext c = ContextOf(b, "dining-room_0/0");
  CHECK(c.free_area == Approx((4.0 - 0.06 - 0.06) * (7.0 - 0.25 - 0.25)).margin(1e-6));
  // Living room: top edge y = 7 is interior over its whole length (bedroom and children's room above).
  // At its corner (7,7) the footprint turns (the notch): the exterior walls' corner block, 0.25 m square,
  // stands in the room's corner beyond the interior walls' 0.06 m.
  RoomContext living = ContextOf(b, "living-room_0/0");
  CHECK(living.free_area == Approx((7.0 - 0.25 - 0.06) * (7.0 - 0.25 - 0.06) - 0.19 * 0.19).margin(1e-6));
  // Children's room: x = 7 from y = 7 to 13 is exterior.
  RoomContext children = ContextOf(b, "children-room_0/0");
  CHECK(children.free_area == Approx((3.0 - 0.06 - 0.25) * (6.0 - 0.06 - 0.25)).margin(1e-6));
}

TEST_CASE("a collinear change of wall depth leaves a step where the deeper wall ends", "[scene][context]") {
  // Room A below, room B on the left half above: A's top edge is interior for x in [0, 6] and exterior
  // for x in [6, 10]. The exterior wall's band reaches 0.25 m past x = 6 (the building mitres the
  // footprint's reflex corner there), so A's free floor steps at x = 5.75.
  Ring a = {{0, 0}, {10, 0}, {10, 4}, {0, 4}};
  Ring bring = {{0, 4}, {6, 4}, {6, 8}, {0, 8}};
  BuildOptions options;
  auto pieces = WallPieces(a, ExteriorBoundaryOf({a, bring}, kTolerance).pieces, options);
  REQUIRE(pieces.size() == 5);  // bottom, right, top split in two, left
  auto free = FreeFloor(a, pieces);
  REQUIRE(free.size() == 1);
  double expected = 9.5 * (4.0 - 0.25 - 0.06) - (10.0 - 0.25 - 5.75) * (0.25 - 0.06);
  CHECK(TotalArea(free) == Approx(expected).margin(1e-6));
}

TEST_CASE("each door sweeps into exactly one of its rooms and leaves a strip in the other", "[scene][context]") {
  BuiltLayout b = LoadBuilt("tests/fixtures/layouts/house_one_floor.json");
  auto contexts = RoomContexts(b.layout, b.building, b.options);
  REQUIRE(contexts.ok());
  for (const Element& door : b.layout.doors) {
    INFO(door.name);
    int sweeps = 0, strips = 0;
    for (const RoomContext& c : *contexts) {
      if (Contains(c.keep_outs, KeepOutKind::kDoorSweep, door.name)) ++sweeps;
      if (Contains(c.keep_outs, KeepOutKind::kDoorStrip, door.name)) ++strips;
    }
    CHECK(sweeps == 1);
    CHECK(strips == 1);
  }
  // The sweep is a square of the door's width reaching from the element's line to the open leaf's far
  // edge: wall face (0.06 interior, 0.25 exterior) + the leaf (door width less two 2 mm gaps) + one gap.
  auto swings = DoorSwings(b.layout, b.building, b.options, 0);
  REQUIRE(swings.size() == b.layout.doors.size() + 1);
  for (const DoorSwing& s : swings) {
    INFO(s.element);
    REQUIRE(s.side != 0);
    double width = Length(s.door);
    double face = s.kind == ElementKind::kEntrance ? 0.25 : 0.06;
    CHECK(Area(s.sweep) == Approx(width * (face + width - 0.002)).margin(1e-6));
    REQUIRE(s.strips.size() == 1);
    CHECK(Area(s.strips[0]) == Approx(width * (s.kind == ElementKind::kEntrance ? 0.6 : 0.66)).margin(1e-6));
  }
}

TEST_CASE("window zones are 0.5 m deep and start at the sill", "[scene][context]") {
  BuiltLayout b = LoadBuilt("tests/fixtures/layouts/house_one_floor.json");
  RoomContext c = ContextOf(b, "bedroom_0/0");
  int windows = 0;
  for (const KeepOut& z : c.keep_outs) {
    if (z.kind != KeepOutKind::kWindow) continue;
    ++windows;
    CHECK(z.element == "bedroom0_window");
    CHECK(z.z_min == Approx(c.floor_z + 0.9));
    CHECK(z.z_max == Approx(c.floor_z + 2.1));
    CHECK(Area(z.polygon) == Approx(2.0 * 0.75));  // 2 m wide, wall 0.25 + zone 0.5
  }
  CHECK(windows == 1);
  // A window does not take the wall from low furniture: only openings and floor-level zones do.
  for (const WallEdge& w : c.walls)
    if (!w.windows.empty()) CHECK(TotalLength(w.free) == Approx(w.length()).margin(1e-9));
}

TEST_CASE("wall openings and door sweeps are not free wall", "[scene][context]") {
  BuiltLayout b = LoadBuilt("tests/fixtures/layouts/house_one_floor.json");
  RoomContext c = ContextOf(b, "kitchen_0/0");
  // The kitchen's two opens (living, dining): 1.2 m and 2 m of its side walls are passages.
  double openings = 0.0;
  for (const WallEdge& w : c.walls) openings += TotalLength(w.openings);
  CHECK(openings == Approx(1.2 + 2.0).margin(1e-6));
  for (const WallEdge& w : c.walls)
    for (const Interval& o : w.openings)
      for (const Interval& f : w.free) CHECK((f.second <= o.first + 1e-9 || f.first >= o.second - 1e-9));
  CHECK(c.FreeWallLength() < (3.0 - 0.12) * 2 + (3.0 - 0.31) * 2 - openings + 1e-6);
}

TEST_CASE("staircase rooms keep the stairs, the hole and the arrival strip out", "[scene][context]") {
  BuiltLayout b = LoadBuilt("tests/fixtures/layouts/villa_three_floors.json");
  RoomContext ground = ContextOf(b, "utility-room_0/0");
  RoomContext middle = ContextOf(b, "utility-room_1/0");
  RoomContext top = ContextOf(b, "utility-room_2/0");
  auto count = [](const RoomContext& c, KeepOutKind kind) {
    int n = 0;
    for (const KeepOut& z : c.keep_outs) n += z.kind == kind;
    return n;
  };
  CHECK(count(ground, KeepOutKind::kStair) == 1);
  CHECK(count(ground, KeepOutKind::kStairHole) == 0);
  CHECK(count(middle, KeepOutKind::kStair) == 1);
  CHECK(count(middle, KeepOutKind::kStairHole) == 1);
  CHECK(count(top, KeepOutKind::kStair) == 0);
  CHECK(count(top, KeepOutKind::kStairHole) == 1);
  for (const RoomContext* c : {&ground, &middle, &top}) {
    INFO(c->name);
    CHECK(count(*c, KeepOutKind::kStairArrival) >= 1);
    // Stairs, hole and arrival take nearly all of a 4 x 4 room.
    CHECK(c->furnishable_area < 0.25 * c->free_area);
    for (const KeepOut& z : c->keep_outs) {
      if (z.kind != KeepOutKind::kStairArrival) continue;
      CHECK(IntersectionArea(z.polygon, c->polygon) == Approx(Area(z.polygon)).margin(1e-6));
      CHECK(z.z_max - z.z_min == Approx(c->clear_height));
    }
  }
  // A room without stairs keeps its whole free floor.
  RoomContext living = ContextOf(b, "living-room_0/0");
  CHECK(living.furnishable_area == Approx(living.free_area));
}

TEST_CASE("a room name not in the layout is an error listing the rooms", "[scene][context]") {
  BuiltLayout b = LoadBuilt("tests/fixtures/layouts/house_one_floor.json");
  auto c = RoomContextOf(b.layout, b.building, b.options, "garage_0/0");
  REQUIRE_FALSE(c.ok());
  CHECK(c.error().find("garage_0/0") != std::string::npos);
  CHECK(c.error().find("living-room_0/0") != std::string::npos);
}
