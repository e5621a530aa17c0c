#include "solver/solve.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <map>
#include <numbers>
#include <iterator>
#include <set>

#include "mesh/geometry2d.h"
#include "scene/scene.h"
#include "solver/group_rules.h"
#include "solver/layer.h"
#include "solver/place.h"
#include "solver/rng.h"
#include "solver/state.h"
#include "layout/geometry.h"

namespace villa::solver {
namespace {

using Clock = std::chrono::steady_clock;
constexpr double kFeasible = 1e-10;  // hard cost below this: no proxy violation
// Issue 27: a start whose hard cost is at most this (overlaps of a few centimetres, an optional piece in a
// sweep) is one the rule agent repairs; among such starts the one with fewer broken group rules is kept.
constexpr double kRepairable = 0.5;
constexpr double kHairline = 1e-2;   // hard cost of a proxy a few millimetres into its margin
constexpr std::string_view kOutcomeNames[] = {"converged", "budget", "infeasible"};

double Since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

std::string Fixed(double v, int digits = 4) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, v);
  return buffer;
}

// Hard violations the exact check found (each failing object once per test).
int Violations(const ExactMetrics& m) {
  return m.colliding + m.floating + m.out_of_bounds + (m.inside_edges - m.contained);
}

// Which state is better: fewer exact violations, then no proxy overlap or support error, then lower E,
// then more objects kept.
bool Better(const ExactMetrics& m, const EnergyTerms& e, const ExactMetrics& best_m, const EnergyTerms& best_e) {
  const int v = Violations(m), bv = Violations(best_m);
  if (v != bv) return v < bv;
  const bool hard = e.collision + e.support > 0.0, best_hard = best_e.collision + best_e.support > 0.0;
  if (hard != best_hard) return !hard;
  if (std::abs(e.total - best_e.total) > 1e-9) return e.total < best_e.total;
  return m.objects > best_m.objects;
}

double Volume(const ProblemObject& o, double scale) {
  return o.asset.size.x * o.asset.size.y * std::max(o.asset.size.z, 0.01) * scale * scale * scale;
}

}  // namespace

std::string_view OutcomeName(Outcome outcome) { return kOutcomeNames[static_cast<int>(outcome)]; }

bool SolveOptions::IsValid(std::string* message) const {
  auto fail = [&](const std::string& m) {
    if (message) *message = m;
    return false;
  };
  auto in = [](double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; };
  if (restarts < 1 || restarts > 16) return fail("restarts must be in [1, 16], is " + std::to_string(restarts));
  if (agent_iterations < 0 || agent_iterations > 200) return fail("agent_iterations must be in [0, 200], is " + std::to_string(agent_iterations));
  if (!in(energy_threshold, 0.0, 1e6)) return fail("energy_threshold must be >= 0");
  if (!in(object_gap, 0.0, 0.2)) return fail("object_gap must be in [0, 0.2] m");
  if (!in(child_gap, 0.0, 0.05)) return fail("child_gap must be in [0, 0.05] m");
  if (!in(bounds_margin, 0.0, 0.1)) return fail("bounds_margin must be in [0, 0.1] m");
  if (!in(max_yaw_offset, 0.0, std::numbers::pi / 4)) return fail("max_yaw_offset must be in [0, pi/4] rad");
  if (!in(pair_slack, 0.0, 100.0)) return fail("pair_slack must be in [0, 100] m");
  if (ceres_max_iterations < 1 || ceres_max_iterations > 1000) return fail("ceres_max_iterations must be in [1, 1000]");
  if (sparse_from_objects < 1 || sparse_from_objects > 100000) return fail("sparse_from_objects must be in [1, 100000]");
  for (double w : {weight_collision, weight_bounds, weight_keep_out, weight_containment, weight_zone, weight_semantic}) {
    if (!in(w, 1e-9, 1000.0)) return fail("every weight must be in (0, 1000]");
  }
  return true;
}

struct RoomSolver::Impl {
  RoomProblem problem;  // the solver's own copy: AddKeepOut extends it
  SolveOptions options;
  ExactCheckOptions check_options;
  RoomState state;
  std::unique_ptr<ExactChecker> checker;
  SolveSummary summary;
  ExactMetrics metrics;
  EnergyTerms energy;
  RoomState best;
  ExactMetrics best_metrics;
  EnergyTerms best_energy;
  bool have_best = false;
  std::map<std::string, int> tries;   // hard-trouble actions taken per object
  std::deque<Action> queued;           // removals still to make for a protected object (MakeWayAction)
  bool strict_groups = false;          // GroupFitsAt asks each member to keep its group's rules (TidyGroups)
  bool coffee_planned = false, tv_planned = false;  // the plan gives the room a coffee table, a TV stand (GroupTrouble)
  std::set<std::string> semantic_tried;
  Clock::time_point start;
  bool initialised = false;

  Impl(const RoomProblem& p, const SolveOptions& o, const ExactCheckOptions& c) : problem(p), options(o), check_options(c) {}

  // ---- the first solve, layer by layer

  void Account(const PolishStats& stats) {
    summary.ceres_solves += stats.solves;
    summary.ceres_iterations += stats.iterations;
    summary.seconds_ceres += stats.seconds;
    summary.sparse |= stats.sparse;
  }

  void PolishInto(Layer& layer) {
    Account(Polish(layer, state, options));
    WriteLayer(layer);
  }

  // Places the layer's movable bodies one by one (constructive start), then polishes them with Ceres.
  LayerCost Construct(Layer& layer, Rng& rng, double jitter) {
    const auto t = Clock::now();
    PlaceStats stats;
    PlaceLayer(layer, state, options, rng, jitter, &stats);
    summary.candidates += stats.candidates;
    summary.seconds_place += Since(t);
    // Issue 27: functional groups stand as their templates put them; the polish moves the rest around them
    // (polished body by body, a member drifts off its group: a coffee table turned off its sofa's axis).
    std::vector<Motion> motions;
    if (options.functional_groups && layer.kind == Layer::Kind::kRoom) {
      for (Body& b : layer.bodies) {
        motions.push_back(b.motion);
        const Membership m = GroupMembership(state, b.object);
        const bool hub = m.role == GroupRole::kNone && !MembersOf(b.object).empty();
        if (b.active && (m.role != GroupRole::kNone || hub) &&
            Evaluate(MakeTerms(layer, state, options, static_cast<int>(&b - layer.bodies.data()), -1.0)).hard <= kFeasible)
          b.motion = Motion::kFixed;
      }
    }
    const PolishStats polish = Polish(layer, state, options);
    for (size_t k = 0; k < motions.size(); ++k) layer.bodies[k].motion = motions[k];
    Account(polish);
    return polish.cost;
  }

  void WriteLayer(const Layer& layer) {
    for (size_t b = 0; b < layer.bodies.size(); ++b) {
      if (layer.bodies[b].motion != Motion::kFixed && layer.bodies[b].active) WriteBack(layer, static_cast<int>(b), state);
    }
  }

  void SolveLayers() {
    AssignSupports(state);
    std::vector<int> floor, hung;
    for (size_t i = 0; i < state.objects.size(); ++i) {
      if (state.parent[i] >= 0) continue;
      state.placements[i].pose.z = problem.floor_z;
      (state.Hung(static_cast<int>(i)) ? hung : floor).push_back(static_cast<int>(i));
    }
    // Floor layer: restarts while the best start still breaks a hard term, or (issue 27) a group's rule (a
    // sofa turned from its TV, a chair with no room behind it). Of two starts whose overlaps the agent can
    // clear (kRepairable), the one with fewer broken group rules wins: a start whose side tables overlap a
    // little but whose sofa faces the TV beats one that overlaps less with the TV on a side wall.
    std::optional<Layer> best_layer;
    LayerCost best_cost{1e300, 1e300};
    int best_trouble = 0;
    for (int r = 0; r < options.restarts; ++r) {
      Layer layer = RoomLayer(state, floor, {});
      Rng rng(options.seed * kSplitMix64Gamma + static_cast<uint64_t>(r) + 1);
      LayerCost cost = Construct(layer, rng, r == 0 ? 0.0 : 0.3);
      cost.hard = HardWithoutDroppable(layer, cost.hard);
      int trouble = 0;
      if (options.functional_groups) {
        const auto before = state.placements;
        WriteLayer(layer);
        trouble = GroupTrouble(true);
        state.placements = before;
      }
      const bool repairable = cost.hard <= kRepairable && best_cost.hard <= kRepairable;
      const bool better = repairable && trouble != best_trouble
                              ? trouble < best_trouble
                              : cost.hard < best_cost.hard - kFeasible ||
                                    (std::abs(cost.hard - best_cost.hard) <= kFeasible && cost.soft < best_cost.soft);
      if (better) {
        best_cost = cost;
        best_trouble = trouble;
        best_layer = std::move(layer);
      }
      if (best_cost.hard <= kFeasible && best_trouble == 0) break;
    }
    if (best_layer) WriteLayer(*best_layer);
    if (options.functional_groups) Regroup();
    // Walls and ceiling, the floor fixed.
    if (!hung.empty()) {
      Layer layer = RoomLayer(state, hung, floor);
      Rng rng(options.seed ^ 0xC0FFEEull);
      Construct(layer, rng, 0.0);
      WriteLayer(layer);
    }
    // Surfaces and cavities, parents before children.
    std::vector<int> parents;
    for (size_t i = 0; i < state.objects.size(); ++i) {
      if (state.parent[i] < 0 && !state.children[i].empty()) parents.push_back(static_cast<int>(i));
    }
    for (size_t k = 0; k < parents.size(); ++k) {
      const int p = parents[k];
      std::map<std::pair<int, int>, std::vector<int>> groups;  // (kind, index) -> children
      for (int c : state.children[p]) {
        const bool inside = state.objects[c].relation == Relation::kInside;
        groups[{inside ? 1 : 0, inside ? state.placements[c].cavity : state.placements[c].surface}].push_back(c);
        if (!state.children[c].empty()) parents.push_back(c);
      }
      for (const auto& [key, members] : groups) {
        Layer layer = ChildLayer(state, p, key.first ? Layer::Kind::kCavity : Layer::Kind::kSurface, key.second, members);
        for (Body& b : layer.bodies) {
          if (b.motion != Motion::kFixed) b.active = false;
        }
        Rng rng(options.seed ^ (0xB00Cull + static_cast<uint64_t>(p) * 131 + key.second));
        Construct(layer, rng, 0.0);
        WriteLayer(layer);
      }
    }
  }

  // A start's hard cost as the agent will be able to repair it: without the side tables and decorative
  // pieces that are deep in trouble (the agent takes them out when they are not asked for). A side table
  // with no room at its sofa's end, left on the sofa, made the start whose sofa faced the TV lose to one
  // whose TV was turned 53 degrees from it. (Armchairs too would be taken out, but on the living-room
  // bench that lost as many sofas to the walkways as it saved.)
  double HardWithoutDroppable(const Layer& layer, double hard) const {
    Layer copy = layer;
    bool dropped = false;
    for (size_t b = 0; b < copy.bodies.size(); ++b) {
      Body& body = copy.bodies[b];
      if (!body.active || body.motion == Motion::kFixed || !Droppable(body.object)) continue;
      if (Evaluate(MakeTerms(copy, state, options, static_cast<int>(b), -1.0)).hard <= kRepairable) continue;
      body.active = false;
      dropped = true;
    }
    return dropped ? Evaluate(MakeTerms(copy, state, options, -1, -1.0)).hard : hard;
  }
  bool Droppable(int i) const {
    const ProblemObject& o = state.objects[i];
    return !IsProtected(o.priority) && (o.priority == Priority::kDecorative || GroupMembership(state, i).role == GroupRole::kSideTable);
  }

  // Issue 27: a polish moves every body on its own, and can draw a member out of its group (a coffee table
  // turned and pulled off its sofa's axis by its other terms): such a member takes its best template pose
  // again where one is free.
  void Regroup() {
    for (size_t k = 0; k < state.objects.size(); ++k) {
      const int j = static_cast<int>(k);
      if (state.parent[j] >= 0 || GroupProblem(j).empty()) continue;
      if (auto slot = FindSlot(j)) MoveWithGroup(j, slot->pose, slot->wall);
    }
  }

  // Object j to a free slot, its own members (if it is a hub too) carried along.
  void MoveWithGroup(int j, const Pose& pose, int wall) {
    const Pose from = state.placements[j].pose;
    state.placements[j].wall = wall;
    state.SetPose(j, pose);
    if (options.functional_groups)
      if (const std::vector<int> members = MembersOf(j); !members.empty()) Carry(members, from, state.placements[j].pose);
  }

  // Places a surface's or cavity's children again from scratch (after a removal freed room there); the
  // new arrangement replaces the old only when it breaks fewer hard terms.
  void Resettle(int parent, bool inside, int group) {
    std::vector<int> members;
    for (int c : state.children[parent]) {
      const bool c_inside = state.objects[c].relation == Relation::kInside;
      if (c_inside == inside && (inside ? state.placements[c].cavity : state.placements[c].surface) == group) members.push_back(c);
    }
    if (members.empty()) return;
    const Layer::Kind kind = inside ? Layer::Kind::kCavity : Layer::Kind::kSurface;
    Layer current = ChildLayer(state, parent, kind, group, members);
    const LayerCost before = Evaluate(MakeTerms(current, state, options, -1, -1.0));
    Layer fresh = ChildLayer(state, parent, kind, group, members);
    for (Body& b : fresh.bodies) {
      if (b.motion != Motion::kFixed) b.active = false;
    }
    Rng rng(options.seed ^ (0xB00Cull + static_cast<uint64_t>(parent) * 131 + group));
    const LayerCost after = Construct(fresh, rng, 0.0);
    if (after.hard < before.hard - kFeasible || (after.hard <= kFeasible && before.hard <= kFeasible && after.soft_linear < before.soft_linear)) {
      WriteLayer(fresh);
    }
  }

  // ---- checks and the best state

  void Check() {
    const auto t = Clock::now();
    metrics = checker->Check(state, false);
    summary.seconds_exact += Since(t);
    energy = StateEnergy(state);
    summary.energy_trace.push_back(energy.total);
    std::string line = "check " + std::to_string(summary.log.size()) + ": E " + Fixed(energy.total) + ", " +
                       std::to_string(metrics.objects) + " objects";
    for (const CollisionPair& pair : metrics.pairs) line += "; collision " + pair.a + " x " + pair.b;
    for (const ObjectCheck& c : metrics.per_object) {
      if (c.floating) line += "; floating " + c.id;
      if (c.out_of_bounds) line += "; out of bounds " + c.id + " (" + Fixed(100.0 * c.in_bound_share, 1) + " % in)";
      if (c.inside_edge && !c.contained) line += "; not contained " + c.id;
    }
    for (const auto& [a, b] : energy.overlaps) line += "; boxes overlap " + a + " x " + b;
    summary.log.push_back(line);
    if (!have_best || Better(metrics, energy, best_metrics, best_energy)) {
      best = state;
      best_metrics = metrics;
      best_energy = energy;
      have_best = true;
    }
  }

  bool Converged(const ExactMetrics& m, const EnergyTerms& e) const {
    return m.Clean() && e.collision == 0.0 && e.support == 0.0 && e.total <= options.energy_threshold;
  }

  // ---- one object in its own layer, everything else fixed

  // Object i's layer with everything else fixed (`without`: objects left out of it, a hub's members that
  // move with it).
  Layer LayerFor(int i, const std::vector<int>& without = {}) const {
    const int p = state.parent[i];
    if (p < 0) {
      std::vector<int> others;
      for (size_t k = 0; k < state.objects.size(); ++k) {
        if (static_cast<int>(k) != i && state.parent[k] < 0 && state.placements[k].placed &&
            std::find(without.begin(), without.end(), static_cast<int>(k)) == without.end())
          others.push_back(static_cast<int>(k));
      }
      return RoomLayer(state, {i}, others);
    }
    const bool inside = state.objects[i].relation == Relation::kInside;
    return ChildLayer(state, p, inside ? Layer::Kind::kCavity : Layer::Kind::kSurface,
                      inside ? state.placements[i].cavity : state.placements[i].surface, {i});
  }

