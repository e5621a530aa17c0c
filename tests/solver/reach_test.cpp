// Reachability (issue 13): the shared clearance query, the raster's verdict (a 0.35 m corridor at radius
// 0.2 and 0.15, a room sealed by a wardrobe, upstairs rooms reached only by the stairs), OMPL paths that
// keep the radius from every obstacle (re-checked here against the building's meshes and the objects'
// boxes with test code of its own), and the same paths for the same input.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "building/building.h"
#include "layout/geometry.h"
#include "layout/layout_io.h"
#include "mesh/geometry2d.h"
#include "reach_checks.h"
#include "solver/free_space.h"
#include "solver/reach.h"

namespace villa::solver {
namespace {

using namespace villa::geo;

Ring Box(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

// A 6 x 3 m floor cut in two by a 2 m thick wall with a straight corridor `width` wide through it; the
// person comes in on the left.
ReachInput Corridor(double width) {
  ReachInput in;
  in.levels.push_back({0, 0.175, {Box(0, 0, 6, 3)}});
  const double y0 = 1.5 - 0.5 * width, y1 = 1.5 + 0.5 * width;
  in.obstacles.push_back({"wall south", ObstacleKind::kWall, 0, "", {Box(2, 0, 4, y0)}, 0.0, 2.8});
  in.obstacles.push_back({"wall north", ObstacleKind::kWall, 0, "", {Box(2, y1, 4, 3)}, 0.0, 2.8});
  in.entrance = {{0, 1}, {0, 2}};
  in.inside = {1, 0};
  in.depth = 0.0;
  in.targets.push_back({TargetKind::kRoom, "left", "left", 0, {{Box(0, 0, 2, 3), TargetArea::Mode::kInside, 0.0}}});
  in.targets.push_back({TargetKind::kRoom, "right", "right", 0, {{Box(4, 0, 6, 3), TargetArea::Mode::kInside, 0.0}}});
  return in;
}

TEST_CASE("plan clearance: discs, capsules and polygons, apart and overlapping", "[reach]") {
  const PlanShape box = PlanShape::Polygon(Box(0, 0, 2, 1));
  CHECK(PlanClearance(PlanShape::Disc({3, 0.5}, 0.2), box) == Approx(0.8));
  CHECK(PlanClearance(PlanShape::Disc({3, 2}, 0.0), box) == Approx(std::sqrt(2.0)));
  // Inside: minus the distance to the nearest edge, minus the radius.
  CHECK(PlanClearance(PlanShape::Disc({1.8, 0.5}, 0.1), box) == Approx(-0.3));
  // A walk past the corner and a walk through the box.
  CHECK(PlanClearance(PlanShape::Capsule({-1, 2}, {3, 2}, 0.2), box) == Approx(0.8));
  CHECK(PlanClearance(PlanShape::Capsule({-1, 0.5}, {3, 0.5}, 0.0), box) < 0.0);
  // Two boxes: separating-axis depth.
  CHECK(PlanClearance(PlanShape::Polygon(Box(1.5, 0.5, 3, 2)), box) == Approx(-0.5));
  CHECK(PlanClearance(PlanShape::Polygon(Box(2.5, 0, 3, 1)), box) == Approx(0.5));
}

TEST_CASE("free space: the region's outside and its holes count, heights gate obstacles", "[reach]") {
  // A 4 x 4 floor with a 1 x 1 hole; one obstacle between z 1 and 2.
  const FreeSpace space({Box(0, 0, 4, 4), Box(1, 1, 2, 2)}, {{PlanShape::Polygon(Box(3, 3, 3.5, 3.5)), 1.0, 2.0, 7}});
  CHECK(space.InRegion({0.5, 0.5}));
  CHECK_FALSE(space.InRegion({1.5, 1.5}));
  CHECK(space.Clearance(PlanShape::Disc({0.5, 0.5}, 0.2), 0.0, 2.0, 5.0).clearance == Approx(0.3));
  CHECK(space.Clearance(PlanShape::Disc({1.5, 1.5}, 0.2), 0.0, 2.0, 5.0).clearance < 0.0);  // in the hole
  const auto near = space.Clearance(PlanShape::Disc({2.9, 3.2}, 0.05), 0.0, 2.0, 5.0);
  CHECK(near.obstacle == 0);
  CHECK(near.clearance == Approx(0.05));
  // Below the obstacle's heights it is not there.
  CHECK(space.Overlapping(PlanShape::Disc({3.2, 3.2}, 0.1), 0.0, 0.9).empty());
  CHECK(space.Overlapping(PlanShape::Disc({3.2, 3.2}, 0.1), 0.0, 1.5) == std::vector<int>{0});
}

TEST_CASE("a corridor 0.35 m wide is impassable at radius 0.2 and passable at 0.15", "[reach]") {
  const ReachInput in = Corridor(0.35);
  ReachOptions wide;
  wide.radius = 0.2;
  auto blocked = CheckReach(in, wide);
  REQUIRE(blocked.ok());
  INFO(blocked->BriefReport());
  CHECK(blocked->entrance_free);
  CHECK(blocked->Find("left")->reachable);
  const TargetResult* right = blocked->Find("right");
  CHECK_FALSE(right->reachable);
  CHECK(right->structural);  // nothing to move: the walls themselves
  CHECK(right->blockers.empty());
  CHECK(blocked->rooms_reachable == 1);

  ReachOptions narrow;
  narrow.radius = 0.15;
  auto open = CheckReach(in, narrow);
  REQUIRE(open.ok());
  INFO(open->BriefReport());
  const TargetResult* through = open->Find("right");
  REQUIRE(through->reachable);
  REQUIRE(through->path);
  // The path runs through the corridor and keeps 0.15 m from both walls.
  CHECK(through->path->points.back().x > 4.0);
  CHECK(PathClearance(*through->path, in, 0) >= 0.15 - 1e-9);
  // A path is at least as long as the straight line and no longer than the raster's 8-connected way.
  const Vec3 a = through->path->points.front(), b = through->path->points.back();
  CHECK(through->path->length >= Norm(b - a) - 1e-9);
  CHECK(through->path->length <= through->raster_length + 0.05);
}

TEST_CASE("a room sealed by a wardrobe across its door is unreachable, and the wardrobe is named", "[reach]") {
  const ReachOptions options;
  const Built built = BuildFixture("house_one_floor.json", options);
  const BuildingMesh* building = &built.building;
  const ReachInput* input = &built.input;
  // The bedroom's only door is (1.5, 5)-(2.5, 5); a 2 m wardrobe stands against that wall inside.
  ReachObject wardrobe;
  wardrobe.id = "bedroom_0/0/wardrobe-0";
  wardrobe.room = "bedroom_0/0";
  wardrobe.box = {{2.0, 5.06 + 0.02 + 0.3}, 0.0, 1.0, 0.3, 0.175, 0.175 + 2.0};
  wardrobe.zone = ZoneFootprints(wardrobe.box, "back", 0.8);  // it faces the room (+y): the asset's -y is the wall side
  ReachInput sealed = *input;
  AddObjects(sealed, {wardrobe}, options);
  auto report = CheckReach(sealed, options);
  REQUIRE(report.ok());
  INFO(report->BriefReport());
  CHECK(report->rooms == 6);
  const TargetResult* bedroom = report->Find("bedroom_0/0");
  REQUIRE(bedroom);
  CHECK_FALSE(bedroom->reachable);
  CHECK_FALSE(bedroom->structural);
  CHECK(bedroom->blockers == std::vector<std::string>{"bedroom_0/0/wardrobe-0"});
  CHECK_FALSE(bedroom->blocked_way.empty());
  CHECK_FALSE(report->Find("bedroom_0/0/wardrobe-0")->reachable);
  for (const std::string room : {"living-room_0/0", "kitchen_0/0", "dining-room_0/0", "bathroom_0/0", "office_0/0"}) {
    CHECK(report->Find(room)->reachable);
  }
  // Every drawn path keeps the radius from the building's meshes and the wardrobe.
  for (const TargetResult& t : report->targets) {
    if (!t.path) continue;
    INFO(t.name);
    CHECK(MeshClearance(*t.path, *building, {wardrobe}) >= options.radius - 1e-9);
  }
  // Without the wardrobe the bedroom is reached through its door.
  auto open = CheckReach(*input, options);
  REQUIRE(open.ok());
  CHECK(open->Find("bedroom_0/0")->reachable);
  CHECK(open->rooms_reachable == 6);
  CHECK(open->paths_drawn == 6);
}

TEST_CASE("rooms upstairs are reached from the entrance only through the staircase", "[reach]") {
  const ReachOptions options;
  const Built built = BuildFixture("house_two_floors.json", options);
  const BuildingMesh* building = &built.building;
  const ReachInput* input = &built.input;
  REQUIRE(input->stairs.size() == 1);
  auto report = CheckReach(*input, options);
  REQUIRE(report.ok());
  INFO(report->BriefReport());
  CHECK(report->rooms_reachable == report->rooms);
  const double upstairs = building->FloorZ(1);
  for (const TargetResult& t : report->targets) {
    INFO(t.name);
    REQUIRE(t.path);
    CHECK(MeshClearance(*t.path, *building, {}) >= options.radius - 1e-9);
    // Upstairs paths start on the ground floor, climb, and end on the upper floor.
    if (t.level == 1) {
      CHECK(t.path->points.front().z == Approx(building->FloorZ(0)));
      CHECK(t.path->points.back().z == Approx(upstairs));
    }
  }
  // Without the stair link nothing upstairs is reachable, and nothing movable is to blame.
  ReachInput no_stairs = *input;
  no_stairs.stairs.clear();
  auto cut = CheckReach(no_stairs, options);
  REQUIRE(cut.ok());
  for (const TargetResult& t : cut->targets) {
    INFO(t.name);
    CHECK(t.reachable == (t.level == 0));
    if (t.level == 1) CHECK(t.structural);
  }
}

TEST_CASE("a staircase is stepped on at its first treads and off at its last, read from its mesh", "[reach]") {
  const Built built = BuildFixture("house_two_floors.json");
  REQUIRE(built.input.stairs.size() == 1);
  const StairLink& link = built.input.stairs.front();
  REQUIRE(built.building.stairs.size() == 1);
  const BuiltStair& stair = built.building.stairs.front();
  CHECK(link.room == stair.room);
  CHECK_FALSE(link.upper_room.empty());
  CHECK(link.upper_room != link.room);  // the room above, by its own name
  const TriangleMesh* mesh = nullptr;
  for (const MeshPart& part : built.building.parts)
    if (part.kind == PartKind::kStair) mesh = &part.mesh;
  REQUIRE(mesh);
  const double floor0 = built.building.FloorZ(0), floor1 = built.building.FloorZ(1);
  const double riser = (floor1 - floor0) / 16.0;
  // Every stretch lies on the stair's outline, and the stair just inside it is within two risers of the
  // floor it is stepped from: low treads for the entries, high treads for the exits.
  auto top_inside = [&](const StairStep& s) {
    const Point m = {0.5 * (s.along.a.x + s.along.b.x) - 0.1 * s.out.x, 0.5 * (s.along.a.y + s.along.b.y) - 0.1 * s.out.y};
    double top = -1e300;
    for (const auto& t : mesh->triangles) {
      const Vec3 &a = mesh->vertices[t[0]], &b = mesh->vertices[t[1]], &c = mesh->vertices[t[2]];
      const double det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
      if (std::abs(det) < 1e-12) continue;
      const double u = ((m.x - a.x) * (c.y - a.y) - (c.x - a.x) * (m.y - a.y)) / det;
      const double v = ((b.x - a.x) * (m.y - a.y) - (m.x - a.x) * (b.y - a.y)) / det;
      if (u >= -1e-9 && v >= -1e-9 && u + v <= 1 + 1e-9) top = std::max(top, a.z + u * (b.z - a.z) + v * (c.z - a.z));
    }
    return top;
  };
  double foot = 0.0;
  REQUIRE_FALSE(link.entries.empty());
  for (const StairStep& s : link.entries) {
    CHECK(DistanceToBoundary(s.along.a, stair.footprint) < 1e-6);
    CHECK(DistanceToBoundary(s.along.b, stair.footprint) < 1e-6);
    const double top = top_inside(s);
    CHECK(top > floor0);
    CHECK(top <= floor0 + 2.0 * riser + 1e-6);
    foot = std::max(foot, Length(s.along));
  }
  REQUIRE_FALSE(link.exits.empty());
  for (const StairStep& s : link.exits) {
    const double top = top_inside(s);
    CHECK(top >= floor1 - 2.0 * riser - 1e-6);
    CHECK(top < floor1);
  }
  // The first flight's foot is a whole stretch: half the staircase's width (two flights side by side).
  CHECK(foot > 0.6);
  // The walk climbs one storey from the foot to the top.
  CHECK(link.walk.front().z == Approx(floor0));
  CHECK(link.walk.back().z == Approx(floor1));
  CHECK(link.length > floor1 - floor0);
}

TEST_CASE("reachability is deterministic: the same input gives the same report", "[reach]") {
  const ReachInput in = Corridor(0.6);
  auto a = CheckReach(in, {});
  auto b = CheckReach(in, {});
  REQUIRE(a.ok());
  REQUIRE(b.ok());
  CHECK(a->ToJson().dump() == b->ToJson().dump());
  CHECK(a->Find("right")->reachable);
}

TEST_CASE("reachability refuses bad options and inputs with the field named", "[reach]") {
  ReachOptions bad;
  bad.radius = 0.0;
  auto r = CheckReach(Corridor(0.5), bad);
  REQUIRE_FALSE(r.ok());
  CHECK(r.error().find("radius") != std::string::npos);
  ReachInput in = Corridor(0.5);
  in.targets[0].level = 3;
  auto t = CheckReach(in, {});
  REQUIRE_FALSE(t.ok());
  CHECK(t.error().find("left") != std::string::npos);
}

}  // namespace
}  // namespace villa::solver
