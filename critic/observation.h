#pragma once
// What a critic sees of a room in one round: pictures (solver/room_view.h: a top view and four corner
// views, walls on the camera's side cut low, object ids as labels) and a compact text state: the room's
// walls and openings, every object (id, category, physical edge, pose, size, scale), every semantic edge
// and interaction zone measured exactly with its state, the energy terms, the exact check's failures
// (which pair collides, which object floats), and what became of the last round's actions. Ids are
// written without the room's prefix ("sofa-0" for "living-room_0/0/sofa-0"); critics may answer either way.
#include <string>
#include <vector>

#include "critic/relations.h"
#include "solver/furnish.h"
#include "solver/room_view.h"
#include "solver/solve.h"
#include "util/result.h"

namespace villa::critic {

// "sofa-0" for "<room>/sofa-0"; other ids unchanged.
std::string ShortId(const std::string& room, const std::string& id);
// The object id a critic meant: "<room>/sofa-0" for "sofa-0" or for the full id itself.
std::string FullId(const std::string& room, const std::string& id);

struct Observation {
  solver::RoomSolution solution;          // the arrangement as it stands
  RoomRelations relations;                // the graph's edges and the zones, measured
  std::string state;                      // the text state
  std::vector<solver::RoomViewImage> views;  // empty when not rendered
};

// The text state of a room (see above). `last` are the actions of the previous round with their results.
std::string RoomStateText(const solver::RoomCriticInput& input, const solver::RoomSolution& solution,
                          const RoomRelations& relations, const std::vector<solver::ActionResult>& last);

// The room's pictures for a critic (labels as `options` says).
Result<std::vector<solver::RoomViewImage>> RoomViews(const solver::RoomCriticInput& input, const solver::RoomSolution& solution,
                                                     const solver::RoomViewOptions& options);

}  // namespace villa::critic
