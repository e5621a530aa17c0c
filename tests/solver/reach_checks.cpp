#include "reach_checks.h"

#include <algorithm>
#include <cmath>

#include <catch2/catch.hpp>

#include "layout/layout_io.h"

namespace villa::solver {
namespace {

constexpr double kBand = 2.0;    // m above the floor: head height
constexpr double kBelow = 0.05;  // m under it

double Cross(Point o, Point a, Point b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

double PointSegment(Point p, Point a, Point b) {
  const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
  double t = l2 > 0.0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / l2 : 0.0;
  t = std::max(0.0, std::min(1.0, t));
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

bool Crossing(Point a, Point b, Point c, Point d) {
  const double d1 = Cross(c, d, a), d2 = Cross(c, d, b), d3 = Cross(a, b, c), d4 = Cross(a, b, d);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0;
}

bool InPolygon(Point p, const std::vector<Point>& poly) {
  bool in = false;
  for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    if ((poly[i].y > p.y) != (poly[j].y > p.y) &&
        p.x < (poly[j].x - poly[i].x) * (p.y - poly[i].y) / (poly[j].y - poly[i].y) + poly[i].x)
      in = !in;
  }
  return in;
}

// Plan distance between segment [a, b] and a polygon (any number of points: 1 a point, 2 a segment).
double SegmentPolygon(Point a, Point b, const std::vector<Point>& poly) {
  if (poly.empty()) return 1e300;
  if (poly.size() >= 3 && (InPolygon(a, poly) || InPolygon(b, poly))) return 0.0;
  double best = 1e300;
  const size_t edges = poly.size() == 1 ? 1 : (poly.size() == 2 ? 1 : poly.size());
  for (size_t i = 0; i < edges; ++i) {
    const Point c = poly[i], d = poly[(i + 1) % poly.size()];
    if (poly.size() >= 2 && Crossing(a, b, c, d)) return 0.0;
    best = std::min({best, PointSegment(a, c, d), PointSegment(b, c, d), PointSegment(c, a, b), PointSegment(d, a, b)});
  }
  return best;
}

// A triangle cut to heights [z0, z1], its points in plan.
std::vector<Point> Cut(const Vec3& p, const Vec3& q, const Vec3& r, double z0, double z1) {
  std::vector<Vec3> poly = {p, q, r};
  for (int side = 0; side < 2; ++side) {
    std::vector<Vec3> out;
    for (size_t i = 0; i < poly.size(); ++i) {
      const Vec3 a = poly[i], b = poly[(i + 1) % poly.size()];
      const double da = side == 0 ? a.z - z0 : z1 - a.z, db = side == 0 ? b.z - z0 : z1 - b.z;
      if (da >= 0) out.push_back(a);
      if ((da >= 0) != (db >= 0)) {
        const double t = da / (da - db);
        out.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z)});
      }
    }
    poly = out;
  }
  std::vector<Point> plan;
  for (const Vec3& v : poly) plan.push_back({v.x, v.y});
  return plan;
}

// The walking segments of a path: consecutive points on the same level.
template <class Visit>
void ForEachWalk(const ReachPath& path, Visit visit) {
  for (size_t i = 0; i + 1 < path.points.size(); ++i) {
    if (path.level[i] < 0 || path.level[i] != path.level[i + 1]) continue;
    visit(path.level[i], Point{path.points[i].x, path.points[i].y}, Point{path.points[i + 1].x, path.points[i + 1].y},
          path.points[i].z);
  }
}

}  // namespace

Built BuildFixture(const std::string& file, const ReachOptions& options) {
  auto layout = LoadLayout(std::string(VILLA_FIXTURE_DIR) + "/layouts/" + file);
  REQUIRE(layout.ok());
  const BuildOptions build_options;
  auto building = BuildBuilding(*layout, build_options);
  REQUIRE(building.ok());
  auto input = BuildingReachInput(*layout, *building, build_options, options);
  REQUIRE(input.ok());
  return {std::move(*building), std::move(*input)};
}

double PathClearance(const ReachPath& path, const ReachInput& input, int level) {
  double best = 1e300;
  ForEachWalk(path, [&](int l, Point a, Point b, double floor_z) {
    if (l != level) return;
    for (const ReachObstacle& o : input.obstacles) {
      if (o.level != l || std::min(o.z1, floor_z + kBand) <= std::max(o.z0, floor_z - kBelow)) continue;
      for (const Ring& piece : o.pieces) best = std::min(best, SegmentPolygon(a, b, piece));
    }
    for (const Ring& ring : input.levels[l].floor) {
      for (size_t i = 0; i < ring.size(); ++i) best = std::min(best, SegmentPolygon(a, b, {ring[i], ring[(i + 1) % ring.size()]}));
    }
  });
  return best;
}

double MeshClearance(const ReachPath& path, const BuildingMesh& building, const std::vector<ReachObject>& objects) {
  double best = 1e300;
  ForEachWalk(path, [&](int l, Point a, Point b, double floor_z) {
    const double z0 = floor_z - kBelow, z1 = floor_z + kBand;
    for (const MeshPart& part : building.parts) {
      const bool walls = part.kind == PartKind::kExteriorWall || part.kind == PartKind::kInteriorWall ||
                         part.kind == PartKind::kDoorLeaf || part.kind == PartKind::kWindowGlass;
      if (part.level != l || !(walls || part.kind == PartKind::kStair)) continue;
      for (const auto& t : part.mesh.triangles) {
        const std::vector<Point> piece = Cut(part.mesh.vertices[t[0]], part.mesh.vertices[t[1]], part.mesh.vertices[t[2]], z0, z1);
        best = std::min(best, SegmentPolygon(a, b, piece));
      }
    }
    if (l < static_cast<int>(building.slab_holes.size())) {
      for (const Ring& hole : building.slab_holes[l]) best = std::min(best, SegmentPolygon(a, b, hole));
    }
    for (const ReachObject& o : objects) {
      if (o.level != l || o.covering || o.box.z0 >= z1) continue;
      best = std::min(best, SegmentPolygon(a, b, o.box.Footprint()));
    }
  });
  return best;
}

}  // namespace villa::solver
