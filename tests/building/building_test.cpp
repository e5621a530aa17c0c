#include <catch2/catch.hpp>

#include <set>

#include "building/building.h"
#include "mesh/solids.h"
#include "layout/geometry.h"
#include "layout/layout_io.h"
#include "mesh/geometry2d.h"
#include "test_support.h"

using namespace villa;
using namespace villa::testing;

namespace {

Point Mid(const Segment& s) { return {(s.a.x + s.b.x) / 2, (s.a.y + s.b.y) / 2}; }

// Unit normal of a segment in the plan, as a 3D direction.
Vec3 PlanNormal(const Segment& s) {
  double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y, l = std::hypot(dx, dy);
  return {-dy / l, dx / l, 0.0};
}

// Whether a horizontal ray crossing the wall line at `p` (height z) through 1 m either side is free of walls.
bool PassesWalls(const BuildingMesh& b, Point p, double z, Vec3 n) {
  Vec3 start = Vec3{p.x, p.y, z} - n * 0.6;
  return !FirstHit(b, start, n, 1.2, IsWall).has_value();
}

int TopHits(const BuildingMesh& b, int level, Point p) {
  // Vertical ray down onto the tops of this level's walls: how many wall pieces cover p.
  double top = (level + 1) * kLevelHeight;
  int hits = 0;
  for (const MeshPart& part : b.parts) {
    if (!IsWall(part) || part.level != level) continue;
    auto t = FirstHit(b, {p.x, p.y, top + 0.01}, {0, 0, -1}, 0.02, [&](const MeshPart& q) { return &q == &part; });
    if (t) ++hits;
  }
  return hits;
}

}  // namespace

TEST_CASE("every part of the built villa is a closed solid with outward normals") {
  const BuildingMesh& b = ThreeFloorBuilding();
  REQUIRE(b.parts.size() > 40);
  for (const MeshPart& part : b.parts) {
    INFO(part.name);
    SolidCheck check = CheckSolid(part.mesh);
    CHECK(check.boundary_edges == 0);
    CHECK(check.non_manifold_edges == 0);
    CHECK(check.volume > 0.0);
  }
}

TEST_CASE("the building has a floor per room, walls per interior element, leaves, panes and stairs") {
  const Layout& layout = ThreeFloorLayout();
  const BuildingMesh& b = ThreeFloorBuilding();
  CHECK(b.levels == 3);
  CHECK(b.CountParts(PartKind::kFloor) == static_cast<int>(layout.rooms.size()));
  CHECK(b.CountParts(PartKind::kDoorLeaf) == static_cast<int>(layout.doors.size() + layout.entrances.size()));
  CHECK(b.CountParts(PartKind::kWindowGlass) == static_cast<int>(layout.windows.size()));
  CHECK(b.CountParts(PartKind::kStair) == 2);  // utility rooms of levels 0 and 1 rise to the next
  CHECK(b.CountParts(PartKind::kRoof) == 1);
  CHECK(b.CountParts(PartKind::kTerrace) == 1);  // level 1 leaves part of the ground floor uncovered
  // Footprint edges: 5 on the ground floor (one angled), 4 above.
  CHECK(b.CountParts(PartKind::kExteriorWall) == 5 + 4 + 4);
  std::set<std::string> elements;
  for (const MeshPart& p : b.parts)
    if (p.kind == PartKind::kInteriorWall) elements.insert(p.element);
  for (const Element& e : layout.interiors) CHECK(elements.count(e.name) == 1);
  for (const Room& r : layout.rooms) {
    auto it = std::find_if(b.rooms.begin(), b.rooms.end(), [&](const BuiltRoom& x) { return x.name == r.name(); });
    REQUIRE(it != b.rooms.end());
    CHECK(it->area == Approx(Area(r.polygon)));
  }
  CHECK(b.warnings.empty());
}

TEST_CASE("bounds: the footprint in plan, three floors of 2.8 m plus the roof in height") {
  Box3 box = ThreeFloorBuilding().Bounds();
  CHECK(box.min.x == Approx(0.0).margin(1e-9));
  CHECK(box.min.y == Approx(0.0).margin(1e-9));
  CHECK(box.max.x == Approx(14.0));
  CHECK(box.max.y == Approx(10.0));
  CHECK(box.min.z == Approx(0.0).margin(1e-9));
  CHECK(box.max.z == Approx(3 * 2.8 + BuildOptions{}.slab_thickness));
}

