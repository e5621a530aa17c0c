#include "solver/reach_feedback.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <set>

#include "layout/geometry.h"
#include "mesh/geometry2d.h"
#include "scene/scene.h"
#include "solver/place.h"
#include "solver/energy.h"
#include "solver/free_space.h"

namespace villa::solver {
namespace {

using namespace villa::geo;

std::string Fixed(double v, int digits) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, v);
  return buffer;
}

// Rectangles along a way on one level, `half` m either side and beyond each end (so consecutive pieces
// overlap at the corners), kept where they come within 0.5 m of the room's bounding box.
std::vector<KeepOut> WalkwayPieces(const std::vector<std::pair<int, std::vector<Point>>>& way, int level, double floor_z,
                                   double head, double half, const Ring& room, const std::string& target) {
  Point lo{1e300, 1e300}, hi{-1e300, -1e300};
  for (const Point& p : room) lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)}, hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  std::vector<KeepOut> out;
  for (const auto& [l, points] : way) {
    if (l != level || points.empty()) continue;
    for (size_t k = 0; k + 1 < points.size() || (points.size() == 1 && k == 0); ++k) {
      const Point a = points[k], b = points.size() == 1 ? points[k] : points[k + 1];
      const Point d = Dist(a, b) > 1e-9 ? Unit(Sub(b, a)) : Point{1.0, 0.0};
      const Point n = Left(d);
      const Point a0 = Sub(a, Scale(d, half)), b0 = Add(b, Scale(d, half));
      Ring rect = {Sub(a0, Scale(n, half)), Sub(b0, Scale(n, half)), Add(b0, Scale(n, half)), Add(a0, Scale(n, half))};
      bool near = false;
      for (const Point& p : rect) near |= p.x >= lo.x - 0.5 && p.x <= hi.x + 0.5 && p.y >= lo.y - 0.5 && p.y <= hi.y + 0.5;
      if (near) out.push_back({std::move(rect), floor_z, floor_z + head, KeepOutKind::kWalkway, "to " + target});
    }
  }
  return out;
}

// Whether a person standing on a reached cell touches one of `zone`'s boxes with their disc clear of
// `owner` (the owner's box where it would stand; the cells were reached with it elsewhere). Every other
// cell is tried: the check after the move decides.
// Whether a person's disc of `radius` at p keeps clear of box b.
bool DiscClearOf(const OrientedBox& b, Point p, double radius) {
  const Point d = Sub(p, b.c);
  return std::hypot(std::max(0.0, std::abs(Dot(d, b.U())) - b.hx), std::max(0.0, std::abs(Dot(d, b.V())) - b.hy)) >= radius;
}

bool ZoneTouchable(const ReachedCells& cells, const std::vector<Ring>& zone, const OrientedBox& owner, double radius) {
  for (const Ring& z : zone) {
    if (z.empty()) continue;
    const Box2 box = BoundingBox(z);
    const int i0 = std::max(0, static_cast<int>(std::floor((box.min_x - radius - cells.x0) / cells.cell)));
    const int j0 = std::max(0, static_cast<int>(std::floor((box.min_y - radius - cells.y0) / cells.cell)));
    const int i1 = std::min(cells.nx - 1, static_cast<int>(std::floor((box.max_x + radius - cells.x0) / cells.cell)));
    const int j1 = std::min(cells.ny - 1, static_cast<int>(std::floor((box.max_y + radius - cells.y0) / cells.cell)));
    for (int j = j0; j <= j1; j += 2) {
      for (int i = i0; i <= i1; i += 2) {
        if (!cells.reached[static_cast<long>(j) * cells.nx + i]) continue;
        const Point p{cells.x0 + (i + 0.5) * cells.cell, cells.y0 + (j + 0.5) * cells.cell};
        const double d = PointInRing(p, z, 0) ? 0.0 : DistanceToBoundary(p, z);
        if (d <= radius && DiscClearOf(owner, p, radius)) return true;
      }
    }
  }
  return false;
}

// A place the last resort may move an object to: its pose, the wall it backs onto (-1: none) and how far
// it is from where the object stands (m; the nearest are tried first).
struct Slot {
  Pose pose;
  int wall = -1;
  double distance = 0.0;
};

constexpr double kPi = 3.14159265358979323846;

double WrapYaw(double yaw) {
  double y = std::remainder(yaw, 2.0 * kPi);
  return y <= -kPi ? y + 2.0 * kPi : y;
}

