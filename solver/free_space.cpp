#include "solver/free_space.h"

#include <algorithm>
#include <cmath>

#include "layout/geometry.h"
#include "mesh/geometry2d.h"
#include "mesh/triangulate.h"
#include "solver/box.h"

namespace villa::solver {
namespace {

using namespace villa::geo;

// Inside or on the boundary of a convex CCW polygon (3 points or more).
bool InsideConvex(Point p, const std::vector<Point>& poly) {
  for (size_t i = 0; i < poly.size(); ++i) {
    const Point& a = poly[i];
    const Point& b = poly[(i + 1) % poly.size()];
    if (Cross(Sub(b, a), Sub(p, a)) < -1e-12) return false;
  }
  return true;
}

int Orientation(Point a, Point b, Point c) {
  const double v = Cross(Sub(b, a), Sub(c, a));
  return v > 1e-14 ? 1 : (v < -1e-14 ? -1 : 0);
}

bool OnSegment(Point p, Point a, Point b) {
  return std::min(a.x, b.x) - 1e-12 <= p.x && p.x <= std::max(a.x, b.x) + 1e-12 && std::min(a.y, b.y) - 1e-12 <= p.y &&
         p.y <= std::max(a.y, b.y) + 1e-12;
}

// Closed segments [p1, p2] and [q1, q2] share a point.
bool SegmentsMeet(Point p1, Point p2, Point q1, Point q2) {
  const int o1 = Orientation(p1, p2, q1), o2 = Orientation(p1, p2, q2);
  const int o3 = Orientation(q1, q2, p1), o4 = Orientation(q1, q2, p2);
  if (o1 != o2 && o3 != o4) return true;
  return (o1 == 0 && OnSegment(q1, p1, p2)) || (o2 == 0 && OnSegment(q2, p1, p2)) ||
         (o3 == 0 && OnSegment(p1, q1, q2)) || (o4 == 0 && OnSegment(p2, q1, q2));
}

// The hull's edges: none for a point (it is its own degenerate edge), one for two points, n for n >= 3.
size_t EdgeCount(const std::vector<Point>& hull) { return hull.size() < 3 ? 1 : hull.size(); }
std::pair<Point, Point> EdgeOf(const std::vector<Point>& hull, size_t i) {
  if (hull.size() == 1) return {hull[0], hull[0]};
  return {hull[i], hull[(i + 1) % hull.size()]};
}

// Distance between two disjoint convex hulls: the nearest pair is a vertex of one and an edge of the other.
double HullDistance(const std::vector<Point>& a, const std::vector<Point>& b) {
  double best = 1e300;
  for (const Point& p : a) {
    for (size_t i = 0; i < EdgeCount(b); ++i) {
      const auto [q0, q1] = EdgeOf(b, i);
      best = std::min(best, PointSegmentDistance(p, {q0, q1}));
    }
  }
  for (const Point& p : b) {
    for (size_t i = 0; i < EdgeCount(a); ++i) {
      const auto [q0, q1] = EdgeOf(a, i);
      best = std::min(best, PointSegmentDistance(p, {q0, q1}));
    }
  }
  return best;
}

bool HullsMeet(const std::vector<Point>& a, const std::vector<Point>& b) {
  if (b.size() >= 3) {
    for (const Point& p : a) {
      if (InsideConvex(p, b)) return true;
    }
  }
  if (a.size() >= 3) {
    for (const Point& p : b) {
      if (InsideConvex(p, a)) return true;
    }
  }
  if (a.size() >= 2 && b.size() >= 2) {
    for (size_t i = 0; i < EdgeCount(a); ++i) {
      const auto [p0, p1] = EdgeOf(a, i);
      for (size_t j = 0; j < EdgeCount(b); ++j) {
        const auto [q0, q1] = EdgeOf(b, j);
        if (SegmentsMeet(p0, p1, q0, q1)) return true;
      }
    }
  }
  // A point on a segment or on another point.
  if (a.size() == 1 || b.size() == 1) return HullDistance(a, b) <= 1e-12;
  return false;
}

void AddAxes(const std::vector<Point>& hull, std::vector<Point>& axes) {
  if (hull.size() == 2) {
    const Point d = Unit(Sub(hull[1], hull[0]));
    axes.push_back(d);
    axes.push_back(Left(d));
  } else if (hull.size() >= 3) {
    for (size_t i = 0; i < hull.size(); ++i) axes.push_back(Unit(Left(Sub(hull[(i + 1) % hull.size()], hull[i]))));
  }
}

// Depth of two overlapping convex hulls along their best separating axis (>= 0).
double SeparatingDepth(const std::vector<Point>& a, const std::vector<Point>& b) {
  std::vector<Point> axes;
  AddAxes(a, axes);
  AddAxes(b, axes);
  double best = axes.empty() ? 0.0 : 1e300;
  for (const Point& u : axes) {
    if (Len(u) == 0.0) continue;
    double a0 = 1e300, a1 = -1e300, b0 = 1e300, b1 = -1e300;
    for (const Point& p : a) {
      a0 = std::min(a0, Dot(p, u));
      a1 = std::max(a1, Dot(p, u));
    }
    for (const Point& p : b) {
      b0 = std::min(b0, Dot(p, u));
      b1 = std::max(b1, Dot(p, u));
    }
    best = std::min(best, std::min(a1 - b0, b1 - a0));
  }
  return std::max(0.0, best == 1e300 ? 0.0 : best);
}

void BoundsOf(const PlanShape& s, Point& lo, Point& hi) {
  lo = {1e300, 1e300};
  hi = {-1e300, -1e300};
  for (const Point& p : s.points) {
    lo = {std::min(lo.x, p.x - s.radius), std::min(lo.y, p.y - s.radius)};
    hi = {std::max(hi.x, p.x + s.radius), std::max(hi.y, p.y + s.radius)};
  }
}

}  // namespace

PlanShape PlanShape::Disc(Point centre, double radius) { return {{centre}, radius}; }
PlanShape PlanShape::Capsule(Point a, Point b, double radius) { return {{a, b}, radius}; }
PlanShape PlanShape::Polygon(Ring convex) { return {std::move(convex), 0.0}; }

double PlanClearance(const PlanShape& a, const PlanShape& b) {
  if (a.points.empty() || b.points.empty()) return 1e300;
  const double hull = HullsMeet(a.points, b.points) ? -SeparatingDepth(a.points, b.points) : HullDistance(a.points, b.points);
  return hull - a.radius - b.radius;
}

std::vector<Ring> ConvexPieces(const Ring& ring) {
  const Ring clean = CleanRing(ring);
  if (clean.size() < 3) return {};
  if (ReflexVertices(clean).empty()) return {clean};
  std::vector<Ring> pieces;
  for (const auto& t : TriangulatePolygon(clean)) {
    Ring tri = {clean[t[0]], clean[t[1]], clean[t[2]]};
    if (Area(tri) > 1e-9) pieces.push_back(std::move(tri));
  }
  return pieces;
}

FreeSpace::FreeSpace(std::vector<Ring> region, std::vector<PlanObstacle> obstacles, double index_cell)
    : region_(std::move(region)), obstacles_(std::move(obstacles)), cell_(index_cell > 0.0 ? index_cell : 0.5) {
  for (const Ring& r : region_) {
    for (size_t i = 0; i < r.size(); ++i) edges_.push_back({r[i], r[(i + 1) % r.size()]});
  }
  std::vector<std::pair<Point, Point>> boxes, edge_boxes;
  lo_ = {1e300, 1e300};
  hi_ = {-1e300, -1e300};
  auto grow = [&](Point l, Point h) {
    lo_ = {std::min(lo_.x, l.x), std::min(lo_.y, l.y)};
    hi_ = {std::max(hi_.x, h.x), std::max(hi_.y, h.y)};
  };
  for (const PlanObstacle& o : obstacles_) {
    Point l, h;
    BoundsOf(o.shape, l, h);
    if (o.shape.points.empty()) l = h = {0.0, 0.0};
    boxes.push_back({l, h});
    grow(l, h);
  }
  for (const auto& [a, b] : edges_) {
    edge_boxes.push_back({{std::min(a.x, b.x), std::min(a.y, b.y)}, {std::max(a.x, b.x), std::max(a.y, b.y)}});
    grow(edge_boxes.back().first, edge_boxes.back().second);
  }
  if (lo_.x > hi_.x) lo_ = hi_ = {0.0, 0.0};
  // At most about four million index cells, whatever the extent.
  while ((hi_.x - lo_.x) / cell_ * (hi_.y - lo_.y) / cell_ > 4e6) cell_ *= 2.0;
  Build(obstacle_index_, boxes);
  Build(edge_index_, edge_boxes);
}

void FreeSpace::Build(Index& index, const std::vector<std::pair<Point, Point>>& boxes) const {
  index.x0 = lo_.x;
  index.y0 = lo_.y;
  index.cell = cell_;
  index.nx = static_cast<int>(std::floor((hi_.x - lo_.x) / cell_)) + 1;
  index.ny = static_cast<int>(std::floor((hi_.y - lo_.y) / cell_)) + 1;
  index.cells.assign(static_cast<size_t>(index.nx) * index.ny, {});
  for (size_t k = 0; k < boxes.size(); ++k) {
    const int i0 = std::clamp(static_cast<int>(std::floor((boxes[k].first.x - index.x0) / cell_)), 0, index.nx - 1);
    const int i1 = std::clamp(static_cast<int>(std::floor((boxes[k].second.x - index.x0) / cell_)), 0, index.nx - 1);
    const int j0 = std::clamp(static_cast<int>(std::floor((boxes[k].first.y - index.y0) / cell_)), 0, index.ny - 1);
    const int j1 = std::clamp(static_cast<int>(std::floor((boxes[k].second.y - index.y0) / cell_)), 0, index.ny - 1);
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) index.cells[static_cast<size_t>(j) * index.nx + i].push_back(static_cast<int>(k));
    }
  }
}

