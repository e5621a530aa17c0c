#include "solver/furnish.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <functional>
#include <optional>
#include <set>
#include <thread>

#include <time.h>

#include "building/export.h"
#include "building/view_scene.h"
#include "layout/layout_io.h"
#include "layout/validate.h"
#include "scene/file_digest.h"
#include "scene/random.h"
#include "scene/request.h"
#include "scene/validate.h"
#include "solver/room_view.h"
#include "solver/scene_problem.h"
#include "util/atomic_file.h"
#include "util/staged_output.h"
#include "util/utf8.h"

namespace villa::solver {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;
using Clock = std::chrono::steady_clock;

double Since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
// CPU time of the calling thread, s.
double ThreadCpuSeconds() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}
double Round4(double v) {
  const double r = std::round(v * 1e4) / 1e4;
  return r == 0.0 ? 0.0 : r;
}
double Round3(double v) { return std::round(v * 1e3) / 1e3; }

constexpr const char* kSceneFile = "scene.json";
constexpr const char* kGlbFile = "furnished.glb";
constexpr const char* kReportFile = "report.json";
constexpr const char* kCreditsFile = "CREDITS";
constexpr const char* kPlanPicture = "plan.png";

// What one room's worker hands back.
struct RoomResult {
  RoomReport report;
  scene::RoomEntry entry;
  std::vector<scene::SceneObject> objects;
  std::string error;  // set when the room could not be furnished for a reason that is not an outcome
  // A solved room keeps its solver for the reachability feedback, with what mapping its solution back needs.
  std::unique_ptr<RoomSolver> solver;
  std::vector<scene::SceneObject> planned;
  std::vector<scene::SemanticEdge> planned_edges;
  std::vector<std::string> dropped_ids;
};

scene::Metrics RoomMetrics(const ExactMetrics& m) {
  return {{{"CR", Round4(m.cr)}, {"FR", Round4(m.fr)}, {"OBR", Round4(m.obr)}, {"CSR", Round4(m.csr)}, {"NO", double(m.objects)}}};
}

// The scene's view of a solved room from its solver's present state: the posed objects, the solve record
// and metrics, the report's outcome, and the plan's edges between objects still there. Called after the
// solve and again after the reachability feedback changed the room.
void TakeSolution(RoomResult& out) {
  const RoomSolution solution = out.solver->Solution();
  const SolveSummary& s = solution.summary;
  out.objects = SolvedSceneObjects(out.solver->Problem(), solution, out.planned);
  scene::RoomSolve record;
  record.outcome = *scene::ParseSolveOutcome(OutcomeName(s.outcome));
  record.iterations = s.iterations;
  record.energy = s.energy.total;
  record.removed = out.dropped_ids;
  record.removed.insert(record.removed.end(), s.removed.begin(), s.removed.end());
  record.actions = Json::array();
  for (const ActionResult& a : s.actions) record.actions.push_back(ActionResultToJson(a));
  record.note = s.reason;
  out.entry.solve = record;
  out.entry.metrics = RoomMetrics(s.metrics);
  out.report.outcome = std::string(OutcomeName(s.outcome));
  out.report.reason = s.reason;
  out.report.solve = s;
  std::set<std::string> kept;
  for (const scene::SceneObject& o : out.objects) kept.insert(o.id);
  out.entry.edges_sem.clear();
  for (const scene::SemanticEdge& e : out.planned_edges)
    if (kept.count(e.source) && kept.count(e.target)) out.entry.edges_sem.push_back(e);
  out.report.objects = static_cast<int>(out.objects.size());
}

// One room: plan, acquire, map, solve, and the scene's view of the result.
RoomResult FurnishRoom(const FurnishedVilla& villa, const scene::RoomContext& context, bool asked,
                       const scene::GraphPlanner& planner, const FurnishOptions& options) {
  RoomResult out;
  RoomReport& report = out.report;
  report.room = context.name;
  report.category = context.category;
  report.level = context.level;
  report.area = context.area;
  report.furnishable_area = context.furnishable_area;
  report.asked = asked;
  out.entry.name = context.name;
  const auto start = Clock::now();
  const double cpu_start = ThreadCpuSeconds();
  auto settle = [&](scene::SolveOutcome outcome, const std::string& reason) {
    out.entry.solve = scene::RoomSolve{outcome, 0, 0.0, {}, Json::array(), reason};
    report.outcome = std::string(scene::SolveOutcomeName(outcome));
    report.reason = reason;
  };
  if (!asked) {
    settle(scene::SolveOutcome::kConverged, "not asked for (the run named other rooms)");
    return out;
  }

  auto t = Clock::now();
  auto plan = planner.Plan({&context, options.text, options.seed, &villa.layout});
  if (!plan.ok()) {
    out.error = context.name + ": " + plan.error();
    return out;
  }
  report.seconds_plan = Since(t);
  report.plan = plan->summary;
  report.plan_notes = plan->record.notes;
  out.entry.plan = plan->record;

  t = Clock::now();
  auto assets = villa.assets->Acquire(context, plan->objects);
  if (!assets.ok()) {
    out.error = context.name + ": " + assets.error();
    return out;
  }
  report.seconds_acquire = Since(t);
  report.assets = assets->choices;
  report.acquire = assets->summary;

  const AssetResolver resolve = [&](const std::string& id) -> Result<std::pair<AssetRecord, std::shared_ptr<const AssetMesh>>> {
    const AssetRecord* record = villa.assets->Find(id);
    if (!record) return Error{"asset " + id + " is not in the library"};
    auto mesh = villa.library->Mesh(id);
    if (!mesh.ok()) return Error{mesh.error()};
    return std::make_pair(*record, *mesh);
  };
  auto mapped = RoomProblemOf(context, villa.building, plan->objects, plan->edges, resolve);
  if (!mapped.ok()) {
    out.error = context.name + ": " + mapped.error();
    return out;
  }
  report.dropped = mapped->dropped;
  report.notes = mapped->notes;
  std::vector<std::string> dropped_ids;
  for (const std::string& d : mapped->dropped) dropped_ids.push_back(d.substr(0, d.find(": ")));

  if (mapped->problem.free_floor.size() < 3 && !mapped->problem.objects.empty()) {
    settle(scene::SolveOutcome::kInfeasible, "the room has no free floor inside its walls: nothing placed");
    out.entry.solve->removed = dropped_ids;
    for (const ProblemObject& o : mapped->problem.objects) out.entry.solve->removed.push_back(o.id);
  } else if (mapped->problem.objects.empty()) {
    std::string why = "nothing to place";
    if (!plan->record.notes.empty()) why += ": " + plan->record.notes.front();
    settle(scene::SolveOutcome::kConverged, why);
    out.entry.solve->removed = dropped_ids;
  } else {
    SolveOptions solve = options.solve;
    solve.seed = scene::SplitMix64(options.seed ^ scene::NameHash(context.name)).Next();
    t = Clock::now();
    out.solver = std::make_unique<RoomSolver>(mapped->problem, solve, options.check);
    if (Status s = out.solver->Initialise(); !s.ok()) {
      out.error = context.name + ": " + s.error();
      return out;
    }
    out.solver->RunAgent();
    // Issue 14: a critic reviews the room and acts through the same session (critic/critic.h).
    if (options.critic) {
      const RoomCriticInput input{&context, &villa.building, &mapped->problem, &plan->objects, &plan->edges,
                                  options.text, solve, options.check, resolve, out.solver.get()};
      auto figures = options.critic(input);
      if (!figures.ok()) {
        out.error = context.name + ": " + figures.error();
        return out;
      }
      report.critic = std::move(*figures);
    }
    out.solver->TidyGroups(/*moves=*/true);
    out.solver->Refill();
    report.seconds_solve = Since(t);
    out.planned = plan->objects;
    out.planned_edges = plan->edges;
    out.dropped_ids = dropped_ids;
    TakeSolution(out);
  }
  report.seconds = Since(start);
  report.cpu_seconds = ThreadCpuSeconds() - cpu_start;
  return out;
}