  // A child taller than the room above its surface (the shelf above) cannot stand there.
  bool TooTall(const Layer& layer, int i) const {
    return layer.kind == Layer::Kind::kSurface &&
           state.objects[i].asset.size.z * state.placements[i].pose.scale > layer.clear_height + 1e-9;
  }

  LayerCost CostAt(int i) {
    Layer layer = LayerFor(i);
    LayerCost cost = Evaluate(MakeTerms(layer, state, options, 0, -1.0));
    if (TooTall(layer, i)) cost.hard += 1.0;
    return cost;
  }

  struct Slot {
    Pose pose;
    int surface = -1, cavity = -1, wall = -1;
    LayerCost cost;
  };

  // The best free pose for object i with everything else where it is: a fresh candidate search in its
  // layer (for a child, on each surface or cavity it may use), polished. nullopt: none without a hard
  // violation.
  std::optional<Slot> FindSlot(int i) {
    const ObjectPlacement saved = state.placements[i];
    std::vector<int> groups = {-2};  // -2: its current choice
    const int p = state.parent[i];
    const ProblemObject& o = state.objects[i];
    if (p >= 0 && o.relation == Relation::kOnTop && o.surface < 0) {
      // Tops and open shelves; the floor of a closed cell (behind a door or drawer front) is for what goes
      // inside, not 'ontop'.
      for (size_t k = 0; k < state.objects[p].asset.support_surfaces.size(); ++k)
        if (!state.objects[p].asset.ClosedCellFloor(static_cast<int>(k))) groups.push_back(static_cast<int>(k));
    }
    if (p >= 0 && o.relation == Relation::kInside && o.cavity < 0) {
      for (size_t k = 0; k < state.objects[p].asset.cavities.size(); ++k) groups.push_back(static_cast<int>(k));
    }
    std::optional<Slot> best;
    for (int g : groups) {
      state.placements[i] = saved;
      if (g >= 0) {
        if (g == (o.relation == Relation::kInside ? saved.cavity : saved.surface)) continue;
        (o.relation == Relation::kInside ? state.placements[i].cavity : state.placements[i].surface) = g;
        state.placements[i].pose.z = state.SupportHeight(i);
      }
      // A hub's members move with it (issue 27): they are no obstacles to its new slot, and a slot where one
      // of them finds no place by it is passed over while another has room for the whole group.
      const std::vector<int> members = p < 0 && options.functional_groups ? MembersOf(i) : std::vector<int>{};
      bool found = false;  // in this surface or cavity (the others are tried too: the best of all wins)
      for (int pass = members.empty() ? 1 : 0; pass < 2 && !found; ++pass) {
        Layer layer = LayerFor(i, members);
        layer.walkways_bind_all = true;  // a slot out of the reachability feedback's way, for everything
        if (TooTall(layer, i)) continue;
        // Its best candidate polished; when the polish does not end clean (a hair of overlap left), the next
        // best, up to four (twelve for a hub whose group must come along).
        Rng rng(options.seed ^ (0x5107ull + i));
        const auto t = Clock::now();
        PlaceStats stats;
        double polishing = 0.0;  // s of the above spent polishing (Account counts it as polish time)
        // (Four times as many for a table the tidy stage moves to seat its chairs roomily: few of a small
        // room's poses have 0.75 m behind every chair.)
        const size_t tries = pass == 0 ? (strict_groups && TableHub(i) ? 48 : 12) : 4;
        PlaceBodyAmong(layer, 0, state, options, rng, tries, &stats, [&] {
          const auto p = Clock::now();
          const std::vector<Body> unpolished = layer.bodies;
          PolishStats polish = Polish(layer, state, options);
          // A clean candidate the polish left a hair inside a margin (pulled towards the wall's middle):
          // the candidate as it was.
          if (polish.cost.hard > kFeasible) {
            std::vector<Body> polished = std::move(layer.bodies);
            layer.bodies = unpolished;
            const LayerCost start = Evaluate(MakeTerms(layer, state, options, -1, -1.0));
            if (start.hard <= kFeasible) polish.cost = start;
            else layer.bodies = std::move(polished);
          }
          polishing += Since(p);
          Account(polish);
          if (polish.cost.hard > kFeasible) return false;
          RoomState probe = state;
          WriteBack(layer, 0, probe);
          const ObjectPlacement& at = probe.placements[i];
          if (pass == 0 && !GroupFitsAt(i, members, at)) return false;
          const Slot slot{at.pose, at.surface, at.cavity, at.wall, polish.cost};
          if (!best || slot.cost.soft_linear < best->cost.soft_linear - 1e-12) best = slot;
          found = true;
          return true;
        });
        summary.candidates += stats.candidates;
        summary.seconds_place += Since(t) - polishing;
      }
    }
    state.placements[i] = saved;
    return best;
  }

  // The pose an object may take near `want`: z from its support, against_wall and on_wall objects put on
  // a wall (the one asked for, else the nearest) with their back at the gap and facing the room.
  // `own_wall`: the placement's wall is the one asked for (an action's or a slot's), not the nearest.
  Pose Snap(int i, Pose want, bool own_wall = false) {
    const ProblemObject& o = state.objects[i];
    ObjectPlacement& pl = state.placements[i];
    const double s = want.scale;
    if (o.relation == Relation::kAgainstWall || o.relation == Relation::kOnWall) {
      int w = pl.wall;
      if (w < 0 || (o.wall < 0 && !own_wall)) {
        double best = 1e300;
        for (size_t k = 0; k < problem.walls.size(); ++k) {
          if (o.wall >= 0 && static_cast<int>(k) != o.wall) continue;
          const double d = PointSegmentDistance({want.x, want.y}, {problem.walls[k].a, problem.walls[k].b});
          if (d < best - 1e-12) {
            best = d;
            w = static_cast<int>(k);
          }
        }
      }
      if (w >= 0) {
        const WallEdge& wall = problem.walls[w];
        const Point d = geo::Unit(geo::Sub(wall.b, wall.a)), n = geo::Left(d);
        const double t = geo::Dot(geo::Sub({want.x, want.y}, wall.a), d);
        const Point c = geo::Add(geo::Add(wall.a, geo::Scale(d, t)), geo::Scale(n, o.wall_gap + 0.5 * o.asset.size.y * s));
        want.x = c.x;
        want.y = c.y;
        want.yaw = std::atan2(n.x, -n.y);
        pl.wall = w;
      }
    }
    if (o.relation == Relation::kHanging) {
      want.z = problem.floor_z + problem.clear_height - o.asset.size.z * s;
    } else if (o.relation == Relation::kOnWall) {
      if (std::isnan(want.z)) want.z = pl.pose.z;
    } else {
      want.z = state.SupportHeight(i);
    }
    want.yaw = WrapAngle(want.yaw);
    return want;
  }

  // After an action moved or resized object i: nothing to do when it is free; else polish it where it is,
  // else find it another free slot. False (and the state untouched by this call) when neither works.
  bool Repair(int i, std::string* how) {
    if (CostAt(i).hard <= kFeasible) return true;
    const Pose before = state.placements[i].pose;
    Layer layer = LayerFor(i);
    if (!TooTall(layer, i)) {
      PolishInto(layer);
      if (CostAt(i).hard <= kFeasible) {
        const Pose& after = state.placements[i].pose;
        *how = "moved " + Fixed(std::hypot(after.x - before.x, after.y - before.y), 3) + " m to the nearest free pose";
        return true;
      }
    }
    state.SetPose(i, before);
    if (auto slot = FindSlot(i)) {
      ObjectPlacement& pl = state.placements[i];
      pl.surface = slot->surface;
      pl.cavity = slot->cavity;
      pl.wall = slot->wall;
      state.SetPose(i, slot->pose);
      *how = "moved to another free slot";
      return true;
    }
    return false;
  }

  // ---- the four actions

  ActionResult Refuse(ActionResult r, const std::string& why) {
    r.status = ActionStatus::kRefused;
    r.message = why;
    return r;
  }

  ActionResult Apply(const Action& action) {
    ActionResult r;
    r.action = action;
    if (action.kind == ActionKind::kAddEntity) return AddEntity(action, r);
    const int i = state.Find(action.id);
    if (i < 0) return Refuse(r, "no object \"" + action.id + "\" in the room");
    if (action.kind == ActionKind::kRemoveEntity) {
      const int p = state.parent[i];
      const std::string parent_id = p >= 0 ? state.objects[p].id : "";
      const bool inside = state.objects[i].relation == Relation::kInside;
      const int group = inside ? state.placements[i].cavity : state.placements[i].surface;
      // A desk's chair goes with its desk (it was protected for the desk's sake; alone it would push the
      // room's other pieces out for nothing).
      std::vector<std::string> seats;  // the partners removed with it
      if (options.functional_groups)
        for (size_t k = 0; k < state.objects.size(); ++k) {
          const Membership m = GroupMembership(state, static_cast<int>(k));
          if (m.role == GroupRole::kDeskSeat && m.hub == i && state.objects[k].priority != Priority::kEssential)
            seats.push_back(state.objects[k].id);
        }
      // And a desk goes with its own chair when the chair finds no place (a desk without its chair is a
      // broken group: the optional pair is dropped whole), unless the desk is protected (essential, named).
      if (options.functional_groups) {
        const Membership m = GroupMembership(state, i);
        if (m.role == GroupRole::kDeskSeat && m.hub >= 0 && !IsProtected(state.objects[m.hub].priority))
          seats.push_back(state.objects[m.hub].id);
      }
      r.removed = state.Remove(i);
      for (const std::string& seat : seats)
        if (const int k = state.Find(seat); k >= 0)
          for (std::string& gone : state.Remove(k)) r.removed.push_back(std::move(gone));
      summary.removed.insert(summary.removed.end(), r.removed.begin(), r.removed.end());
      r.status = ActionStatus::kApplied;
      r.message = "removed " + std::to_string(r.removed.size()) + " object(s)";
      // The room freed may let the neighbours settle: re-pack the surface or cavity, or polish the room.
      if (p >= 0) {
        Resettle(state.Find(parent_id), inside, group);
      } else {
        std::vector<int> room_level;
        for (size_t k = 0; k < state.objects.size(); ++k) {
          if (state.parent[k] < 0) room_level.push_back(static_cast<int>(k));
        }
        Layer layer = RoomLayer(state, room_level, {});
        // Undone when it ends in harder trouble than it started (a walkway's push can leave a chair in its
        // desk where the room is tight).
        // Nor may it pull a group apart (the dining table turned off its chairs): issue 27.
        const double hard_before = Evaluate(MakeTerms(layer, state, options, -1, -1.0)).hard;
        const int trouble_before = options.functional_groups ? GroupTrouble() : 0;
        const PolishStats polish = Polish(layer, state, options);  // the state changes only by WriteLayer
        Account(polish);
        if (polish.cost.hard <= hard_before + kFeasible) {
          const RoomState unpolished = state;
          WriteLayer(layer);
          if (options.functional_groups && GroupTrouble() > trouble_before) state = unpolished;
        }
      }
      return r;
    }
    const RoomState saved = state;
    const ProblemObject& o = state.objects[i];
    Pose want = state.placements[i].pose;
    if (action.kind == ActionKind::kUpdateScale) {
      if (!action.scale) return Refuse(r, "update_scale needs a scale");
      if (*action.scale < o.scale_min - 1e-9 || *action.scale > o.scale_max + 1e-9) {
        return Refuse(r, "scale " + Fixed(*action.scale, 3) + " is outside the object's range [" + Fixed(o.scale_min, 3) +
                             ", " + Fixed(o.scale_max, 3) + "]");
      }
      want.scale = *action.scale;
    } else {
      if (!action.pose) return Refuse(r, "update_pose needs a pose");
      want.x = action.pose->x;
      want.y = action.pose->y;
      want.yaw = action.pose->yaw;
      if (!std::isnan(action.pose->z)) want.z = action.pose->z;
      if (action.scale) {  // moved and resized at once (a slot that holds it only smaller)
        if (*action.scale < o.scale_min - 1e-9 || *action.scale > o.scale_max + 1e-9)
          return Refuse(r, "scale " + Fixed(*action.scale, 3) + " is outside the object's range [" + Fixed(o.scale_min, 3) + ", " +
                               Fixed(o.scale_max, 3) + "]");
        want.scale = *action.scale;
      }
      ObjectPlacement& pl = state.placements[i];
      const int p = state.parent[i];
      if (action.surface) {
        if (p < 0 || *action.surface < 0 || *action.surface >= static_cast<int>(state.objects[p].asset.support_surfaces.size()))
          return Refuse(r, "surface " + std::to_string(*action.surface) + " does not exist on the parent");
        pl.surface = *action.surface;
      }
      if (action.cavity) {
        if (p < 0 || *action.cavity < 0 || *action.cavity >= static_cast<int>(state.objects[p].asset.cavities.size()))
          return Refuse(r, "cavity " + std::to_string(*action.cavity) + " does not exist on the parent");
        pl.cavity = *action.cavity;
      }
      if (action.wall) {
        if (*action.wall < 0 || *action.wall >= static_cast<int>(problem.walls.size()))
          return Refuse(r, "wall " + std::to_string(*action.wall) + " does not exist");
        pl.wall = *action.wall;
      }
    }
    // A hub carries its group's members (issue 27): the chairs go with their table, the nightstands with
    // their bed; a member that lands in trouble is seated again from its template.
    const std::vector<int> members = options.functional_groups ? MembersOf(i) : std::vector<int>{};
    std::set<std::string> troubled;  // members in hard trouble already: theirs to mend, no reason to refuse
    for (int j : members)
      if (CostAt(j).hard > kFeasible) troubled.insert(state.objects[j].id);
    const bool in_group = options.functional_groups && GroupProblem(i).empty();
    // A move for the semantics (the critic's, the agent's for unmet relations) never leaves the room's
    // groups worse: the sofa turned along an angled wall away from its TV is no fix.
    const bool semantic = options.functional_groups && (action.reason.rfind("critic:", 0) == 0 ||
                                                         action.reason.rfind("relations or interaction zones unmet", 0) == 0);
    const int trouble_before = semantic ? GroupTrouble(true) : 0;
    const Pose from = state.placements[i].pose;
    state.SetPose(i, Snap(i, want, action.wall.has_value()));
    if (!members.empty()) Carry(members, from, state.placements[i].pose);
    std::string how;
    const Pose snapped = state.placements[i].pose;
    if (!Repair(i, &how)) {
      state = saved;
      return Refuse(r, "no free pose for \"" + action.id + "\" there or elsewhere: it would collide or leave its support");
    }
    std::vector<std::string> dropped;
    if (!members.empty()) {
      Carry(members, snapped, state.placements[i].pose);
      // The group moves as a unit: a member with no free pose at its hub's new place is dropped when it is
      // optional and the agent or the reachability feedback moves the hub (to mend a hard violation or clear
      // a way); a protected one, or any for a critic's move (semantics never cost a member), keeps the hub
      // where it was.
      const bool critic = action.reason.rfind("critic:", 0) == 0;
      std::vector<std::string> stuck;
      for (int j : Reseat(members)) {
        if (troubled.count(state.objects[j].id)) continue;
        if (critic || IsProtected(state.objects[j].priority)) {
          state = saved;
          return Refuse(r, "\"" + action.id + "\" cannot take its group along there: " + state.objects[j].id +
                               " finds no free place by it");
        }
        stuck.push_back(state.objects[j].id);
      }
      for (const std::string& id : stuck)
        if (const int j = state.Find(id); j >= 0) {
          const std::vector<std::string> gone = state.Remove(j);
          dropped.insert(dropped.end(), gone.begin(), gone.end());
        }
    }
    // A member stays in its group: a move that would carry it out of its group's rules is refused (one
    // already out of them may move, towards them or not).
    // (Its index again: dropping members renumbers the objects.)
    if (const std::string why = in_group ? GroupProblem(state.Find(action.id)) : ""; !why.empty()) {
      state = saved;
      return Refuse(r, "\"" + action.id + "\" would leave its group: " + why);
    }
    if (semantic) {
      if (const int after = GroupTrouble(true); after > trouble_before) {
        state = saved;
        return Refuse(r, "moving \"" + action.id + "\" would put " + std::to_string(after - trouble_before) +
                             " more member(s) of the room's groups out of their places");
      }
    }
    r.status = how.empty() ? ActionStatus::kApplied : ActionStatus::kRepaired;
    r.message = how.empty() ? "done" : how;
    if (!dropped.empty()) {
      r.removed = dropped;
      summary.removed.insert(summary.removed.end(), dropped.begin(), dropped.end());
      r.message += "; its group came along, " + std::to_string(dropped.size()) + " optional object(s) with no place by it left out";
    }
    const int at = state.Find(action.id);
    r.final_pose = state.placements[at].pose;
    return r;
  }

