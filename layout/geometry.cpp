#include "layout/geometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <boost/geometry.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>

namespace villa {
namespace {

namespace bg = boost::geometry;
using BgPoint = bg::model::d2::point_xy<double>;
using BgPolygon = bg::model::polygon<BgPoint, /*clockwise=*/false, /*closed=*/false>;
using BgMultiPolygon = bg::model::multi_polygon<BgPolygon>;

double Cross(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }
double Len(const Segment& s) { return std::sqrt((s.b.x - s.a.x) * (s.b.x - s.a.x) + (s.b.y - s.a.y) * (s.b.y - s.a.y)); }

// A segment as origin, unit direction and length: computed once, tested against many edges.
struct Frame {
  double ax = 0, ay = 0, ux = 0, uy = 0, len = 0;
  explicit Frame(const Segment& s) : ax(s.a.x), ay(s.a.y), len(Len(s)) {
    if (len > 0) ux = (s.b.x - s.a.x) / len, uy = (s.b.y - s.a.y) / len;
  }
};

// The part of the frame's segment on the edge ea-eb, as an arc-length interval (see CollinearOverlap).
inline bool Overlap(const Frame& f, const Point& ea, const Point& eb, double tolerance, Interval* out) {
  if (f.len <= tolerance) return false;
  double h1 = f.ux * (ea.y - f.ay) - f.uy * (ea.x - f.ax);
  double h2 = f.ux * (eb.y - f.ay) - f.uy * (eb.x - f.ax);
  if ((h1 > tolerance && h2 > tolerance) || (h1 < -tolerance && h2 < -tolerance)) return false;  // off to one side
  double ex = eb.x - ea.x, ey = eb.y - ea.y;
  if (ex * ex + ey * ey <= tolerance * tolerance) return false;
  double t1 = (ea.x - f.ax) * f.ux + (ea.y - f.ay) * f.uy;
  double t2 = (eb.x - f.ax) * f.ux + (eb.y - f.ay) * f.uy;
  double from = std::max(0.0, std::min(t1, t2)), to = std::min(f.len, std::max(t1, t2));
  if (to - from <= tolerance) return false;
  // Offsets across the segment at both ends of the overlap (linear along the edge).
  auto across = [&](double t) { return t1 == t2 ? h1 : h1 + (h2 - h1) * (t - t1) / (t2 - t1); };
  if (std::abs(across(from)) > tolerance || std::abs(across(to)) > tolerance) return false;
  *out = {from, to};
  return true;
}

// The ring counter-clockwise (a copy reversed when it was given clockwise).
Ring Ccw(const Ring& ring) {
  if (SignedArea(ring) >= 0) return ring;
  return Ring(ring.rbegin(), ring.rend());
}

BgPolygon ToBoost(const Ring& ring) {
  BgPolygon polygon;
  for (const auto& p : Ccw(ring)) polygon.outer().emplace_back(p.x, p.y);
  return polygon;
}

Ring FromBoost(const bg::model::ring<BgPoint, false, false>& ring) {
  Ring out;
  out.reserve(ring.size());
  for (const auto& p : ring) out.push_back({p.x(), p.y()});
  return out;
}

// Convex polygon clipping (Sutherland-Hodgman): `subject` clipped by the convex CCW `clip`.
Ring ClipConvex(const Ring& subject, const Ring& clip) {
  Ring output = subject;
  for (std::size_t i = 0; i < clip.size() && !output.empty(); ++i) {
    const Point& a = clip[i];
    const Point& b = clip[(i + 1) % clip.size()];
    auto side = [&](const Point& p) { return Cross(b.x - a.x, b.y - a.y, p.x - a.x, p.y - a.y); };
    Ring input;
    input.swap(output);
    for (std::size_t j = 0; j < input.size(); ++j) {
      const Point& p = input[j];
      const Point& q = input[(j + 1) % input.size()];
      double sp = side(p), sq = side(q);
      if (sp >= 0) output.push_back(p);
      if ((sp >= 0) != (sq >= 0)) {
        double t = sp / (sp - sq);
        output.push_back({p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)});
      }
    }
  }
  return output;
}

// Convex hull (Andrew's monotone chain), counter-clockwise, no collinear points.
Ring ConvexHull(Ring points) {
  std::sort(points.begin(), points.end(), [](const Point& a, const Point& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  if (points.size() < 3) return points;
  Ring hull(2 * points.size());
  std::size_t k = 0;
  auto turn = [](const Point& o, const Point& a, const Point& b) { return Cross(a.x - o.x, a.y - o.y, b.x - o.x, b.y - o.y); };
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && turn(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && turn(hull[k - 2], hull[k - 1], points[i - 1]) <= 0) --k;
    hull[k++] = points[i - 1];
  }
  hull.resize(k - 1);
  return hull;
}

// Orientation of r against the line p->q: +1 left, -1 right, 0 on it.
int Orientation(const Point& p, const Point& q, const Point& r) {
  double c = Cross(q.x - p.x, q.y - p.y, r.x - p.x, r.y - p.y);
  return c > 0 ? 1 : c < 0 ? -1 : 0;
}

bool OnSegment(const Point& p, const Point& a, const Point& b) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}

// Closed segments ab and cd share a point.
bool SegmentsMeet(const Point& a, const Point& b, const Point& c, const Point& d) {
  int o1 = Orientation(a, b, c), o2 = Orientation(a, b, d), o3 = Orientation(c, d, a), o4 = Orientation(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;  // a proper crossing
  return (o1 == 0 && OnSegment(c, a, b)) || (o2 == 0 && OnSegment(d, a, b)) || (o3 == 0 && OnSegment(a, c, d)) ||
         (o4 == 0 && OnSegment(b, c, d));
}

// Edges meet only at the corners they share, and no corner folds back on itself.
bool IsSimpleRing(const Ring& ring) {
  const std::size_t n = ring.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const Point& a = ring[i];
    const Point& b = ring[(i + 1) % n];
    const Point& c = ring[(i + 2) % n];
    if (a == b) return false;
    double cross = Cross(b.x - a.x, b.y - a.y, c.x - b.x, c.y - b.y);
    if (cross == 0 && (b.x - a.x) * (c.x - b.x) + (b.y - a.y) * (c.y - b.y) < 0) return false;  // a spike
  }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // adjacent through the closing corner
      if (SegmentsMeet(ring[i], ring[(i + 1) % n], ring[j], ring[(j + 1) % n])) return false;
    }
  return true;
}

}  // namespace

