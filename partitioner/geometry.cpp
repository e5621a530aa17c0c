#include "partitioner/geometry.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <tuple>
#include <utility>

#include "layout/geometry.h"

namespace villa::partition {
namespace {

int Sign(int64_t v) { return (v > 0) - (v < 0); }

// p on the closed segment [a, b]?
bool OnSegment(IPoint a, IPoint b, IPoint p) {
  if (Cross(a, b, p) != 0) return false;
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

bool SegmentsTouch(IPoint a, IPoint b, IPoint c, IPoint d) {
  int d1 = Sign(Cross(a, b, c)), d2 = Sign(Cross(a, b, d));
  int d3 = Sign(Cross(c, d, a)), d4 = Sign(Cross(c, d, b));
  if (d1 * d2 < 0 && d3 * d4 < 0) return true;
  return (d1 == 0 && OnSegment(a, b, c)) || (d2 == 0 && OnSegment(a, b, d)) || (d3 == 0 && OnSegment(c, d, a)) ||
         (d4 == 0 && OnSegment(c, d, b));
}

// Rotation by +90 degrees and back: a horizontal split is a vertical split of the rotated ring.
IPoint RotateCcw(IPoint p) { return {-p.y, p.x}; }
IPoint RotateCw(IPoint p) { return {p.y, -p.x}; }

// The turn angle of (dot, cross), in (-pi, pi] as atan2(cross, dot) gives it, compared exactly: true when a's
// angle is greater than b's (a turns further counter-clockwise).
int TurnHalf(IPoint t) { return t.y < 0 ? 0 : (t.y == 0 && t.x > 0 ? 1 : (t.y > 0 ? 2 : 3)); }
bool TurnsMoreLeft(IPoint a, IPoint b) {
  const int ha = TurnHalf(a), hb = TurnHalf(b);
  if (ha != hb) return ha > hb;
  if (ha == 1 || ha == 3) return false;  // the same direction
  return b.x * a.y - b.y * a.x > 0;     // a counter-clockwise of b within the same open half-plane
}

struct DirectedEdge {
  IPoint a, b;
  bool used = false;
};

// Joins directed edges (every vertex with equal in- and out-degree) into closed loops. At a vertex with
// several ways on, the most counter-clockwise turn is taken, which separates regions touching at a point.
std::vector<IRing> AssembleLoops(std::vector<DirectedEdge>& edges) {
  std::vector<IRing> loops;
  // Sort by start point for lookup.
  // A total order (start, then end point), so the loops come out the same with any sort algorithm.
  std::sort(edges.begin(), edges.end(), [](const DirectedEdge& l, const DirectedEdge& r) {
    if (l.a.x != r.a.x) return l.a.x < r.a.x;
    if (l.a.y != r.a.y) return l.a.y < r.a.y;
    if (l.b.x != r.b.x) return l.b.x < r.b.x;
    return l.b.y < r.b.y;
  });
  auto range = [&](IPoint p) {
    auto lo = std::lower_bound(edges.begin(), edges.end(), p, [](const DirectedEdge& e, IPoint q) {
      return e.a.x != q.x ? e.a.x < q.x : e.a.y < q.y;
    });
    auto hi = lo;
    while (hi != edges.end() && hi->a == p) ++hi;
    return std::make_pair(lo - edges.begin(), hi - edges.begin());
  };
  for (std::size_t s = 0; s < edges.size(); ++s) {
    if (edges[s].used) continue;
    edges[s].used = true;
    IRing loop{edges[s].a};
    IPoint prev = edges[s].a, cur = edges[s].b;
    std::size_t guard = 0;
    while (true) {
      if (++guard > edges.size() + 2) break;  // malformed input: give up on this loop
      auto [lo, hi] = range(cur);
      long best = -1;
      IPoint best_turn{0, 0};  // (dot, cross) of the incoming direction with the best outgoing edge
      const IPoint in{cur.x - prev.x, cur.y - prev.y};
      for (long i = lo; i < hi; ++i) {
        const bool is_start = static_cast<std::size_t>(i) == s;
        if (edges[i].used && !is_start) continue;
        const IPoint out{edges[i].b.x - cur.x, edges[i].b.y - cur.y};
        const IPoint turn{in.x * out.x + in.y * out.y, in.x * out.y - in.y * out.x};
        if (best < 0 || TurnsMoreLeft(turn, best_turn)) {
          best_turn = turn;
          best = i;
        }
      }
      if (best < 0) break;
      if (static_cast<std::size_t>(best) == s) break;  // closed
      edges[best].used = true;
      loop.push_back(cur);
      prev = cur;
      cur = edges[best].b;
    }
    IRing normalized = Normalize(loop);
    if (normalized.size() >= 3 && TwiceArea(normalized) != 0) loops.push_back(std::move(normalized));
  }
  return loops;
}

bool SplitVertical(const IRing& ring, int64_t k, std::vector<IRing>* low, std::vector<IRing>* high) {
  // 1. Subdivide edges at their crossings with the line (exact grid points, or refuse).
  IRing q;
  q.reserve(ring.size() + 8);
  bool any_low = false, any_high = false;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const IPoint p = ring[i], r = ring[(i + 1) % ring.size()];
    q.push_back(p);
    any_low |= p.x < k;
    any_high |= p.x > k;
    if ((p.x - k) * (r.x - k) < 0) {
      const int64_t num = (k - p.x) * (r.y - p.y);
      const int64_t den = r.x - p.x;
      if (num % den != 0) return false;
      q.push_back({k, p.y + num / den});
    }
  }
  if (!any_high) {
    low->push_back(Normalize(ring));
    return true;
  }
  if (!any_low) {
    high->push_back(Normalize(ring));
    return true;
  }
  // 2. Edges by side; edges on the line go to the side their interior faces.
  std::vector<DirectedEdge> low_edges, high_edges;
  std::vector<int64_t> events;
  std::vector<std::pair<int64_t, int64_t>> on_line;  // y intervals covered by edges on the line
  for (std::size_t i = 0; i < q.size(); ++i) {
    const IPoint p = q[i], r = q[(i + 1) % q.size()];
    if (p.x == k) events.push_back(p.y);
    if (p.x == k && r.x == k) {
      on_line.push_back({std::min(p.y, r.y), std::max(p.y, r.y)});
      (r.y > p.y ? low_edges : high_edges).push_back({p, r});
    } else if (std::max(p.x, r.x) <= k) {
      low_edges.push_back({p, r});
    } else {
      high_edges.push_back({p, r});
    }
  }
  std::sort(events.begin(), events.end());
  events.erase(std::unique(events.begin(), events.end()), events.end());
  // 3. Intervals of the line inside the ring become boundary of both sides. The midpoint (k, (y0 + y1) / 2)
  // of an interval is tested in doubled coordinates, where it is a grid point; it is on no edge, so
  // PointInRing's crossing parity decides.
  IRing doubled;
  doubled.reserve(q.size());
  for (const IPoint& p : q) doubled.push_back({2 * p.x, 2 * p.y});
  for (std::size_t i = 0; i + 1 < events.size(); ++i) {
    const int64_t y0 = events[i], y1 = events[i + 1];
    bool covered = false;
    for (const auto& [a, b] : on_line) covered |= (a <= y0 && y1 <= b);
    if (covered) continue;
    if (PointInRing(doubled, {2 * k, y0 + y1}) <= 0) continue;
    low_edges.push_back({{k, y0}, {k, y1}});
    high_edges.push_back({{k, y1}, {k, y0}});
  }
  for (IRing& loop : AssembleLoops(low_edges)) low->push_back(std::move(loop));
  for (IRing& loop : AssembleLoops(high_edges)) high->push_back(std::move(loop));
  return true;
}

}  // namespace

int64_t Gcd(int64_t a, int64_t b) {
  a = std::llabs(a);
  b = std::llabs(b);
  while (b != 0) {
    const int64_t t = a % b;
    a = b;
    b = t;
  }
  return a;
}

int64_t TwiceArea(const IRing& ring) {
  int64_t sum = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const IPoint p = ring[i], r = ring[(i + 1) % ring.size()];
    sum += p.x * r.y - r.x * p.y;
  }
  return sum;
}

