#include "annotator/plan_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace villa::annotator {
namespace {

double Cross(const Point& o, const Point& a, const Point& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Distance of p from the infinite line through a-b (a != b).
double LineDistance(const Point& p, const Point& a, const Point& b) {
  double len = std::hypot(b.x - a.x, b.y - a.y);
  if (len <= 0) return std::hypot(p.x - a.x, p.y - a.y);
  return std::abs(Cross(a, b, p)) / len;
}

// Parameter of p's projection on a-b, in metres from a.
double Along(const Point& p, const Point& a, const Point& b) {
  double len = std::hypot(b.x - a.x, b.y - a.y);
  if (len <= 0) return 0;
  return ((p.x - a.x) * (b.x - a.x) + (p.y - a.y) * (b.y - a.y)) / len;
}

Point At(const Point& a, const Point& b, double t) {
  double len = std::hypot(b.x - a.x, b.y - a.y);
  if (len <= 0) return a;
  return {a.x + (b.x - a.x) * t / len, a.y + (b.y - a.y) * t / len};
}

using Interval = std::pair<double, double>;

// Intervals of [0, len] minus the union of `cuts`.
std::vector<Interval> Subtract(double len, std::vector<Interval> cuts, double tol) {
  std::sort(cuts.begin(), cuts.end());
  std::vector<Interval> out;
  double cursor = 0;
  for (auto [lo, hi] : cuts) {
    lo = std::max(lo, 0.0);
    hi = std::min(hi, len);
    if (hi <= lo) continue;
    if (lo > cursor + tol) out.push_back({cursor, lo});
    cursor = std::max(cursor, hi);
  }
  if (len > cursor + tol) out.push_back({cursor, len});
  return out;
}

// The collinear overlap of edge a-b with edge c-d, as an interval along a-b; empty when none.
std::optional<Interval> Overlap(const Point& a, const Point& b, const Point& c, const Point& d, double tol) {
  if (LineDistance(c, a, b) > tol || LineDistance(d, a, b) > tol) return std::nullopt;
  double len = std::hypot(b.x - a.x, b.y - a.y);
  double t0 = Along(c, a, b), t1 = Along(d, a, b);
  if (t0 > t1) std::swap(t0, t1);
  t0 = std::max(t0, 0.0);
  t1 = std::min(t1, len);
  if (t1 - t0 <= tol) return std::nullopt;
  return Interval{t0, t1};
}

}  // namespace

bool SegmentOnRing(const Segment& segment, const Ring& ring, double tol) {
  std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point& a = ring[i];
    const Point& b = ring[(i + 1) % n];
    double len = std::hypot(b.x - a.x, b.y - a.y);
    if (len <= tol) continue;
    if (LineDistance(segment.a, a, b) > tol || LineDistance(segment.b, a, b) > tol) continue;
    double t0 = Along(segment.a, a, b), t1 = Along(segment.b, a, b);
    if (std::min(t0, t1) >= -tol && std::max(t0, t1) <= len + tol) return true;
  }
  return false;
}

std::vector<Stretch> ExteriorStretches(const Layout& layout, int room, double tol) {
  const Room& r = layout.rooms[room];
  std::vector<Stretch> out;
  std::size_t n = r.polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point& a = r.polygon[i];
    const Point& b = r.polygon[(i + 1) % n];
    double len = std::hypot(b.x - a.x, b.y - a.y);
    std::vector<Interval> cuts;
    for (int other : layout.RoomsOnLevel(r.level)) {
      if (other == room) continue;
      const Ring& ring = layout.rooms[other].polygon;
      for (std::size_t j = 0; j < ring.size(); ++j)
        if (auto overlap = Overlap(a, b, ring[j], ring[(j + 1) % ring.size()], tol)) cuts.push_back(*overlap);
    }
    for (auto [lo, hi] : Subtract(len, cuts, tol)) out.push_back({{At(a, b, lo), At(a, b, hi)}});
  }
  return out;
}

std::vector<Stretch> SharedStretches(const Layout& layout, int room_a, int room_b, double tol) {
  const Ring& ra = layout.rooms[room_a].polygon;
  const Ring& rb = layout.rooms[room_b].polygon;
  std::vector<Stretch> out;
  if (layout.rooms[room_a].level != layout.rooms[room_b].level) return out;
  for (std::size_t i = 0; i < ra.size(); ++i) {
    const Point& a = ra[i];
    const Point& b = ra[(i + 1) % ra.size()];
    for (std::size_t j = 0; j < rb.size(); ++j)
      if (auto overlap = Overlap(a, b, rb[j], rb[(j + 1) % rb.size()], tol))
        out.push_back({{At(a, b, overlap->first), At(a, b, overlap->second)}});
  }
  return out;
}

std::vector<int> RoomsHolding(const Layout& layout, const Element& element, double tol) {
  std::vector<int> out;
  for (int i = 0; i < static_cast<int>(layout.rooms.size()); ++i)
    if (element.OnLevel(layout.rooms[i].level) && SegmentOnRing(element.shape, layout.rooms[i].polygon, tol))
      out.push_back(i);
  return out;
}

Point Centroid(const Ring& ring) {
  double a = 0, cx = 0, cy = 0;
  std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point& p = ring[i];
    const Point& q = ring[(i + 1) % n];
    double c = p.x * q.y - q.x * p.y;
    a += c;
    cx += (p.x + q.x) * c;
    cy += (p.y + q.y) * c;
  }
  if (std::abs(a) < 1e-12) {
    Point mean;
    for (const Point& p : ring) mean = {mean.x + p.x / n, mean.y + p.y / n};
    return mean;
  }
  return {cx / (3 * a), cy / (3 * a)};
}

bool PointInRing(const Point& point, const Ring& ring, double tol) {
  std::size_t n = ring.size();
  bool inside = false;
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point& a = ring[i];
    const Point& b = ring[j];
    // On the outline?
    double len = std::hypot(b.x - a.x, b.y - a.y);
    if (len > 0 && LineDistance(point, a, b) <= tol) {
      double t = Along(point, a, b);
      if (t >= -tol && t <= len + tol) return true;
    }
    if ((a.y > point.y) != (b.y > point.y)) {
      double x = a.x + (point.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (point.x < x) inside = !inside;
    }
  }
  return inside;
}

Bounds LevelBounds(const Layout& layout, int level) {
  Bounds b{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
           std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest()};
  bool any = false;
  for (const Room& room : layout.rooms) {
    if (room.level != level) continue;
    for (const Point& p : room.polygon) {
      any = true;
      b.min_x = std::min(b.min_x, p.x);
      b.min_y = std::min(b.min_y, p.y);
      b.max_x = std::max(b.max_x, p.x);
      b.max_y = std::max(b.max_y, p.y);
    }
  }
  return any ? b : Bounds{};
}

Bounds LayoutBounds(const Layout& layout) {
  Bounds b = LevelBounds(layout, 0);
  for (int level = 1; level < layout.LevelCount(); ++level) {
    Bounds l = LevelBounds(layout, level);
    b.min_x = std::min(b.min_x, l.min_x);
    b.min_y = std::min(b.min_y, l.min_y);
    b.max_x = std::max(b.max_x, l.max_x);
    b.max_y = std::max(b.max_y, l.max_y);
  }
  return b;
}

}  // namespace villa::annotator
