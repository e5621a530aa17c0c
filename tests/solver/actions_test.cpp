// The four actions: JSON round trips and errors, and applied through RoomSolver::Apply: a pose into a
// collision is repaired, an impossible one refused, a scale outside the range refused, a removal takes the
// object's children along, a new object is placed in a free slot.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "fixtures.h"
#include "solver/solve.h"

namespace villa::solver {
namespace {

using namespace fixtures;

TEST_CASE("Actions round-trip through JSON", "[solver]") {
  Action move;
  move.kind = ActionKind::kUpdatePose;
  move.id = "r/armchair-0";
  move.pose = Pose{1.25, 2.5, std::nan(""), 1.5707963267948966, 1.0};
  move.reason = "face the coffee table";
  const auto json = ActionToJson(move);
  CHECK(json.dump() == R"({"action":"update_pose","id":"r/armchair-0","pose":{"x":1.25,"y":2.5,"yaw":90.0},"reason":"face the coffee table"})");
  auto back = ActionFromJson(nlohmann::json::parse(json.dump()), "critic");
  REQUIRE(back.ok());
  CHECK(ActionToJson(*back).dump() == json.dump());

  Action scale;
  scale.kind = ActionKind::kUpdateScale;
  scale.id = "r/plant-0";
  scale.scale = 0.85;
  CHECK(ActionToJson(scale).dump() == R"({"action":"update_scale","id":"r/plant-0","scale":0.85})");

  ProblemObject cup = SmallObject("cup-0", 0.1, 0.1, 0.12, "table-0", Relation::kOnTop);
  cup.scale_min = 0.9;
  Action add;
  add.kind = ActionKind::kAddEntity;
  add.id = cup.id;
  add.object = cup;
  add.edges = {DefaultEdge("r/cup-0", SemanticRelation::kNear, "r/sofa-0")};
  const auto add_json = ActionToJson(add);
  CHECK(add_json["object"]["asset"] == "test:cup");
  CHECK(add_json["edges"][0]["params"]["max_gap"] == 1.5);
  AssetResolver resolve = [&](const std::string& id) -> Result<std::pair<AssetRecord, std::shared_ptr<const AssetMesh>>> {
    if (id != "test:cup") return Error{"asset \"" + id + "\" is not in the library"};
    return std::make_pair(cup.asset, cup.mesh);
  };
  auto add_back = ActionFromJson(nlohmann::json::parse(add_json.dump()), "critic", resolve);
  REQUIRE(add_back.ok());
  CHECK(ActionToJson(*add_back).dump() == add_json.dump());
  CHECK(add_back->object->mesh == cup.mesh);
}

TEST_CASE("Action JSON errors name the place, the path and the value", "[solver]") {
  auto parse = [](const char* text) { return ActionFromJson(nlohmann::json::parse(text), "critic.json:3"); };
  CHECK(parse(R"({"action": "teleport", "id": "a"})").error() == "critic.json:3.action: unknown action \"teleport\"");
  CHECK(parse(R"({"action": "update_pose", "id": "a"})").error() == "critic.json:3.pose: missing (update_pose needs a pose)");
  CHECK(parse(R"({"action": "update_pose", "id": "a", "pose": {"x": 1, "y": "2"}})").error() ==
        "critic.json:3.pose.y: must be a number, is \"2\"");
  CHECK(parse(R"({"action": "remove_entity", "id": "a", "why": "x"})").error() == "critic.json:3: unknown key \"why\"");
  CHECK(parse(R"({"action": "update_scale", "id": "a", "scale": 40})").error().find("critic.json:3.scale: 40 is out of range") == 0);
  CHECK(parse(R"({"action": "add_entity", "object": {"id": "r/x", "category": "cup", "asset": "a:b", "parent": "floor", "relation": "ontop"}})")
            .error() == "critic.json:3.object.asset: no asset library to resolve \"a:b\"");
  CHECK(parse(R"({"action": "add_entity", "object": {"id": "r/x", "category": "cup", "asset": "a:b", "parent": "floor", "relation": "under"}})")
            .error() == "critic.json:3.object.relation: unknown relation \"under\"");
}

struct Session {
  RoomProblem room = Rectangle(5.0, 4.2);
  std::unique_ptr<RoomSolver> solver;
  Session() {
    FurnishLivingRoom(room);
    solver = std::make_unique<RoomSolver>(room, SolveOptions{});
    REQUIRE(solver->Initialise().ok());
    solver->RunAgent();
    REQUIRE(solver->Solution().summary.metrics.Clean());
  }
  Pose PoseOf(const std::string& id) const {
    const RoomSolution s = solver->Solution();
    for (size_t i = 0; i < s.objects.size(); ++i) {
      if (s.objects[i].id == id) return s.placements[i].pose;
    }
    FAIL("no " << id);
    return {};
  }
};

TEST_CASE("update_pose into a collision is repaired, an unknown object refused", "[solver]") {
  Session s;
  const Pose sofa = s.PoseOf("r/sofa-0");
  Action onto;
  onto.kind = ActionKind::kUpdatePose;
  onto.id = "r/armchair-0";
  onto.pose = Pose{sofa.x, sofa.y, std::nan(""), 0.0, 1.0};
  const ActionResult r = s.solver->Apply(onto);
  INFO(r.message);
  CHECK(r.status == ActionStatus::kRepaired);
  REQUIRE(r.final_pose);
  CHECK(s.solver->Solution().summary.metrics.Clean());

  Action away;
  away.kind = ActionKind::kUpdatePose;
  away.id = "r/nothing-0";
  away.pose = Pose{};
  const ActionResult missing = s.solver->Apply(away);
  CHECK(missing.status == ActionStatus::kRefused);
  CHECK(missing.message == "no object \"r/nothing-0\" in the room");
}

TEST_CASE("update_pose keeps the wall it names, not the nearest, and may resize at once", "[solver]") {
  // A bed with its head to the east wall of a 6.5 x 3 m room, pushed towards the south wall: its centre
  // (1.0 m from the east wall) is nearer the south wall (0.6 m). The wall asked for holds: it stays with
  // its head east, not turned against the south wall. Then it moves and shrinks in one action.
  RoomProblem room = Rectangle(6.5, 3.0);
  ProblemObject bed = BoxObject("bed-0", 0.9, 2.0, 0.5);
  bed.relation = Relation::kAgainstWall;
  bed.scale_min = 0.8;
  room.objects.push_back(bed);
  RoomSolver solver(room, {});
  REQUIRE(solver.Initialise().ok());
  solver.RunAgent();
  int east = -1;
  for (size_t w = 0; w < room.walls.size(); ++w)
    if (std::abs(room.walls[w].a.x - 6.5) < 1e-6 && std::abs(room.walls[w].b.x - 6.5) < 1e-6) east = static_cast<int>(w);
  REQUIRE(east >= 0);
  Action a;
  a.kind = ActionKind::kUpdatePose;
  a.id = "r/bed-0";
  a.pose = Pose{5.48, 0.6, std::nan(""), -std::numbers::pi / 2.0, 1.0};
  a.wall = east;
  const ActionResult r = solver.Apply(a);
  INFO(r.message);
  REQUIRE(r.status == ActionStatus::kApplied);
  RoomSolution s = solver.Solution();
  REQUIRE(s.objects.size() == 1);
  CHECK(s.placements[0].wall == east);
  CHECK(std::abs(WrapAngle(s.placements[0].pose.yaw + std::numbers::pi / 2.0)) < 1e-6);  // its front west
  CHECK(s.placements[0].pose.x == Approx(6.5 - 1.0 - room.objects[0].wall_gap).margin(1e-6));
  CHECK(s.placements[0].pose.y == Approx(0.6).margin(1e-6));
  a.pose = Pose{5.48, 2.0, std::nan(""), -std::numbers::pi / 2.0, 1.0};
  a.scale = 0.8;
  REQUIRE(solver.Apply(a).status == ActionStatus::kApplied);
  s = solver.Solution();
  CHECK(s.placements[0].pose.scale == Approx(0.8));
  CHECK(s.placements[0].pose.x == Approx(6.5 - 0.8 - room.objects[0].wall_gap).margin(1e-6));
  CHECK(s.summary.metrics.Clean());
  a.scale = 0.5;  // below its range
  CHECK(solver.Apply(a).status == ActionStatus::kRefused);
}

TEST_CASE("update_scale outside the range is refused, inside it applied", "[solver]") {
  Session s;
  Action grow;
  grow.kind = ActionKind::kUpdateScale;
  grow.id = "r/plant-0";
  grow.scale = 1.5;
  const ActionResult refused = s.solver->Apply(grow);
  CHECK(refused.status == ActionStatus::kRefused);
  CHECK(refused.message == "scale 1.500 is outside the object's range [1.000, 1.000]");
  // The bowl may shrink to 0.8: it does, and stays on the coffee table.
  Action shrink;
  shrink.kind = ActionKind::kUpdateScale;
  shrink.id = "r/bowl-0";
  shrink.scale = 0.85;
  const ActionResult applied = s.solver->Apply(shrink);
  INFO(applied.message);
  CHECK(applied.status == ActionStatus::kApplied);
  CHECK(s.PoseOf("r/bowl-0").scale == 0.85);
  CHECK(s.solver->Solution().summary.metrics.Clean());
}

TEST_CASE("remove_entity takes the children along and add_entity finds a free slot", "[solver]") {
  Session s;
  Action remove;
  remove.kind = ActionKind::kRemoveEntity;
  remove.id = "r/tv-stand-0";
  const ActionResult r = s.solver->Apply(remove);
  CHECK(r.status == ActionStatus::kApplied);
  CHECK(r.removed == std::vector<std::string>{"r/tv-stand-0", "r/tv-0"});
  const size_t before = s.solver->Solution().objects.size();

  Action add;
  add.kind = ActionKind::kAddEntity;
  ProblemObject cup = SmallObject("cup-0", 0.09, 0.09, 0.11, "coffee-table-0", Relation::kOnTop);
  add.id = cup.id;
  add.object = cup;
  const ActionResult added = s.solver->Apply(add);
  INFO(added.message);
  CHECK(added.status != ActionStatus::kRefused);
  const RoomSolution after = s.solver->Solution();
  CHECK(after.objects.size() == before + 1);
  CHECK(after.summary.metrics.Clean());

  Action clash = add;  // the same id again
  CHECK(s.solver->Apply(clash).message == "room r: objects: id \"r/cup-0\" appears twice");
}

}  // namespace
}  // namespace villa::solver