// Slots for a floor object, nearest its place first: against a wall, every `step` m along each wall with
// its back to it; standing free, every `step` m over the room's floor in its yaw and the three quarter
// turns of it.
std::vector<Slot> FloorSlots(const RoomProblem& problem, const ProblemObject& o, const ObjectPlacement& pl, double step) {
  std::vector<Slot> out;
  const Point at{pl.pose.x, pl.pose.y};
  if (o.relation == Relation::kAgainstWall) {
    const double off = 0.5 * o.asset.size.y * pl.pose.scale + o.wall_gap;
    for (size_t w = 0; w < problem.walls.size(); ++w) {
      const WallEdge& e = problem.walls[w];
      const double len = Dist(e.a, e.b);
      if (len < 1e-6) continue;
      const Point d = Unit(Sub(e.b, e.a)), n = Left(d);  // the room is on the wall's left
      for (double t = 0.5 * step; t < len; t += step) {
        const Point c = Add(Add(e.a, Scale(d, t)), Scale(n, off));
        Pose p = pl.pose;
        p.x = c.x, p.y = c.y, p.yaw = std::atan2(n.x, -n.y);  // the front, (sin yaw, -cos yaw), faces n
        out.push_back({p, static_cast<int>(w), Dist(c, at)});
      }
    }
  } else if (o.relation == Relation::kOnTop && o.parent == "floor" && !problem.free_floor.empty()) {
    Point lo = problem.free_floor[0], hi = lo;
    for (const Point& p : problem.free_floor) lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)}, hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    for (double y = lo.y + 0.5 * step; y < hi.y; y += step) {
      for (double x = lo.x + 0.5 * step; x < hi.x; x += step) {
        if (!PointInRing({x, y}, problem.free_floor, 0)) continue;
        for (int k = 0; k < 4; ++k) {
          Pose p = pl.pose;
          p.x = x, p.y = y, p.yaw = WrapYaw(pl.pose.yaw + k * 0.5 * kPi);
          out.push_back({p, -1, Dist({x, y}, at) + 1e-3 * k});
        }
      }
    }
  }
  std::stable_sort(out.begin(), out.end(), [](const Slot& a, const Slot& b) { return a.distance < b.distance; });
  return out;
}

// The share of `zone`'s boxes within `radius` of a reached cell whose disc keeps clear of `owner` (the
// owner's box where it would stand), sampled every 4 cm: ZoneShare's measure (solver/reach.cpp) on the
// cells reached with the owner elsewhere. Every other cell is tried, like ZoneTouchable.
double ZoneCover(const ReachedCells& cells, const std::vector<Ring>& zone, const OrientedBox& owner, double radius) {
  constexpr double kSample = 0.04;
  const int k = static_cast<int>(std::ceil(radius / cells.cell));
  long inside = 0, covered = 0;
  for (const Ring& z : zone) {
    if (z.empty()) continue;
    const Box2 box = BoundingBox(z);
    for (double y = box.min_y + 0.5 * kSample; y < box.max_y; y += kSample) {
      for (double x = box.min_x + 0.5 * kSample; x < box.max_x; x += kSample) {
        const Point p{x, y};
        if (!PointInRing(p, z, 0)) continue;
        ++inside;
        const int ci = static_cast<int>(std::floor((x - cells.x0) / cells.cell)), cj = static_cast<int>(std::floor((y - cells.y0) / cells.cell));
        bool hit = false;
        for (int j = std::max(0, cj - k); j <= std::min(cells.ny - 1, cj + k) && !hit; j += 2) {
          for (int i = std::max(0, ci - k); i <= std::min(cells.nx - 1, ci + k) && !hit; i += 2) {
            if (!cells.reached[static_cast<long>(j) * cells.nx + i]) continue;
            const Point q{cells.x0 + (i + 0.5) * cells.cell, cells.y0 + (j + 0.5) * cells.cell};
            hit = Dist(p, q) <= radius && DiscClearOf(owner, q, radius);
          }
        }
        covered += hit;
      }
    }
  }
  return inside ? static_cast<double>(covered) / inside : 0.0;
}

// Moves object `id` of `solver` to the nearest slot, at most `max_move` m away, where `good` holds for its
// box and zone there and that keeps the room's hard constraints; the action's result, or nothing when no
// slot does. `why` ends the action's reason ("... moved 0.40 m to a free slot WHY"). An object with no
// interaction zone is moved only when `zoneless` (`good` then sees no zone).
std::optional<ActionResult> MoveToSlot(RoomSolver& solver, const std::string& id, const ReachFeedbackOptions& options, double max_move,
                                       const std::string& cause,
                                       const std::function<bool(const OrientedBox&, const std::vector<Ring>&)>& good,
                                       const std::string& why, const std::function<bool()>& keep = nullptr, bool zoneless = false) {
  const RoomSolution now = solver.Solution();
  int i = -1;
  for (size_t k = 0; k < now.objects.size() && k < now.placements.size(); ++k) {
    if (now.objects[k].id == id && now.placements[k].placed) i = static_cast<int>(k);
  }
  if (i < 0) return std::nullopt;
  const ProblemObject& o = now.objects[i];
  const std::optional<InteractionZone> zone = ZoneOf(o);
  if (!zone && !zoneless) return std::nullopt;
  int tries = 0, refused = 0;
  for (const Slot& slot : FloorSlots(solver.Problem(), o, now.placements[i], options.slot_step)) {
    if (slot.distance > max_move) break;
    const OrientedBox box = StandingBox(o, slot.pose);
    if (!good(box, zone ? ZoneFootprints(box, zone->side, zone->depth * slot.pose.scale) : std::vector<Ring>{})) continue;
    const std::optional<int> wall = slot.wall >= 0 ? std::optional<int>(slot.wall) : std::nullopt;
    if (!solver.Fits(id, slot.pose, wall)) {
      if (++tries >= options.slot_tries) break;
      continue;
    }
    Action a;
    a.kind = ActionKind::kUpdatePose;
    a.id = id;
    a.pose = slot.pose;
    a.wall = wall;
    a.reason = "reachability: " + cause + "; moved " + Fixed(slot.distance, 2) + " m to a free slot " + why;
    const std::shared_ptr<const RoomSolver::Snapshot> undo = keep ? solver.Save() : nullptr;
    ActionResult r = solver.Apply(a);
    if (r.status != ActionStatus::kRefused) {
      if (!keep || keep()) return r;
      solver.Restore(*undo);  // the move costs what `keep` guards: the next slot
    } else if (++refused >= 3) {
      break;  // a member its group holds (or a hub its members): farther slots are refused alike
    }
    if (++tries >= options.slot_tries) break;
  }
  return std::nullopt;
}