// The reachability of the building with every room's objects as its solver holds them now.
Result<ReachReport> ReachOf(const ReachInput& building, const std::map<std::string, RoomSolver*>& solvers, const ReachOptions& options) {
  ReachInput input = building;
  std::vector<ReachObject> objects;
  for (const auto& [name, solver] : solvers) {
    int level = 0;
    for (const ReachTarget& t : building.targets)
      if (t.kind == TargetKind::kRoom && t.name == name) level = t.level;
    for (ReachObject& o : ReachObjectsOf(solver->Solution(), name, level)) objects.push_back(std::move(o));
  }
  AddObjects(input, objects, options);
  return CheckReach(input, options);
}

// The parts of a path walked on each level (its points on a stair's way, level -1, are left out).
std::vector<ReachFigures::Path> PathPieces(const ReachPath& path) {
  std::vector<ReachFigures::Path> out;
  ReachFigures::Path piece;
  piece.level = -1;
  auto close = [&] {
    if (piece.points.size() >= 2) out.push_back(piece);
    piece.points.clear();
  };
  for (size_t k = 0; k < path.points.size() && k < path.level.size(); ++k) {
    if (path.level[k] != piece.level) {
      close();
      piece.level = path.level[k];
    }
    if (piece.level >= 0) piece.points.push_back({path.points[k].x, path.points[k].y});
  }
  close();
  return out;
}

// Reachability on the furnished building (docs/REACH.md), with the feedback loop acting on the rooms'
// solvers: rooms it changed (walkways laid, actions taken) take their solver's new state. Errors: a
// building reachability cannot read (no entrance, a staircase without a foot), bad options.
Result<ReachFigures> CheckReachability(const Layout& layout, const BuildingMesh& building, std::vector<RoomResult>& results,
                                       const FurnishOptions& options) {
  const auto start = Clock::now();
  auto input = BuildingReachInput(layout, building, options.build, options.reach.reach);
  if (!input.ok()) return Error{input.error()};
  std::map<std::string, RoomSolver*> solvers;
  std::map<std::string, RoomResult*> by_room;
  for (RoomResult& r : results) {
    if (!r.solver) continue;
    solvers[r.report.room] = r.solver.get();
    by_room[r.report.room] = &r;
  }
  auto loop = FreeBlockedWays(*input, solvers, options.reach);
  if (!loop.ok()) return Error{loop.error()};
  ReachFigures f;
  std::set<std::string> changed;
  for (const FeedbackRound& round : loop->rounds) {
    for (const Walkway& w : round.walkways) changed.insert(w.room);
    for (const RoomAction& a : round.actions) changed.insert(a.room);
    f.actions += static_cast<int>(round.actions.size());
  }
  // The feedback's last moves and restores act one object at a time: a room it leaves physically wrong (a
  // chair carried into its desk) gets the rule agent once more, so no room ends colliding.
  for (const std::string& room : changed) {
    RoomSolver& solver = *by_room.at(room)->solver;
    if (!solver.Solution().summary.metrics.Clean()) solver.RunAgent();
  }
  // Issue 27: two steps on every room after the feedback, each kept where one more reachability check loses
  // no room a person reached and leaves no zone unreachable that was not; when the villa's step loses one,
  // room by room (a room whose step loses one goes back, and `fallback` runs there).
  ReachReport last = loop->last;
  // (A zone that went with an object the step left out is not a zone lost: only unreached ones count.)
  auto worse = [&](const ReachReport& r) {
    return r.rooms_reachable < last.rooms_reachable || r.zones - r.zones_reachable > last.zones - last.zones_reachable;
  };
  auto stepwise = [&](const std::function<bool(RoomSolver&)>& step, const std::function<void(const std::string&, RoomSolver&)>& fallback) {
    std::map<std::string, std::shared_ptr<const RoomSolver::Snapshot>> undo;
    std::vector<std::string> touched;
    for (auto& [room, solver] : solvers) {
      undo[room] = solver->Save();
      if (step(*solver)) touched.push_back(room);
    }
    if (touched.empty()) return;
    auto again = ReachOf(*input, solvers, options.reach.reach);
    if (again.ok() && !worse(*again)) {
      last = std::move(*again);
      return;
    }
    for (const std::string& room : touched) solvers.at(room)->Restore(*undo.at(room));
    for (const std::string& room : touched) {
      RoomSolver& solver = *solvers.at(room);
      auto before = solver.Save();
      if (step(solver)) {
        auto one = ReachOf(*input, solvers, options.reach.reach);
        if (one.ok() && !worse(*one)) {
          last = std::move(*one);
          continue;
        }
        solver.Restore(*before);
      }
      if (fallback) fallback(room, solver);
    }
  };
  // The feedback's walkways and moves may have pushed groups apart (a TV stand slid off the sofa's axis):
  // the tidy stage once more; where it cannot be kept, in the rooms the feedback changed only its removals.
  stepwise([](RoomSolver& solver) { return solver.TidyGroups(/*moves=*/true); },
           [&](const std::string& room, RoomSolver& solver) {
             if (changed.count(room)) solver.TidyGroups(/*moves=*/false);
           });
  // What the feedback removed (and what the rooms lost while settling) put back where it fits now.
  stepwise([](RoomSolver& solver) { return solver.Refill(); }, nullptr);
  for (auto& [room, solver] : solvers) TakeSolution(*by_room.at(room));

  f.outcome = loop->reason;
  f.rooms = last.rooms;
  f.rooms_reachable = last.rooms_reachable;
  f.zones = last.zones;
  f.zones_reachable = last.zones_reachable;
  f.acc_mean = last.Acc();
  for (const TargetResult& t : last.targets) {
    (t.kind == TargetKind::kRoom ? f.rch : f.acc)[t.name] = t.share;
    if (t.path) {
      for (ReachFigures::Path& piece : PathPieces(*t.path)) f.paths.push_back(std::move(piece));
    }
  }
  char radius[32];
  std::snprintf(radius, sizeof radius, "%.2f", options.reach.reach.radius);
  f.note = std::string("a person (a disc of radius ") + radius +
           " m) from the entrance to every room and V_int interaction zone, across floors by the stairs; a 2 cm raster "
           "decides, OMPL draws the paths (PRM per level, RRTConnect); feedback: " + loop->reason;
  f.levels = last.levels;
  f.record = last.ToJson();
  f.record["radius"] = options.reach.reach.radius;
  f.record["feedback"] = loop->ToJson();
  f.seconds = Since(start);
  f.record["seconds"] = Round4(f.seconds);
  return f;
}