IBox BoundingBox(const IRing& ring) {
  IBox box{std::numeric_limits<int64_t>::max(), std::numeric_limits<int64_t>::max(),
           std::numeric_limits<int64_t>::min(), std::numeric_limits<int64_t>::min()};
  for (const IPoint& p : ring) {
    box.min_x = std::min(box.min_x, p.x);
    box.min_y = std::min(box.min_y, p.y);
    box.max_x = std::max(box.max_x, p.x);
    box.max_y = std::max(box.max_y, p.y);
  }
  return box;
}

IRing BoxRing(const IBox& box) {
  return {{box.min_x, box.min_y}, {box.max_x, box.min_y}, {box.max_x, box.max_y}, {box.min_x, box.max_y}};
}

IRing Normalize(const IRing& ring) {
  IRing out;
  out.reserve(ring.size());
  for (const IPoint& p : ring) {
    if (!out.empty() && out.back() == p) continue;
    out.push_back(p);
  }
  while (out.size() > 1 && out.front() == out.back()) out.pop_back();
  // Remove collinear vertices (and spikes) until none is left.
  bool changed = true;
  while (changed && out.size() >= 3) {
    changed = false;
    for (std::size_t i = 0; i < out.size() && out.size() >= 3; ++i) {
      const std::size_t n = out.size();
      const IPoint& a = out[(i + n - 1) % n];
      const IPoint& b = out[i];
      const IPoint& c = out[(i + 1) % n];
      if (Cross(a, b, c) == 0 || a == c) {
        out.erase(out.begin() + static_cast<long>(i));
        changed = true;
        --i;
      }
    }
  }
  if (out.size() < 3) out.clear();
  return out;
}