// Moves object `id` of `solver` to the nearest slot whose zone a person on `cells` touches and that keeps
// the room's hard constraints; the action's result, or nothing when no slot does.
std::optional<ActionResult> MoveToReachableSlot(RoomSolver& solver, const std::string& id, const ReachedCells& cells,
                                                const ReachFeedbackOptions& options) {
  return MoveToSlot(
      solver, id, options, std::numeric_limits<double>::infinity(), "its zone cannot be reached where it stands",
      [&](const OrientedBox& box, const std::vector<Ring>& zone) { return ZoneTouchable(cells, zone, box, options.reach.radius); },
      "a person can step up to");
}

bool Protected(const RoomSolver& solver, const std::string& id) {
  const int i = solver.Problem().Find(id);
  return i >= 0 && IsProtected(solver.Problem().objects[i].priority);
}

// Removes object `id`, unless it is protected (an essential piece of its room, or named in the request:
// issue 27) and `even_protected` is false: then the action is refused with why, and the zone or way it
// closes is reported instead.
ActionResult Remove(RoomSolver& solver, const std::string& id, const std::string& why, bool even_protected = false) {
  Action a;
  a.kind = ActionKind::kRemoveEntity;
  a.id = id;
  a.reason = "reachability: " + why;
  const RoomProblem& problem = solver.Problem();
  if (const int i = problem.Find(id); !even_protected && i >= 0 && IsProtected(problem.objects[i].priority)) {
    ActionResult r;
    r.action = a;
    r.status = ActionStatus::kRefused;
    r.message = "kept: " + std::string(PriorityName(problem.objects[i].priority)) + " objects are not removed to clear a way";
    return r;
  }
  return solver.Apply(a);
}

}  // namespace

std::optional<InteractionZone> ZoneOf(const ProblemObject& o) {
  std::optional<InteractionZone> zone = o.zone;
  if (!zone && o.asset.interaction_zone && o.asset.Has(kInteractor)) {
    zone = InteractionZone{o.asset.interaction_zone->side, o.asset.interaction_zone->depth, {}};
  }
  const bool hung = o.relation == Relation::kOnWall || o.relation == Relation::kHanging;
  if (!zone || !(zone->depth > 0.0) || hung) return std::nullopt;
  return zone;
}

bool ReachFeedbackOptions::IsValid(std::string* message) const {
  if (!reach.IsValid(message)) return false;
  if (rounds < 0 || rounds > 20) {
    if (message) *message = "rounds must be in [0, 20], is " + std::to_string(rounds);
    return false;
  }
  if (!(walkway_margin >= 0.0 && walkway_margin <= 0.5)) {
    if (message) *message = "walkway_margin must be in [0, 0.5] m, is " + Fixed(walkway_margin, 3);
    return false;
  }
  if (!(slot_step >= 0.02 && slot_step <= 1.0)) {
    if (message) *message = "slot_step must be in [0.02, 1] m, is " + Fixed(slot_step, 3);
    return false;
  }
  if (!(thin_share >= 0.0 && thin_share <= 1.0)) {
    if (message) *message = "thin_share must be in [0, 1], is " + Fixed(thin_share, 3);
    return false;
  }
  if (!(widen_move >= 0.0 && widen_move <= 20.0)) {
    if (message) *message = "widen_move must be in [0, 20] m, is " + Fixed(widen_move, 3);
    return false;
  }
  if (slot_tries < 1 || slot_tries > 100000) {
    if (message) *message = "slot_tries must be in [1, 100000], is " + std::to_string(slot_tries);
    return false;
  }
  return true;
}

std::vector<ReachObject> ReachObjectsOf(const RoomSolution& solution, const std::string& room, int level) {
  std::vector<ReachObject> out;
  const size_t n = std::min(solution.objects.size(), solution.placements.size());
  for (size_t i = 0; i < n; ++i) {
    const ProblemObject& o = solution.objects[i];
    const ObjectPlacement& pl = solution.placements[i];
    if (!pl.placed) continue;
    ReachObject r;
    r.id = o.id;
    r.room = room;
    r.level = level;
    r.box = StandingBox(o, pl.pose);
    r.covering = IsFloorCovering(o);
    if (const std::optional<InteractionZone> zone = ZoneOf(o)) {
      r.zone = ZoneFootprints(r.box, zone->side, zone->depth * pl.pose.scale);
      for (const std::string& id : zone->exempt) {
        for (size_t j = 0; j < n; ++j) {
          if (solution.objects[j].id != id || !solution.placements[j].placed) continue;
          const PlanShape other = PlanShape::Polygon(StandingBox(solution.objects[j], solution.placements[j].pose).Footprint());
          for (const Ring& z : r.zone) r.zone_shared |= PlanClearance(PlanShape::Polygon(z), other) < 0.0;
        }
      }
    }
    out.push_back(std::move(r));
  }
  return out;
}

