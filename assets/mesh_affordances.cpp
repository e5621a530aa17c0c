#include "assets/mesh_affordances.h"

#include <algorithm>
#include <cmath>
#include <deque>

#include "mesh/ray_caster.h"

namespace villa {
namespace {

constexpr Vec3 kUp{0, 0, 1};
constexpr Vec3 kDown{0, 0, -1};
constexpr double kLift = 1e-3;  // m: rays start this far off the face they leave

// A raster of the asset's footprint (cells of `cell` m), for the area a level covers and its pieces.
class Footprint {
 public:
  Footprint(Vec3 size, double cell) : cell_(cell) {
    x0_ = -size.x / 2 - cell;
    y0_ = -size.y / 2 - cell;
    nx_ = static_cast<int>(std::ceil(size.x / cell)) + 2;
    ny_ = static_cast<int>(std::ceil(size.y / cell)) + 2;
    on_.assign(static_cast<std::size_t>(nx_) * ny_, 0);
  }
  double cell() const { return cell_; }
  int nx() const { return nx_; }
  int ny() const { return ny_; }
  Point Centre(int i, int j) const { return {x0_ + (i + 0.5) * cell_, y0_ + (j + 0.5) * cell_}; }
  bool On(int i, int j) const { return on_[Index(i, j)] != 0; }
  void Set(int i, int j) { on_[Index(i, j)] = 1; }
  int Column(double x) const { return std::clamp(static_cast<int>(std::floor((x - x0_) / cell_)), 0, nx_ - 1); }
  int Row(double y) const { return std::clamp(static_cast<int>(std::floor((y - y0_) / cell_)), 0, ny_ - 1); }

  // Marks the cells whose centre lies in the triangle's shadow, and the cell of its centroid (so a
  // triangle smaller than a cell still counts).
  void Fill(Vec3 a, Vec3 b, Vec3 c) {
    auto edge = [](Point p, Point q, Point r) { return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x); };
    Point pa{a.x, a.y}, pb{b.x, b.y}, pc{c.x, c.y};
    double area = edge(pa, pb, pc);
    int i0 = Column(std::min({a.x, b.x, c.x})), i1 = Column(std::max({a.x, b.x, c.x}));
    int j0 = Row(std::min({a.y, b.y, c.y})), j1 = Row(std::max({a.y, b.y, c.y}));
    if (area != 0.0) {
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
          Point p = Centre(i, j);
          double u = edge(pb, pc, p) / area, v = edge(pc, pa, p) / area, w = edge(pa, pb, p) / area;
          if (u >= 0 && v >= 0 && w >= 0) Set(i, j);
        }
    }
    Set(Column((a.x + b.x + c.x) / 3), Row((a.y + b.y + c.y) / 3));
  }

  // 8-connected pieces of the marked cells, each as its cells (i, j).
  std::vector<std::vector<std::pair<int, int>>> Pieces() const {
    std::vector<std::vector<std::pair<int, int>>> out;
    std::vector<char> seen(on_.size(), 0);
    for (int j = 0; j < ny_; ++j)
      for (int i = 0; i < nx_; ++i) {
        if (!On(i, j) || seen[Index(i, j)]) continue;
        std::vector<std::pair<int, int>> piece;
        std::deque<std::pair<int, int>> queue{{i, j}};
        seen[Index(i, j)] = 1;
        while (!queue.empty()) {
          auto [ci, cj] = queue.front();
          queue.pop_front();
          piece.push_back({ci, cj});
          for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di) {
              int ni = ci + di, nj = cj + dj;
              if (ni < 0 || nj < 0 || ni >= nx_ || nj >= ny_ || !On(ni, nj) || seen[Index(ni, nj)]) continue;
              seen[Index(ni, nj)] = 1;
              queue.push_back({ni, nj});
            }
        }
        out.push_back(std::move(piece));
      }
    return out;
  }

  // Convex hull of a piece's cells (their outer corners), counter-clockwise.
  Ring Hull(const std::vector<std::pair<int, int>>& cells) const {
    std::vector<Point> points;
    std::vector<int> lo(ny_, nx_), hi(ny_, -1);
    for (auto [i, j] : cells) {
      lo[j] = std::min(lo[j], i);
      hi[j] = std::max(hi[j], i);
    }
    for (int j = 0; j < ny_; ++j) {
      if (hi[j] < 0) continue;
      double ya = y0_ + j * cell_, yb = ya + cell_;
      double xa = x0_ + lo[j] * cell_, xb = x0_ + (hi[j] + 1) * cell_;
      points.insert(points.end(), {{xa, ya}, {xa, yb}, {xb, ya}, {xb, yb}});
    }
    std::sort(points.begin(), points.end(), [](const Point& p, const Point& q) { return p.x < q.x || (p.x == q.x && p.y < q.y); });
    auto cross = [](Point o, Point a, Point b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); };
    std::vector<Point> hull(2 * points.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
      hull[k++] = points[i];
    }
    for (std::size_t i = points.size() - 1, t = k + 1; i-- > 0;) {
      while (k >= t && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
      hull[k++] = points[i];
    }
    hull.resize(k > 0 ? k - 1 : 0);
    return hull;
  }

 private:
  std::size_t Index(int i, int j) const { return static_cast<std::size_t>(j) * nx_ + i; }
  double cell_, x0_, y0_;
  int nx_, ny_;
  std::vector<char> on_;
};

