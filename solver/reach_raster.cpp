#include "solver/reach_raster.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "mesh/geometry2d.h"

namespace villa::solver {
namespace {

using namespace villa::geo;

constexpr double kFar = 1e20;  // squared distance (cells) of "no obstacle"

class Occupancy {
 public:
  explicit Occupancy(const Grid& g) : g_(g), occ_(g.size(), 0) {}

  void Mark(Point p) {
    const long i = g_.CellOf(p);
    if (i >= 0) occ_[i] = 1;
  }
  // Every cell a segment passes through, sampled an eighth of a cell apart (so every point of it lies
  // within a sixteenth of a cell of a sample, and so of a marked cell).
  void MarkSegment(Point a, Point b) {
    const double len = Dist(a, b);
    const int n = static_cast<int>(std::ceil(len / (0.125 * g_.cell))) + 1;
    for (int k = 0; k <= n; ++k) Mark(Lerp(a, b, static_cast<double>(k) / n));
  }
  // Cells whose centres lie in a convex CCW polygon, row by row.
  void FillConvex(const std::vector<Point>& poly) {
    double ylo = 1e300, yhi = -1e300, xlo = 1e300, xhi = -1e300;
    for (const Point& p : poly) ylo = std::min(ylo, p.y), yhi = std::max(yhi, p.y), xlo = std::min(xlo, p.x), xhi = std::max(xhi, p.x);
    int i0, i1, j0, j1;
    g_.Range({xlo, ylo}, {xhi, yhi}, &i0, &i1, &j0, &j1);
    for (int j = j0; j <= j1; ++j) {
      const double y = g_.y0 + (j + 0.5) * g_.cell;
      double a = 1e300, b = -1e300;
      for (size_t k = 0; k < poly.size(); ++k) {
        const Point& p = poly[k];
        const Point& q = poly[(k + 1) % poly.size()];
        if ((p.y <= y && y <= q.y) || (q.y <= y && y <= p.y)) {
          if (std::abs(q.y - p.y) < 1e-15) {
            a = std::min({a, p.x, q.x});
            b = std::max({b, p.x, q.x});
          } else {
            const double x = p.x + (y - p.y) * (q.x - p.x) / (q.y - p.y);
            a = std::min(a, x);
            b = std::max(b, x);
          }
        }
      }
      if (a > b) continue;
      const int c0 = std::max(i0, static_cast<int>(std::ceil((a - g_.x0) / g_.cell - 0.5)));
      const int c1 = std::min(i1, static_cast<int>(std::floor((b - g_.x0) / g_.cell - 0.5)));
      for (int i = c0; i <= c1; ++i) occ_[static_cast<long>(j) * g_.nx + i] = 1;
    }
  }
  // Cells whose centres lie outside the rings (even-odd), row by row.
  void FillOutside(const std::vector<Ring>& rings) {
    std::vector<double> xs;
    for (int j = 0; j < g_.ny; ++j) {
      const double y = g_.y0 + (j + 0.5) * g_.cell;
      xs.clear();
      for (const Ring& r : rings) {
        for (size_t k = 0; k < r.size(); ++k) {
          const Point& p = r[k];
          const Point& q = r[(k + 1) % r.size()];
          if ((p.y > y) != (q.y > y)) xs.push_back(p.x + (y - p.y) * (q.x - p.x) / (q.y - p.y));
        }
      }
      std::sort(xs.begin(), xs.end());
      size_t next = 0;
      bool inside = false;
      for (int i = 0; i < g_.nx; ++i) {
        const double x = g_.x0 + (i + 0.5) * g_.cell;
        while (next < xs.size() && xs[next] < x) inside = !inside, ++next;
        if (!inside) occ_[static_cast<long>(j) * g_.nx + i] = 1;
      }
    }
  }
  const std::vector<uint8_t>& cells() const { return occ_; }

