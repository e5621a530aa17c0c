// The reachability input from a layout and its built building (walls cut at head height, door leaves,
// panes, stairs and their links, holes, the entrance, a target per room) and from placed objects.
#include <algorithm>
#include <cmath>
#include <map>

#include "building/building.h"
#include "layout/geometry.h"
#include "mesh/geometry2d.h"
#include "solver/free_space.h"
#include "solver/reach.h"
#include "solver/reach_raster.h"

namespace villa::solver {
namespace {

using namespace villa::geo;


// Convex hull (CCW, no collinear points) of plan points: 1 point, 2 (a segment) or a polygon.
std::vector<Point> Hull(std::vector<Point> p) {
  std::sort(p.begin(), p.end(), [](Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  p.erase(std::unique(p.begin(), p.end(), [](Point a, Point b) { return Dist(a, b) < 1e-9; }), p.end());
  if (p.size() < 3) return p;
  std::vector<Point> h(2 * p.size());
  size_t k = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && Cross(Sub(h[k - 1], h[k - 2]), Sub(p[i], h[k - 2])) <= 1e-14) --k;
    h[k++] = p[i];
  }
  for (size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && Cross(Sub(h[k - 1], h[k - 2]), Sub(p[i - 1], h[k - 2])) <= 1e-14) --k;
    h[k++] = p[i - 1];
  }
  h.resize(k - 1);
  return h;
}

// The part of a triangle between heights z0 and z1, projected on the plan: a convex piece (its hull).
std::vector<Point> SliceTriangle(const Vec3& a, const Vec3& b, const Vec3& c, double z0, double z1) {
  std::vector<Vec3> poly = {a, b, c};
  auto clip = [&](double level, bool keep_above) {
    std::vector<Vec3> out;
    for (size_t i = 0; i < poly.size(); ++i) {
      const Vec3& p = poly[i];
      const Vec3& q = poly[(i + 1) % poly.size()];
      const double dp = keep_above ? p.z - level : level - p.z;
      const double dq = keep_above ? q.z - level : level - q.z;
      if (dp >= 0.0) out.push_back(p);
      if ((dp >= 0.0) != (dq >= 0.0)) out.push_back(p + (q - p) * (dp / (dp - dq)));
    }
    poly = std::move(out);
  };
  clip(z0, true);
  if (!poly.empty()) clip(z1, false);
  std::vector<Point> plan;
  for (const Vec3& v : poly) plan.push_back({v.x, v.y});
  return Hull(std::move(plan));
}

// A mesh's plan footprint between two heights: one convex piece per triangle that reaches the band.
std::vector<Ring> SliceMesh(const TriangleMesh& mesh, double z0, double z1) {
  std::vector<Ring> pieces;
  for (const auto& t : mesh.triangles) {
    std::vector<Point> hull = SliceTriangle(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], z0, z1);
    if (!hull.empty()) pieces.push_back(std::move(hull));
  }
  return pieces;
}

// The highest point of the mesh above plan point p (its upward surface there), or -1e300.
double TopAt(const TriangleMesh& mesh, Point p) {
  double top = -1e300;
  for (const auto& t : mesh.triangles) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const double det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    if (std::abs(det) < 1e-12) continue;  // vertical in plan
    const double u = ((p.x - a.x) * (c.y - a.y) - (c.x - a.x) * (p.y - a.y)) / det;
    const double v = ((b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y)) / det;
    if (u < -1e-9 || v < -1e-9 || u + v > 1.0 + 1e-9) continue;
    top = std::max(top, a.z + u * (b.z - a.z) + v * (c.z - a.z));
  }
  return top;
}