Box2 BoundingBox(const Ring& ring) {
  Box2 box{INFINITY, INFINITY, -INFINITY, -INFINITY};
  for (const auto& p : ring) {
    box.min_x = std::min(box.min_x, p.x), box.max_x = std::max(box.max_x, p.x);
    box.min_y = std::min(box.min_y, p.y), box.max_y = std::max(box.max_y, p.y);
  }
  return box;
}

Box2 BoundingBox(const Segment& s) {
  return {std::min(s.a.x, s.b.x), std::min(s.a.y, s.b.y), std::max(s.a.x, s.b.x), std::max(s.a.y, s.b.y)};
}

namespace {
Box2 RoomsBounds(const Layout& layout, int level) {
  Box2 box{INFINITY, INFINITY, -INFINITY, -INFINITY};
  bool any = false;
  for (const Room& room : layout.rooms) {
    if (level != kAllLevels && room.level != level) continue;
    for (const Point& p : room.polygon) {
      any = true;
      box.min_x = std::min(box.min_x, p.x), box.max_x = std::max(box.max_x, p.x);
      box.min_y = std::min(box.min_y, p.y), box.max_y = std::max(box.max_y, p.y);
    }
  }
  return any ? box : Box2{};
}
}  // namespace

Box2 LevelBounds(const Layout& layout, int level) { return RoomsBounds(layout, level); }
Box2 LayoutBounds(const Layout& layout) { return RoomsBounds(layout, kAllLevels); }

double Distance(const Point& a, const Point& b) { return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y)); }

double PointSegmentDistance(const Point& p, const Segment& s) {
  double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
  double len2 = dx * dx + dy * dy;
  if (len2 == 0) return Distance(p, s.a);
  double t = std::clamp(((p.x - s.a.x) * dx + (p.y - s.a.y) * dy) / len2, 0.0, 1.0);
  return Distance(p, {s.a.x + t * dx, s.a.y + t * dy});
}

