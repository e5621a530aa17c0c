#include "mesh/convex_parts.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <unordered_map>

#include "mesh/triangulate.h"

namespace villa {
namespace {

double Cross2(Point o, Point a, Point b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

double RingArea(const Ring& ring) {
  double a = 0.0;
  for (size_t i = 0; i < ring.size(); ++i) a += Cross2({0, 0}, ring[i], ring[(i + 1) % ring.size()]);
  return 0.5 * a;
}

bool InsideRing(const Ring& ring, Point p) {
  bool in = false;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
    if ((ring[i].y > p.y) != (ring[j].y > p.y) &&
        p.x < (ring[j].x - ring[i].x) * (p.y - ring[i].y) / (ring[j].y - ring[i].y) + ring[i].x)
      in = !in;
  return in;
}

// A convex polygon of a cross-section: indices into its points, counter-clockwise.
using Poly = std::vector<int>;

bool Convex(const Poly& poly, const std::vector<Point>& at) {
  const size_t n = poly.size();
  for (size_t i = 0; i < n; ++i)
    if (Cross2(at[poly[i]], at[poly[(i + 1) % n]], at[poly[(i + 2) % n]]) < -1e-12) return false;
  return true;
}

// `a` and `b` joined across an edge they share (a's u -> v is b's v -> u), or nullopt.
std::optional<Poly> Join(const Poly& a, const Poly& b) {
  for (size_t i = 0; i < a.size(); ++i) {
    const int u = a[i], v = a[(i + 1) % a.size()];
    for (size_t j = 0; j < b.size(); ++j) {
      if (b[j] != v || b[(j + 1) % b.size()] != u) continue;
      Poly out;
      for (size_t k = 0; k < a.size(); ++k) out.push_back(a[(i + 1 + k) % a.size()]);  // v round to u
      for (size_t k = 2; k < b.size(); ++k) out.push_back(b[(j + k) % b.size()]);      // after u, before v
      return out;
    }
  }
  return std::nullopt;
}

// Corners where the outline goes straight on are dropped (a rectangle keeps 4, so it can be a box).
Poly WithoutStraightCorners(const Poly& poly, const std::vector<Point>& at) {
  Poly out;
  const size_t n = poly.size();
  for (size_t i = 0; i < n; ++i) {
    const Point a = at[poly[(i + n - 1) % n]], b = at[poly[i]], c = at[poly[(i + 1) % n]];
    const double scale = std::hypot(b.x - a.x, b.y - a.y) * std::hypot(c.x - b.x, c.y - b.y);
    if (std::abs(Cross2(a, b, c)) > 1e-9 * scale) out.push_back(poly[i]);
  }
  return out;
}

// The loops where the plane h = Dot(p, d) cuts the side faces, in (u, v): each oriented with the solid on
// its left (outer boundaries counter-clockwise, holes clockwise). Two faces back to back (inside the solid)
// cancel; where loops touch at a point, each goes on by its sharpest left turn, so they stay apart. Empty
// when they do not close.
std::vector<Ring> CrossSection(const TriangleMesh& piece, const std::vector<int>& sides, Vec3 d, Vec3 u, Vec3 v, double h) {
  using Key = std::pair<long long, long long>;
  auto key = [](Point p) { return Key{std::llround(p.x * 1e7), std::llround(p.y * 1e7)}; };
  std::multimap<Key, std::pair<Point, Point>> next;  // a segment's start -> (start, end)
  for (int t : sides) {
    const auto& tri = piece.triangles[t];
    Point cut[2];
    int found = 0;
    for (int e = 0; e < 3 && found < 2; ++e) {
      // Each edge from its lower-indexed end, so two triangles sharing it compute the same point.
      int i = tri[e], j = tri[(e + 1) % 3];
      if (i > j) std::swap(i, j);
      const Vec3 a = piece.vertices[i], b = piece.vertices[j];
      const double da = Dot(a, d) - h, db = Dot(b, d) - h;
      if ((da < 0) == (db < 0)) continue;
      const Vec3 p = a + (b - a) * (da / (da - db));
      cut[found++] = {Dot(p, u), Dot(p, v)};
    }
    if (found != 2) continue;
    const Vec3 n = Cross(piece.vertices[tri[1]] - piece.vertices[tri[0]], piece.vertices[tri[2]] - piece.vertices[tri[0]]);
    const Vec3 dir = u * (cut[1].x - cut[0].x) + v * (cut[1].y - cut[0].y);
    if (Dot(Cross(dir, d), n) < 0) std::swap(cut[0], cut[1]);
    if (key(cut[0]) == key(cut[1])) continue;
    // Back to back with a segment already there: both go.
    bool cancelled = false;
    for (auto [it, end] = next.equal_range(key(cut[1])); it != end && !cancelled; ++it)
      if (key(it->second.second) == key(cut[0])) {
        next.erase(it);
        cancelled = true;
        break;  // `it` is gone
      }
    if (!cancelled) next.emplace(key(cut[0]), std::pair{cut[0], cut[1]});
  }
  std::vector<Ring> loops;
  while (!next.empty()) {
    Ring ring;
    auto it = next.begin();
    const Key first = it->first;
    for (;;) {
      const Point from = it->second.first, to = it->second.second;
      ring.push_back(from);
      next.erase(it);
      if (key(to) == first) break;
      auto [lo, hi] = next.equal_range(key(to));
      if (lo == hi) return {};
      it = lo;
      double best = -10.0;
      for (auto c = lo; c != hi; ++c) {
        const Point a{to.x - from.x, to.y - from.y}, b{c->second.second.x - to.x, c->second.second.y - to.y};
        const double turn = std::atan2(a.x * b.y - a.y * b.x, a.x * b.x + a.y * b.y);
        if (turn > best) best = turn, it = c;
      }
    }
    if (ring.size() >= 3) loops.push_back(std::move(ring));
  }
  return loops;
}

// The convex polygons making up the region bounded by `loops` (outer counter-clockwise, holes clockwise).
std::vector<std::vector<Point>> ConvexPieces(const std::vector<Ring>& loops) {
  std::vector<std::vector<Point>> out;
  std::vector<const Ring*> outers, holes;
  for (const Ring& r : loops) (RingArea(r) > 0 ? outers : holes).push_back(&r);
  // Each hole belongs to the smallest outer loop holding it (an island inside a hole has its own holes).
  std::vector<const Ring*> owner(holes.size(), nullptr);
  for (size_t h = 0; h < holes.size(); ++h)
    for (const Ring* outer : outers)
      if (InsideRing(*outer, (*holes[h])[0]) && (!owner[h] || RingArea(*outer) < RingArea(*owner[h]))) owner[h] = outer;
  for (const Ring* outer : outers) {
    std::vector<Ring> inner;
    for (size_t h = 0; h < holes.size(); ++h)
      if (owner[h] == outer) inner.push_back(*holes[h]);
    std::vector<Point> at = *outer;
    for (const Ring& h : inner) at.insert(at.end(), h.begin(), h.end());
    std::vector<Poly> polys;
    for (const auto& t : TriangulatePolygon(*outer, inner))
      if (Cross2(at[t[0]], at[t[1]], at[t[2]]) > 1e-14) polys.push_back({t[0], t[1], t[2]});
    for (bool joined = true; joined;) {
      joined = false;
      for (size_t i = 0; i < polys.size() && !joined; ++i)
        for (size_t j = i + 1; j < polys.size() && !joined; ++j)
          if (auto both = Join(polys[i], polys[j]); both && Convex(*both, at)) {
            polys[i] = *both;
            polys.erase(polys.begin() + static_cast<std::ptrdiff_t>(j));
            joined = true;
          }
    }
    for (const Poly& raw : polys) {
      const Poly poly = WithoutStraightCorners(raw, at);
      if (poly.size() < 3) continue;
      std::vector<Point> points;
      for (int k : poly) points.push_back(at[k]);
      out.push_back(std::move(points));
    }
  }
  return out;
}

// The prism over `poly` (in u, v; counter-clockwise seen from +d) from h0 to h1 along d.
TriangleMesh Prism(const std::vector<Point>& poly, Vec3 d, Vec3 u, Vec3 v, double h0, double h1) {
  TriangleMesh m;
  const int n = static_cast<int>(poly.size());
  for (double h : {h1, h0})
    for (const Point& p : poly) m.vertices.push_back(u * p.x + v * p.y + d * h);
  for (int k = 1; k + 1 < n; ++k) {
    m.AddTriangle(0, k, k + 1);          // the top, facing +d
    m.AddTriangle(n, n + k + 1, n + k);  // the bottom, facing -d
  }
  for (int k = 0; k < n; ++k) {
    const int a = k, b = (k + 1) % n;
    m.AddTriangle(a, n + a, n + b);
    m.AddTriangle(a, n + b, b);
  }
  return m;
}

// A piece with more face directions than this is curved somewhere (a lathe, a scanned model): not tried.
constexpr size_t kMaxDirections = 64;

}  // namespace

TriangleMesh WeldedByPosition(const TriangleMesh& mesh) {
  TriangleMesh out;
  std::map<std::array<long long, 3>, int> index;
  std::vector<int> id(mesh.vertices.size());
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec3& v = mesh.vertices[i];
    const std::array<long long, 3> key{std::llround(v.x * 1e7), std::llround(v.y * 1e7), std::llround(v.z * 1e7)};
    auto [it, added] = index.emplace(key, static_cast<int>(out.vertices.size()));
    if (added) out.vertices.push_back(v);
    id[i] = it->second;
  }
  for (const auto& t : mesh.triangles)
    if (id[t[0]] != id[t[1]] && id[t[1]] != id[t[2]] && id[t[0]] != id[t[2]]) out.AddTriangle(id[t[0]], id[t[1]], id[t[2]]);
  return out;
}

namespace {
int Root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}
}  // namespace