bool IsSimple(const IRing& ring) {
  const std::size_t n = ring.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const IPoint a = ring[i], b = ring[(i + 1) % n];
    if (a == b) return false;
    for (std::size_t j = i + 1; j < n; ++j) {
      const IPoint c = ring[j], d = ring[(j + 1) % n];
      const bool adjacent_next = j == i + 1;
      const bool adjacent_prev = i == 0 && j == n - 1;
      if (adjacent_next) {
        // Share b == c; they must not fold back onto each other.
        if (Cross(a, b, d) == 0 && ((d.x - b.x) * (a.x - b.x) + (d.y - b.y) * (a.y - b.y)) > 0) return false;
        continue;
      }
      if (adjacent_prev) {
        if (Cross(c, d, b) == 0 && ((b.x - a.x) * (c.x - a.x) + (b.y - a.y) * (c.y - a.y)) > 0) return false;
        continue;
      }
      if (SegmentsTouch(a, b, c, d)) return false;
    }
  }
  return true;
}

bool HasAngledEdge(const IRing& ring) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const IPoint p = ring[i], r = ring[(i + 1) % ring.size()];
    if (p.x != r.x && p.y != r.y) return true;
  }
  return false;
}

bool HasSharpCorner(const IRing& ring) {
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const IPoint a = ring[(i + n - 1) % n], b = ring[i], c = ring[(i + 1) % n];
    if (Cross(a, b, c) <= 0) continue;  // straight or reflex: at least 180 degrees inside
    const int64_t ux = a.x - b.x, uy = a.y - b.y, vx = c.x - b.x, vy = c.y - b.y;
    const int64_t dot = ux * vx + uy * vy;
    // angle < 45 degrees <=> cos > 1 / sqrt(2) <=> dot > 0 and 2 dot^2 > |u|^2 |v|^2
    if (dot > 0 && 2 * dot * dot > (ux * ux + uy * uy) * (vx * vx + vy * vy)) return true;
  }
  return false;
}

int PointInRing(const IRing& ring, IPoint point) {
  bool inside = false;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const IPoint p = ring[i], r = ring[(i + 1) % ring.size()];
    if (OnSegment(p, r, point)) return 0;
    if ((p.y > point.y) == (r.y > point.y)) continue;
    const int64_t num = (point.y - p.y) * (r.x - p.x) + (p.x - point.x) * (r.y - p.y);
    if ((r.y - p.y > 0) ? num > 0 : num < 0) inside = !inside;
  }
  return inside ? 1 : -1;
}

bool SplitIsOnGrid(const IRing& ring, Axis axis, int64_t k) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    IPoint p = ring[i], r = ring[(i + 1) % ring.size()];
    if (axis == Axis::kY) {
      p = RotateCcw(p);
      r = RotateCcw(r);
      // y = k became x = -k
    }
    const int64_t line = axis == Axis::kY ? -k : k;
    if ((p.x - line) * (r.x - line) < 0 && ((line - p.x) * (r.y - p.y)) % (r.x - p.x) != 0) return false;
  }
  return true;
}