double SegmentOffDistance(const Segment& s, const Segment& target) {
  // The distance to a convex set is convex along s, so its maximum is at an endpoint.
  return std::max(PointSegmentDistance(s.a, target), PointSegmentDistance(s.b, target));
}

std::vector<Interval> MergeIntervals(std::vector<Interval> intervals, double tolerance) {
  std::sort(intervals.begin(), intervals.end());
  std::vector<Interval> merged;
  for (const auto& iv : intervals) {
    if (!merged.empty() && iv.first <= merged.back().second + tolerance)
      merged.back().second = std::max(merged.back().second, iv.second);
    else
      merged.push_back(iv);
  }
  std::erase_if(merged, [&](const Interval& iv) { return iv.second - iv.first <= tolerance; });
  return merged;
}

double TotalLength(const std::vector<Interval>& intervals) {
  double total = 0;
  for (const auto& iv : intervals) total += iv.second - iv.first;
  return total;
}

std::vector<Interval> IntersectIntervals(const std::vector<Interval>& a, const std::vector<Interval>& b, double tolerance) {
  std::vector<Interval> out;
  for (const auto& x : a)
    for (const auto& y : b) {
      double from = std::max(x.first, y.first), to = std::min(x.second, y.second);
      if (to - from > tolerance) out.push_back({from, to});
    }
  return MergeIntervals(std::move(out), tolerance);
}

std::vector<Interval> ComplementIntervals(const std::vector<Interval>& covered, double length, double tolerance) {
  std::vector<Interval> gaps;
  double at = 0.0;
  for (const Interval& iv : covered) {
    if (iv.first - at > tolerance) gaps.push_back({at, iv.first});
    at = std::max(at, iv.second);
  }
  if (length - at > tolerance) gaps.push_back({at, length});
  return gaps;
}

Point PointAt(const Segment& s, double t) {
  double len = Len(s);
  if (len == 0) return s.a;
  double f = t / len;
  return {s.a.x + f * (s.b.x - s.a.x), s.a.y + f * (s.b.y - s.a.y)};
}

bool CollinearOverlapInterval(const Segment& s, const Segment& edge, double tolerance, Interval* out) {
  return Overlap(Frame(s), edge.a, edge.b, tolerance, out);
}

std::vector<Interval> IntervalsOnSegments(const Segment& s, const std::vector<Segment>& segments, double tolerance) {
  std::vector<Interval> found;
  const Frame frame(s);
  for (const Segment& other : segments) {
    Interval iv;
    if (Overlap(frame, other.a, other.b, tolerance, &iv)) found.push_back(iv);
  }
  return MergeIntervals(std::move(found), tolerance);
}

bool SegmentsCover(const std::vector<Segment>& segments, const Segment& s, double tolerance) {
  const double length = Length(s);
  if (length <= tolerance) return false;
  const std::vector<Interval> on = IntervalsOnSegments(s, segments, tolerance);
  return on.size() == 1 && on[0].first <= tolerance && on[0].second >= length - tolerance;
}

Segment SubSegment(const Segment& s, const Interval& along) { return {PointAt(s, along.first), PointAt(s, along.second)}; }

std::vector<Interval> CollinearOverlap(const Segment& s, const Segment& edge, double tolerance) {
  Interval iv;
  if (!CollinearOverlapInterval(s, edge, tolerance, &iv)) return {};
  return {iv};
}

namespace {
// Appends (unmerged) the parts of s on the ring's edges.
void AppendIntervalsOnBoundary(const Segment& s, const Ring& ring, double tolerance, std::vector<Interval>& out) {
  Box2 sb = BoundingBox(s);
  Frame frame(s);
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point& a = ring[i];
    const Point& b = ring[i + 1 == n ? 0 : i + 1];
    if (std::max(a.x, b.x) < sb.min_x - tolerance || std::min(a.x, b.x) > sb.max_x + tolerance ||
        std::max(a.y, b.y) < sb.min_y - tolerance || std::min(a.y, b.y) > sb.max_y + tolerance)
      continue;
    Interval iv;
    if (Overlap(frame, a, b, tolerance, &iv)) out.push_back(iv);
  }
}
}  // namespace

