// Each energy term and each exact metric can fail: overlapping boxes, a floating cup, a book through a
// shelf side, a sofa through a wall, a box across the inner corner of an L room, a chair in a door sweep,
// unmet relations and a blocked interaction zone; and a clean arrangement scores zero everywhere.
#include <catch2/catch.hpp>

#include <numbers>

#include "fixtures.h"
#include "solver/energy.h"
#include "solver/exact_check.h"

namespace villa::solver {
namespace {

using namespace fixtures;

ObjectPlacement At(double x, double y, double z, double yaw_deg = 0.0, int surface = -1, int cavity = -1) {
  ObjectPlacement p;
  p.pose = {x, y, z, yaw_deg * std::numbers::pi / 180.0, 1.0};
  p.surface = surface;
  p.cavity = cavity;
  p.placed = true;
  return p;
}

TEST_CASE("A clean arrangement has zero energy and clean metrics", "[solver]") {
  RoomProblem room = Rectangle(4, 3);
  room.objects = {BoxObject("box-0", 1, 1, 1), BoxObject("box-1", 1, 1, 1, true),
                  SmallObject("cup-0", 0.1, 0.1, 0.12, "box-1", Relation::kOnTop)};
  const double z = room.floor_z;
  const std::vector<ObjectPlacement> at = {At(1, 1, z), At(3, 1.5, z), At(3, 1.5, z + 1.0, 0, 0)};
  const EnergyTerms e = ArrangementEnergy(room, at);
  CHECK(e.total == 0.0);
  const ExactMetrics m = CheckArrangement(room, at);
  CHECK(m.Clean());
  CHECK(m.objects == 3);
  CHECK(m.consumers == 3);
  CHECK(m.min_clearance < 0.0);  // nothing close enough to probe
}

TEST_CASE("Overlapping boxes: E_col is their shared volume and both count in CR", "[solver]") {
  RoomProblem room = Rectangle(4, 3);
  room.objects = {BoxObject("box-0", 1, 1, 1), BoxObject("box-1", 1, 1, 0.5), BoxObject("box-2", 0.5, 0.5, 0.5)};
  const double z = room.floor_z;
  const std::vector<ObjectPlacement> at = {At(1, 1, z), At(1.6, 1.2, z), At(3.2, 2.2, z)};
  const EnergyTerms e = ArrangementEnergy(room, at);
  CHECK(e.collision == Approx(0.4 * 0.8 * 0.5));
  CHECK(e.total == Approx(5 * 0.16));
  const ExactMetrics m = CheckArrangement(room, at);
  CHECK(m.colliding == 2);
  CHECK(m.cr == Approx(2.0 / 3.0));
  REQUIRE(m.pairs.size() == 1);
  CHECK(m.pairs[0].b == "r/box-1");
  // Two boxes 3 mm apart are close but not colliding: the nudge rule is not needed and FCL measures the gap.
  const std::vector<ObjectPlacement> close = {At(1, 1, z), At(2.003, 1, z), At(3.2, 2.2, z)};
  const ExactMetrics c = CheckArrangement(room, close);
  CHECK(c.colliding == 0);
  CHECK(c.min_clearance == Approx(0.003).margin(1e-6));
}

TEST_CASE("A floating cup fails FR and adds its gap to E_sup", "[solver]") {
  RoomProblem room = Rectangle(4, 3);
  room.objects = {TableObject("table-0", 1.2, 0.8, 0.75), SmallObject("cup-0", 0.1, 0.1, 0.12, "table-0", Relation::kOnTop)};
  const double z = room.floor_z;
  std::vector<ObjectPlacement> at = {At(2, 1.5, z), At(2.2, 1.4, z + 0.75 + 0.05, 0, 0)};
  EnergyTerms e = ArrangementEnergy(room, at);
  CHECK(e.support == Approx(0.05));
  ExactMetrics m = CheckArrangement(room, at);
  CHECK(m.floating == 1);
  CHECK(m.fr == Approx(0.5));
  CHECK(m.per_object[1].support_gap == Approx(0.05));
  // Resting on the top (a touching contact, no collision with its parent counted) is clean.
  at[1].pose.z = z + 0.75;
  CHECK(ArrangementEnergy(room, at).total == 0.0);
  CHECK(CheckArrangement(room, at).Clean());
  // Off the edge of the table: E_sup's out-of-support penalty and OBR.
  at[1].pose.x = 2.0 + 0.62;
  e = ArrangementEnergy(room, at);
  CHECK(e.support == Approx(1.0));
  m = CheckArrangement(room, at);
  CHECK(m.per_object[1].out_of_bounds);
  CHECK(m.per_object[1].in_bound_share < 0.99);
}

TEST_CASE("A book through a shelf side fails CSR, a book resting in the cavity passes", "[solver]") {
  RoomProblem room = Rectangle(4, 3);
  room.objects = {BookcaseObject("bookcase-0", 0.9, 0.32, 1.8, 5), SmallObject("books-0", 0.05, 0.22, 0.24, "bookcase-0", Relation::kInside)};
  const double z = room.floor_z;
  const double shelf = 0.02;  // cavity 0's floor above the bookcase bottom
  std::vector<ObjectPlacement> at = {At(2, 2.7, z), At(2.0, 2.68, z + shelf, 0, -1, 0)};
  ExactMetrics m = CheckArrangement(room, at);
  CHECK(m.inside_edges == 1);
  CHECK(m.contained == 1);
  CHECK(m.csr == 1.0);
  at[1].pose.x = 2.0 + 0.43;  // half the book sticks through the right side panel
  m = CheckArrangement(room, at);
  CHECK(m.contained == 0);
  CHECK(m.csr == 0.0);
  CHECK_FALSE(m.Clean());
  // Floating in the cavity: not resting on its floor.
  at[1].pose.x = 2.0;
  at[1].pose.z = z + shelf + 0.03;
  m = CheckArrangement(room, at);
  CHECK(m.contained == 0);
  CHECK(m.floating == 1);
}

TEST_CASE("A sofa through a wall collides with the wall part and leaves the floor", "[solver]") {
  RoomProblem room = Rectangle(4, 3);
  room.objects = {BoxObject("sofa-0", 2.0, 0.9, 0.85)};
  const double z = room.floor_z;
  const std::vector<ObjectPlacement> at = {At(2.0, 2.8, z)};  // back 0.25 m into the wall at y = 3
  const EnergyTerms e = ArrangementEnergy(room, at);
  CHECK(e.collision == Approx(2.0 * 0.25 * 0.85));
  const ExactMetrics m = CheckArrangement(room, at);
  CHECK(m.colliding == 1);
  REQUIRE_FALSE(m.pairs.empty());
  CHECK(m.pairs[0].building);
  CHECK(m.out_of_bounds == 1);
  CHECK(m.per_object[0].in_bound_share < 0.9);
}

TEST_CASE("A box across the inner corner of an L room is caught though its corners are all inside", "[solver]") {
  RoomProblem room = LShape();
  room.objects = {BoxObject("bench-0", 2.4, 0.4, 0.45)};
  const std::vector<ObjectPlacement> at = {At(3.0, 2.5, room.floor_z, -45.0)};
  const EnergyTerms e = ArrangementEnergy(room, at);
  CHECK(e.collision > 0.0);
  const ExactMetrics m = CheckArrangement(room, at);
  CHECK(m.out_of_bounds == 1);
  CHECK(m.colliding == 1);
}

TEST_CASE("A chair in a door sweep and a window zone for tall objects only", "[solver]") {
  RoomProblem room = Rectangle(4, 3);
  room.keep_outs.push_back({{{0, 0}, {0.9, 0}, {0.9, 0.9}, {0, 0.9}}, room.floor_z, room.floor_z + 2.1, KeepOutKind::kDoorSweep, "door"});
  room.keep_outs.push_back({{{2, 2.5}, {3.5, 2.5}, {3.5, 3}, {2, 3}}, room.floor_z + 0.9, room.floor_z + 2.1, KeepOutKind::kWindowZone, "window"});
  room.objects = {BoxObject("chair-0", 0.5, 0.5, 0.9), BoxObject("sideboard-0", 1.2, 0.4, 0.8), BoxObject("wardrobe-0", 1.0, 0.6, 2.0)};
  const double z = room.floor_z;
  std::vector<ObjectPlacement> at = {At(0.8, 0.8, z), At(2.75, 2.78, z), At(3.3, 1.0, z)};
  EnergyTerms e = ArrangementEnergy(room, at);
  CHECK(e.collision == Approx(0.35 * 0.35 * 0.9));  // the chair's corner in the sweep; the sideboard fits under the sill
  REQUIRE(e.overlaps.size() == 1);
  CHECK(e.overlaps[0] == std::make_pair(std::string("r/chair-0"), std::string("door_sweep door")));
  CHECK(e.findings == std::vector<std::string>{"collision r/chair-0 x door_sweep door: 0.110250 m3"});
  at[2] = At(2.75, 2.68, z);  // the wardrobe in front of the window
  at[1] = At(1.0, 2.78, z);
  e = ArrangementEnergy(room, at);
  CHECK(e.collision > 0.35 * 0.35 * 0.9 + 0.1);
}

TEST_CASE("Unmet relations and a blocked interaction zone raise E_sem", "[solver]") {
  RoomProblem room = Rectangle(6, 5);
  ProblemObject sofa = BoxObject("sofa-0", 2.0, 0.9, 0.85);
  sofa.zone = InteractionZone{"front", 0.45, {}};
  room.objects = {sofa, BoxObject("coffee-table-0", 1.0, 0.5, 0.4)};
  room.edges = {DefaultEdge("r/coffee-table-0", SemanticRelation::kNextTo, "r/sofa-0"),
                DefaultEdge("r/coffee-table-0", SemanticRelation::kFrontOf, "r/sofa-0")};
  const double z = room.floor_z;
  // 2.0 m in front of the sofa: front_of holds, next_to misses by 1.5 m.
  std::vector<ObjectPlacement> at = {At(3, 4, z), At(3, 4 - 0.45 - 2.0 - 0.25, z)};
  EnergyTerms e = ArrangementEnergy(room, at);
  CHECK(e.edge_violation[0] == Approx(1.5));
  CHECK(e.edge_violation[1] == 0.0);
  CHECK(e.semantic == Approx(1.5));
  // 0.2 m in front: both relations hold, but the table stands in the sofa's 0.45 m zone (not exempt).
  at[1].pose.y = 4 - 0.45 - 0.2 - 0.25;
  e = ArrangementEnergy(room, at);
  CHECK(e.edge_violation[0] == 0.0);
  CHECK(e.semantic == Approx(0.25));
  // Exempt: the zone may hold it.
  room.objects[0].zone->exempt = {"r/coffee-table-0"};
  CHECK(ArrangementEnergy(room, at).semantic == 0.0);
}

}  // namespace
}  // namespace villa::solver
