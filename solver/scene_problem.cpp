#include "solver/scene_problem.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "layout/geometry.h"
#include "mesh/geometry2d.h"
#include "solver/box.h"
#include "solver/functional.h"
#include "solver/group_rules.h"
#include "solver/place.h"

namespace villa::solver {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
// m around the room's polygon within which building parts are obstacles of its exact check.
constexpr double kPartReach = 0.5;

KeepOutKind KindOf(scene::KeepOutKind kind) {
  switch (kind) {
    case scene::KeepOutKind::kDoorSweep: return KeepOutKind::kDoorSweep;
    case scene::KeepOutKind::kDoorStrip: return KeepOutKind::kDoorStrip;
    case scene::KeepOutKind::kOpenPassage: return KeepOutKind::kOpenPassage;
    case scene::KeepOutKind::kWindow: return KeepOutKind::kWindowZone;
    case scene::KeepOutKind::kStair: return KeepOutKind::kStaircase;
    case scene::KeepOutKind::kStairHole: return KeepOutKind::kStairHole;
    case scene::KeepOutKind::kStairArrival: return KeepOutKind::kStairArrival;
  }
  return KeepOutKind::kOther;
}

// The scene's and the solver's relation enums name the same five relations in the same order.
Relation RelationOf(scene::Relation r) { return *ParseRelation(scene::RelationName(r)); }
SemanticRelation SemanticOf(scene::SemanticRelation r) { return *ParseSemanticRelation(scene::SemanticRelationName(r)); }

bool OnRing(const Point& p, const Ring& ring) { return PointOnBoundary(p, ring, 1e-6); }

// The solver's edges for one scene edge: the relation with its parameters, and for a side relation with a
// gap range a gap edge as well (next_to up to 0.5 m, far from 1.5 m, near otherwise).
std::vector<SemanticEdge> EdgesOf(const scene::SemanticEdge& e) {
  const SemanticRelation relation = SemanticOf(e.relation);
  const scene::EdgeParams p = scene::EffectiveParams(e.relation, e.params);
  SemanticEdge out = DefaultEdge(e.source, relation, e.target);
  switch (relation) {
    case SemanticRelation::kFaceTo: out.max_angle = p.max_deg.value_or(30.0) * kDeg; break;
    case SemanticRelation::kAlign: out.tolerance = p.max_deg.value_or(5.0) * kDeg; break;
    case SemanticRelation::kCentered: out.tolerance = p.max_offset.value_or(0.05); break;
    case SemanticRelation::kNextTo:
    case SemanticRelation::kNear:
    case SemanticRelation::kFar:
      if (p.min_gap) out.min_gap = *p.min_gap;
      if (p.max_gap) out.max_gap = *p.max_gap;
      break;
    default: break;
  }
  std::vector<SemanticEdge> edges{out};
  const bool side = relation == SemanticRelation::kFrontOf || relation == SemanticRelation::kBehind ||
                    relation == SemanticRelation::kLeftOf || relation == SemanticRelation::kRightOf;
  if (side && (e.params.min_gap || e.params.max_gap)) {
    const double lo = e.params.min_gap.value_or(0.0), hi = e.params.max_gap.value_or(1e9);
    const SemanticRelation gap = hi <= 0.5 ? SemanticRelation::kNextTo : lo >= 1.5 ? SemanticRelation::kFar : SemanticRelation::kNear;
    SemanticEdge g = DefaultEdge(e.source, gap, e.target);
    g.min_gap = lo;
    g.max_gap = std::max(lo, hi);
    edges.push_back(g);
  }
  return edges;
}

// A room with two or more doors or opens is walked through: between every two of them a corridor 0.7 m wide
// stays free of furniture (rugs may lie on it), from a point 0.45 m inside each doorway, straight where the
// straight way stays on the free floor, else through the free floor's inner corner that joins them; none
// where neither does (the reachability check still walks the room). Heights: the floor to 2 m.
std::vector<KeepOut> CirculationOf(const scene::RoomContext& context, const Ring& free_floor, double floor_z, double clear_height) {
  constexpr double kInward = 0.45, kHalfWidth = 0.35;
  std::vector<std::pair<std::string, Point>> ends;
  for (const scene::ContextOpening& o : context.openings) {
    if (o.kind == ElementKind::kWindow) continue;
    const Point a = o.shape.a, b = o.shape.b;
    const Point mid = geo::Scale(geo::Add(a, b), 0.5), n = geo::Left(geo::Unit(geo::Sub(b, a)));
    for (double side : {1.0, -1.0}) {
      const Point in = geo::Add(mid, geo::Scale(n, side * (kInward + 0.3)));  // past the wall's thickness
      if (!PointInRing(in, free_floor, 0.0)) continue;
      ends.push_back({o.name, geo::Add(mid, geo::Scale(n, side * kInward))});
      break;
    }
  }
  std::vector<KeepOut> out;
  if (ends.size() < 2) return out;
  auto clear = [&](Point p, Point q) {  // the segment stays on the free floor, kHalfWidth from its edge
    const double length = geo::Dist(p, q);
    for (double t = 0.0; t <= length; t += 0.1) {
      const Point s = geo::Lerp(p, q, length > 0 ? t / length : 0.0);
      if (!PointInRing(s, free_floor, 0.0) || DistanceToBoundary(s, free_floor) < kHalfWidth - 0.05) return false;
    }
    return true;
  };
  auto corridor = [&](Point p, Point q, const std::string& name) {
    if (geo::Dist(p, q) < 1e-6) return;
    const Point d = geo::Unit(geo::Sub(q, p)), n = geo::Scale(geo::Left(d), kHalfWidth);
    Ring rect{geo::Sub(p, n), geo::Sub(q, n), geo::Add(q, n), geo::Add(p, n)};
    out.push_back({std::move(rect), floor_z, floor_z + std::min(2.0, clear_height), KeepOutKind::kCirculation, name});
  };
  // Inner corners pushed off the walls to the corridor's middle: where a bent way turns.
  std::vector<Point> turns;
  for (Point v : ReflexVertices(free_floor)) {
    Point best = v;
    for (double dx : {-1.0, 1.0})
      for (double dy : {-1.0, 1.0}) {
        const Point t{v.x + dx * (kHalfWidth + 0.05), v.y + dy * (kHalfWidth + 0.05)};
        if (PointInRing(t, free_floor, 0.0) && DistanceToBoundary(t, free_floor) > DistanceToBoundary(best, free_floor)) best = t;
      }
    turns.push_back(best);
  }
  for (size_t i = 0; i < ends.size(); ++i)
    for (size_t j = i + 1; j < ends.size(); ++j) {
      const std::string name = ends[i].first + " <-> " + ends[j].first;
      const Point p = ends[i].second, q = ends[j].second;
      if (clear(p, q)) {
        corridor(p, q, name);
        continue;
      }
      for (Point t : turns)
        if (clear(p, t) && clear(t, q)) {
          corridor(p, t, name);
          corridor(t, q, name);
          break;
        }
    }
  return out;
}

Priority PriorityOf(const scene::SceneObject& o) {
  if (o.origin == scene::Origin::kPrompt) return Priority::kNamed;
  // Small things the priors put on or in furniture give way first.
  if (!scene::IsRootParent(o.parent)) return Priority::kDecorative;
  return Priority::kPrior;
}

}  // namespace

