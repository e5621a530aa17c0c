#pragma once
// The bridge between the furnishing stage's scene model (scene/) and the pose solver's plain problem:
// a room's context + its planned objects (assets chosen) + the built building -> RoomProblem, and the
// solved arrangement -> the scene's objects with poses.
//
//   context.free_floor (largest ring)  -> free_floor        context.walls -> walls (doors and opens as
//   context.keep_outs (kinds 1:1)      -> keep_outs         full-height openings, windows sill to head)
//   building parts of the room's level near it: wall pieces, door leaves, window panes, the staircase
//   rising from the level and the one arriving from below     -> building (obstacles of the exact check)
//   objects: asset record + mesh, parent/relation, surface/cavity/wall when named, scale [0.8, 1],
//   priority from the origin (prompt: named; small objects of the priors: decorative), zone
//   semantic edges: parameters carried over; a side relation with a gap range (coffee table front_of sofa
//   0.45-0.6 m) also becomes a gap edge, since the solver reads sides without distance.
// Frames: both sides use the world frame of SCENE.md (plan metres, z up); yaw in radians.
#include <string>
#include <vector>

#include "building/building.h"
#include "scene/room_context.h"
#include "scene/scene.h"
#include "solver/actions.h"
#include "solver/problem.h"
#include "solver/solve.h"
#include "util/result.h"

namespace villa::solver {

// Scale range given to every object (SCENE.md allows [0.8, 1.25]; growing never helps a fit).
inline constexpr double kSceneScaleMin = 0.8;
inline constexpr double kSceneScaleMax = 1.0;

struct SceneRoomProblem {
  RoomProblem problem;
  // Objects left out before solving, with why ("…/books-3: its parent has no cavity"): the rest of the
  // room is still solved.
  std::vector<std::string> dropped;
  std::vector<std::string> notes;  // approximations ("the free floor has 2 pieces; the largest is furnished")
};

// The problem of one room. `objects` are the room's (assets chosen, no poses needed); `resolve` gives each
// asset's record and mesh. Errors only for an asset that cannot be resolved.
Result<SceneRoomProblem> RoomProblemOf(const scene::RoomContext& context, const BuildingMesh& building,
                                       const std::vector<scene::SceneObject>& objects,
                                       const std::vector<scene::SemanticEdge>& edges, const AssetResolver& resolve);

// Issue 27: the room type's essential pieces (solver/functional.h EssentialsOf: the first of each needed
// category, as many as it needs) and what carries them get Priority::kEssential, so that the agent, the
// critic and the reachability feedback make room for them rather than remove them; a living room's coffee
// table, TV stand and TV (the rest of its seating group) are protected as named ones.
void MarkEssentials(Category room, RoomProblem& problem);
// Issue 27: a dining or meeting table's chair (a next_to or face_to edge to it) keeps kSeatBehind free
// behind it to be pulled out (ProblemObject::pull_out).
void MarkPullOut(RoomProblem& problem);

// The scene's objects after solving: every object of `solution` posed (pose, uniform scale, size = asset
// size x scale, wall edge and gap, surface or cavity), in the planned order; objects the solver removed
// are left out, and so are their ids in other objects' zone exemptions. `planned` supplies what the
// solver does not keep (origin, hints, affordances, room, level).
std::vector<scene::SceneObject> SolvedSceneObjects(const RoomProblem& problem, const RoomSolution& solution,
                                                   const std::vector<scene::SceneObject>& planned);

}  // namespace villa::solver