  // ---- functional groups (issue 27; the rules of solver/group_rules.h, the templates of place.h)

  // What is wrong with member i's place in its group ("" when it holds, or when i is no member).
  std::string GroupProblem(int i) const {
    const Membership m = GroupMembership(state, i);
    if (m.role == GroupRole::kNone) return "";
    const OrientedBox self = state.WorldBox(i), hub = state.WorldBox(m.hub);
    switch (m.role) {
      case GroupRole::kTableSeat: return TableSeatProblem(self, hub);
      case GroupRole::kDeskSeat: return DeskSeatProblem(self, hub);
      case GroupRole::kBedside: return BedsideProblem(self, hub);
      case GroupRole::kCoffeeTable: return CoffeeTableProblem(self, hub);
      case GroupRole::kSideTable: return SideTableProblem(self, hub);
      case GroupRole::kArmchair: return ArmchairProblem(self, hub.c);
      case GroupRole::kTvStand: {  // the TV on it where there is one (what the functional check measures)
        OrientedBox tv = self;
        for (int c : state.children[i])
          if (state.objects[c].category == "tv") {
            tv = state.WorldBox(c);
            break;
          }
        return TvProblem(hub, tv);
      }
      case GroupRole::kNone: break;
    }
    return "";
  }

  // Place settings follow the chairs (issue 27): a dining or meeting table keeps as many plates, glasses,
  // laptops and cups of each kind as it has chairs; the surplus, farthest from any chair first, is left out
  // (the planner laid one per seat it planned, and chairs that could not be pulled out have gone).
  bool DropUnseatedSettings() {
    std::vector<std::string> surplus;
    for (size_t t = 0; t < state.objects.size(); ++t) {
      const std::string& table = state.objects[t].category;
      if (table != "dining-table" && table != "conference-table") continue;
      std::vector<Point> chairs;
      for (size_t k = 0; k < state.objects.size(); ++k) {
        const Membership m = GroupMembership(state, static_cast<int>(k));
        if (m.role == GroupRole::kTableSeat && m.hub == static_cast<int>(t)) chairs.push_back(state.WorldBox(static_cast<int>(k)).c);
      }
      for (std::string_view kind : {"plate", "glass", "laptop", "cup"}) {
        std::vector<std::pair<double, std::string>> settings;  // distance to the nearest chair, id
        for (int c : state.children[t]) {
          if (state.objects[c].category != kind || IsProtected(state.objects[c].priority)) continue;
          double nearest = 1e9;
          for (Point p : chairs) nearest = std::min(nearest, geo::Dist(p, state.WorldBox(c).c));
          settings.push_back({nearest, state.objects[c].id});
        }
        if (settings.size() <= chairs.size()) continue;
        std::sort(settings.begin(), settings.end());
        for (size_t k = chairs.size(); k < settings.size(); ++k) surplus.push_back(settings[k].second);
      }
    }
    for (const std::string& id : surplus) TakeRemoval(id, "a place setting with no chair at its table: left out");
    return !surplus.empty();
  }

  // A dining or meeting room whose table has no place keeps none of its chairs (issue 27: no chair stands
  // farther than 1.5 m from a table): a chair is there to sit at the table, and the room is reported without
  // its table (the functional check's essentials say so).
  bool TablelessRoom() const {
    const std::string& room = state.problem->room;
    if (!room.starts_with("dining-room_") && !room.starts_with("meeting-room_")) return false;
    return std::none_of(state.objects.begin(), state.objects.end(),
                        [](const ProblemObject& o) { return o.category == "dining-table" || o.category == "conference-table"; });
  }
  static bool IsChair(const ProblemObject& o) { return o.category == "chair" || o.category == "office-chair"; }
  bool DropTablelessChairs() {
    if (!TablelessRoom()) return false;
    std::vector<std::string> chairs;
    for (const ProblemObject& o : state.objects)
      if (IsChair(o)) chairs.push_back(o.id);
    for (const std::string& id : chairs) TakeRemoval(id, "its table has no place in the room: left out with it");
    return !chairs.empty();
  }

  // How many of the room's group members break their group's rules now; with `seats`, a dining or meeting
  // chair without its 0.75 m behind it counts too (a table moved for a relation must not cram its chairs).
  // A side table's trouble weighs 1, the rest 3 (a sofa turned from its TV is worse than a side table
  // astray).
  int GroupTrouble(bool seats = false) const {
    int n = 0;
    std::set<int> with_coffee, with_tv;  // sofas that have them
    for (size_t k = 0; k < state.objects.size(); ++k) {
      const int kk = static_cast<int>(k);
      const Membership m = GroupMembership(state, kk);
      const int weight = m.role == GroupRole::kSideTable ? 1 : 3;
      n += weight * (!GroupProblem(kk).empty() || (seats && TableSeat(kk) && SeatBehind(kk) < kSeatBehind - 1e-9));
      if (m.role == GroupRole::kCoffeeTable) with_coffee.insert(m.hub);
      if (m.role == GroupRole::kTvStand) with_tv.insert(m.hub);
    }
    // A sofa without the coffee table or the TV stand its plan gave it breaks its group's rule too: putting
    // one back is never more trouble than its absence (an armchair it brings back into the group with it).
    for (size_t k = 0; k < state.objects.size(); ++k)
      if (state.objects[k].category == "sofa" && state.parent[k] < 0)
        n += 3 * ((coffee_planned && !with_coffee.count(static_cast<int>(k))) + (tv_planned && !with_tv.count(static_cast<int>(k))));
    return n;
  }

  // The members of hub i's group (objects whose GroupMembership names it).
  std::vector<int> MembersOf(int i) const {
    std::vector<int> out;
    for (size_t k = 0; k < state.objects.size(); ++k)
      if (state.parent[k] < 0 && static_cast<int>(k) != i && GroupMembership(state, static_cast<int>(k)).hub == i)
        out.push_back(static_cast<int>(k));
    return out;
  }

  // Moves `members` rigidly with their hub from pose `from` to pose `to` (plan turn and shift; heights from
  // their support, wall-bound ones onto their wall).
  // `armchairs`: false leaves the armchairs where they stand.
  void Carry(const std::vector<int>& members, const Pose& from, const Pose& to, bool armchairs = true) {
    const double turn = WrapAngle(to.yaw - from.yaw);
    const double c = std::cos(turn), s = std::sin(turn);
    // A member that is a hub itself (the coffee table of the sofa, with its armchairs) takes its own along.
    auto taken = [&](int j) { return armchairs || GroupMembership(state, j).role != GroupRole::kArmchair; };
    std::vector<int> all;
    std::copy_if(members.begin(), members.end(), std::back_inserter(all), taken);
    for (size_t k = 0; k < all.size(); ++k)
      for (int m : MembersOf(all[k]))
        if (std::find(all.begin(), all.end(), m) == all.end() && taken(m)) all.push_back(m);
    for (int j : all) {
      Pose p = state.placements[j].pose;
      const double dx = p.x - from.x, dy = p.y - from.y;
      p.x = to.x + c * dx - s * dy;
      p.y = to.y + s * dx + c * dy;
      p.yaw = WrapAngle(p.yaw + turn);
      state.SetPose(j, Snap(j, p));
    }
  }

  // Whether hub i at `at` takes its members along: carried rigidly, each free there or re-seated from its
  // template. The state is left as it was.
  bool GroupFitsAt(int i, const std::vector<int>& members, const ObjectPlacement& at) {
    const RoomState before = state;
    const Pose from = state.placements[i].pose;
    state.placements[i].wall = at.wall;
    state.SetPose(i, at.pose);
    Carry(members, from, at.pose);
    bool fits = Reseat(members).empty();
    // The tidy stage asks for the whole group to hold its rules there (the TV stand across from the sofa).
    if (strict_groups)
      for (int j : members) fits = fits && GroupProblem(j).empty() && (!TableSeat(j) || SeatHolds(j));
    state = before;
    return fits;
  }

  // Members in hard trouble or out of their template after their hub moved take their best template pose;
  // the ones in hard trouble that find none.
  std::vector<int> Reseat(const std::vector<int>& members) {
    std::vector<int> stuck;
    for (int j : members) {
      if (CostAt(j).hard <= kFeasible && GroupProblem(j).empty()) continue;
      if (auto slot = FindSlot(j)) {
        MoveWithGroup(j, slot->pose, slot->wall);
      } else if (CostAt(j).hard > kFeasible) {
        stuck.push_back(j);
      }
    }
    return stuck;
  }

  ActionResult AddEntity(const Action& action, ActionResult r) {
    if (!action.object) return Refuse(r, "add_entity needs an object");
    RoomProblem probe = problem;
    probe.objects = state.objects;
    probe.objects.push_back(*action.object);
    probe.edges = state.edges;
    probe.edges.insert(probe.edges.end(), action.edges.begin(), action.edges.end());
    if (Status s = probe.Check(); !s.ok()) return Refuse(r, s.error());
    const RoomState saved = state;
    state.objects.push_back(*action.object);
    state.placements.push_back({});
    ObjectPlacement& pl = state.placements.back();
    pl.surface = action.object->surface;
    pl.cavity = action.object->cavity;
    pl.wall = action.object->wall;
    state.edges = probe.edges;
    state.Reindex();
    AssignSupports(state);
    const int i = static_cast<int>(state.objects.size()) - 1;
    state.placements[i].pose.z = state.Hung(i) ? problem.floor_z : state.SupportHeight(i);
    std::string how;
    bool ok = false;
    if (action.pose) {
      Pose want = *action.pose;
      if (std::isnan(want.z)) want.z = state.placements[i].pose.z;
      state.SetPose(i, Snap(i, want));
      state.placements[i].placed = true;
      ok = Repair(i, &how);
    } else if (auto slot = FindSlot(i)) {
      state.placements[i].surface = slot->surface;
      state.placements[i].cavity = slot->cavity;
      state.placements[i].wall = slot->wall;
      state.placements[i].placed = true;
      state.SetPose(i, slot->pose);
      ok = true;
      how = "placed at the best free slot";
    }
    if (!ok) {
      state = saved;
      return Refuse(r, "no free pose for the new object \"" + action.object->id + "\"");
    }
    r.status = action.pose && how.empty() ? ActionStatus::kApplied : ActionStatus::kRepaired;
    r.message = how.empty() ? "added" : how;
    r.final_pose = state.placements[i].pose;
    return r;
  }

  // ---- the rule agent

  // Objects in hard trouble, the one that should give way first: lowest priority, then smallest.
  std::vector<int> Culprits() const {
    std::set<int> set;
    auto lesser = [&](int a, int b) {
      const ProblemObject& A = state.objects[a];
      const ProblemObject& B = state.objects[b];
      if (A.priority != B.priority) return A.priority < B.priority ? a : b;
      if (const int m = MemberOfOther(a, b); m >= 0) return m;  // a group's member yields to its hub
      return Volume(A, state.placements[a].pose.scale) <= Volume(B, state.placements[b].pose.scale) ? a : b;
    };
    // Objects in trouble with the building (a wall, a door leaf or sweep, the stairs): a child there because
    // its parent is there gives way only through its parent (books in a bookcase that stands in a door's
    // sweep cannot leave it by moving along their shelf).
    std::set<int> with_building;
    for (const CollisionPair& pair : metrics.pairs)
      if (pair.building) with_building.insert(state.Find(pair.a));
    for (const auto& [a_id, b_id] : energy.overlaps)
      if (state.Find(b_id) < 0) with_building.insert(state.Find(a_id));
    auto carrier = [&](int i) {
      int top = i;
      for (int p = state.parent[i]; p >= 0; p = state.parent[p])
        if (with_building.count(p)) top = p;
      return top;
    };
    for (const CollisionPair& pair : metrics.pairs) {
      const int a = state.Find(pair.a), b = pair.building ? -1 : state.Find(pair.b);
      if (a >= 0) set.insert(b >= 0 ? lesser(a, b) : carrier(a));
    }
    for (const auto& [a_id, b_id] : energy.overlaps) {
      const int a = state.Find(a_id), b = state.Find(b_id);
      if (a >= 0) set.insert(b >= 0 ? lesser(a, b) : carrier(a));
    }
    for (size_t i = 0; i < state.objects.size(); ++i) {
      const ObjectCheck& c = metrics.per_object[i];
      if (c.floating || c.out_of_bounds || (c.inside_edge && !c.contained) || energy.object_support[i] > 0.0) {
        set.insert(static_cast<int>(i));
      }
    }
    std::vector<int> out(set.begin(), set.end());
    std::sort(out.begin(), out.end(), [&](int a, int b) {
      const ProblemObject& A = state.objects[a];
      const ProblemObject& B = state.objects[b];
      if (A.priority != B.priority) return A.priority < B.priority;
      const double va = Volume(A, state.placements[a].pose.scale), vb = Volume(B, state.placements[b].pose.scale);
      if (va != vb) return va < vb;
      return a > b;
    });
    return out;
  }

  // Of objects a and b, the one that is a member of the other's functional group (issue 27), else -1.
  int MemberOfOther(int a, int b) const {
    if (a == b || !options.functional_groups) return -1;
    if (GroupMembership(state, a).hub == b) return a;
    if (GroupMembership(state, b).hub == a) return b;
    return -1;
  }

  // Who goes when nothing else helps: the least important of the object and those it conflicts with
  // (its collision partners, its siblings on the same surface or in the same cavity).
  int LeastImportant(int i) const {
    std::vector<int> set = {i};
    const std::string& id = state.objects[i].id;
    bool with_objects = false;
    for (const CollisionPair& pair : metrics.pairs) {
      if (pair.building) continue;
      if (pair.a == id) set.push_back(state.Find(pair.b));
      if (pair.b == id) set.push_back(state.Find(pair.a));
      with_objects = with_objects || pair.a == id || pair.b == id;
    }
    // In trouble with the building alone (a window's zone above the sill): what stands on it and rises
    // above it is part of the conflict (a counter under a window is low enough once the bottle on it goes).
    if (!with_objects) {
      const double top = state.placements[i].pose.z + state.objects[i].asset.size.z * state.placements[i].pose.scale;
      for (int c : state.children[i]) {
        const double child_top = state.placements[c].pose.z + state.objects[c].asset.size.z * state.placements[c].pose.scale;
        if (state.objects[c].relation == Relation::kOnTop && child_top > top + 1e-6) set.push_back(c);
      }
    }
    const int p = state.parent[i];
    if (p >= 0) {
      for (int c : state.children[p]) {
        if (state.objects[c].relation == state.objects[i].relation &&
            state.placements[c].surface == state.placements[i].surface && state.placements[c].cavity == state.placements[i].cavity)
          set.push_back(c);
      }
    }
    int pick = i;
    for (int k : set) {
      if (k < 0) continue;
      const ProblemObject& K = state.objects[k];
      const ProblemObject& P = state.objects[pick];
      if (K.priority < P.priority || (K.priority == P.priority && MemberOfOther(k, pick) == k) ||
          (K.priority == P.priority && MemberOfOther(k, pick) < 0 &&
           Volume(K, state.placements[k].pose.scale) < Volume(P, state.placements[pick].pose.scale) - 1e-12))
        pick = k;
    }
    return pick;
  }

