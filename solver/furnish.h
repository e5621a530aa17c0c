#pragma once
// The furnish pipeline (paper Sec. 3.2-3.4 end to end): a validated layout -> the built building -> per
// room: its context, the graph planner's A-PSSG, an asset for every object, the pose solver with its exact
// check and rule agent -> one scene file, a furnished .glb, a report and pictures. `villa furnish` is a
// thin CLI over FurnishLayoutFile; `villa generate` calls the same function after planning a layout.
//
//   FurnishOptions options;                 // rooms, text, seed, jobs, library, solver settings
//   auto summary = FurnishLayoutFile("layout.json", "out/", options);
//
// Rooms are independent given the building: they are furnished in parallel (`jobs`), each from its own
// seed (the run's seed mixed with the room's name), and gathered in layout order, so scene.json,
// furnished.glb, CREDITS and the pictures are byte-identical whatever the job count (report.json differs
// only in its times). A room that cannot be completed keeps its best state and says why (SCENE.md
// "Failure outcomes"); that is an outcome, not an error.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "assets/asset_library.h"
#include "building/building.h"
#include "layout/layout.h"
#include "physics/glb_settle.h"
#include "render/plan_render.h"
#include "render/view3d.h"
#include "scene/acquire.h"
#include "scene/planner.h"
#include "scene/room_context.h"
#include "scene/scene.h"
#include "solver/exact_check.h"
#include "solver/functional.h"
#include "solver/options.h"
#include "solver/reach_feedback.h"
#include "solver/solve.h"
#include "util/result.h"

namespace villa::solver {

// What reachability (issue 13: solver/reach*, docs/REACH.md) adds to a furnished villa, measured once after
// every room is solved and the feedback loop has run: RCH per room (1 reachable from the entrance by a
// person of the given radius, across floors by the stairs; 0 not) and ACC per V_int object (the share of
// its interaction zone that person reaches, SCENE.md, docs/METRICS.md), the drawn paths (plan.png) and the
// full record for report.json.
struct ReachFigures {
  std::map<std::string, double> rch;  // room name -> 1 reachable / 0 not
  std::map<std::string, double> acc;  // V_int object id -> share of its interaction zone reachable, [0, 1]
  struct Path {
    int level = 0;
    std::vector<Point> points;  // plan m: the part of a path walked on this level
  };
  std::vector<Path> paths;
  int rooms = 0, rooms_reachable = 0, zones = 0, zones_reachable = 0;  // zones with any part reachable
  double acc_mean = 1.0;        // ACC over the villa: the mean of `acc`
  int actions = 0;              // actions the rooms' agents took to clear walkways
  std::string outcome;          // how the feedback loop ended, one line
  std::string note;             // what was measured how, for the report
  nlohmann::ordered_json record;  // report.json "reachability": every target, the levels, the feedback's rounds
  std::vector<LevelStats> levels;  // the last check's, with its times (raster, roadmap, queries)
  double seconds = 0.0;         // wall time of the check and the feedback loop
};

// What a critic (issue 14, critic/) is given for one room: the room's solver session, initialised and
// with the rule agent run, which it drives (Apply, Fits, Suggest, KeepCurrent, Finish; solver/solve.h)
// and leaves as it wants the room (the reachability feedback goes on with the same session). Everything
// pointed to outlives the call; critics run on the room workers' threads.
struct RoomCriticInput {
  const scene::RoomContext* context = nullptr;
  const BuildingMesh* building = nullptr;
  const RoomProblem* problem = nullptr;
  const std::vector<scene::SceneObject>* planned = nullptr;  // the plan's objects, assets chosen
  const std::vector<scene::SemanticEdge>* edges = nullptr;   // the plan's semantic edges
  std::string text;       // the request ("" = priors only)
  SolveOptions solve;     // the room's seed already mixed in
  ExactCheckOptions check;
  AssetResolver resolve;  // add_entity's asset ids to records and meshes
  RoomSolver* session = nullptr;  // the room's session (null: the critic makes its own from the problem)
};
// What report.json says of a room's critic.
struct CriticFigures {
  std::string critic;  // "offline", "mllm"
  int rounds = 0;
  int requests = 0, cache_hits = 0;  // questions sent to a model / answered from the answer cache
  int prompt_tokens = 0, completion_tokens = 0;
  double seconds = 0.0;              // wall time of the critic's rounds (after the first solve)
  nlohmann::ordered_json record;     // the critic's own account: rounds, scores, relations before and after
};
using RoomCritic = std::function<Result<CriticFigures>(const RoomCriticInput& input)>;

struct FurnishOptions {
  // Rooms to furnish, as the layout names them ("living-room_0/0"); empty: every room. The others are
  // listed in the scene with no objects and the note "not asked for".
  std::vector<std::string> rooms;
  std::string text;     // the request ("" = the room priors only); may speak of many rooms
  uint64_t seed = 0;    // planner draws, procedural assets, solver choices
  int jobs = 0;         // rooms furnished at once, [0, 256]; 0 = the machine's hardware threads
  // The asset library (scene/acquire.h OpenFurnishingLibrary): a folder, else the installed one, else
  // procedural assets only; `procedural_only` ignores any library.
  std::filesystem::path library;
  bool procedural_only = false;