Result<SceneRoomProblem> RoomProblemOf(const scene::RoomContext& context, const BuildingMesh& building,
                                       const std::vector<scene::SceneObject>& objects,
                                       const std::vector<scene::SemanticEdge>& edges, const AssetResolver& resolve) {
  SceneRoomProblem out;
  RoomProblem& p = out.problem;
  p.room = context.name;
  p.floor_z = context.floor_z;
  p.clear_height = context.clear_height;

  // The free floor: one ring (a room with a neck narrower than its walls gives more; the largest is used).
  size_t largest = 0;
  for (size_t i = 1; i < context.free_floor.size(); ++i)
    if (Area(context.free_floor[i]) > Area(context.free_floor[largest])) largest = i;
  if (!context.free_floor.empty()) p.free_floor = context.free_floor[largest];
  if (context.free_floor.size() > 1)
    out.notes.push_back("the free floor has " + std::to_string(context.free_floor.size()) +
                        " pieces; the largest is furnished");

  // Walls on that ring: doors and opens block their whole height (nothing hangs over a door either).
  for (const scene::WallEdge& w : context.walls) {
    if (!OnRing(w.inner.a, p.free_floor) || !OnRing(w.inner.b, p.free_floor)) continue;
    WallEdge wall;
    wall.edge = w.edge;
    wall.a = w.inner.a;
    wall.b = w.inner.b;
    for (const Interval& o : w.openings) wall.openings.push_back({o.first, o.second, p.floor_z, p.floor_z + p.clear_height});
    for (const scene::WallWindow& win : w.windows)
      wall.openings.push_back({win.span.first, win.span.second, p.floor_z + win.sill, p.floor_z + win.head});
    p.walls.push_back(std::move(wall));
  }
  for (const scene::KeepOut& k : context.keep_outs) {
    if (k.polygon.size() < 3 || Area(k.polygon) <= 1e-9 || !(k.z_max > k.z_min)) continue;
    p.keep_outs.push_back({k.polygon, k.z_min, k.z_max, KindOf(k.kind), std::string(scene::KeepOutKindName(k.kind)) + " " + k.element});
  }

  // The way through the room between its doors and opens (issue 27).
  for (KeepOut& k : CirculationOf(context, p.free_floor, p.floor_z, p.clear_height)) p.keep_outs.push_back(std::move(k));

  // Building parts near the room on its level (and the staircase arriving from below).
  Box2 near = BoundingBox(context.polygon);
  for (const MeshPart& part : building.parts) {
    const bool solid = part.kind == PartKind::kExteriorWall || part.kind == PartKind::kInteriorWall ||
                       part.kind == PartKind::kDoorLeaf || part.kind == PartKind::kWindowGlass || part.kind == PartKind::kStair ||
                       part.kind == PartKind::kRailing || part.kind == PartKind::kWindowFrame;
    if (!solid || part.mesh.triangles.empty()) continue;
    if (part.level != context.level && !(part.kind == PartKind::kStair && part.level + 1 == context.level)) continue;
    const Box3 b = part.mesh.Bounds();
    if (b.max.z <= p.floor_z + 1e-3 || b.min.z >= p.floor_z + p.clear_height) continue;
    if (!near.Touches({b.min.x, b.min.y, b.max.x, b.max.y}, kPartReach)) continue;
    p.building.push_back({std::string(PartKindName(part.kind)) + " " + part.name, part.mesh});
  }

  // Objects; children whose parent cannot hold them are left out with their descendants.
  std::map<std::string, const scene::SceneObject*> by_id;
  for (const scene::SceneObject& o : objects) by_id[o.id] = &o;
  std::map<std::string, AssetRecord> records;
  std::set<std::string> dropped;
  for (const scene::SceneObject& o : objects) {
    if (o.asset.empty()) {
      out.dropped.push_back(o.id + ": no asset chosen");
      dropped.insert(o.id);
      continue;
    }
    auto resolved = resolve(o.asset);
    if (!resolved.ok()) return Error{o.id + ": " + resolved.error()};
    if (!resolved->second || resolved->second->TriangleCount() == 0) {
      out.dropped.push_back(o.id + ": asset " + o.asset + " has no mesh");
      dropped.insert(o.id);
      continue;
    }
    if (std::string outside = MeshOutsideAssetBox(resolved->first, *resolved->second); !outside.empty()) {
      out.dropped.push_back(o.id + ": asset " + o.asset + ": " + outside);
      dropped.insert(o.id);
      continue;
    }
    ProblemObject po;
    po.id = o.id;
    po.category = o.category;
    po.asset = resolved->first;
    po.mesh = resolved->second;
    po.parent = o.parent;
    po.relation = RelationOf(o.relation);
    if (o.surface) po.surface = *o.surface;
    if (o.cavity) po.cavity = *o.cavity;
    if (o.wall) {
      po.wall_gap = std::clamp(o.wall->gap, 0.0, 0.2);
      for (size_t w = 0; w < p.walls.size(); ++w)
        if (p.walls[w].edge == o.wall->edge) {
          po.wall = static_cast<int>(w);
          break;
        }
    }
    po.scale_min = kSceneScaleMin;
    po.scale_max = kSceneScaleMax;
    po.priority = PriorityOf(o);
    po.hints = o.hints;
    if (o.interaction_zone) po.zone = InteractionZone{o.interaction_zone->side, o.interaction_zone->depth, o.interaction_zone->exempt};
    records[o.id] = po.asset;
    p.objects.push_back(std::move(po));
  }
  // Parents before children in the problem is not required; a child needs its parent kept and able to hold it.
  bool changed = true;
  while (changed) {
    changed = false;
    for (const ProblemObject& o : p.objects) {
      if (dropped.count(o.id) || scene::IsRootParent(o.parent)) continue;
      std::string why;
      auto parent = records.find(o.parent);
      if (parent == records.end() || dropped.count(o.parent)) {
        why = "its parent " + o.parent + " is left out";
      } else if (o.relation == Relation::kInside && parent->second.cavities.empty()) {
        why = "its parent's asset " + parent->second.id + " has no cavity";
      } else if (o.relation == Relation::kOnTop && parent->second.support_surfaces.empty()) {
        why = "its parent's asset " + parent->second.id + " has no support surface";
      } else if (o.relation == Relation::kInside && o.cavity >= static_cast<int>(parent->second.cavities.size())) {
        why = "cavity " + std::to_string(o.cavity) + " does not exist on " + parent->second.id;
      } else if (o.relation == Relation::kOnTop && o.surface >= static_cast<int>(parent->second.support_surfaces.size())) {
        why = "surface " + std::to_string(o.surface) + " does not exist on " + parent->second.id;
      }
      if (why.empty()) continue;
      out.dropped.push_back(o.id + ": " + why);
      dropped.insert(o.id);
      changed = true;
    }
  }
  std::erase_if(p.objects, [&](const ProblemObject& o) { return dropped.count(o.id) > 0; });
  for (ProblemObject& o : p.objects)
    if (o.zone) std::erase_if(o.zone->exempt, [&](const std::string& id) { return dropped.count(id) || !by_id.count(id); });

  for (const scene::SemanticEdge& e : edges) {
    if (dropped.count(e.source) || dropped.count(e.target) || !by_id.count(e.source) || !by_id.count(e.target)) continue;
    for (SemanticEdge& s : EdgesOf(e)) p.edges.push_back(std::move(s));
  }
  MarkEssentials(context.category, p);
  MarkPullOut(p);
  return out;
}