TEST_CASE("a ray passes through every door, entrance, open and window, and is blocked by the wall above or below") {
  const Layout& layout = ThreeFloorLayout();
  const BuildingMesh& b = ThreeFloorBuilding();
  BuildOptions o;
  auto check = [&](const Element& e, int level, double pass_z, double block_z) {
    INFO(e.name);
    double floor = b.FloorZ(level);
    Vec3 n = PlanNormal(e.shape);
    CHECK(PassesWalls(b, Mid(e.shape), floor + pass_z, n));
    if (block_z > 0) CHECK_FALSE(PassesWalls(b, Mid(e.shape), floor + block_z, n));
  };
  for (const Element& e : layout.entrances) check(e, 0, 1.0, 2.4);
  for (const Element& e : layout.doors) check(e, e.level, 1.0, 2.4);
  for (const Element& e : layout.opens) check(e, e.level, 2.5, 0.0);  // full height
  for (const Element& e : layout.windows) {
    double sill = e.panoramic ? o.panoramic_sill : o.window_sill;
    check(e, e.level, (sill + o.window_head) / 2, e.panoramic ? 0.0 : sill / 2);
  }
  // Door leaves stand open beside their openings: the opening itself stays free of them too.
  for (const Element& e : layout.doors) {
    Vec3 n = PlanNormal(e.shape);
    Point m = Mid(e.shape);
    Vec3 start = Vec3{m.x, m.y, b.FloorZ(e.level) + 1.0} - n * 0.6;
    CHECK_FALSE(FirstHit(b, start, n, 1.2, [](const MeshPart& p) { return p.kind == PartKind::kDoorLeaf; }));
  }
  // And a ray into plain wall is blocked: the middle of the kitchen's east half of the south facade.
  CHECK_FALSE(PassesWalls(b, {8.5, 0}, 1.0, {0, 1, 0}));
}

TEST_CASE("slabs have their stair holes: a vertical ray passes through the hole and not beside it") {
  const BuildingMesh& b = ThreeFloorBuilding();
  REQUIRE(b.stairs.size() == 2);
  for (const BuiltStair& s : b.stairs) {
    INFO("stair of level " << s.level);
    REQUIRE(s.hole.size() == 4);
    Point c{0, 0};
    for (Point p : s.hole) c = {c.x + p.x / 4, c.y + p.y / 4};
    double below = (s.level + 1) * kLevelHeight - 0.05;
    CHECK_FALSE(FirstHit(b, {c.x, c.y, below}, {0, 0, 1}, 0.4, IsSlab));
    // Beside the hole: the arrival strip of the same utility room, and the bedroom next door.
    CHECK(FirstHit(b, {2.0, 3.6, below}, {0, 0, 1}, 0.4, IsSlab));
    CHECK(FirstHit(b, {6.5, 2.0, below}, {0, 0, 1}, 0.4, IsSlab));
  }
  // The top floor's utility room has no staircase, so the roof above it is whole.
  CHECK(FirstHit(b, {2.0, 2.0, 3 * kLevelHeight - 0.05}, {0, 0, 1}, 0.4, IsSlab));
}

TEST_CASE("the staircase climbs one storey in risers of 2.8 m / 16") {
  const BuildingMesh& b = ThreeFloorBuilding();
  for (const MeshPart& p : b.parts) {
    if (p.kind != PartKind::kStair) continue;
    Box3 box = p.mesh.Bounds();
    CHECK(box.min.z == Approx(b.FloorZ(p.level)));
    CHECK(box.max.z == Approx(b.FloorZ(p.level + 1) - kLevelHeight / 16));  // the last riser is the slab edge
    std::set<long> heights;
    for (const Vec3& v : p.mesh.vertices) heights.insert(std::lround((v.z - b.FloorZ(p.level)) / (kLevelHeight / 16) * 1000));
    for (long h : heights) CHECK(h % 1000 == 0);  // every vertex on a riser boundary
    CHECK(box.max.x - box.min.x < 4.0);
    CHECK(box.max.y - box.min.y < 4.0);
  }
}