  // The unprotected objects that may give way to object i (MakeWayFor, a table seating its chairs): of i's
  // layer (the room's floor for what stands on it, i's siblings for what stands on a parent), not of i's
  // own group (its members, its hub), nothing protected on them; the least important first, then the
  // biggest, what hangs on a wall after what stands (or the other way round).
  std::vector<int> GiveWayPool(int i) const {
    std::vector<int> pool;
    const int p = state.parent[i];
    // An essential (the children's room's bed) is kept before what the request names besides it (the desk
    // asked for beside it): those give way to it too, after every unprotected piece (the order below).
    // (Not a piece of its own kind or group: the two essential chairs of a table do not push out the other
    // chairs the request asks for.)
    const bool essential = state.objects[i].priority == Priority::kEssential;
    const int hub = GroupMembership(state, i).hub;
    auto keeps = [&](int k) {
      const Priority q = state.objects[k].priority;
      if (!IsProtected(q)) return false;
      if (!essential || q != Priority::kNamed) return true;
      return state.objects[k].category == state.objects[i].category || (hub >= 0 && GroupMembership(state, k).hub == hub);
    };
    for (size_t k = 0; k < state.objects.size(); ++k) {
      const int kk = static_cast<int>(k);
      if (kk == i || keeps(kk) || state.parent[k] != p) continue;
      // Its own group goes with it, not for it (its members, its hub).
      if (GroupMembership(state, kk).hub == i || GroupMembership(state, i).hub == kk) continue;
      // Nothing kept stands on it (the counter under the sink stays).
      const std::vector<int> below = state.Descendants(kk);
      if (std::any_of(below.begin(), below.end(), keeps)) continue;
      pool.push_back(kk);
    }
    std::stable_sort(pool.begin(), pool.end(), [&](int a, int b) {
      const ProblemObject& A = state.objects[a];
      const ProblemObject& B = state.objects[b];
      const bool a_other = state.Hung(a) != state.Hung(i), b_other = state.Hung(b) != state.Hung(i);
      if (a_other != b_other) return b_other;
      if (A.priority != B.priority) return A.priority < B.priority;
      return Volume(A, state.placements[a].pose.scale) > Volume(B, state.placements[b].pose.scale);
    });
    return pool;
  }

  // The unprotected objects whose removal lets protected object i find a free slot, of those that may give
  // way to it (GiveWayPool, in its order). One removal when one does (the first ten tried, each on a copy of the state); else all of them at once and,
  // when that frees a slot, each put back again, the most important first, while the slot stays free (a
  // bedroom keeps its bed and loses the wardrobe and the desk in its way, not its lamps). Empty when even
  // the emptied layer has no slot for i.
  std::vector<int> MakeWayFor(int i, bool at_size = false) {
    const std::vector<int> pool = GiveWayPool(i);
    const std::string id = state.objects[i].id;
    // Tried at its smallest scale (a king-size bed in a 2 m wide room): the shrink comes after the room is made.
    // `at_size`: at the scale it has (an essential keeps its size where optional pieces can make way).
    auto frees_at_smallest = [&](int j) {
      Pose small = state.placements[j].pose;
      if (!at_size) small.scale = std::min(small.scale, state.objects[j].scale_min);
      state.SetPose(j, small);
      return FindSlot(j).has_value();
    };
    for (size_t n = 0; n < pool.size() && n < 10; ++n) {
      const RoomState saved = state;
      state.Remove(pool[n]);
      const int j = state.Find(id);
      const bool frees = j >= 0 && frees_at_smallest(j);
      state = saved;
      if (frees) return {pool[n]};
    }
    if (pool.size() < 2) return {};
    // By id: indices shift as objects go.
    std::vector<std::string> ids;
    for (int k : pool) ids.push_back(state.objects[k].id);
    const RoomState saved = state;
    auto frees_without = [&](const std::vector<bool>& gone) {
      state = saved;
      for (size_t n = 0; n < ids.size(); ++n)
        if (gone[n])
          if (const int k = state.Find(ids[n]); k >= 0) state.Remove(k);
      const int j = state.Find(id);
      return j >= 0 && frees_at_smallest(j);
    };
    std::vector<bool> gone(ids.size(), true);
    if (!frees_without(gone)) {
      state = saved;
      return {};
    }
    for (size_t n = ids.size(); n-- > 0;) {
      gone[n] = false;
      if (!frees_without(gone)) gone[n] = true;
    }
    state = saved;
    std::vector<int> out;
    for (size_t n = 0; n < ids.size(); ++n)
      if (gone[n]) out.push_back(state.Find(ids[n]));
    return out;
  }

  // The protected objects standing in walkways, when every proxy overlap left is such a one (else empty).
  std::vector<std::string> ProtectedInWalkways() const {
    std::set<std::string> ids;
    for (const auto& [a, b] : energy.overlaps) {
      const int i = state.Find(a);
      if (i < 0 || b.rfind("walkway ", 0) != 0 || !IsProtected(state.objects[i].priority)) return {};
      ids.insert(a);
    }
    return {ids.begin(), ids.end()};
  }

  // A member of i's group whose box overlaps i's (a chair pulled into its shrunk table): moved to its best
  // template slot, else removed; none when no member is in i's way.
  std::optional<Action> MemberOutOfTheWay(int i) {
    if (!options.functional_groups) return std::nullopt;
    const std::string& id = state.objects[i].id;
    for (const auto& [a_id, b_id] : energy.overlaps) {
      const std::string other = a_id == id ? b_id : b_id == id ? a_id : "";
      const int j = other.empty() ? -1 : state.Find(other);
      if (j < 0 || GroupMembership(state, j).hub != i) continue;
      Action a;
      a.id = other;
      if (auto slot = FindSlot(j)) {
        a.kind = ActionKind::kUpdatePose;
        a.pose = slot->pose;
        if (slot->wall >= 0 && slot->wall != state.placements[j].wall) a.wall = slot->wall;
        a.reason = "in the way of its group's " + state.objects[i].category + ": re-seated";
      } else {
        a.kind = ActionKind::kRemoveEntity;
        a.reason = "in the way of its group's " + state.objects[i].category + " and no seat free by it: remove it";
      }
      return a;
    }
    return std::nullopt;
  }

  // The removals that let protected object i find a slot (MakeWayFor), as actions: the first now, the
  // others queued for the next calls; none when none does.
  std::optional<Action> MakeWayAction(int i, bool at_size = false) {
    const std::vector<int> ks = MakeWayFor(i, at_size);
    if (ks.empty()) return std::nullopt;
    const std::string reason_head = "make room for " + state.objects[i].id + " (" +
                                    std::string(PriorityName(state.objects[i].priority)) + "): remove ";
    for (size_t n = 1; n < ks.size(); ++n) {
      Action a;
      a.kind = ActionKind::kRemoveEntity;
      a.id = state.objects[ks[n]].id;
      a.reason = reason_head + std::string(PriorityName(state.objects[ks[n]].priority)) + " " + state.objects[ks[n]].category;
      queued.push_back(a);
    }
    Action a;
    a.kind = ActionKind::kRemoveEntity;
    a.id = state.objects[ks[0]].id;
    a.reason = reason_head + std::string(PriorityName(state.objects[ks[0]].priority)) + " " + state.objects[ks[0]].category;
    return a;
  }

  // Whether object i's only hard trouble is the reachability feedback's walkways (its meshes clean, its
  // support right, its box overlapping nothing but walkway zones).
  bool OnlyInWalkways(int i) const {
    const ObjectCheck& c = metrics.per_object[i];
    if (c.colliding || c.floating || c.out_of_bounds || (c.inside_edge && !c.contained) || energy.object_support[i] > 0.0)
      return false;
    const std::string& id = state.objects[i].id;
    bool any = false;
    for (const auto& [a, b] : energy.overlaps) {
      if (a != id && b != id) continue;
      if (b.rfind("walkway ", 0) != 0) return false;
      any = true;
    }
    return any;
  }

  std::optional<Action> NextAction() {
    // The rest of a set of removals that makes room for a protected object.
    while (!queued.empty()) {
      Action a = queued.front();
      queued.pop_front();
      if (state.Find(a.id) >= 0) return a;
    }
    for (int i : Culprits()) {
      // Copies: MakeWayFor tries removals on the state and puts it back.
      const std::string id = state.objects[i].id;
      int& n = tries[id];
      const ProblemObject o = state.objects[i];
      if (n == 0) {
        ++n;
        if (auto slot = FindSlot(i)) {
          Action a;
          a.kind = ActionKind::kUpdatePose;
          a.id = id;
          a.pose = slot->pose;
          if (slot->surface >= 0 && slot->surface != state.placements[i].surface) a.surface = slot->surface;
          if (slot->cavity >= 0 && slot->cavity != state.placements[i].cavity) a.cavity = slot->cavity;
          if (slot->wall >= 0 && slot->wall != state.placements[i].wall) a.wall = slot->wall;
          a.reason = "collides, floats or is out of bounds: move to a free slot";
          return a;
        }
      }
      if (n == 1) {
        ++n;
        if (o.scale_min < state.placements[i].pose.scale - 1e-9) {
          // A bed (the bedroom's essential) keeps its size where optional pieces can make way for it: they go
          // before it shrinks (issue 27: at 0.8 a double is 1.6-1.7 m long, a 0.9 m single 0.72 m wide: no
          // adult's bed; half the rooms bench's beds were so). Other essentials shrink first, as before
          // (making way first for every one turned three sofas from their TVs on the rooms bench).
          if (o.priority == Priority::kEssential && o.category == "bed")
            if (std::optional<Action> a = MakeWayAction(i, /*at_size=*/true)) {
              n = 0;
              return a;
            }
          Action a;
          a.kind = ActionKind::kUpdateScale;
          a.id = id;
          a.scale = o.scale_min;
          a.reason = "no free slot at full size: shrink to the smallest allowed scale";
          return a;
        }
      }
      if (n == 2) {
        ++n;
        int victim = LeastImportant(i);
        // A protected object (essential, or named in the request) that would go, itself or for another
        // protected one (the TV the request asks for, in conflict with its stand): an unprotected one whose
        // removal frees a slot goes instead, and it tries again (issue 27: a bedroom keeps its bed and loses
        // its dresser).
        if (IsProtected(state.objects[victim].priority) && (victim == i || IsProtected(o.priority))) {
          if (std::optional<Action> a = MakeWayAction(i)) {
            n = 0;
            return a;
          }
          // Only in the reachability feedback's walkways: it stays where it stands (the way it closes is
          // reported) rather than leave the room without it.
          if (OnlyInWalkways(i)) {
            n = 4;
            continue;
          }
        }
        Action a;
        a.kind = ActionKind::kRemoveEntity;
        a.id = state.objects[victim].id;
        a.reason = victim == i ? "no free slot even at its smallest scale: remove it (least important of its conflict)"
                               : "no room for both: remove the least important object of the conflict with " + id;
        if (victim == i) ++n;  // nothing is left to try for it
        return a;
      }
      if (n == 3) {
        // Its conflict gave way and it is still in trouble (a thing on a surface its shrunk parent no longer
        // holds): it goes itself, so the room ends physically valid; a protected one first has an
        // unprotected object make room for it.
        ++n;
        if (IsProtected(o.priority)) {
          // Its own group's member in its way yields to it: re-seated from its template, else taken out.
          if (std::optional<Action> a = MemberOutOfTheWay(i)) {
            n = 0;
            return a;
          }
          if (std::optional<Action> a = MakeWayAction(i)) {
            n = 0;
            return a;
          }
          if (OnlyInWalkways(i)) continue;
        }
        Action a;
        a.kind = ActionKind::kRemoveEntity;
        a.id = id;
        a.reason = "still colliding, floating or out of bounds after its conflict gave way: remove it";
        return a;
      }
    }
    if (!Culprits().empty()) return std::nullopt;  // hard trouble left and every remedy tried
    // Physically valid: lower the semantic energy, one try per object, the most involved first. An unmet
    // relation may be mended from either end (the painting cannot be centred over the bed beside a window,
    // but the bed can move under the painting).
    std::vector<double> involved = energy.object_semantic;
    for (size_t k = 0; k < state.edges.size() && k < energy.edge_violation.size(); ++k) {
      const int t = state.Find(state.edges[k].target);
      if (t >= 0) involved[t] += energy.edge_violation[k];
    }
    std::vector<int> order;
    for (size_t i = 0; i < state.objects.size(); ++i) {
      if (involved[i] > 1e-6 && !semantic_tried.count(state.objects[i].id)) order.push_back(static_cast<int>(i));
    }
    std::sort(order.begin(), order.end(), [&](int a, int b) {
      if (involved[a] != involved[b]) return involved[a] > involved[b];
      return a < b;
    });
    for (int i : order) {
      semantic_tried.insert(state.objects[i].id);
      const LayerCost now = CostAt(i);
      auto slot = FindSlot(i);
      if (!slot || slot->cost.soft_linear >= now.soft_linear - 1e-9) continue;
      Action a;
      a.kind = ActionKind::kUpdatePose;
      a.id = state.objects[i].id;
      a.pose = slot->pose;
      if (slot->wall >= 0 && slot->wall != state.placements[i].wall) a.wall = slot->wall;
      a.reason = "relations or interaction zones unmet: move to where they hold better";
      return a;
    }
    return std::nullopt;
  }

