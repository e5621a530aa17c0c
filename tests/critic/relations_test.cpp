// The exact measures of the graph's relations (critic/relations.h): each relation holding and failing on
// boxes placed by hand, with the measured value; interaction zones with their exemptions; and agreement
// with the solver's own energy (an edge the critic calls met costs the solver nothing, and the other way
// round) on a solved room.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "critic/relations.h"
#include "room_fixture.h"
#include "solver/energy.h"
#include "solver/solve.h"

namespace villa {
namespace {

using critic::CheckEdge;
using critic::ObjectBox;
using R = scene::SemanticRelation;

constexpr double kDeg = std::numbers::pi / 180.0;

// A box centred at (x, y), turned by yaw degrees, w x d x h.
ObjectBox Box(double x, double y, double yaw_deg, double w, double d, double h = 0.8, double z = 0.0) {
  return {{x, y}, yaw_deg * kDeg, 0.5 * w, 0.5 * d, z, z + h};
}
scene::SemanticEdge Edge(R relation, scene::EdgeParams params = {}) { return {"a", relation, "b", params}; }

}  // namespace

TEST_CASE("face_to measures the angle between the source's front and the direction to the target", "[critic][relations]") {
  const ObjectBox sofa = Box(0, 0, 0, 2.0, 0.9);  // yaw 0: faces -y
  auto at = [&](double x, double y) { return CheckEdge(Edge(R::kFaceTo), sofa, Box(x, y, 0, 1.6, 0.45)); };
  CHECK(at(0, -2.5).satisfied);
  CHECK(at(0, -2.5).value == Approx(0.0).margin(1e-9));
  const critic::EdgeCheck side = at(2.5, -2.5);  // 45 degrees off
  CHECK_FALSE(side.satisfied);
  CHECK(side.value == Approx(45.0));
  CHECK(side.violation == Approx(15.0 / 30.0));
  CHECK(side.detail == "facing off by 45.0 deg, at most 30");
  CHECK_FALSE(at(0, 2.5).satisfied);  // behind it
  CHECK(CheckEdge(Edge(R::kFaceTo, {50.0, {}, {}, {}}), sofa, Box(2.5, -2.5, 0, 1, 1)).satisfied);
}

TEST_CASE("Side relations are bands: past the target's centre line and within its extent across it", "[critic][relations]") {
  const ObjectBox sofa = Box(0, 0, 0, 2.0, 0.9);  // front = -y, left = +x
  // A painting on the wall behind the sofa: its centre in front of the sofa's back face, still behind.
  const ObjectBox painting = Box(0.3, 0.41, 0, 1.0, 0.04, 0.7, 1.2);
  CHECK(CheckEdge(Edge(R::kBehind), painting, sofa).satisfied);
  CHECK_FALSE(CheckEdge(Edge(R::kFrontOf), painting, sofa).satisfied);
  // Past the sofa's end it is no longer behind it.
  const critic::EdgeCheck off = CheckEdge(Edge(R::kBehind), Box(1.4, 0.41, 0, 0.6, 0.04), sofa);
  CHECK_FALSE(off.satisfied);
  CHECK(off.violation == Approx(0.4));
  // A side table at the sofa's left (+x), within its depth.
  CHECK(CheckEdge(Edge(R::kLeftOf), Box(1.3, 0.0, 0, 0.5, 0.5), sofa).satisfied);
  CHECK_FALSE(CheckEdge(Edge(R::kRightOf), Box(1.3, 0.0, 0, 0.5, 0.5), sofa).satisfied);
  // The same frame turned: the sofa at yaw 90 faces +x, its left is +y.
  const ObjectBox turned = Box(0, 0, 90, 2.0, 0.9);
  CHECK(CheckEdge(Edge(R::kFrontOf), Box(1.5, 0.2, 0, 1, 0.6), turned).satisfied);
  CHECK(CheckEdge(Edge(R::kLeftOf), Box(0.0, 1.3, 0, 0.5, 0.5), turned).satisfied);
  // With a gap range the distance counts too: a coffee table 0.5 m in front of the sofa, then 0.9 m.
  const scene::EdgeParams gap{std::nullopt, 0.45, 0.6, std::nullopt};
  CHECK(CheckEdge(Edge(R::kFrontOf, gap), Box(0, -1.25, 0, 1.1, 0.6), sofa).satisfied);
  const critic::EdgeCheck far = CheckEdge(Edge(R::kFrontOf, gap), Box(0, -1.65, 0, 1.1, 0.6), sofa);
  CHECK_FALSE(far.satisfied);
  CHECK(far.violation == Approx(0.3));
}

TEST_CASE("next_to, near and far read the gap between the boxes, align the yaws, centered the lateral offset", "[critic][relations]") {
  const ObjectBox bed = Box(0, 0, 0, 1.6, 2.0);
  CHECK(critic::PlanGap(Box(1.05, 0, 0, 0.4, 0.4), bed) == Approx(0.05));
  CHECK(CheckEdge(Edge(R::kNextTo), Box(1.05, 0, 0, 0.4, 0.4), bed).satisfied);
  CHECK(CheckEdge(Edge(R::kNextTo, {std::nullopt, std::nullopt, 0.03, std::nullopt}), Box(1.05, 0, 0, 0.4, 0.4), bed).violation ==
        Approx(0.02));
  CHECK_FALSE(CheckEdge(Edge(R::kNextTo), Box(0.9, 0, 0, 0.4, 0.4), bed).satisfied);  // overlapping: gap < 0
  CHECK(CheckEdge(Edge(R::kNear), Box(2.0, 0, 0, 0.4, 0.4), bed).satisfied);
  CHECK_FALSE(CheckEdge(Edge(R::kNear), Box(1.05, 0, 0, 0.4, 0.4), bed).satisfied);
  CHECK(CheckEdge(Edge(R::kFar), Box(3.0, 0, 0, 0.4, 0.4), bed).satisfied);
  CHECK(CheckEdge(Edge(R::kAlign), Box(3, 0, 92, 1, 1), bed).satisfied);
  CHECK(CheckEdge(Edge(R::kAlign), Box(3, 0, 183, 1, 1), bed).satisfied);
  const critic::EdgeCheck turned = CheckEdge(Edge(R::kAlign), Box(3, 0, 20, 1, 1), bed);
  CHECK_FALSE(turned.satisfied);
  CHECK(turned.value == Approx(20.0));
  CHECK(CheckEdge(Edge(R::kCentered), Box(0.04, 1.2, 0, 1.0, 0.04), bed).satisfied);
  CHECK(CheckEdge(Edge(R::kCentered), Box(0.3, 1.2, 0, 1.0, 0.04), bed).value == Approx(0.3));
}

TEST_CASE("An interaction zone is entered by other objects' boxes, not by exempt ones or rugs", "[critic][relations]") {
  auto room = testing::MakeCriticRoom("living-room_0/0");
  solver::RoomSolver session(room->mapped.problem, room->input.solve, room->input.check);
  REQUIRE(session.Initialise().ok());
  session.RunAgent();
  solver::RoomSolution s = session.Solution();
  int sofa = -1, armchair = -1, table = -1;
  for (size_t i = 0; i < s.objects.size(); ++i) {
    if (s.objects[i].id == "living-room_0/0/sofa-0") sofa = static_cast<int>(i);
    if (s.objects[i].id == "living-room_0/0/armchair-0") armchair = static_cast<int>(i);
    if (s.objects[i].id == "living-room_0/0/coffee-table-0") table = static_cast<int>(i);
  }
  REQUIRE(sofa >= 0);
  REQUIRE(armchair >= 0);
  REQUIRE(table >= 0);
  REQUIRE(s.objects[sofa].zone);
  auto zone_of_sofa = [&](const critic::RoomRelations& r) {
    for (const critic::ZoneCheck& z : r.zones)
      if (z.owner == s.objects[sofa].id) return z;
    FAIL("no zone for the sofa");
    return critic::ZoneCheck{};
  };
  // An armchair put right in front of the sofa enters its zone; the coffee table there is exempt.
  const solver::Pose& p = s.placements[sofa].pose;
  const double fx = std::sin(p.yaw), fy = -std::cos(p.yaw);
  const double reach = 0.5 * s.objects[sofa].asset.size.y + 0.25;
  for (int k : {armchair, table}) {
    std::vector<solver::ObjectPlacement> moved = s.placements;
    moved[k].pose.x = p.x + fx * reach;
    moved[k].pose.y = p.y + fy * reach;
    const critic::ZoneCheck z = zone_of_sofa(critic::MeasureRelations(s.objects, moved, *room->input.edges));
    if (k == armchair) {
      CHECK(std::find(z.intruders.begin(), z.intruders.end(), s.objects[armchair].id) != z.intruders.end());
    } else {
      CHECK(std::find(z.intruders.begin(), z.intruders.end(), s.objects[table].id) == z.intruders.end());
    }
  }
}

TEST_CASE("The critic's measure agrees with the solver's energy on every edge of solved rooms", "[critic][relations]") {
  for (const char* name : {"living-room_0/0", "bedroom_0/0", "kitchen_0/0", "dining-room_0/0"}) {
    auto room = testing::MakeCriticRoom(name, 5);
    solver::RoomSolver session(room->mapped.problem, room->input.solve, room->input.check);
    REQUIRE(session.Initialise().ok());
    session.RunAgent();
    const solver::RoomSolution s = session.Solution();
    solver::RoomProblem now = room->mapped.problem;
    now.objects = s.objects;
    now.edges = s.edges;
    const solver::EnergyTerms e = solver::ArrangementEnergy(now, s.placements);
    REQUIRE(e.edge_violation.size() == s.edges.size());
    int measured = 0;
    for (size_t k = 0; k < s.edges.size(); ++k) {
      const solver::SemanticEdge& edge = s.edges[k];
      // The solver's edge as the graph writes it (angles in degrees).
      scene::SemanticEdge graph{edge.source, *scene::ParseSemanticRelation(solver::SemanticRelationName(edge.relation)), edge.target, {}};
      switch (edge.relation) {
        case solver::SemanticRelation::kFaceTo:
        case solver::SemanticRelation::kAlign: graph.params.max_deg = (edge.relation == solver::SemanticRelation::kFaceTo ? edge.max_angle : edge.tolerance) / kDeg; break;
        case solver::SemanticRelation::kCentered: graph.params.max_offset = edge.tolerance; break;
        case solver::SemanticRelation::kNextTo:
        case solver::SemanticRelation::kNear:
        case solver::SemanticRelation::kFar:
          graph.params.min_gap = edge.min_gap;
          if (edge.max_gap < 1e8) graph.params.max_gap = edge.max_gap;
          break;
        default: break;
      }
      const critic::RoomRelations r = critic::MeasureRelations(s.objects, s.placements, {graph});
      REQUIRE(r.edges.size() == 1);
      INFO(name << ": " << edge.source << " " << solver::SemanticRelationName(edge.relation) << " " << edge.target << ": "
                << r.edges[0].detail << ", solver violation " << e.edge_violation[k]);
      // The measure reads to 1 mm and 0.1 degree (0.0033 of the solver's 30-degree unit); the solver counts
      // any violation at all.
      if (r.edges[0].satisfied)
        CHECK(e.edge_violation[k] <= 0.004);
      else
        CHECK(e.edge_violation[k] > 1e-9);
      ++measured;
    }
    INFO(name << ": " << s.objects.size() << " objects, " << s.edges.size() << " edges; " << s.summary.BriefReport());
    CHECK(measured > 0);
  }
}

}  // namespace villa