ILine AxisLine(Axis axis, int64_t k) { return axis == Axis::kX ? ILine{1, 0, k} : ILine{0, 1, k}; }

ILine LineThrough(IPoint p, IPoint q) {
  const int64_t g = Gcd(q.x - p.x, q.y - p.y);
  ILine line{-(q.y - p.y) / g, (q.x - p.x) / g, 0};
  line.k = LineValue(line, p);
  return line;
}

std::vector<ILine> SlantedLines(const IRing& ring) {
  std::vector<ILine> out;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const IPoint a = ring[i], b = ring[(i + 1) % ring.size()];
    if (a.x != b.x && a.y != b.y) out.push_back(LineThrough(a, b));
  }
  return out;
}

namespace {
// A unimodular map M = [[a, b], [c, d]] (a*d - b*c = 1) taking the line a*x + b*y = k to x = k, and back.
struct Unimodular {
  int64_t a, b, c, d;
  IPoint Forward(IPoint p) const { return {a * p.x + b * p.y, c * p.x + d * p.y}; }
  IPoint Back(IPoint p) const { return {d * p.x - b * p.y, -c * p.x + a * p.y}; }
};
Unimodular MapToVertical(const ILine& line) {
  // Extended Euclid: s*a + t*b = 1; then (c, d) = (-t, s) gives a*d - b*c = 1.
  int64_t r0 = line.a, r1 = line.b, s0 = 1, s1 = 0, t0 = 0, t1 = 1;
  while (r1 != 0) {
    const int64_t q = r0 / r1;
    std::tie(r0, r1) = std::make_pair(r1, r0 - q * r1);
    std::tie(s0, s1) = std::make_pair(s1, s0 - q * s1);
    std::tie(t0, t1) = std::make_pair(t1, t0 - q * t1);
  }
  if (r0 < 0) s0 = -s0, t0 = -t0;  // gcd came out as -1
  return {line.a, line.b, -t0, s0};
}
IRing MapRing(const IRing& ring, const Unimodular& m, bool forward) {
  IRing out;
  out.reserve(ring.size());
  for (const IPoint& p : ring) out.push_back(forward ? m.Forward(p) : m.Back(p));
  return out;
}
}  // namespace

bool SplitIsOnGrid(const IRing& ring, const ILine& line) {
  if (line.a == 1 && line.b == 0) return SplitIsOnGrid(ring, Axis::kX, line.k);
  if (line.a == 0 && line.b == 1) return SplitIsOnGrid(ring, Axis::kY, line.k);
  // The vertical test in the mapped plane, point by point (no copy of the ring).
  const Unimodular m = MapToVertical(line);
  const int64_t k = line.k;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const IPoint p = m.Forward(ring[i]), r = m.Forward(ring[(i + 1) % ring.size()]);
    if ((p.x - k) * (r.x - k) < 0 && ((k - p.x) * (r.y - p.y)) % (r.x - p.x) != 0) return false;
  }
  return true;
}

bool SplitRing(const IRing& ring, const ILine& line, std::vector<IRing>* low, std::vector<IRing>* high) {
  if (line.a == 1 && line.b == 0) return SplitRing(ring, Axis::kX, line.k, low, high);
  if (line.a == 0 && line.b == 1) return SplitRing(ring, Axis::kY, line.k, low, high);
  const Unimodular m = MapToVertical(line);
  std::vector<IRing> l, h;
  if (!SplitVertical(MapRing(ring, m, true), line.k, &l, &h)) return false;
  for (auto& r : l) low->push_back(Normalize(MapRing(r, m, false)));
  for (auto& r : h) high->push_back(Normalize(MapRing(r, m, false)));
  return true;
}

