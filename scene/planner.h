#pragma once
// The graph planner: a room's context + an optional request text + a seed -> the room's A-PSSG (paper
// Sec. 3.2): objects with affordance roles, one physical edge each (parent + relation), interaction zones
// and semantic edges, no poses yet.
//
// GraphPlanner is the extension point: PriorsPlanner (built in, offline, the default) reads the request's
// wishes and fills the room from the priors of PRIORS.md; an MLLM planner (issue 14) implements the same
// interface. Deterministic for a seed: the same inputs give the same graph on every machine (SplitMix64,
// no std distributions).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "scene/room_context.h"
#include "scene/scene.h"
#include "util/result.h"

namespace villa::scene {

struct PlanRequest {
  const RoomContext* room = nullptr;  // required
  std::string text;                   // the request ("" = priors only); may speak of other rooms too
  uint64_t seed = 0;
  // The layout the room belongs to, when the caller has it: a planner that revises graphs (an MLLM)
  // checks them with the structural validator, which needs it. May be null.
  const Layout* layout = nullptr;
};

struct PlannerOptions {
  // Share of the furnishable floor (free floor outside staircases) that floor objects' footprints may
  // cover, from the category's usual size; Holodeck's 40 %. Range (0, 1].
  double floor_share = 0.4;
  // The same for objects the request names: they come first and may use more of the floor before the
  // planner refuses them. Range [floor_share, 1].
  double prompt_floor_share = 0.6;
  // At most this many small objects of one category on one parent, or in one compartment of it (ProcTHOR's
  // MAX_OF_TYPE_ON_RECEPTACLE). Place settings (one per chair) are exempt. Range [1, 10].
  int max_per_receptacle = 3;
  // Object counts aimed at in the five rich room types (living, dining, bed, kitchen, children's room) of
  // at least `rich_min_area` m2: the paper's 22-30 placed, planned 3 higher (issue 27: the agent and the
  // reachability feedback leave out about 3 a room, with what stands on them); the furniture is then dressed
  // with small things up to `rich_max_objects`. Other rooms aim at PRIORS.md's NO target scaled by size.
  int rich_min_objects = 25;
  int rich_max_objects = 33;
  double rich_min_area = 12.0;  // m2 of room polygon
  // Whether the rich rooms' furniture is dressed with small things up to `rich_max_objects` once the drawn
  // target is met (tests of fixed arrangements turn it off).
  bool dress = true;

  // Empty when usable, else what is wrong ("floor_share = 0: must be in (0, 1]").
  std::string Check() const;
};

enum class PlanOutcome {
  kPlanned,   // the graph reaches the target count
  kPartial,   // something asked for or needed did not fit (see notes), or the count stayed below target
  kEmpty,     // nothing fits (a staircase room without free floor), or no priors and no request
};
std::string_view PlanOutcomeName(PlanOutcome outcome);  // "planned", "partial", "empty"

struct PlanSummary {
  PlanOutcome outcome = PlanOutcome::kPlanned;
  int objects = 0;
  int from_prompt = 0;
  int target_min = 0;      // the count range aimed at
  int target_max = 0;
  int dropped = 0;         // objects asked for or drawn that did not fit
  double floor_used = 0.0; // share of the furnishable floor under floor objects' usual footprints
  double seconds = 0.0;
};

struct RoomPlan {
  std::vector<SceneObject> objects;     // ids "<room>/<category>-<k>", asset "" (chosen later), no pose
  std::vector<SemanticEdge> edges;
  PlanRecord record;                    // planner name, seed, text, notes
  PlanSummary summary;
};

class GraphPlanner {
 public:
  virtual ~GraphPlanner() = default;
  virtual std::string_view name() const = 0;
  // Errors are for unusable input (no room given); a room that cannot be furnished is an outcome.
  virtual Result<RoomPlan> Plan(const PlanRequest& request) const = 0;
};

class PriorsPlanner : public GraphPlanner {
 public:
  explicit PriorsPlanner(PlannerOptions options = {}) : options_(options) {}
  std::string_view name() const override { return "priors"; }
  Result<RoomPlan> Plan(const PlanRequest& request) const override;

 private:
  PlannerOptions options_;
};

}  // namespace villa::scene

namespace villa::scene {

// The scene file of a plan (docs/SCENE.md "Plans"): the planned room's graph and objects (no poses, asset
// ""), the layout it was planned on by path and SHA-256, the wall thicknesses of the context.
SceneFile PlanSceneFile(const FileRef& layout, const BuildOptions& build, const std::string& room, const RoomPlan& plan);

// The plan as a text table: id (without the room prefix), category, parent / relation, affordances, zone,
// origin; then the semantic edges, one a line, and the notes.
std::string PlanTable(const RoomPlan& plan, const std::string& room);

}  // namespace villa::scene
