#pragma once
// Reachability fed back to the pose solver (issue 13): what a person cannot reach becomes an energy term
// and actions in the rooms' solver loops. Round by round: check the building (solver/reach.h); for every
// unreachable room or zone whose cheapest way in crosses objects, keep that way free in the rooms holding
// them (a walkway keep-out, the person's width plus a margin along the way, floor to head height: every
// object standing in it adds its overlap to E_col, so the room is no longer converged) and let each such
// room's rule agent act on it through the paper's actions (update_pose to a free slot that keeps out of the
// walkway, update_scale, remove_entity), re-solve and re-check. The summary records every round: what
// was unreachable, which walkways were laid, and every action taken.
// Zones are cheaper to give up than what stands around them: a zone whose way in crosses an object with a
// bigger footprint than the zone's owner (a chair wedged behind its table), or an open door leaf, gets no
// walkway; the owner's own place becomes a keep-out instead (a "spot"), so the owner is moved to a free
// slot or, failing that, removed. Zones of a room that cannot be entered wait until it can.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "solver/reach.h"
#include "solver/solve.h"
#include "util/result.h"

namespace villa::solver {

struct ReachFeedbackOptions {
  ReachOptions reach;
  int rounds = 3;                // check, lay walkways, let the agents act; then a last check. [0, 20]
  double walkway_margin = 0.05;  // m beyond the radius on each side of a walkway, [0, 0.5]
  // The last resort, once the rounds are spent: the owner of a zone still unreachable in a room a person
  // enters moves to the nearest free slot whose zone a reached cell touches; failing that (and for what
  // still blocks a room) it is removed, unless only a door leaf is in the way (the building's to mend).
  bool last_resort = true;
  // Then the owners of zones reached only at their edge (a share below thin_share; 0: never) move to the
  // nearest free slot within widen_move m where a person covers far more of the zone (at least thin_share
  // and 0.3 more) and no more of the owner's relations are violated (the solver's semantic proxy); a room
  // whose zones end up less reached, or that cuts a way, goes back.
  double thin_share = 0.5;       // [0, 1]
  double widen_move = 3.0;       // m, [0, 20]
  double slot_step = 0.1;        // m between the slots tried (along walls, over the floor), [0.02, 1]
  int slot_tries = 1000;         // slots checked against the room's hard constraints per object, [1, 100000]
  bool IsValid(std::string* message) const;
};

// A keep-out the loop laid in a room. A "walkway" keeps the way to an unreachable room or zone free
// through the objects that block it; a "spot" is the place of a V_int object whose zone cannot be reached
// without clearing something bigger than it (or past a door leaf), so that the object itself moves.
struct Walkway {
  std::string room;    // the room whose solver keeps it free
  std::string target;  // the room or zone it leads to
  int pieces = 0;      // keep-out rectangles laid
  std::string kind = "walkway";  // "walkway" or "spot"
};

struct RoomAction {
  std::string room;
  ActionResult result;
};

struct FeedbackRound {
  // "walkways" (the rounds), "move" (the last resort's moves to slots with a reachable zone, and the
  // removals of what blocks a room), "remove" (owners of zones still unreachable after the moves), "widen"
  // (owners of thinly reached zones moved where more of the zone is reached; `unreachable` lists them).
  std::string stage = "walkways";
  std::vector<std::string> unreachable;  // targets unreachable when the round began
  std::vector<Walkway> walkways;
  std::vector<RoomAction> actions;       // what the rooms' agents did
};

struct FeedbackSummary {
  bool all_reachable = false;
  std::string reason;               // one line: how it ended
  std::vector<FeedbackRound> rounds;
  ReachReport first;                // before any action
  int moved = 0;                    // the last resort: owners moved to a slot with a reachable zone
  int removed = 0;                  // the last resort: objects removed (with what stood on them)
  int widened = 0;                  // owners moved where their thinly reached zone is reached more widely
  ReachReport last;                 // after the last round
  double seconds = 0.0;

  std::string BriefReport() const;
  // {"all_reachable", "reason", "rch_before", "acc_before", "rooms_reachable_before",
  // "zones_reachable_before", "last_resort": {"moved", "removed", "widened"}, "rounds": [{"stage", "unreachable",
  // "walkways", "actions": [{"room", ...action result}]}]}
  nlohmann::ordered_json ToJson() const;
};

// The objects of a solved room as reachability sees them: boxes where they stand (scaled), floor
// coverings marked, each V_int object's zone (its own or its asset's) with whether objects allowed in it
// stand there.
std::vector<ReachObject> ReachObjectsOf(const RoomSolution& solution, const std::string& room, int level);
// The zone an object keeps free: its own, else its asset's when it is an interactor; none when hung.
std::optional<InteractionZone> ZoneOf(const ProblemObject& object);

// Runs the loop on a building: `building` is BuildingReachInput's (no objects yet); `solvers` the rooms'
// initialised solvers by room name (rooms without one hold no objects and are never changed). The
// solvers keep the walkways and their states change; an error only for bad options.
Result<FeedbackSummary> FreeBlockedWays(const ReachInput& building, const std::map<std::string, RoomSolver*>& solvers,
                                        const ReachFeedbackOptions& options);

}  // namespace villa::solver