// Room means of the per-room metrics, over the rooms that hold objects.
scene::Metrics BuildingMetrics(const std::vector<RoomReport>& rooms) {
  double cr = 0, fr = 0, obr = 0, csr = 0, no = 0;
  int n = 0;
  for (const RoomReport& r : rooms) {
    if (!r.solve) continue;
    const ExactMetrics& m = r.solve->metrics;
    cr += m.cr, fr += m.fr, obr += m.obr, csr += m.csr, no += m.objects;
    ++n;
  }
  if (n == 0) return {};
  return {{{"CR", Round4(cr / n)}, {"FR", Round4(fr / n)}, {"OBR", Round4(obr / n)}, {"CSR", Round4(csr / n)}, {"NO", Round4(no / n)}}};
}

Json StringArray(const std::vector<std::string>& v) { return Json(v); }

Json CriticJson(const CriticFigures& c) {
  Json j{{"critic", c.critic},
         {"rounds", c.rounds},
         {"requests", c.requests},
         {"cache_hits", c.cache_hits},
         {"prompt_tokens", c.prompt_tokens},
         {"completion_tokens", c.completion_tokens},
         {"seconds", Round4(c.seconds)}};
  if (!c.record.is_null()) j["record"] = c.record;
  return j;
}

Json RoomJson(const RoomReport& r, const std::optional<ReachFigures>& reach, const std::vector<scene::SceneObject>& objects) {
  Json j;
  j["room"] = r.room;
  j["category"] = std::string(CategoryName(r.category));
  j["level"] = r.level;
  j["area_m2"] = Round3(r.area);
  j["furnishable_m2"] = Round3(r.furnishable_area);
  j["asked"] = r.asked;
  j["outcome"] = r.outcome;
  j["reason"] = r.reason;
  if (!r.asked) return j;
  j["plan"] = {{"outcome", std::string(scene::PlanOutcomeName(r.plan.outcome))},
               {"objects", r.plan.objects},
               {"target", {r.plan.target_min, r.plan.target_max}},
               {"notes", StringArray(r.plan_notes)}};
  j["assets"] = {{"library", r.acquire.library},
                 {"procedural", r.acquire.procedural},
                 {"fallbacks", r.acquire.fallbacks},
                 {"distinct", r.acquire.distinct_assets}};
  std::map<std::string, std::string> placed;
  for (const scene::SceneObject& o : objects)
    if (o.room == r.room) placed[o.id] = o.asset;
  Json list = Json::array();
  for (const scene::AcquiredAsset& a : r.assets) {
    Json o{{"id", a.object}, {"asset", a.asset}, {"rule", std::string(scene::AcquireRuleName(a.rule))}, {"placed", placed.count(a.object) > 0}};
    if (!a.note.empty()) o["note"] = a.note;
    list.push_back(std::move(o));
  }
  j["objects"] = std::move(list);
  j["dropped"] = StringArray(r.dropped);
  if (!r.notes.empty()) j["notes"] = StringArray(r.notes);
  Json metrics;
  if (r.solve) {
    const SolveSummary& s = *r.solve;
    const ExactMetrics& m = s.metrics;
    metrics = {{"CR", Round4(m.cr)}, {"FR", Round4(m.fr)}, {"OBR", Round4(m.obr)}, {"CSR", Round4(m.csr)}, {"NO", m.objects}};
    j["iterations"] = s.iterations;
    j["energy"] = {{"total", Round4(s.energy.total)},
                   {"collision", Round4(s.energy.collision)},
                   {"support", Round4(s.energy.support)},
                   {"semantic", Round4(s.energy.semantic)}};
    Json trace = Json::array();
    for (double e : s.energy_trace) trace.push_back(Round4(e));
    j["energy_trace"] = std::move(trace);
    Json actions = Json::array();
    for (const ActionResult& a : s.actions) actions.push_back(ActionResultToJson(a));
    j["actions"] = std::move(actions);
    j["removed"] = StringArray(s.removed);
    Json collisions = Json::array();
    for (const CollisionPair& p : m.pairs) collisions.push_back({p.a, p.b});
    j["collisions"] = std::move(collisions);
    j["clearance_m"] = m.min_clearance < 0 ? Json(nullptr) : Json(Round4(m.min_clearance));
    j["log"] = StringArray(s.log);
  } else {
    metrics = {{"NO", 0}};
  }
  if (reach) {
    auto rch = reach->rch.find(r.room);
    metrics["RCH"] = rch == reach->rch.end() ? Json(nullptr) : Json(Round4(rch->second));
    Json acc = Json::object();
    for (const scene::SceneObject& o : objects)
      if (o.room == r.room)
        if (auto it = reach->acc.find(o.id); it != reach->acc.end()) acc[o.id] = Round4(it->second);
    metrics["ACC"] = std::move(acc);
  } else {
    metrics["RCH"] = nullptr;  // not measured: no reachability check plugged in (issue 13)
    metrics["ACC"] = nullptr;
  }
  j["metrics"] = std::move(metrics);
  if (r.functional) j["functional"] = FunctionalJson(*r.functional);
  if (r.critic) j["critic"] = CriticJson(*r.critic);
  j["seconds"] = {{"plan", Round4(r.seconds_plan)}, {"acquire", Round4(r.seconds_acquire)}, {"solve", Round4(r.seconds_solve)},
                  {"total", Round4(r.seconds)}, {"cpu", Round4(r.cpu_seconds)}};
  return j;
}

// Per room type over the rooms that hold objects: rooms, mean NO, pooled CR/FR/OBR/CSR, outcomes, time.
Json ByRoomType(const std::vector<RoomReport>& rooms) {
  struct Sum {
    int rooms = 0, converged = 0, objects = 0, colliding = 0, floating = 0, consumers = 0, out = 0, inside = 0, contained = 0;
    double seconds = 0;
    FunctionalTally functional;
  };
  std::map<std::string, Sum> by;
  for (const RoomReport& r : rooms) {
    if (!r.solve) continue;
    Sum& s = by[std::string(CategoryName(r.category))];
    const ExactMetrics& m = r.solve->metrics;
    ++s.rooms;
    s.converged += r.solve->outcome == Outcome::kConverged;
    s.objects += m.objects, s.colliding += m.colliding, s.floating += m.floating, s.consumers += m.consumers;
    s.out += m.out_of_bounds, s.inside += m.inside_edges, s.contained += m.contained;
    s.seconds += r.seconds;
    if (r.functional) s.functional.Add(*r.functional);
  }
  Json out = Json::object();
  for (const auto& [type, s] : by)
    out[type] = {{"rooms", s.rooms},
                 {"converged", s.converged},
                 {"NO_mean", Round4(double(s.objects) / s.rooms)},
                 {"CR", Round4(s.objects ? double(s.colliding) / s.objects : 0.0)},
                 {"FR", Round4(s.consumers ? double(s.floating) / s.consumers : 0.0)},
                 {"OBR", Round4(s.objects ? double(s.out) / s.objects : 0.0)},
                 {"CSR", Round4(s.inside ? double(s.contained) / s.inside : 1.0)},
                 {"seconds_mean", Round4(s.seconds / s.rooms)},
                 {"functional", s.functional.ToJson()}};
  return out;
}