Result<FeedbackSummary> FreeBlockedWays(const ReachInput& building, const std::map<std::string, RoomSolver*>& solvers,
                                        const ReachFeedbackOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  std::string message;
  if (!options.IsValid(&message)) return Error{"reach feedback options: " + message};
  std::map<std::string, const ReachTarget*> rooms;
  for (const ReachTarget& t : building.targets) {
    if (t.kind == TargetKind::kRoom) rooms[t.name] = &t;
  }
  // The objects as last checked: room, footprint (world), its area, whether it stands on the floor.
  struct Seen {
    std::string room;
    Ring footprint;
    double area = 0.0;
    bool on_floor = false;
  };
  std::map<std::string, Seen> seen;
  auto check = [&]() -> Result<ReachReport> {
    ReachInput input = building;
    std::vector<ReachObject> objects;
    seen.clear();
    for (const auto& [name, solver] : solvers) {
      const auto it = rooms.find(name);
      const int level = it != rooms.end() ? it->second->level : 0;
      const double floor_z = level < static_cast<int>(building.levels.size()) ? building.levels[level].floor_z : 0.0;
      for (ReachObject& o : ReachObjectsOf(solver->Solution(), name, level)) {
        seen[o.id] = {name, o.box.Footprint(), 4.0 * o.box.hx * o.box.hy, o.box.z0 <= floor_z + 0.02};
        objects.push_back(std::move(o));
      }
    }
    AddObjects(input, objects, options.reach);
    return CheckReach(input, options.reach);
  };
  auto first = check();
  if (!first.ok()) return Error{first.error()};
  FeedbackSummary summary;
  summary.first = *first;
  ReachReport report = *first;
  const double half = options.reach.radius + options.walkway_margin;
  constexpr int kProtectedTries = 8;  // reachability checks for one protected piece's slots
  // The last resort for a protected piece (essential, or asked for: issue 27) that closes room `target`
  // after every round (the agent never pushes such a piece through a wall or out of its group): moved, with
  // its group, to the nearest slot where a person gets into the room, a reachability check for each of at
  // most eight slots 0.4 m apart. Nothing when it is no protected piece or no slot lets a person in.
  const auto move_aside = [&](const std::string& target, const std::string& id) -> std::optional<RoomAction> {
    const auto b = seen.find(id);
    if (b == seen.end() || !solvers.count(b->second.room)) return std::nullopt;
    const std::string room = b->second.room;  // (a copy: the checks below rebuild `seen`)
    RoomSolver& solver = *solvers.at(room);
    if (!Protected(solver, id)) return std::nullopt;
    constexpr double kApart = 0.4;  // m between the slots tried (and from where it stands): nudges do not open a way
    std::vector<Point> tried{seen.at(id).footprint.empty() ? Point{} : Centroid(seen.at(id).footprint)};
    const auto spread = [&](const OrientedBox& box, const std::vector<Ring>&) {
      return std::all_of(tried.begin(), tried.end(), [&](Point p) { return geo::Dist(p, box.c) >= kApart; });
    };
    const auto entered = [&] {
      const RoomSolution now = solver.Solution();
      for (size_t k = 0; k < now.objects.size() && k < now.placements.size(); ++k)
        if (now.objects[k].id == id) tried.push_back({now.placements[k].pose.x, now.placements[k].pose.y});
      if (static_cast<int>(tried.size()) > kProtectedTries + 1) return false;
      const auto again = check();
      const TargetResult* after = again.ok() ? again->Find(target) : nullptr;
      return after && after->reachable;
    };
    auto moved = MoveToSlot(solver, id, options, std::numeric_limits<double>::infinity(), "it closes the way into " + target, spread,
                            "where a person gets into " + target + ", its group along", entered, /*zoneless=*/true);
    if (!moved) return std::nullopt;
    return RoomAction{room, *moved};
  };
  // Before the last resort removes a protected piece that closes room `target` (a children's bed across the
  // only way into the next bedroom while a desk holds the room's far end): slots clear of the blocked way
  // (`way`, the cells the feedback keeps free), nearest first, each taken where only optional floor pieces
  // stand in it (they go, with what stands on them; the refill puts back what fits afterwards), at most
  // eight with a reachability check each; at full size, else at its smallest. The actions taken, none when
  // no slot lets a person in (the room is then as it was).
  const auto make_room = [&](const std::string& target, const std::string& id,
                             const std::vector<std::pair<int, std::vector<Point>>>& way) -> std::vector<ActionResult> {
    const auto b = seen.find(id);
    if (b == seen.end() || !solvers.count(b->second.room)) return {};
    RoomSolver& solver = *solvers.at(b->second.room);
    const int level = rooms.count(b->second.room) ? rooms.at(b->second.room)->level : 0;
    std::vector<Point> cells;  // the way's points, 0.1 m apart
    for (const auto& [l, points] : way)
      for (size_t k = 0; l == level && k < points.size(); ++k) {
        cells.push_back(points[k]);
        if (k + 1 == points.size()) continue;
        const double length = geo::Dist(points[k], points[k + 1]);
        for (double t = 0.1; t < length; t += 0.1) cells.push_back(geo::Add(points[k], geo::Scale(geo::Sub(points[k + 1], points[k]), t / length)));
      }
    if (cells.empty()) return {};
    const std::shared_ptr<const RoomSolver::Snapshot> undo = solver.Save();
    int checks = 0, misfits = 0;
    std::vector<ActionResult> out;
    for (int shrunk = 0; shrunk < 2; ++shrunk) {
      const RoomSolution now = solver.Solution();
      int i = -1;
      for (size_t k = 0; k < now.objects.size() && k < now.placements.size(); ++k)
        if (now.objects[k].id == id && now.placements[k].placed) i = static_cast<int>(k);
      if (i < 0) break;
      const double scale = shrunk == 0 ? now.placements[i].pose.scale : now.objects[i].scale_min;
      if (shrunk == 1 && scale >= now.placements[i].pose.scale - 1e-9) break;
      ObjectPlacement at = now.placements[i];
      at.pose.scale = scale;
      const std::shared_ptr<const RoomSolver::Snapshot> here = solver.Save();
      for (Slot slot : FloorSlots(solver.Problem(), now.objects[i], at, options.slot_step)) {
        slot.pose.scale = scale;
        if (checks >= kProtectedTries || misfits >= options.slot_tries) break;
        const PlanShape shape = PlanShape::Polygon(StandingBox(now.objects[i], slot.pose).Footprint());
        if (!std::all_of(cells.begin(), cells.end(), [&](Point p) { return PlanClearance(PlanShape::Disc(p, half), shape) > 0.0; }))
          continue;
        // What stands in the slot: optional floor pieces only.
        std::vector<std::string> in_way;
        bool kept = false;
        for (size_t k = 0; k < now.objects.size() && !kept; ++k) {
          const ProblemObject& o = now.objects[k];
          if (static_cast<int>(k) == i || o.parent != "floor" || !now.placements[k].placed) continue;
          if (PlanClearance(PlanShape::Polygon(StandingBox(o, now.placements[k].pose).Footprint()), shape) > 0.05) continue;
          if (!IsProtected(o.priority)) {
            if (std::find(in_way.begin(), in_way.end(), o.id) == in_way.end()) in_way.push_back(o.id);
            continue;
          }
          // A desk's own chair is protected to stay at its desk: it goes with an optional desk.
          bool seat = false;
          for (const ProblemObject& desk : now.objects)
            if (desk.category == "desk" && !IsProtected(desk.priority) && IsDeskSeat(now.edges, o.id, desk.id)) {
              if (std::find(in_way.begin(), in_way.end(), desk.id) == in_way.end()) in_way.push_back(desk.id);
              seat = true;
            }
          kept = !seat;
        }
        if (kept) continue;
        std::vector<ActionResult> taken;
        for (const std::string& other : in_way) {
          ActionResult r = Remove(solver, other, "makes room for " + id + " off the way into " + target);
          if (r.status != ActionStatus::kRefused) taken.push_back(std::move(r));
        }
        const std::optional<int> wall = slot.wall >= 0 ? std::optional<int>(slot.wall) : std::nullopt;
        bool ok = solver.Fits(id, slot.pose, wall);
        if (!ok) ++misfits;
        if (ok) {
          Action a;
          a.kind = ActionKind::kUpdatePose;
          a.id = id;
          a.pose = slot.pose;
          a.wall = wall;
          if (shrunk == 1) a.scale = scale;
          a.reason = "reachability: it closes the way into " + target + "; moved " + Fixed(slot.distance, 2) + " m to a slot off the way" +
                     (shrunk == 1 ? " at its smallest scale" : "") +
                     (in_way.empty() ? "" : ", " + std::to_string(in_way.size()) + " optional piece(s) there out");
          ActionResult r = solver.Apply(a);
          ok = r.status != ActionStatus::kRefused;
          if (ok) {
            ++checks;
            const auto again = check();
            const TargetResult* after = again.ok() ? again->Find(target) : nullptr;
            ok = after && after->reachable;
          }
          if (ok) {
            out.insert(out.end(), taken.begin(), taken.end());
            out.push_back(std::move(r));
            return out;
          }
        }
        solver.Restore(*here);
      }
    }
    solver.Restore(*undo);
    return {};
  };
  std::set<std::string> aside_tried;  // protected blockers tried with move_aside (once each)
  int extra_rounds = 0;               // one more round after a protected blocker moved aside
  for (int round = 0;; ++round) {
    std::vector<std::string> unreachable;
    for (const TargetResult& t : report.targets) {
      if (!t.reachable) unreachable.push_back(t.name);
    }
    if (unreachable.empty()) {
      summary.all_reachable = true;
      summary.reason = round == 0 ? "every room and zone reachable" : "every room and zone reachable after " + std::to_string(round) + " round(s)";
      break;
    }
    if (round == options.rounds + extra_rounds) {
      summary.reason = std::to_string(unreachable.size()) + " target(s) still unreachable after " + std::to_string(round) + " round(s)";
      break;
    }
    FeedbackRound fr;
    fr.unreachable = unreachable;
    std::map<std::string, std::vector<KeepOut>> lay;
    std::set<std::string> rooms_unreached;
    for (const TargetResult& t : report.targets) {
      if (t.kind == TargetKind::kRoom && !t.reachable) rooms_unreached.insert(t.name);
    }
    // A room a protected piece still closes after a round of walkways: the piece moves aside (at most once
    // a piece), and the room's zones get one more round.
    std::set<std::string> opened;
    if (round > 0)
      for (const TargetResult& t : report.targets) {
        if (t.kind != TargetKind::kRoom || t.reachable || t.structural) continue;
        for (const std::string& id : t.blockers) {
          if (!aside_tried.insert(id).second) continue;
          if (std::optional<RoomAction> a = move_aside(t.name, id)) {
            fr.actions.push_back(std::move(*a));
            opened.insert(t.name);
            extra_rounds = 1;
          }
        }
      }
    for (const TargetResult& t : report.targets) {
      if (t.reachable || t.structural || opened.count(t.name)) continue;
      if (t.kind == TargetKind::kZone) {
        // A zone in a room that cannot be entered waits for the room's walkway.
        if (rooms_unreached.count(t.room)) continue;
        const auto owner = seen.find(t.name);
        if (owner == seen.end()) continue;
        bool clearable = !t.blockers.empty() && t.door_leaves.empty();
        for (const std::string& id : t.blockers) {
          if (auto b = seen.find(id); b != seen.end() && b->second.area > owner->second.area + 1e-9) clearable = false;
        }
        if (!clearable) {
          const Seen& o = owner->second;
          const auto r = rooms.find(o.room);
          if (!o.on_floor || r == rooms.end() || !solvers.count(o.room)) continue;
          const double floor_z = building.levels[r->second->level].floor_z;
          fr.walkways.push_back({o.room, t.name, 1, "spot"});
          lay[o.room].push_back({o.footprint, floor_z, floor_z + options.reach.head_height, KeepOutKind::kWalkway,
                                 "the unreachable place of " + t.name});
          continue;
        }
      }
      if (t.blockers.empty()) continue;
      std::set<std::string> holders;
      for (const std::string& id : t.blockers) {
        if (auto it = seen.find(id); it != seen.end()) holders.insert(it->second.room);
      }
      for (const std::string& room : holders) {
        const auto r = rooms.find(room);
        if (r == rooms.end() || !solvers.count(room)) continue;
        const int level = r->second->level;
        std::vector<KeepOut> pieces = WalkwayPieces(t.blocked_way, level, building.levels[level].floor_z, options.reach.head_height,
                                                    half, r->second->areas.front().polygon, t.name);
        if (pieces.empty()) continue;
        fr.walkways.push_back({room, t.name, static_cast<int>(pieces.size()), "walkway"});
        auto& list = lay[room];
        list.insert(list.end(), pieces.begin(), pieces.end());
      }
    }
    if (lay.empty() && fr.actions.empty()) {
      summary.reason = std::to_string(unreachable.size()) +
                       " target(s) unreachable, none that moving furniture can help (walls, stairs, holes or door leaves close them)";
      summary.rounds.push_back(std::move(fr));
      break;
    }
    for (const auto& [room, zones] : lay) {
      RoomSolver* solver = solvers.at(room);
      const size_t before = solver->Solution().summary.actions.size();
      if (Status s = solver->AddKeepOuts(zones); !s.ok()) return Error{"room " + room + ": walkway: " + s.error()};
      solver->RunAgent();
      const RoomSolution after = solver->Solution();
      for (size_t k = before; k < after.summary.actions.size(); ++k) fr.actions.push_back({room, after.summary.actions[k]});
    }
    summary.rounds.push_back(std::move(fr));
    auto next = check();
    if (!next.ok()) return Error{next.error()};
    report = std::move(*next);
  }
  // The last resort: what the rounds left. First the owners of unreachable zones in rooms a person enters
  // move to slots whose zone a reached cell touches, and what still blocks a room is removed; after a check,
  // the owners of zones still unreachable are removed, unless only door leaves close the way (the building's
  // to mend: a leaf's swing, not the furniture).
  const std::string rounds_reason = summary.reason;
  for (const char* stage : {"move", "remove"}) {
    if (summary.all_reachable || !options.last_resort) break;
    std::set<std::string> rooms_unreached;
    for (const TargetResult& t : report.targets) {
      if (t.kind == TargetKind::kRoom && !t.reachable) rooms_unreached.insert(t.name);
    }
    FeedbackRound fr;
    fr.stage = stage;
    const bool moving = std::string(stage) == "move";
    std::set<std::string> gone;  // removed in this stage, with what stood on them
    auto act = [&](const std::string& room, const ActionResult& r) {
      if (r.action.kind == ActionKind::kRemoveEntity && r.status != ActionStatus::kRefused) {
        summary.removed += static_cast<int>(r.removed.size());
        gone.insert(r.removed.begin(), r.removed.end());
      }
      if (r.action.kind == ActionKind::kUpdatePose) ++summary.moved;
      fr.actions.push_back({room, r});
    };
    for (const TargetResult& t : report.targets) {
      if (t.reachable) continue;
      fr.unreachable.push_back(t.name);
      const bool leaves_only = !t.structural && t.blockers.empty();
      if (t.kind == TargetKind::kRoom) {
        // A room sealed by furniture the walkways could not clear: what stands in its way goes.
        if (leaves_only || !t.door_leaves.empty()) continue;
        for (const std::string& id : t.blockers) {
          const auto b = seen.find(id);
          if (gone.count(id) || b == seen.end() || !solvers.count(b->second.room)) continue;
          const std::string room = b->second.room;
          RoomSolver& solver = *solvers.at(room);
          const std::string why = "it closes the way into " + t.name + " after every round";
          if (!Protected(solver, id)) {
            act(room, Remove(solver, id, why));
          } else if (moving) {
            if (!aside_tried.insert(id).second) continue;  // tried in the rounds already
            if (std::optional<RoomAction> a = move_aside(t.name, id)) act(a->room, a->result);
          } else {
            // The room's optional pieces make way for it where that lets a person in; else no slot does: the
            // way wins (a room no one can enter serves no one); the room's functional check reports the
            // piece missing, with this reason.
            const std::vector<ActionResult> made = make_room(t.name, id, t.blocked_way);
            for (const ActionResult& r : made) act(room, r);
            if (made.empty()) act(room, Remove(solver, id, why + ", and no slot off the way holds it", /*even_protected=*/true));
          }
        }
        continue;
      }
      const auto owner = seen.find(t.name);
      if (rooms_unreached.count(t.room) || owner == seen.end() || gone.count(t.name) || !solvers.count(owner->second.room)) continue;
      RoomSolver& solver = *solvers.at(owner->second.room);
      if (moving) {
        if (t.level >= static_cast<int>(report.reached.size())) continue;
        if (auto r = MoveToReachableSlot(solver, t.name, report.reached[t.level], options)) act(owner->second.room, *r);
      } else if (!leaves_only) {
        act(owner->second.room, Remove(solver, t.name, "its zone stays unreachable and no free slot has a reachable one"));
      }
    }
    if (fr.actions.empty()) continue;  // nothing moved: on to the removals, with nothing new to check
    summary.rounds.push_back(std::move(fr));
    auto next = check();
    if (!next.ok()) return Error{next.error()};
    report = std::move(*next);
    int left = 0;
    for (const TargetResult& t : report.targets) left += !t.reachable;
    summary.all_reachable = left == 0;
    summary.reason = rounds_reason + "; last resort: " + std::to_string(summary.moved) + " moved, " + std::to_string(summary.removed) + " removed, " +
                      (left ? std::to_string(left) + " target(s) still unreachable" : "every room and zone reachable");
  }
  // Widening: the owners of zones a person reaches only at their edge (share below thin_share: a wardrobe
  // whose front a bed leaves a strip of) move to the nearest free slot within widen_move m where a person on
  // the reached cells covers far more of the zone. A room where that leaves any of its zones less reached
  // (or a target anywhere unreachable) goes back to how it was.
  if (options.last_resort && options.thin_share > 0.0) {
    FeedbackRound fr;
    fr.stage = "widen";
    std::map<std::string, std::shared_ptr<const RoomSolver::Snapshot>> saved;
    std::map<std::string, std::vector<RoomAction>> acted;
    for (const TargetResult& t : report.targets) {
      if (t.kind != TargetKind::kZone || !t.reachable || t.share >= options.thin_share || t.level >= static_cast<int>(report.reached.size()))
        continue;
      const auto owner = seen.find(t.name);
      if (owner == seen.end() || !owner->second.on_floor || !solvers.count(owner->second.room)) continue;
      const std::string& room = owner->second.room;
      RoomSolver& solver = *solvers.at(room);
      if (!saved.count(room)) saved.emplace(room, solver.Save());  // before any widening in the room
      const ReachedCells& cells = report.reached[t.level];
      const double want = std::max(options.thin_share, t.share + 0.3);
      // The owner's relations (a nightstand beside its bed) are worth more than a wider zone: a slot where
      // more of them are violated (the solver's semantic proxy) is passed over.
      const auto violated = [&] {
        const RoomSolution now = solver.Solution();
        const auto placed = [&](const std::string& id) {
          for (size_t k = 0; k < now.objects.size() && k < now.placements.size(); ++k)
            if (now.objects[k].id == id && now.placements[k].placed) return static_cast<int>(k);
          return -1;
        };
        int n = 0;
        for (const SemanticEdge& edge : now.edges) {
          if (edge.source != t.name && edge.target != t.name) continue;
          const int a = placed(edge.source), b = placed(edge.target);
          n += a >= 0 && b >= 0 && EdgeViolation(edge, now.objects[a], now.placements[a], now.objects[b], now.placements[b]) > 1e-6;
        }
        return n;
      };
      const int violated_before = violated();
      auto r = MoveToSlot(
          solver, t.name, options, options.widen_move, "a person reaches " + Fixed(100.0 * t.share, 0) + " % of its zone where it stands",
          [&](const OrientedBox& box, const std::vector<Ring>& zone) { return ZoneCover(cells, zone, box, options.reach.radius) >= want; },
          "where they reach most of it, its relations kept", [&] { return violated() <= violated_before; });
      if (!r) continue;
      fr.unreachable.push_back(t.name);
      acted[room].push_back({room, *r});
    }
    if (!acted.empty()) {
      auto next = check();
      if (!next.ok()) return Error{next.error()};
      // The rooms where the widening made things worse: a zone less reached, the zones' shares not risen
      // in all. A target lost anywhere (a way cut) sends every room back: which move cut it is not known.
      const auto worse_rooms = [&](const ReachReport& after, bool* lost) {
        std::map<std::string, const TargetResult*> was;
        for (const TargetResult& t : report.targets) was[t.name] = &t;
        std::map<std::string, std::pair<double, double>> shares;
        std::set<std::string> worse;
        *lost = false;
        for (const TargetResult& t : after.targets) {
          const auto w = was.find(t.name);
          if (w == was.end()) continue;
          const TargetResult& before = *w->second;
          *lost = *lost || (before.reachable && !t.reachable);
          if (t.kind != TargetKind::kZone || !acted.count(t.room)) continue;
          shares[t.room].first += before.share;
          shares[t.room].second += t.share;
          if (t.share < before.share - 0.05) worse.insert(t.room);
        }
        for (const auto& [room, sum] : shares)
          if (sum.second <= sum.first + 1e-6) worse.insert(room);
        return worse;
      };
      bool lost = false;
      std::set<std::string> worse = worse_rooms(*next, &lost);
      const auto restore_all = [&] {
        for (const auto& [room, list] : acted) {
          solvers.at(room)->Restore(*saved.at(room));
          worse.insert(room);
        }
      };
      if (lost) {
        restore_all();
      } else if (worse.empty()) {
        report = std::move(*next);
      } else if (worse.size() < acted.size()) {
        for (const std::string& room : worse) solvers.at(room)->Restore(*saved.at(room));
        // What is kept is judged again on its own: if it no longer stands, nothing is kept.
        auto again = check();
        if (!again.ok()) return Error{again.error()};
        bool lost_again = false;
        const std::set<std::string> still = worse_rooms(*again, &lost_again);
        const bool holds = !lost_again && std::all_of(still.begin(), still.end(), [&](const std::string& r) { return worse.count(r) > 0; });
        if (holds) report = std::move(*again);
        else restore_all();
      } else {
        restore_all();
      }
      // When every room went back, the solvers are as `report` saw them (a snapshot is an exact copy).
      for (const auto& [room, list] : acted) {
        if (worse.count(room)) continue;
        for (const RoomAction& act : list) {
          fr.actions.push_back(act);
          ++summary.widened;
        }
      }
      std::erase_if(fr.unreachable, [&](const std::string& id) {
        const auto o = seen.find(id);
        return o == seen.end() || worse.count(o->second.room) > 0;
      });
      if (!fr.actions.empty()) {
        summary.rounds.push_back(std::move(fr));
        int left = 0;
        for (const TargetResult& t : report.targets) left += !t.reachable;
        const bool was_all = summary.all_reachable;
        summary.all_reachable = left == 0;
        summary.reason += "; " + std::to_string(summary.widened) + " moved where their zone is reached more widely" +
                          (left ? ", " + std::to_string(left) + " target(s) still unreachable" : was_all ? "" : ", every room and zone reachable");
      }
    }
  }
  summary.last = std::move(report);
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

std::string FeedbackSummary::BriefReport() const {
  std::string out = "reach feedback: " + reason + " (RCH " + Fixed(first.Rch(), 3) + " -> " + Fixed(last.Rch(), 3) + ", ACC " +
                    Fixed(first.Acc(), 3) + " -> " + Fixed(last.Acc(), 3) + ")\n";
  for (size_t r = 0; r < rounds.size(); ++r) {
    out += "  round " + std::to_string(r + 1) + (rounds[r].stage == "walkways" ? "" : " (last resort: " + rounds[r].stage + ")") +
           ": " + std::to_string(rounds[r].unreachable.size()) + " unreachable, " +
           std::to_string(rounds[r].walkways.size()) + " walkway(s)";
    for (const RoomAction& a : rounds[r].actions) {
      out += "; " + a.room + ": " + std::string(ActionKindName(a.result.action.kind)) + " " + a.result.action.id + " (" +
             std::string(ActionStatusName(a.result.status)) + ")";
    }
    out += "\n";
  }
  return out;
}

nlohmann::ordered_json FeedbackSummary::ToJson() const {
  nlohmann::ordered_json j;
  j["all_reachable"] = all_reachable;
  j["reason"] = reason;
  j["rch_before"] = std::round(first.Rch() * 1e4) / 1e4;
  j["acc_before"] = std::round(first.Acc() * 1e4) / 1e4;
  j["rooms_reachable_before"] = first.rooms_reachable;
  j["zones_reachable_before"] = first.zones_reachable;
  j["last_resort"] = {{"moved", moved}, {"removed", removed}, {"widened", widened}};
  j["rounds"] = nlohmann::ordered_json::array();
  for (const FeedbackRound& r : rounds) {
    nlohmann::ordered_json jr;
    jr["stage"] = r.stage;
    jr["unreachable"] = r.unreachable;
    jr["walkways"] = nlohmann::ordered_json::array();
    for (const Walkway& w : r.walkways)
      jr["walkways"].push_back({{"room", w.room}, {"target", w.target}, {"kind", w.kind}, {"pieces", w.pieces}});
    jr["actions"] = nlohmann::ordered_json::array();
    for (const RoomAction& a : r.actions) {
      nlohmann::ordered_json ja = ActionResultToJson(a.result);
      ja["room"] = a.room;
      jr["actions"].push_back(std::move(ja));
    }
    j["rounds"].push_back(std::move(jr));
  }
  return j;
}

}  // namespace villa::solver