TEST_CASE("VCR on the built geometry: each staircase overlaps the hole of the slab above") {
  VcrReport vcr = MeasureVcr(ThreeFloorBuilding());
  REQUIRE(vcr.floor_pairs() == 2);
  CHECK(vcr.connected_pairs() == 2);
  CHECK(vcr.vcr() == 1.0);
  // The flights leave a passage beside them (for the first floor's east door), so they cover about
  // 1.8 x 2.8 m of the 3.65 m square free, not the whole room as before.
  for (const auto& pair : vcr.pairs) CHECK(pair.overlap_area > 4.5);
  // Without its utility room upstairs... a one-floor building has no pair at all.
  Layout ground = ThreeFloorLayout();
  std::erase_if(ground.rooms, [](const Room& r) { return r.level > 0; });
  auto b = BuildBuilding(ground);
  REQUIRE(b);
  CHECK(MeasureVcr(*b).floor_pairs() == 0);
  CHECK(b->CountParts(PartKind::kStair) == 0);
}

TEST_CASE("walls meet cleanly: no plan point is under two wall pieces, junctions and corners are covered once") {
  const Layout& layout = ThreeFloorLayout();
  const BuildingMesh& b = ThreeFloorBuilding();
  // A grid over the ground floor: coverage is 0 or 1 everywhere.
  int covered = 0;
  for (double x = 0.013; x < 14; x += 0.071)
    for (double y = 0.011; y < 10; y += 0.067) {
      int hits = TopHits(b, 0, {x, y});
      REQUIRE(hits <= 1);
      covered += hits;
    }
  CHECK(covered > 100);
  // Every interior wall end (T, L, X junctions and ends on the facade) is inside exactly one piece.
  for (const Element& e : layout.interiors)
    for (int end = 0; end < 2; ++end) {
      Point p = end == 0 ? e.shape.a : e.shape.b, q = end == 0 ? e.shape.b : e.shape.a;
      double len = std::hypot(q.x - p.x, q.y - p.y);
      Point d{(q.x - p.x) / len, (q.y - p.y) / len};
      // 2 mm into the wall from its end, off its centre line (not on a bisector through the node).
      Point probe{p.x + 0.002 * d.x - 0.0007 * d.y, p.y + 0.002 * d.y + 0.0007 * d.x};
      INFO(e.name << " end (" << p.x << ", " << p.y << ")");
      bool on_open = false;
      for (const Element& o : layout.opens)
        on_open = on_open || (o.level == e.level && std::abs((o.shape.a.x - p.x) * (o.shape.b.y - p.y) -
                                                             (o.shape.a.y - p.y) * (o.shape.b.x - p.x)) < 1e-9 &&
                              std::min(o.shape.a.x, o.shape.b.x) <= p.x && p.x <= std::max(o.shape.a.x, o.shape.b.x) &&
                              std::min(o.shape.a.y, o.shape.b.y) <= p.y && p.y <= std::max(o.shape.a.y, o.shape.b.y));
      if (!on_open) CHECK(TopHits(b, e.level, probe) == 1);
    }
  // Mitred corners, the angled ones included: just inside each footprint corner of the ground floor.
  for (Point c : {Point{0.01, 0.03}, Point{13.99, 0.03}, Point{13.97, 6.0}, Point{12.0, 9.98}, Point{0.01, 9.97}})  // off the mitre lines
    CHECK(TopHits(b, 0, c) == 1);
}

TEST_CASE("a wall piece with a door and a window is one closed solid, openings are cut through") {
  WallFrame f{{0, 0.0}, {1, 0}, {0, 1}, 0.2};
  Ring plan = {{0, -0.1}, {5, -0.1}, {5, 0.1}, {0, 0.1}};
  SRange full = FullSection(plan, f);
  CHECK(full.lo == Approx(0.0).margin(1e-12));
  CHECK(full.hi == Approx(5.0));
  TriangleMesh m = WallSolid(plan, f, 0.0, 2.6, {{0.5, 1.5, 0.0, 2.1}, {2.5, 4.0, 0.9, 2.1}});
  SolidCheck check = CheckSolid(m);
  CHECK(check.closed);
  CHECK(check.volume == Approx(0.2 * (5 * 2.6 - 1.0 * 2.1 - 1.5 * 1.2)));
}