// Issue 27's checks of one furnished room: its objects as placed, the request's wishes for it, and what the
// planner and the solver said (why something asked for or needed is not there).
FunctionalCheck RoomFunction(const FurnishedVilla& villa, const scene::RoomContext& context, const RoomReport& rep,
                             const std::string& text) {
  FunctionalInput in;
  in.context = &context;
  for (const scene::SceneObject& o : villa.scene.objects)
    if (o.room == context.name) in.objects.push_back(&o);
  in.assets = [&](std::string_view id) { return villa.assets->Find(id); };
  if (!text.empty())
    for (const scene::Wish& w : scene::ParseRoomRequest(text, context.category, context.ordinal).wishes)
      in.wishes.push_back({std::string(w.category->name), w.count, w.fill});
  in.notes = rep.plan_notes;
  if (const scene::RoomEntry* entry = villa.scene.FindRoom(context.name)) in.edges = entry->edges_sem;
  for (const std::string& d : rep.dropped) in.notes.push_back("left out before solving: " + d);
  if (rep.solve)
    for (const ActionResult& a : rep.solve->actions)
      if (a.action.kind == ActionKind::kRemoveEntity && a.status != ActionStatus::kRefused)
        in.notes.push_back("removed " + a.action.id + ": " + a.action.reason);
  return CheckRoomFunction(in);
}

std::vector<std::string> OutputNames(const Layout& layout, bool pictures) {
  std::vector<std::string> names{kSceneFile, kGlbFile, kReportFile, kCreditsFile};
  if (pictures) {
    names.push_back(kPlanPicture);
    for (const Room& r : layout.rooms) names.push_back(RoomPictureName(r.name()));
  }
  return names;
}

Status RefuseExisting(const fs::path& dir, const std::vector<std::string>& names) {
  std::error_code ec;
  for (const std::string& name : names)
    if (fs::exists(dir / name, ec))
      return Error{"usage: " + (dir / name).string() + " exists (an earlier run's output); pass --force to overwrite it"};
  return Status::Ok();
}

}  // namespace

std::string FurnishOptions::Check() const {
  if (jobs < 0 || jobs > 256) return "jobs = " + std::to_string(jobs) + ": must be in [0, 256]";
  if (!text.empty())
    if (std::string p = RequestTextProblem(text); !p.empty()) return "text: " + p;
  if (std::string p = build.Check(); !p.empty()) return p;
  if (std::string p = planner.Check(); !p.empty()) return "planner: " + p;
  if (std::string p = acquire.Check(); !p.empty()) return "assets: " + p;
  std::string message;
  if (!solve.IsValid(&message)) return "solver: " + message;
  if (!check.IsValid(&message)) return "exact check: " + message;
  if (check_reach && !reach.IsValid(&message)) return "reach: " + message;
  if (check_physics) {
    if (std::string bad = settle.Check(); !bad.empty()) return "physics: " + bad;
    if (physics_rounds < 0 || physics_rounds > 10) return "physics rounds = " + std::to_string(physics_rounds) + ": must be in [0, 10]";
  }
  return "";
}

std::string RoomPictureName(const std::string& room) {
  std::string name = room;
  std::replace(name.begin(), name.end(), '/', '_');
  return "rooms/" + name + ".png";
}

std::string FurnishSummary::BriefReport() const {
  auto pct = [](double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", 100.0 * v);
    return std::string(text);
  };
  std::string out;
  out += std::to_string(furnished) + " of " + std::to_string(rooms) + " rooms furnished: " + std::to_string(converged) +
         " converged, " + std::to_string(budget) + " budget, " + std::to_string(infeasible) + " infeasible\n";
  out += std::to_string(objects) + " objects placed of " + std::to_string(planned) + " planned (" + std::to_string(removed) +
         " removed by the solver, " + std::to_string(dropped) + " left out before solving); assets " +
         std::to_string(library_assets) + " from the library, " + std::to_string(procedural_assets) + " procedural\n";
  out += "CR " + pct(cr()) + " %  FR " + pct(fr()) + " %  OBR " + pct(obr()) + " %  CSR " + pct(csr()) + " % (" +
         std::to_string(contained) + "/" + std::to_string(inside_edges) + ")\n";
  char time[128];
  std::snprintf(time, sizeof time, "%.2f s (%.2f s of room work, %.3f s a room)\n", seconds, room_seconds,
                furnished ? room_seconds / furnished : 0.0);
  out += "time: " + std::string(time);
  if (functional.rooms > 0) out += "rooms as rooms: " + functional.Line() + "\n";
  if (reach_checked) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "reach: RCH %s %% (%d/%d rooms), ACC %s %% (%d/%d zones reachable); %d action(s) cleared ways; %.2f s\n",
                  pct(rch()).c_str(), rooms_reachable, reach_rooms, pct(acc()).c_str(), zones_reachable, reach_zones,
                  reach_actions, reach_seconds);
    out += line + ("  " + reach_note + "\n");
  } else if (!reach_note.empty()) {
    out += "reach: " + reach_note + "\n";
  }
  if (physics_checked) {
    const int n = stability.free;
    auto share = [&](int k) { return pct(n ? double(k) / n : 1.0); };
    char line[256];
    std::snprintf(line, sizeof line,
                  "physics: %s %% of %d free objects stay within 1 cm and 0.1 rad in %.3g s of Bullet, %s %% within 20 "
                  "cm and 8 degrees; %d start inside another; %d optional piece(s) that moved taken out, %d moved out of "
                  "their parent's collision hull; %.2f s\n",
                  share(stability.strict).c_str(), n, physics_simulated, share(stability.loose).c_str(), starts_inside,
                  physics_removed, physics_lifted, physics_seconds);
    out += line;
  }
  return out;
}