  // ---- Issue 27: seats a person can pull out. A dining or meeting table's chair beside a side of its table,
  // facing it, with 0.75 m of floor behind it (walls, stairs and furniture of 0.1 m2 or more stop it: the
  // functional check's measure, solver/functional.cpp).
  bool TableSeat(int j) const {
    const Membership m = GroupMembership(state, j);
    return m.role == GroupRole::kTableSeat && TableHub(m.hub);
  }
  // The furniture stopping chair j's pull-out room (an index per blocked sample; -1 a wall or the stairs),
  // and the free depth behind it (m, capped at the rule's 0.75).
  double SeatBehind(int j, std::set<int>* blockers = nullptr) const {
    const OrientedBox chair = state.WorldBox(j);
    const Point u = chair.U(), v = chair.V();
    double clear = kSeatBehind;
    for (double side : {-1.0, -0.5, 0.0, 0.5, 1.0})
      for (double d = 0.0; d < kSeatBehind; d += 0.025) {
        const Point p = geo::Add(geo::Add(chair.c, geo::Scale(v, chair.hy + d + 0.01)), geo::Scale(u, side * chair.hx));
        int by = PointInRing(p, problem.free_floor, 0.0) ? -2 : -1;
        for (const KeepOut& k : problem.keep_outs)
          if (by == -2 && (k.kind == KeepOutKind::kStaircase || k.kind == KeepOutKind::kStairHole || k.kind == KeepOutKind::kStairArrival) && PointInRing(p, k.polygon, 0.0)) by = -1;
        for (size_t k = 0; k < state.objects.size() && by == -2; ++k) {
          const int kk = static_cast<int>(k);
          if (kk == j || state.parent[k] >= 0 || state.Hung(kk) || state.IsFloorCovering(kk)) continue;
          const OrientedBox box = state.WorldBox(kk);
          if (4.0 * box.hx * box.hy >= 0.1 && box.ContainsPlan(p)) by = kk;
        }
        if (by == -2) continue;
        if (blockers) blockers->insert(by);
        clear = std::min(clear, d);
        break;
      }
    return clear;
  }
  bool TableHub(int i) const { return state.objects[i].category == "dining-table" || state.objects[i].category == "conference-table"; }
  bool SeatHolds(int j) const {
    const Membership m = GroupMembership(state, j);
    return TableSeatProblem(state.WorldBox(j), state.WorldBox(m.hub)).empty() && SeatBehind(j) >= kSeatBehind - 1e-9;
  }
  void TakeAction(const Action& a) {
    summary.actions.push_back(Apply(a));
    ++summary.iterations;
    Check();
  }
  // Whether the exact check finds the arrangement as it stands clean (`metrics` unchanged).
  bool ExactlyClean() { return checker->Check(state, false).Clean(); }
  // A move the tidy stage made on the state itself (already checked), logged as an applied action with what
  // it removed, and the state checked.
  void LogMove(const std::string& id, const Pose& to, const std::string& reason, const std::string& message = "done",
               const std::vector<std::string>& removed = {}) {
    ActionResult r;
    r.action.kind = ActionKind::kUpdatePose;
    r.action.id = id;
    r.action.pose = to;
    r.action.reason = reason;
    r.status = ActionStatus::kApplied;
    r.message = message;
    r.final_pose = to;
    r.removed = removed;
    summary.removed.insert(summary.removed.end(), removed.begin(), removed.end());
    summary.actions.push_back(r);
    Check();
  }
  // The room and the record of what was done, to go back to when a trial does not hold (the actions,
  // removals and energies logged since are dropped).
  struct Mark {
    RoomState state;
    EnergyTerms energy;
    ExactMetrics metrics;
    size_t actions = 0, removed = 0, trace = 0;
    int iterations = 0;
  };
  Mark Here() const {
    return {state, energy, metrics, summary.actions.size(), summary.removed.size(), summary.energy_trace.size(), summary.iterations};
  }
  void Rewind(const Mark& m) {
    state = m.state;
    energy = m.energy;
    metrics = m.metrics;
    summary.actions.resize(m.actions);
    summary.removed.resize(m.removed);
    summary.energy_trace.resize(m.trace);
    summary.iterations = m.iterations;
  }

  void TakeRemoval(const std::string& id, const std::string& reason) {
    Action a;
    a.kind = ActionKind::kRemoveEntity;
    a.id = id;
    a.reason = reason;
    TakeAction(a);
  }

  // A sofa that does not face its TV (the stand on an angled wall, or off its axis): the stand slid along
  // its wall onto the sofa's axis, else the sofa slid sideways (with its coffee and side tables) until the TV
  // is before it; all of the way, else three quarters, half or a quarter of it. Kept where nothing collides
  // (the exact check has the last word) and the groups break fewer rules. True when one held.
  bool AlignWithTv(int sofa, int stand, const std::string& why) {
    const std::string sofa_id = state.objects[sofa].id, stand_id = state.objects[stand].id;
    // 0: the stand slides; 1: the sofa with all its floor members; 2: the sofa with its coffee and side
    // tables while the armchairs stay (a short slide carries one into a bookcase).
    for (int which = 0; which < 3; ++which) {
      const std::string& mover = which == 0 ? stand_id : sofa_id;
      const int k = state.Find(mover), sofa_k = state.Find(sofa_id), stand_k = state.Find(stand_id);
      if (sofa_k < 0 || stand_k < 0) return false;
      const OrientedBox so = state.WorldBox(sofa_k), st = state.WorldBox(stand_k);
      const Point f = so.Front(), w = geo::Sub(st.c, so.c);
      double shift = 0.0;
      Point along;
      if (which == 0) {  // the stand along its own width onto the sofa's axis
        along = st.U();
        const double c = geo::Cross(f, along);
        if (std::abs(c) < 0.3) continue;
        shift = -geo::Cross(f, w) / c;
      } else {  // the sofa along its width under the TV
        along = so.U();
        shift = geo::Dot(w, along);
      }
      if (std::abs(shift) < 0.05 || std::abs(shift) > 3.0) continue;
      std::vector<int> carried;
      if (which > 0)
        for (int j : MembersOf(k))
          if (state.objects[j].relation != Relation::kAgainstWall) carried.push_back(j);
      if (which == 2) {  // (no armchair in the group: the same as the try before)
        bool armchair = false;
        for (int j : carried)
          for (int m : MembersOf(j)) armchair = armchair || GroupMembership(state, m).role == GroupRole::kArmchair;
        if (!armchair) continue;
      }
      const RoomState saved = state;
      const int trouble = GroupTrouble();
      for (double frac : {1.0, 0.75, 0.5, 0.35, 0.25, 0.15}) {
        state = saved;
        const Pose from = state.placements[k].pose;
        Pose to = from;
        to.x += frac * shift * along.x;
        to.y += frac * shift * along.y;
        state.SetPose(k, to);
        Carry(carried, from, to, which < 2);
        // An optional side table that no longer fits at the sofa's end is left out; a protected member
        // that does not fit keeps the sofa where it was.
        bool ok = true;
        std::vector<std::string> left_out;
        for (int j : carried)
          if (CostAt(j).hard > kHairline) {
            if (IsProtected(state.objects[j].priority)) ok = false;
            else left_out.push_back(state.objects[j].id);
          }
        std::vector<std::string> removed;
        for (const std::string& gone : left_out)
          if (const int j = state.Find(gone); j >= 0) {
            const std::vector<std::string> g = state.Remove(j);
            removed.insert(removed.end(), g.begin(), g.end());
          }
        const int kk = state.Find(mover);
        if (!ok || kk < 0 || CostAt(kk).hard > kHairline || GroupTrouble() >= trouble || !ExactlyClean()) continue;
        std::string message = carried.empty() ? "done" : "done; its coffee and side tables came along";
        if (!removed.empty()) message += ", " + std::to_string(left_out.size()) + " with no place at its end left out";
        LogMove(mover, to,
                "the sofa does not face its TV (" + why + "): " +
                    (which == 0 ? "the TV stand slid along its wall onto the sofa's axis" : "the sofa slid sideways before the TV"),
                message, removed);
        return true;
      }
      state = saved;
    }
    return false;
  }

  // Nothing tall between a sofa and its TV: a plant, a floor lamp or a chair standing in the 0.8 m wide
  // strip from the sofa's front to the TV stand (a coffee table, a rug and what is lower than 0.6 m do not
  // block the view) goes to its best free place out of the strip, else it is left out unless protected.
  // Kept where nothing collides (the exact check has the last word) and no group breaks more rules. True
  // when anything moved or went.
  bool ClearSightlines() {
    constexpr double kStrip = 0.4, kLow = 0.6;  // m: half the strip's width; what is lower leaves the view free
    constexpr double kKnees = 0.45;             // m before the sofa kept for the legs of who sits on it
    bool changed = false;
    for (size_t t = 0; t < state.objects.size(); ++t) {
      const Membership m = GroupMembership(state, static_cast<int>(t));
      if (m.role != GroupRole::kTvStand) continue;
      const std::string sofa_id = state.objects[m.hub].id, stand_id = state.objects[t].id;
      auto strip = [&] {
        const OrientedBox so = state.WorldBox(state.Find(sofa_id)), st = state.WorldBox(state.Find(stand_id));
        const Point a = geo::Add(so.c, geo::Scale(so.Front(), so.hy)), b = geo::Add(st.c, geo::Scale(st.Front(), st.hy));
        OrientedBox box;
        box.c = geo::Scale(geo::Add(a, b), 0.5);
        const Point d = geo::Sub(b, a);
        box.yaw = std::atan2(d.y, d.x);
        box.hx = 0.5 * geo::Dist(a, b);
        box.hy = kStrip;
        return box;
      };
      // Issue 27: the sofa's knee room too, 0.45 m before it along its whole width (a floor lamp that its
      // next_to edge put before the sofa's end, in `make run`'s living room).
      auto knees = [&] {
        OrientedBox box = state.WorldBox(state.Find(sofa_id));
        box.c = geo::Add(box.c, geo::Scale(box.Front(), box.hy + 0.5 * kKnees));
        box.hy = 0.5 * kKnees;
        return box;
      };
      auto blockers = [&] {
        std::vector<std::string> out;
        const OrientedBox view = strip(), knee = knees();
        for (size_t k = 0; k < state.objects.size(); ++k) {
          const int kk = static_cast<int>(k);
          if (state.parent[k] >= 0 || state.Hung(kk) || state.IsFloorCovering(kk) || state.objects[k].id == sofa_id ||
              state.objects[k].id == stand_id)
            continue;
          const OrientedBox box = state.WorldBox(kk);
          if (box.z1 - box.z0 < kLow || GroupMembership(state, kk).role == GroupRole::kCoffeeTable) continue;
          if (PlanDepth(box, view) > 0.02 || PlanDepth(box, knee) > 0.02) out.push_back(state.objects[k].id);
        }
        return out;
      };
      for (const std::string& id : blockers()) {
        const int k = state.Find(id);
        if (k < 0) continue;
        const RoomState saved = state;
        const int trouble = GroupTrouble();
        // Its best free place with the view kept out of reach (what is lower than the view may stand in it).
        KeepOut view;
        view.polygon = strip().Footprint();
        view.z_min = problem.floor_z + kLow;
        view.z_max = problem.floor_z + 3.0;
        view.name = "the view from the sofa to its TV";
        problem.keep_outs.push_back(view);
        // And the whole floor between the sofa's front and the stand's, as wide as each: moved out of the
        // knee room, a floor lamp is not to stand beside the coffee table in mid-room instead.
        KeepOut between = view;
        {
          const OrientedBox so = state.WorldBox(state.Find(sofa_id)), st = state.WorldBox(state.Find(stand_id));
          const Point sf = geo::Add(so.c, geo::Scale(so.Front(), so.hy)), tf = geo::Add(st.c, geo::Scale(st.Front(), st.hy));
          between.polygon = {geo::Add(sf, geo::Scale(so.U(), so.hx)), geo::Add(sf, geo::Scale(so.U(), -so.hx)),
                             geo::Add(tf, geo::Scale(st.U(), st.hx)), geo::Add(tf, geo::Scale(st.U(), -st.hx))};
          if (SignedArea(between.polygon) < 0) std::reverse(between.polygon.begin(), between.polygon.end());
        }
        between.name = "the floor between the sofa and its TV";
        problem.keep_outs.push_back(between);
        const std::optional<Slot> slot = FindSlot(k);
        problem.keep_outs.pop_back();
        problem.keep_outs.pop_back();
        if (slot) {
          state.placements[k].wall = slot->wall;
          state.SetPose(k, slot->pose);
          const std::vector<std::string> still = blockers();
          if (std::find(still.begin(), still.end(), id) == still.end() && CostAt(k).hard <= kHairline && GroupTrouble() <= trouble &&
              ExactlyClean()) {
            LogMove(id, slot->pose, "stands between the sofa and its TV or before the sofa: to its best free place out of the view");
            changed = true;
            continue;
          }
          state = saved;
        }
        if (IsProtected(state.objects[k].priority)) continue;
        TakeRemoval(id, "stands between the sofa and its TV or before the sofa and no free place out of the view holds it: left out");
        changed = true;
      }
    }
    return changed;
  }

  // A sofa that cannot face its TV from where it stands (along an angled wall, the stand on a wall at 45
  // degrees to it; its back to the TV): the sofa floated before the TV as a designer floats one, on the
  // stand's axis 1.6-3.3 m from it (up to 1.5 m to either side, the stand slid along its wall as far where
  // it can), turned to face it, its coffee and side
  // tables and armchairs carried along (re-seated from their templates where they collide; an optional one
  // with no place left out). Kept where nothing collides (the exact check has the last word) and the groups
  // break fewer rules. True when one held.
  // `slides`: the stand may slide along its wall; `trouble`: the group rules broken to better (-1: now).
  bool FaceTv(int sofa, int stand, const std::string& why, bool slides = true, int trouble = -1) {
    const std::string sofa_id = state.objects[sofa].id, stand_id = state.objects[stand].id;
    const OrientedBox st = state.WorldBox(stand), so = state.WorldBox(sofa);
    const Point f = st.Front(), u = st.U();
    const Pose from = state.placements[sofa].pose, stand_from = state.placements[stand].pose;
    const Point offset{from.x - so.c.x, from.y - so.c.y};  // the pose's point from the box's centre
    std::vector<std::string> carried;
    for (int j : MembersOf(sofa))
      if (state.objects[j].relation != Relation::kAgainstWall) carried.push_back(state.objects[j].id);
    const RoomState saved = state;
    if (trouble < 0) trouble = GroupTrouble();
    for (double side : {0.0, 0.3, -0.3, 0.6, -0.6, 0.9, -0.9, 1.2, -1.2, 1.5, -1.5})
      for (bool slide : {true, false}) {   // the stand slid along its wall by as much, or where it stands
        if (slide && (side == 0.0 || !slides)) continue;
        state = saved;
        if (slide) {
          Pose to = stand_from;
          to.x += side * u.x;
          to.y += side * u.y;
          state.SetPose(stand, to);
          if (CostAt(stand).hard > kHairline) continue;
        }
        const RoomState stand_placed = state;
        for (double d : {2.4, 2.1, 2.7, 1.8, 3.0, 3.3, 1.6}) {
          state = stand_placed;
          const int k = state.Find(sofa_id);
          ProblemObject& o = state.objects[k];
          if (o.relation == Relation::kAgainstWall) o.relation = Relation::kOnTop, o.parent = "floor";  // it floats now
          o.wall = -1;
          state.placements[k].wall = -1;
          const Point centre = geo::Add(geo::Add(st.c, geo::Scale(f, d)), geo::Scale(u, side));
          // Its front towards the TV (square to the stand when it sits on the stand's axis).
          const Point tv = state.WorldBox(state.Find(stand_id)).c, look = geo::Unit(geo::Sub(tv, centre));
          const double turn = WrapAngle(std::atan2(look.x, -look.y) - so.yaw);
          const double c = std::cos(turn), s = std::sin(turn);
          Pose to = from;
          to.x = centre.x + c * offset.x - s * offset.y;
          to.y = centre.y + s * offset.x + c * offset.y;
          to.yaw = WrapAngle(from.yaw + turn);
          state.SetPose(k, to);
          std::vector<int> members;
          for (const std::string& id : carried) members.push_back(state.Find(id));
          Carry(members, from, to);
          // (The proxy's corner and reflex-vertex terms miss a box edge across a wedge of wall: the floor it
          // covers says.)
          const OrientedBox box = state.WorldBox(k);
          if (CostAt(k).hard > kHairline || ClippedArea(problem.free_floor, box.Footprint()) < 4.0 * box.hx * box.hy - 1e-4) continue;
          if (!GroupProblem(state.Find(stand_id)).empty()) continue;  // the TV stand's rule, as the group measures it
          bool ok = true;
          std::vector<std::string> left_out;
          for (int j : Reseat(members)) {
            if (IsProtected(state.objects[j].priority)) ok = false;
            else left_out.push_back(state.objects[j].id);
          }
          if (!ok) continue;
          std::vector<std::string> removed;
          for (const std::string& gone : left_out)
            if (const int j = state.Find(gone); j >= 0) {
              const std::vector<std::string> g = state.Remove(j);
              removed.insert(removed.end(), g.begin(), g.end());
            }
          if (GroupTrouble() >= trouble || !ExactlyClean()) continue;
          if (slide) LogMove(stand_id, state.placements[state.Find(stand_id)].pose, "the sofa does not face its TV (" + why + "): the TV stand slid along its wall to where the sofa can face it");
          std::string message = "done; its coffee and side tables came along";
          if (!left_out.empty()) message += ", " + std::to_string(left_out.size()) + " with no place by it left out";
          LogMove(sofa_id, to, "the sofa does not face its TV (" + why + "): floated before the TV, facing it", message, removed);
          return true;
        }
      }
    state = saved;
    return false;
  }