bool SplitRing(const IRing& ring, Axis axis, int64_t k, std::vector<IRing>* low, std::vector<IRing>* high) {
  if (axis == Axis::kX) {
    std::vector<IRing> l, h;
    if (!SplitVertical(ring, k, &l, &h)) return false;
    for (auto& r : l) low->push_back(std::move(r));
    for (auto& r : h) high->push_back(std::move(r));
    return true;
  }
  // y = k: rotate by +90 degrees, (x, y) -> (-y, x): the line becomes x = -k; y < k maps to x > -k.
  IRing rotated;
  rotated.reserve(ring.size());
  for (const IPoint& p : ring) rotated.push_back(RotateCcw(p));
  std::vector<IRing> l, h;
  if (!SplitVertical(rotated, -k, &l, &h)) return false;
  auto back = [](IRing r) {
    for (IPoint& p : r) p = RotateCw(p);
    return r;
  };
  for (auto& r : h) low->push_back(back(std::move(r)));
  for (auto& r : l) high->push_back(back(std::move(r)));
  return true;
}

std::vector<IRing> UnionTiles(const std::vector<IRing>& tiles) {
  std::vector<IPoint> vertices;
  for (const IRing& t : tiles) vertices.insert(vertices.end(), t.begin(), t.end());
  std::vector<DirectedEdge> edges;
  for (const IRing& t : tiles) {
    for (std::size_t i = 0; i < t.size(); ++i) {
      const IPoint a = t[i], b = t[(i + 1) % t.size()];
      // Vertices of other tiles strictly inside this edge split it (T-junctions).
      std::vector<std::pair<int64_t, IPoint>> cuts;
      const int64_t len2 = (b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y);
      for (const IPoint& v : vertices) {
        if (v == a || v == b || !OnSegment(a, b, v)) continue;
        const int64_t t_along = (v.x - a.x) * (b.x - a.x) + (v.y - a.y) * (b.y - a.y);
        if (t_along > 0 && t_along < len2) cuts.push_back({t_along, v});
      }
      std::sort(cuts.begin(), cuts.end(), [](const auto& l, const auto& r) { return l.first < r.first; });
      IPoint from = a;
      for (const auto& [t_along, v] : cuts) {
        if (v == from) continue;
        edges.push_back({from, v});
        from = v;
      }
      edges.push_back({from, b});
    }
  }
  // Cancel each edge against an opposite twin.
  std::sort(edges.begin(), edges.end(), [](const DirectedEdge& l, const DirectedEdge& r) {
    if (l.a.x != r.a.x) return l.a.x < r.a.x;
    if (l.a.y != r.a.y) return l.a.y < r.a.y;
    if (l.b.x != r.b.x) return l.b.x < r.b.x;
    return l.b.y < r.b.y;
  });
  auto find = [&](IPoint a, IPoint b) -> long {
    auto it = std::lower_bound(edges.begin(), edges.end(), DirectedEdge{a, b}, [](const DirectedEdge& l, const DirectedEdge& r) {
      if (l.a.x != r.a.x) return l.a.x < r.a.x;
      if (l.a.y != r.a.y) return l.a.y < r.a.y;
      if (l.b.x != r.b.x) return l.b.x < r.b.x;
      return l.b.y < r.b.y;
    });
    while (it != edges.end() && it->a == a && it->b == b) {
      if (!it->used) return it - edges.begin();
      ++it;
    }
    return -1;
  };
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (edges[i].used) continue;
    const long twin = find(edges[i].b, edges[i].a);
    if (twin >= 0) {
      edges[i].used = true;
      edges[twin].used = true;
    }
  }
  std::vector<DirectedEdge> rest;
  for (const auto& e : edges)
    if (!e.used) rest.push_back({e.a, e.b});
  return AssembleLoops(rest);
}