std::vector<Interval> IntervalsOnBoundary(const Segment& s, const Ring& ring, double tolerance) {
  std::vector<Interval> all;
  AppendIntervalsOnBoundary(s, ring, tolerance, all);
  return MergeIntervals(std::move(all), tolerance);
}

double LengthOnBoundary(const Segment& s, const Ring& ring, double tolerance) {
  // Without allocating: the ring's edges do not overlap one another, so at most one interval an edge;
  // sort the few intervals in place and add up their union.
  Interval buffer[64];
  std::vector<Interval> spill;
  int n = 0;
  Box2 sb = BoundingBox(s);
  Frame frame(s);
  const std::size_t count = ring.size();
  for (std::size_t i = 0; i < count; ++i) {
    const Point& a = ring[i];
    const Point& b = ring[i + 1 == count ? 0 : i + 1];
    if (std::max(a.x, b.x) < sb.min_x - tolerance || std::min(a.x, b.x) > sb.max_x + tolerance ||
        std::max(a.y, b.y) < sb.min_y - tolerance || std::min(a.y, b.y) > sb.max_y + tolerance)
      continue;
    Interval iv;
    if (!Overlap(frame, a, b, tolerance, &iv)) continue;
    if (n < 64) buffer[n++] = iv;
    else spill.push_back(iv);
  }
  if (!spill.empty()) {
    spill.insert(spill.end(), buffer, buffer + n);
    return TotalLength(MergeIntervals(std::move(spill), tolerance));
  }
  std::sort(buffer, buffer + n);
  double total = 0, from = 0, to = -INFINITY;
  for (int i = 0; i < n; ++i) {
    if (buffer[i].first <= to + tolerance) {
      to = std::max(to, buffer[i].second);
      continue;
    }
    if (to - from > tolerance) total += to - from;
    from = buffer[i].first, to = buffer[i].second;
  }
  if (to - from > tolerance) total += to - from;
  return total;
}

bool RingHoldsSegment(const Ring& ring, const Segment& s, double tolerance) {
  const double on = LengthOnBoundary(s, ring, tolerance);
  return on > tolerance && on >= Length(s) - tolerance;
}

std::vector<Segment> SharedBoundaries(const Ring& a, const Ring& b, double tolerance) {
  std::vector<Segment> out;
  if (!BoundingBox(a).Touches(BoundingBox(b), tolerance)) return out;
  std::vector<Interval> found;
  for (std::size_t i = 0; i < a.size(); ++i) {
    Segment edge{a[i], a[(i + 1) % a.size()]};
    found.clear();
    AppendIntervalsOnBoundary(edge, b, tolerance, found);
    if (found.size() > 1) found = MergeIntervals(std::move(found), tolerance);
    for (const auto& iv : found) out.push_back({PointAt(edge, iv.first), PointAt(edge, iv.second)});
  }
  return out;
}

double SharedBoundaryLength(const Ring& a, const Ring& b, double tolerance) {
  double total = 0;
  for (const auto& s : SharedBoundaries(a, b, tolerance)) total += Length(s);
  return total;
}

Point Centroid(const Ring& ring) {
  double a = 0, cx = 0, cy = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point& p = ring[i];
    const Point& q = ring[(i + 1) % ring.size()];
    double c = Cross(p.x, p.y, q.x, q.y);
    a += c, cx += (p.x + q.x) * c, cy += (p.y + q.y) * c;
  }
  if (a == 0) {
    Point m;
    for (const auto& p : ring) m.x += p.x / ring.size(), m.y += p.y / ring.size();
    return m;
  }
  return {cx / (3 * a), cy / (3 * a)};
}