std::vector<TriangleMesh> SolidPiecesOf(const TriangleMesh& mesh) {
  // Welded first: a file with vertex normals repeats a corner for each face that meets there at a crease,
  // so that by index a box is six loose faces, and a shading weld may join two solids at a shared corner.
  const TriangleMesh welded = WeldedByPosition(mesh);
  const size_t n = welded.triangles.size();
  auto edge = [](int a, int b) { return static_cast<uint64_t>(static_cast<uint32_t>(a)) << 32 | static_cast<uint32_t>(b); };
  // Each directed edge's triangle, or -2 where more than one triangle runs along it that way.
  std::unordered_map<uint64_t, int> along;
  along.reserve(3 * n);
  for (size_t t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k) {
      auto [it, added] = along.emplace(edge(welded.triangles[t][k], welded.triangles[t][(k + 1) % 3]), static_cast<int>(t));
      if (!added) it->second = -2;
    }
  // Triangles joined across an edge that exactly one triangle runs each way (two solids touching along an
  // edge run it twice each way, and stay apart).
  std::vector<int> parent(n);
  for (size_t t = 0; t < n; ++t) parent[t] = static_cast<int>(t);
  std::vector<std::array<int, 3>> loose;  // (triangle, a, b) of an edge without a single twin
  for (size_t t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = welded.triangles[t][k], b = welded.triangles[t][(k + 1) % 3];
      const auto it = along.find(edge(a, b)), back = along.find(edge(b, a));
      if (it->second < 0 || back == along.end() || back->second < 0)
        loose.push_back({static_cast<int>(t), a, b});
      else
        parent[Root(parent, static_cast<int>(t))] = Root(parent, back->second);
    }
  // A piece is closed when each edge of it is run once each way by its own triangles (an edge that two
  // stacked boxes share is run once each way in each box); the others are joined with what they meet at
  // the same positions (an imported tray's open shell and its glass sheet are one solid).
  std::map<std::array<int, 3>, int> runs;  // (piece, a, b) -> triangles of the piece running a to b
  for (const auto& [t, a, b] : loose) ++runs[{Root(parent, t), a, b}];
  std::vector<bool> open_piece(n, false);
  for (const auto& [e, count] : runs) {
    const auto back = runs.find({e[0], e[2], e[1]});
    if (count != 1 || back == runs.end() || back->second != 1) open_piece[e[0]] = true;
  }
  // Triangles by piece (closed pieces in the order they first appear, then the open ones together).
  std::vector<int> piece_of(n, -1), order(n);
  int pieces = 0;
  for (size_t t = 0; t < n; ++t) {
    const int r = Root(parent, static_cast<int>(t));
    if (open_piece[r]) continue;
    if (piece_of[r] < 0) piece_of[r] = pieces++;
  }
  std::vector<int> key(n);
  for (size_t t = 0; t < n; ++t) {
    const int r = Root(parent, static_cast<int>(t));
    key[t] = open_piece[r] ? pieces : piece_of[r];
    order[t] = static_cast<int>(t);
  }
  std::stable_sort(order.begin(), order.end(), [&](int x, int y) { return key[x] < key[y]; });
  std::vector<TriangleMesh> out(pieces);
  TriangleMesh open;
  std::vector<int> index(welded.vertices.size(), -1), stamp(welded.vertices.size(), -1);
  for (int t : order) {
    const int p = key[t];
    TriangleMesh& target = p < pieces ? out[p] : open;
    std::array<int, 3> v;
    for (int k = 0; k < 3; ++k) {
      const int w = welded.triangles[t][k];
      if (stamp[w] != p) {  // a corner two stacked boxes share is a vertex of each
        stamp[w] = p;
        index[w] = static_cast<int>(target.vertices.size());
        target.vertices.push_back(welded.vertices[w]);
      }
      v[k] = index[w];
    }
    target.triangles.push_back(v);
  }
  for (TriangleMesh& piece : SplitPieces(open)) out.push_back(std::move(piece));
  return out;
}