TEST_CASE("layouts that cannot become a building are refused with the reason") {
  Layout gap = ThreeFloorLayout();
  std::erase_if(gap.rooms, [](const Room& r) { return r.level == 1; });  // level 2 floats above nothing
  auto b = BuildBuilding(gap);
  REQUIRE_FALSE(b);
  CHECK_THAT(b.error(), Catch::Contains("level 1 has no rooms"));

  Layout apart = ThreeFloorLayout();
  std::erase_if(apart.rooms, [](const Room& r) { return r.level > 0; });
  for (Room& r : apart.rooms)
    if (r.name() == "dining-room_0/0") r.polygon = {{20, 0}, {25, 0}, {25, 4}, {20, 4}};
  b = BuildBuilding(apart);
  REQUIRE_FALSE(b);
  CHECK_THAT(b.error(), Catch::Contains("do not tile one polygon"));

  CHECK_FALSE(BuildBuilding(Layout{}));
  BuildOptions bad;
  bad.exterior_wall_thickness = 0.0;
  auto refused = BuildBuilding(ThreeFloorLayout(), bad);
  REQUIRE_FALSE(refused);
  CHECK_THAT(refused.error(), Catch::Contains("exterior_wall_thickness"));
}

TEST_CASE("every fixture layout that passes the geometric rules builds into closed solids") {
  for (const char* name : {"house_one_floor", "house_two_floors", "bungalow_angled", "villa_three_floors"}) {
    INFO(name);
    auto layout = LoadLayout(std::string(VILLA_FIXTURE_DIR) + "/layouts/" + name + ".json");
    REQUIRE(layout);
    auto b = BuildBuilding(*layout);
    REQUIRE(b);
    for (const MeshPart& p : b->parts) {
      INFO(p.name);
      CHECK(CheckSolid(p.mesh).ok());
    }
    VcrReport vcr = MeasureVcr(*b);
    CHECK(vcr.connected_pairs() == vcr.floor_pairs());
    CHECK(b->Bounds().max.z == Approx(b->levels * kLevelHeight + b->slab_thickness));
  }
}

TEST_CASE("a wall ending on the facade beside a courtyard notch stops at the exterior wall's inner face") {
  auto layout = ParseLayoutText(kUShapedHouse, "u-shaped fixture");
  REQUIRE(layout);
  auto b = BuildBuilding(*layout);
  REQUIRE(b);
  CHECK(b->warnings.empty());  // every door found its wall
  for (const MeshPart& p : b->parts) {
    INFO(p.name);
    CHECK(CheckSolid(p.mesh).ok());
    if (p.name == "wall_living0_bathroom0") {
      Box3 box = p.mesh.Bounds();
      CHECK(box.min.x == Approx(0.25));
      CHECK(box.max.x == Approx(4.25));  // the courtyard's exterior wall is x in [4.25, 4.5]
    }
  }
  CHECK(b->CountParts(PartKind::kDoorLeaf) == static_cast<int>(layout->doors.size() + layout->entrances.size()));
}