void MarkPullOut(RoomProblem& problem) {
  for (ProblemObject& o : problem.objects)
    for (const SemanticEdge& e : problem.edges)
      if (e.source == o.id && (o.category == "chair" || o.category == "office-chair") &&
          (e.relation == SemanticRelation::kNextTo || e.relation == SemanticRelation::kFaceTo))
        if (const int t = problem.Find(e.target);
            t >= 0 && (problem.objects[t].category == "dining-table" || problem.objects[t].category == "conference-table"))
          o.pull_out = kSeatBehind;
}

void MarkEssentials(Category room, RoomProblem& problem) {
  std::set<std::string> essential;
  for (const Essential& e : EssentialsOf(room)) {
    int n = 0;
    for (const ProblemObject& o : problem.objects)
      if (n < e.count && std::find(e.categories.begin(), e.categories.end(), o.category) != e.categories.end()) {
        essential.insert(o.id);
        ++n;
      }
  }
  // What carries an essential piece is essential too (the counter under the sink).
  for (bool grew = true; grew;) {
    grew = false;
    for (const ProblemObject& o : problem.objects)
      if (essential.count(o.id) && !scene::IsRootParent(o.parent) && essential.insert(o.parent).second) grew = true;
  }
  for (ProblemObject& o : problem.objects)
    if (essential.count(o.id)) o.priority = Priority::kEssential;
  // A desk's own chair (pulled in before it) goes with its desk: the room gives way to it like to what the
  // request names.
  for (ProblemObject& o : problem.objects)
    for (const SemanticEdge& e : problem.edges)
      if (e.source == o.id && (o.category == "chair" || o.category == "office-chair" || o.category == "child-chair"))
        if (const int d = problem.Find(e.target); d >= 0 && problem.objects[d].category == "desk" && IsDeskSeat(problem.edges, o.id, e.target))
          o.priority = std::max(o.priority, Priority::kNamed);
  // The rest of a living room's seating group (what its functional check asks for) is protected like what
  // the request names: the first coffee table, TV stand and TV.
  if (room == Category::kLivingRoom)
    for (std::string_view core : {"coffee-table", "tv-stand", "tv"})
      for (ProblemObject& o : problem.objects)
        if (o.category == core) {
          o.priority = std::max(o.priority, Priority::kNamed);
          break;
        }
  // What carries a protected piece is protected like it: the TV stand under the TV the request asks for,
  // the bookcase holding its books.
  for (bool grew = true; grew;) {
    grew = false;
    for (const ProblemObject& o : problem.objects)
      if (IsProtected(o.priority) && !scene::IsRootParent(o.parent))
        if (const int c = problem.Find(o.parent); c >= 0 && problem.objects[c].priority < Priority::kNamed) {
          problem.objects[c].priority = Priority::kNamed;
          grew = true;
        }
  }
}