double CellFor(Vec3 size) { return std::max(0.01, std::max(size.x, size.y) / 300.0); }

// A surface found in the geometry, before it is written: its cells give the samples for clear height.
struct Level {
  double z = 0.0;
  Ring polygon;
  std::vector<Vec3> samples;   // cell centres spread over the piece, at the height of the geometry there
  std::string from;
  double area = 0.0;  // m2 covered
};

// `height(i, j)`: where the geometry is in that cell (a drop surface's cushions rise above its height).
template <class Height>
std::vector<Vec3> Samples(const Footprint& grid, const std::vector<std::pair<int, int>>& cells, Height&& height) {
  std::vector<Vec3> out;
  std::size_t stride = std::max<std::size_t>(1, cells.size() / 16);
  for (std::size_t k = stride / 2; k < cells.size(); k += stride) {
    auto [i, j] = cells[k];
    Point p = grid.Centre(i, j);
    out.push_back({p.x, p.y, height(i, j)});
  }
  return out;
}

template <class Height>
void AddPieces(const Footprint& grid, double z, const std::string& from, const AffordanceOptions& o, Height&& height,
               std::vector<Level>* out) {
  double cell_area = grid.cell() * grid.cell();
  for (const auto& cells : grid.Pieces()) {
    double area = cells.size() * cell_area;
    if (area < o.min_part_area) continue;
    Level level{z, grid.Hull(cells), Samples(grid, cells, height), from, area};
    if (level.polygon.size() < 3) continue;
    Box3 box;
    for (const Point& p : level.polygon) box.Add(Vec3{p.x, p.y, 0});
    if (std::min(box.max.x - box.min.x, box.max.y - box.min.y) < o.min_part_width) continue;  // a rim, an edge
    out->push_back(std::move(level));
  }
}

// Clear height above a level: the 10th percentile of upward hits from its samples; the storey's clear
// height above it when fewer than half the samples hit anything (a top surface, `*top` set).
double ClearHeight(const RayCaster& rays, const Level& level, const AffordanceOptions& o, bool* top) {
  std::vector<double> hits;
  for (const Vec3& p : level.samples)
    if (auto hit = rays.Cast(p + Vec3{0, 0, kLift}, kUp, 1e6)) hits.push_back(p.z - level.z + hit->t + kLift);
  *top = hits.size() * 2 < level.samples.size();
  if (*top) return std::max(o.storey_clear_height - level.z, o.min_clearance);
  std::sort(hits.begin(), hits.end());
  return hits[hits.size() / 10];
}