// Where a built staircase is stepped on and off, read from its own mesh, so it holds whichever side the
// builder chose: along the footprint's outline, 5 cm apart, the top of the stair just inside (10 cm in).
// The lowest top found is the first tread (one riser up): stretches whose tops are within two risers of
// the floor are entries, stretches within two risers of the floor above are exits. The walk runs from the
// middle of the first flight's foot (the open edge half holding the lowest top) inward to the landing,
// across it, and back out along the other half to the second flight's top.
std::optional<StairLink> LinkOf(const BuiltStair& stair, const TriangleMesh& mesh, double floor_z, double rise) {
  const Ring f = CleanRing(stair.footprint, 1e-9);
  if (f.size() < 3 || mesh.triangles.empty()) return std::nullopt;
  constexpr double kInside = 0.1, kSpacing = 0.05;
  struct Sample {
    int edge;
    double t;  // m along the edge
    double top;
  };
  std::vector<Sample> samples;
  double lowest = 1e300;
  for (size_t i = 0; i < f.size(); ++i) {
    const Point a = f[i], b = f[(i + 1) % f.size()];
    const double len = Dist(a, b);
    const Point u = Unit(Sub(b, a)), in = Left(u);  // into a CCW ring
    const int n = std::max(1, static_cast<int>(std::floor(len / kSpacing)));
    for (int k = 0; k < n; ++k) {
      const double t = (k + 0.5) * len / n;
      const double top = TopAt(mesh, Add(Add(a, Scale(u, t)), Scale(in, kInside)));
      samples.push_back({static_cast<int>(i), t, top});
      if (top > -1e299) lowest = std::min(lowest, top);
    }
  }
  // The first flight's foot: the edge half with the most samples on the first tread (a flight's side
  // touches it for one tread only).
  std::map<std::pair<int, int>, int> on_first;
  for (const Sample& q : samples) {
    const int i = q.edge;
    if (q.top > -1e299 && q.top <= lowest + 0.01) ++on_first[{i, q.t < 0.5 * Dist(f[i], f[(i + 1) % f.size()]) ? 0 : 1}];
  }
  int edge = -1, half = -1, most = 0;
  for (const auto& [where, count] : on_first) {
    if (count > most) edge = where.first, half = where.second, most = count;
  }
  const double riser = lowest - floor_z;
  if (edge < 0 || riser <= 0.0 || riser > 0.5 * rise) return std::nullopt;
  StairLink link;
  link.room = stair.room;
  link.level = stair.level;
  // Runs of consecutive samples along one edge that pass `test`, as stretches of that edge.
  auto runs = [&](auto test) {
    std::vector<StairStep> out;
    for (size_t k = 0; k < samples.size();) {
      if (samples[k].top < -1e299 || !test(samples[k].top)) {
        ++k;
        continue;
      }
      size_t e = k;
      while (e + 1 < samples.size() && samples[e + 1].edge == samples[k].edge && samples[e + 1].top > -1e299 && test(samples[e + 1].top)) ++e;
      const Point a = f[samples[k].edge], b = f[(samples[k].edge + 1) % f.size()];
      const Point u = Unit(Sub(b, a));
      const double half_step = 0.5 * Dist(a, b) / std::max(1, static_cast<int>(std::floor(Dist(a, b) / kSpacing)));
      const double t0 = std::max(0.0, samples[k].t - half_step), t1 = std::min(Dist(a, b), samples[e].t + half_step);
      out.push_back({{Add(a, Scale(u, t0)), Add(a, Scale(u, t1))}, Scale(Left(u), -1.0)});
      k = e + 1;
    }
    return out;
  };
  const double step = 2.0 * riser + 0.5 * riser;  // two risers, with room for rounding
  link.entries = runs([&](double top) { return top <= floor_z + step; });
  link.exits = runs([&](double top) { return top >= floor_z + rise - step; });
  if (link.entries.empty() || link.exits.empty()) return std::nullopt;
  // The walk: the first flight runs inward from its foot until the landing, half a storey up.
  const Point a = f[edge], b = f[(edge + 1) % f.size()];
  const Point in = Left(Unit(Sub(b, a)));
  const Point m = Lerp(a, b, 0.5);
  const Point e = half == 0 ? Lerp(a, m, 0.5) : Lerp(m, b, 0.5), x = half == 0 ? Lerp(m, b, 0.5) : Lerp(a, m, 0.5);
  if (TopAt(mesh, Add(x, Scale(in, kInside))) < floor_z + rise - step) return std::nullopt;
  double run = 0.0;
  while (run < 10.0 && TopAt(mesh, Add(e, Scale(in, run))) < floor_z + 0.5 * rise - 0.01) run += 0.01;
  const double z_landing = floor_z + 0.5 * rise;
  link.walk = {{e.x, e.y, floor_z},
               {e.x + in.x * run, e.y + in.y * run, z_landing},
               {x.x + in.x * run, x.y + in.y * run, z_landing},
               {x.x, x.y, floor_z + rise}};
  for (size_t k = 0; k + 1 < link.walk.size(); ++k) link.length += Norm(link.walk[k + 1] - link.walk[k]);
  return link;
}

