#include "solver/problem.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <sstream>

#include "util/excerpt.h"

namespace villa::solver {
namespace {

constexpr std::string_view kKeepOutNames[] = {"door_sweep", "door_strip",  "open_passage",  "window_zone",
                                              "staircase",  "stair_hole", "stair_arrival", "other",
                                              "walkway",    "circulation"};
constexpr std::string_view kRelationNames[] = {"ontop", "inside", "against_wall", "on_wall", "hanging"};
constexpr std::string_view kPriorityNames[] = {"decorative", "prior", "named", "essential"};
constexpr std::string_view kSemanticNames[] = {"face_to", "front_of", "behind", "left_of", "right_of",
                                               "next_to", "near",     "far",    "align",   "centered"};

template <class Enum, size_t N>
std::optional<Enum> ParseName(const std::string_view (&names)[N], std::string_view name) {
  for (size_t i = 0; i < N; ++i) {
    if (names[i] == name) return static_cast<Enum>(i);
  }
  return std::nullopt;
}

bool Finite(Point p) { return std::isfinite(p.x) && std::isfinite(p.y); }

}  // namespace

std::string_view KeepOutKindName(KeepOutKind kind) { return kKeepOutNames[static_cast<int>(kind)]; }
std::string_view RelationName(Relation relation) { return kRelationNames[static_cast<int>(relation)]; }
std::optional<Relation> ParseRelation(std::string_view name) { return ParseName<Relation>(kRelationNames, name); }
std::string_view PriorityName(Priority priority) { return kPriorityNames[static_cast<int>(priority)]; }
std::optional<Priority> ParsePriority(std::string_view name) { return ParseName<Priority>(kPriorityNames, name); }
std::string_view SemanticRelationName(SemanticRelation relation) { return kSemanticNames[static_cast<int>(relation)]; }
std::optional<SemanticRelation> ParseSemanticRelation(std::string_view name) {
  return ParseName<SemanticRelation>(kSemanticNames, name);
}

SemanticEdge DefaultEdge(std::string source, SemanticRelation relation, std::string target) {
  SemanticEdge edge;
  edge.source = std::move(source);
  edge.relation = relation;
  edge.target = std::move(target);
  constexpr double kDeg = std::numbers::pi / 180.0;
  switch (relation) {
    case SemanticRelation::kFaceTo: edge.max_angle = 30.0 * kDeg; break;
    case SemanticRelation::kNextTo: edge.min_gap = 0.0; edge.max_gap = 0.5; break;
    case SemanticRelation::kNear: edge.min_gap = 0.5; edge.max_gap = 1.5; break;
    case SemanticRelation::kFar: edge.min_gap = 1.5; edge.max_gap = 1e9; break;
    case SemanticRelation::kAlign: edge.tolerance = 5.0 * kDeg; break;
    case SemanticRelation::kCentered: edge.tolerance = 0.05; break;
    default: break;
  }
  return edge;
}

int RoomProblem::Find(std::string_view id) const {
  for (size_t i = 0; i < objects.size(); ++i) {
    if (objects[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

OrientedBox StandingBox(const ProblemObject& object, const Pose& pose) {
  const Vec3& s = object.asset.size;
  OrientedBox b;
  b.c = {pose.x, pose.y};
  b.yaw = pose.yaw;
  b.hx = 0.5 * s.x * pose.scale;
  b.hy = 0.5 * s.y * pose.scale;
  b.z0 = pose.z;
  b.z1 = pose.z + s.z * pose.scale;
  return b;
}

bool IsFloorCovering(const ProblemObject& object) {
  return object.parent == "floor" && object.relation == Relation::kOnTop && object.asset.size.z <= 0.03;
}

std::string MeshOutsideAssetBox(const AssetRecord& asset, const AssetMesh& mesh) {
  const Vec3& s = asset.size;
  const Box3 b = mesh.Bounds();
  const double lo[3] = {-0.5 * s.x, -0.5 * s.y, 0.0}, hi[3] = {0.5 * s.x, 0.5 * s.y, s.z};
  const double mlo[3] = {b.min.x, b.min.y, b.min.z}, mhi[3] = {b.max.x, b.max.y, b.max.z};
  for (int k = 0; k < 3; ++k) {
    const double tolerance = std::max(0.01, 0.01 * (hi[k] - lo[k]));
    if (mlo[k] < lo[k] - tolerance || mhi[k] > hi[k] + tolerance) {
      std::ostringstream m;
      m << "mesh reaches [" << mlo[k] << ", " << mhi[k] << "] along " << "xyz"[k] << ", outside the asset box [" << lo[k]
        << ", " << hi[k] << "] of its size";
      return m.str();
    }
  }
  return "";
}

std::vector<WallEdge> WallsAlongFloor(const Ring& free_floor) {
  std::vector<WallEdge> walls;
  for (size_t i = 0; i < free_floor.size(); ++i) {
    WallEdge wall;
    wall.edge = static_cast<int>(i);
    wall.a = free_floor[i];
    wall.b = free_floor[(i + 1) % free_floor.size()];
    walls.push_back(wall);
  }
  return walls;
}

Status RoomProblem::Check() const {
  const std::string where = "room " + Excerpt(room) + ": ";
  auto fail = [&](const std::string& what) { return Status(Error{where + what}); };

  if (free_floor.size() < 3) return fail("free_floor: needs at least 3 vertices, has " + std::to_string(free_floor.size()));
  for (size_t i = 0; i < free_floor.size(); ++i) {
    if (!Finite(free_floor[i])) return fail("free_floor[" + std::to_string(i) + "]: not a finite point");
  }
  if (SignedArea(free_floor) <= 1e-6) return fail("free_floor: must be counter-clockwise with a positive area");
  if (!std::isfinite(floor_z)) return fail("floor_z: not finite");
  if (!(clear_height > 0.0)) return fail("clear_height: must be > 0, is " + std::to_string(clear_height));

  for (size_t i = 0; i < walls.size(); ++i) {
    const WallEdge& w = walls[i];
    const std::string at = "walls[" + std::to_string(i) + "]";
    if (!Finite(w.a) || !Finite(w.b) || std::hypot(w.b.x - w.a.x, w.b.y - w.a.y) < 1e-6) {
      return fail(at + ": a and b must be distinct finite points");
    }
    for (const WallOpening& o : w.openings) {
      if (!(o.t1 > o.t0) || !(o.z1 > o.z0)) return fail(at + ".openings: each needs t1 > t0 and z1 > z0");
    }
  }
  for (size_t i = 0; i < keep_outs.size(); ++i) {
    const KeepOut& k = keep_outs[i];
    const std::string at = "keep_outs[" + std::to_string(i) + "] (" + Excerpt(k.name) + ")";
    if (k.polygon.size() < 3 || Area(k.polygon) <= 1e-9) return fail(at + ": polygon needs 3 vertices and an area");
    if (!(k.z_max > k.z_min)) return fail(at + ": z_max must exceed z_min");
  }

  std::set<std::string> ids;
  for (const ProblemObject& o : objects) {
    if (o.id.empty()) return fail("an object has an empty id");
    if (!ids.insert(o.id).second) return fail("objects: id \"" + Excerpt(o.id) + "\" appears twice");
  }
  for (size_t i = 0; i < objects.size(); ++i) {
    const ProblemObject& o = objects[i];
    const std::string at = "object \"" + Excerpt(o.id) + "\"";
    const Vec3& s = o.asset.size;
    if (!(s.x > 0.0 && s.y > 0.0 && s.z >= 0.0) || !std::isfinite(s.x + s.y + s.z)) {
      return fail(at + ": asset size must be positive, is [" + std::to_string(s.x) + ", " + std::to_string(s.y) + ", " +
                  std::to_string(s.z) + "]");
    }
    if (!o.mesh || o.mesh->TriangleCount() == 0) return fail(at + ": has no mesh (the exact check needs one)");
    if (std::string outside = MeshOutsideAssetBox(o.asset, *o.mesh); !outside.empty()) return fail(at + ": " + outside);
    if (!(o.scale_min > 0.49 && o.scale_min <= 1.0 && o.scale_max >= 1.0 && o.scale_max < 2.01)) {
      return fail(at + ": scale range [" + std::to_string(o.scale_min) + ", " + std::to_string(o.scale_max) +
                  "] must hold 1 within [0.5, 2]");
    }
    if (!(o.wall_gap >= 0.0 && o.wall_gap <= 0.2)) return fail(at + ": wall_gap " + std::to_string(o.wall_gap) + " not in [0, 0.2]");
    if (o.wall >= static_cast<int>(walls.size())) return fail(at + ": wall " + std::to_string(o.wall) + " does not exist");
    if (o.zone) {
      static const std::set<std::string> kSides = {"front", "back", "left", "right", "sides"};
      if (!kSides.count(o.zone->side)) return fail(at + ": interaction zone side \"" + Excerpt(o.zone->side) + "\" unknown");
      if (!(o.zone->depth >= 0.0 && o.zone->depth <= 3.0)) return fail(at + ": interaction zone depth not in [0, 3]");
    }
    const bool on_floor = o.parent == "floor";
    if (o.parent == "floor" || o.parent == "wall" || o.parent == "ceiling") {
      const bool fits = (on_floor && (o.relation == Relation::kOnTop || o.relation == Relation::kAgainstWall)) ||
                        (o.parent == "wall" && o.relation == Relation::kOnWall) ||
                        (o.parent == "ceiling" && o.relation == Relation::kHanging);
      if (!fits) return fail(at + ": relation " + std::string(RelationName(o.relation)) + " does not fit parent " + o.parent);
      continue;
    }
    int p = Find(o.parent);
    if (p < 0) return fail(at + ": parent \"" + Excerpt(o.parent) + "\" is not an object of the room");
    if (o.relation != Relation::kOnTop && o.relation != Relation::kInside) {
      return fail(at + ": on another object the relation must be ontop or inside, is " + std::string(RelationName(o.relation)));
    }
    const AssetRecord& pa = objects[p].asset;
    if (o.relation == Relation::kOnTop) {
      if (pa.support_surfaces.empty()) return fail(at + ": parent \"" + Excerpt(o.parent) + "\" has no support surface");
      if (o.surface >= static_cast<int>(pa.support_surfaces.size())) {
        return fail(at + ": surface " + std::to_string(o.surface) + " does not exist on \"" + Excerpt(o.parent) + "\"");
      }
    } else {
      if (pa.cavities.empty()) return fail(at + ": parent \"" + Excerpt(o.parent) + "\" has no cavity");
      if (o.cavity >= static_cast<int>(pa.cavities.size())) {
        return fail(at + ": cavity " + std::to_string(o.cavity) + " does not exist on \"" + Excerpt(o.parent) + "\"");
      }
    }
    // The parent chain must end at floor, wall or ceiling.
    std::set<int> seen = {static_cast<int>(i)};
    for (int q = p; q >= 0; q = Find(objects[q].parent)) {
      if (!seen.insert(q).second) return fail(at + ": its parent chain is a cycle");
    }
  }
  for (size_t i = 0; i < edges.size(); ++i) {
    const SemanticEdge& e = edges[i];
    const std::string at = "edges[" + std::to_string(i) + "] (" + std::string(SemanticRelationName(e.relation)) + ")";
    if (Find(e.source) < 0) return fail(at + ": source \"" + Excerpt(e.source) + "\" is not an object of the room");
    if (Find(e.target) < 0) return fail(at + ": target \"" + Excerpt(e.target) + "\" is not an object of the room");
    if (e.source == e.target) return fail(at + ": source and target are the same object \"" + Excerpt(e.source) + "\"");
    if (e.min_gap > e.max_gap) return fail(at + ": min_gap exceeds max_gap");
  }
  return Status::Ok();
}

}  // namespace villa::solver
