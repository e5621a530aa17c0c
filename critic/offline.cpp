#include "critic/offline.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <set>

#include "assets/category.h"
#include "critic/observation.h"
#include "layout/geometry.h"
#include "mesh/geometry2d.h"
#include "util/text_table.h"

namespace villa::critic {
namespace {

constexpr double kHalfPi = 0.5 * std::numbers::pi;

bool WallBound(const solver::ProblemObject& o) {
  return o.relation == solver::Relation::kAgainstWall || o.relation == solver::Relation::kOnWall;
}
bool OnObject(const solver::ProblemObject& o) { return o.parent != "floor" && o.parent != "wall" && o.parent != "ceiling"; }
bool Covering(const solver::ProblemObject& o, double scale) {
  return o.parent == "floor" && o.relation == solver::Relation::kOnTop && o.asset.size.z * scale <= 0.03;
}

// The room as the candidates see it: objects, where they are, who stands on whom.
struct Room {
  const solver::RoomProblem& problem;
  const solver::RoomSolution& solution;
  const std::vector<scene::SemanticEdge>& graph;
  std::map<std::string, int> index;
  std::vector<int> parent;                 // index of the parent object, -1 for floor, wall, ceiling
  std::vector<std::vector<int>> children;
  std::vector<double> stack_top;           // top of the object with what stands on it, m