// A door leaf shut in its opening (closed doors, or a leaf with no free way to swing) lies along its door's
// segment: its longest plan extent runs parallel to the door, within the wall. The person opens it.
bool ShutInOpening(const MeshPart& leaf, const Layout& layout) {
  const Element* door = nullptr;
  for (const auto* list : {&layout.doors, &layout.entrances}) {
    for (const Element& e : *list) {
      if (e.name == leaf.element && e.OnLevel(leaf.level)) door = &e;
    }
  }
  if (!door || leaf.mesh.vertices.empty()) return false;
  Point a{leaf.mesh.vertices[0].x, leaf.mesh.vertices[0].y}, b = a;
  double longest = 0.0;
  for (const Vec3& p : leaf.mesh.vertices) {
    for (const Vec3& q : leaf.mesh.vertices) {
      const double d = std::hypot(p.x - q.x, p.y - q.y);
      if (d > longest) longest = d, a = {p.x, p.y}, b = {q.x, q.y};
    }
  }
  const Point along = Unit(Sub(door->shape.b, door->shape.a));
  const double across = std::abs(Cross(along, Unit(Sub(b, a))));
  return across < 0.2 && PointSegmentDistance(Lerp(a, b, 0.5), {door->shape.a, door->shape.b}) < 0.2;
}

}  // namespace

std::vector<Ring> ZoneFootprints(const OrientedBox& box, const std::string& side, double depth) {
  if (!(depth > 0.0)) return {};
  const double d = depth, hx = box.hx, hy = box.hy;
  struct Local {
    double cx, cy, hx, hy;
  };
  std::vector<Local> boxes;
  if (side == "front") boxes = {{0.0, -(hy + 0.5 * d), hx, 0.5 * d}};
  else if (side == "back") boxes = {{0.0, hy + 0.5 * d, hx, 0.5 * d}};
  else if (side == "left") boxes = {{hx + 0.5 * d, 0.0, 0.5 * d, hy}};
  else if (side == "right") boxes = {{-(hx + 0.5 * d), 0.0, 0.5 * d, hy}};
  else boxes = {{hx + 0.5 * d, 0.0, 0.5 * d, hy}, {-(hx + 0.5 * d), 0.0, 0.5 * d, hy}};
  std::vector<Ring> out;
  for (const Local& l : boxes) {
    OrientedBox z = box;
    z.c = Add(box.c, Add(Scale(box.U(), l.cx), Scale(box.V(), l.cy)));
    z.hx = l.hx;
    z.hy = l.hy;
    out.push_back(z.Footprint());
  }
  return out;
}