void FreeSpace::Candidates(const Index& index, Point lo, Point hi, std::vector<int>& out) const {
  out.clear();
  if (index.cells.empty() || hi.x < index.x0 || hi.y < index.y0) return;
  const double x1 = index.x0 + index.nx * index.cell, y1 = index.y0 + index.ny * index.cell;
  if (lo.x > x1 || lo.y > y1) return;
  const int i0 = std::clamp(static_cast<int>(std::floor((lo.x - index.x0) / index.cell)), 0, index.nx - 1);
  const int i1 = std::clamp(static_cast<int>(std::floor((hi.x - index.x0) / index.cell)), 0, index.nx - 1);
  const int j0 = std::clamp(static_cast<int>(std::floor((lo.y - index.y0) / index.cell)), 0, index.ny - 1);
  const int j1 = std::clamp(static_cast<int>(std::floor((hi.y - index.y0) / index.cell)), 0, index.ny - 1);
  for (int j = j0; j <= j1; ++j) {
    for (int i = i0; i <= i1; ++i) {
      const auto& c = index.cells[static_cast<size_t>(j) * index.nx + i];
      out.insert(out.end(), c.begin(), c.end());
    }
  }
  if (i0 != i1 || j0 != j1) {
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }
}

bool FreeSpace::InRegion(Point p) const {
  if (region_.empty()) return true;
  bool inside = false;
  for (const Ring& r : region_) inside ^= PointInRing(p, r, 0);
  return inside;
}