bool IsConvex(const Ring& input) {
  const std::size_t n = input.size();
  if (n < 3) return false;
  const bool ccw = SignedArea(input) >= 0;
  auto at = [&](std::size_t i) -> const Point& { return ccw ? input[i % n] : input[n - 1 - i % n]; };
  // Quadrant of a direction: 0 (x > 0, y >= 0), 1 (x <= 0, y > 0), 2 (x < 0, y <= 0), 3 (x >= 0, y < 0).
  auto quadrant = [](double x, double y) { return x > 0 && y >= 0 ? 0 : x <= 0 && y > 0 ? 1 : x < 0 && y <= 0 ? 2 : 3; };
  int steps = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Point& p = at(i);
    const Point& q = at(i + 1);
    const Point& r = at(i + 2);
    double ax = q.x - p.x, ay = q.y - p.y, bx = r.x - q.x, by = r.y - q.y;
    if ((ax == 0 && ay == 0) || (bx == 0 && by == 0)) return false;
    double c = Cross(ax, ay, bx, by);
    if (c < 0 || (c == 0 && ax * bx + ay * by < 0)) return false;  // a reflex corner or a spike
    // Each left turn is under 180 degrees, so the quadrant moves on by (difference mod 4) quarter turns.
    steps += (quadrant(bx, by) - quadrant(ax, ay) + 4) % 4;
  }
  return steps == 4;  // the directions go round exactly once (a star goes round twice)
}

bool IsAxisAlignedBox(const Ring& ring, double tolerance) {
  if (ring.size() != 4) return false;
  for (std::size_t i = 0; i < 4; ++i) {
    const Point& p = ring[i];
    const Point& q = ring[(i + 1) % 4];
    bool horizontal = std::abs(p.y - q.y) <= tolerance, vertical = std::abs(p.x - q.x) <= tolerance;
    if (horizontal == vertical) return false;
    const Point& r = ring[(i + 2) % 4];
    bool next_horizontal = std::abs(q.y - r.y) <= tolerance;
    if (horizontal == next_horizontal) return false;
  }
  return true;
}

Ring WithoutCollinearCorners(const Ring& ring, double tolerance) {
  Ring out;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point& prev = ring[(i + n - 1) % n];
    const Point& p = ring[i];
    const Point& next = ring[(i + 1) % n];
    Segment chord{prev, next};
    double ax = p.x - prev.x, ay = p.y - prev.y, bx = next.x - p.x, by = next.y - p.y;
    bool straight = ax * bx + ay * by > 0 && PointSegmentDistance(p, chord) <= tolerance;
    if (!straight) out.push_back(p);
  }
  return out.size() >= 3 ? out : ring;
}

bool SameRing(const Ring& a_in, const Ring& b_in, double tolerance) {
  Ring a = WithoutCollinearCorners(Ccw(a_in), tolerance), b = WithoutCollinearCorners(Ccw(b_in), tolerance);
  if (a.size() != b.size() || a.empty()) return false;
  const std::size_t n = a.size();
  for (std::size_t shift = 0; shift < n; ++shift) {
    bool all = true;
    for (std::size_t i = 0; i < n && all; ++i) all = Distance(a[i], b[(i + shift) % n]) <= tolerance;
    if (all) return true;
  }
  return false;
}

bool PointInRing(const Point& p, const Ring& ring, double tolerance) {
  bool inside = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Point& a = ring[i];
    const Point& b = ring[j];
    if (tolerance > 0 && PointSegmentDistance(p, {a, b}) <= tolerance) return true;
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
  }
  return inside;
}

bool PointOnBoundary(const Point& p, const Ring& ring, double tolerance) {
  for (std::size_t i = 0; i < ring.size(); ++i)
    if (PointSegmentDistance(p, {ring[i], ring[(i + 1) % ring.size()]}) <= tolerance) return true;
  return false;
}

double DistanceToBoundary(const Point& p, const Ring& ring) {
  double best = INFINITY;
  for (std::size_t i = 0; i < ring.size(); ++i)
    best = std::min(best, PointSegmentDistance(p, {ring[i], ring[(i + 1) % ring.size()]}));
  return best;
}

std::string RingProblem(const Ring& ring) {
  if (ring.size() < 3) return "has fewer than 3 corners";
  // Fast path: a convex ring without repeated points or spikes, turning once, is valid; so is a ring whose
  // edges meet only at their shared corners. Anything else goes to Boost.Geometry for the verdict and why.
  if (IsConvex(ring)) return Area(ring) > 0 ? "" : "has zero area";
  if (IsSimpleRing(ring) && Area(ring) > 0) return "";
  BgPolygon polygon = ToBoost(ring);
  std::string message;
  if (!bg::is_valid(polygon, message)) return message;
  if (Area(ring) <= 0) return "has zero area";
  return "";
}

