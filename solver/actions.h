#pragma once
// The paper's four actions on a room's arrangement (Sec. 3.4): add_entity, remove_entity, update_pose,
// update_scale, as plain structs with JSON. The rule agent and a multimodal critic drive the same
// interface (RoomSolver::Apply in solver/solve.h). An action that would leave a collision, an object off
// its support or out of the room is repaired (the object is moved to the nearest free pose, or to another
// free slot) or refused, and the result says which and why.
//
// JSON (angles in degrees, lengths in metres):
//   {"action": "update_pose", "id": "living-room_0/0/armchair-0", "pose": {"x": 1.2, "y": 3.4, "yaw": 90},
//    "reason": "..."}                       pose.z only for on_wall objects; optional "surface"/"cavity"/"wall"
//                                           (the wall is kept, not the nearest) and "scale" (resized too)
//   {"action": "update_scale", "id": "...", "scale": 0.9}
//   {"action": "remove_entity", "id": "..."}
//   {"action": "add_entity", "object": {"id", "category", "asset", "parent", "relation", "surface", "cavity",
//    "wall", "scale_range": [lo, hi], "priority", "interaction_zone": {"side", "depth", "exempt"}},
//    "edges": [{"source", "relation", "target", "params": {...}}], "pose": {...}}
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "solver/placement.h"
#include "solver/problem.h"
#include "util/result.h"

namespace villa::solver {

enum class ActionKind { kAddEntity, kRemoveEntity, kUpdatePose, kUpdateScale };
std::string_view ActionKindName(ActionKind kind);  // "add_entity", "remove_entity", "update_pose", "update_scale"

struct Action {
  ActionKind kind = ActionKind::kUpdatePose;
  std::string id;                       // the object acted on (add_entity: the new object's id)
  std::optional<Pose> pose;             // update_pose (required), add_entity (optional start); world frame
  std::optional<int> surface, cavity, wall;  // update_pose: a new support choice for the object
  std::optional<double> scale;          // update_scale (required); update_pose (optional: moved and resized at once)
  std::optional<ProblemObject> object;  // add_entity: the new object, its asset already resolved
  std::vector<SemanticEdge> edges;      // add_entity: the new object's semantic edges
  std::string reason;                   // why: the agent's rule or the critic's words
};

enum class ActionStatus { kApplied, kRepaired, kRefused };
std::string_view ActionStatusName(ActionStatus status);  // "applied", "repaired", "refused"

struct ActionResult {
  Action action;
  ActionStatus status = ActionStatus::kRefused;
  std::string message;               // what happened and why ("moved 0.12 m to clear sofa-0")
  std::optional<Pose> final_pose;    // where the object ended up
  // remove_entity: the object and its descendants; update_pose of a group's hub (issue 27): the optional
  // members that found no place by it where it went, left out
  std::vector<std::string> removed;
};

nlohmann::ordered_json ActionToJson(const Action& action);
nlohmann::ordered_json ActionResultToJson(const ActionResult& result);

// What add_entity needs from the asset library: the record and mesh of an asset id.
using AssetResolver =
    std::function<Result<std::pair<AssetRecord, std::shared_ptr<const AssetMesh>>>(const std::string& asset_id)>;

// Strict: unknown keys, wrong types and bad values are errors naming `where`, the JSON path and the value.
// add_entity resolves its asset through `resolve` (may be empty for the other actions).
Result<Action> ActionFromJson(const nlohmann::json& json, const std::string& where, const AssetResolver& resolve = {});

}  // namespace villa::solver