FreeSpace::Nearest FreeSpace::ObstacleClearance(const PlanShape& shape, double z0, double z1, double reach) const {
  Nearest best{reach, kNone};
  if (shape.points.empty()) return best;
  Point lo, hi;
  BoundsOf(shape, lo, hi);
  std::vector<int> near;
  Candidates(obstacle_index_, {lo.x - reach, lo.y - reach}, {hi.x + reach, hi.y + reach}, near);
  for (int k : near) {
    const PlanObstacle& o = obstacles_[k];
    if (std::min(z1, o.z1) - std::max(z0, o.z0) <= 0.0) continue;
    const double c = PlanClearance(shape, o.shape);
    if (c < best.clearance) best = {c, k};
  }
  return best;
}

FreeSpace::Nearest FreeSpace::RegionClearance(const PlanShape& shape, double reach) const {
  if (region_.empty() || shape.points.empty()) return {reach, kNone};
  if (!InRegion(shape.points[0])) {
    double d = 1e300;
    for (const auto& [a, b] : edges_) d = std::min(d, PointSegmentDistance(shape.points[0], {a, b}));
    return {-d - shape.radius, kRegion};
  }
  Point lo, hi;
  BoundsOf(shape, lo, hi);
  std::vector<int> near;
  Candidates(edge_index_, {lo.x - reach, lo.y - reach}, {hi.x + reach, hi.y + reach}, near);
  Nearest best{reach, kNone};
  for (int k : near) {
    const double c = PlanClearance(shape, PlanShape::Capsule(edges_[k].first, edges_[k].second, 0.0));
    if (c < best.clearance) best = {c, kRegion};
  }
  return best;
}

FreeSpace::Nearest FreeSpace::Clearance(const PlanShape& shape, double z0, double z1, double reach) const {
  const Nearest region = RegionClearance(shape, reach);
  // Obstacles deeper than the region's outside still win; the search reaches no farther than needed.
  const Nearest obstacle = ObstacleClearance(shape, z0, z1, std::max(0.0, std::min(reach, region.clearance)));
  return obstacle.clearance < region.clearance ? obstacle : region;
}

std::vector<int> FreeSpace::Overlapping(const PlanShape& shape, double z0, double z1) const {
  std::vector<int> out;
  if (shape.points.empty()) return out;
  Point lo, hi;
  BoundsOf(shape, lo, hi);
  std::vector<int> near;
  Candidates(obstacle_index_, lo, hi, near);
  for (int k : near) {
    const PlanObstacle& o = obstacles_[k];
    if (std::min(z1, o.z1) - std::max(z0, o.z0) <= 0.0) continue;
    if (PlanClearance(shape, o.shape) < 0.0) out.push_back(k);
  }
  return out;
}

}  // namespace villa::solver