double IntersectionArea(const Ring& a, const Ring& b) {
  Box2 ba = BoundingBox(a), bb = BoundingBox(b);
  double w = std::min(ba.max_x, bb.max_x) - std::max(ba.min_x, bb.min_x);
  double h = std::min(ba.max_y, bb.max_y) - std::max(ba.min_y, bb.min_y);
  if (w <= 0 || h <= 0) return 0;
  if (IsAxisAlignedBox(a, 0) && IsAxisAlignedBox(b, 0)) return w * h;
  // Sutherland-Hodgman needs only the clipping polygon convex; the subject may be any simple polygon
  // (the result may carry zero-width bridges, which add no area).
  if (IsConvex(b)) {
    Ring clipped = ClipConvex(Ccw(a), Ccw(b));
    return clipped.size() >= 3 ? std::abs(SignedArea(clipped)) : 0;
  }
  if (IsConvex(a)) {
    Ring clipped = ClipConvex(Ccw(b), Ccw(a));
    return clipped.size() >= 3 ? std::abs(SignedArea(clipped)) : 0;
  }
  // Two non-convex rooms: the signed fan decomposition. A ring's indicator function is the signed sum of
  // its fan triangles (o, p_i, p_i+1) from any origin o (a.e.), so the overlap is the signed sum of the
  // overlaps of triangle pairs, each a convex clip. Plain doubles without Boost's rescaling, whose error
  // (about 1e-6 m2, depending on vertex order) made exactly touching rooms look overlapping.
  auto fan = [](const Ring& ring) {
    std::vector<std::pair<Ring, double>> triangles;  // counter-clockwise triangle, sign
    for (std::size_t i = 1; i + 1 < ring.size(); ++i) {
      Ring t{ring[0], ring[i], ring[i + 1]};
      double area = SignedArea(t);
      if (std::abs(area) < 1e-15) continue;
      if (area < 0) std::swap(t[1], t[2]);
      triangles.push_back({std::move(t), area < 0 ? -1.0 : 1.0});
    }
    return triangles;
  };
  auto fan_a = fan(a), fan_b = fan(b);
  double total = 0;
  for (const auto& [ta, sa] : fan_a) {
    Box2 box_a = BoundingBox(ta);
    for (const auto& [tb, sb] : fan_b) {
      Box2 box_b = BoundingBox(tb);
      if (box_a.max_x <= box_b.min_x || box_b.max_x <= box_a.min_x || box_a.max_y <= box_b.min_y || box_b.max_y <= box_a.min_y) continue;
      Ring clipped = ClipConvex(ta, tb);
      if (clipped.size() >= 3) total += sa * sb * std::abs(SignedArea(clipped));
    }
  }
  return std::max(0.0, total);
}

std::vector<PolygonWithHoles> UnionOfRings(const std::vector<Ring>& rings) {
  BgMultiPolygon acc;
  for (const auto& ring : rings) {
    if (ring.size() < 3) continue;
    BgMultiPolygon next;
    try {
      bg::union_(acc, ToBoost(ring), next);
    } catch (const std::exception&) {
      continue;  // an invalid ring (see RingProblem) is left out rather than taking the process down
    }
    acc.swap(next);
  }
  std::vector<PolygonWithHoles> out;
  for (const auto& polygon : acc) {
    PolygonWithHoles p;
    p.outer = FromBoost(polygon.outer());
    for (const auto& inner : polygon.inners()) p.holes.push_back(Ccw(FromBoost(inner)));
    out.push_back(std::move(p));
  }
  return out;
}