Result<FurnishedVilla> FurnishLayout(const Layout& layout, const scene::FileRef& layout_ref,
                                     std::shared_ptr<const AssetLibrary> library, std::optional<scene::FileRef> library_ref,
                                     const FurnishOptions& options) {
  const auto start = Clock::now();
  if (std::string problem = options.Check(); !problem.empty()) return Error{"usage: " + problem};
  if (!library) return Error{"no asset library given (a bug: OpenFurnishingLibrary makes one)"};
  std::set<std::string> asked(options.rooms.begin(), options.rooms.end());
  for (const std::string& name : asked)
    if (layout.FindRoom(name) < 0) {
      std::string names;
      for (const Room& r : layout.rooms) names += (names.empty() ? "" : ", ") + r.name();
      return Error{"usage: --room " + name + ": no such room in the layout (rooms: " + names + ")"};
    }

  FurnishedVilla villa;
  villa.layout = layout;
  villa.library = library;
  auto building = BuildBuilding(layout, options.build);
  if (!building.ok()) return Error{building.error()};
  villa.building = std::move(*building);
  auto contexts = scene::RoomContexts(villa.layout, villa.building, options.build);
  if (!contexts.ok()) return Error{contexts.error()};
  villa.contexts = std::move(*contexts);
  auto acquirer = scene::AssetAcquirer::Make(*library, options.acquire, options.seed, options.text);
  if (!acquirer.ok()) return Error{acquirer.error()};
  villa.assets = *acquirer;
  // Floors and paint in the colours of the style the furniture is chosen in (issue 31).
  villa.building.style = villa.assets->style();

  // Rooms in parallel; results land in layout order, so the output does not depend on the job count.
  const scene::PriorsPlanner priors(options.planner);
  const scene::GraphPlanner& planner = options.graph_planner ? *options.graph_planner : priors;
  const size_t n = villa.contexts.size();
  if (options.on_start) options.on_start(asked.empty() ? n : asked.size());
  std::vector<RoomResult> results(n);
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t i = next++; i < n; i = next++) {
      const scene::RoomContext& context = villa.contexts[i];
      try {
        results[i] = FurnishRoom(villa, context, asked.empty() || asked.count(context.name), planner, options);
      } catch (const std::exception& e) {
        results[i].error = context.name + ": " + e.what();
      }
      if (options.on_room_done && (asked.empty() || asked.count(context.name))) options.on_room_done(context.name);
    }
  };
  const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  const size_t jobs = std::min<size_t>(n, options.jobs > 0 ? options.jobs : hardware);
  if (jobs <= 1) {
    worker();
  } else {
    std::vector<std::thread> threads;
    for (size_t j = 0; j < jobs; ++j) threads.emplace_back(worker);
    for (std::thread& t : threads) t.join();
  }

  for (const RoomResult& r : results)
    if (!r.error.empty()) return Error{r.error};
  FurnishSummary& sum = villa.summary;
  // Reachability before the rooms are gathered: its feedback may still change them.
  std::string reach_unmeasured;  // why, when it was asked for and could not be measured
  if (options.check_reach) {
    auto reach = CheckReachability(villa.layout, villa.building, results, options);
    if (reach.ok()) villa.reach = std::move(*reach);
    else reach_unmeasured = "not measured: " + reach.error();
  }

  // The scene, the summary's room figures and each room's functional check from the rooms as their solvers
  // hold them now (again after the physics check changed some).
  auto gather = [&]() -> Status {
    scene::SceneFile& s = villa.scene;
    s = scene::SceneFile{};
    s.layout = layout_ref;
    s.library = library_ref;
    s.build = {options.build.slab_thickness, options.build.exterior_wall_thickness, options.build.interior_wall_thickness};
    villa.rooms.clear();
    sum = FurnishSummary{};
    sum.rooms = static_cast<int>(n);
    sum.reach_note = reach_unmeasured;
    if (const std::optional<ReachFigures>& reach = villa.reach) {
      sum.reach_checked = true;
      sum.reach_rooms = reach->rooms, sum.rooms_reachable = reach->rooms_reachable;
      sum.reach_zones = reach->zones, sum.zones_reachable = reach->zones_reachable;
      sum.reach_acc = reach->acc_mean, sum.reach_actions = reach->actions;
      sum.reach_note = reach->outcome, sum.reach_seconds = reach->seconds;
    }
    for (const RoomResult& r : results) {
      s.rooms.push_back(r.entry);
      s.objects.insert(s.objects.end(), r.objects.begin(), r.objects.end());
      const RoomReport& rep = r.report;
      villa.rooms.push_back(rep);
      if (!rep.asked) continue;
      ++sum.furnished;
      sum.planned += rep.plan.objects;
      sum.dropped += static_cast<int>(rep.dropped.size());
      sum.room_seconds += rep.seconds;
      for (const scene::AcquiredAsset& a : rep.assets) (a.rule == scene::AcquireRule::kLibrary ? sum.library_assets : sum.procedural_assets)++;
      if (!rep.solve) {
        ++sum.converged;
        continue;
      }
      const SolveSummary& so = *rep.solve;
      sum.converged += so.outcome == Outcome::kConverged;
      sum.budget += so.outcome == Outcome::kBudget;
      sum.infeasible += so.outcome == Outcome::kInfeasible;
      sum.removed += static_cast<int>(so.removed.size());
      const ExactMetrics& m = so.metrics;
      sum.objects += m.objects, sum.colliding += m.colliding, sum.floating += m.floating, sum.out_of_bounds += m.out_of_bounds;
      sum.consumers += m.consumers, sum.inside_edges += m.inside_edges, sum.contained += m.contained;
    }
    if (auto metrics = BuildingMetrics(villa.rooms); !metrics.values.empty()) s.metrics = metrics;
    // Issue 27: does each furnished room work as a room, on its final arrangement.
    for (size_t i = 0; i < villa.rooms.size(); ++i) {
      RoomReport& rep = villa.rooms[i];
      if (!rep.asked) continue;
      rep.functional = RoomFunction(villa, villa.contexts[i], rep, options.text);
      sum.functional.Add(*rep.functional);
    }
    // The scene must pass its own validator before anyone reads it.
    const scene::AssetLookup lookup = [&](std::string_view id) { return villa.assets->Find(id); };
    auto findings = scene::ValidateScene(s, villa.layout, lookup);
    if (!findings.empty()) return Error{"the furnished scene breaks the scene rules (a bug; nothing written):\n" + scene::FormatFindings(findings)};
    return Status::Ok();
  };
  if (Status g = gather(); !g) return Error{g.error()};

  // Issue 28: the villa as a simulator would load it. What moves is a defect: an optional piece that moved
  // (not essential, not named in the request) is taken out by its room's solver (its children with it) and
  // the villa is settled again, up to `physics_rounds` times; protected pieces stay and are reported.
  // After the first settle only the rooms that changed are settled again (objects of different rooms never
  // touch; the others keep what the settle before found).
  if (options.check_physics) {
    double seconds = 0.0;
    int taken = 0, lifted = 0;
    std::optional<physics::GlbSettleSummary> before;
    std::set<std::string> resettle;
    for (int round = 0;; ++round) {
      auto glb = FurnishedGlb(villa);
      if (!glb.ok()) return Error{"furnished.glb: " + glb.error()};
      auto settled = before ? physics::ResettleRooms(*glb, *before, resettle, options.settle) : physics::SettleGlbBytes(*glb, options.settle);
      if (!settled.ok()) return Error{"physics: " + settled.error()};
      seconds += settled->seconds;
      std::map<std::string, const physics::GlbObjectMotion*> moved, inside;
      for (const physics::GlbObjectMotion& o : settled->objects) {
        if (!o.motion.welded && !o.motion.strict) moved[o.id] = &o;
        if (o.motion.start_depth > physics::kStartsInside) inside[o.id] = &o;
      }
      std::set<size_t> changed;
      if (round < options.physics_rounds) {
        for (size_t i = 0; i < results.size(); ++i) {
          RoomResult& r = results[i];
          if (!r.solver || (moved.empty() && inside.empty())) continue;
          const RoomSolution now = r.solver->Solution();
          // A piece that starts inside its parent's collision hull (an imported bed's mattress or headboard, a
          // basin's rim) is moved out of it, with what stands on it.
          for (const ProblemObject& o : now.objects) {
            auto it = inside.find(o.id);
            if (it == inside.end() || it->second->motion.start_against != o.parent || moved.count(o.id)) continue;
            if (r.solver->MoveOutOfParent(o.id, it->second->motion.start_out, it->second->motion.start_depth)) {
              ++lifted;
              changed.insert(i);
            }
          }
          for (const ProblemObject& o : now.objects) {
            auto it = moved.find(o.id);
            if (it == moved.end() || IsProtected(o.priority)) continue;
            Action a;
            a.kind = ActionKind::kRemoveEntity;
            a.id = o.id;
            char why[160];
            std::snprintf(why, sizeof why, "physics: moved %.1f cm and turned %.2f rad in %.3g s of Bullet", 100.0 * it->second->motion.moved,
                          it->second->motion.turned, options.settle.seconds);
            a.reason = why;
            const ActionResult done = r.solver->Apply(a);
            if (done.status != ActionStatus::kRefused) {
              taken += static_cast<int>(done.removed.size());
              changed.insert(i);
            }
          }
        }
      }
      if (changed.empty()) {
        sum.physics_checked = true;
        sum.stability = settled->all;
        sum.starts_inside = settled->starts_inside;
        sum.physics_seconds = seconds;
        sum.physics_simulated = options.settle.seconds;
        sum.physics_removed = taken;
        sum.physics_lifted = lifted;
        villa.physics = std::move(*settled);
        villa.glb = std::move(*glb);  // the bytes settled are the ones written
        break;
      }
      resettle.clear();
      for (size_t i : changed) {
        TakeSolution(results[i]);
        resettle.insert(results[i].report.room);
      }
      before = std::move(*settled);
      if (Status g = gather(); !g) return Error{g.error()};
    }
  }

  sum.seconds = Since(start);
  return villa;
}

