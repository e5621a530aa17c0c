#include "finetune/geometry_key.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <utility>

#include "layout/shape_codec.h"
#include "util/hash.h"

namespace villa {
namespace {

// A point on the format's 0.01 m grid, in integer centimetres, so edges can be matched exactly.
struct GridPoint {
  std::int64_t x = 0;
  std::int64_t y = 0;
  friend bool operator==(const GridPoint&, const GridPoint&) = default;
  friend auto operator<=>(const GridPoint&, const GridPoint&) = default;
};

GridPoint ToGrid(const Point& p) { return {std::llround(p.x * 100.0), std::llround(p.y * 100.0)}; }

std::int64_t Cross(const GridPoint& o, const GridPoint& a, const GridPoint& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// True when `p` lies strictly between `a` and `b` on the segment a-b.
bool StrictlyInside(const GridPoint& a, const GridPoint& b, const GridPoint& p) {
  if (Cross(a, b, p) != 0) return false;
  std::int64_t dot = (p.x - a.x) * (b.x - a.x) + (p.y - a.y) * (b.y - a.y);
  std::int64_t len2 = (b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y);
  return dot > 0 && dot < len2;
}

std::string SegmentText(const Segment& s) {
  Segment ordered = s;
  Point a{RoundToFormat(s.a.x), RoundToFormat(s.a.y)};
  Point b{RoundToFormat(s.b.x), RoundToFormat(s.b.y)};
  if (b.x < a.x || (b.x == a.x && b.y < a.y)) std::swap(a, b);
  ordered = {a, b};
  return FormatLineShape(ordered);
}

}  // namespace

std::string GeometryKey(const Layout& layout) {
  std::vector<std::string> parts;
  for (const auto& room : layout.rooms) {
    parts.push_back("room " + std::to_string(room.level) + " " + FormatPolygonShape(room.polygon));
  }
  for (ElementKind kind : kAllElementKinds) {
    for (const auto& e : layout.elements(kind)) {
      std::string part = std::string(ElementKindKey(kind)) + " " + std::to_string(e.level) + " " + SegmentText(e.shape);
      if (kind == ElementKind::kWindow) part += e.panoramic ? " panoramic" : " plain";
      parts.push_back(std::move(part));
    }
  }
  std::sort(parts.begin(), parts.end());
  std::string key;
  for (const auto& part : parts) {
    key += part;
    key += '\n';
  }
  return key;
}

std::uint64_t StableHash(std::string_view text) { return SplitMix64Hash(Fnv1a64(text)); }

Ring FootprintOutline(const Layout& layout, int level) {
  std::vector<std::vector<GridPoint>> rings;
  std::vector<GridPoint> vertices;
  for (int index : layout.RoomsOnLevel(level)) {
    std::vector<GridPoint> ring;
    for (const auto& p : layout.rooms[index].polygon) ring.push_back(ToGrid(p));
    if (ring.size() < 3) return {};
    vertices.insert(vertices.end(), ring.begin(), ring.end());
    rings.push_back(std::move(ring));
  }
  if (rings.empty()) return {};
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());

