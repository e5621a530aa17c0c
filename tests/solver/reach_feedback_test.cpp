// Reachability fed back to the solver: a bedroom whose only door a wardrobe closes is found unreachable,
// the loop lays a walkway through the door and the room's rule agent moves the wardrobe out of it; the
// bedroom is then reached, on a path that keeps the radius from the building and the furniture. A chair
// wedged behind a long table is dealt with by moving (or removing) the chair, not the table.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fixtures.h"
#include "reach_checks.h"
#include "solver/reach_feedback.h"

namespace villa::solver {
namespace {

using namespace fixtures;

// house_one_floor.json's bedroom (0, 5)-(5, 9): exterior walls on its west and north sides (0.25 m),
// interior ones east and south (0.06 m). The problem knows nothing of the door in its south wall, as a
// careless plan would not: no opening, no sweep.
RoomProblem Bedroom() {
  RoomProblem room = WithFloor({{0.25, 5.06}, {4.94, 5.06}, {4.94, 8.75}, {0.25, 8.75}});
  room.room = "bedroom_0/0";
  ProblemObject wardrobe = BoxObject("wardrobe-0", 2.0, 0.6, 2.0);
  wardrobe.relation = Relation::kAgainstWall;
  wardrobe.priority = Priority::kNamed;
  wardrobe.zone = InteractionZone{"front", 0.8, {}};
  room.objects.push_back(wardrobe);
  ProblemObject bed = BoxObject("bed-0", 1.6, 2.0, 0.5);
  bed.relation = Relation::kAgainstWall;
  bed.wall = 2;  // the north wall
  bed.zone = InteractionZone{"sides", 0.6, {}};
  room.objects.push_back(bed);
  return room;
}

TEST_CASE("the solver loop frees a room sealed by a wardrobe across its door", "[reach]") {
  const Built built = BuildFixture("house_one_floor.json");
  const RoomProblem problem = Bedroom();
  RoomSolver solver(problem, {});
  REQUIRE(solver.Initialise().ok());
  solver.RunAgent();
  // Across the door (1.5, 5)-(2.5, 5): against the south wall (wall 0), centred at x = 2.
  Action across;
  across.kind = ActionKind::kUpdatePose;
  across.id = "r/wardrobe-0";
  across.pose = Pose{2.0, 5.06 + 0.02 + 0.3, std::nan(""), 0.0, 1.0};
  across.wall = 0;
  const ActionResult placed = solver.Apply(across);
  INFO(placed.message);
  REQUIRE(placed.status == ActionStatus::kApplied);

  const std::map<std::string, RoomSolver*> solvers = {{"bedroom_0/0", &solver}};
  auto summary = FreeBlockedWays(built.input, solvers, {});
  REQUIRE(summary.ok());
  INFO(summary->BriefReport() << summary->last.BriefReport());
  // Before: the bedroom and both zones in it are cut off, and the wardrobe is named.
  const TargetResult* before = summary->first.Find("bedroom_0/0");
  REQUIRE(before);
  CHECK_FALSE(before->reachable);
  CHECK(before->blockers == std::vector<std::string>{"r/wardrobe-0"});
  // The loop moved the wardrobe (it is still there) and everything is reached.
  REQUIRE_FALSE(summary->rounds.empty());
  CHECK_FALSE(summary->rounds[0].walkways.empty());
  bool moved = false;
  for (const RoomAction& a : summary->rounds[0].actions) {
    moved |= a.result.action.id == "r/wardrobe-0" && a.result.action.kind == ActionKind::kUpdatePose &&
             a.result.status != ActionStatus::kRefused;
  }
  CHECK(moved);
  CHECK(summary->all_reachable);
  const RoomSolution after = solver.Solution();
  CHECK(after.summary.removed.empty());
  const TargetResult* bedroom = summary->last.Find("bedroom_0/0");
  REQUIRE(bedroom);
  CHECK(bedroom->reachable);
  REQUIRE(bedroom->path);
  CHECK(MeshClearance(*bedroom->path, built.building, ReachObjectsOf(after, "bedroom_0/0", 0)) >= 0.2 - 1e-9);
  CHECK(summary->last.Find("r/wardrobe-0")->reachable);
  CHECK(summary->last.Find("r/bed-0")->reachable);
  // The record says what was done, as JSON.
  const auto json = summary->ToJson();
  CHECK(json["all_reachable"] == true);
  CHECK(json["rounds"][0]["actions"].size() >= 1);
}

TEST_CASE("a chair wedged behind a long table is moved or taken out, never the table", "[reach]") {
  const Built built = BuildFixture("house_one_floor.json");
  RoomProblem problem = WithFloor({{0.25, 5.06}, {4.94, 5.06}, {4.94, 8.75}, {0.25, 8.75}});
  problem.room = "bedroom_0/0";
  problem.objects.push_back(BoxObject("table-0", 3.0, 0.9, 0.75));
  ProblemObject chair = BoxObject("chair-0", 0.4, 0.35, 0.9);
  chair.zone = InteractionZone{"front", 0.5, {"r/table-0"}};
  problem.objects.push_back(chair);
  RoomSolver solver(problem, {});
  REQUIRE(solver.Initialise().ok());
  solver.RunAgent();
  // The chair against the north wall (y = 8.75), the table 2 cm in front of it: the 0.35 m between the
  // table and the wall is too narrow for the person, and the table's ends are 1.5 m away.
  auto put = [&](const std::string& id, double x, double y, bool exactly) {
    Action a;
    a.kind = ActionKind::kUpdatePose;
    a.id = id;
    a.pose = Pose{x, y, std::nan(""), 0.0, 1.0};
    const ActionResult r = solver.Apply(a);
    INFO(id << ": " << r.message);
    if (exactly) REQUIRE(r.status == ActionStatus::kApplied);
  };
  put("r/chair-0", 0.6, 5.5, false);  // out of the way first
  put("r/table-0", 2.5, 8.75 - 0.02 - 0.35 - 0.02 - 0.45, true);
  put("r/chair-0", 2.5, 8.75 - 0.02 - 0.175, true);

  auto summary = FreeBlockedWays(built.input, {{"bedroom_0/0", &solver}}, {});
  REQUIRE(summary.ok());
  INFO(summary->BriefReport() << summary->first.BriefReport());
  const TargetResult* before = summary->first.Find("r/chair-0");
  REQUIRE(before);
  CHECK_FALSE(before->reachable);
  // The way in crosses the table, bigger than the chair: no walkway through it; the chair's own place
  // becomes the keep-out, and the chair's agent acts on the chair.
  REQUIRE_FALSE(summary->rounds.empty());
  REQUIRE(summary->rounds[0].walkways.size() == 1);
  CHECK(summary->rounds[0].walkways[0].kind == "spot");
  CHECK(summary->rounds[0].walkways[0].target == "r/chair-0");
  for (const FeedbackRound& round : summary->rounds) {
    for (const RoomAction& a : round.actions) CHECK(a.result.action.id != "r/table-0");
  }
  const RoomSolution after = solver.Solution();
  CHECK(std::find(after.summary.removed.begin(), after.summary.removed.end(), "r/table-0") == after.summary.removed.end());
  // Whatever became of the chair, nothing is left unreachable.
  CHECK(summary->all_reachable);
}

}  // namespace
}  // namespace villa::solver