 private:
  const Grid& g_;
  std::vector<uint8_t> occ_;
};

std::vector<uint8_t> Draw(const FreeSpace& space, const Grid& g, double z0, double z1) {
  Occupancy occ(g);
  if (!space.region().empty()) {
    occ.FillOutside(space.region());
    for (const Ring& r : space.region()) {
      for (size_t k = 0; k < r.size(); ++k) occ.MarkSegment(r[k], r[(k + 1) % r.size()]);
    }
  }
  for (const PlanObstacle& o : space.obstacles()) {
    if (std::min(z1, o.z1) - std::max(z0, o.z0) <= 0.0 || o.shape.points.empty()) continue;
    const std::vector<Point>& p = o.shape.points;
    if (o.shape.radius > 0.0) {
      // A rounded shape (none from the reachability input): every cell whose centre it covers.
      double xlo = 1e300, ylo = 1e300, xhi = -1e300, yhi = -1e300;
      for (const Point& q : p) xlo = std::min(xlo, q.x), ylo = std::min(ylo, q.y), xhi = std::max(xhi, q.x), yhi = std::max(yhi, q.y);
      const double r = o.shape.radius;
      int i0, i1, j0, j1;
      g.Range({xlo - r, ylo - r}, {xhi + r, yhi + r}, &i0, &i1, &j0, &j1);
      for (int j = j0; j <= j1; ++j) {
        for (int i = i0; i <= i1; ++i) {
          const Point c = g.Centre(static_cast<long>(j) * g.nx + i);
          if (PlanClearance(PlanShape::Disc(c, 0.0), o.shape) <= 0.0) occ.Mark(c);
        }
      }
    }
    if (p.size() >= 3) occ.FillConvex(p);
    if (p.size() == 1) occ.Mark(p[0]);
    for (size_t k = 0; p.size() >= 2 && k < (p.size() == 2 ? 1 : p.size()); ++k) occ.MarkSegment(p[k], p[(k + 1) % p.size()]);
  }
  return occ.cells();
}

// Felzenszwalb and Huttenlocher's 1D squared distance transform of f (length n) into d.
void Transform1d(const double* f, int n, double* d, int* v, double* z) {
  int k = 0;
  v[0] = 0;
  z[0] = -kFar;
  z[1] = kFar;
  for (int q = 1; q < n; ++q) {
    double s = ((f[q] + static_cast<double>(q) * q) - (f[v[k]] + static_cast<double>(v[k]) * v[k])) / (2.0 * q - 2.0 * v[k]);
    while (s <= z[k]) {
      --k;
      s = ((f[q] + static_cast<double>(q) * q) - (f[v[k]] + static_cast<double>(v[k]) * v[k])) / (2.0 * q - 2.0 * v[k]);
    }
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = kFar;
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[k + 1] < q) ++k;
    d[q] = static_cast<double>(q - v[k]) * (q - v[k]) + f[v[k]];
  }
}

// Distance (m) from every cell centre to the nearest marked cell's centre.
std::vector<float> DistanceTransform(const std::vector<uint8_t>& occ, const Grid& g) {
  const int n = std::max(g.nx, g.ny);
  std::vector<double> f(n), d(n), z(n + 1);
  std::vector<int> v(n);
  std::vector<double> sq(g.size());
  for (int i = 0; i < g.nx; ++i) {
    for (int j = 0; j < g.ny; ++j) f[j] = occ[static_cast<long>(j) * g.nx + i] ? 0.0 : kFar;
    Transform1d(f.data(), g.ny, d.data(), v.data(), z.data());
    for (int j = 0; j < g.ny; ++j) sq[static_cast<long>(j) * g.nx + i] = d[j];
  }
  std::vector<float> out(g.size());
  for (int j = 0; j < g.ny; ++j) {
    const long row = static_cast<long>(j) * g.nx;
    for (int i = 0; i < g.nx; ++i) f[i] = sq[row + i];
    Transform1d(f.data(), g.nx, d.data(), v.data(), z.data());
    for (int i = 0; i < g.nx; ++i) out[row + i] = static_cast<float>(std::sqrt(std::min(d[i], kFar)) * g.cell);
  }
  return out;
}

}  // namespace

long Grid::CellOf(Point p) const {
  const int i = static_cast<int>(std::floor((p.x - x0) / cell));
  const int j = static_cast<int>(std::floor((p.y - y0) / cell));
  if (i < 0 || j < 0 || i >= nx || j >= ny) return -1;
  return static_cast<long>(j) * nx + i;
}

void Grid::Range(Point lo, Point hi, int* i0, int* i1, int* j0, int* j1) const {
  *i0 = std::max(0, static_cast<int>(std::floor((lo.x - x0) / cell - 0.5)));
  *i1 = std::min(nx - 1, static_cast<int>(std::ceil((hi.x - x0) / cell - 0.5)));
  *j0 = std::max(0, static_cast<int>(std::floor((lo.y - y0) / cell - 0.5)));
  *j1 = std::min(ny - 1, static_cast<int>(std::ceil((hi.y - y0) / cell - 0.5)));
}