TEST_CASE("issue 31: railings guard every stair hole but where the flight arrives, and every terrace's open edge") {
  const BuildingMesh& b = ThreeFloorBuilding();
  auto part = [&](const std::string& name) -> const MeshPart* {
    for (const MeshPart& p : b.parts)
      if (p.name == name) return &p;
    return nullptr;
  };
  REQUIRE(b.stairs.size() == 2);
  for (const BuiltStair& st : b.stairs) {
    INFO(st.room);
    const MeshPart* rail = part("railing_" + st.room);
    REQUIRE(rail);
    CHECK(rail->kind == PartKind::kRailing);
    CHECK(rail->level == st.level + 1);
    // Standing on the floor above, 1 m tall.
    const Box3 box = rail->mesh.Bounds();
    CHECK(box.min.z == Approx(b.FloorZ(st.level + 1)).margin(1e-9));
    CHECK(box.max.z == Approx(b.FloorZ(st.level + 1) + 1.0).margin(1e-9));
    CHECK(CheckSolid(rail->mesh).ok());
    // Along the hole, on the floor beside it: every vertex within 0.15 m of the hole's outline, none inside.
    for (const Vec3& v : rail->mesh.vertices) {
      CHECK(DistanceToBoundary({v.x, v.y}, st.hole) < 0.15);
      CHECK(!PointInRing({v.x, v.y}, st.hole, 0.0));
    }
    // The way off the flight stays open: nothing within 0.3 m of the arrival edge's middle.
    const Point mid = geo::Scale(geo::Add(st.arrival[0], st.arrival[1]), 0.5);
    for (const Vec3& v : rail->mesh.vertices) CHECK(Distance(mid, {v.x, v.y}) > 0.3);
    // And it stands where a person could fall: it guards more than the arrival edge's length.
    CHECK((box.max.x - box.min.x) + (box.max.y - box.min.y) > Distance(st.arrival[0], st.arrival[1]));
  }
  // The terrace: a railing on its slab, inside its outline, not along the wall of the level above.
  int terraces = 0;
  for (const MeshPart& t : b.parts) {
    if (t.kind != PartKind::kTerrace) continue;
    ++terraces;
    const MeshPart* rail = part("railing_" + t.name);
    REQUIRE(rail);
    const Box3 slab = t.mesh.Bounds(), box = rail->mesh.Bounds();
    CHECK(box.min.z == Approx(slab.max.z).margin(1e-9));
    CHECK(box.max.z == Approx(slab.max.z + 1.0).margin(1e-9));
    CHECK(box.min.x >= slab.min.x - 1e-9);
    CHECK(box.max.x <= slab.max.x + 1e-9);
    CHECK(box.min.y >= slab.min.y - 1e-9);
    CHECK(box.max.y <= slab.max.y + 1e-9);
  }
  CHECK(terraces >= 1);
  CHECK(b.CountParts(PartKind::kRailing) == static_cast<int>(b.stairs.size()) + terraces);
}

TEST_CASE("issue 31: every window has a frame round its pane, within the wall's thickness") {
  const BuildingMesh& b = ThreeFloorBuilding();
  const Layout& layout = ThreeFloorLayout();
  CHECK(b.CountParts(PartKind::kWindowFrame) == static_cast<int>(layout.windows.size()));
  for (const MeshPart& pane : b.parts) {
    if (pane.kind != PartKind::kWindowGlass) continue;
    INFO(pane.name);
    const MeshPart* frame = nullptr;
    for (const MeshPart& p : b.parts)
      if (p.kind == PartKind::kWindowFrame && p.name == "frame_" + pane.name) frame = &p;
    REQUIRE(frame);
    CHECK(frame->level == pane.level);
    CHECK(frame->element == pane.element);
    // Its outline is the pane's: the same extent up and along the wall; no thicker than the wall.
    const Box3 g = pane.mesh.Bounds(), f = frame->mesh.Bounds();
    CHECK(f.min.z == Approx(g.min.z).margin(1e-9));
    CHECK(f.max.z == Approx(g.max.z).margin(1e-9));
    CHECK(std::max(f.max.x - f.min.x, f.max.y - f.min.y) == Approx(std::max(g.max.x - g.min.x, g.max.y - g.min.y)).margin(0.08));
    if (std::min(g.max.x - g.min.x, g.max.y - g.min.y) < 0.05)  // a wall along x or y (not an angled one)
      CHECK(std::min(f.max.x - f.min.x, f.max.y - f.min.y) <= 0.07 + 1e-9);
    // Four closed bars leave the pane's middle clear.
    CHECK(frame->mesh.triangles.size() == 4 * 12);
    const Vec3 mid{(g.min.x + g.max.x) / 2, (g.min.y + g.max.y) / 2, (g.min.z + g.max.z) / 2};
    for (const Vec3& v : frame->mesh.vertices) CHECK(std::abs(v.z - mid.z) + std::hypot(v.x - mid.x, v.y - mid.y) > 0.1);
  }
}