namespace {
// The report without its wall and CPU timings: the same bytes whatever machine, load or thread count.
void StripTimings(Json& j) {
  if (j.is_object()) {
    for (const char* key : {"seconds", "seconds_mean", "room_seconds"}) j.erase(key);
    for (auto& [k, v] : j.items()) StripTimings(v);
  } else if (j.is_array()) {
    for (Json& v : j) StripTimings(v);
  }
}
}  // namespace

Json FurnishReportJson(const FurnishedVilla& villa, const FurnishOptions& options) {
  const FurnishSummary& s = villa.summary;
  Json j;
  j["format"] = "villa-furnish-report/1";
  j["layout"] = villa.scene.layout.file;
  j["seed"] = options.seed;
  j["text"] = options.text;
  j["library"] = {{"file", villa.scene.library ? Json(villa.scene.library->file) : Json(nullptr)},
                  {"records", villa.library->records().size()},
                  {"note", villa.library_note}};
  j["style"] = villa.assets->style();
  j["jobs"] = options.jobs;
  j["totals"] = {{"rooms", s.rooms},
                 {"furnished", s.furnished},
                 {"converged", s.converged},
                 {"budget", s.budget},
                 {"infeasible", s.infeasible},
                 {"planned", s.planned},
                 {"objects", s.objects},
                 {"removed", s.removed},
                 {"dropped", s.dropped},
                 {"assets_library", s.library_assets},
                 {"assets_procedural", s.procedural_assets},
                 {"CR", Round4(s.cr())},
                 {"FR", Round4(s.fr())},
                 {"OBR", Round4(s.obr())},
                 {"CSR", Round4(s.csr())},
                 {"NO_mean", Round4(s.furnished ? double(s.objects) / s.furnished : 0.0)},
                 {"RCH", s.reach_checked ? Json(Round4(s.rch())) : Json(nullptr)},
                 {"ACC", s.reach_checked ? Json(Round4(s.acc())) : Json(nullptr)},
                 {"seconds", Round4(s.seconds)},
                 {"room_seconds", Round4(s.room_seconds)},
                 {"functional", s.functional.ToJson()}};
  j["by_room_type"] = ByRoomType(villa.rooms);
  // The critic's cost over the rooms: questions, answers from the cache, tokens, time.
  CriticFigures critic;
  for (const RoomReport& r : villa.rooms) {
    if (!r.critic) continue;
    critic.critic = r.critic->critic;
    critic.rounds += r.critic->rounds;
    critic.requests += r.critic->requests;
    critic.cache_hits += r.critic->cache_hits;
    critic.prompt_tokens += r.critic->prompt_tokens;
    critic.completion_tokens += r.critic->completion_tokens;
    critic.seconds += r.critic->seconds;
  }
  j["totals"]["critic"] = critic.critic.empty() ? Json(nullptr) : CriticJson(critic);
  Json rooms = Json::array();
  for (const RoomReport& r : villa.rooms) rooms.push_back(RoomJson(r, villa.reach, villa.scene.objects));
  j["rooms"] = std::move(rooms);
  if (villa.reach) {
    Json r;
    r["note"] = villa.reach->note;
    for (const auto& [key, value] : villa.reach->record.items()) r[key] = value;
    j["reachability"] = std::move(r);
  } else {
    // Not asked for (null), or asked for and not measurable (why).
    j["reachability"] = s.reach_note.empty() ? Json(nullptr) : Json{{"note", s.reach_note}};
  }
  j["physics"] = villa.physics ? physics::SettleSummaryJson(*villa.physics, options.settle) : Json(nullptr);
  if (villa.physics) {
    j["physics"]["taken_out"] = s.physics_removed;  // optional pieces that moved (with what they held)
    j["physics"]["out_of_parent_hull"] = s.physics_lifted;  // pieces raised onto or slid off their parent's collision hull
  }
  // Issue 31's budget: what furnished.glb draws (each placed object's mesh counted once per placement).
  {
    size_t building = 0, furniture = 0;
    for (const MeshPart& part : villa.building.parts) building += part.mesh.triangles.size();
    std::map<std::string, size_t> of_asset;
    for (const scene::SceneObject& o : villa.scene.objects) {
      if (!o.pose) continue;
      auto [it, added] = of_asset.emplace(o.asset, 0);
      if (added)
        if (auto mesh = villa.library->Mesh(o.asset); mesh.ok())
          for (const AssetMeshPart& part : (*mesh)->parts) it->second += part.mesh.triangles.size();
      furniture += it->second;
    }
    size_t heaviest = 0;
    std::string heaviest_asset;
    for (const auto& [asset, n] : of_asset)
      if (n > heaviest) heaviest = n, heaviest_asset = asset;
    j["triangles"] = {{"total", building + furniture},
                      {"building", building},
                      {"furniture", furniture},
                      {"assets", of_asset.size()},
                      {"heaviest_asset", heaviest_asset.empty() ? Json(nullptr) : Json{{"id", heaviest_asset}, {"triangles", heaviest}}}};
  }
  if (!options.report_timings) {
    StripTimings(j);
    j.erase("jobs");  // how many rooms ran at once: the villa is the same whatever it was
    j["timings"] = "left out (FurnishOptions::report_timings) so that the file is the same on every run";
  }
  return j;
}

Result<std::string> FurnishedGlb(const FurnishedVilla& villa) {
  if (!villa.glb.empty()) return villa.glb;
  ExportFurniture furniture;
  std::map<std::string, int> mesh_of;
  std::vector<std::shared_ptr<const AssetMesh>> keep;  // the borrowed meshes live until the export is done
  Json assets = Json::array();
  std::vector<std::string> credits;
  for (const scene::SceneObject& o : villa.scene.objects) {
    if (!o.pose) continue;
    const AssetRecord* record = villa.assets->Find(o.asset);
    if (!record) return Error{o.id + ": asset " + o.asset + " is not in the library"};
    auto [it, added] = mesh_of.emplace(o.asset, static_cast<int>(furniture.meshes.size()));
    if (added) {
      auto mesh = villa.library->Mesh(o.asset);
      if (!mesh.ok()) return Error{o.id + ": " + mesh.error()};
      keep.push_back(*mesh);
      ExportAssetMesh m;
      m.name = o.asset;
      for (const AssetMeshPart& part : (*mesh)->parts)
        m.parts.push_back({&part.mesh, PartMaterial{part.material.name, {part.material.r, part.material.g, part.material.b},
                                                    part.material.alpha, 0.7}});
      furniture.meshes.push_back(std::move(m));
      assets.push_back({{"id", record->id}, {"name", record->name}, {"license", record->license}, {"creator", record->creator}});
      if (std::string credit = record->Credit(); !credit.empty()) credits.push_back(credit);
    }
    ExportObject node;
    node.name = o.id;
    node.room = o.room;
    node.mesh = it->second;
    node.position = {o.pose->x, o.pose->y, o.pose->z};
    node.yaw = o.pose->yaw;
    node.scale = {o.scale[0], o.scale[1], o.scale[2]};
    Json& e = node.extras;
    e["id"] = o.id;
    e["category"] = o.category;
    e["asset"] = o.asset;
    e["room"] = o.room;
    e["level"] = o.level;
    e["parent"] = o.parent;
    e["relation"] = std::string(scene::RelationName(o.relation));
    if (o.surface) e["surface"] = *o.surface;
    if (o.cavity) e["cavity"] = *o.cavity;
    if (o.wall) e["wall"] = o.wall->edge;
    e["license"] = record->license;
    e["creator"] = record->creator;
    furniture.objects.push_back(std::move(node));
  }
  furniture.asset_extras = {{"assets", std::move(assets)}, {"credits", credits}};
  return BuildingToGlb(villa.building, &furniture);
}