namespace {
// Chains directed exterior pieces into rings. At a vertex where several pieces start (a hole or a separate
// piece touching at a point), kKeepHolesApart takes the first one counter-clockwise from the way back: the
// ring keeps the same outside region on its right, so a hole touching the outline still comes out as its
// own ring; kKeepRegionsApart takes the last one (the sharpest left turn) among those not used yet.
// False when some piece has no continuation.
bool ChainRings(const std::vector<Segment>& pieces, const std::vector<int>& owners, double tolerance, PinchRule pinch,
                std::vector<BoundaryRing>& rings) {
  const std::size_t n = pieces.size();
  const double match = 4 * tolerance;
  bool closed = true;
  std::vector<bool> used(n, false);
  for (std::size_t start = 0; start < n; ++start) {
    if (used[start]) continue;
    BoundaryRing ring;
    std::size_t current = start;
    while (true) {
      used[current] = true;
      const Segment& s = pieces[current];
      ring.pieces.push_back(s);
      ring.owners.push_back(owners[current]);
      ring.signed_area += Cross(s.a.x, s.a.y, s.b.x, s.b.y) / 2;
      double bx = s.a.x - s.b.x, by = s.a.y - s.b.y;  // the way back
      std::size_t best = n;
      double best_angle = 0;
      for (std::size_t k = 0; k < n; ++k) {
        const Segment& c = pieces[k];
        double gx = c.a.x - s.b.x, gy = c.a.y - s.b.y;
        if (gx * gx + gy * gy > match * match) continue;
        double dx = c.b.x - c.a.x, dy = c.b.y - c.a.y;
        double ccw = std::atan2(Cross(bx, by, dx, dy), bx * dx + by * dy);
        if (ccw <= 0) ccw += 2 * std::numbers::pi;
        if (pinch == PinchRule::kKeepHolesApart) {
          if (best == n || ccw < best_angle) best = k, best_angle = ccw;
        } else if ((!used[k] || k == start) && (best == n || ccw > best_angle)) {
          best = k, best_angle = ccw;
        }
      }
      if (best == start) break;
      if (best == n || used[best]) {
        closed = false;
        break;
      }
      current = best;
    }
    rings.push_back(std::move(ring));
  }
  return closed;
}
}  // namespace

ExteriorBoundary ExteriorBoundaryOf(const std::vector<Ring>& input, double tolerance, const std::vector<bool>& subtract,
                                    PinchRule pinch) {
  ExteriorBoundary result;
  std::vector<Ring> reversed;  // copies only of rings given clockwise
  reversed.reserve(input.size());
  std::vector<const Ring*> rooms;
  std::vector<Box2> boxes;
  for (const auto& r : input) {
    if (SignedArea(r) < 0) reversed.push_back(Ring(r.rbegin(), r.rend())), rooms.push_back(&reversed.back());
    else rooms.push_back(&r);
    boxes.push_back(BoundingBox(r));
  }

  // 1. Every edge part not covered by another room's edge.
  std::vector<Interval> covered;
  std::vector<double> cuts;
  for (std::size_t i = 0; i < rooms.size(); ++i) {
    const Ring& ring = *rooms[i];
    for (std::size_t e = 0; e < ring.size(); ++e) {
      Segment edge{ring[e], ring[(e + 1) % ring.size()]};
      double len = Len(edge);
      if (len <= tolerance) continue;
      Box2 eb = BoundingBox(edge);
      covered.clear();
      cuts.clear();
      Frame frame(edge);
      for (std::size_t j = 0; j < rooms.size(); ++j) {
        if (j == i || !boxes[j].Touches(eb, tolerance)) continue;
        AppendIntervalsOnBoundary(edge, *rooms[j], tolerance, covered);
        // Corners of room j inside this edge: where j only touches the outline at a point, the outline
        // must be cut there so that a hole closed off by that touch comes out as its own ring.
        for (const Point& v : *rooms[j]) {
          double t = (v.x - frame.ax) * frame.ux + (v.y - frame.ay) * frame.uy;
          if (t <= tolerance || t >= len - tolerance) continue;
          if (std::abs(frame.ux * (v.y - frame.ay) - frame.uy * (v.x - frame.ax)) <= tolerance) cuts.push_back(t);
        }
      }
      if (covered.size() > 1) covered = MergeIntervals(std::move(covered), tolerance);
      if (cuts.size() > 1) std::sort(cuts.begin(), cuts.end());
      double at = 0;
      auto emit_piece = [&](double from, double to) {
        if (to - from <= tolerance) return;
        Point a = from == 0 ? edge.a : PointAt(edge, from);
        Point b = to == len ? edge.b : PointAt(edge, to);
        result.pieces.push_back({a, b});
        result.owners.push_back(static_cast<int>(i));
      };
      auto emit = [&](double from, double to) {
        for (double t : cuts)
          if (t > from + tolerance && t < to - tolerance) emit_piece(from, t), from = t;
        emit_piece(from, to);
      };
      for (const auto& iv : covered) emit(at, iv.first), at = std::max(at, iv.second);
      emit(at, len);
    }
  }

  // 2. Chain the pieces into rings, those of subtracted rings turned round.
  for (std::size_t k = 0; k < result.pieces.size(); ++k)
    if (static_cast<std::size_t>(result.owners[k]) < subtract.size() && subtract[result.owners[k]])
      std::swap(result.pieces[k].a, result.pieces[k].b);
  result.closed = ChainRings(result.pieces, result.owners, tolerance, pinch, result.rings);
  return result;
}