  // Issue 27: a sofa that cannot face its TV from anywhere before the stand's wall (a slanted wall that faces
  // a near one, a stretch the sofa cannot stand 2 m before): the stand to each other place with its back to
  // a wall, every 0.5 m along each, and the sofa with its group floated before it (FaceTv), the first where
  // the room's groups break fewer rules and the exact check is clean. True when one held.
  bool StandElsewhere(int sofa, int stand, const std::string& why) {
    const std::string sofa_id = state.objects[sofa].id, stand_id = state.objects[stand].id;
    const RoomState saved = state;
    const int trouble = GroupTrouble();
    const Pose home = state.placements[stand].pose;
    const OrientedBox box = state.WorldBox(stand);
    const double off_wall = state.objects[stand].wall_gap + box.hy;
    for (size_t w = 0; w < problem.walls.size(); ++w) {
      const WallEdge& wall = problem.walls[w];
      const Point d = geo::Unit(geo::Sub(wall.b, wall.a)), n = geo::Left(d);
      const double length = geo::Dist(wall.a, wall.b);
      for (double t = box.hx + 0.05; t <= length - box.hx - 0.05 + 1e-9; t += 0.5) {
        state = saved;
        const int k = state.Find(stand_id);
        Pose to = home;
        to.yaw = std::atan2(n.x, -n.y);  // its front into the room
        state.SetPose(k, to);            // turned first, then its box centred where it goes
        const Point target = geo::Add(geo::Add(wall.a, geo::Scale(d, t)), geo::Scale(n, off_wall));
        const Point now = state.WorldBox(k).c;
        to.x += target.x - now.x;
        to.y += target.y - now.y;
        state.SetPose(k, to);
        state.placements[k].wall = static_cast<int>(w);
        if (CostAt(k).hard > kHairline) continue;
        const size_t logged = summary.actions.size();
        if (!FaceTv(state.Find(sofa_id), k, why, /*slides=*/false, trouble)) continue;
        // The stand's move, logged before the sofa's.
        LogMove(stand_id, to, "the sofa cannot face its TV where it stands (" + why + "): the TV stand to another wall, the sofa before it");
        std::rotate(summary.actions.begin() + static_cast<long>(logged), summary.actions.end() - 1, summary.actions.end());
        return true;
      }
    }
    state = saved;
    return false;
  }

  // Object k to its best free place (FindSlot) when the room's groups break fewer rules there (GroupTrouble)
  // and the move is applied; else nothing changes (the state and the removals as they were).
  // `scale`: at that scale (a TV stand at its smallest, for a short stretch of wall between two doors).
  bool MoveIfTidier(int k, const std::string& reason, std::optional<double> scale = std::nullopt) {
    const RoomState saved = state;
    if (scale) {
      Pose smaller = state.placements[k].pose;
      smaller.scale = *scale;
      state.SetPose(k, smaller);
    }
    strict_groups = true;
    const std::optional<Slot> slot = FindSlot(k);
    strict_groups = false;
    if (scale) state = saved;
    if (!slot) return false;
    Action a;
    a.kind = ActionKind::kUpdatePose;
    a.id = state.objects[k].id;
    a.pose = slot->pose;
    if (scale) a.scale = *scale;
    if (slot->wall >= 0) a.wall = slot->wall;
    a.reason = reason;
    const size_t removed = summary.removed.size();
    const int before = GroupTrouble(/*seats=*/true);
    const bool clean = metrics.Clean();
    ActionResult r = Apply(a);
    // The exact check has the last word (the proxy passes a sofa a hair into a reflex corner).
    if (r.status != ActionStatus::kRefused && GroupTrouble(/*seats=*/true) < before && (!clean || ExactlyClean())) {
      summary.actions.push_back(std::move(r));
      ++summary.iterations;
      Check();
      return true;
    }
    state = saved;
    summary.removed.resize(removed);
    return false;
  }

  bool SmallerStand(int stand, const std::string& why) {
    const double smallest = state.objects[stand].scale_min;
    if (state.placements[stand].pose.scale <= smallest + 1e-9) return false;
    const std::string id = state.objects[stand].id, reason = "out of its group (" + why + "): smaller, to its best free place by its hub";
    if (MoveIfTidier(stand, reason, smallest)) return true;
    std::vector<std::string> ornaments;
    for (int c : state.children[stand])
      if (state.objects[c].category != "tv" && !IsProtected(state.objects[c].priority)) ornaments.push_back(state.objects[c].id);
    if (ornaments.empty()) return false;
    const Mark before = Here();
    for (const std::string& o : ornaments) TakeRemoval(o, "no room beside the TV on " + id + " made smaller to face its sofa: left out");
    if (const int k = state.Find(id); k >= 0 && MoveIfTidier(k, reason, smallest)) return true;
    Rewind(before);
    return false;
  }

  // Each dining or meeting chair that does not hold (SeatHolds) after the agent and the critic: what stands
  // in its pull-out room goes when nothing protected does and that frees it (a sideboard the agent moved
  // behind the chairs); else, with `moves`, it takes its group's best free seat where it holds; else it is
  // left out unless protected (a chair no one can pull out serves no one). Ends on the result when the
  // room is still clean. True when anything changed.
  bool TidyGroups(bool moves) {
    if (!options.functional_groups) return false;
    bool changed = false;
    std::vector<std::string> chairs, tables;
    for (size_t k = 0; k < state.objects.size(); ++k) {
      const int kk = static_cast<int>(k);
      if (TableSeat(kk)) chairs.push_back(state.objects[k].id);
      if (TableSeat(kk) && !SeatHolds(kk)) {
        const std::string& table = state.objects[GroupMembership(state, kk).hub].id;
        if (std::find(tables.begin(), tables.end(), table) == tables.end()) tables.push_back(table);
      }
    }
    // First the table with its chairs, to its best free place where every chair has its 0.75 m (a 2.5 m
    // square dining room seats two at a table in its corner, none across one in its middle).
    // Else with one piece of the room's unprotected furniture out of the way (not of the table's group,
    // nothing protected on it, hung things and floor coverings aside), the least important and biggest
    // first, three tried: the chairs' room comes before a cabinet.
    const std::string why = "its chairs have no room to pull out (0.75 m behind each): with them to its best free place";
    if (moves)
      for (const std::string& table : tables) {
        const int t = state.Find(table);
        if (t < 0) continue;
        if (MoveIfTidier(t, why)) {
          changed = true;
          continue;
        }
        std::vector<std::string> ids;
        for (int k : GiveWayPool(t))
          if (ids.size() < 3 && !state.Hung(k) && !state.IsFloorCovering(k)) ids.push_back(state.objects[k].id);
        for (const std::string& id : ids) {
          const Mark before = Here();
          TakeRemoval(id, "in the way of a place where the chairs of " + table + " can be pulled out: left out");
          if (const int tt = state.Find(table); tt >= 0 && MoveIfTidier(tt, why)) {
            changed = true;
            break;
          }
          Rewind(before);
        }
      }
    for (const std::string& id : chairs) {
      int j = state.Find(id);
      if (j < 0 || SeatHolds(j)) continue;
      std::set<int> blockers;
      SeatBehind(j, &blockers);
      const bool removable = !blockers.empty() && !blockers.count(-1) && std::none_of(blockers.begin(), blockers.end(), [&](int k) {
        const std::vector<int> below = state.Descendants(k);
        return IsProtected(state.objects[k].priority) || TableSeat(k) || GroupMembership(state, j).hub == k ||
               std::any_of(below.begin(), below.end(), [&](int d) { return IsProtected(state.objects[d].priority); });
      });
      if (removable) {
        std::vector<std::string> gone;
        for (int k : blockers) gone.push_back(state.objects[k].id);
        RoomState trial = state;
        for (const std::string& g : gone) trial.Remove(trial.Find(g));
        std::swap(state, trial);
        const bool frees = SeatHolds(state.Find(id));
        std::swap(state, trial);
        if (frees) {
          for (const std::string& g : gone) TakeRemoval(g, "in the room to pull " + id + " out from its table (0.75 m behind it)");
          changed = true;
          continue;
        }
      }
      if (moves) {
        if (auto slot = FindSlot(j)) {
          const ObjectPlacement before = state.placements[j];
          state.SetPose(j, slot->pose);
          const bool holds = SeatHolds(j) && CostAt(j).hard <= kFeasible;
          state.placements[j] = before;
          state.SetPose(j, before.pose);
          if (holds) {
            Action a;
            a.kind = ActionKind::kUpdatePose;
            a.id = id;
            a.pose = slot->pose;
            a.reason = "no room to pull it out from its table: to a free seat with 0.75 m behind it";
            TakeAction(a);
            j = state.Find(id);
            if (j >= 0 && SeatHolds(j)) {
              changed = true;
              continue;
            }
          }
        }
      }
      j = state.Find(id);
      if (j < 0) continue;
      // An essential chair that cannot be pulled out hands its rank to one of its table's chairs that can.
      if (state.objects[j].priority == Priority::kEssential) {
        const int hub = GroupMembership(state, j).hub;
        for (size_t k = 0; k < state.objects.size(); ++k) {
          const int kk = static_cast<int>(k);
          if (kk == j || !TableSeat(kk) || GroupMembership(state, kk).hub != hub || IsProtected(state.objects[k].priority) || !SeatHolds(kk))
            continue;
          std::swap(state.objects[k].priority, state.objects[j].priority);
          break;
        }
      }
      if (IsProtected(state.objects[j].priority)) continue;
      TakeRemoval(id, "no seat at its table with 0.75 m behind it to pull it out: left out");
      changed = true;
    }
    changed = DropUnseatedSettings() || changed;
    changed = DropTablelessChairs() || changed;
    // The other members out of their group's rules (a TV stand off the sofa's axis, a nightstand at the
    // bed's foot): with `moves`, to their best free place by the hub when it holds them (for a TV stand,
    // else the sofa with its group to its best free place); else an optional one is left out.
    std::vector<std::string> loose;
    for (size_t k = 0; k < state.objects.size(); ++k) {
      const int kk = static_cast<int>(k);
      if (!TableSeat(kk) && !GroupProblem(kk).empty()) loose.push_back(state.objects[k].id);
    }
    for (const std::string& id : loose) {
      int j = state.Find(id);
      if (j < 0 || GroupProblem(j).empty()) continue;
      const std::string why = GroupProblem(j);
      if (moves) {
        if (MoveIfTidier(j, "out of its group (" + why + "): to its best free place by its hub")) {
          changed = true;
          continue;
        }
        const Membership m = GroupMembership(state, j);
        if (m.role == GroupRole::kTvStand && AlignWithTv(m.hub, j, why)) {
          changed = true;
          continue;
        }
        if (m.role == GroupRole::kTvStand && MoveIfTidier(m.hub, "its TV stand is out of its group (" + why + "): with its group to its best free place")) {
          changed = true;
          continue;
        }
        if (m.role == GroupRole::kTvStand && FaceTv(m.hub, j, why)) {
          changed = true;
          continue;
        }
        // A smaller stand where the wall before the sofa has only a short stretch between its doors; the
        // ornaments beside its TV left out where the smaller top has no room for them (Refill puts back
        // what fits).
        if (m.role == GroupRole::kTvStand && SmallerStand(j, why)) {
          changed = true;
          continue;
        }
        if (m.role == GroupRole::kTvStand && StandElsewhere(m.hub, j, why)) {
          changed = true;
          continue;
        }
      }
      j = state.Find(id);
      if (j < 0 || GroupProblem(j).empty() || IsProtected(state.objects[j].priority)) continue;
      TakeRemoval(id, "out of its group (" + why + ") and no free place by its hub holds it: left out");
      changed = true;
    }
    // A pillow the bed's head has no room for (the second one on a narrow imported bed, turned mid-bed) is
    // left out: pillows lie at the head or not at all. The one nearest the head stays (a bed whose mattress
    // starts well below its box's head keeps a pillow).
    std::vector<std::string> pillows;
    for (size_t k = 0; k < state.objects.size(); ++k) {
      const int p = state.parent[k];
      if (state.objects[k].category != "pillow" || p < 0 || IsProtected(state.objects[k].priority) ||
          (state.objects[p].category != "bed" && state.objects[p].category != "child-bed"))
        continue;
      const OrientedBox bed = MattressBox(state.WorldBox(p), &state.objects[p].asset, state.placements[p].pose.scale);
      const Point at = state.WorldBox(static_cast<int>(k)).c;
      if (PillowProblem(at, bed).empty()) continue;
      bool nearer = false;  // another pillow on this bed lies nearer its head
      for (int c : state.children[p])
        nearer = nearer || (c != static_cast<int>(k) && state.objects[c].category == "pillow" &&
                            bed.Local(state.WorldBox(c).c).y > bed.Local(at).y + 1e-9);
      if (nearer) pillows.push_back(state.objects[k].id);
    }
    for (const std::string& id : pillows) {
      TakeRemoval(id, "no room for it at the bed's head: left out");
      changed = true;
    }
    if (moves) changed = PackKitchenRun() || changed;
    if (moves) changed = ClearSightlines() || changed;
    if (moves) changed = SquareUp() || changed;
    if (moves) changed = RugUnderGroup() || changed;
    if (changed && metrics.Clean()) {
      best = state;
      best_metrics = metrics;
      best_energy = energy;
    }
    if (changed) Finish(false);
    return changed;
  }

  // Whether a floor object stands within kRunGap of a counter (in a kitchen's run: the functional check's rule).
  bool TouchesCounter(int j) const {
    const OrientedBox box = state.WorldBox(j);
    for (size_t k = 0; k < state.objects.size(); ++k)
      if (static_cast<int>(k) != j && state.objects[k].category == "counter" && state.parent[k] < 0 &&
          PlanGap(box, state.WorldBox(static_cast<int>(k))) <= kRunGap)
        return true;
    return false;
  }

  // The hard cost of floor object i in its layer, leaving out its terms with things hung on the wall (a range
  // hood 0.69 m wide over a 0.5 m cooker overhangs the counter beside it, 0.3 m above its top: the layer's
  // plan test flags it, the exact check does not).
  double HardBesidesHung(int i) {
    Layer layer = LayerFor(i);
    std::vector<Term> terms = MakeTerms(layer, state, options, 0, -1.0);
    std::vector<Term> kept;
    for (Term& term : terms) {
      if (!term.hard) continue;
      const bool hung = std::any_of(term.bodies.begin(), term.bodies.end(), [&](int b) {
        return b >= 0 && b < static_cast<int>(layer.bodies.size()) && layer.bodies[b].object >= 0 &&
               state.objects[layer.bodies[b].object].relation == Relation::kOnWall;
      });
      if (!hung) kept.push_back(std::move(term));
    }
    return Evaluate(kept).hard + (TooTall(layer, i) ? 1.0 : 0.0);
  }