std::string FurnishCredits(const FurnishedVilla& villa) {
  std::set<std::string> seen;
  std::string lines;
  for (const scene::SceneObject& o : villa.scene.objects) {
    if (!seen.insert(o.asset).second) continue;
    const AssetRecord* record = villa.assets->Find(o.asset);
    if (!record) continue;
    if (std::string credit = record->Credit(); !credit.empty()) {
      lines += "- " + credit;
      if (!record->source.package.empty() || !record->source.library.empty())
        lines += "; from " + record->source.library + (record->source.package.empty() ? "" : " (" + record->source.package + ")");
      lines += "\n";
    }
  }
  std::string out = "Credits for the 3D models placed in furnished.glb (scene.json names every object's asset).\n";
  out += lines.empty() ? "No placed model needs credit (every one is CC0 or made by villa's procedural generators).\n"
                       : "These models are licensed under Creative Commons Attribution and are credited as their licence asks:\n" + lines;
  return out;
}

// rooms/<room>.png of one room (solver/room_view.h RoomPicture): its objects as the scene places them.
Result<std::string> RoomPicturePng(const FurnishedVilla& villa, const scene::RoomContext& context) {
  RoomViewInput input;
  input.building = &villa.building;
  input.room = context.name;
  input.level = context.level;
  input.polygon = context.polygon;
  input.floor_z = context.floor_z;
  input.clear_height = context.clear_height;
  for (const scene::SceneObject& o : villa.scene.objects) {
    if (o.room != context.name || !o.pose) continue;
    auto mesh = villa.library->Mesh(o.asset);
    if (!mesh.ok()) return Error{o.id + ": " + mesh.error()};
    input.objects.push_back({"", *mesh, Pose{o.pose->x, o.pose->y, o.pose->z, o.pose->yaw, o.scale[0]}});
  }
  auto picture = RoomPicture(input);
  if (!picture.ok()) return Error{picture.error()};
  return EncodePng(*picture);
}

namespace {
// A placed object's footprint (its size, turned by its yaw) in the plan.
Ring FootprintOf(const scene::SceneObject& o) {
  OrientedBox box;
  box.c = {o.pose->x, o.pose->y};
  box.yaw = o.pose->yaw;
  box.hx = o.size.x / 2.0;
  box.hy = o.size.y / 2.0;
  return box.Footprint();
}
}  // namespace

PlanOverlay FurnishedPlanOverlay(const FurnishedVilla& villa) {
  PlanOverlay overlay;
  std::map<std::string, Category> category_of;
  for (const Room& r : villa.layout.rooms) category_of[r.name()] = r.category;
  std::vector<const scene::SceneObject*> objects;
  for (const scene::SceneObject& o : villa.scene.objects)
    if (o.pose && o.relation != scene::Relation::kHanging) objects.push_back(&o);
  // Lowest first; at one height the larger footprint first, so a rug or a table never hides what is on it.
  std::stable_sort(objects.begin(), objects.end(), [](const scene::SceneObject* a, const scene::SceneObject* b) {
    if (a->pose->z != b->pose->z) return a->pose->z < b->pose->z;
    return a->size.x * a->size.y > b->size.x * b->size.y;
  });
  auto mix = [](Rgb a, Rgb b, double t) { return Rgb{a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t}; };
  for (const scene::SceneObject* o : objects) {
    auto it = category_of.find(o->room);
    const Category category = it == category_of.end() ? Category::kRoom : it->second;
    PlanOverlay::Shape shape;
    shape.level = o->level;
    shape.outline = FootprintOf(*o);
    shape.fill = mix(CategoryColor(category), CategoryInk(category), 0.4);
    shape.fill_alpha = 0.9;
    shape.ink = mix(CategoryInk(category), Rgb{0.1, 0.1, 0.1}, 0.3);
    overlay.shapes.push_back(std::move(shape));
  }
  if (villa.reach)
    for (const ReachFigures::Path& p : villa.reach->paths)
      overlay.paths.push_back({p.level, p.points, Rgb{0.07, 0.36, 0.66}, 1.6});
  // Each functional group (issue 27) in a thin outline: the rectangle, in its hub's frame, around the hub
  // and its members with 10 cm to spare; green when the group holds, red when its check fails.
  std::map<std::string, const scene::SceneObject*> by_id;
  for (const scene::SceneObject& o : villa.scene.objects)
    if (o.pose) by_id[o.id] = &o;
  for (const RoomReport& r : villa.rooms) {
    if (!r.functional) continue;
    for (const GroupCheck& g : r.functional->groups) {
      const auto hub = by_id.find(g.anchor);
      if (hub == by_id.end() || g.members.empty()) continue;
      const scene::Pose& h = *hub->second->pose;
      const Point u{std::cos(h.yaw), std::sin(h.yaw)}, v{-u.y, u.x};
      double x0 = 1e18, x1 = -1e18, y0 = 1e18, y1 = -1e18;
      auto take = [&](const scene::SceneObject& o) {
        for (const Point& corner : FootprintOf(o)) {
          const Point d{corner.x - h.x, corner.y - h.y};
          const double a = d.x * u.x + d.y * u.y, b = d.x * v.x + d.y * v.y;
          x0 = std::min(x0, a), x1 = std::max(x1, a), y0 = std::min(y0, b), y1 = std::max(y1, b);
        }
      };
      take(*hub->second);
      for (const std::string& m : g.members)
        if (const auto it = by_id.find(m); it != by_id.end()) take(*it->second);
      constexpr double kPad = 0.1;
      x0 -= kPad, x1 += kPad, y0 -= kPad, y1 += kPad;
      PlanOverlay::Path outline;
      outline.level = hub->second->level;
      for (const auto& [a, b] : {std::pair{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}, {x0, y0}})
        outline.points.push_back({h.x + a * u.x + b * v.x, h.y + a * u.y + b * v.y});
      outline.color = g.ok() ? Rgb{0.13, 0.55, 0.13} : Rgb{0.80, 0.10, 0.10};
      outline.width_px = 1.2;
      overlay.paths.push_back(std::move(outline));
    }
  }
  return overlay;
}

Result<std::string> FurnishedPlanPng(const FurnishedVilla& villa) {
  PlanRenderOptions options;
  options.source_name = villa.scene.layout.file + " (furnished)";
  return RenderPlanPng(villa.layout, FurnishedPlanOverlay(villa), options);
}