  // Split every room edge at the vertices of other rooms lying on it, then let pieces shared by two
  // rooms (traversed in opposite directions) cancel: what remains is the outer boundary.
  std::map<std::pair<GridPoint, GridPoint>, int> net;  // undirected piece (low, high) -> +1 low->high, -1 back
  for (const auto& ring : rings) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      GridPoint a = ring[i], b = ring[(i + 1) % ring.size()];
      if (a == b) continue;
      std::vector<GridPoint> cuts{a};
      for (const auto& v : vertices)
        if (StrictlyInside(a, b, v)) cuts.push_back(v);
      cuts.push_back(b);
      std::sort(cuts.begin() + 1, cuts.end() - 1, [&](const GridPoint& p, const GridPoint& q) {
        return std::llabs(p.x - a.x) + std::llabs(p.y - a.y) < std::llabs(q.x - a.x) + std::llabs(q.y - a.y);
      });
      for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
        GridPoint p = cuts[k], q = cuts[k + 1];
        if (p < q) net[{p, q}] += 1;
        else net[{q, p}] -= 1;
      }
    }
  }
  std::map<GridPoint, GridPoint> next;
  std::size_t pieces = 0;
  for (const auto& [piece, count] : net) {
    if (count == 0) continue;
    if (std::abs(count) != 1) return {};  // overlapping rooms: no single outline
    GridPoint from = count > 0 ? piece.first : piece.second;
    GridPoint to = count > 0 ? piece.second : piece.first;
    if (!next.emplace(from, to).second) return {};  // a pinch point: not one simple outline
    ++pieces;
  }
  if (next.empty()) return {};
  std::vector<GridPoint> loop;
  GridPoint start = next.begin()->first, at = start;
  do {
    loop.push_back(at);
    auto it = next.find(at);
    if (it == next.end() || loop.size() > pieces) return {};
    at = it->second;
  } while (!(at == start));
  if (loop.size() != pieces) return {};  // holes or several pieces

  // Merge collinear runs.
  std::vector<GridPoint> merged;
  const std::size_t n = loop.size();
  for (std::size_t i = 0; i < n; ++i) {
    const GridPoint& prev = loop[(i + n - 1) % n];
    const GridPoint& cur = loop[i];
    const GridPoint& nxt = loop[(i + 1) % n];
    if (Cross(prev, cur, nxt) != 0) merged.push_back(cur);
  }
  Ring out;
  for (const auto& p : merged) out.push_back({static_cast<double>(p.x) / 100.0, static_cast<double>(p.y) / 100.0});
  if (SignedArea(out) < 0) std::reverse(out.begin(), out.end());
  return out;
}

std::string ClassifyFootprint(const Layout& layout) {
  if (layout.RoomsOnLevel(0).empty()) return "none";
  Ring ring = FootprintOutline(layout, 0);
  const std::size_t n = ring.size();
  if (n < 3) return "irregular";
  for (std::size_t i = 0; i < n; ++i) {
    const Point& a = ring[i];
    const Point& b = ring[(i + 1) % n];
    if (a.x != b.x && a.y != b.y) return "irregular";  // a slanted edge
  }
  std::vector<int> reflex;
  for (std::size_t i = 0; i < n; ++i) {
    const Point& p = ring[(i + n - 1) % n];
    const Point& c = ring[i];
    const Point& q = ring[(i + 1) % n];
    double turn = (c.x - p.x) * (q.y - c.y) - (c.y - p.y) * (q.x - c.x);
    if (turn < 0) reflex.push_back(static_cast<int>(i));
  }
  const int size = static_cast<int>(n);
  auto adjacent = [&](int i, int j) { return (i + 1) % size == j || (j + 1) % size == i; };
  if (n == 4 && reflex.empty()) return "rectangle";
  if (n == 6 && reflex.size() == 1) return "L";
  if (n == 8 && reflex.size() == 2) {
    // A notch in one side leaves its two reflex corners next to each other (U); two neighbouring corners
    // cut away leave them 3 and 5 steps apart around the outline (T).
    if (adjacent(reflex[0], reflex[1])) return "U";
    int gap = reflex[1] - reflex[0];
    if (gap == 3 || gap == 5) return "T";
    return "irregular";
  }
  if (n == 12 && reflex.size() == 4) {
    // H: two notches in opposite sides. Each notch is a pair of adjacent reflex corners; the notch floors
    // run in opposite directions.
    std::vector<std::pair<Point, Point>> floors;
    for (std::size_t k = 0; k < reflex.size(); ++k) {
      int i = reflex[k], j = reflex[(k + 1) % reflex.size()];
      if ((i + 1) % size == j) floors.push_back({ring[i], ring[j]});
    }
    if (floors.size() == 2) {
      double dx0 = floors[0].second.x - floors[0].first.x, dy0 = floors[0].second.y - floors[0].first.y;
      double dx1 = floors[1].second.x - floors[1].first.x, dy1 = floors[1].second.y - floors[1].first.y;
      bool antiparallel = dx0 * dy1 - dy0 * dx1 == 0 && dx0 * dx1 + dy0 * dy1 < 0;
      if (antiparallel) return "H";
    }
  }
  return "irregular";
}

}  // namespace villa