  // Issue 27: a cooker or fridge left off the run of counters because the run was laid piece by piece with
  // gaps (a kitchen of 3.3 m of wall held fridge, two counters and a cooker, 3.0 m, but the fridge stood
  // 0.49 m off the corner and the cooker found no end). The run on the counters' wall is packed toward one
  // end, in its order, and the stray piece stands at the other, beside the last counter; what hangs above a
  // moved piece (its upper cabinet, the range hood) moves with it. Kept when the room is exactly clean, no
  // group breaks and the piece touches a counter; else everything goes back. True when a piece joined.
  bool PackKitchenRun() {
    bool changed = false;
    for (const char* category : {"cooker", "fridge"}) {
      for (size_t k = 0; k < state.objects.size(); ++k) {
        const int j = static_cast<int>(k);
        if (state.objects[k].category != category || state.parent[k] >= 0 || TouchesCounter(j)) continue;
        // The counters' wall: the one most counters stand against.
        std::map<int, int> on_wall;
        for (size_t c = 0; c < state.objects.size(); ++c)
          if (state.objects[c].category == "counter" && state.parent[c] < 0 && state.placements[c].wall >= 0) ++on_wall[state.placements[c].wall];
        if (on_wall.empty()) continue;
        const int w = std::max_element(on_wall.begin(), on_wall.end(), [](auto& a, auto& b) { return a.second < b.second; })->first;
        const WallEdge& wall = problem.walls[w];
        const Point d = geo::Unit(geo::Sub(wall.b, wall.a));
        const double length = geo::Dist(wall.a, wall.b);
        auto along = [&](int i) { return geo::Dot(geo::Sub(state.WorldBox(i).c, wall.a), d); };
        auto half = [&](int i) { return 0.5 * state.objects[i].asset.size.x * state.placements[i].pose.scale; };
        std::vector<int> run;
        for (size_t c = 0; c < state.objects.size(); ++c)
          if (static_cast<int>(c) != j && state.parent[c] < 0 && state.placements[c].wall == w &&
              (state.objects[c].category == "counter" || state.objects[c].category == "fridge" ||
               state.objects[c].category == "cooker" || state.objects[c].category == "dishwasher"))
            run.push_back(static_cast<int>(c));
        if (run.empty()) continue;
        std::sort(run.begin(), run.end(), [&](int a, int b) { return along(a) < along(b); });
        const std::string id = state.objects[k].id;
        // Hung pieces above a moved one (behind it on the wall) follow it.
        auto hung_above = [&](int i) {
          std::vector<int> out;
          for (const SemanticEdge& e : state.edges)
            if (e.target == state.objects[i].id && e.relation == SemanticRelation::kBehind)
              if (const int h = state.Find(e.source); h >= 0 && state.objects[h].relation == Relation::kOnWall) out.push_back(h);
          return out;
        };
        bool joined = false;
        for (int direction : {+1, -1}) {  // packed toward the wall's start, the stray piece at its end; then the other way
          std::vector<int> order = run;
          if (direction < 0) std::reverse(order.begin(), order.end());
          // The piece at the open end must be a counter for the stray piece to join the run there.
          if (state.objects[order.back()].category != "counter") continue;
          // The run's length, 2 cm between pieces; it starts 3 cm off the corner (as the free floor keeps), or
          // further along past what stands in the corner (a fridge of the next wall's run), 5 cm at a time.
          const double gap = 0.02;
          double total = 0.0;
          for (int i : order) total += 2.0 * half(i) + gap;
          total += 2.0 * half(j);
          for (double start = 0.03; !joined && start + total <= length + 1e-9; start += 0.05) {
            const RoomState saved = state;
            const int trouble = GroupTrouble();
            double cursor = start;
            std::vector<std::pair<int, double>> targets;
            for (int i : order) {
              targets.push_back({i, cursor + half(i)});
              cursor += 2.0 * half(i) + gap;
            }
            targets.push_back({j, cursor + half(j)});
            std::vector<ActionResult> done;
            for (const auto& [i, t0] : targets) {
              const double t = direction > 0 ? t0 : length - t0;
              const Point at = geo::Add(wall.a, geo::Scale(d, t));
              const Pose from = state.placements[i].pose;
              const Pose to = StandAgainst(i, w, at, hung_above(i));
              if (std::hypot(to.x - from.x, to.y - from.y) < 1e-6) continue;
              ActionResult r;
              r.action.kind = ActionKind::kUpdatePose;
              r.action.id = state.objects[i].id;
              r.action.pose = to;
              r.action.wall = w;
              r.action.reason = i == j ? "off the run of counters: joins it, the run packed along its wall"
                                       : "the run of counters packed along its wall to make room for " + id;
              r.status = ActionStatus::kApplied;
              r.message = "done";
              r.final_pose = to;
              done.push_back(std::move(r));
            }
            // The cheap tests first, the exact check last.
            bool fine = TouchesCounter(j);
            for (const auto& [i, t0] : targets) fine = fine && HardBesidesHung(i) <= kFeasible;
            fine = fine && GroupTrouble() <= trouble && ExactlyClean();
            if (fine) {
              for (ActionResult& r : done) summary.actions.push_back(std::move(r));
              ++summary.iterations;
              Check();
              changed = joined = true;
            } else {
              state = saved;
            }
          }
          if (joined) break;
        }
        if (!joined) joined = TurnCorner(j, hung_above);
        changed = changed || joined;
      }
    }
    return changed;
  }

  // Object i against wall w at the point `at` of it (snapped: back to the wall, facing the room), the pieces
  // hung above it following it on that wall. Returns its new pose.
  Pose StandAgainst(int i, int w, Point at, const std::vector<int>& hung) {
    for (int k : hung) {
      Pose hp = state.placements[k].pose;
      hp.x = at.x;
      hp.y = at.y;
      state.placements[k].wall = w;
      state.SetPose(k, Snap(k, hp));
    }
    Pose want = state.placements[i].pose;
    want.x = at.x;
    want.y = at.y;
    state.placements[i].wall = w;
    const Pose to = Snap(i, want);
    state.SetPose(i, to);
    return to;
  }

  // The run turned round a corner (an L): stray piece j against the next wall, just past a counter whose
  // end stands against that wall, its side along the counter's front. Kept as PackKitchenRun keeps.
  template <class HungAbove>
  bool TurnCorner(int j, const HungAbove& hung_above) {
    const std::string id = state.objects[j].id;
    const double half_j = 0.5 * state.objects[j].asset.size.x * state.placements[j].pose.scale;
    for (size_t c = 0; c < state.objects.size(); ++c) {
      if (state.objects[c].category != "counter" || state.parent[c] >= 0) continue;
      const OrientedBox box = state.WorldBox(static_cast<int>(c));
      for (size_t w2 = 0; w2 < problem.walls.size(); ++w2) {
        if (static_cast<int>(w2) == state.placements[c].wall) continue;
        const WallEdge& wall = problem.walls[w2];
        const Point d = geo::Unit(geo::Sub(wall.b, wall.a));
        const double length = geo::Dist(wall.a, wall.b);
        // The counter's extent along this wall and how near it stands to it.
        double lo = 1e9, hi = -1e9, near = 1e9;
        for (int sx : {-1, 1})
          for (int sy : {-1, 1}) {
            const Point corner = geo::Add(geo::Add(box.c, geo::Scale(box.U(), sx * box.hx)), geo::Scale(box.V(), sy * box.hy));
            const double t = geo::Dot(geo::Sub(corner, wall.a), d);
            lo = std::min(lo, t), hi = std::max(hi, t);
            near = std::min(near, std::abs(geo::Cross(d, geo::Sub(corner, wall.a))));
          }
        if (near > 0.1) continue;  // its end does not stand against this wall
        for (const double t : {hi + 0.02 + half_j, lo - 0.02 - half_j}) {
          if (t - half_j < 0.0 || t + half_j > length) continue;
          const RoomState saved = state;
          const int trouble = GroupTrouble();
          const Point at = geo::Add(wall.a, geo::Scale(d, t));
          const Pose to = StandAgainst(j, static_cast<int>(w2), at, hung_above(j));
          if (TouchesCounter(j) && HardBesidesHung(j) <= kFeasible && GroupTrouble() <= trouble && ExactlyClean()) {
            ActionResult r;
            r.action.kind = ActionKind::kUpdatePose;
            r.action.id = id;
            r.action.pose = to;
            r.action.wall = static_cast<int>(w2);
            r.action.reason = "off the run of counters: joins it round the corner, beside " + state.objects[c].id;
            r.status = ActionStatus::kApplied;
            r.message = "done";
            r.final_pose = to;
            summary.actions.push_back(std::move(r));
            ++summary.iterations;
            Check();
            return true;
          }
          state = saved;
        }
      }
    }
    return false;
  }

  // Issue 27: what the agent, the critic or the reachability feedback removed while the room was still
  // settling (a wardrobe with its clothes that had no free slot when the bed was being fitted, books from a
  // shelf a neighbour crowded) put back where it fits now: each removed piece of the plan, parents before
  // what stands on or in them, at its best free slot (full size, else its smallest), kept where it collides
  // with nothing (the exact check has the last word), stays out of the walkways, keeps its group's rules
  // and breaks no other group's, and adds at most kRefillSemantic to E_sem (its own relations and the zones
  // it enters). Pillows stay out (the bed rule took them); a desk comes back with its chair or not at all.
  // True when anything came back.
  bool Refill() {
    if (!options.functional_groups) return false;
    bool changed = false;
    std::set<std::string> tried;
    for (int round = 0; round < 2; ++round)  // a parent put back in the first round brings its children in the second
      for (const ProblemObject& original : problem.objects) {
        if (state.Find(original.id) >= 0 || original.category == "pillow" || tried.count(original.id)) continue;
        if (IsChair(original) && TablelessRoom()) continue;  // nothing to sit at (DropTablelessChairs)
        if (!scene::IsRootParent(original.parent) && state.Find(original.parent) < 0) continue;
        tried.insert(original.id);
        const Mark before = Here();
        if (!PutBack(original)) continue;
        // A desk comes back with its chair, or not at all.
        bool whole = true;
        for (const ProblemObject& seat : problem.objects)
          if (whole && state.Find(seat.id) < 0 && IsDeskSeat(problem.edges, seat.id, original.id)) {
            tried.insert(seat.id);
            whole = PutBack(seat);
          }
        if (whole) {
          changed = true;
          continue;
        }
        Rewind(before);
      }
    if (changed) {
      best = state;
      best_metrics = metrics;
      best_energy = energy;
      Finish(false);
    }
    return changed;
  }

  bool PutBack(const ProblemObject& original) {
    constexpr double kRefillSemantic = 0.25;
    const RoomState saved = state;
    const EnergyTerms saved_energy = energy;
    const int trouble = GroupTrouble(/*seats=*/true);  // nothing comes back into a chair's pull-out room
    state.objects.push_back(original);
    state.placements.push_back({});
    state.placements.back().surface = original.surface;  // the problem's own choices; -1: AssignSupports picks
    state.placements.back().cavity = original.cavity;
    state.placements.back().wall = original.wall;
    for (const SemanticEdge& e : problem.edges) {
      const std::string& other = e.source == original.id ? e.target : e.target == original.id ? e.source : "";
      if (!other.empty() && state.Find(other) >= 0) state.edges.push_back(e);
    }
    state.Reindex();
    AssignSupports(state);
    const RoomState added = state;
    const double full = std::clamp(1.0, original.scale_min, original.scale_max);
    std::vector<double> scales{full};  // full size, else the smallest
    if (original.scale_min < full - 1e-9) scales.push_back(original.scale_min);
    for (double scale : scales) {
      state = added;
      const int i = static_cast<int>(state.objects.size()) - 1;
      state.placements[i].pose.scale = scale;  // its surface, cavity or wall as AssignSupports chose
      state.placements[i].pose.z = state.Hung(i) ? problem.floor_z : state.SupportHeight(i);
      const std::optional<Slot> slot = FindSlot(i);
      if (!slot) continue;
      ObjectPlacement& pl = state.placements[i];
      pl.surface = slot->surface;
      pl.cavity = slot->cavity;
      pl.wall = slot->wall;
      pl.placed = true;
      state.SetPose(i, slot->pose);
      if (CostAt(i).hard > kFeasible || !GroupProblem(i).empty() || (TableSeat(i) && !SeatHolds(i)) || GroupTrouble(true) > trouble)
        continue;
      const EnergyTerms e = StateEnergy(state);
      // The coffee table or TV stand a sofa lacks completes its group by its rules (GroupProblem, above): the
      // relations it brings along may cost more than a decorative piece may.
      const GroupRole role = GroupMembership(state, i).role;
      const bool completes = role == GroupRole::kCoffeeTable || role == GroupRole::kTvStand;
      if (e.collision > 0.0 || e.support > 0.0 || (!completes && e.semantic > saved_energy.semantic + kRefillSemantic) || !ExactlyClean())
        continue;
      ActionResult r;
      r.action.kind = ActionKind::kAddEntity;
      r.action.id = original.id;
      r.action.pose = slot->pose;
      r.action.reason = "removed while the room was settling; it fits now: put back at its best free slot" +
                        std::string(scale < 1.0 - 1e-9 ? " at its smallest scale" : "");
      r.status = ActionStatus::kApplied;
      r.message = "put back";
      r.final_pose = slot->pose;
      summary.actions.push_back(r);
      summary.removed.erase(std::remove(summary.removed.begin(), summary.removed.end(), original.id), summary.removed.end());
      Check();
      return true;
    }
    state = saved;
    energy = saved_energy;
    return false;
  }

  // A rug of a room with a seating group lies under its coffee table, turned like the sofa (the rug is laid
  // first, on its own; the group is arranged after it). Kept where the rug stays clear of doors and walls.
  bool RugUnderGroup() {
    for (size_t k = 0; k < state.objects.size(); ++k) {
      const int coffee = static_cast<int>(k);
      const Membership m = GroupMembership(state, coffee);
      if (m.role != GroupRole::kCoffeeTable) continue;
      for (size_t r = 0; r < state.objects.size(); ++r) {
        const int rug = static_cast<int>(r);
        if (state.objects[r].category != "rug" || !state.IsFloorCovering(rug)) continue;
        const Pose from = state.placements[rug].pose;
        const Pose& sofa = state.placements[m.hub].pose;
        // Its near edge 2 cm before the sofa's front, centred on the sofa's axis, the coffee table on it;
        // long side along the sofa, else across it.
        const OrientedBox sofa_box = state.WorldBox(m.hub);
        const Point front = geo::Add(sofa_box.c, geo::Scale(sofa_box.Front(), sofa_box.hy));
        const RoomState saved = state;
        for (double turn : {0.0, 0.5 * std::numbers::pi}) {
          Pose to = from;
          to.yaw = WrapAngle(sofa.yaw + turn);
          const double half = turn == 0.0 ? 0.5 * state.objects[r].asset.size.y : 0.5 * state.objects[r].asset.size.x;
          const Point c = geo::Add(front, geo::Scale(sofa_box.Front(), half * from.scale + 0.02));
          to.x = c.x;
          to.y = c.y;
          if (std::hypot(to.x - from.x, to.y - from.y) < 0.05 && std::abs(WrapAngle(to.yaw - from.yaw)) < 0.01) return false;
          state.SetPose(rug, to);
          bool ok = CostAt(rug).hard <= kHairline;
          // What stands on the floor keeps its support (a lamp half on the rug's edge would tilt).
          for (size_t j = 0; j < state.objects.size() && ok; ++j)
            ok = state.parent[j] >= 0 || static_cast<int>(j) == rug || CostAt(static_cast<int>(j)).hard <= kHairline;
          if (ok && ExactlyClean()) {
            LogMove(state.objects[r].id, to, "under its seating group: between the sofa and the coffee table, turned like the sofa");
            return true;
          }
          state = saved;
        }
        return false;
      }
    }
    return false;
  }