std::optional<std::vector<TriangleMesh>> ConvexPrismParts(const TriangleMesh& given, const PrismTolerance& tolerance) {
  if (given.triangles.empty()) return std::nullopt;
  // A solid written inside out (an imported model's) is read turned right.
  TriangleMesh flipped;
  const bool inverted = given.SignedVolume() < 0;
  if (inverted) {
    flipped = given;
    for (auto& t : flipped.triangles) std::swap(t[1], t[2]);
  }
  const TriangleMesh& piece = inverted ? flipped : given;
  // Candidate directions: up first (walls, slabs), then the face normals, the largest area first.
  std::vector<std::pair<double, Vec3>> normals{{1e300, Vec3{0, 0, 1}}};
  for (const auto& t : piece.triangles) {
    const Vec3 c = Cross(piece.vertices[t[1]] - piece.vertices[t[0]], piece.vertices[t[2]] - piece.vertices[t[0]]);
    const double area = Norm(c);
    if (area < 1e-12) continue;
    const Vec3 n = c * (1.0 / area);
    bool seen = false;
    for (auto& [sum, m] : normals)
      if (std::abs(Dot(n, m)) > 1.0 - 1e-9) {
        sum += area;
        seen = true;
        break;
      }
    if (!seen) normals.push_back({area, n});
    if (normals.size() > kMaxDirections) return std::nullopt;  // curved: no stack of prisms
  }
  std::sort(normals.begin(), normals.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  if (normals.size() > 6) normals.resize(6);
  const double volume = piece.SignedVolume();
  for (const auto& [area, d] : normals) {
    std::vector<int> sides;
    std::vector<double> heights;
    bool stack = true;
    for (size_t t = 0; t < piece.triangles.size() && stack; ++t) {
      const auto& tri = piece.triangles[t];
      const Vec3 c = Cross(piece.vertices[tri[1]] - piece.vertices[tri[0]], piece.vertices[tri[2]] - piece.vertices[tri[0]]);
      const double len = Norm(c);
      if (len < 1e-12) continue;
      const double along = std::abs(Dot(c, d)) / len;
      if (along < std::sin(tolerance.slope)) {
        sides.push_back(static_cast<int>(t));
      } else if (along > std::cos(tolerance.slope)) {
        for (int k : tri) heights.push_back(Dot(piece.vertices[k], d));
      } else {
        stack = false;
      }
    }
    if (!stack || heights.size() < 2) continue;
    // Heights within `snap` of each other are one: the highest of them.
    std::sort(heights.begin(), heights.end());
    std::vector<double> levels;
    for (double h : heights)
      if (levels.empty() || h - levels.back() > tolerance.snap) levels.push_back(h);
      else levels.back() = h;
    heights = levels;
    if (heights.size() < 2) continue;
    const Vec3 u = Normalized(std::abs(d.x) < 0.9 ? Cross(d, Vec3{1, 0, 0}) : Cross(d, Vec3{0, 1, 0}));
    const Vec3 v = Cross(d, u);
    std::vector<TriangleMesh> parts;
    double sum = 0.0;
    bool closed = true;
    for (size_t k = 0; k + 1 < heights.size() && closed; ++k) {
      const double h0 = heights[k], h1 = heights[k + 1];
      const std::vector<Ring> loops = CrossSection(piece, sides, d, u, v, 0.5 * (h0 + h1));
      closed = !loops.empty();
      for (const std::vector<Point>& poly : ConvexPieces(loops)) {
        double a = 0.0;
        for (size_t i = 0; i < poly.size(); ++i) a += Cross2({0, 0}, poly[i], poly[(i + 1) % poly.size()]);
        sum += 0.5 * a * (h1 - h0);
        parts.push_back(Prism(poly, d, u, v, h0, h1));
      }
    }
    if (closed && !parts.empty() && std::abs(sum - volume) <= tolerance.volume_share * std::max(1e-6, std::abs(volume)) + 1e-12)
      return parts;
  }
  return std::nullopt;
}

}  // namespace villa