double RoomWidth(const Ring& input, double tolerance) {
  const std::size_t n = input.size();
  if (n < 3) return 0;
  Ring reversed;
  if (SignedArea(input) < 0) reversed.assign(input.rbegin(), input.rend());
  const Ring& ring = reversed.empty() ? input : reversed;
  const bool convex = IsConvex(ring);
  // Minimum caliper width of the convex hull (the ring itself when convex).
  Ring computed_hull;
  if (!convex) computed_hull = ConvexHull(ring);
  const Ring& hull = convex ? ring : computed_hull;
  double width = INFINITY;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Point& a = hull[i];
    const Point& b = hull[(i + 1) % hull.size()];
    double len = Distance(a, b);
    if (len <= 0) continue;
    double far = 0;
    for (const auto& p : hull) far = std::max(far, std::abs(Cross(b.x - a.x, b.y - a.y, p.x - a.x, p.y - a.y)) / len);
    width = std::min(width, far);
  }
  if (hull.size() < 3) return 0;
  if (convex) return width;
  // Thin arms: facing anti-parallel edges with overlapping projections.
  const double cos_limit = std::cos(std::numbers::pi / 180);
  for (std::size_t i = 0; i < n; ++i) {
    Segment e{ring[i], ring[(i + 1) % n]};
    double le = Length(e);
    if (le <= tolerance) continue;
    double ux = (e.b.x - e.a.x) / le, uy = (e.b.y - e.a.y) / le;
    double nx = -uy, ny = ux;  // inward normal of a counter-clockwise ring
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i) continue;
      Segment f{ring[j], ring[(j + 1) % n]};
      double lf = Length(f);
      if (lf <= tolerance) continue;
      double vx = (f.b.x - f.a.x) / lf, vy = (f.b.y - f.a.y) / lf;
      if (ux * vx + uy * vy > -cos_limit) continue;
      double t1 = (f.a.x - e.a.x) * ux + (f.a.y - e.a.y) * uy;
      double t2 = (f.b.x - e.a.x) * ux + (f.b.y - e.a.y) * uy;
      double from = std::max(0.0, std::min(t1, t2)), to = std::min(le, std::max(t1, t2));
      if (to - from <= tolerance) continue;
      double mid = (from + to) / 2;
      Point on_e{e.a.x + ux * mid, e.a.y + uy * mid};
      // Distance from e across to f's line along e's inward normal (the same all along: they are parallel).
      double gap = (f.a.x - on_e.x) * nx + (f.a.y - on_e.y) * ny;
      if (gap <= tolerance || gap >= width) continue;
      Point middle{on_e.x + nx * gap / 2, on_e.y + ny * gap / 2};
      if (PointInRing(middle, ring, 0)) width = gap;
    }
  }
  return width;
}

std::pair<double, double> RectangleSides(const Ring& input, double tolerance) {
  Ring r = WithoutCollinearCorners(Ccw(input), tolerance);
  if (r.size() != 4) return {0, 0};
  double s[4];
  for (int i = 0; i < 4; ++i) {
    const Point& p = r[i];
    const Point& q = r[(i + 1) % 4];
    const Point& t = r[(i + 2) % 4];
    s[i] = Distance(p, q);
    double dot = (q.x - p.x) * (t.x - q.x) + (q.y - p.y) * (t.y - q.y);
    if (std::abs(dot) > tolerance * (s[i] + Distance(q, t))) return {0, 0};
  }
  if (std::abs(s[0] - s[2]) > tolerance || std::abs(s[1] - s[3]) > tolerance) return {0, 0};
  return {s[0], s[1]};
}

}  // namespace villa
