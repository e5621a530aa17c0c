#pragma once
// Constructive placement (internal to villa_solver): the discrete choices Ceres cannot make. Each body is
// put at the best of a set of candidate poses, scored with the layer's own cost terms against the bodies
// already placed: anchors slide along free wall intervals, related objects go where their relations say
// (around their target, at the relation's gap, facing it), free objects on a grid or by a wall, hung
// objects along the walls at eye level or above their target, small objects in rows on their surface or
// in their cavity. Ceres then polishes what this finds.
#include <functional>
#include <vector>

#include "solver/layer.h"
#include "solver/rng.h"

namespace villa::solver {

struct PlaceStats {
  int candidates = 0;  // candidate poses scored
  int infeasible = 0;  // bodies whose best candidate still breaks a hard term
};

// Puts body `b` at its best candidate given the active bodies and marks it active. `jitter` (>= 0) adds
// rng noise of that size to the soft preferences (restarts explore; 0 keeps the first start's order).
// Returns the hard cost at the chosen pose (0: no proxy violation).
double PlaceBody(Layer& layer, int b, const RoomState& state, const SolveOptions& options, Rng& rng, double jitter,
                 PlaceStats* stats);
// Puts body `b` (marked active) at each of its best `keep` candidates in turn, best first (ranked once,
// as PlaceBody with no jitter), until `accept` (called with the body at the candidate: it may polish it)
// says yes; false when none was accepted. For a slot search that moves on to the next candidate when the
// polish of one does not end clean.
bool PlaceBodyAmong(Layer& layer, int b, const RoomState& state, const SolveOptions& options, Rng& rng, size_t keep,
                    PlaceStats* stats, const std::function<bool()>& accept);

// Places every movable body of the layer in PlacementOrder. A body that others relate to (a hub: the
// bed, the sofa, the table) is tried at its few best poses with its dependents placed around each, and the
// group that holds best is kept.
void PlaceLayer(Layer& layer, const RoomState& state, const SolveOptions& options, Rng& rng, double jitter,
                PlaceStats* stats);

// The order a layer's movable bodies are placed in: a relation's target before its source, then objects
// against a wall, higher priority and bigger footprints first; floor coverings last.
std::vector<int> PlacementOrder(const Layer& layer, const RoomState& state);

// Issue 27: functional groups. A member of a group stands where its group's template puts it relative to
// its hub as the hub stands: a chair at a side of its dining, meeting or play table (evenly spaced along the
// long sides, one at each end of a long table, facing it, 0.75 m clear behind it), a desk's chair before it,
// a nightstand at the head of its bed on the bed's wall, the coffee table centred before the sofa, side
// tables at the sofa's ends, armchairs at the coffee table's ends facing it, the TV stand on a wall the sofa
// faces within 20 degrees at 1.8-3.5 m. The constructive start, the agent's moves (FindSlot) and every
// repair draw a member's candidates from its template only, so a member is never carried away from its
// group; where no template pose is free it is shrunk, and an optional member then removed.
enum class GroupRole { kNone, kTableSeat, kDeskSeat, kBedside, kCoffeeTable, kSideTable, kArmchair, kTvStand };
struct Membership {
  GroupRole role = GroupRole::kNone;
  int hub = -1;   // object index of the hub
  int side = 0;   // nightstands and side tables: +1 the hub's left (+x, its left_of edge), -1 its right, 0 either
};
// The group role of an object standing on the floor, read from its category and its edges to the hub.
Membership GroupMembership(const RoomState& state, int object);
// Whether `chair` is `desk`'s own chair, pulled in: a front_of edge to the desk whose gap (the next_to edge
// scene_problem.cpp derives from it) is at most 0.5 m; a visitor's chair 0.5-1.5 m before the desk is not.
bool IsDeskSeat(const std::vector<SemanticEdge>& edges, const std::string& chair, const std::string& desk);

// Children without a chosen surface or cavity get one: the surface or cavity with the most room left
// that is tall enough (asset height x scale_min within its clear height), in a deterministic order.
void AssignSupports(RoomState& state);

}  // namespace villa::solver