  // Furniture a few degrees off the room's walls (the polish's yaw freedom) turned square to them, and a
  // coffee or side table turned like its sofa. Kept where nothing collides (the exact check has the last
  // word) and no group breaks more rules. True when anything turned.
  bool SquareUp() {
    constexpr double kMaxTurn = 20.0 * std::numbers::pi / 180.0, kMinTurn = 0.5 * std::numbers::pi / 180.0;
    const std::vector<double> classes = RoomYawClasses(problem);
    std::vector<std::string> ids;
    for (int pass = 0; pass < 2; ++pass)  // hubs and loners first, then the members that turn like their hub
      for (size_t k = 0; k < state.objects.size(); ++k) {
        const int kk = static_cast<int>(k);
        if (state.parent[k] >= 0 || state.Hung(kk)) continue;
        const bool member = GroupMembership(state, kk).role != GroupRole::kNone;
        if (member == (pass == 1)) ids.push_back(state.objects[k].id);
      }
    bool turned = false;
    for (const std::string& id : ids) {
      const int k = state.Find(id);
      if (k < 0) continue;
      const Membership m = GroupMembership(state, k);
      const Pose from = state.placements[k].pose;
      double yaw = SnapYaw(from.yaw, classes);
      if (m.role == GroupRole::kCoffeeTable || m.role == GroupRole::kSideTable) yaw = SnapYaw(from.yaw, {state.placements[m.hub].pose.yaw});
      else if (m.role != GroupRole::kNone) continue;  // seats and stands keep their template's facing
      const double turn = WrapAngle(yaw - from.yaw);
      if (std::abs(turn) < kMinTurn || std::abs(turn) > kMaxTurn) continue;
      const RoomState saved = state;
      const int trouble = GroupTrouble();
      // Turned where it stands, else shifted up to 15 cm as well (a corner of it would touch a wall); its
      // group's members stay (each is squared in turn), as long as they keep their group's rules.
      Pose to = from;
      bool ok = false;
      for (double r = 0.0; r < 0.16 && !ok; r += 0.05)
        for (int a = 0; a < (r == 0.0 ? 1 : 8) && !ok; ++a) {
          state = saved;
          to = from;
          to.yaw = WrapAngle(from.yaw + turn);
          to.x += r * std::cos(a * std::numbers::pi / 4.0);
          to.y += r * std::sin(a * std::numbers::pi / 4.0);
          state.SetPose(k, to);
          // The proxies keep a margin: within a hair of it, the exact check decides.
          ok = CostAt(k).hard <= kHairline && GroupTrouble() <= trouble && ExactlyClean();
        }
      if (!ok) {
        state = saved;
        continue;
      }
      LogMove(id, to,
              "square to the walls" + std::string(m.role != GroupRole::kNone ? " (turned like its sofa)" : "") + ": turned " +
                  Fixed(std::abs(turn) * 180.0 / std::numbers::pi, 1) + " degrees");
      turned = true;
    }
    return turned;
  }

  void RunAgent() {
    bool stuck = false;
    for (int it = 0; it < options.agent_iterations; ++it) {
      if (Converged(metrics, energy)) break;
      std::optional<Action> action = NextAction();
      if (!action) {
        stuck = true;
        break;
      }
      summary.actions.push_back(Apply(*action));
      ++summary.iterations;
      Check();
    }
    Finish(stuck);
  }

  // Ends on the best state seen (its check again, with the clearance figure this time) and says why.
  void Finish(bool stuck) {
    state = best;
    energy = best_energy;
    const auto t = Clock::now();
    metrics = checker->Check(state, true);
    summary.seconds_exact += Since(t);
    summary.metrics = metrics;
    summary.energy = energy;
    if (Converged(metrics, energy)) {
      summary.outcome = Outcome::kConverged;
      summary.reason = "E = " + Fixed(energy.total) + " <= " + Fixed(options.energy_threshold, 2) + ", exact check clean";
      if (!summary.removed.empty()) {
        summary.reason += ", after removing " + std::to_string(summary.removed.size()) + " object(s) that did not fit";
      }
    } else if (metrics.Clean() && energy.collision == 0.0 && energy.support == 0.0) {
      summary.outcome = Outcome::kBudget;
      summary.reason = "physically valid, but E = " + Fixed(energy.total) + " (semantic " + Fixed(energy.semantic) +
                       ") stays above " + Fixed(options.energy_threshold, 2) +
                       (stuck ? ": no move lowers it further" : ": iterations spent");
    } else if (std::vector<std::string> kept = ProtectedInWalkways(); metrics.Clean() && energy.support == 0.0 && !kept.empty()) {
      // Only the reachability feedback's walkways are entered, by objects the room keeps (issue 27).
      summary.outcome = Outcome::kBudget;
      std::string ids;
      for (const std::string& id : kept) ids += (ids.empty() ? "" : ", ") + id;
      summary.reason = "physically valid; kept in a walkway the reachability check laid (essential or named): " + ids;
    } else if (stuck) {
      summary.outcome = Outcome::kInfeasible;
      summary.reason = std::to_string(Violations(metrics)) + " exact violation(s) left after every remedy (move, shrink, remove)";
    } else {
      summary.outcome = Outcome::kBudget;
      summary.reason = std::to_string(Violations(metrics)) + " exact violation(s) left when the iterations ran out";
    }
  }
};

RoomSolver::RoomSolver(const RoomProblem& problem, const SolveOptions& options, const ExactCheckOptions& check)
    : impl_(new Impl(problem, options, check)) {}
RoomSolver::~RoomSolver() = default;

Status RoomSolver::Initialise() {
  Impl& im = *impl_;
  im.start = Clock::now();
  std::string message;
  if (!im.options.IsValid(&message)) return Error{"solver options: " + message};
  if (!im.check_options.IsValid(&message)) return Error{"exact check options: " + message};
  if (Status s = im.problem.Check(); !s.ok()) return s;
  im.state = RoomState::From(im.problem);
  for (const ProblemObject& o : im.problem.objects) {
    im.coffee_planned = im.coffee_planned || o.category == "coffee-table";
    im.tv_planned = im.tv_planned || o.category == "tv-stand";
  }
  im.checker = std::make_unique<ExactChecker>(im.problem, im.check_options);
  im.SolveLayers();
  im.Check();
  im.summary.metrics = im.metrics;
  im.summary.energy = im.energy;
  im.initialised = true;
  im.summary.seconds = Since(im.start);
  return Status::Ok();
}

ActionResult RoomSolver::Apply(const Action& action) {
  Impl& im = *impl_;
  if (!im.initialised) {
    ActionResult r;
    r.action = action;
    return im.Refuse(r, "the solver is not initialised");
  }
  ActionResult r = im.Apply(action);
  im.summary.actions.push_back(r);
  im.Check();
  im.summary.metrics = im.metrics;
  im.summary.energy = im.energy;
  return r;
}

bool RoomSolver::Fits(const std::string& id, const Pose& pose, std::optional<int> wall) {
  Impl& im = *impl_;
  const int i = im.initialised ? im.state.Find(id) : -1;
  if (i < 0) return false;
  if (wall && (*wall < 0 || *wall >= static_cast<int>(im.problem.walls.size()))) return false;
  const RoomState saved = im.state;
  if (wall) im.state.placements[i].wall = *wall;
  Pose want = pose;
  if (std::isnan(want.z)) want.z = im.state.placements[i].pose.z;
  im.state.SetPose(i, im.Snap(i, want, wall.has_value()));
  const bool fits = im.CostAt(i).hard <= kFeasible;
  im.state = saved;
  return fits;
}

std::optional<ObjectPlacement> RoomSolver::Suggest(const std::string& id) {
  Impl& im = *impl_;
  const int i = im.initialised ? im.state.Find(id) : -1;
  if (i < 0) return std::nullopt;
  auto slot = im.FindSlot(i);
  if (!slot) return std::nullopt;
  ObjectPlacement out = im.state.placements[i];
  out.pose = slot->pose;
  out.wall = slot->wall;
  out.surface = slot->surface;
  out.cavity = slot->cavity;
  return out;
}

void RoomSolver::RunAgent() {
  Impl& im = *impl_;
  if (!im.initialised) return;
  im.RunAgent();
  im.summary.seconds = Since(im.start);
}

bool RoomSolver::TidyGroups(bool moves) {
  Impl& im = *impl_;
  if (!im.initialised) return false;
  const bool changed = im.TidyGroups(moves);
  im.summary.seconds = Since(im.start);
  return changed;
}

bool RoomSolver::Refill() {
  Impl& im = *impl_;
  if (!im.initialised) return false;
  const bool changed = im.Refill();
  im.summary.seconds = Since(im.start);
  return changed;
}

void RoomSolver::Finish() {
  Impl& im = *impl_;
  if (!im.initialised) return;
  im.Finish(false);
  im.summary.seconds = Since(im.start);
}

bool RoomSolver::Lift(const std::string& id, double dz) {
  Impl& im = *impl_;
  if (!im.initialised || !(dz > 0.0) || dz > kMaxOutOfHull + 1e-12) return false;
  const int i = im.state.Find(id);
  if (i < 0 || im.state.parent[i] < 0 || im.state.objects[i].relation != Relation::kOnTop ||
      im.state.placements[i].lift + dz > kMaxOutOfHull + 1e-12)
    return false;
  const RoomState saved = im.state;
  im.state.placements[i].lift += dz;
  Pose raised = im.state.placements[i].pose;
  raised.z = im.state.SupportHeight(i);
  im.state.SetPose(i, raised);
  im.Check();
  if (!im.metrics.Clean()) {
    im.state = saved;
    im.Check();
    return false;
  }
  ActionResult r;
  r.action.kind = ActionKind::kUpdatePose;
  r.action.id = id;
  r.action.pose = raised;
  r.action.reason = "physics: starts " + Fixed(1000.0 * dz, 1) + " mm inside its parent's collision hull: raised onto it";
  r.status = ActionStatus::kApplied;
  r.message = "done";
  r.final_pose = raised;
  im.summary.actions.push_back(std::move(r));
  im.summary.metrics = im.metrics;
  im.summary.energy = im.energy;
  KeepCurrent();
  return true;
}

bool RoomSolver::MoveOutOfParent(const std::string& id, Vec3 out, double depth) {
  const double step = depth + 0.0005, flat = std::hypot(out.x, out.y);
  if (std::abs(out.z) >= std::sqrt(0.5)) return Lift(id, step);
  Impl& im = *impl_;
  const int i = im.state.Find(id);
  if (!im.initialised || i < 0 || im.state.parent[i] < 0 || !(flat > 1e-9) || !(step <= kMaxOutOfHull)) return false;
  Action a;
  a.kind = ActionKind::kUpdatePose;
  a.id = id;
  Pose to = im.state.placements[i].pose;
  to.x += step * out.x / flat;
  to.y += step * out.y / flat;
  to.z = std::nan("");  // from its support
  a.pose = to;
  a.reason = "physics: starts " + Fixed(1000.0 * depth, 1) + " mm inside its parent's collision hull: slid off it";
  if (Apply(a).status != ActionStatus::kApplied) return false;  // (Apply refuses what breaks a hard constraint)
  KeepCurrent();
  return true;
}

void RoomSolver::KeepCurrent() {
  Impl& im = *impl_;
  if (!im.initialised) return;
  im.best = im.state;
  im.best_metrics = im.metrics;
  im.best_energy = im.energy;
  im.have_best = true;
}

struct RoomSolver::Snapshot {
  std::string room;
  RoomState state;
  ExactMetrics metrics;
  EnergyTerms energy;
  std::vector<std::string> removed;
};

std::shared_ptr<const RoomSolver::Snapshot> RoomSolver::Save() const {
  const Impl& im = *impl_;
  return std::make_shared<const Snapshot>(Snapshot{im.problem.room, im.state, im.metrics, im.energy, im.summary.removed});
}

void RoomSolver::Restore(const Snapshot& snapshot) {
  Impl& im = *impl_;
  if (!im.initialised || snapshot.room != im.problem.room) return;
  im.state = snapshot.state;
  im.metrics = snapshot.metrics;
  im.energy = snapshot.energy;
  im.summary.removed = snapshot.removed;  // what came back is no longer removed
  im.summary.metrics = im.metrics;
  im.summary.energy = im.energy;
  im.summary.energy_trace.push_back(im.energy.total);
  KeepCurrent();
}

const RoomProblem& RoomSolver::Problem() const { return impl_->problem; }

Status RoomSolver::AddKeepOuts(const std::vector<KeepOut>& zones) {
  Impl& im = *impl_;
  if (!im.initialised) return Error{"room " + im.problem.room + ": the solver is not initialised"};
  const size_t before = im.problem.keep_outs.size();
  im.problem.keep_outs.insert(im.problem.keep_outs.end(), zones.begin(), zones.end());
  if (Status s = im.problem.Check(); !s.ok()) {
    im.problem.keep_outs.resize(before);
    return s;
  }
  // The arrangement is judged anew against the zones: every remedy may be tried again on what stands in
  // them, and the best state so far is the present one (the old best never saw them).
  im.tries.clear();
  im.semantic_tried.clear();
  im.have_best = false;
  im.Check();
  im.summary.metrics = im.metrics;
  im.summary.energy = im.energy;
  return Status::Ok();
}

RoomSolution RoomSolver::Solution() const {
  RoomSolution s;
  s.objects = impl_->state.objects;
  s.placements = impl_->state.placements;
  s.edges = impl_->state.edges;
  s.summary = impl_->summary;
  return s;
}

Result<RoomSolution> SolveRoom(const RoomProblem& problem, const SolveOptions& options, const ExactCheckOptions& check) {
  RoomSolver solver(problem, options, check);
  if (Status s = solver.Initialise(); !s.ok()) return Error{s.error()};
  solver.RunAgent();
  return solver.Solution();
}

std::string SolveSummary::BriefReport() const {
  std::string out;
  out += "outcome: " + std::string(OutcomeName(outcome)) + " (" + reason + ")\n";
  out += "objects: " + std::to_string(metrics.objects);
  if (!removed.empty()) {
    out += ", removed " + std::to_string(removed.size()) + ":";
    for (const std::string& id : removed) out += " " + id;
  }
  out += "\n";
  out += "exact: CR " + Fixed(metrics.cr, 3) + "  FR " + Fixed(metrics.fr, 3) + "  OBR " + Fixed(metrics.obr, 3) + "  CSR " +
         Fixed(metrics.csr, 3) + " (" + std::to_string(metrics.contained) + "/" + std::to_string(metrics.inside_edges) + ")\n";
  out += "energy: E " + Fixed(energy.total) + " = 5 x " + Fixed(energy.collision, 6) + " + 2 x " + Fixed(energy.support) +
         " + " + Fixed(energy.semantic) + "\n";
  int applied = 0, repaired = 0, refused = 0;
  for (const ActionResult& a : actions) {
    applied += a.status == ActionStatus::kApplied;
    repaired += a.status == ActionStatus::kRepaired;
    refused += a.status == ActionStatus::kRefused;
  }
  out += "agent: " + std::to_string(iterations) + " iteration(s), " + std::to_string(actions.size()) + " action(s) (" +
         std::to_string(applied) + " applied, " + std::to_string(repaired) + " repaired, " + std::to_string(refused) +
         " refused)\n";
  out += "time: " + Fixed(seconds, 3) + " s (placement " + Fixed(seconds_place, 3) + ", ceres " + Fixed(seconds_ceres, 3) +
         " in " + std::to_string(ceres_solves) + " solves / " + std::to_string(ceres_iterations) + " iterations" +
         (sparse ? " sparse" : " dense") + ", exact " + Fixed(seconds_exact, 3) + ")\n";
  return out;
}

nlohmann::ordered_json SolveSummary::SolveRecord() const {
  nlohmann::ordered_json j;
  j["outcome"] = std::string(OutcomeName(outcome));
  j["reason"] = reason;
  j["iterations"] = iterations;
  j["energy"] = std::round(energy.total * 1e4) / 1e4;
  j["removed"] = removed;
  j["actions"] = nlohmann::ordered_json::array();
  for (const ActionResult& a : actions) j["actions"].push_back(ActionResultToJson(a));
  return j;
}

}  // namespace villa::solver