  BuildOptions build;
  scene::PlannerOptions planner;
  scene::AcquireOptions acquire;
  SolveOptions solve;  // its seed is replaced per room by the run's seed mixed with the room's name
  ExactCheckOptions check;
  bool allow_invalid = false;  // furnish a layout that breaks the geometric rules 1-5 (the builder adapts)
  bool pictures = true;        // plan.png and rooms/<room>.png
  // report.json with its wall and CPU seconds and --jobs; `villa scenes` leaves them out so that a villa's
  // files are the same bytes on every machine and shard (its seconds go into the dataset's index).
  bool report_timings = true;
  bool force = false;          // overwrite the outputs of an earlier run in the folder (never other files)
  // Reachability (docs/REACH.md), after every room is solved: a person (a disc of reach.reach.radius) walks
  // from the entrance to every room and interaction zone, across floors by the stairs; what furniture
  // blocks becomes walkways the rooms' agents clear (up to reach.rounds rounds of move, shrink or remove);
  // RCH, ACC and the paths go into report.json and plan.png. Off (`--no-reach`): not measured (null).
  bool check_reach = true;
  ReachFeedbackOptions reach;
  // Issue 28: the finished villa dropped into Bullet (physics/glb_settle.h) as its .glb, to measure how
  // many objects stay put; report.json's "physics" and the summary say it. Off (`--no-physics`): null.
  bool check_physics = true;
  physics::SettleOptions settle;
  // Settles after which optional pieces that moved are taken out and the villa settled again, [0, 10].
  int physics_rounds = 1;
  // Issue 14: a critic reviews each solved room and acts through its solver session (critic/critic.h
  // makes one); unset: the rule agent alone.
  RoomCritic critic;
  // The A-PSSG planner (an MLLM that revises the priors' graph, critic/); unset: PriorsPlanner(planner).
  std::shared_ptr<const scene::GraphPlanner> graph_planner;

  // Progress (the CLI's bar), both may be empty: on_start once with the number of rooms to furnish, then
  // on_room_done from the worker threads as each room finishes.
  std::function<void(size_t rooms)> on_start;
  std::function<void(const std::string& room)> on_room_done;