// Mesh levels: horizontal faces with free space above (a face under a board, or inside a solid, has the
// board or the solid's far side right above it), grouped by height, kept when they cover enough.
std::vector<Level> MeshLevels(const TriangleMesh& mesh, const RayCaster& rays, Vec3 size, double orientation,
                              const AffordanceOptions& o) {
  struct Candidate {
    double z;
    int triangle;
    double area;
  };
  std::vector<Candidate> candidates;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Vec3 &a = mesh.vertices[mesh.triangles[t][0]], &b = mesh.vertices[mesh.triangles[t][1]],
               &c = mesh.vertices[mesh.triangles[t][2]];
    Vec3 n = Cross(b - a, c - a);
    double twice_area = Norm(n);
    if (twice_area <= 0 || std::abs(n.z) / twice_area <= o.min_normal_z) continue;
    Vec3 centroid = (a + b + c) * (1.0 / 3);
    if (centroid.z < o.min_z) continue;
    // Four probes: the centroid and the points halfway to each corner; a face counts when at least two
    // have room above (a large shelf face stays a surface where a divider stands on part of it).
    int clear = 0;
    for (const Vec3& p : {centroid, (centroid + a) * 0.5, (centroid + b) * 0.5, (centroid + c) * 0.5}) {
      auto hit = rays.Cast(p + Vec3{0, 0, kLift}, kUp, 1e6);
      // Room above: nothing, or the first face met looks down at it (a face that looks up, along the
      // ray, is the far side of a solid the probe started inside).
      if (!hit || (hit->t + kLift >= o.min_clearance && orientation * hit->normal.z <= 0.5)) ++clear;
    }
    if (clear < 2) continue;
    candidates.push_back({centroid.z, static_cast<int>(t), twice_area / 2});
  }
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& p, const Candidate& q) { return p.z < q.z; });

  std::vector<Level> levels;
  const double footprint = size.x * size.y;
  for (std::size_t begin = 0; begin < candidates.size();) {
    std::size_t end = begin;
    double weighted = 0, total = 0;
    while (end < candidates.size() && candidates[end].z - candidates[begin].z <= o.bin) {
      weighted += candidates[end].z * candidates[end].area;
      total += candidates[end].area;
      ++end;
    }
    Footprint grid(size, CellFor(size));
    for (std::size_t k = begin; k < end; ++k) {
      const auto& tri = mesh.triangles[candidates[k].triangle];
      grid.Fill(mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]]);
    }
    double z = total > 0 ? weighted / total : candidates[begin].z;
    std::vector<Level> pieces;
    AddPieces(grid, z, "mesh", o, [z](int, int) { return z; }, &pieces);
    double covered = 0;
    for (const Level& l : pieces) covered += l.area;
    if (covered >= o.min_share * footprint)
      for (Level& l : pieces) levels.push_back(std::move(l));
    begin = end;
  }
  return levels;
}

// The drop surface: where rays from just above the drop height first meet near-horizontal geometry
// within the tolerance of that height.
std::vector<Level> DropLevels(const RayCaster& rays, Vec3 size, double drop, double min_share, const AffordanceOptions& o) {
  Footprint grid(size, std::max(CellFor(size), std::max(size.x, size.y) / 100.0));
  std::vector<double> heights(static_cast<std::size_t>(grid.nx()) * grid.ny(), drop);
  double start = std::min(drop + o.min_clearance, size.z + o.min_clearance);
  for (int j = 0; j < grid.ny(); ++j)
    for (int i = 0; i < grid.nx(); ++i) {
      Point p = grid.Centre(i, j);
      if (std::abs(p.x) > size.x / 2 || std::abs(p.y) > size.y / 2) continue;
      auto hit = rays.Cast({p.x, p.y, start}, kDown, start + 1.0);
      if (!hit || std::abs(hit->normal.z) < 0.7) continue;
      double z = start - hit->t;
      if (std::abs(z - drop) > o.drop_tolerance) continue;
      grid.Set(i, j);
      heights[static_cast<std::size_t>(j) * grid.nx() + i] = std::max(z, drop);
    }
  std::vector<Level> pieces;
  AddPieces(grid, drop, "drop_on_top", o, [&](int i, int j) { return heights[static_cast<std::size_t>(j) * grid.nx() + i]; },
            &pieces);
  double covered = 0;
  for (const Level& l : pieces) covered += l.area;
  if (covered < min_share * size.x * size.y) return {};
  return pieces;
}

// Empty boxes above a covered surface: the surface's box split where probes along x meet geometry
// (dividers), each part then trimmed to where probes along y and z first meet geometry.
std::vector<Cavity> CavitiesAbove(const RayCaster& rays, const SupportSurface& s, int index, Vec3 size, const AffordanceOptions& o) {
  Box3 box;
  for (const Point& p : s.polygon) box.Add(Vec3{p.x, p.y, 0});
  double x0 = box.min.x + o.margin, x1 = box.max.x - o.margin;
  double y0 = box.min.y + o.margin, y1 = box.max.y - o.margin;
  double z0 = s.z + o.margin, z1 = s.z + s.clear_height - o.margin;
  const Vec3& m = o.min_cavity;
  if (x1 - x0 < m.x || y1 - y0 < m.y || z1 - z0 < m.z) return {};
  auto at = [](double lo, double hi, double f) { return lo + (hi - lo) * f; };
  const double kProbe[3] = {0.2, 0.5, 0.8};

  std::vector<double> walls{x0, x1};
  for (double fy : kProbe)
    for (double fz : kProbe) {
      Vec3 origin{x0, at(y0, y1, fy), at(z0, z1, fz)};
      for (double t : rays.Crossings(origin, {1, 0, 0}, x1 - x0)) walls.push_back(x0 + t);
    }
  std::sort(walls.begin(), walls.end());

  std::vector<Cavity> out;
  for (std::size_t k = 0; k + 1 < walls.size(); ++k) {
    double a = walls[k] + (k == 0 ? 0 : o.margin), b = walls[k + 1] - (k + 2 == walls.size() ? 0 : o.margin);
    if (b - a < m.x) continue;
    double back = y1, top = z1;
    int roofed = 0;
    for (double fx : kProbe) {
      double x = at(a, b, fx);
      for (double f : kProbe) {
        for (double t : rays.Crossings({x, y0, at(z0, z1, f)}, {0, 1, 0}, y1 - y0)) back = std::min(back, y0 + t - o.margin);
        auto up = rays.Crossings({x, at(y0, y1, f), z0}, kUp, z1 - z0 + o.margin + 0.02);
        if (!up.empty()) {
          top = std::min(top, z0 + up.front() - o.margin);
          ++roofed;
        }
      }
    }
    if (back - y0 < m.y || top - z0 < m.z || roofed * 3 < 9 * 2) continue;  // most probes must meet a roof
    Cavity c;
    c.min = {a, y0, z0};
    c.max = {b, back, top};
    c.floor_surface = index;
    int open = 0;
    for (double fx : kProbe) {
      Vec3 origin{at(a, b, fx), y0, (z0 + top) / 2};
      if (!rays.Cast(origin, {0, -1, 0}, y0 + size.y / 2 + 0.01)) ++open;
    }
    c.open = open == 3 ? "-y" : "closed";
    out.push_back(c);
  }
  return out;
}

}  // namespace

