#pragma once
// The pose solver of a room (paper Sec. 3.4): discrete choices and a constructive start outside Ceres,
// a Ceres polish per layer, the exact check (FCL) after every solve, and a rule agent that applies the
// paper's four actions until the energy is below its threshold or the budget is spent.
//
//   Result<RoomSolution> s = SolveRoom(problem, options);
//   std::cout << s->summary.BriefReport();
//
// Layers, in order: the floor (objects on the floor or against a wall), the walls and the ceiling (hung
// objects, the floor fixed), then every support surface and cavity in its parent's frame. Deterministic for
// a seed: the same problem and options give the same poses, bit for bit, on one build.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "solver/actions.h"
#include "solver/energy.h"
#include "solver/exact_check.h"
#include "solver/options.h"
#include "solver/placement.h"
#include "solver/problem.h"
#include "util/result.h"

namespace villa::solver {

// SCENE.md "Failure outcomes": converged (E <= threshold, E_col = E_sup = 0, the exact check clean),
// budget (iterations spent, or no action lowers E further while the hard constraints hold), infeasible
// (the hard constraints could not be met with the actions the agent may take).
enum class Outcome { kConverged, kBudget, kInfeasible };
std::string_view OutcomeName(Outcome outcome);  // "converged", "budget", "infeasible"

struct SolveSummary {
  Outcome outcome = Outcome::kInfeasible;
  std::string reason;                 // one line: why the room ended so
  int iterations = 0;                 // rule-agent iterations run
  EnergyTerms energy;                 // of the kept (best) state
  ExactMetrics metrics;               // of the kept state: CR, FR, OBR, CSR, NO
  std::vector<std::string> removed;   // ids removed by actions
  std::vector<ActionResult> actions;  // every action tried, in order
  std::vector<double> energy_trace;   // E after the first solve and after each agent iteration
  // One line per check: E, the exact violations and who was involved ("check 2: E 0.31, collisions
  // r/a x r/b; floating r/cup-0"), so a room that ends badly says what stood in the way.
  std::vector<std::string> log;

  int ceres_solves = 0;
  int ceres_iterations = 0;
  bool sparse = false;                // the largest solve used sparse normal Cholesky
  int candidates = 0;                 // candidate poses scored by the constructive search
  double seconds = 0.0;               // wall time of the whole solve
  double seconds_place = 0.0;         // constructive placement
  double seconds_ceres = 0.0;         // Ceres polishes
  double seconds_exact = 0.0;         // exact checks

  std::string BriefReport() const;    // a few lines for people
  // SCENE.md rooms[r].solve: {"outcome", "iterations", "energy", "removed", "actions"}.
  nlohmann::ordered_json SolveRecord() const;
};

struct RoomSolution {
  std::vector<ProblemObject> objects;       // the room's objects at the end (actions add and remove)
  std::vector<ObjectPlacement> placements;  // parallel to objects
  std::vector<SemanticEdge> edges;          // the edges among them (removals drop edges, add_entity adds some)
  SolveSummary summary;
};

// Solves a room. An invalid problem or options is an error (the message names the field); a room that
// cannot reach the targets is an outcome in the summary, with its best state.
Result<RoomSolution> SolveRoom(const RoomProblem& problem, const SolveOptions& options,
                               const ExactCheckOptions& check = {});

// The same solver as a session a critic can drive: Initialise() places everything, Apply() takes one
// action through the path the rule agent uses (repaired or refused when it would break a hard
// constraint), RunAgent() lets the rule agent finish (and may be called again after more actions),
// Finish() ends on the best state without the agent. The solver keeps its own copy of the problem;
// AddKeepOuts() extends it (the reachability feedback's walkways, solver/reach_feedback.h).
class RoomSolver {
 public:
  RoomSolver(const RoomProblem& problem, const SolveOptions& options, const ExactCheckOptions& check = {});
  ~RoomSolver();
  RoomSolver(const RoomSolver&) = delete;
  RoomSolver& operator=(const RoomSolver&) = delete;