bool SubtractBox(const IRing& ring, const IBox& box, std::vector<IRing>* out) {
  std::vector<IRing> keep, work{ring};
  struct Cut {
    Axis axis;
    int64_t k;
    bool keep_low;
  };
  const Cut cuts[] = {{Axis::kX, box.min_x, true}, {Axis::kX, box.max_x, false},
                      {Axis::kY, box.min_y, true}, {Axis::kY, box.max_y, false}};
  const IBox rb = BoundingBox(ring);
  if (box.max_x <= rb.min_x || box.min_x >= rb.max_x || box.max_y <= rb.min_y || box.min_y >= rb.max_y) {
    *out = {ring};  // no overlap
    return true;
  }
  for (const Cut& cut : cuts) {
    std::vector<IRing> next;
    for (IRing& piece : work) {
      // A line that misses the piece leaves it whole on one side.
      const IBox pb = BoundingBox(piece);
      const int64_t lo = cut.axis == Axis::kX ? pb.min_x : pb.min_y;
      const int64_t hi = cut.axis == Axis::kX ? pb.max_x : pb.max_y;
      if (cut.k <= lo || cut.k >= hi) {
        const bool piece_low = cut.k >= hi;
        (piece_low == cut.keep_low ? keep : next).push_back(std::move(piece));
        continue;
      }
      std::vector<IRing> low, high;
      if (!SplitRing(piece, cut.axis, cut.k, &low, &high)) return false;
      for (auto& r : (cut.keep_low ? low : high)) keep.push_back(std::move(r));
      for (auto& r : (cut.keep_low ? high : low)) next.push_back(std::move(r));
    }
    work = std::move(next);
  }
  if (keep.empty()) {
    out->clear();
    return true;
  }
  if (keep.size() == 1) {
    *out = std::move(keep);
    return true;
  }
  std::vector<IRing> merged = UnionTiles(keep);
  for (const IRing& r : merged)
    if (TwiceArea(r) <= 0) return false;  // a hole
  *out = std::move(merged);
  return true;
}

bool SubtractInside(const IRing& ring, const IRing& inner, std::vector<IRing>* out) {
  for (const IPoint& p : inner)
    if (PointInRing(ring, p) < 0) return false;
  for (const IPoint& p : ring)
    if (PointInRing(inner, p) > 0) return false;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const IPoint a = ring[i], b = ring[(i + 1) % ring.size()];
    for (std::size_t j = 0; j < inner.size(); ++j) {
      const IPoint c = inner[j], d = inner[(j + 1) % inner.size()];
      if (Sign(Cross(a, b, c)) * Sign(Cross(a, b, d)) < 0 && Sign(Cross(c, d, a)) * Sign(Cross(c, d, b)) < 0)
        return false;  // proper crossing
    }
  }
  IRing reversed(inner.rbegin(), inner.rend());
  std::vector<IRing> loops = UnionTiles({ring, reversed});
  int64_t total = 0;
  for (const IRing& r : loops) {
    const int64_t a = TwiceArea(r);
    if (a <= 0) return false;
    total += a;
  }
  if (total != TwiceArea(ring) - TwiceArea(inner)) return false;
  *out = std::move(loops);
  return true;
}

std::vector<ISegment> SharedSegments(const IRing& a, const IRing& b) {
  std::vector<ISegment> shared;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const IPoint p = a[i], q = a[(i + 1) % a.size()];
    const IBox eb{std::min(p.x, q.x), std::min(p.y, q.y), std::max(p.x, q.x), std::max(p.y, q.y)};
    for (std::size_t j = 0; j < b.size(); ++j) {
      const IPoint r = b[j], s = b[(j + 1) % b.size()];
      if (std::max(r.x, s.x) < eb.min_x || std::min(r.x, s.x) > eb.max_x || std::max(r.y, s.y) < eb.min_y ||
          std::min(r.y, s.y) > eb.max_y)
        continue;
      if (Cross(p, q, r) != 0 || Cross(p, q, s) != 0) continue;
      // Project on p->q: parameters of r and s.
      const int64_t dx = q.x - p.x, dy = q.y - p.y;
      const int64_t len2 = dx * dx + dy * dy;
      int64_t tr = (r.x - p.x) * dx + (r.y - p.y) * dy;
      int64_t ts = (s.x - p.x) * dx + (s.y - p.y) * dy;
      const int64_t lo = std::max<int64_t>(0, std::min(tr, ts));
      const int64_t hi = std::min<int64_t>(len2, std::max(tr, ts));
      if (hi <= lo) continue;
      auto at = [&](int64_t t) -> IPoint {
        // t / len2 of the way along p->q; exact because the end points are vertices of a or b.
        return {p.x + dx * t / len2, p.y + dy * t / len2};
      };
      shared.push_back({at(lo), at(hi)});
    }
  }
  return shared;
}