std::string AffordanceOptions::Check() const {
  if (!(min_normal_z > 0 && min_normal_z <= 1)) return "min_normal_z must be in (0, 1]";
  if (!(bin > 0)) return "bin must be > 0 m";
  if (!(min_share > 0 && min_share <= 1)) return "min_share must be in (0, 1]";
  if (!(min_clearance > 0)) return "min_clearance must be > 0 m";
  if (!(min_part_area >= 0)) return "min_part_area must be >= 0 m2";
  if (!(min_part_width >= 0)) return "min_part_width must be >= 0 m";
  if (!(min_z >= 0)) return "min_z must be >= 0 m";
  if (!(storey_clear_height > 0)) return "storey_clear_height must be > 0 m";
  if (!(drop_tolerance > 0)) return "drop_tolerance must be > 0 m";
  if (!(min_drop_share > 0 && min_drop_share <= 1)) return "min_drop_share must be in (0, 1]";
  if (!(min_cavity.x > 0 && min_cavity.y > 0 && min_cavity.z > 0)) return "min_cavity sides must be > 0 m";
  if (!(margin >= 0)) return "margin must be >= 0 m";
  return "";
}

MeshAffordances AffordancesFromMesh(const TriangleMesh& mesh, Vec3 size, std::optional<double> drop_on_top,
                                    const AffordanceOptions& o) {
  MeshAffordances out;
  if (mesh.triangles.empty() || !(size.x > 0 && size.y > 0 && size.z > 0)) return out;
  RayCaster rays(mesh);
  // Models are mostly wound outward; a mesh with a negative volume is wound the other way throughout.
  double orientation = mesh.SignedVolume() < 0 ? -1.0 : 1.0;

  std::vector<Level> levels = MeshLevels(mesh, rays, size, orientation, o);
  // SH3D's drop height: given, it is a surface where the geometry has one there; not given, SH3D drops
  // on the top, which the mesh levels already find.
  if (drop_on_top && *drop_on_top >= o.min_z) {
    std::vector<Level> drop = DropLevels(rays, size, std::min(*drop_on_top, size.z), o.min_drop_share, o);
    if (!drop.empty()) {
      std::erase_if(levels, [&](const Level& l) { return std::abs(l.z - drop.front().z) <= o.drop_tolerance; });
      levels.insert(levels.end(), drop.begin(), drop.end());
    }
  } else if (!drop_on_top) {
    for (Level& l : levels)
      if (std::abs(l.z - size.z) <= o.drop_tolerance) l.from = "drop_on_top";
  }
  std::sort(levels.begin(), levels.end(), [](const Level& a, const Level& b) {
    return a.z != b.z ? a.z < b.z : a.polygon.front().x < b.polygon.front().x;
  });

  std::vector<bool> covered;
  for (const Level& level : levels) {
    bool top = false;
    double clear = ClearHeight(rays, level, o, &top);
    if (clear < o.min_clearance) continue;
    out.surfaces.push_back({level.z, level.polygon, clear, level.from});
    covered.push_back(!top);
  }
  for (std::size_t i = 0; i < out.surfaces.size(); ++i) {
    if (!covered[i]) continue;
    for (Cavity& c : CavitiesAbove(rays, out.surfaces[i], static_cast<int>(i), size, o)) out.cavities.push_back(c);
  }
  return out;
}

}  // namespace villa