  // Empty when usable, else what is wrong ("jobs = -1: must be in [0, 256]").
  std::string Check() const;
};

// One room's record in report.json.
struct RoomReport {
  std::string room;
  Category category = Category::kRoom;
  int level = 0;
  double area = 0.0;              // m2 of the polygon
  double furnishable_area = 0.0;  // m2
  bool asked = true;              // false: left out by FurnishOptions::rooms
  scene::PlanSummary plan;
  std::vector<std::string> plan_notes;
  std::vector<scene::AcquiredAsset> assets;  // one per planned object
  scene::AcquireSummary acquire;
  std::vector<std::string> dropped;  // left out before solving, with why
  std::vector<std::string> notes;    // approximations of the problem mapping
  std::optional<SolveSummary> solve;  // absent when nothing was placed (no objects, not asked)
  std::optional<CriticFigures> critic;  // when a critic drove the solver
  std::string outcome;               // "converged" / "budget" / "infeasible"
  std::string reason;                // why, in words
  int objects = 0;                   // NO: objects placed
  // Issue 27: does the room work as a room (essentials, groups, floor use, wishes, support semantics),
  // measured on the final arrangement (after the critic and the reachability feedback).
  std::optional<FunctionalCheck> functional;
  double seconds_plan = 0.0, seconds_acquire = 0.0, seconds_solve = 0.0, seconds = 0.0;  // wall
  double cpu_seconds = 0.0;  // the room's thread CPU time (a room runs on one thread): load-independent
};

struct FurnishSummary {
  int rooms = 0;            // rooms of the layout
  int furnished = 0;        // rooms asked for
  int converged = 0, budget = 0, infeasible = 0;
  int objects = 0;          // placed, over the furnished rooms
  int planned = 0;          // planned, over the furnished rooms
  int removed = 0;          // taken out by the solver's agent
  int dropped = 0;          // left out before solving (a parent that could not hold them)
  int colliding = 0, floating = 0, out_of_bounds = 0, consumers = 0, inside_edges = 0, contained = 0;
  int library_assets = 0, procedural_assets = 0;  // object counts by where their asset came from
  double seconds = 0.0;     // wall time of the whole run
  double room_seconds = 0.0;  // sum over rooms (plan + acquire + solve), as on one core
  // Reachability (when checked): rooms and V_int zones reachable from the entrance, what the feedback did.
  bool reach_checked = false;
  int reach_rooms = 0, rooms_reachable = 0, reach_zones = 0, zones_reachable = 0;
  int reach_actions = 0;     // actions the rooms' agents took to clear walkways
  std::string reach_note;    // how the feedback ended, or why reachability was not measured
  double reach_seconds = 0.0;
  // Physics (when settled): free objects and those stable by the strict and loose rules, the settle's time.
  bool physics_checked = false;
  physics::StabilityCount stability;
  int starts_inside = 0;
  double physics_seconds = 0.0, physics_simulated = 0.0;
  int physics_removed = 0;  // optional pieces (with what they held) taken out because they moved
  int physics_lifted = 0;   // pieces raised onto or slid off their parent's collision hull (they started inside it)
  std::vector<std::string> written;  // files written, relative to the output folder