  Room(const solver::RoomProblem& p, const solver::RoomSolution& s, const std::vector<scene::SemanticEdge>& g)
      : problem(p), solution(s), graph(g) {
    const size_t n = s.objects.size();
    for (size_t i = 0; i < n; ++i) index[s.objects[i].id] = static_cast<int>(i);
    parent.assign(n, -1);
    children.assign(n, {});
    for (size_t i = 0; i < n; ++i) {
      auto it = index.find(s.objects[i].parent);
      if (it != index.end()) {
        parent[i] = it->second;
        children[it->second].push_back(static_cast<int>(i));
      }
    }
    stack_top.assign(n, 0.0);
    for (size_t i = 0; i < n; ++i) {
      const double top = BoxOf(s.objects[i], s.placements[i]).z1;
      for (int a = static_cast<int>(i); a >= 0; a = parent[a]) stack_top[a] = std::max(stack_top[a], top);
    }
  }
  int Find(const std::string& id) const {
    auto it = index.find(id);
    return it == index.end() ? -1 : it->second;
  }
  int Root(int i) const {
    while (parent[i] >= 0) i = parent[i];
    return i;
  }
  std::vector<int> Descendants(int i) const {
    std::vector<int> out, stack = children[i];
    while (!stack.empty()) {
      const int k = stack.back();
      stack.pop_back();
      out.push_back(k);
      stack.insert(stack.end(), children[k].begin(), children[k].end());
    }
    return out;
  }
  // The placements with object i moved to `pose` (scale included) and what stands on it carried along.
  std::vector<solver::ObjectPlacement> Moved(int i, const solver::Pose& pose, int wall) const {
    return Moved(solution.placements, i, pose, wall);
  }
  std::vector<solver::ObjectPlacement> Moved(std::vector<solver::ObjectPlacement> out, int i, const solver::Pose& pose,
                                             int wall) const {
    const solver::Pose old = out[i].pose;
    const double turn = pose.yaw - old.yaw, c = std::cos(turn), s = std::sin(turn), k = pose.scale / old.scale;
    for (int d : Descendants(i)) {
      solver::Pose& p = out[d].pose;
      const double dx = p.x - old.x, dy = p.y - old.y;
      p.x = pose.x + k * (c * dx - s * dy);
      p.y = pose.y + k * (s * dx + c * dy);
      p.z = pose.z + k * (p.z - old.z);
      p.yaw = solver::WrapAngle(p.yaw + turn);
    }
    out[i].pose = pose;
    if (wall >= 0) out[i].wall = wall;
    return out;
  }
};

struct Candidate {
  solver::Pose pose;
  int wall = -1;
  int surface = -1, cavity = -1;  // a new support choice (the solver's suggestions for small things)
  bool proven = false;            // the solver found it itself (RoomSolver::Suggest): it fits
  bool remove = false;            // not moved but taken out (a decorative thing with no open place left)
};

// The box of object k at `pose`.
ObjectBox BoxAt(const Room& room, int k, const solver::Pose& pose) {
  solver::ObjectPlacement pl = room.solution.placements[k];
  pl.pose = pose;
  return BoxOf(room.solution.objects[k], pl);
}

// Whether a box meets one of the room's keep-outs (plan overlap and height ranges meeting).
bool InKeepOut(const Room& room, const ObjectBox& box) {
  const Ring footprint = box.Footprint();
  for (const solver::KeepOut& k : room.problem.keep_outs) {
    if (k.kind == solver::KeepOutKind::kCirculation) continue;  // a preference of the placement (issue 27)
    if (std::min(box.z1, k.z_max) - std::max(box.z0, k.z_min) <= 0.0) continue;
    if (solver::ClippedArea(footprint, k.polygon) > 1e-6) return true;
  }
  return false;
}

// The free-standing objects closer than `clearance` to object i at `pose` (none: it is free of them), or
// nothing at all when the floor's edge or a keep-out is in the way (no object can be moved out of that).
std::optional<std::vector<int>> Blockers(const Room& room, int i, const solver::Pose& pose, double clearance,
                                         const std::set<int>& ignore = {}, bool own_box = false) {
  const solver::ProblemObject& o = room.solution.objects[i];
  ObjectBox box = BoxAt(room, i, pose);
  const double top = own_box ? box.z1
                             : pose.z + (room.stack_top[i] - room.solution.placements[i].pose.z) * pose.scale /
                                            room.solution.placements[i].pose.scale;
  const bool covering = Covering(o, pose.scale);
  std::vector<int> blockers;
  for (size_t j = 0; j < room.solution.objects.size(); ++j) {
    if (static_cast<int>(j) == i || room.parent[j] >= 0 || ignore.count(static_cast<int>(j))) continue;
    const solver::ProblemObject& other = room.solution.objects[j];
    if (covering || Covering(other, room.solution.placements[j].pose.scale)) continue;
    const ObjectBox b = BoxOf(other, room.solution.placements[j]);
    if (std::min(top, room.stack_top[j]) - std::max(box.z0, b.z0) <= 0.0) continue;
    if (PlanGap(box, b) < clearance) blockers.push_back(static_cast<int>(j));
  }
  if (o.relation != solver::Relation::kOnWall) {
    for (const Point& p : box.Footprint())
      if (!PointInRing(p, room.problem.free_floor, 0.0) || DistanceToBoundary(p, room.problem.free_floor) < 0.012) return std::nullopt;
  }
  box.z1 = top;
  if (InKeepOut(room, box)) return std::nullopt;
  return blockers;
}

// Whether object i at `pose` keeps `clearance` from the other free-standing objects, stays on the free
// floor and out of the keep-outs. Only the object's own box is tested (what stands on it moves with it and
// stays within it).
bool Free(const Room& room, int i, const solver::Pose& pose, double clearance, const std::set<int>& ignore = {},
          bool own_box = false) {
  auto blockers = Blockers(room, i, pose, clearance, ignore, own_box);
  return blockers && blockers->empty();
}

// m along wall w from its start to the foot of point p.
double AlongWall(const Room& room, int w, Point p) {
  const solver::WallEdge& wall = room.problem.walls[w];
  return geo::Dot(geo::Sub(p, wall.a), geo::Unit(geo::Sub(wall.b, wall.a)));
}

// The yaw at which something standing at `from` faces `to` (yaw 0 faces -y, 90 degrees +x).
double FacingYaw(Point from, Point to) { return std::atan2(to.x - from.x, -(to.y - from.y)); }

// Poses along a wall for a wall-bound object: its back at its gap from the wall, facing the room, at
// `t` m along the wall from its start; none where it would overhang the wall's ends or cover an opening.
std::optional<Candidate> OnWallAt(const Room& room, int i, int w, double t, double scale) {
  const solver::ProblemObject& o = room.solution.objects[i];
  const solver::WallEdge& wall = room.problem.walls[w];
  const double length = geo::Dist(wall.a, wall.b);
  const double half = 0.5 * o.asset.size.x * scale;
  const double end = o.relation == solver::Relation::kOnWall ? 0.1 : 0.01;  // wall decor keeps 10 cm from the ends (solver/place.cpp)
  if (t < half + end || t > length - half - end) return std::nullopt;
  const solver::ObjectPlacement& now = room.solution.placements[i];
  const double z = o.relation == solver::Relation::kOnWall ? now.pose.z : room.problem.floor_z;
  // Hung things keep 0.1 m from openings all round, as the solver's opening prisms demand (solver/layer.cpp).
  const double around = o.relation == solver::Relation::kOnWall ? 0.1 : 0.01, rise = o.relation == solver::Relation::kOnWall ? 0.1 : 0.0;
  for (const solver::WallOpening& op : wall.openings)
    if (t + half > op.t0 - around && t - half < op.t1 + around && z < op.z1 + rise && z + o.asset.size.z * scale > op.z0 - rise)
      return std::nullopt;
  const Point d = geo::Unit(geo::Sub(wall.b, wall.a)), n = geo::Left(d);
  const Point c = geo::Add(geo::Add(wall.a, geo::Scale(d, t)), geo::Scale(n, o.wall_gap + 0.5 * o.asset.size.y * scale));
  Candidate out;
  out.pose = {c.x, c.y, z, std::atan2(n.x, -n.y), scale};
  out.wall = w;
  return out;
}

// Object i's poses against every wall but `skip`, every `step` m from each wall's start, at `scale`, where
// OnWallAt finds one (wall by wall, in order).
std::vector<Candidate> AlongEveryWall(const Room& room, int i, double step, double scale, int skip = -1) {
  std::vector<Candidate> out;
  for (size_t w = 0; w < room.problem.walls.size(); ++w) {
    if (static_cast<int>(w) == skip) continue;
    const double length = geo::Dist(room.problem.walls[w].a, room.problem.walls[w].b);
    for (double t = 0.0; t < length; t += step)
      if (auto c = OnWallAt(room, i, static_cast<int>(w), t, scale)) out.push_back(*c);
  }
  return out;
}

// Half the extent of a box of half sizes (hx, hy) at `yaw` along the unit direction n.
double HalfAlong(double hx, double hy, double yaw, Point n) {
  return hx * std::abs(n.x * std::cos(yaw) + n.y * std::sin(yaw)) + hy * std::abs(-n.x * std::sin(yaw) + n.y * std::cos(yaw));
}

// Gaps (m between the boxes) worth trying for a relation.
std::vector<double> GapsFor(const scene::SemanticEdge& e) {
  using R = scene::SemanticRelation;
  const scene::EdgeParams p = scene::EffectiveParams(e.relation, e.params);
  if ((e.relation == R::kFrontOf || e.relation == R::kBehind || e.relation == R::kLeftOf || e.relation == R::kRightOf) &&
      (e.params.min_gap || e.params.max_gap)) {
    const double lo = e.params.min_gap.value_or(0.0), hi = e.params.max_gap.value_or(lo + 1.0);
    return {lo + 0.02, 0.5 * (lo + hi), std::max(lo + 0.02, hi - 0.02)};
  }
  switch (e.relation) {
    case R::kNextTo: return {0.04, 0.15, 0.3, 0.45};
    case R::kNear: return {std::max(*p.min_gap, 0.5) + 0.05, 0.8, 1.1, p.max_gap.value_or(1.5) - 0.05};
    case R::kFar: return {*p.min_gap + 0.1, *p.min_gap + 0.5, *p.min_gap + 1.0};
    case R::kFaceTo: return {0.3, 0.6, 1.0, 1.6};
    default: return {0.04, 0.3, 0.6};
  }
}

// Candidate poses for object m so that an edge with `other` may hold: in place (turned), around the other
// object, or along the walls.
// `other_box`: the other object's box where it is about to stand (default: where it stands).
std::vector<Candidate> CandidatesFor(const Room& room, int m, int other, const scene::SemanticEdge& edge, double scale,
                                     const ObjectBox* other_box = nullptr) {
  const solver::ProblemObject& o = room.solution.objects[m];
  const solver::ObjectPlacement& now = room.solution.placements[m];
  const ObjectBox ob = other_box ? *other_box : BoxOf(room.solution.objects[other], room.solution.placements[other]);
  std::vector<Candidate> out;
  if (WallBound(o)) {
    for (size_t w = 0; w < room.problem.walls.size(); ++w) {
      if (o.wall >= 0 && static_cast<int>(w) != o.wall) continue;
      const solver::WallEdge& wall = room.problem.walls[w];
      const Point d = geo::Unit(geo::Sub(wall.b, wall.a));
      const double foot = geo::Dot(geo::Sub(ob.c, wall.a), d), half = 0.5 * o.asset.size.x * scale;
      const double other_half = HalfAlong(ob.hx, ob.hy, ob.yaw, d);
      std::vector<double> ts{foot};
      for (double g : GapsFor(edge)) {
        ts.push_back(foot - other_half - g - half);
        ts.push_back(foot + other_half + g + half);
      }
      const double length = geo::Dist(wall.a, wall.b);
      for (double t = half + 0.02; t < length - half; t += 0.25) ts.push_back(t);
      for (double t : ts)
        if (auto c = OnWallAt(room, m, static_cast<int>(w), t, scale)) out.push_back(*c);
    }
    return out;
  }
  if (OnObject(o)) return out;  // small things stay on their surfaces: their parent moves instead
  // Turned in place: facing the other object exactly, or along its axes.
  const double face = FacingYaw({now.pose.x, now.pose.y}, ob.c);
  std::vector<double> yaws{now.pose.yaw, face, face + std::numbers::pi};
  for (int k = 0; k < 4; ++k) yaws.push_back(ob.yaw + k * kHalfPi);
  // Turned a little either way, and half way to facing: a second face_to of the object may still hold.
  for (int k = -4; k <= 4; ++k)
    if (k != 0) yaws.push_back(now.pose.yaw + k * std::numbers::pi / 18.0);
  yaws.push_back(now.pose.yaw + 0.5 * solver::WrapAngle(face - now.pose.yaw));
  for (double yaw : yaws) out.push_back({{now.pose.x, now.pose.y, now.pose.z, solver::WrapAngle(yaw), scale}, -1});
  // Around the other object: on each of its sides, at the relation's gaps, along the side.
  const double hx = 0.5 * o.asset.size.x * scale, hy = 0.5 * o.asset.size.y * scale;
  const Point u = ob.U(), v = ob.V();
  const Point normals[4] = {geo::Scale(v, -1.0), v, u, geo::Scale(u, -1.0)};  // front (-y), back, left (+x), right
  const double along[4] = {ob.hx, ob.hx, ob.hy, ob.hy};
  const double depth[4] = {ob.hy, ob.hy, ob.hx, ob.hx};
  for (int side = 0; side < 4; ++side) {
    const Point n = normals[side], l = side < 2 ? u : v;
    for (double gap : GapsFor(edge)) {
      for (double lateral : {0.0, -0.5, 0.5, -0.9, 0.9}) {
        // Facing the other object from this side, turned like it, or as it stands.
        const double toward = std::atan2(-n.x, n.y);
        for (double yaw : {toward, ob.yaw, now.pose.yaw, ob.yaw + kHalfPi, toward + std::numbers::pi}) {
          const double reach = depth[side] + gap + HalfAlong(hx, hy, yaw, n);
          const Point c = geo::Add(geo::Add(ob.c, geo::Scale(n, reach)), geo::Scale(l, lateral * along[side]));
          out.push_back({{c.x, c.y, now.pose.z, solver::WrapAngle(yaw), scale}, -1});
        }
      }
    }
  }
  return out;
}

// An update_pose (and an update_scale first when the scale changes) for a candidate.
std::vector<solver::Action> ActionsFor(const Room& room, int m, const Candidate& c, const std::string& why) {
  std::vector<solver::Action> seq;
  const solver::ObjectPlacement& now = room.solution.placements[m];
  const std::string& id = room.solution.objects[m].id;
  if (std::abs(c.pose.scale - now.pose.scale) > 1e-9) {
    solver::Action scale;
    scale.kind = solver::ActionKind::kUpdateScale;
    scale.id = id;
    scale.scale = c.pose.scale;
    scale.reason = "critic: smaller, so that " + why;
    seq.push_back(scale);
  }
  solver::Action pose;
  pose.kind = solver::ActionKind::kUpdatePose;
  pose.id = id;
  pose.pose = c.pose;
  if (room.solution.objects[m].relation == solver::Relation::kOnWall) pose.pose->z = c.pose.z;
  else pose.pose->z = std::nan("");
  if (c.wall >= 0 && c.wall != now.wall) pose.wall = c.wall;
  if (c.surface >= 0 && c.surface != now.surface) pose.surface = c.surface;
  if (c.cavity >= 0 && c.cavity != now.cavity) pose.cavity = c.cavity;
  pose.reason = "critic: " + why;
  seq.push_back(pose);
  return seq;
}

struct Ranked {
  Unmet unmet;
  double moved = 0.0;
  std::string id;
  Candidate candidate;
  std::vector<Step> steps;
};

std::vector<Step> Steps(std::vector<solver::Action> actions) {
  std::vector<Step> out;
  for (solver::Action& a : actions) out.push_back({std::move(a), false});
  return out;
}
Step Suggested(const std::string& id, const std::string& why) {
  Step step;
  step.action.kind = solver::ActionKind::kUpdatePose;
  step.action.id = id;
  step.action.reason = "critic: " + why + " (re-placed by the solver around the group)";
  step.suggest = true;
  return step;
}

// Ranks the candidates of object m (those that are free and leave fewer unmet relations than now) and
// keeps the best `keep` as alternatives.
void RankInto(const Room& room, int m, const std::vector<Candidate>& candidates, const Unmet& now, double clearance,
              const std::string& why, std::vector<Ranked>& out) {
  const solver::Pose& at = room.solution.placements[m].pose;
  for (const Candidate& c : candidates) {
    if (std::hypot(c.pose.x - at.x, c.pose.y - at.y) < 0.01 && std::abs(solver::WrapAngle(c.pose.yaw - at.yaw)) < 0.01 &&
        std::abs(c.pose.scale - at.scale) < 1e-9)
      continue;
    if (!c.proven && !Free(room, m, c.pose, clearance)) continue;
    const RoomRelations r = MeasureRelations(room.solution.objects, room.Moved(m, c.pose, c.wall), room.graph);
    const Unmet u = UnmetOf(r);
    if (!(u < now)) continue;
    out.push_back({u, std::hypot(c.pose.x - at.x, c.pose.y - at.y), room.solution.objects[m].id, c, Steps(ActionsFor(room, m, c, why))});
  }
}

// The best `keep` candidates the solver says fit, best first.
std::vector<std::vector<Step>> Best(solver::RoomSolver& session, std::vector<Ranked> ranked, int keep) {
  std::stable_sort(ranked.begin(), ranked.end(), [](const Ranked& a, const Ranked& b) {
    if (a.unmet < b.unmet || b.unmet < a.unmet) return a.unmet < b.unmet;
    return a.moved < b.moved;
  });
  std::vector<std::vector<Step>> out;
  int asked = 0;
  for (const Ranked& r : ranked) {
    if (static_cast<int>(out.size()) >= keep || asked >= 8 * keep) break;
    ++asked;
    if (!r.candidate.proven &&
        !session.Fits(r.id, r.candidate.pose, r.candidate.wall >= 0 ? std::optional<int>(r.candidate.wall) : std::nullopt))
      continue;
    out.push_back(r.steps);
  }
  return out;
}

// Poses with room around them for a hub (the objects related to it are about to be re-placed, so only the
// others count): along its walls for a wall-bound hub, on a grid over the free floor otherwise; the
// roomiest first, at most `keep`.
std::vector<Candidate> RoomyPoses(const Room& room, int hub, const std::set<int>& group, double clearance, int keep) {
  const solver::ProblemObject& o = room.solution.objects[hub];
  const solver::ObjectPlacement& now = room.solution.placements[hub];
  const double scale = now.pose.scale;
  std::vector<Candidate> poses;
  if (WallBound(o)) {
    for (size_t w = 0; w < room.problem.walls.size(); ++w) {
      if (o.wall >= 0 && static_cast<int>(w) != o.wall) continue;
      const double length = geo::Dist(room.problem.walls[w].a, room.problem.walls[w].b);
      for (double t = 0.0; t < length; t += 0.2)
        if (auto c = OnWallAt(room, hub, static_cast<int>(w), t, scale)) poses.push_back(*c);
    }
  } else if (!OnObject(o)) {
    Box2 box = BoundingBox(room.problem.free_floor);
    for (double x = box.min_x + 0.2; x < box.max_x; x += 0.3)
      for (double y = box.min_y + 0.2; y < box.max_y; y += 0.3)
        for (double turn : {0.0, 0.5 * std::numbers::pi})
          poses.push_back({{x, y, now.pose.z, solver::WrapAngle(now.pose.yaw + turn), scale}, -1});
  }
  struct Scored {
    double room = 0.0;
    Candidate c;
  };
  std::vector<Scored> scored;
  for (const Candidate& c : poses) {
    if (std::hypot(c.pose.x - now.pose.x, c.pose.y - now.pose.y) < 0.2) continue;
    if (!Free(room, hub, c.pose, clearance, group)) continue;
    solver::ObjectPlacement pl = now;
    pl.pose = c.pose;
    const ObjectBox box = BoxOf(o, pl);
    double gap = 1.0;
    for (size_t j = 0; j < room.solution.objects.size(); ++j) {
      if (static_cast<int>(j) == hub || room.parent[j] >= 0 || group.count(static_cast<int>(j))) continue;
      if (Covering(room.solution.objects[j], room.solution.placements[j].pose.scale)) continue;
      gap = std::min(gap, PlanGap(box, BoxOf(room.solution.objects[j], room.solution.placements[j])));
    }
    if (!WallBound(o))
      for (const Point& p : box.Footprint()) gap = std::min(gap, DistanceToBoundary(p, room.problem.free_floor));
    scored.push_back({gap, c});
  }
  std::stable_sort(scored.begin(), scored.end(), [](const Scored& a, const Scored& b) { return a.room > b.room + 1e-9; });
  std::vector<Candidate> out;
  for (const Scored& s : scored) {
    if (static_cast<int>(out.size()) >= keep) break;
    out.push_back(s.c);
  }
  return out;
}

}  // namespace

Unmet UnmetOf(const RoomRelations& r) {
  Unmet u;
  for (const EdgeCheck& c : r.edges) {
    if (c.present && c.satisfied) continue;
    ++u.count;
    u.amount += c.present ? c.violation : 1.0;
  }
  for (const ZoneCheck& z : r.zones) {
    if (z.clear()) continue;
    ++u.count;
    u.amount += 0.5 * static_cast<double>(z.intruders.size());
  }
  return u;
}

double OfflineScore(const RoomRelations& relations) {
  const int total = static_cast<int>(relations.edges.size() + relations.zones.size());
  if (total == 0) return 10.0;
  return 10.0 * (relations.Satisfied() + relations.ZonesClear()) / total;
}

std::vector<std::string> OfflineProblems(const std::string& room, const RoomRelations& relations) {
  std::vector<std::string> out;
  for (const EdgeCheck& c : relations.edges) {
    if (c.present && c.satisfied) continue;
    out.push_back(ShortId(room, c.edge.source) + " " + std::string(scene::SemanticRelationName(c.edge.relation)) + " " +
                  ShortId(room, c.edge.target) + ": " + c.detail);
  }
  for (const ZoneCheck& z : relations.zones) {
    if (z.clear()) continue;
    std::string line = "zone " + z.side + " of " + ShortId(room, z.owner) + " (" + FormatFixed(z.depth, 2) + " m) entered by";
    for (const std::string& id : z.intruders) line += ' ' + ShortId(room, id);
    out.push_back(line);
  }
  return out;
}

namespace {

using Suggestions = std::function<const std::vector<Candidate>&(int object)>;

// Poses near where object k stands (a step of 0.25 to 1.2 m in eight directions, or along its wall), for
// making room: `away` is the box it must keep clear of.
std::vector<Candidate> StepsAside(const Room& room, int k, const ObjectBox& away, double clearance,
                                  const std::vector<double>& steps = {0.25, 0.5, 0.8, 1.2}) {
  const solver::ProblemObject& o = room.solution.objects[k];
  const solver::ObjectPlacement& now = room.solution.placements[k];
  std::vector<Candidate> out;
  if (WallBound(o)) {
    const int w = now.wall;
    if (w < 0) return out;
    const double t = AlongWall(room, w, {now.pose.x, now.pose.y});
    for (double step : steps)
      for (double sign : {-1.0, 1.0})
        if (auto c = OnWallAt(room, k, w, t + sign * step, now.pose.scale)) out.push_back(*c);
    // Something hung (a towel rail in the place of a mirror) may go to another wall as well: it stands in
    // no one's way there.
    if (o.relation == solver::Relation::kOnWall)
      for (const Candidate& c : AlongEveryWall(room, k, 0.25, now.pose.scale, w)) out.push_back(c);
  } else if (!OnObject(o)) {
    for (double step : steps)
      for (int dir = 0; dir < 8; ++dir) {
        const double a = dir * std::numbers::pi / 4.0;
        out.push_back({{now.pose.x + step * std::cos(a), now.pose.y + step * std::sin(a), now.pose.z, now.pose.yaw, now.pose.scale}, -1});
      }
  }
  std::vector<Candidate> kept;
  for (const Candidate& c : out) {
    solver::ObjectPlacement pl = now;
    pl.pose = c.pose;
    if (PlanGap(BoxOf(o, pl), away) >= clearance) kept.push_back(c);
  }
  return kept;
}

// Moves that make room: a pose of object m where the edge would hold but one free-standing object k stands
// in the way; k steps aside first (to a free pose clear of m's new box), then m moves. Kept when the two
// together leave fewer unmet relations.
// With `loose_hung_only`, only a hung object without relations is asked to step aside (a towel rail).
void PushesInto(const Room& room, int m, int other, const std::vector<Candidate>& candidates, const Unmet& now, double clearance,
                const std::string& why, std::vector<Ranked>& out, bool loose_hung_only = false) {
  int tried = 0;
  for (const Candidate& c : candidates) {
    if (tried >= 40) break;
    auto blockers = Blockers(room, m, c.pose, clearance);
    if (!blockers || blockers->size() != 1) continue;
    const int k = (*blockers)[0];
    if (k == other || !room.children[k].empty() || Covering(room.solution.objects[k], room.solution.placements[k].pose.scale)) continue;
    if (loose_hung_only && (room.solution.objects[k].relation != solver::Relation::kOnWall ||
                            std::any_of(room.graph.begin(), room.graph.end(), [&](const scene::SemanticEdge& e) {
                              return e.source == room.solution.objects[k].id || e.target == room.solution.objects[k].id;
                            })))
      continue;
    ++tried;
    solver::ObjectPlacement moved = room.solution.placements[m];
    moved.pose = c.pose;
    const ObjectBox m_box = BoxOf(room.solution.objects[m], moved);
    for (const Candidate& aside : StepsAside(room, k, m_box, clearance)) {
      if (!Free(room, k, aside.pose, clearance, {m})) continue;
      const auto placements = room.Moved(room.Moved(k, aside.pose, aside.wall), m, c.pose, c.wall);
      const Unmet u = UnmetOf(MeasureRelations(room.solution.objects, placements, room.graph));
      if (!(u < now)) continue;
      std::vector<Step> steps = Steps(ActionsFor(room, k, aside, why + " (making room)"));
      const std::vector<Step> then = Steps(ActionsFor(room, m, c, why));
      steps.insert(steps.end(), then.begin(), then.end());
      out.push_back({u, std::hypot(c.pose.x - room.solution.placements[m].pose.x, c.pose.y - room.solution.placements[m].pose.y) +
                            std::hypot(aside.pose.x - room.solution.placements[k].pose.x, aside.pose.y - room.solution.placements[k].pose.y),
                     room.solution.objects[k].id, aside, std::move(steps)});
      break;  // the nearest free step for this candidate
    }
  }
}

// Moves of one object (either end of the edge, or what carries it) that make the edge hold: the solver's
// own suggestion, then the candidate poses of CandidatesFor, at the object's scale and, when none is
// free, at its smallest.
Attempt SingleMoves(solver::RoomSolver& session, const Room& room, const EdgeCheck& c, int s, int t, const Unmet& now,
                    const OfflineProposalOptions& options, const std::string& line, const Suggestions& suggestion) {
  std::vector<Ranked> ranked;
  for (int m : {s, t}) {
    const int mover = room.Root(m);
    const int other = m == s ? t : s;
    if (mover == room.Root(other)) continue;
    RankInto(room, m, suggestion(m), now, options.clearance, line, ranked);
    if (mover != m) RankInto(room, mover, suggestion(mover), now, options.clearance, line, ranked);
    const solver::ProblemObject& o = room.solution.objects[mover];
    const double scale = room.solution.placements[mover].pose.scale;
    const std::vector<Candidate> candidates = CandidatesFor(room, mover, room.Root(other), c.edge, scale);
    RankInto(room, mover, candidates, now, options.clearance, line, ranked);
    // At the smallest scale too when nothing fits at this one, and always for wall decor (a smaller picture
    // fits between the window and the corner, centred over the sofa).
    if ((ranked.empty() || o.relation == solver::Relation::kOnWall) && o.scale_min < scale - 1e-9)
      RankInto(room, mover, CandidatesFor(room, mover, room.Root(other), c.edge, o.scale_min), now, options.clearance, line, ranked);
    if (ranked.empty()) PushesInto(room, mover, room.Root(other), candidates, now, options.clearance, line, ranked);
    // Where the free poses only bring the edge nearer, a loose hung object stepping aside may let it hold
    // (the mirror's place over the basin taken by a towel rail); ranked with the rest, a mend goes first.
    else if (std::none_of(ranked.begin(), ranked.end(), [&](const Ranked& r) { return r.unmet.count < now.count; }))
      PushesInto(room, mover, room.Root(other), candidates, now, options.clearance, line, ranked, true);
  }
  return Attempt{line, Best(session, std::move(ranked), options.alternatives)};
}

// The run through object m: the wall-standing objects (against_wall, nothing under them) linked to it by
// next_to edges, in the order of the chain (a kitchen's fridge, counters, cooker, dishwasher); empty unless
// they form one simple path of three or more.
std::vector<int> RunThrough(const Room& room, int m) {
  const auto standing = [&](int k) {
    return k >= 0 && room.parent[k] < 0 && room.solution.objects[k].relation == solver::Relation::kAgainstWall;
  };
  if (!standing(m)) return {};
  std::map<int, std::set<int>> links;
  for (const scene::SemanticEdge& e : room.graph) {
    if (e.relation != scene::SemanticRelation::kNextTo) continue;
    const int a = room.Find(e.source), b = room.Find(e.target);
    if (a == b || !standing(a) || !standing(b)) continue;
    links[a].insert(b);
    links[b].insert(a);
  }
  std::set<int> seen{m};
  std::vector<int> stack{m};
  size_t link_count = 0;
  while (!stack.empty()) {
    const int k = stack.back();
    stack.pop_back();
    link_count += links[k].size();
    if (links[k].size() > 2) return {};
    for (int j : links[k])
      if (seen.insert(j).second) stack.push_back(j);
  }
  if (seen.size() < 3 || link_count / 2 != seen.size() - 1) return {};
  int end = -1;
  for (int k : seen)
    if (links[k].size() == 1) {
      end = k;
      break;
    }
  std::vector<int> order{end};
  for (int prev = -1, at = end; order.size() < seen.size();) {
    const int next = *links[at].begin() != prev ? *links[at].begin() : *links[at].rbegin();
    prev = at;
    at = next;
    order.push_back(at);
  }
  return order;
}

// Several objects moved together (a run laid out again, a cluster carried): the relations left unmet, how
// far they move, the moves in the order they are applied, and what the solver re-places after them.
struct MultiMove {
  Unmet unmet;
  double moved = 0.0;
  std::vector<std::pair<int, Candidate>> poses{};
  std::vector<int> ring{};
  int displaced = 0;  // of the ring, those that were in the way (not the group's own): fewer is better
  // Moved after `poses`, in any order, with their own reason (a rug keeping its place under a moving bed).
  std::vector<std::pair<int, Candidate>> after{};
  std::string after_how{};
  bool unordered = false;  // `poses` still to be put in an order (MoveOrder) when chosen; none found: passed over
};

// An order of moves taking each object of `poses` to its pose, where none enters the place of one still to
// move (height ranges counted: an upper cabinet hangs over a counter). Where every remaining one waits for
// another (a cycle: the cooker must pass the fridge; a counter and the cabinet over it), one of them is
// parked first (all of them stand against or hang on walls), what hangs before what stands, clear of
// everything, of where the others stand and of every pose to come, and moved on when its pose is free.
// False when no order is found.
bool MoveOrder(const Room& room, const std::vector<std::pair<int, Candidate>>& poses, double clearance,
               std::vector<std::pair<int, Candidate>>* order, bool hung_first = false) {
  const size_t n = poses.size();
  std::vector<solver::ObjectPlacement> at(n);
  std::vector<ObjectBox> target(n);
  for (size_t a = 0; a < n; ++a) {
    at[a] = room.solution.placements[poses[a].first];
    solver::ObjectPlacement pl = at[a];
    pl.pose = poses[a].second.pose;
    target[a] = BoxOf(room.solution.objects[poses[a].first], pl);
  }
  const auto height = [&](size_t a) { return room.stack_top[poses[a].first] - room.solution.placements[poses[a].first].pose.z; };
  const auto meets = [&](const ObjectBox& box, double top, const ObjectBox& other, double other_top) {
    return PlanGap(box, other) < 0.02 && std::min(top, other_top) > std::max(box.z0, other.z0) - 0.05;  // with margins
  };
  // A rug lies under the others: it neither blocks nor is blocked.
  const auto covering = [&](size_t a) { return Covering(room.solution.objects[poses[a].first], at[a].pose.scale); };
  std::vector<bool> done(n, false), parked(n, false);
  for (size_t step = 0; step < 2 * n + 1; ++step) {
    int pick = -1;
    for (size_t a = 0; a < n && pick < 0; ++a) {
      if (done[a]) continue;
      bool clear = true;
      for (size_t b = 0; b < n && clear; ++b) {
        if (b == a || done[b] || covering(a) || covering(b)) continue;
        const ObjectBox there = BoxOf(room.solution.objects[poses[b].first], at[b]);
        clear = !meets(target[a], target[a].z0 + height(a), there, there.z0 + height(b));
      }
      if (clear) pick = static_cast<int>(a);
    }
    if (pick >= 0) {
      done[pick] = true;
      at[pick].pose = poses[pick].second.pose;
      order->push_back(poses[pick]);
      if (order->size() >= n + std::count(parked.begin(), parked.end(), true)) return true;
      continue;
    }
    // Park a waiting object not parked yet: the first one, on another wall than its pose's; or with
    // `hung_first`, what hangs before what stands (a wall has room for it more often), anywhere along a wall
    // where it meets neither another's place now nor any place to come.
    std::vector<size_t> waiting;
    for (size_t a = 0; a < n; ++a)
      if (!done[a] && !parked[a]) waiting.push_back(a);
    if (waiting.empty()) return false;
    if (hung_first) {
      std::stable_sort(waiting.begin(), waiting.end(), [&](size_t a, size_t b) {
        return (room.solution.objects[poses[a].first].relation == solver::Relation::kOnWall) >
               (room.solution.objects[poses[b].first].relation == solver::Relation::kOnWall);
      });
    }
    std::set<int> moving;
    for (const auto& p : poses) moving.insert(p.first);
    int park = -1;
    std::optional<Candidate> spot;
    for (size_t a : waiting) {
      const int obj = poses[a].first;
      for (const Candidate& c : AlongEveryWall(room, obj, hung_first ? 0.1 : 0.25, at[a].pose.scale, hung_first ? -1 : poses[a].second.wall)) {
        if (!(hung_first ? Free(room, obj, c.pose, clearance, moving) : Free(room, obj, c.pose, clearance))) continue;
        solver::ObjectPlacement pl = at[a];
        pl.pose = c.pose;
        const ObjectBox box = BoxOf(room.solution.objects[obj], pl);
        bool clear = true;
        for (size_t b = 0; b < n && clear; ++b) {
          if (hung_first && b == a) continue;
          clear = !meets(box, box.z0 + height(a), target[b], target[b].z0 + height(b));
          if (clear && hung_first) {
            const ObjectBox there = BoxOf(room.solution.objects[poses[b].first], at[b]);
            clear = !meets(box, box.z0 + height(a), there, there.z0 + height(b));
          }
        }
        if (clear) {
          spot = c;
          break;
        }
      }
      if (spot) {
        park = static_cast<int>(a);
        break;
      }
      if (!hung_first) break;  // only the first waiting one
    }
    if (!spot) return false;
    const int k = poses[park].first;
    parked[park] = true;
    at[park].pose = spot->pose;
    at[park].wall = spot->wall;
    order->push_back({k, *spot});
  }
  return false;
}

// The best `keep` of them (fewest unmet, then fewest displaced, then least moved) as step sequences.
std::vector<std::vector<Step>> BestMultiMoves(const Room& room, std::vector<MultiMove> moves, int keep, const std::string& why,
                                              const std::string& how, double clearance = 0.0) {
  std::stable_sort(moves.begin(), moves.end(), [](const MultiMove& a, const MultiMove& b) {
    if (a.unmet < b.unmet || b.unmet < a.unmet) return a.unmet < b.unmet;
    if (a.displaced != b.displaced) return a.displaced < b.displaced;
    return a.moved < b.moved;
  });
  std::vector<std::vector<Step>> out;
  for (MultiMove& l : moves) {
    if (static_cast<int>(out.size()) >= keep) break;
    if (l.unordered) {
      std::vector<std::pair<int, Candidate>> order;
      if (!MoveOrder(room, l.poses, clearance, &order)) continue;
      l.poses = std::move(order);
    }
    std::vector<Step> steps;
    for (const auto& [k, c] : l.poses) {
      const std::vector<Step> more = Steps(ActionsFor(room, k, c, why + " (" + how + ")"));
      steps.insert(steps.end(), more.begin(), more.end());
    }
    for (const auto& [k, c] : l.after) {
      const std::vector<Step> more = Steps(ActionsFor(room, k, c, why + " (" + l.after_how + ")"));
      steps.insert(steps.end(), more.begin(), more.end());
    }
    for (int k : l.ring) steps.push_back(Suggested(room.solution.objects[k].id, why));
    out.push_back(std::move(steps));
  }
  return out;
}

// A unit of a kitchen's run: a counter, the fridge, the cooker, the dishwasher.
bool KitchenUnit(const solver::ProblemObject& o) {
  return o.category == "counter" || o.category == "fridge" || o.category == "cooker" || o.category == "dishwasher";
}

// A layout of a run: where each member (and what hangs behind it) goes, in the order the moves are applied.
struct RunLayout {
  Unmet unmet;
  double moved = 0.0;
  std::vector<std::pair<int, Candidate>> poses;
  std::vector<std::pair<int, Candidate>> before;  // moved first: things on members slid (ShiftsOffKeepOuts),
                                                  // a table and its chairs out of the way (MakeRoomForRun)
};
using MemberPoses = std::vector<std::pair<int, Candidate>>;

// What hangs on the wall behind a run's member (a counter's upper cabinet, the cooker's hood): (hung object,
// member). It moves with its member, keeping its place along the wall relative to it.
std::vector<std::pair<int, int>> HungOverRun(const Room& room, const std::set<int>& members) {
  std::vector<std::pair<int, int>> hung;
  for (const scene::SemanticEdge& e : room.graph) {
    if (e.relation != scene::SemanticRelation::kBehind) continue;
    const int h = room.Find(e.source), member = room.Find(e.target);
    if (h < 0 || member < 0 || !members.count(member) || members.count(h) || room.parent[h] >= 0 ||
        room.solution.objects[h].relation != solver::Relation::kOnWall)
      continue;
    hung.push_back({h, member});
  }
  return hung;
}

// How far (m) box `from` slides along the unit direction u, in steps of 2 cm from `first` to `last` steps
// each length tried to both sides (the nearer first), within [lo, hi], before it stays out of the room's
// keep-outs and 5 mm clear of every box of `boxes` but `self` that it meets in height; nullopt if never.
std::optional<double> SlideClear(const Room& room, const ObjectBox& from, Point u, int first, int last, double lo, double hi,
                                 const std::vector<ObjectBox>& boxes, int self) {
  for (int step = first; step <= last; ++step) {
    for (double sign : {-1.0, 1.0}) {
      const double dx = sign * 0.02 * step;
      if (dx < lo || dx > hi || (step == 0 && sign > 0)) continue;
      ObjectBox there = from;
      there.c = geo::Add(from.c, geo::Scale(u, dx));
      if (InKeepOut(room, there)) continue;
      bool clear = true;
      for (size_t o = 0; o < boxes.size() && clear; ++o)
        clear = static_cast<int>(o) == self || HeightOverlap(there, boxes[o]) <= 0.0 || PlanGap(there, boxes[o]) >= 0.005;
      if (clear) return dx;
    }
  }
  return std::nullopt;
}

// A place for child `ch` of member k on another surface of k (an open shelf of a counter, never the floor of
// a closed cell): the surface index and the place in the member's frame (m along its width and depth).
// `top` is the member's box where it goes, `boxes` its children's boxes there (the one at `self` is the
// child's); none clears a keep-out and every other child by 5 mm, within the surface's extent and under
// the room above it.
struct ShelfPlace {
  int surface = -1;
  double x = 0.0, y = 0.0;
};
std::optional<ShelfPlace> OnLowerShelf(const Room& room, int k, int ch, const ObjectBox& top, std::vector<ObjectBox>& boxes, int self) {
  const solver::ProblemObject& child = room.solution.objects[ch];
  const solver::ProblemObject& member = room.solution.objects[k];
  if (child.surface >= 0 || child.category == "sink") return std::nullopt;
  const double scale = room.solution.placements[k].pose.scale;
  const ObjectBox at = boxes[self];
  const double height = at.z1 - at.z0;
  const double hx = HalfAlong(at.hx, at.hy, at.yaw - top.yaw, {1.0, 0.0}), hy = HalfAlong(at.hx, at.hy, at.yaw - top.yaw, {0.0, 1.0});
  for (size_t j = 0; j < member.asset.support_surfaces.size(); ++j) {
    const SupportSurface& surface = member.asset.support_surfaces[j];
    if (static_cast<int>(j) == room.solution.placements[ch].surface || surface.clear_height * scale < height + 0.01) continue;
    if (member.asset.ClosedCellFloor(static_cast<int>(j))) continue;  // behind a door: not a place to stand things
    const Box2 extent = BoundingBox(surface.polygon);
    const double x0 = extent.min_x * scale + hx + 0.01, x1 = extent.max_x * scale - hx - 0.01;
    const double y = 0.5 * (extent.min_y + extent.max_y) * scale;
    if (x1 < x0 || (extent.max_y - extent.min_y) * scale < 2.0 * hy + 0.02) continue;
    const double mid = 0.5 * (x0 + x1);
    ObjectBox there = at;  // at the shelf's middle, then slid along it
    there.c = geo::Add(geo::Add(top.c, geo::Scale(top.U(), mid)), geo::Scale(top.V(), y));
    there.z0 = top.z0 + surface.z * scale;
    there.z1 = there.z0 + height;
    if (const std::optional<double> dx = SlideClear(room, there, top.U(), 0, 100, x0 - mid, x1 - mid, boxes, self)) {
      there.c = geo::Add(there.c, geo::Scale(top.U(), *dx));
      boxes[self] = there;
      return ShelfPlace{static_cast<int>(j), mid + *dx, y};
    }
  }
  return std::nullopt;
}

// What stands on the run's members and would enter a keep-out where they go (a window's zone starts at the
// sill: a counter under it is low enough, the kettle on it is not): each such thing slid along its member's
// top, the nearest first, to where it stays clear of the keep-outs and of the things beside it, else onto an
// open shelf of the member; the shifts, as poses in the member's present frame (made before the member
// moves, which carries them). A decorative thing with no such place is taken out (issue 27: never into a
// closed cell behind a door, and optional pieces go first); nullopt when another finds none: the layout
// would lose it, so it is not tried.
std::optional<std::vector<std::pair<int, Candidate>>> ShiftsOffKeepOuts(const Room& room,
                                                                        const std::vector<std::pair<int, Candidate>>& members) {
  std::vector<std::pair<int, Candidate>> shifts;
  for (const auto& [k, c] : members) {
    const std::vector<solver::ObjectPlacement> moved = room.Moved(k, c.pose, c.wall);
    std::vector<ObjectBox> boxes;  // the children where they will stand, shifts included
    std::vector<int> stuck;
    for (int ch : room.children[k]) {
      boxes.push_back(BoxOf(room.solution.objects[ch], moved[ch]));
      if (InKeepOut(room, boxes.back())) stuck.push_back(static_cast<int>(boxes.size()) - 1);
    }
    if (stuck.empty()) continue;
    solver::ObjectPlacement member = room.solution.placements[k];
    member.pose = c.pose;
    const ObjectBox top = BoxOf(room.solution.objects[k], member);
    const Point u = top.U();
    for (int s : stuck) {
      const int ch = room.children[k][s];
      if (!room.children[ch].empty() || room.solution.objects[ch].relation != solver::Relation::kOnTop) return std::nullopt;
      const ObjectBox at = boxes[s];
      const double half = HalfAlong(at.hx, at.hy, at.yaw - top.yaw, {1.0, 0.0});
      const double local = geo::Dot(geo::Sub(at.c, top.c), u), room_on_top = top.hx - 0.01 - half;
      const std::optional<double> best = SlideClear(room, at, u, 1, 200, -room_on_top - local, room_on_top - local, boxes, s);
      if (best) boxes[s].c = geo::Add(at.c, geo::Scale(u, *best));
      const ObjectBox member_now = BoxOf(room.solution.objects[k], room.solution.placements[k]);
      const solver::ObjectPlacement& now = room.solution.placements[ch];
      Candidate shift;
      shift.pose = now.pose;
      if (best) {
        shift.pose.x += member_now.U().x * *best;
        shift.pose.y += member_now.U().y * *best;
      } else {
        // Down onto a shelf of the member (below the sill), where the solver may put it (not pinned to
        // its surface, not a sink: a sink belongs on the worktop).
        const auto shelf = OnLowerShelf(room, k, ch, top, boxes, s);
        if (!shelf && room.solution.objects[ch].priority == solver::Priority::kDecorative) {
          shift.remove = true;
          shifts.push_back({ch, shift});
          continue;
        }
        if (!shelf) return std::nullopt;
        shift.pose.x = member_now.c.x + member_now.U().x * shelf->x + member_now.V().x * shelf->y;
        shift.pose.y = member_now.c.y + member_now.U().y * shelf->x + member_now.V().y * shelf->y;
        shift.surface = shelf->surface;
      }
      shifts.push_back({ch, shift});
    }
  }
  return shifts;
}

// The width and the depth of object k as it stands (its scale), m.
double WidthOf(const Room& room, int k) { return room.solution.objects[k].asset.size.x * room.solution.placements[k].pose.scale; }
double DepthOf(const Room& room, int k) { return room.solution.objects[k].asset.size.y * room.solution.placements[k].pose.scale; }

// Moves that make room for a run's layout: the free-standing objects `movers` (a dining table and its chairs)
// shifted together by one translation, the shortest on a 10 cm grid up to 3 m, to where each keeps
// `clearance` from everything else as it stands now (the run's members still at their places) and from
// `targets` (where the run goes), on the free floor and out of the keep-outs; in an order where none enters
// the place of another still to move. Nullopt when no translation or order is found.
std::optional<MemberPoses> MakeRoomForRun(const Room& room, const std::vector<int>& movers, const std::vector<ObjectBox>& targets,
                                          double clearance) {
  const std::set<int> ignore(movers.begin(), movers.end());
  // Shifts on a 10 cm grid up to 3 m, nearest first: the same for every call, built once.
  static const std::vector<Point> deltas = [] {
    std::vector<Point> out;
    for (int i = -30; i <= 30; ++i)
      for (int j = -30; j <= 30; ++j)
        if (i != 0 || j != 0) out.push_back({0.1 * i, 0.1 * j});
    std::stable_sort(out.begin(), out.end(), [](Point a, Point b) { return std::hypot(a.x, a.y) < std::hypot(b.x, b.y) - 1e-9; });
    return out;
  }();
  for (const Point& d : deltas) {
    if (std::hypot(d.x, d.y) > 3.0) break;
    MemberPoses poses;
    for (int m : movers) {
      Candidate c;
      c.pose = room.solution.placements[m].pose;
      c.pose.x += d.x;
      c.pose.y += d.y;
      const ObjectBox box = BoxAt(room, m, c.pose);
      bool clear = std::all_of(targets.begin(), targets.end(), [&](const ObjectBox& t) {
        return PlanGap(box, t) >= clearance || std::min(room.stack_top[m] - room.solution.placements[m].pose.z + box.z0, t.z1) <= std::max(box.z0, t.z0);
      });
      if (!clear || !Free(room, m, c.pose, clearance, ignore)) break;
      poses.push_back({m, c});
    }
    if (poses.size() != movers.size()) continue;
    // The one furthest along the shift goes first: none then enters the place of one still to move.
    std::stable_sort(poses.begin(), poses.end(), [&](const auto& a, const auto& b) {
      const solver::Pose& pa = room.solution.placements[a.first].pose;
      const solver::Pose& pb = room.solution.placements[b.first].pose;
      return pa.x * d.x + pa.y * d.y > pb.x * d.x + pb.y * d.y + 1e-9;
    });
    bool ordered = true;
    for (size_t a = 0; a < poses.size() && ordered; ++a) {
      const ObjectBox there = BoxAt(room, poses[a].first, poses[a].second.pose);
      for (size_t b = a + 1; b < poses.size() && ordered; ++b)
        ordered = PlanGap(there, BoxOf(room.solution.objects[poses[b].first], room.solution.placements[poses[b].first])) >= 0.01;
    }
    if (ordered) return poses;
  }
  return std::nullopt;
}

// Completes a layout of the run's members (`poses`, each on its wall) with what hangs behind them, finds an
// order of moves (MoveOrder) and measures it; kept in `layouts` when it leaves fewer unmet relations than
// `now`. Hung objects of members on different walls must not meet (round a corner they could). `movers`
// (free-standing objects the members may have been placed over) are moved out of the way first.
void AddRunLayout(const Room& room, MemberPoses poses, const std::vector<std::pair<int, int>>& hung, const std::set<int>& group,
                  const std::vector<int>& movers, const Unmet& now, double clearance, std::vector<RunLayout>* layouts) {
  const size_t members = poses.size();
  auto before = ShiftsOffKeepOuts(room, poses);
  if (!before) return;
  std::set<int> ignore = group;
  ignore.insert(movers.begin(), movers.end());
  for (const auto& [h, member] : hung) {
    const auto at_member = std::find_if(poses.begin(), poses.begin() + members, [&](const auto& p) { return p.first == member; });
    const int w = at_member->second.wall;
    const solver::WallEdge& wall = room.problem.walls[w];
    const Point d = geo::Unit(geo::Sub(wall.b, wall.a));
    const solver::ObjectPlacement& mp = room.solution.placements[member];
    const solver::ObjectPlacement& hp = room.solution.placements[h];
    // Its offset along the member's width now, kept (0 when it hangs on another wall): it stays clear of what
    // stands on the member as it is now.
    const double offset = hp.wall == mp.wall ? geo::Dot(geo::Sub({hp.pose.x, hp.pose.y}, {mp.pose.x, mp.pose.y}), d) : 0.0;
    const double t = geo::Dot(geo::Sub({at_member->second.pose.x, at_member->second.pose.y}, wall.a), d) + offset;
    auto c = OnWallAt(room, h, w, t, hp.pose.scale);
    if (!c || !Free(room, h, c->pose, clearance, ignore)) return;
    const ObjectBox box = BoxAt(room, h, c->pose);
    for (size_t k = members; k < poses.size(); ++k) {
      const ObjectBox b = BoxAt(room, poses[k].first, poses[k].second.pose);
      if (PlanGap(box, b) < clearance && std::min(box.z1, b.z1) > std::max(box.z0, b.z0)) return;
    }
    poses.push_back({h, *c});
  }
  std::vector<solver::ObjectPlacement> placements = room.solution.placements;
  if (!movers.empty()) {
    std::vector<ObjectBox> targets;
    for (const auto& [k, c] : poses) {
      ObjectBox box = BoxAt(room, k, c.pose);
      box.z1 = c.pose.z + room.stack_top[k] - room.solution.placements[k].pose.z;
      targets.push_back(box);
    }
    auto room_made = MakeRoomForRun(room, movers, targets, clearance);
    if (!room_made) return;
    for (const auto& [k, c] : *room_made) placements = room.Moved(placements, k, c.pose, -1);
    before->insert(before->begin(), room_made->begin(), room_made->end());
  }
  std::vector<std::pair<int, Candidate>> order;
  if (!MoveOrder(room, poses, clearance, &order, true)) return;
  for (const auto& [k, c] : *before)
    if (!c.remove && !std::count(movers.begin(), movers.end(), k)) placements[k].pose = c.pose;
  double moved = 0.0;
  for (const auto& [k, c] : poses) {
    placements = room.Moved(placements, k, c.pose, c.wall);
    moved += std::hypot(c.pose.x - room.solution.placements[k].pose.x, c.pose.y - room.solution.placements[k].pose.y);
  }
  for (int m : movers) moved += std::hypot(placements[m].pose.x - room.solution.placements[m].pose.x, placements[m].pose.y - room.solution.placements[m].pose.y);
  const Unmet u = UnmetOf(MeasureRelations(room.solution.objects, placements, room.graph));
  if (u < now) layouts->push_back({u, moved, std::move(order), std::move(*before)});
}

// Whether object k may stand against wall w (some objects are held to one wall).
bool MayStandOn(const Room& room, int k, int w) { return room.solution.objects[k].wall < 0 || room.solution.objects[k].wall == w; }

// Member k of a run against wall w, centred `t` m along it, free of everything but `ignore` (what stands on
// it is not counted: ShiftsOffKeepOuts keeps it out of the keep-outs).
std::optional<Candidate> RunMemberAt(const Room& room, int k, int w, double t, const std::set<int>& ignore, double clearance) {
  if (!MayStandOn(room, k, w)) return std::nullopt;
  auto c = OnWallAt(room, k, w, t, room.solution.placements[k].pose.scale);
  if (!c || !Free(room, k, c->pose, clearance, ignore, true)) return std::nullopt;
  return c;
}

// Members `chain` side by side along wall w, `joint` apart, from `start` m along it onwards (`direction` 1)
// or backwards (-1); false when one does not fit there.
bool LayAlong(const Room& room, const std::vector<int>& chain, int w, double start, double direction, const std::set<int>& ignore,
              double clearance, double joint, MemberPoses* poses) {
  double at = start;
  for (int k : chain) {
    auto c = RunMemberAt(room, k, w, at + direction * 0.5 * WidthOf(room, k), ignore, clearance);
    if (!c) return false;
    poses->push_back({k, *c});
    at += direction * (WidthOf(room, k) + joint);
  }
  return true;
}

// Layouts of the run along one wall: its members in the chain's order, `joint` apart, slid along the wall
// in 5 cm steps, either way round; free of everything but `ignore`.
std::vector<MemberPoses> StraightRunLayouts(const Room& room, const std::vector<int>& run, const std::set<int>& ignore, double clearance,
                                            double joint) {
  std::vector<MemberPoses> out;
  double total = 0.0;
  for (int k : run) total += WidthOf(room, k) + joint;
  for (size_t w = 0; w < room.problem.walls.size(); ++w) {
    const double length = geo::Dist(room.problem.walls[w].a, room.problem.walls[w].b);
    if (length < total) continue;
    for (bool reversed : {false, true}) {
      for (double start = 0.0; start + total <= length + joint; start += 0.05) {
        std::vector<int> chain = run;
        if (reversed) std::reverse(chain.begin(), chain.end());
        MemberPoses poses;
        if (LayAlong(room, chain, static_cast<int>(w), start, 1.0, ignore, clearance, joint, &poses)) out.push_back(std::move(poses));
      }
    }
  }
  return out;
}

// Layouts of the run as an L: along two walls meeting in a room's corner at a right angle (wall a ends where
// wall b starts, the room on the left of both), the first members on wall a up to the corner, the rest on
// wall b from it, split after every member, either way round. The corner square stays empty (a blind
// corner): the last member of wall a stops `joint` short of the front of wall b's first member and that one
// starts `joint` past the last one's front, so the two boxes touch across the corner (next_to holds: the gap
// is the widest separation along a face normal) and neither stands in the other's front zone.
std::vector<MemberPoses> CornerRunLayouts(const Room& room, const std::vector<int>& run, const std::set<int>& ignore, double clearance,
                                          double joint) {
  std::vector<MemberPoses> out;
  const auto& walls = room.problem.walls;
  for (size_t a = 0; a < walls.size(); ++a) {
    for (size_t b = 0; b < walls.size(); ++b) {
      if (a == b || geo::Dist(walls[a].b, walls[b].a) > 0.02) continue;
      const Point da = geo::Unit(geo::Sub(walls[a].b, walls[a].a)), db = geo::Unit(geo::Sub(walls[b].b, walls[b].a));
      if (geo::Cross(da, db) < 0.995) continue;  // a right-angled corner seen from inside the room
      const double length_a = geo::Dist(walls[a].a, walls[a].b);
      for (bool reversed : {false, true}) {
        std::vector<int> chain = run;
        if (reversed) std::reverse(chain.begin(), chain.end());
        for (size_t split = 1; split < chain.size(); ++split) {
          const int last_a = chain[split - 1], first_b = chain[split];
          // Wall a from the corner back (the last member first), wall b from the corner on.
          std::vector<int> leg_a(chain.begin(), chain.begin() + split), leg_b(chain.begin() + split, chain.end());
          std::reverse(leg_a.begin(), leg_a.end());
          MemberPoses poses, on_b;
          if (!LayAlong(room, leg_a, static_cast<int>(a),
                        length_a - room.solution.objects[first_b].wall_gap - DepthOf(room, first_b) - joint, -1.0, ignore, clearance,
                        joint, &poses) ||
              !LayAlong(room, leg_b, static_cast<int>(b), room.solution.objects[last_a].wall_gap + DepthOf(room, last_a) + joint, 1.0,
                        ignore, clearance, joint, &on_b))
            continue;
          std::reverse(poses.begin(), poses.end());
          poses.insert(poses.end(), on_b.begin(), on_b.end());
          out.push_back(std::move(poses));
        }
      }
    }
  }
  return out;
}

// The free-standing objects a run's layout may find in its way (a kitchen's dining table, an island), each
// with the free-standing objects related to it (the chairs round the table): moved together as one.
std::vector<std::vector<int>> MovableSets(const Room& room, const std::set<int>& group) {
  std::vector<std::vector<int>> out;
  const auto free_standing = [&](int k) {
    return k >= 0 && room.parent[k] < 0 && !group.count(k) && !WallBound(room.solution.objects[k]) &&
           room.solution.objects[k].parent == "floor" && !Covering(room.solution.objects[k], room.solution.placements[k].pose.scale);
  };
  for (size_t x = 0; x < room.solution.objects.size(); ++x) {
    const int hub = static_cast<int>(x);
    if (!free_standing(hub) || room.children[hub].empty()) continue;  // a table or an island: it carries things
    std::vector<int> set{hub};
    for (const scene::SemanticEdge& e : room.graph) {
      const int a = room.Find(e.source), b = room.Find(e.target);
      for (auto [mine, other] : {std::pair{a, b}, std::pair{b, a}})
        if (mine == hub && free_standing(other) && !std::count(set.begin(), set.end(), other)) set.push_back(other);
    }
    out.push_back(std::move(set));
  }
  return out;
}

// Run moves for an unmet next_to inside a run: the whole run laid out again in its chain's order, each
// member touching the next (2 cm apart), along one wall (StraightRunLayouts) or round a corner
// (CornerRunLayouts). The members move one after the other in an order where none enters another's present
// place; a layout without such an order is not tried. When no layout is free, the layouts a table or an
// island with its seats stands in the way of are tried with that set moved aside first (MakeRoomForRun).
// Ranked like single moves, the best `keep` kept.
std::vector<std::vector<Step>> RunMoves(const Room& room, int s, int t, const Unmet& now, const OfflineProposalOptions& options,
                                        const std::string& why) {
  const std::vector<int> run = RunThrough(room, s);
  if (run.empty() || std::find(run.begin(), run.end(), t) == run.end()) return {};
  std::set<int> group(run.begin(), run.end());
  const std::vector<std::pair<int, int>> hung = HungOverRun(room, group);
  for (const auto& [h, member] : hung) group.insert(h);
  constexpr double kJoint = 0.02;  // m between neighbours of the run
  constexpr size_t kMaxMadeRoom = 40;  // layouts tried with a set moved aside, per set (each a search)
  // Kitchen units turn corners (an L of counters) and a kitchen's table may make room for them; a bed with
  // its nightstands does neither.
  const bool kitchen = std::all_of(run.begin(), run.end(), [&](int k) { return KitchenUnit(room.solution.objects[k]); });
  std::vector<RunLayout> layouts;
  const auto lay = [&](const std::set<int>& ignore, const std::vector<int>& movers) {
    std::vector<MemberPoses> raw = StraightRunLayouts(room, run, ignore, options.clearance, kJoint);
    if (kitchen) {
      std::vector<MemberPoses> corner = CornerRunLayouts(room, run, ignore, options.clearance, kJoint);
      raw.insert(raw.end(), corner.begin(), corner.end());
    }
    size_t tried = 0;
    for (MemberPoses& poses : raw) {
      if (!movers.empty() && tried++ >= kMaxMadeRoom) break;
      AddRunLayout(room, std::move(poses), hung, group, movers, now, options.clearance, &layouts);
    }
  };
  lay(group, {});
  if (layouts.empty() && kitchen) {
    for (const std::vector<int>& movers : MovableSets(room, group)) {
      std::set<int> ignore = group;
      ignore.insert(movers.begin(), movers.end());
      lay(ignore, movers);
    }
  }
  std::stable_sort(layouts.begin(), layouts.end(), [](const RunLayout& a, const RunLayout& b) {
    if (a.unmet < b.unmet || b.unmet < a.unmet) return a.unmet < b.unmet;
    return a.moved < b.moved;
  });
  std::vector<std::vector<Step>> out;
  for (const RunLayout& l : layouts) {
    if (static_cast<int>(out.size()) >= options.alternatives) break;
    std::vector<Step> steps;
    for (const auto& [k, c] : l.before) {
      if (c.remove) {
        solver::Action drop;
        drop.kind = solver::ActionKind::kRemoveEntity;
        drop.id = room.solution.objects[k].id;
        drop.reason = "critic: " + why + " (no open place on the run for it)";
        steps.push_back({std::move(drop), false});
        continue;
      }
      const std::vector<Step> more = Steps(ActionsFor(room, k, c, why + " (making room for the run)"));
      steps.insert(steps.end(), more.begin(), more.end());
    }
    for (const auto& [k, c] : l.poses) {
      const std::vector<Step> more = Steps(ActionsFor(room, k, c, why + " (the run laid out again)"));
      steps.insert(steps.end(), more.begin(), more.end());
    }
    out.push_back(std::move(steps));
  }
  return out;
}

// The hub of an edge: of its two ends (what stands on nothing), the one with more relations to other objects
// (the dining table of the chairs, the bed of the nightstands, the sofa of the TV stand).
int HubOf(const Room& room, int s, int t) {
  std::map<int, int> degree;
  for (const scene::SemanticEdge& e : room.graph) {
    const int a = room.Find(e.source), b = room.Find(e.target);
    if (a >= 0 && b >= 0 && room.Root(a) != room.Root(b)) ++degree[room.Root(a)], ++degree[room.Root(b)];
  }
  return degree[room.Root(t)] >= degree[room.Root(s)] ? room.Root(t) : room.Root(s);
}

// The cluster of a hub: the objects standing free on the floor joined to it by edges through such objects
// (a sofa's coffee table, side tables and floor lamp, the rug and armchairs of its coffee table); for a hub
// against a wall also what stands against the same wall joined to it (a bed's nightstands). `keep` (the
// edge's other end) is not in it; neither is what hangs on walls or from the ceiling. `near_only`: only the
// hub's own neighbours (and floor coverings), leaving the rest (the armchairs of the coffee table) in place.
std::vector<int> ClusterOf(const Room& room, int hub, int keep, bool near_only) {
  const auto free_standing = [&](int k) {
    const solver::ProblemObject& o = room.solution.objects[k];
    return room.parent[k] < 0 && o.parent == "floor" && o.relation == solver::Relation::kOnTop;
  };
  const auto same_wall = [&](int k) {
    return room.solution.objects[hub].relation == solver::Relation::kAgainstWall && room.parent[k] < 0 &&
           room.solution.objects[k].relation == solver::Relation::kAgainstWall &&
           room.solution.placements[k].wall == room.solution.placements[hub].wall;
  };
  std::vector<int> cluster;
  std::set<int> seen{hub, keep};
  std::vector<int> stack{hub};
  while (!stack.empty()) {
    const int k = stack.back();
    stack.pop_back();
    for (const scene::SemanticEdge& e : room.graph) {
      const int a = room.Find(e.source), b = room.Find(e.target);
      if (a < 0 || b < 0) continue;
      const int ra = room.Root(a), rb = room.Root(b);
      const int j = ra == k ? rb : rb == k ? ra : -1;
      if (j < 0 || seen.count(j) || !(free_standing(j) || same_wall(j))) continue;
      // Near only: the hub's own neighbours, and the floor coverings of any member (they move freely).
      if (near_only && k != hub && !Covering(room.solution.objects[j], room.solution.placements[j].pose.scale)) continue;
      seen.insert(j);
      cluster.push_back(j);
      if (free_standing(j)) stack.push_back(j);
    }
  }
  return cluster;
}

// Where an object hung on a wall goes to be `behind` and `centred` on a target standing at `pose`: on the
// nearest wall behind the target that faces the way it faces, at the foot of its centre; none when no such
// wall is within 4 m or the spot is not free (an opening, the wall's end).
std::optional<Candidate> HungBehind(const Room& room, int k, const solver::Pose& pose) {
  const Point facing{std::sin(pose.yaw), -std::cos(pose.yaw)};
  std::optional<Candidate> best;
  double nearest = 4.0;
  for (size_t w = 0; w < room.problem.walls.size(); ++w) {
    if (room.solution.objects[k].wall >= 0 && static_cast<int>(w) != room.solution.objects[k].wall) continue;
    const solver::WallEdge& wall = room.problem.walls[w];
    const Point d = geo::Unit(geo::Sub(wall.b, wall.a)), n = geo::Left(d);
    if (geo::Dot(n, facing) < 0.995) continue;
    const double behind = geo::Dot(geo::Sub({pose.x, pose.y}, wall.a), n);  // m from the wall to the target's centre
    if (behind <= 0.0 || behind >= nearest) continue;
    if (auto c = OnWallAt(room, k, static_cast<int>(w), AlongWall(room, static_cast<int>(w), {pose.x, pose.y}), room.solution.placements[k].pose.scale)) {
      best = c;
      nearest = behind;
    }
  }
  return best;
}

// Whether object k at `pose` keeps `clearance` from where the objects of `landed` land (heights counted;
// floor coverings neither block nor are blocked).
bool ClearOfLanded(const Room& room, int k, const solver::Pose& pose, const std::vector<std::pair<int, Candidate>>& landed, double clearance) {
  if (Covering(room.solution.objects[k], pose.scale)) return true;
  const ObjectBox box = BoxAt(room, k, pose);
  const double top = box.z0 + room.stack_top[k] - room.solution.placements[k].pose.z;
  return std::none_of(landed.begin(), landed.end(), [&](const auto& p) {
    if (p.first == k || Covering(room.solution.objects[p.first], p.second.pose.scale)) return false;
    const ObjectBox there = BoxAt(room, p.first, p.second.pose);
    return PlanGap(box, there) < clearance &&
           std::min(top, there.z0 + room.stack_top[p.first] - room.solution.placements[p.first].pose.z) > std::max(box.z0, there.z0);
  });
}

// Steps (m) for what steps aside out of a group move's way: well clear of where the piece lands.
const std::vector<double> kWellAside{0.5, 1.0, 1.5, 2.0, 2.5, 3.0};

// The first of `spots` where object k stands free (of everything but `moving`) and clear of where the
// objects of `landed` land.
std::optional<Candidate> FirstClear(const Room& room, int k, const std::vector<Candidate>& spots, const std::set<int>& moving,
                                    const std::vector<std::pair<int, Candidate>>& landed, double clearance) {
  for (const Candidate& c : spots)
    if (Free(room, k, c.pose, clearance, moving) && ClearOfLanded(room, k, c.pose, landed, clearance)) return c;
  return std::nullopt;
}

// The candidate poses of object k against the hub, whose box will be `hub_box` (CandidatesFor by `edge`),
// where every edge of `edges` between the two holds.
std::vector<Candidate> SeatsAgainst(const Room& room, int k, int hub, const ObjectBox& hub_box, const scene::SemanticEdge& edge,
                                    const std::vector<scene::SemanticEdge>& edges, double scale) {
  std::vector<Candidate> out;
  for (const Candidate& c : CandidatesFor(room, k, hub, edge, scale, &hub_box)) {
    const ObjectBox kb = BoxAt(room, k, c.pose);
    if (std::all_of(edges.begin(), edges.end(), [&](const scene::SemanticEdge& e) {
          return room.Find(e.source) == k ? CheckEdge(e, kb, hub_box).satisfied : CheckEdge(e, hub_box, kb).satisfied;
        }))
      out.push_back(c);
  }
  return out;
}

// The relations left unmet with `placements`, leaving out what the solver re-places after a group move
// (`replaced`, roots): their edges, their zones, and where they alone enter a zone.
Unmet UnmetBesides(const Room& room, const std::vector<solver::ObjectPlacement>& placements, const std::vector<int>& replaced) {
  const auto re = [&](const std::string& id) {
    const int k = room.Find(id);
    return k >= 0 && std::find(replaced.begin(), replaced.end(), room.Root(k)) != replaced.end();
  };
  std::vector<scene::SemanticEdge> graph;
  for (const scene::SemanticEdge& e : room.graph)
    if (!re(e.source) && !re(e.target)) graph.push_back(e);
  RoomRelations r = MeasureRelations(room.solution.objects, placements, graph);
  std::erase_if(r.zones, [&](ZoneCheck& z) {
    std::erase_if(z.intruders, re);
    return re(z.owner);
  });
  return UnmetOf(r);
}

// Cluster moves for an unmet edge: its hub and the hub's cluster moved as one rigid piece, so the relations
// inside it keep holding (the sofa with its coffee table, side table and lamp slid until the painting above
// it is centred, or carried 2-3 m before the TV stand; a bed with its nightstands along its wall). Motions:
// slides along and across the hub's axes (along its wall for a hub against one) in 10 cm steps up to 3 m;
// turns about the hub's centre (to face the other end, a quarter or half turn); and, when the hub faces the
// other end standing against a wall at a gap (the TV stand 2-3 m before the sofa), the other end to every
// 25 cm of every wall it may stand on with the hub carried to face it at that gap. What hangs `behind` the
// hub (the painting) is hung again behind it where it lands. Every member must land free of everything
// outside the cluster, on the free floor, out of the keep-outs (along its wall, clear of openings); the moves
// are ordered so none enters the place of one still to move. Ranked like single moves.
std::vector<std::vector<Step>> ClusterMoves(const Room& room, int s, int t, const scene::SemanticEdge& edge, const Unmet& now,
                                            const OfflineProposalOptions& options, const std::string& why) {
  if (room.Root(s) == room.Root(t)) return {};
  const int hub = HubOf(room, s, t);
  const int other = hub == room.Root(t) ? room.Root(s) : room.Root(t);
  const solver::ProblemObject& ho = room.solution.objects[hub];
  if (OnObject(ho) || ho.relation == solver::Relation::kOnWall || ho.relation == solver::Relation::kHanging) return {};
  // The whole cluster moved, or only the hub's own neighbours with the rest of the cluster (the ring: the
  // armchairs of the coffee table) re-placed by the solver afterwards; then the ring's relations are left out
  // of the ranking (the solver mends them) and the real result decides in the loop.
  struct Variant {
    std::vector<int> members, ring;
  };
  std::vector<Variant> variants;
  std::vector<int> all{hub};
  for (int k : ClusterOf(room, hub, other, false)) all.push_back(k);
  variants.push_back({all, {}});
  std::vector<int> near{hub};
  for (int k : ClusterOf(room, hub, other, true)) near.push_back(k);
  if (near != all) {
    Variant v{near, {}};
    for (int k : all)
      if (std::find(near.begin(), near.end(), k) == near.end()) v.ring.push_back(k);
    variants.push_back(std::move(v));
  }
  if (all.size() > 1) variants.push_back({{hub}, std::vector<int>(all.begin() + 1, all.end())});  // the hub alone, all re-placed
  // From the graph, in one pass: what hangs on a wall behind the hub (hung again behind it after the move);
  // what stands against a wall in front of it (the TV stand before the sofa: slid along its wall to stay
  // before it); the edges between hub and other end, and whether the other end, standing free with edges
  // only to the hub itself, may be re-seated against it after the move; the gap range at which the other
  // end stands before the hub, if it does.
  std::vector<int> hung, before_hub;
  std::vector<scene::SemanticEdge> between;
  std::optional<std::pair<double, double>> facing_gap;
  bool reseat = room.parent[other] < 0 && room.solution.objects[other].parent == "floor" &&
                room.solution.objects[other].relation == solver::Relation::kOnTop &&
                !Covering(room.solution.objects[other], room.solution.placements[other].pose.scale);
  const auto add_once = [](std::vector<int>& list, int k) {
    if (std::find(list.begin(), list.end(), k) == list.end()) list.push_back(k);
  };
  for (const scene::SemanticEdge& e : room.graph) {
    const int a = room.Find(e.source), b = room.Find(e.target);
    if (a < 0 || b < 0) continue;
    const bool loose_root = room.parent[a] < 0;
    if (b == hub && loose_root && e.relation == scene::SemanticRelation::kBehind &&
        room.solution.objects[a].relation == solver::Relation::kOnWall)
      add_once(hung, a);
    if (b == hub && loose_root && a != other && e.relation == scene::SemanticRelation::kFrontOf &&
        room.solution.objects[a].relation == solver::Relation::kAgainstWall && room.solution.placements[a].wall >= 0)
      add_once(before_hub, a);
    if (a == other && b == hub && e.relation == scene::SemanticRelation::kFrontOf && e.params.min_gap && e.params.max_gap)
      facing_gap = {*e.params.min_gap, *e.params.max_gap};
    if ((a == other && b == hub) || (a == hub && b == other)) between.push_back(e);
    else if ((room.Root(a) == other && b == hub) || (a == hub && room.Root(b) == other) || (room.Root(a) == hub && b == other) ||
             (a == other && room.Root(b) == hub))
      reseat = false;
  }
  reseat = reseat && !between.empty();
  // Loose things (standing free on the floor, no relation, nothing on them: a plant) may step aside.
  const auto loose = [&](int k) {
    const solver::ProblemObject& o = room.solution.objects[k];
    if (room.parent[k] >= 0 || o.parent != "floor" || o.relation != solver::Relation::kOnTop || !room.children[k].empty()) return false;
    return std::none_of(room.graph.begin(), room.graph.end(), [&](const scene::SemanticEdge& e) { return e.source == o.id || e.target == o.id; });
  };
  // What may make way for the hub and the other end placed anew (re-placed by the solver after): a root
  // standing on the floor or against a wall, not a kitchen's unit (its run holds it).
  const auto makes_way = [&](int k) {
    const solver::ProblemObject& o = room.solution.objects[k];
    if (room.parent[k] >= 0 || k == hub || k == other || KitchenUnit(o)) return false;
    return (o.parent == "floor" && o.relation == solver::Relation::kOnTop) || o.relation == solver::Relation::kAgainstWall;
  };
  const solver::Pose& at = room.solution.placements[hub].pose;
  const bool on_wall = ho.relation == solver::Relation::kAgainstWall;
  struct Motion {
    double dx = 0.0, dy = 0.0, turn = 0.0;
    std::optional<Candidate> other_at;  // the other end moved too
    std::optional<Candidate> hub_at;    // the hub to another wall's slot
  };
  std::vector<Motion> motions;
  std::vector<Point> axes;
  if (on_wall) {
    const int w = room.solution.placements[hub].wall;
    if (w < 0) return {};
    axes.push_back(geo::Unit(geo::Sub(room.problem.walls[w].b, room.problem.walls[w].a)));
  } else {
    axes = {{std::cos(at.yaw), std::sin(at.yaw)}, {-std::sin(at.yaw), std::cos(at.yaw)}};
    const ObjectBox ob = BoxOf(room.solution.objects[other], room.solution.placements[other]);
    const double face = FacingYaw({at.x, at.y}, ob.c);
    for (double turn : {solver::WrapAngle(face - at.yaw), kHalfPi, -kHalfPi, std::numbers::pi})
      if (std::abs(turn) > 0.01) motions.push_back({0.0, 0.0, turn, std::nullopt, std::nullopt});
  }
  for (const Point& axis : axes)
    for (int k = -30; k <= 30; ++k)
      if (k != 0) motions.push_back({0.1 * k * axis.x, 0.1 * k * axis.y, 0.0, std::nullopt, std::nullopt});
  // A free-standing hub also slides on a 20 cm grid off its axes (back from a corner of the floor, then along).
  if (!on_wall)
    for (int i = -3; i <= 3; ++i)
      for (int j = -3; j <= 3; ++j)
        if (i != 0 && j != 0)
          motions.push_back({0.2 * (i * axes[0].x + j * axes[1].x), 0.2 * (i * axes[0].y + j * axes[1].y), 0.0, std::nullopt, std::nullopt});
  // The hub faces the other end, which stands against a wall in front of it at a gap: both placed anew.
  if (facing_gap && !on_wall && room.solution.objects[other].relation == solver::Relation::kAgainstWall && room.parent[other] < 0) {
    const solver::ProblemObject& oo = room.solution.objects[other];
    const double scale = room.solution.placements[other].pose.scale;
    for (const Candidate& slot : AlongEveryWall(room, other, 0.25, scale)) {
      if (oo.wall >= 0 && slot.wall != oo.wall) continue;
      const solver::WallEdge& wall = room.problem.walls[slot.wall];
      const Point n = geo::Left(geo::Unit(geo::Sub(wall.b, wall.a)));
      const double yaw = std::atan2(-n.x, n.y);  // the hub faces the wall
      for (double gap : {facing_gap->first + 0.05, 0.5 * (facing_gap->first + facing_gap->second), facing_gap->second - 0.05}) {
        const double reach = 0.5 * oo.asset.size.y * scale + gap + 0.5 * ho.asset.size.y * at.scale;
        const Point c = geo::Add({slot.pose.x, slot.pose.y}, geo::Scale(n, reach));
        const double turn = solver::WrapAngle(yaw - at.yaw);
        // The rigid motion taking the hub's centre to c, turned by `turn` about it.
        motions.push_back({c.x - at.x, c.y - at.y, turn, slot, std::nullopt});
      }
    }
  }
  // A hub against a wall facing the other end on the wall across (the sofa and the TV stand on opposite
  // walls): the hub along every wall it may stand on (every 10 cm, and tight against its ends and openings), the other end to the foot of its axis on
  // the first wall it faces across the room, when the gap between them is in range.
  if (facing_gap && on_wall && room.solution.objects[other].relation == solver::Relation::kAgainstWall && room.parent[other] < 0) {
    const solver::ProblemObject& oo = room.solution.objects[other];
    for (size_t w = 0; w < room.problem.walls.size(); ++w) {
      if (ho.wall >= 0 && static_cast<int>(w) != ho.wall) continue;
      const solver::WallEdge& wall = room.problem.walls[w];
      const double length = geo::Dist(wall.a, wall.b);
      const Point n = geo::Left(geo::Unit(geo::Sub(wall.b, wall.a)));
      // Every 10 cm, and tight against the wall's ends and its openings (a sofa fits between a door and the
      // corner only there).
      const double half = 0.5 * ho.asset.size.x * at.scale;
      std::vector<double> stops{half + 0.02, length - half - 0.02};
      for (const solver::WallOpening& op : wall.openings) stops.push_back(op.t0 - half - 0.02), stops.push_back(op.t1 + half + 0.02);
      for (double tw = 0.0; tw < length; tw += 0.1) stops.push_back(tw);
      for (double tw : stops) {
        auto slot = OnWallAt(room, hub, static_cast<int>(w), tw, at.scale);
        if (!slot) continue;
        const Point c{slot->pose.x, slot->pose.y};
        // The nearest wall across, facing back, whose span the hub's axis meets.
        std::optional<Candidate> across;
        double nearest = 1e9;
        for (size_t v = 0; v < room.problem.walls.size(); ++v) {
          if (v == w || (oo.wall >= 0 && static_cast<int>(v) != oo.wall)) continue;
          const solver::WallEdge& facing_wall = room.problem.walls[v];
          const Point dv = geo::Unit(geo::Sub(facing_wall.b, facing_wall.a)), nv = geo::Left(dv);
          if (geo::Dot(nv, n) > -0.995) continue;
          const double dist = geo::Dot(geo::Sub(c, facing_wall.a), nv);  // from that wall to the hub's centre
          if (dist <= 0.0 || dist >= nearest) continue;
          const double t_foot = geo::Dot(geo::Sub(c, facing_wall.a), dv);
          // At the foot, else off it along the wall while still before the hub (the foot under a window, in
          // a keep-out: what stands in the way may move, a keep-out not).
          std::optional<Candidate> stand;
          for (double off : {0.0, -0.25, 0.25, -0.5, 0.5, -0.75, 0.75}) {
            stand = OnWallAt(room, other, static_cast<int>(v), t_foot + off * half, room.solution.placements[other].pose.scale);
            if (stand && Blockers(room, other, stand->pose, options.clearance, {hub, other})) break;
            stand.reset();
          }
          if (!stand) continue;
          const double gap = dist - 0.5 * ho.asset.size.y * at.scale - (oo.wall_gap + oo.asset.size.y * room.solution.placements[other].pose.scale);
          if (gap < facing_gap->first || gap > facing_gap->second) continue;
          nearest = dist;
          across = stand;
        }
        if (!across) continue;
        motions.push_back({c.x - at.x, c.y - at.y, solver::WrapAngle(slot->pose.yaw - at.yaw), across, slot});
      }
    }
  }
  std::vector<MultiMove> layouts;
  for (const Variant& variant : variants) {
    const std::vector<int>& members = variant.members;
    const Unmet before = variant.ring.empty() ? now : UnmetBesides(room, room.solution.placements, variant.ring);
    std::set<int> cluster(members.begin(), members.end());
    cluster.insert(hung.begin(), hung.end());
    cluster.insert(before_hub.begin(), before_hub.end());
    for (const Motion& mo : motions) {
      std::set<int> moving = cluster;
      if (mo.other_at || reseat) moving.insert(other);  // re-seated: it does not block the members
      const double cs = std::cos(mo.turn), sn = std::sin(mo.turn);
      std::vector<std::pair<int, Candidate>> poses;
      std::vector<int> made_way;
      // Whether object k may land at `pose`: it is free there, or what stands in the way steps aside first,
      // well clear of where k lands. A loose thing (a plant) only steps aside; when both ends are placed
      // anew (the sofa carried before a TV stand on another wall), anything standing on the floor or against
      // a wall may make way, and the solver re-places it after (an armchair, a bookcase).
      // It must keep clear of what has landed already (the other end on its new wall, what stepped aside).
      // (Blockers never counts the object itself: `moving` serves every member.)
      const auto clear_way = [&](int k, const solver::Pose& pose) {
        if (!ClearOfLanded(room, k, pose, poses, options.clearance)) return false;
        const auto blockers = Blockers(room, k, pose, options.clearance, moving);
        if (!blockers) return false;
        const ObjectBox box = BoxAt(room, k, pose);
        for (int b : *blockers) {
          const bool is_loose = loose(b);
          // The ring, re-placed by the solver after the move, steps aside first where it is in the way.
          const bool ringed = std::find(variant.ring.begin(), variant.ring.end(), b) != variant.ring.end();
          if (!is_loose && !ringed && !(mo.other_at && makes_way(b))) return false;
          std::vector<Candidate> spots = StepsAside(room, b, box, 1.0, kWellAside);
          // What makes way for a wall-standing piece and is re-placed by the solver after may wait on any
          // wall (a bookcase between a door and a window has no step aside along its own).
          if (!is_loose && !ringed && WallBound(room.solution.objects[b]))
            for (const Candidate& c : AlongEveryWall(room, b, 0.25, room.solution.placements[b].pose.scale))
              if (PlanGap(BoxAt(room, b, c.pose), box) >= 1.0) spots.push_back(c);
          const std::optional<Candidate> aside = FirstClear(room, b, spots, moving, poses, options.clearance);
          if (!aside) return false;
          poses.push_back({b, *aside});
          moving.insert(b);
          if (!is_loose && !ringed) made_way.push_back(b);
        }
        return true;
      };
      if (mo.other_at) {
        if (!clear_way(other, mo.other_at->pose)) continue;
        poses.push_back({other, *mo.other_at});
      }
      bool ok = true;
      for (int k : members) {
        const solver::ObjectPlacement& pl = room.solution.placements[k];
        const double rx = pl.pose.x - at.x, ry = pl.pose.y - at.y;
        Candidate cand;
        cand.pose = {at.x + cs * rx - sn * ry + mo.dx, at.y + sn * rx + cs * ry + mo.dy, pl.pose.z,
                     solver::WrapAngle(pl.pose.yaw + mo.turn), pl.pose.scale};
        if (k == hub && mo.hub_at) {
          cand = *mo.hub_at;
        } else if (room.solution.objects[k].relation == solver::Relation::kAgainstWall) {
          if (mo.turn != 0.0) {  // a turned piece leaves its wall: what stands against it cannot come along
            ok = false;
            break;
          }
          auto on = OnWallAt(room, k, pl.wall, AlongWall(room, pl.wall, {cand.pose.x, cand.pose.y}), pl.pose.scale);
          if (!on) {
            ok = false;
            break;
          }
          cand = *on;
        }
        if (!clear_way(k, cand.pose)) {
          ok = false;
          break;
        }
        poses.push_back({k, cand});
      }
      if (!ok) continue;
      const solver::Pose hub_at = std::find_if(poses.begin(), poses.end(), [&](const auto& p) { return p.first == hub; })->second.pose;
      const ObjectBox hub_box = BoxAt(room, hub, hub_at);
      for (int h : hung)
        if (auto c = HungBehind(room, h, hub_at)) poses.push_back({h, *c});
      // What of the ring stands free before the hub (the coffee table, when the sofa moves alone) is seated
      // before it where it lands, at the first pose where all its edges to the hub hold, rather than left to
      // the solver, which would place it around the ring still standing where it was (the armchairs in its
      // place). What stands beside the hub (side tables, a lamp) the solver places well.
      std::vector<int> seated;
      for (int k : variant.ring) {
        const solver::ProblemObject& ko = room.solution.objects[k];
        const solver::ObjectPlacement& kp = room.solution.placements[k];
        if (room.parent[k] >= 0 || ko.parent != "floor" || ko.relation != solver::Relation::kOnTop || Covering(ko, kp.pose.scale)) continue;
        std::vector<scene::SemanticEdge> to_hub;
        for (const scene::SemanticEdge& e : room.graph)
          if ((room.Find(e.source) == k && room.Find(e.target) == hub) || (room.Find(e.source) == hub && room.Find(e.target) == k))
            to_hub.push_back(e);
        if (std::none_of(to_hub.begin(), to_hub.end(), [&](const scene::SemanticEdge& e) {
              return e.relation == scene::SemanticRelation::kFrontOf && room.Find(e.source) == k;
            }))
          continue;
        // Where it stepped aside for the hub, it goes to its seat instead (MoveOrder lets it leave first).
        std::optional<std::pair<int, Candidate>> aside;
        if (auto it = std::find_if(poses.begin(), poses.end(), [&](const auto& p) { return p.first == k; }); it != poses.end()) {
          aside = *it;
          poses.erase(it);
        }
        for (const Candidate& c : SeatsAgainst(room, k, hub, hub_box, to_hub.front(), to_hub, kp.pose.scale)) {
          const size_t landed = poses.size(), gave_way = made_way.size();
          const std::set<int> was_moving = moving;
          if (!clear_way(k, c.pose)) {  // (what stepped aside for it on the way comes back)
            poses.resize(landed);
            made_way.resize(gave_way);
            moving = was_moving;
            continue;
          }
          poses.push_back({k, c});
          moving.insert(k);
          seated.push_back(k);
          break;
        }
        if (aside && std::find(seated.begin(), seated.end(), k) == seated.end()) poses.push_back(*aside);
      }
      if (reseat && !mo.other_at) {
        // The other end re-seated against the hub where it lands (the side table at the sofa's end the slide
        // made room for): the first pose where every edge between the two holds, clear of everything.
        std::vector<ObjectBox> landed;
        for (const auto& [k, cand] : poses) {
          if (Covering(room.solution.objects[k], cand.pose.scale)) continue;
          solver::ObjectPlacement pl = room.solution.placements[k];
          pl.pose = cand.pose;
          landed.push_back(BoxOf(room.solution.objects[k], pl));
        }
        const solver::ObjectPlacement& op = room.solution.placements[other];
        for (const Candidate& c : SeatsAgainst(room, other, hub, hub_box, edge, between, op.pose.scale)) {
          const ObjectBox ob = BoxAt(room, other, c.pose);
          if (std::any_of(landed.begin(), landed.end(), [&](const ObjectBox& b) { return PlanGap(ob, b) < options.clearance; })) continue;
          if (!Free(room, other, c.pose, options.clearance, moving)) continue;
          poses.push_back({other, c});
          break;
        }
        // Not re-seated: it stays, and must then be clear of where the members land.
        if (poses.back().first != other) {
          const ObjectBox stays = BoxOf(room.solution.objects[other], op);
          if (std::any_of(landed.begin(), landed.end(), [&](const ObjectBox& b) { return PlanGap(stays, b) < options.clearance; })) continue;
        }
      }
      for (int f : before_hub) {
        if (mo.turn != 0.0) continue;  // a turned hub faces another wall: its own edges decide
        const solver::WallEdge& wall = room.problem.walls[room.solution.placements[f].wall];
        const Point d = geo::Unit(geo::Sub(wall.b, wall.a));
        auto c = OnWallAt(room, f, room.solution.placements[f].wall, geo::Dot(geo::Sub({hub_at.x, hub_at.y}, wall.a), d),
                          room.solution.placements[f].pose.scale);
        if (c && Free(room, f, c->pose, options.clearance, moving)) poses.push_back({f, *c});
      }
      std::vector<solver::ObjectPlacement> placements = room.solution.placements;
      for (const auto& [k, cand] : poses) placements = room.Moved(placements, k, cand.pose, cand.wall);
      // What made way is re-placed by the solver, as the ring is: left out of the ranking.
      std::vector<int> ring;
      for (int k : variant.ring)
        if (std::find(seated.begin(), seated.end(), k) == seated.end()) ring.push_back(k);
      ring.insert(ring.end(), made_way.begin(), made_way.end());
      const Unmet u = UnmetBesides(room, placements, ring);
      if (!(u < (made_way.empty() && seated.empty() ? before : UnmetBesides(room, room.solution.placements, ring)))) continue;
      std::vector<std::pair<int, Candidate>> order;
      if (!MoveOrder(room, poses, options.clearance, &order)) continue;  // (what it parks on the way counts as moves)
      layouts.push_back({.unmet = u,
                         .moved = std::hypot(mo.dx, mo.dy) + std::abs(mo.turn),
                         .poses = std::move(order),
                         .ring = std::move(ring),
                         .displaced = static_cast<int>(made_way.size())});
    }
  }
  return BestMultiMoves(room, std::move(layouts), options.alternatives, why, "moved with " + room.solution.objects[hub].id);
}

// The satellites of a root m: what stands free on the floor with all its edges to m (the armchairs and the
// rug of a coffee table); a satellite's own things may have edges to it too.
std::vector<int> SatellitesOf(const Room& room, int m) {
  std::map<int, bool> only_m;  // root -> whether every edge of it so far ends at m (or at itself)
  for (const scene::SemanticEdge& e : room.graph) {
    const int a = room.Find(e.source), b = room.Find(e.target);
    if (a < 0 || b < 0) continue;
    const int ra = room.Root(a), rb = room.Root(b);
    if (ra == rb) continue;
    if (ra != m) only_m.emplace(ra, true).first->second &= rb == m;
    if (rb != m) only_m.emplace(rb, true).first->second &= ra == m;
  }
  std::vector<int> out;
  for (const auto& [k, only] : only_m) {
    const solver::ProblemObject& o = room.solution.objects[k];
    if (only && room.parent[k] < 0 && o.parent == "floor" && o.relation == solver::Relation::kOnTop) out.push_back(k);
  }
  return out;
}

// Moves of an object standing free on the floor that take its satellites along (the coffee table brought
// before the sofa with the rug under it and the armchairs around it): the object to each candidate pose of
// the edge, each satellite carried by the same rigid motion where it lands free, else re-placed by the
// solver after (stepping aside first when it stands where the others land). The re-placed ones' relations
// are left out of the ranking, which the loop's real measure then decides. Ranked like cluster moves.
std::vector<std::vector<Step>> SatelliteMoves(const Room& room, int s, int t, const scene::SemanticEdge& edge, const OfflineProposalOptions& options,
                                              const std::string& why) {
  std::vector<MultiMove> layouts;
  std::map<std::vector<int>, Unmet> before;  // by the set re-placed
  for (int m : {s, t}) {
    const int other = m == s ? t : s;
    const solver::ProblemObject& mo = room.solution.objects[m];
    if (room.parent[m] >= 0 || mo.parent != "floor" || mo.relation != solver::Relation::kOnTop || room.Root(other) == m) continue;
    const std::vector<int> satellites = SatellitesOf(room, m);
    if (satellites.empty() || std::find(satellites.begin(), satellites.end(), room.Root(other)) != satellites.end()) continue;
    std::set<int> group(satellites.begin(), satellites.end());
    group.insert(m);
    const solver::Pose at = room.solution.placements[m].pose;
    for (const Candidate& c : CandidatesFor(room, m, room.Root(other), edge, at.scale)) {
      if (!Free(room, m, c.pose, options.clearance, group)) continue;
      const double turn = solver::WrapAngle(c.pose.yaw - at.yaw), cs = std::cos(turn), sn = std::sin(turn);
      std::vector<std::pair<int, Candidate>> poses{{m, c}};
      std::vector<int> ring;
      for (int k : satellites) {
        const solver::Pose& p = room.solution.placements[k].pose;
        const double rx = p.x - at.x, ry = p.y - at.y;
        Candidate carried;
        carried.pose = {c.pose.x + cs * rx - sn * ry, c.pose.y + sn * rx + cs * ry, p.z, solver::WrapAngle(p.yaw + turn), p.scale};
        if (Free(room, k, carried.pose, options.clearance, group) && ClearOfLanded(room, k, carried.pose, poses, options.clearance))
          poses.push_back({k, carried});
        else
          ring.push_back(k);
      }
      // A re-placed satellite standing where another lands steps aside first.
      bool ok = true;
      for (int k : ring) {
        if (ClearOfLanded(room, k, room.solution.placements[k].pose, poses, options.clearance)) continue;
        const std::optional<Candidate> aside =
            FirstClear(room, k, StepsAside(room, k, BoxAt(room, m, c.pose), 1.0, kWellAside), group, poses, options.clearance);
        if (!aside) {
          ok = false;
          break;
        }
        poses.push_back({k, *aside});
      }
      if (!ok) continue;
      std::vector<solver::ObjectPlacement> placements = room.solution.placements;
      for (const auto& [k, cand] : poses) placements = room.Moved(placements, k, cand.pose, cand.wall);
      std::sort(ring.begin(), ring.end());
      auto [was, added] = before.emplace(ring, Unmet{});
      if (added) was->second = UnmetBesides(room, room.solution.placements, ring);
      const Unmet u = UnmetBesides(room, placements, ring);
      if (!(u < was->second)) continue;
      std::vector<std::pair<int, Candidate>> order;
      if (!MoveOrder(room, poses, options.clearance, &order)) continue;
      layouts.push_back(
          {.unmet = u, .moved = std::hypot(c.pose.x - at.x, c.pose.y - at.y) + std::abs(turn), .poses = std::move(order), .ring = std::move(ring)});
    }
  }
  return BestMultiMoves(room, std::move(layouts), options.alternatives, why, "with what stands around it");
}

// Both ends smaller, tried last (after the single moves at the smallest scale): where the edge's source
// stands free on the floor (a desk chair), its target (a desk against the wall of a narrow arm, 0.68 m deep,
// with 1.2 m of floor to the wall across) shrinks to its smallest in place (its back kept to its wall, one
// standing free about its centre; what stands on it carried) and the source is seated before it, at its
// own scale or its smallest. Ranked like cluster moves; the loop's real measure decides.
std::vector<std::vector<Step>> ShrunkPairMoves(const Room& room, int s, int t, const scene::SemanticEdge& edge, const Unmet& now,
                                               const OfflineProposalOptions& options, const std::string& why) {
  std::vector<MultiMove> layouts;
  const int hub = room.Root(t);
  const solver::ProblemObject& so = room.solution.objects[s];
  const solver::ProblemObject& ho = room.solution.objects[hub];
  const solver::ObjectPlacement& hp = room.solution.placements[hub];
  if (room.parent[s] >= 0 || so.parent != "floor" || so.relation != solver::Relation::kOnTop || hub == s ||
      ho.scale_min >= hp.pose.scale - 1e-9)
    return {};
  std::vector<scene::SemanticEdge> between;
  std::vector<int> facers;  // what stands on the other end and faces the first (the monitor): turned to it
  for (const scene::SemanticEdge& e : room.graph) {
    const int a = room.Find(e.source), b = room.Find(e.target);
    if ((a == s && b >= 0 && room.Root(b) == hub) || (b == s && a >= 0 && room.Root(a) == hub)) between.push_back(e);
    if (b == s && a >= 0 && a != hub && room.Root(a) == hub && e.relation == scene::SemanticRelation::kFaceTo) facers.push_back(a);
  }
  Candidate shrunk;
  shrunk.pose = hp.pose;
  shrunk.pose.scale = ho.scale_min;
  if (ho.relation == solver::Relation::kAgainstWall && hp.wall >= 0) {
    const std::optional<Candidate> c = OnWallAt(room, hub, hp.wall, AlongWall(room, hp.wall, {hp.pose.x, hp.pose.y}), ho.scale_min);
    if (!c) return {};
    shrunk = *c;
  }
  const ObjectBox hub_box = BoxAt(room, hub, shrunk.pose);
  const solver::Pose at = room.solution.placements[s].pose;
  for (double scale : {at.scale, so.scale_min}) {
    for (const Candidate& c : SeatsAgainst(room, s, hub, hub_box, edge, between, scale)) {
      // Seated at the edge's own gap from where the other end lands.
      if (!Free(room, s, c.pose, options.clearance, {hub})) continue;
      std::vector<solver::ObjectPlacement> placements = room.Moved(room.solution.placements, hub, shrunk.pose, shrunk.wall);
      placements = room.Moved(placements, s, c.pose, c.wall);
      std::vector<std::pair<int, Candidate>> poses{{hub, shrunk}, {s, c}};
      for (int k : facers) {
        Candidate turned;
        turned.pose = placements[k].pose;
        turned.pose.yaw = FacingYaw({turned.pose.x, turned.pose.y}, {c.pose.x, c.pose.y});
        placements = room.Moved(placements, k, turned.pose, -1);
        poses.push_back({k, turned});
      }
      const Unmet u = UnmetBesides(room, placements, {});
      if (!(u < now)) continue;
      layouts.push_back({.unmet = u, .moved = std::hypot(c.pose.x - at.x, c.pose.y - at.y) + (at.scale - scale), .poses = std::move(poses)});
    }
    if (!layouts.empty() || so.scale_min >= at.scale - 1e-9) break;
  }
  return BestMultiMoves(room, std::move(layouts), options.alternatives, why, "both smaller");
}

// A bed and what belongs at its head: the things standing against the wall beside it (nightstands, by a
// left_of / right_of / next_to edge to it) and what hangs on the wall above it (the painting, behind it or
// centred on it). Single moves cannot mend a bed put where its wall has no room for a nightstand on one
// side, or where a window is above its middle: the bed must move, and the others with it.
struct BedGroup {
  int bed = -1;
  std::vector<std::pair<int, int>> sides;  // (object, side): +1 the bed's left, -1 its right, 0 either
  std::vector<int> above;                  // hung on the wall above the bed
  std::vector<int> others;                 // free-standing things related to the bed (slippers, a rug)
};

bool IsBed(const solver::ProblemObject& o) { return o.category == "bed" || o.category == "child-bed"; }

std::optional<BedGroup> BedGroupOf(const Room& room, int bed) {
  const solver::ProblemObject& b = room.solution.objects[bed];
  if (!IsBed(b) || room.parent[bed] >= 0 || b.relation != solver::Relation::kAgainstWall) return std::nullopt;
  using R = scene::SemanticRelation;
  BedGroup g;
  g.bed = bed;
  std::map<int, int> side;  // object -> side (as in BedGroup::sides)
  std::set<int> hung, others;
  for (const scene::SemanticEdge& e : room.graph) {
    if (e.target != b.id) continue;
    const int k = room.Find(e.source);
    if (k < 0 || k == bed || room.parent[k] >= 0) continue;
    const solver::ProblemObject& o = room.solution.objects[k];
    if (o.relation == solver::Relation::kAgainstWall && (e.relation == R::kLeftOf || e.relation == R::kRightOf || e.relation == R::kNextTo)) {
      int& s = side.emplace(k, 0).first->second;
      if (e.relation != R::kNextTo) s = e.relation == R::kLeftOf ? 1 : -1;
    } else if (o.relation == solver::Relation::kOnWall && (e.relation == R::kBehind || e.relation == R::kCentered)) {
      hung.insert(k);
    } else if (!WallBound(o) && room.children[k].empty()) {
      others.insert(k);
    }
  }
  if (side.empty() && hung.empty()) return std::nullopt;
  for (const auto& [k, s] : side) g.sides.push_back({k, s});
  g.above.assign(hung.begin(), hung.end());
  for (int k : others)
    if (!side.count(k) && !hung.count(k)) g.others.push_back(k);
  return g;
}

// The bed laid out again with its group along every wall it may stand on (a 5 cm comb and the stops
// where the group just clears a wall end or an opening), at the group's scales, with the bed at its
// smallest, and with everything that carries nothing at its smallest: the nightstands 3 cm beside it on
// their sides of it (one of either side on the side left free), what hangs above it centred over it at
// its height (left where it is when a window or door is there), a rug related to the bed carried along
// (its place relative to the bed kept where the floor is free for it). A layout is tried only where each
// member is free of everything outside the group, in an order where none enters the place of one still to
// move; the other free-standing things related to the bed are re-placed by the solver afterwards when the
// layout leaves their edges unmet. Ranked like single moves (then the less shrunk first), the best `keep`.
std::vector<std::vector<Step>> BedGroupMoves(const Room& room, const BedGroup& g, const Unmet& now, const OfflineProposalOptions& options,
                                             const std::string& why) {
  constexpr double kBeside = 0.03;  // m between the bed and a nightstand (next_to asks at most 0.1)
  const solver::ProblemObject& bed = room.solution.objects[g.bed];
  std::set<int> group{g.bed};
  for (const auto& [k, s] : g.sides) group.insert(k);
  group.insert(g.above.begin(), g.above.end());
  // Which of the either-side members go left: each bit of `flip` for one of them.
  std::vector<size_t> either;
  for (size_t i = 0; i < g.sides.size(); ++i)
    if (g.sides[i].second == 0) either.push_back(i);
  // Either-side members past the first two go right when a fixed member takes the left, else left.
  const bool taken_left = std::any_of(g.sides.begin(), g.sides.end(), [](const auto& p) { return p.second == 1; });
  // Layouts as multi-moves: `displaced` holds the shrink (0 the scales as they are, 1 the bed at its
  // smallest, 2 everything that can be), `after` the rugs moved with the bed, `ring` what the solver
  // re-places after (a smaller bed's pillows, others whose edges the layout leaves unmet).
  std::vector<MultiMove> layouts;
  // What carries things (a nightstand with its lamp and books) keeps its scale: smaller, its load would
  // no longer fit on it. The bed's pillows fit a smaller bed.
  // A bed is not shrunk below a single bed's length (1.95 m) nor a single below its size (the planner's where
  // no double fits, scene/planner.cpp BedFits): smaller it is no adult's bed; a nightstand stays unmended
  // instead (issue 27).
  const CategoryInfo* bed_info = FindCategory(bed.category);
  const bool bed_shrinks = bed.asset.size.x >= 1.4 - 1e-9 &&
                           (!bed_info || bed.asset.size.y * bed.scale_min >= bed_info->size_min.y - 1e-9);
  const auto scale_of = [&](int k, int shrink) {
    const bool smallest = (shrink >= 1 && k == g.bed && bed_shrinks) || (shrink == 2 && room.children[k].empty() && k != g.bed);
    return smallest ? room.solution.objects[k].scale_min : room.solution.placements[k].pose.scale;
  };
  for (int shrink = 0; shrink <= 2; ++shrink) {
    bool smaller = shrink == 0;
    for (int k : group) smaller = smaller || scale_of(k, shrink) < scale_of(k, shrink - 1) - 1e-9;
    if (!smaller) continue;
    for (size_t w = 0; w < room.problem.walls.size(); ++w) {
      if (bed.wall >= 0 && bed.wall != static_cast<int>(w)) continue;
      const solver::WallEdge& wall = room.problem.walls[w];
      const Point d = geo::Unit(geo::Sub(wall.b, wall.a));
      const double length = geo::Dist(wall.a, wall.b);
      const double bed_scale = scale_of(g.bed, shrink), bed_half = 0.5 * bed.asset.size.x * bed_scale;
      // A comb, and the stops where the group, the bed or what hangs above it just clears a wall end or an
      // opening (a painting fits beside a window only in a few centimetres of the wall).
      std::vector<double> reaches{bed_half, bed_half + kBeside};
      for (const auto& [k, s] : g.sides) reaches.push_back(reaches.back() + room.solution.objects[k].asset.size.x * scale_of(k, shrink) + kBeside);
      for (int k : g.above) reaches.push_back(0.5 * room.solution.objects[k].asset.size.x * scale_of(k, shrink));
      std::vector<double> ts;
      for (double t = bed_half + 0.02; t < length - bed_half; t += 0.05) ts.push_back(t);
      for (double e : reaches) {
        ts.push_back(e + 0.021);
        ts.push_back(length - e - 0.021);
        for (const solver::WallOpening& op : wall.openings) {
          ts.push_back(op.t0 - e - 0.016);
          ts.push_back(op.t1 + e + 0.016);
        }
      }
      std::erase_if(ts, [&](double t) { return t < bed_half + 0.01 || t > length - bed_half - 0.01; });
      // Stops closer than 5 mm are one stop (the comb meets the wall's ends and openings): measured once.
      std::sort(ts.begin(), ts.end());
      ts.erase(std::unique(ts.begin(), ts.end(), [](double a, double b) { return b - a < 0.005; }), ts.end());
      for (double t : ts) {
        auto c = OnWallAt(room, g.bed, static_cast<int>(w), t, bed_scale);
        if (!c || !Free(room, g.bed, c->pose, options.clearance, group)) continue;
        // The bed's left (its +x, seen from the bed) along the wall: +1 toward the wall's end, -1 its start.
        const double left = std::cos(c->pose.yaw) * d.x + std::sin(c->pose.yaw) * d.y > 0.0 ? 1.0 : -1.0;
        for (unsigned flip = 0; flip < (1u << std::min<size_t>(either.size(), 2)); ++flip) {
          std::vector<std::pair<int, Candidate>> poses{{g.bed, *c}};
          double reach[2] = {bed_half + kBeside, bed_half + kBeside};  // taken on the left [0] and right [1]
          bool ok = true;
          for (size_t i = 0; i < g.sides.size() && ok; ++i) {
            const auto [k, fixed] = g.sides[i];
            int s = fixed;
            if (s == 0) {
              const size_t bit = std::find(either.begin(), either.end(), i) - either.begin();
              s = bit < 2 ? ((flip >> bit) & 1u ? 1 : -1) : (taken_left ? -1 : 1);
            }
            const double scale = scale_of(k, shrink), half = 0.5 * room.solution.objects[k].asset.size.x * scale;
            double& r = reach[s > 0 ? 0 : 1];
            auto m = OnWallAt(room, k, static_cast<int>(w), t + s * left * (r + half), scale);
            r += 2.0 * half + kBeside;
            ok = m && Free(room, k, m->pose, options.clearance, group);
            if (ok) poses.push_back({k, *m});
          }
          if (!ok) continue;
          for (int k : g.above) {
            const double scale = scale_of(k, shrink);
            auto m = OnWallAt(room, k, static_cast<int>(w), t, scale);
            if (m && Free(room, k, m->pose, options.clearance, group))
              poses.push_back({k, *m});
          }
          // A rug keeps its place relative to the bed (it lies under or beside it: nothing collides with
          // it, so it moves last, in any order) where the floor is free for it.
          std::vector<std::pair<int, Candidate>> carried;
          const solver::Pose& from = room.solution.placements[g.bed].pose;
          const double turn = c->pose.yaw - from.yaw, cos_t = std::cos(turn), sin_t = std::sin(turn);
          for (int k : g.others) {
            const solver::Pose& at = room.solution.placements[k].pose;
            if (!Covering(room.solution.objects[k], at.scale)) continue;
            const double dx = at.x - from.x, dy = at.y - from.y;
            Candidate rug;
            rug.pose = {c->pose.x + cos_t * dx - sin_t * dy, c->pose.y + sin_t * dx + cos_t * dy, at.z, solver::WrapAngle(at.yaw + turn),
                        at.scale};
            if (Free(room, k, rug.pose, options.clearance, group)) carried.push_back({k, rug});
          }
          std::vector<solver::ObjectPlacement> placements = room.solution.placements;
          double moved = 0.0;
          for (const auto& [k, m] : poses) {
            placements = room.Moved(placements, k, m.pose, m.wall);
            moved += std::hypot(m.pose.x - room.solution.placements[k].pose.x, m.pose.y - room.solution.placements[k].pose.y);
          }
          for (const auto& [k, m] : carried) placements = room.Moved(placements, k, m.pose, m.wall);
          const RoomRelations r = MeasureRelations(room.solution.objects, placements, room.graph);
          const Unmet u = UnmetOf(r);
          if (!(u < now)) continue;
          MultiMove l{.unmet = u,
                      .moved = moved,
                      .poses = std::move(poses),
                      .displaced = shrink,
                      .after = std::move(carried),
                      .after_how = "the rug moves with the bed",
                      .unordered = true};
          // A smaller bed brings its pillows closer together: the solver lays them out again on it.
          if (shrink > 0) l.ring = room.Descendants(g.bed);
          for (int k : g.others) {
            if (std::any_of(l.after.begin(), l.after.end(), [&](const auto& p) { return p.first == k; })) continue;
            const std::string& id = room.solution.objects[k].id;
            const bool unmet = std::any_of(r.edges.begin(), r.edges.end(),
                                           [&](const EdgeCheck& e) { return !e.satisfied && (e.edge.source == id || e.edge.target == id); });
            if (unmet) l.ring.push_back(k);
          }
          layouts.push_back(std::move(l));
        }
      }
    }
  }
  return BestMultiMoves(room, std::move(layouts), options.alternatives, why, "the bed and its group laid out again", options.clearance);
}

// The group move for an edge single moves could not mend: its hub (the end with more relations to other
// objects) goes to a roomier place, then everything related to it is re-placed by the solver around it;
// or, first, only the related objects are re-placed.
std::optional<Attempt> GroupMove(solver::RoomSolver& session, const Room& room, int s, int t, const OfflineProposalOptions& options,
                                 const std::string& line) {
  if (room.Root(s) == room.Root(t)) return std::nullopt;
  const int hub = HubOf(room, s, t);
  std::vector<int> members;
  std::set<int> group;
  for (const scene::SemanticEdge& e : room.graph) {
    const int a = room.Find(e.source), b = room.Find(e.target);
    if (a < 0 || b < 0) continue;
    const int ra = room.Root(a), rb = room.Root(b);
    for (auto [mine, other] : {std::pair{ra, rb}, std::pair{rb, ra}})
      if (mine == hub && other != hub && group.insert(other).second) members.push_back(other);
  }
  if (members.empty()) return std::nullopt;
  std::vector<Step> reslot;
  for (int m : members) reslot.push_back(Suggested(room.solution.objects[m].id, line));
  Attempt a{line + " [group]", {reslot}};
  const std::string& hub_id = room.solution.objects[hub].id;
  for (const Candidate& c : RoomyPoses(room, hub, group, options.clearance, options.alternatives)) {
    if (!session.Fits(hub_id, c.pose, c.wall >= 0 ? std::optional<int>(c.wall) : std::nullopt)) continue;
    std::vector<Step> seq = Steps(ActionsFor(room, hub, c, line + " (its group moves)"));
    seq.insert(seq.end(), reslot.begin(), reslot.end());
    a.alternatives.push_back(std::move(seq));
  }
  return a;
}

}  // namespace

std::vector<Attempt> ProposeOffline(solver::RoomSolver& session, const solver::RoomProblem& problem, const solver::RoomSolution& solution,
                                    const std::vector<scene::SemanticEdge>& graph, const RoomRelations& relations,
                                    const OfflineProposalOptions& options, const std::set<std::string>& given_up) {
  const Room room(problem, solution, graph);
  const Unmet now = UnmetOf(relations);
  // The solver's own best pose for an object (asked once a round per object).
  std::map<int, std::vector<Candidate>> suggested;
  const Suggestions suggestion = [&](int m) -> const std::vector<Candidate>& {
    auto [it, added] = suggested.emplace(m, std::vector<Candidate>{});
    if (added)
      if (auto slot = session.Suggest(solution.objects[m].id)) it->second.push_back({slot->pose, slot->wall, slot->surface, slot->cavity, true});
    return it->second;
  };
  const std::vector<std::string> problems = OfflineProblems(problem.room, relations);
  std::vector<Attempt> out;
  // A bed whose group (BedGroupOf) has an unmet edge or an entered zone: first the bed laid out again
  // with the group, which mends what moving one of them cannot.
  for (size_t b = 0; b < solution.objects.size(); ++b) {
    const std::optional<BedGroup> g = BedGroupOf(room, static_cast<int>(b));
    if (!g) continue;
    std::set<std::string> members{solution.objects[b].id};
    for (const auto& [k, s] : g->sides) members.insert(solution.objects[k].id);
    for (int k : g->above) members.insert(solution.objects[k].id);
    for (int k : g->others) members.insert(solution.objects[k].id);
    const auto member = [&](const std::string& id) {
      const int k = room.Find(id);
      return k >= 0 && members.count(solution.objects[room.Root(k)].id) > 0;
    };
    bool trouble = false;
    for (const EdgeCheck& c : relations.edges) trouble = trouble || (c.present && !c.satisfied && (member(c.edge.source) || member(c.edge.target)));
    for (const ZoneCheck& z : relations.zones)
      trouble = trouble || (!z.clear() && (member(z.owner) || std::any_of(z.intruders.begin(), z.intruders.end(), member)));
    const std::string key = ShortId(problem.room, solution.objects[b].id) + " laid out again with its nightstands and what hangs above it";
    if (!trouble || given_up.count(key)) continue;
    std::vector<std::vector<Step>> layouts = BedGroupMoves(room, *g, now, options, key);
    if (!layouts.empty()) out.push_back({key, std::move(layouts)});
  }
  size_t p = 0;
  for (const EdgeCheck& c : relations.edges) {
    if (c.present && c.satisfied) continue;
    const std::string& line = problems[p++];
    if (!c.present) continue;
    const int s = room.Find(c.edge.source), t = room.Find(c.edge.target);
    if (!given_up.count(line)) {
      Attempt single = SingleMoves(session, room, c, s, t, now, options, line, suggestion);
      // A run of wall-standing objects chained next_to (a kitchen's) laid out again as a whole.
      for (std::vector<Step>& run : RunMoves(room, s, t, now, options, line)) single.alternatives.push_back(std::move(run));
      // The edge's hub with its cluster, moved as one piece.
      for (std::vector<Step>& moved : ClusterMoves(room, s, t, c.edge, now, options, line)) single.alternatives.push_back(std::move(moved));
      // Either end with its satellites.
      for (std::vector<Step>& moved : SatelliteMoves(room, s, t, c.edge, options, line)) single.alternatives.push_back(std::move(moved));
      // Both ends smaller, where nothing else fits (a desk and its chair in a narrow arm).
      for (std::vector<Step>& moved : ShrunkPairMoves(room, s, t, c.edge, now, options, line)) single.alternatives.push_back(std::move(moved));
      if (!single.alternatives.empty()) {
        out.push_back(std::move(single));
        continue;
      }
    }
    if (given_up.count(line + " [group]")) continue;
    if (auto group = GroupMove(session, room, s, t, options, line)) out.push_back(std::move(*group));
  }
  for (const ZoneCheck& z : relations.zones) {
    if (z.clear()) continue;
    const std::string& line = problems[p++];
    if (given_up.count(line)) continue;
    const int owner = room.Find(z.owner);
    std::vector<Ranked> ranked;
    for (const std::string& id : z.intruders) {
      const int mover = room.Root(room.Find(id));
      if (mover == room.Root(owner)) continue;
      RankInto(room, mover, suggestion(mover), now, options.clearance, line, ranked);
      RankInto(room, room.Root(owner), suggestion(room.Root(owner)), now, options.clearance, line, ranked);
      // Away from the zone: around the owner at the zone's depth and beyond, or along the walls.
      scene::SemanticEdge away;
      away.source = solution.objects[mover].id;
      away.target = z.owner;
      away.relation = scene::SemanticRelation::kNear;
      RankInto(room, mover, CandidatesFor(room, mover, owner, away, solution.placements[mover].pose.scale), now, options.clearance, line,
               ranked);
      // The owner may move instead.
      away.source = z.owner;
      away.target = solution.objects[mover].id;
      RankInto(room, room.Root(owner), CandidatesFor(room, room.Root(owner), mover, away, solution.placements[room.Root(owner)].pose.scale),
               now, options.clearance, line, ranked);
    }
    Attempt a{line, Best(session, std::move(ranked), options.alternatives)};
    // A decorative intruder with nowhere to go leaves the room (the zone is for using the object).
    if (a.alternatives.empty()) {
      for (const std::string& id : z.intruders) {
        const int k = room.Find(id);
        if (k < 0 || solution.objects[k].priority != solver::Priority::kDecorative) continue;
        bool has_edges = false;
        for (const scene::SemanticEdge& e : graph) has_edges = has_edges || e.source == id || e.target == id;
        if (has_edges || !room.children[k].empty()) continue;
        // What stands on a kitchen unit that is itself in the zone (the pan on a cooker) leaves the zone
        // entered: taking it out would lose it for nothing. (Kitchen units only so far: other room types'
        // figures were measured with such removals, see docs/BENCHMARKS.md.)
        const solver::ProblemObject& carrier = solution.objects[room.Root(k)];
        if (room.Root(k) != k && KitchenUnit(carrier) && std::count(z.intruders.begin(), z.intruders.end(), carrier.id)) continue;
        solver::Action remove;
        remove.kind = solver::ActionKind::kRemoveEntity;
        remove.id = id;
        remove.reason = "critic: " + line + "; it has no free place elsewhere";
        a.alternatives.push_back({Step{remove, false}});
        break;
      }
    }
    if (!a.alternatives.empty()) out.push_back(std::move(a));
  }
  return out;
}

}  // namespace villa::critic