Result<Image> RenderFurnishedPreview(const FurnishedVilla& villa, const PreviewOptions& options) {
  ViewScene view = ViewSceneOf(villa.building);
  // The objects' meshes moved into the world frame; the scene borrows them until the picture is made.
  std::vector<std::unique_ptr<TriangleMesh>> meshes;
  for (const scene::SceneObject& o : villa.scene.objects) {
    if (!o.pose) continue;
    auto asset = villa.library->Mesh(o.asset);
    if (!asset.ok()) return Error{o.id + ": " + asset.error()};
    const double c = std::cos(o.pose->yaw), s = std::sin(o.pose->yaw);
    const bool hung = o.relation == scene::Relation::kOnWall || o.relation == scene::Relation::kHanging;
    for (const AssetMeshPart& part : (*asset)->parts) {
      if (part.mesh.triangles.empty()) continue;
      auto world = std::make_unique<TriangleMesh>(part.mesh);
      for (Vec3& v : world->vertices) {
        const double x = v.x * o.scale[0], y = v.y * o.scale[1];
        v = {o.pose->x + c * x - s * y, o.pose->y + s * x + c * y, o.pose->z + v.z * o.scale[2]};
      }
      ViewMesh mesh;
      mesh.mesh = world.get();
      mesh.color = {part.material.r, part.material.g, part.material.b};
      mesh.alpha = part.material.alpha;
      mesh.level = o.level;
      mesh.cut = hung ? CutAway::kCut : CutAway::kKeep;
      view.meshes.push_back(mesh);
      meshes.push_back(std::move(world));
    }
  }
  return RenderPreview(view, options);
}

Result<std::vector<std::string>> WriteFurnishedVillaFiles(const FurnishedVilla& villa, const fs::path& dir,
                                                          const FurnishOptions& options) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) return Error{dir.string() + ": cannot create the folder: " + ec.message()};
  std::vector<std::string> written;
  auto write = [&](const std::string& name, const std::string& bytes) -> Status {
    if (Status s = WriteFileAtomic(dir / name, bytes); !s) return s;
    written.push_back(name);
    return Status::Ok();
  };
  auto glb = FurnishedGlb(villa);
  if (!glb.ok()) return Error{(dir / kGlbFile).string() + ": " + glb.error()};
  // The report first: it is the one that can fail on the request's text (a JSON dump), before any bytes.
  std::string report;
  try {
    report = FurnishReportJson(villa, options).dump(2) + "\n";
  } catch (const nlohmann::json::exception& e) {
    return Error{"report.json: " + std::string(e.what())};
  }
  if (Status s = write(kSceneFile, scene::SceneToText(villa.scene)); !s) return Error{s.error()};
  if (Status s = write(kGlbFile, *glb); !s) return Error{s.error()};
  if (Status s = write(kCreditsFile, FurnishCredits(villa)); !s) return Error{s.error()};
  if (options.pictures) {
    auto plan = FurnishedPlanPng(villa);
    if (!plan.ok()) return Error{(dir / kPlanPicture).string() + ": " + plan.error()};
    if (Status s = write(kPlanPicture, *plan); !s) return Error{s.error()};
  }
  if (Status s = write(kReportFile, report); !s) return Error{s.error()};
  if (options.pictures) {
    fs::create_directories(dir / "rooms", ec);
    if (ec) return Error{(dir / "rooms").string() + ": cannot create the folder: " + ec.message()};
    for (size_t i = 0; i < villa.contexts.size(); ++i) {
      const std::string name = RoomPictureName(villa.contexts[i].name);
      auto png = RoomPicturePng(villa, villa.contexts[i]);
      if (!png.ok()) return Error{(dir / name).string() + ": " + png.error()};
      if (Status s = write(name, *png); !s) return Error{s.error()};
    }
  }
  return written;
}

namespace {

// The staged folder of a run; "busy: " (another run holds it) becomes a usage error.
Result<std::unique_ptr<StagedOutput>> OpenStage(const fs::path& dir) {
  auto stage = StagedOutput::Open(dir);
  if (!stage.ok() && stage.error().rfind("busy: ", 0) == 0) return Error{"usage: " + stage.error().substr(6)};
  return stage;
}

}  // namespace

Result<std::vector<std::string>> WriteFurnishedVilla(const FurnishedVilla& villa, const fs::path& dir,
                                                     const FurnishOptions& options) {
  auto stage = OpenStage(dir);
  if (!stage.ok()) return Error{stage.error()};
  if (!options.force)
    if (Status refused = RefuseExisting(dir, OutputNames(villa.layout, options.pictures)); !refused) return Error{refused.error()};
  auto written = WriteFurnishedVillaFiles(villa, (*stage)->path(), options);
  if (!written.ok()) return written;
  if (Status s = (*stage)->Commit(*written); !s) return Error{s.error()};
  return written;
}

Result<FurnishSummary> FurnishLayoutFile(const fs::path& layout_path, const fs::path& dir, const FurnishOptions& options) {
  if (std::string problem = options.Check(); !problem.empty()) return Error{"usage: " + problem};
  std::error_code ec;
  if (!fs::exists(layout_path, ec)) return Error{"usage: " + layout_path.string() + ": no such file"};
  // Issue 33: the outputs are staged and moved into place together at the end (the critic's log too: the
  // CLI points it into StagedOutput's folder), under a lock, so a killed or failed run leaves the folder as
  // it was and a second run into it is refused while this one writes.
  auto stage = OpenStage(dir);
  if (!stage.ok()) return Error{stage.error()};
  if (!options.force)
    if (Status refused = RefuseExisting(dir, {kSceneFile, kGlbFile, kReportFile, kCreditsFile, kPlanPicture}); !refused)
      return Error{refused.error()};
  auto layout = LoadLayout(layout_path.string());
  if (!layout.ok()) return Error{layout.error()};
  if (!options.force)
    if (Status refused = RefuseExisting(dir, OutputNames(*layout, options.pictures)); !refused) return Error{refused.error()};
  ValidateOptions vo;
  vo.check_architecture = false;
  ValidationReport report = ValidateLayout(*layout, vo);
  if (!report.geometric_ok() && !options.allow_invalid) {
    std::string why;
    for (const Violation& v : report.violations)
      if (v.rule <= 5) why += "\n  rule " + std::to_string(v.rule) + ": " + v.message;
    return Error{layout_path.string() + ": breaks the geometric rules 1-5; not furnished (--allow-invalid furnishes it anyway)" + why};
  }
  auto digest = scene::FileSha256(layout_path);
  if (!digest.ok()) return Error{digest.error()};
  // The scene names the layout relative to its own folder when it can.
  fs::path absolute_dir = fs::absolute(dir, ec);
  fs::path relative = fs::relative(fs::absolute(layout_path, ec), absolute_dir, ec);
  const std::string layout_file = ec || relative.empty() ? fs::absolute(layout_path, ec).string() : relative.generic_string();

  auto library = scene::OpenFurnishingLibrary(options.library, options.procedural_only);
  if (!library.ok()) return Error{library.error()};
  auto villa = FurnishLayout(*layout, {layout_file, *digest}, library->library, library->file, options);
  if (!villa.ok()) return Error{villa.error()};
  villa->library_note = library->note;
  auto written = WriteFurnishedVillaFiles(*villa, (*stage)->path(), options);
  if (!written.ok()) return Error{written.error()};
  std::vector<std::string> moved = *written;
  if (fs::is_directory((*stage)->path() / kCriticLogFolder, ec)) moved.push_back(kCriticLogFolder);
  if (Status s = (*stage)->Commit(moved); !s) return Error{s.error()};
  FurnishSummary summary = villa->summary;
  summary.written = *written;
  return summary;
}

}  // namespace villa::solver