  // CR, FR, OBR over every object of the furnished rooms; CSR over their inside edges (1 when none).
  double cr() const { return objects ? double(colliding) / objects : 0.0; }
  double fr() const { return consumers ? double(floating) / consumers : 0.0; }
  double obr() const { return objects ? double(out_of_bounds) / objects : 0.0; }
  double csr() const { return inside_edges ? double(contained) / inside_edges : 1.0; }
  double rch() const { return reach_rooms ? double(rooms_reachable) / reach_rooms : 1.0; }
  double reach_acc = 1.0;    // ACC: the mean share of the V_int zones reachable
  FunctionalTally functional;  // issue 27's checks over the furnished rooms
  double acc() const { return reach_acc; }
  std::string BriefReport() const;  // a few lines for people
};

// Everything a run made, in memory.
struct FurnishedVilla {
  Layout layout;
  BuildingMesh building;
  std::vector<scene::RoomContext> contexts;  // layout order
  scene::SceneFile scene;                    // validated
  std::vector<RoomReport> rooms;             // layout order
  std::shared_ptr<const AssetLibrary> library;
  std::shared_ptr<const scene::AssetAcquirer> assets;  // records of every asset used (Find)
  std::string library_note;                  // "procedural assets only" ...
  std::optional<ReachFigures> reach;
  std::optional<physics::GlbSettleSummary> physics;  // the settle, when check_physics
  // furnished.glb's bytes as the physics check settled them (FurnishLayout's final villa; empty without
  // the check): FurnishedGlb() returns them rather than exporting again.
  std::string glb;
  FurnishSummary summary;
};

// Furnishes `layout` (already validated; `layout_ref` names its file for the scene). The library must
// make proc: meshes (OpenFurnishingLibrary does). Errors: bad options, an unbuildable layout, an unknown
// room name, an asset that cannot be loaded, a scene that fails its own validation (a bug).
Result<FurnishedVilla> FurnishLayout(const Layout& layout, const scene::FileRef& layout_ref,
                                     std::shared_ptr<const AssetLibrary> library, std::optional<scene::FileRef> library_ref,
                                     const FurnishOptions& options);

// The output files of a run, written into `dir` (created if needed) all or nothing (util/staged_output.h:
// staged, then moved into place together, under the folder's lock): scene.json, furnished.glb,
// report.json, CREDITS and plan.png (rooms/<room>.png, the room name with "/" as "_", are reserved: refused
// without force, not drawn yet). Files of an earlier run are replaced only with options.force; other files
// in the folder are never touched. Returns the paths written, relative to `dir`. A usage problem (existing
// outputs, another run writing the folder) starts with "usage: ".
Result<std::vector<std::string>> WriteFurnishedVilla(const FurnishedVilla& villa, const std::filesystem::path& dir,
                                                     const FurnishOptions& options);
// The same files written straight into `dir`, a folder the caller makes whole itself (`villa scenes` builds
// each villa under a temporary name): no lock, no staging, no check of what is there.
Result<std::vector<std::string>> WriteFurnishedVillaFiles(const FurnishedVilla& villa, const std::filesystem::path& dir,
                                                          const FurnishOptions& options);
// The critic's log folder of `villa furnish` (inside the staged folder while the run writes).
inline constexpr const char* kCriticLogFolder = "critic";

// The whole run from a layout file: read and validate it (rules 1-5 unless allow_invalid), open the
// library, furnish, write. Errors name the file; a usage problem (an existing output without force, an
// unknown room) starts with "usage: ".
Result<FurnishSummary> FurnishLayoutFile(const std::filesystem::path& layout, const std::filesystem::path& dir,
                                         const FurnishOptions& options);

// The parts of the outputs, for tests and `villa generate`.
nlohmann::ordered_json FurnishReportJson(const FurnishedVilla& villa, const FurnishOptions& options);
// The furnished .glb (villa.glb when FurnishLayout settled it, else exported now).
Result<std::string> FurnishedGlb(const FurnishedVilla& villa);

std::string FurnishCredits(const FurnishedVilla& villa);  // "" when no placed asset needs credit
// "rooms/kitchen_0_0.png" for "kitchen_0/0".
std::string RoomPictureName(const std::string& room);
// That picture of one room (solver/room_view.h RoomPicture: a top view and a cut-away view), PNG bytes.
Result<std::string> RoomPicturePng(const FurnishedVilla& villa, const scene::RoomContext& context);

// What plan.png draws over the floor plan: every placed object's oriented box (its size x scale, turned
// by its yaw) in a muted tone of its room's colour, on its level, lowest objects first so what stands
// on a table shows over it (objects hung from the ceiling are left out: they would cover the room), and
// the reachability check's walking paths (villa.reach) as thin lines when it ran, and a thin outline
// around each functional group of the rooms' checks (green when it holds, red when it fails).
PlanOverlay FurnishedPlanOverlay(const FurnishedVilla& villa);
// plan.png: the floor plans of every level with that overlay.
Result<std::string> FurnishedPlanPng(const FurnishedVilla& villa);
// The furnished villa in the 3D view (render/view3d.h RenderPreview): the building as `villa build
// --preview` draws it plus every placed object in its assets' colours; the cut-away of a level keeps
// standing furniture whole and cuts what hangs on walls or from the ceiling like the walls.
Result<Image> RenderFurnishedPreview(const FurnishedVilla& villa, const PreviewOptions& options = {});

}  // namespace villa::solver