LevelCells ClassifyCells(const FreeSpace& building, const FreeSpace& full, Point lo, Point hi, double cell, double radius,
                         double z0, double z1) {
  LevelCells out;
  Grid& g = out.grid;
  g.cell = cell;
  g.x0 = lo.x;
  g.y0 = lo.y;
  g.nx = std::max(1, static_cast<int>(std::ceil((hi.x - lo.x) / cell)));
  g.ny = std::max(1, static_cast<int>(std::ceil((hi.y - lo.y) / cell)));
  const std::vector<float> d_full = DistanceTransform(Draw(full, g, z0, z1), g);
  std::vector<float> d_building = DistanceTransform(Draw(building, g, z0, z1), g);
  const double band = 1.5 * cell + 0.005;  // > the transform's error bound, with room for rounding
  auto decide = [&](const FreeSpace& space, float d, long i) {
    if (d > radius + band) return true;
    if (d < radius - band) return false;
    ++out.exact;
    return space.Clearance(PlanShape::Disc(g.Centre(i), radius), z0, z1, 0.0).clearance >= 0.0;
  };
  out.cell.assign(g.size(), Cell::kBuilding);
  out.clearance = d_full;
  out.clearance_fixed = std::move(d_building);
  for (long i = 0; i < g.size(); ++i) {
    if (decide(full, d_full[i], i)) {
      out.cell[i] = Cell::kFree;
    } else if (decide(building, out.clearance_fixed[i], i)) {
      out.cell[i] = Cell::kObjects;
    }
  }
  return out;
}

WayGraph MakeWayGraph(std::vector<const LevelCells*> levels) {
  WayGraph g;
  g.levels = std::move(levels);
  g.offset.push_back(0);
  for (const LevelCells* l : g.levels) g.offset.push_back(g.offset.back() + l->grid.size());
  return g;
}

bool WayGraph::Locate(long node, int* level, long* cell) const {
  if (node >= offset.back()) return false;
  const int l = static_cast<int>(std::upper_bound(offset.begin(), offset.end(), node) - offset.begin()) - 1;
  *level = l;
  *cell = node - offset[l];
  return true;
}

Ways ShortestWays(const WayGraph& graph, const std::vector<long>& sources, double object_cost) {
  Ways w;
  const long n = graph.Nodes();
  constexpr float kInf = std::numeric_limits<float>::infinity();
  w.dist.assign(n, kInf);
  w.prev.assign(n, -1);
  using Item = std::pair<double, long>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
  std::vector<double> best(n, 1e300);  // doubles while searching, so long ways add up exactly enough
  for (long s : sources) {
    if (s < 0 || s >= n) continue;
    best[s] = 0.0;
    heap.push({0.0, s});
  }
  auto relax = [&](long from, long to, double cost, double d) {
    if (d + cost < best[to]) {
      best[to] = d + cost;
      w.prev[to] = static_cast<int32_t>(from);
      heap.push({best[to], to});
    }
  };
  const double diagonal = std::sqrt(2.0);
  while (!heap.empty()) {
    const auto [d, node] = heap.top();
    heap.pop();
    if (d > best[node]) continue;
    int level = 0;
    long cell = 0;
    if (!graph.Locate(node, &level, &cell)) {
      const WayGraph::Stair& s = graph.stairs[node - graph.offset.back()];
      for (long end : s.ends) {
        int l = 0;
        long c = 0;
        graph.Locate(end, &l, &c);
        const Cell state = graph.levels[l]->cell[c];
        if (state == Cell::kFree || (state == Cell::kObjects && std::isfinite(object_cost))) relax(node, end, 0.5 * s.length, d);
      }
      continue;
    }
    const LevelCells& lc = *graph.levels[level];
    const Grid& g = lc.grid;
    const int i = static_cast<int>(cell % g.nx), j = static_cast<int>(cell / g.nx);
    for (int dj = -1; dj <= 1; ++dj) {
      for (int di = -1; di <= 1; ++di) {
        if ((di == 0 && dj == 0) || i + di < 0 || j + dj < 0 || i + di >= g.nx || j + dj >= g.ny) continue;
        const long c = cell + static_cast<long>(dj) * g.nx + di;
        const Cell state = lc.cell[c];
        if (state == Cell::kBuilding || (state == Cell::kObjects && !std::isfinite(object_cost))) continue;
        const double step = g.cell * (di != 0 && dj != 0 ? diagonal : 1.0) * (state == Cell::kObjects ? object_cost : 1.0);
        relax(node, graph.offset[level] + c, step, d);
      }
    }
    if (auto it = graph.stairs_at.find(node); it != graph.stairs_at.end()) {
      for (int s : it->second) relax(node, graph.StairNode(s), 0.5 * graph.stairs[s].length, d);
    }
  }
  for (long k = 0; k < n; ++k) {
    if (best[k] < 1e299) w.dist[k] = static_cast<float>(best[k]);
  }
  return w;
}

std::vector<long> WayTo(const Ways& ways, long node) {
  std::vector<long> out;
  for (long k = node; k >= 0; k = ways.prev[k]) out.push_back(k);
  std::reverse(out.begin(), out.end());
  return out;
}

}  // namespace villa::solver
