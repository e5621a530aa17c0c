#pragma once
// The offline critic: geometry instead of a model. It evaluates the graph's semantic edges and
// interaction zones exactly (critic/relations.h) and proposes the solver's actions to mend what fails:
//   update_pose  for an unmet edge, either end moves to a pose where the edge holds: around the other
//                object at the relation's distances on each of its sides, turned like it, facing it or as
//                it stands; along a wall for wall-bound objects (slid opposite the target for face_to and
//                centred, beside it for next_to); turned in place for face_to and align; candidates that
//                would come closer than `clearance` to another object or leave the free floor are not tried;
//                the rest are ranked by the unmet edges and zones they would leave, then by how far from
//                holding those are;
//   update_scale the same poses at the object's smallest scale when none fits at its own;
//   remove_entity a decorative object that stands in an interaction zone and has no free pose elsewhere.
// Each proposal is an Attempt: alternatives tried in order through RoomSolver::Apply; the loop keeps the
// first that leaves fewer unmet relations (or as many with a lower E) with the exact check clean and
// undoes the others. Deterministic: candidates are generated and ranked in a fixed order.
#include <set>
#include <string>
#include <vector>

#include "critic/relations.h"
#include "solver/actions.h"
#include "solver/problem.h"
#include "solver/solve.h"

namespace villa::critic {

// One step of an alternative: an action, or "move action.id where the solver would put it now"
// (RoomSolver::Suggest, asked when the step comes: after the steps before it have moved things).
struct Step {
  solver::Action action;
  bool suggest = false;
};

struct Attempt {
  std::string problem;  // what it mends, for the log (and the key of `given_up`)
  // Tried in order, the first kept that helps; each a short sequence (update_scale then update_pose; or a
  // group move: the hub, then each object related to it where the solver would now put it).
  std::vector<std::vector<Step>> alternatives;
};

// How far an arrangement is from its graph: the edges that do not hold (an edge whose object was removed
// counts: removing an object never mends its edges) plus the zones entered, and in sum how far from
// holding they are (edges: CheckEdge's violation; a lost edge 1; a zone 0.5 per object standing in it).
struct Unmet {
  // Functional group problems (solver/functional.h: a chair off its table, a sofa turned from the TV, a
  // missing essential) come first: a move that tears a group apart never counts as a fix (issue 27).
  int groups = 0;
  int count = 0;
  double amount = 0.0;
  bool operator<(const Unmet& o) const {
    if (groups != o.groups) return groups < o.groups;
    return count != o.count ? count < o.count : amount < o.amount - 1e-6;
  }
};
Unmet UnmetOf(const RoomRelations& relations);

// The offline score: 10 x the share of the graph's edges and zones that hold (10 when there are none).
double OfflineScore(const RoomRelations& relations);
// One line per unmet edge or entered zone ("tv-stand-0 face_to sofa-0: facing off by 42.0 deg, at most 30").
std::vector<std::string> OfflineProblems(const std::string& room, const RoomRelations& relations);

struct OfflineProposalOptions {
  double clearance = 0.025;  // m kept from other objects' boxes by a candidate before it is tried
  int alternatives = 4;      // candidate poses tried per unmet edge or zone, best first
};

// The attempts of one round. `given_up` holds the problems (OfflineProblems' lines, and the same with
// " [group]") whose attempts all failed in an earlier round. A problem whose single moves failed is tried
// once more as a group move: the hub of the edge (its end with the most relations) to a few roomier
// places, then every object related to it re-placed by the solver around it; or those objects alone.
// Every alternative is one the solver says fits (RoomSolver::Fits), so it is applied, not repaired.
std::vector<Attempt> ProposeOffline(solver::RoomSolver& session, const solver::RoomProblem& problem, const solver::RoomSolution& solution,
                                    const std::vector<scene::SemanticEdge>& graph, const RoomRelations& relations,
                                    const OfflineProposalOptions& options, const std::set<std::string>& given_up);

}  // namespace villa::critic