std::vector<scene::SceneObject> SolvedSceneObjects(const RoomProblem& problem, const RoomSolution& solution,
                                                   const std::vector<scene::SceneObject>& planned) {
  std::map<std::string, size_t> solved;
  for (size_t i = 0; i < solution.objects.size(); ++i) solved[solution.objects[i].id] = i;
  std::vector<scene::SceneObject> out;
  auto posed = [&](scene::SceneObject o, size_t i) {
    const ProblemObject& po = solution.objects[i];
    const ObjectPlacement& pl = solution.placements[i];
    o.asset = po.asset.id;
    o.pose = scene::Pose{pl.pose.x, pl.pose.y, pl.pose.z, scene::WrapYaw(pl.pose.yaw)};
    o.scale = {pl.pose.scale, pl.pose.scale, pl.pose.scale};
    o.size = po.asset.size * pl.pose.scale;
    o.surface.reset();
    o.cavity.reset();
    o.wall.reset();
    // What stands in the room takes its relation as solved (a sofa the tidy stage floated off its wall
    // before the TV stands on the floor now).
    if (scene::IsRootParent(o.parent) && scene::IsRootParent(po.parent)) {
      o.parent = po.parent;
      o.relation = *scene::ParseRelation(RelationName(po.relation));
    }
    const bool on_object = !scene::IsRootParent(o.parent);
    if (on_object && o.relation == scene::Relation::kOnTop && pl.surface >= 0) o.surface = pl.surface;
    if (on_object && o.relation == scene::Relation::kInside && pl.cavity >= 0) o.cavity = pl.cavity;
    if ((o.relation == scene::Relation::kAgainstWall || o.relation == scene::Relation::kOnWall) && pl.wall >= 0 &&
        pl.wall < static_cast<int>(problem.walls.size()))
      o.wall = scene::WallRef{problem.walls[pl.wall].edge, po.wall_gap};
    return o;
  };
  for (const scene::SceneObject& o : planned) {
    auto it = solved.find(o.id);
    if (it == solved.end()) continue;
    out.push_back(posed(o, it->second));
    solved.erase(it);
  }
  // Objects an action added (a critic's add_entity): built from the problem's object.
  for (size_t i = 0; i < solution.objects.size(); ++i) {
    const ProblemObject& po = solution.objects[i];
    if (!solved.count(po.id)) continue;
    scene::SceneObject o;
    o.id = po.id;
    o.category = po.category;
    o.room = problem.room;
    o.level = planned.empty() ? 0 : planned.front().level;
    o.affordances = po.asset.affordances;
    o.parent = po.parent;
    o.relation = *scene::ParseRelation(RelationName(po.relation));
    o.origin = scene::Origin::kCritic;
    if (po.zone) o.interaction_zone = scene::InteractionZone{po.zone->side, po.zone->depth, po.zone->exempt};
    out.push_back(posed(o, i));
  }
  std::set<std::string> kept;
  for (const scene::SceneObject& o : out) kept.insert(o.id);
  for (scene::SceneObject& o : out)
    if (o.interaction_zone) std::erase_if(o.interaction_zone->exempt, [&](const std::string& id) { return !kept.count(id); });
  return out;
}

}  // namespace villa::solver
