// The solver on small realistic rooms: every object placed with CR = FR = OBR = 0 and full containment
// (rectangular, L-shaped and angled rooms), relations honoured, the dense-table failure resolved by
// removal and reported, the same seed giving the same poses, and bad input rejected with its reason.
#include <catch2/catch.hpp>

#include <cmath>
#include <iostream>

#include "fixtures.h"
#include "mesh/geometry2d.h"
#include "solver/solve.h"
#include "layout/geometry.h"

namespace villa::solver {
namespace {

using namespace fixtures;

const ObjectPlacement& PlacementOf(const RoomSolution& s, const std::string& id) {
  for (size_t i = 0; i < s.objects.size(); ++i) {
    if (s.objects[i].id == id) return s.placements[i];
  }
  FAIL("no object " << id);
  return s.placements[0];
}

void RequireClean(const RoomSolution& s, size_t objects) {
  INFO(s.summary.BriefReport());
  const ExactMetrics& m = s.summary.metrics;
  CHECK(s.summary.outcome == Outcome::kConverged);
  CHECK(m.cr == 0.0);
  CHECK(m.fr == 0.0);
  CHECK(m.obr == 0.0);
  CHECK(m.csr == 1.0);
  CHECK(m.objects == static_cast<int>(objects));
  CHECK(s.summary.removed.empty());
  CHECK(s.summary.energy.collision == 0.0);
  CHECK(s.summary.energy.support == 0.0);
  CHECK(s.summary.energy.total <= 1.0);
  for (const ObjectPlacement& p : s.placements) {
    CHECK(p.placed);
    CHECK(p.pose.yaw > -3.1416);
    CHECK(p.pose.yaw <= 3.1416);
  }
}

TEST_CASE("A living room is furnished with no collision, nothing floating or out of bounds, books inside", "[solver]") {
  RoomProblem room = Rectangle(5.0, 4.2);
  FurnishLivingRoom(room);
  auto solved = SolveRoom(room, {});
  REQUIRE(solved.ok());
  RequireClean(*solved, room.objects.size());
  const RoomSolution& s = *solved;
  CHECK(s.summary.metrics.inside_edges == 8);
  // The coffee table stands in front of the sofa, centred, within 0.5 m.
  const Pose sofa = PlacementOf(s, "r/sofa-0").pose, table = PlacementOf(s, "r/coffee-table-0").pose;
  const Point f{std::sin(sofa.yaw), -std::cos(sofa.yaw)};
  const Point d{table.x - sofa.x, table.y - sofa.y};
  const double ahead = geo::Dot(d, f), lateral = std::abs(geo::Cross(f, d));
  // The table's half extent along the sofa's facing (it may stand turned by 90 degrees).
  const double half = 0.5 * std::abs(std::cos(table.yaw - sofa.yaw)) * 0.55 + 0.5 * std::abs(std::sin(table.yaw - sofa.yaw)) * 1.0;
  CHECK(ahead - 0.45 - half >= -0.01);
  CHECK(ahead - 0.45 - half <= 0.51);
  CHECK(lateral <= 0.051);
  // The sofa stands with its back 2 cm from its wall.
  const ObjectPlacement& sp = PlacementOf(s, "r/sofa-0");
  REQUIRE(sp.wall >= 0);
  const WallEdge& wall = room.walls[sp.wall];
  CHECK(PointSegmentDistance({sofa.x, sofa.y}, {wall.a, wall.b}) == Approx(0.02 + 0.45).margin(1e-6));
  // The TV rests on its stand, the books on their cavities' floors.
  const ObjectPlacement& tv = PlacementOf(s, "r/tv-0");
  CHECK(tv.pose.z == Approx(PlacementOf(s, "r/tv-stand-0").pose.z + 0.5));
  CHECK(tv.surface == 0);
  for (int k = 0; k < 8; ++k) CHECK(PlacementOf(s, "r/books-" + std::to_string(k)).cavity >= 0);
  // The painting hangs on a wall, clear of the floor objects below it.
  const ObjectPlacement& painting = PlacementOf(s, "r/painting-0");
  CHECK(painting.wall >= 0);
  CHECK(painting.pose.z >= room.floor_z + 0.6 - 1e-9);
  std::cout << "living room:\n" << s.summary.BriefReport();
}

TEST_CASE("An L-shaped living room keeps every object off the inner corner", "[solver]") {
  RoomProblem room = LShape();
  FurnishLivingRoom(room);
  auto solved = SolveRoom(room, {});
  REQUIRE(solved.ok());
  RequireClean(*solved, room.objects.size());
}

TEST_CASE("A room with an angled wall is furnished cleanly", "[solver]") {
  RoomProblem room = Angled();
  FurnishLivingRoom(room);
  auto solved = SolveRoom(room, {});
  REQUIRE(solved.ok());
  RequireClean(*solved, room.objects.size());
}

TEST_CASE("A room with no right angle and a skewed inner corner is furnished cleanly", "[solver]") {
  // Walls at 0, 17, 113, 200 and 250 degrees or so, and a reflex corner between two of them.
  RoomProblem room = WithFloor({{0, 0}, {4.6, 0}, {5.9, 4.0}, {3.4, 3.1}, {2.2, 5.3}, {-0.8, 4.6}});
  FurnishLivingRoom(room);
  auto solved = SolveRoom(room, {});
  REQUIRE(solved.ok());
  RequireClean(*solved, room.objects.size());
}

TEST_CASE("A piece on its parent is moved out of the parent's collision hull, raised or slid, a few mm at most", "[solver][physics]") {
  RoomProblem room = Rectangle(4, 3);
  room.objects.push_back(TableObject("table-0", 0.8, 0.8, 0.7));
  room.objects.push_back(SmallObject("cup-0", 0.12, 0.12, 0.1, "table-0", Relation::kOnTop));
  RoomSolver solver(room, {});
  const Status init = solver.Initialise();
  INFO((init.ok() ? std::string() : init.error()));
  REQUIRE(init.ok());
  solver.RunAgent();
  solver.Finish();
  auto pose_of = [&](const std::string& id) {
    const RoomSolution s = solver.Solution();
    for (size_t k = 0; k < s.objects.size(); ++k)
      if (s.objects[k].id == id) return s.placements[k].pose;
    return Pose{-100.0, -100.0, -1.0, 0.0, 1.0};
  };
  auto z_of = [&](const std::string& id) { return pose_of(id).z; };
  const double cup = z_of("r/cup-0"), table = z_of("r/table-0");
  REQUIRE(cup > table);
  CHECK(solver.Lift("r/cup-0", 0.004));
  CHECK(z_of("r/cup-0") == Approx(cup + 0.004).margin(1e-9));
  CHECK(z_of("r/table-0") == table);
  CHECK(solver.Solution().summary.metrics.Clean());
  CHECK_FALSE(solver.Lift("r/cup-0", RoomSolver::kMaxOutOfHull));  // 4 mm + 8 mm: more than a hull's error
  CHECK_FALSE(solver.Lift("r/table-0", 0.002));                // on the floor: nothing to rise onto
  // Pressed sideways into its parent's hull: slid along the surface, depth and 0.5 mm, its height kept.
  const double x = pose_of("r/cup-0").x, z = z_of("r/cup-0");
  CHECK(solver.MoveOutOfParent("r/cup-0", {1.0, 0.0, 0.1}, 0.003));
  CHECK(pose_of("r/cup-0").x == Approx(x + 0.0035).margin(1e-6));
  CHECK(z_of("r/cup-0") == Approx(z).margin(1e-9));
  CHECK_FALSE(solver.MoveOutOfParent("r/cup-0", {0.0, 1.0, 0.0}, 0.01));  // deeper than a hull's error
  CHECK(solver.Solution().summary.metrics.Clean());
  CHECK_FALSE(solver.Lift("no-such-thing", 0.002));
}

TEST_CASE("Too many things on a small table end in remove_entity, said in the outcome", "[solver]") {
  // 20 cups of 12 x 12 cm for a 50 x 50 cm top: 16 fit at most.
  RoomProblem room = Rectangle(4, 3);
  room.objects.push_back(TableObject("table-0", 0.5, 0.5, 0.7));
  for (int k = 0; k < 20; ++k) {
    ProblemObject cup = SmallObject("cup-" + std::to_string(k), 0.12, 0.12, 0.1, "table-0", Relation::kOnTop);
    cup.priority = k < 3 ? Priority::kNamed : Priority::kDecorative;
    room.objects.push_back(cup);
  }
  auto solved = SolveRoom(room, {});
  REQUIRE(solved.ok());
  const RoomSolution& s = *solved;
  INFO(s.summary.BriefReport());
  CHECK(s.summary.metrics.Clean());
  CHECK_FALSE(s.summary.removed.empty());
  CHECK(s.summary.outcome == Outcome::kConverged);
  int removals = 0;
  for (const ActionResult& a : s.summary.actions) removals += a.action.kind == ActionKind::kRemoveEntity;
  CHECK(removals == static_cast<int>(s.summary.removed.size()));
  // The named cups stay; at most 16 cups of 12 cm fit a 50 cm top (4 x 4 with gaps of a few mm).
  for (int k = 0; k < 3; ++k) CHECK(PlacementOf(s, "r/cup-" + std::to_string(k)).placed);
  CHECK(s.objects.size() <= 1 + 16);
  CHECK(s.objects.size() >= 1 + 9);
  const auto record = s.summary.SolveRecord();
  CHECK(record["removed"].size() == s.summary.removed.size());
  REQUIRE_FALSE(record["actions"].empty());
  CHECK(record["actions"].back()["action"] == "remove_entity");
}

TEST_CASE("Every room type, rectangular, L-shaped and angled, is furnished cleanly with its full count", "[solver]") {
  for (RoomType type : kRoomTypes) {
    for (RoomShape shape : {RoomShape::kRectangle, RoomShape::kL, RoomShape::kAngled}) {
      const RoomProblem room = SyntheticRoom(type, shape, 1);
      auto solved = SolveRoom(room, {});
      REQUIRE(solved.ok());
      INFO(RoomTypeName(type) << " " << RoomShapeName(shape) << "\n" << solved->summary.BriefReport());
      const ExactMetrics& m = solved->summary.metrics;
      CHECK(m.Clean());
      CHECK(m.cr == 0.0);
      CHECK(m.fr == 0.0);
      CHECK(m.obr == 0.0);
      CHECK(m.csr == 1.0);
      CHECK(solved->summary.outcome == Outcome::kConverged);
      CHECK(solved->summary.removed.empty());
      if (type == RoomType::kLiving || type == RoomType::kDining || type == RoomType::kBedroom ||
          type == RoomType::kKitchen || type == RoomType::kChildren) {
        CHECK(m.objects >= 22);
      }
    }
  }
}

TEST_CASE("An anchor too wide for every wall is shrunk within its range rather than removed", "[solver]") {
  RoomProblem room = Rectangle(3.0, 2.6);
  ProblemObject bench = BoxObject("bench-0", 3.1, 0.45, 0.45);
  bench.relation = Relation::kAgainstWall;
  bench.scale_min = 0.9;
  room.objects.push_back(bench);
  auto solved = SolveRoom(room, {});
  REQUIRE(solved.ok());
  INFO(solved->summary.BriefReport());
  CHECK(solved->summary.metrics.Clean());
  CHECK(solved->summary.removed.empty());
  REQUIRE(solved->objects.size() == 1);
  CHECK(solved->placements[0].pose.scale == Approx(0.9));
  bool shrunk = false;
  for (const ActionResult& a : solved->summary.actions) shrunk |= a.action.kind == ActionKind::kUpdateScale;
  CHECK(shrunk);
  // With scaling inside Ceres, the polish finds a scale that fits by itself.
  SolveOptions options;
  options.optimise_scale = true;
  auto free_scale = SolveRoom(room, options);
  REQUIRE(free_scale.ok());
  CHECK(free_scale->summary.metrics.Clean());
  CHECK(free_scale->placements[0].pose.scale < 0.96);
  CHECK(free_scale->placements[0].pose.scale >= 0.9);
}

TEST_CASE("The same seed gives the same poses and the same solve record bytes", "[solver]") {
  RoomProblem room = LShape();
  FurnishLivingRoom(room);
  SolveOptions options;
  options.seed = 7;
  auto a = SolveRoom(room, options);
  auto b = SolveRoom(room, options);
  REQUIRE(a.ok());
  REQUIRE(b.ok());
  REQUIRE(a->placements.size() == b->placements.size());
  for (size_t i = 0; i < a->placements.size(); ++i) {
    CHECK(a->placements[i].pose.x == b->placements[i].pose.x);
    CHECK(a->placements[i].pose.y == b->placements[i].pose.y);
    CHECK(a->placements[i].pose.z == b->placements[i].pose.z);
    CHECK(a->placements[i].pose.yaw == b->placements[i].pose.yaw);
  }
  CHECK(a->summary.SolveRecord().dump() == b->summary.SolveRecord().dump());
}

TEST_CASE("Sparse and dense linear solvers both give clean rooms", "[solver]") {
  RoomProblem room = Rectangle(5.0, 4.2);
  FurnishLivingRoom(room);
  SolveOptions options;
  options.linear_solver = LinearSolverChoice::kSparseNormalCholesky;
  auto sparse = SolveRoom(room, options);
  REQUIRE(sparse.ok());
  CHECK(sparse->summary.sparse);
  RequireClean(*sparse, room.objects.size());
  options.linear_solver = LinearSolverChoice::kDenseQr;
  auto dense = SolveRoom(room, options);
  REQUIRE(dense.ok());
  CHECK_FALSE(dense->summary.sparse);
  RequireClean(*dense, room.objects.size());
}

TEST_CASE("Bad problems and options are refused with the field and the value", "[solver]") {
  RoomProblem room = Rectangle(4, 3);
  room.objects = {BoxObject("box-0", 1, 1, 1), BoxObject("box-0", 1, 1, 1)};
  auto twice = SolveRoom(room, {});
  REQUIRE_FALSE(twice.ok());
  CHECK(twice.error() == "room r: objects: id \"r/box-0\" appears twice");
  room.objects = {SmallObject("cup-0", 0.1, 0.1, 0.1, "table-9", Relation::kOnTop)};
  auto orphan = SolveRoom(room, {});
  REQUIRE_FALSE(orphan.ok());
  CHECK(orphan.error() == "room r: object \"r/cup-0\": parent \"r/table-9\" is not an object of the room");
  room.objects = {BoxObject("box-0", 1, 1, 1)};
  room.objects[0].relation = Relation::kInside;
  CHECK(SolveRoom(room, {}).error() == "room r: object \"r/box-0\": relation inside does not fit parent floor");
  room.objects[0].relation = Relation::kOnTop;
  room.objects[0].scale_min = 1.1;
  CHECK(SolveRoom(room, {}).error().find("scale range [1.1") != std::string::npos);
  room.objects[0].scale_min = 1.0;
  room.free_floor = {{0, 0}, {0, 3}, {4, 3}, {4, 0}};
  CHECK(SolveRoom(room, {}).error() == "room r: free_floor: must be counter-clockwise with a positive area");
  room.free_floor = Rectangle(4, 3).free_floor;
  room.objects[0].mesh = std::make_shared<AssetMesh>(AssetMesh{{{MeshMaterial{}, BoxMesh({-0.5, -0.5, 0}, {0.7, 0.5, 1})}}});
  CHECK(SolveRoom(room, {}).error() ==
        "room r: object \"r/box-0\": mesh reaches [-0.5, 0.7] along x, outside the asset box [-0.5, 0.5] of its size");
  room = Rectangle(4, 3);
  SolveOptions options;
  options.object_gap = 0.5;
  CHECK(SolveRoom(room, options).error() == "solver options: object_gap must be in [0, 0.2] m");
  ExactCheckOptions check;
  check.obr_samples = 3;
  CHECK(SolveRoom(room, {}, check).error() == "exact check options: obr_samples must be in [16, 100000]");
}

TEST_CASE("An empty room converges at once", "[solver]") {
  RoomProblem room = Rectangle(3, 3);
  auto solved = SolveRoom(room, {});
  REQUIRE(solved.ok());
  CHECK(solved->summary.outcome == Outcome::kConverged);
  CHECK(solved->summary.metrics.objects == 0);
  CHECK(solved->summary.energy.total == 0.0);
}

}  // namespace
}  // namespace villa::solver