namespace {
struct DPoint {
  double x, y;
};
// Closest point of segment [a, b] to p.
DPoint ClosestOnSegment(DPoint p, DPoint a, DPoint b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return {a.x + t * dx, a.y + t * dy};
}
DPoint D(IPoint p) { return {static_cast<double>(p.x), static_cast<double>(p.y)}; }

// Inside `ring` (grid units as doubles) and more than 1e-9 from its boundary: layout's point in polygon.
bool StrictlyInside(const Ring& ring, DPoint p) {
  return DistanceToBoundary({p.x, p.y}, ring) >= 1e-9 && villa::PointInRing(Point{p.x, p.y}, ring, 0);
}
}  // namespace

namespace {
// Smallest interior distance between non-adjacent edges below `limit` (squared), or `limit` squared.
// Pairs whose bounding boxes are `limit` apart are skipped.
double MinWidthSquaredBelow(const IRing& ring, double limit) {
  const std::size_t n = ring.size();
  double best = limit * limit;
  if (n < 3) return 0.0;
  if (n == 3) {
    for (std::size_t i = 0; i < 3; ++i) {
      const DPoint p = D(ring[i]);
      const DPoint q = ClosestOnSegment(p, D(ring[(i + 1) % 3]), D(ring[(i + 2) % 3]));
      best = std::min(best, (p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y));
    }
    return best;
  }
  if (n == 4 && ring[0].x != ring[1].x && ring[0].y == ring[1].y && ring[1].x == ring[2].x && ring[2].y == ring[3].y &&
      ring[3].x == ring[0].x) {
    const double side = static_cast<double>(std::min(std::llabs(ring[1].x - ring[0].x), std::llabs(ring[2].y - ring[1].y)));
    return std::min(best, side * side);
  }
  // Non-adjacent edges whose closest approach runs through the interior (a thin arm or sliver; gaps
  // across a notch or a bite outside the ring do not count).
  Ring as_doubles;
  as_doubles.reserve(n);
  for (const IPoint& p : ring) as_doubles.push_back({static_cast<double>(p.x), static_cast<double>(p.y)});
  for (std::size_t i = 0; i < n; ++i) {
    const IPoint a = ring[i], b = ring[(i + 1) % n];
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // adjacent through the closing vertex
      const IPoint c = ring[j], d = ring[(j + 1) % n];
      const double gap_x = static_cast<double>(std::max(std::min(a.x, b.x) - std::max(c.x, d.x), std::min(c.x, d.x) - std::max(a.x, b.x)));
      const double gap_y = static_cast<double>(std::max(std::min(a.y, b.y) - std::max(c.y, d.y), std::min(c.y, d.y) - std::max(a.y, b.y)));
      if ((gap_x > 0 && gap_x * gap_x >= best) || (gap_y > 0 && gap_y * gap_y >= best)) continue;
      if (SegmentsTouch(a, b, c, d)) return 0.0;
      const DPoint pairs[4][2] = {{D(a), ClosestOnSegment(D(a), D(c), D(d))},
                                  {D(b), ClosestOnSegment(D(b), D(c), D(d))},
                                  {D(c), ClosestOnSegment(D(c), D(a), D(b))},
                                  {D(d), ClosestOnSegment(D(d), D(a), D(b))}};
      for (const auto& pq : pairs) {
        const double dist2 = (pq[0].x - pq[1].x) * (pq[0].x - pq[1].x) + (pq[0].y - pq[1].y) * (pq[0].y - pq[1].y);
        if (dist2 >= best) continue;
        if (StrictlyInside(as_doubles, {(pq[0].x + pq[1].x) / 2, (pq[0].y + pq[1].y) / 2})) best = dist2;
      }
    }
  }
  return best;
}
}  // namespace

double MinWidth(const IRing& ring) {
  return std::sqrt(MinWidthSquaredBelow(ring, std::numeric_limits<double>::infinity()));
}

bool NarrowerThan(const IRing& ring, double width) { return MinWidthSquaredBelow(ring, width) < width * width; }

void Centroid(const IRing& ring, double* x, double* y) {
  double a = 0.0, cx = 0.0, cy = 0.0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const IPoint p = ring[i], r = ring[(i + 1) % ring.size()];
    const double w = double(p.x) * double(r.y) - double(r.x) * double(p.y);
    a += w;
    cx += (double(p.x) + double(r.x)) * w;
    cy += (double(p.y) + double(r.y)) * w;
  }
  *x = cx / (3.0 * a);
  *y = cy / (3.0 * a);
}

}  // namespace villa::partition