Result<ReachInput> BuildingReachInput(const Layout& layout, const BuildingMesh& building, const BuildOptions& options,
                                      const ReachOptions& reach) {
  std::string message;
  if (!reach.IsValid(&message)) return Error{"reach options: " + message};
  if (layout.entrances.empty()) return Error{"layout: no entrance to walk in from"};
  ReachInput input;
  const int levels = std::max(building.levels, layout.LevelCount());
  for (int level = 0; level < levels; ++level) {
    ReachLevel l;
    l.level = level;
    l.floor_z = building.FloorZ(level);
    std::vector<Ring> rooms;
    for (int i : layout.RoomsOnLevel(level)) rooms.push_back(layout.rooms[i].polygon);
    for (const PolygonWithHoles& p : UnionOfRings(rooms)) {
      l.floor.push_back(p.outer);
      l.floor.insert(l.floor.end(), p.holes.begin(), p.holes.end());
    }
    if (l.floor.empty()) return Error{"layout: level " + std::to_string(level) + " has no floor"};
    input.levels.push_back(std::move(l));
  }
  // Building parts in the walking band of their level: the wall under a door is gone there, the lintel
  // above it is higher than a person, so a door is a gap and a window is not.
  for (const MeshPart& part : building.parts) {
    ObstacleKind kind;
    switch (part.kind) {
      case PartKind::kExteriorWall:
      case PartKind::kInteriorWall:
      case PartKind::kRailing: kind = ObstacleKind::kWall; break;
      case PartKind::kDoorLeaf: kind = ObstacleKind::kDoorLeaf; break;
      case PartKind::kWindowGlass: kind = ObstacleKind::kWindow; break;
      default: continue;  // slabs are walked on; stairs are their footprints below
    }
    if (part.level < 0 || part.level >= levels) continue;
    if (kind == ObstacleKind::kDoorLeaf && (!options.door_leaves_open || ShutInOpening(part, layout))) continue;
    const double z0 = input.levels[part.level].floor_z - kBelowFloor, z1 = input.levels[part.level].floor_z + reach.head_height;
    std::vector<Ring> pieces = SliceMesh(part.mesh, z0, z1);
    if (pieces.empty()) continue;
    input.obstacles.push_back({part.name, kind, part.level, "", std::move(pieces), z0, z1});
  }
  for (const BuiltStair& st : building.stairs) {
    if (st.level < 0 || st.level >= levels) continue;
    const double z0 = input.levels[st.level].floor_z - kBelowFloor;
    input.obstacles.push_back({"stair " + st.room, ObstacleKind::kStair, st.level, st.room, ConvexPieces(st.footprint), z0,
                               z0 + kBelowFloor + reach.head_height});
    const MeshPart* mesh = nullptr;
    for (const MeshPart& part : building.parts) {
      if (part.kind == PartKind::kStair && part.level == st.level && part.name == "stair_" + st.room) mesh = &part;
    }
    if (st.level + 1 >= levels) continue;
    if (auto link = mesh ? LinkOf(st, mesh->mesh, building.FloorZ(st.level), building.FloorZ(st.level + 1) - building.FloorZ(st.level))
                         : std::nullopt) {
      const Point middle = Centroid(st.footprint);
      for (int i : layout.RoomsOnLevel(st.level + 1)) {
        if (PointInRing(middle, layout.rooms[i].polygon, 0)) link->upper_room = layout.rooms[i].name();
      }
      input.stairs.push_back(std::move(*link));
    } else {
      return Error{"building: the staircase in " + st.room + " has no flight foot to step on (its mesh is missing or unusual)"};
    }
  }
  for (int level = 1; level < levels && level < static_cast<int>(building.slab_holes.size()); ++level) {
    const double z0 = input.levels[level].floor_z - kBelowFloor;
    for (const Ring& hole : building.slab_holes[level]) {
      input.obstacles.push_back({"stair hole", ObstacleKind::kStairHole, level, "", ConvexPieces(hole), z0,
                                 z0 + kBelowFloor + reach.head_height});
    }
  }
  // The entrance: its inward normal points into the ground floor.
  const Element& e = layout.entrances.front();
  input.entrance = e.shape;
  const Point mid = Lerp(e.shape.a, e.shape.b, 0.5);
  const Point n = Left(Unit(Sub(e.shape.b, e.shape.a)));
  bool in_left = false;
  for (const Ring& r : input.levels[0].floor) in_left ^= PointInRing(Add(mid, Scale(n, 0.05)), r, 0);
  input.inside = in_left ? n : Scale(n, -1.0);
  input.depth = options.exterior_wall_thickness;
  for (const auto* list : {&layout.doors, &layout.opens, &layout.entrances}) {
    for (const Element& d : *list) {
      for (int level = 0; level < levels; ++level) {
        if (d.OnLevel(level)) input.anchors.push_back({level, Lerp(d.shape.a, d.shape.b, 0.5)});
      }
    }
  }
  for (const Room& room : layout.rooms) {
    input.targets.push_back({TargetKind::kRoom, room.name(), room.name(), room.level, {{room.polygon, TargetArea::Mode::kInside, 0.0}}});
  }
  return input;
}

void AddObjects(ReachInput& input, const std::vector<ReachObject>& objects, const ReachOptions& options) {
  for (const ReachObject& o : objects) {
    if (o.level < 0 || o.level >= static_cast<int>(input.levels.size())) continue;
    const double floor_z = input.levels[o.level].floor_z;
    const Ring footprint = o.box.Footprint();
    if (!o.covering && o.box.z0 < floor_z + options.head_height) {
      input.obstacles.push_back({o.id, ObstacleKind::kObject, o.level, o.room, {footprint}, o.box.z0, o.box.z1});
    }
    if (o.zone.empty()) continue;
    ReachTarget t{TargetKind::kZone, o.id, o.room, o.level, {}};
    for (const Ring& z : o.zone) t.areas.push_back({z, TargetArea::Mode::kTouch, 0.0});
    if (o.zone_shared) t.areas.push_back({footprint, TargetArea::Mode::kTouch, options.arm_reach});
    input.targets.push_back(std::move(t));
  }
}

}  // namespace villa::solver