  // Checks the problem and options; then places every layer and runs the first exact check.
  Status Initialise();
  ActionResult Apply(const Action& action);
  // Issue 28: object `id`, standing on its parent, where a physics engine finds it starting `depth` m inside
  // its parent's collision hull (the hull of an imported model's non-convex piece stands a few mm above or
  // beside the surface read off the mesh), moved out by depth + 0.5 mm along `out` (the contact's normal,
  // world frame): raised onto the hull when `out` is within 45 degrees of vertical (Lift), else slid along
  // its surface (an update_pose). Kept as the session's state when the exact check stays clean. False when
  // refused (no such object, not on a parent, more than kMaxOutOfHull, or a hard constraint broken).
  bool MoveOutOfParent(const std::string& id, Vec3 out, double depth);
  // The vertical case: raised `dz` m with what stands on it.
  bool Lift(const std::string& id, double dz);
  static constexpr double kMaxOutOfHull = 0.008;
  // Whether object `id` could take `pose` as update_pose would put it there (z from its support, a wall
  // object onto `wall` or the nearest wall, facing the room) without breaking a hard constraint, with
  // everything else where it is. Changes nothing; a critic asks before it acts.
  bool Fits(const std::string& id, const Pose& pose, std::optional<int> wall = std::nullopt);
  // Where the solver's own search would put object `id` now, everything else where it is: the best free
  // pose in its layer by the soft terms (relations, zones), polished, with the wall, surface or cavity it
  // chose; nothing when no pose is free of hard violations. Changes nothing (the rule agent's move).
  std::optional<ObjectPlacement> Suggest(const std::string& id);
  void RunAgent();
  // A critic that judges the semantics itself (a multimodal model) accepts the arrangement as it stands:
  // it becomes the state the session keeps (RunAgent ends on the best state seen, and without this a
  // lower geometric proxy E of an earlier state would undo the critic's moves). Later states replace it
  // as before: by fewer exact violations, then lower E.
  void KeepCurrent();
  // A copy of the arrangement as it stands (its objects, poses, check and energy), and going back to one
  // (it becomes the state kept, as KeepCurrent; the actions taken since stay in the log): a critic that
  // finds a later round worse returns to an earlier round's room. Restore ignores a snapshot of another
  // session's room.
  struct Snapshot;
  std::shared_ptr<const Snapshot> Save() const;
  void Restore(const Snapshot& snapshot);
  // Issue 27, after the agent and the critic: every dining or meeting chair that cannot be pulled out from
  // its table (0.75 m behind it) gets room: what stands behind it goes (nothing protected), else with
  // `moves` it takes a free seat where it can, else it is left out unless protected; every other member out
  // of its group's rules (a TV stand off the sofa's axis) takes its best free place by its hub where it
  // holds (with `moves`; the sofa with its group for its TV stand), else it is left out unless protected;
  // with `moves`, what stands tall between a sofa and its TV goes out of the view. The room ends on the
  // result while it stays clean. True when anything changed.
  bool TidyGroups(bool moves);
  // Issue 27, after the tidy stage: the plan's pieces removed while the room was settling (a wardrobe and
  // its clothes that had no free slot while the bed was fitted) put back where they fit now: parents before
  // their children, at the best free slot (full size, else the smallest), kept only where the exact check stays clean, no walkway is entered,
  // every group keeps its rules and E_sem rises by at most 0.25; a desk with its chair or not at all, never a
  // pillow. The room ends on the result. True when anything came back.
  bool Refill();
  // Ends the session without more agent actions: the best state seen is kept, checked again (with the
  // clearance figure) and the outcome and its reason set, as at the end of RunAgent.
  void Finish();
  // Adds zones no object may enter (checked like the problem's own), checks the arrangement against them
  // and lets the agent's remedies (move, shrink, remove) apply anew to what stands in them; call RunAgent()
  // next. An error (nothing changed) when a zone is malformed or the solver is not initialised.
  Status AddKeepOuts(const std::vector<KeepOut>& zones);
  const RoomProblem& Problem() const;
  RoomSolution Solution() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace villa::solver
