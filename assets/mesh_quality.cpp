#include "assets/mesh_quality.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace villa {
namespace {

// Cube coordinates packed into one key: 21 bits an axis, offset so that negatives fit. Cubes are at
// least 1/4096 of the longest side, so coordinates stay far inside the range.
std::uint64_t CubeKey(Vec3 p, double cell) {
  constexpr std::int64_t kOffset = std::int64_t{1} << 20;
  auto axis = [&](double v) { return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(v / cell)) + kOffset) & 0x1FFFFFu; };
  return axis(p.x) << 42 | axis(p.y) << 21 | axis(p.z);
}

}  // namespace

EdgeStatistics MeshEdgeStatistics(const AssetMesh& mesh) {
  constexpr double kWeld = 1e-6;  // m
  // Weld: sort the quantised positions, one id per distinct position.
  struct Corner {
    std::array<std::int64_t, 3> key;
    std::uint32_t index;  // over all parts
  };
  std::vector<Corner> corners;
  for (const AssetMeshPart& part : mesh.parts)
    for (const Vec3& p : part.mesh.vertices)
      corners.push_back({{std::llround(p.x / kWeld), std::llround(p.y / kWeld), std::llround(p.z / kWeld)},
                         static_cast<std::uint32_t>(corners.size())});
  std::sort(corners.begin(), corners.end(), [](const Corner& a, const Corner& b) { return a.key < b.key; });
  std::vector<std::uint32_t> id(corners.size());
  std::uint32_t next = 0;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    if (i > 0 && corners[i].key != corners[i - 1].key) ++next;
    id[corners[i].index] = next;
  }
  // Edges as sorted keys; runs of equal keys count the triangles using each.
  std::vector<std::uint64_t> edges;
  std::uint32_t base = 0;
  for (const AssetMeshPart& part : mesh.parts) {
    for (const auto& t : part.mesh.triangles) {
      std::uint32_t v[3] = {id[base + t[0]], id[base + t[1]], id[base + t[2]]};
      if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) continue;  // degenerate after welding: no edges
      for (int e = 0; e < 3; ++e) {
        std::uint64_t a = std::min(v[e], v[(e + 1) % 3]), b = std::max(v[e], v[(e + 1) % 3]);
        edges.push_back(a << 32 | b);
      }
    }
    base += static_cast<std::uint32_t>(part.mesh.vertices.size());
  }
  std::sort(edges.begin(), edges.end());
  EdgeStatistics s;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    ++s.edges;
    if (j - i == 1) ++s.boundary;
    else if (j - i == 2) ++s.two_sided;
    else ++s.non_manifold;
    i = j;
  }
  return s;
}

std::vector<std::vector<std::uint32_t>> SolidPieceIds(const AssetMesh& mesh) {
  // Union-find over every vertex of every part: a triangle's corners are one piece, and so are vertices
  // at one position (to 0.1 um: models split vertices for flat shading and between materials).
  std::vector<std::size_t> first(mesh.parts.size() + 1, 0);
  for (std::size_t k = 0; k < mesh.parts.size(); ++k) first[k + 1] = first[k] + mesh.parts[k].mesh.vertices.size();
  std::vector<std::uint32_t> parent(first.back());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = static_cast<std::uint32_t>(i);
  auto find = [&](std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  auto unite = [&](std::uint32_t a, std::uint32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  };
  struct PointHash {
    std::size_t operator()(const std::array<std::int64_t, 3>& p) const {
      return std::hash<std::int64_t>()(p[0] * 73856093 ^ p[1] * 19349663 ^ p[2] * 83492791);
    }
  };
  std::unordered_map<std::array<std::int64_t, 3>, std::uint32_t, PointHash> at;
  auto quantised = [](Vec3 v) {
    return std::array<std::int64_t, 3>{std::llround(v.x * 1e7), std::llround(v.y * 1e7), std::llround(v.z * 1e7)};
  };
  for (std::size_t k = 0; k < mesh.parts.size(); ++k) {
    const TriangleMesh& m = mesh.parts[k].mesh;
    for (std::size_t i = 0; i < m.vertices.size(); ++i) {
      const std::uint32_t id = static_cast<std::uint32_t>(first[k] + i);
      auto [it, fresh] = at.try_emplace(quantised(m.vertices[i]), id);
      if (!fresh) unite(it->second, id);
    }
    for (const auto& t : m.triangles) {
      unite(static_cast<std::uint32_t>(first[k] + t[0]), static_cast<std::uint32_t>(first[k] + t[1]));
      unite(static_cast<std::uint32_t>(first[k] + t[0]), static_cast<std::uint32_t>(first[k] + t[2]));
    }
  }
  std::vector<std::vector<std::uint32_t>> out(mesh.parts.size());
  for (std::size_t k = 0; k < mesh.parts.size(); ++k) {
    out[k].resize(mesh.parts[k].mesh.vertices.size());
    for (std::size_t i = 0; i < out[k].size(); ++i) out[k][i] = find(static_cast<std::uint32_t>(first[k] + i));
  }
  return out;
}

namespace {

// What clustering leaves of a piece: its area, its triangles and the volume its triangles enclose (signed,
// as cones from a point of the piece: the same point before and after, so a closed piece's volume).
struct Tally {
  double area = 0.0, volume = 0.0;
  int count = 0;
};

double Cone(Vec3 r, Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 u = a - r, v = b - r, w = c - r;
  return (u.x * (v.y * w.z - v.z * w.y) - u.y * (v.x * w.z - v.z * w.x) + u.z * (v.x * w.y - v.y * w.x)) / 6.0;
}

double Area(Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 u = b - a, v = c - a;
  return 0.5 * std::sqrt(std::pow(u.y * v.z - u.z * v.y, 2) + std::pow(u.z * v.x - u.x * v.z, 2) + std::pow(u.x * v.y - u.y * v.x, 2));
}

// ClusterVertices with the pieces of `thin` kept as they are too; `kept` (when given) sums the area and
// the count of the triangles each piece keeps.
AssetMesh Cluster(const AssetMesh& mesh, double cell, const std::vector<std::vector<std::uint32_t>>* pieces,
                  const std::unordered_set<std::uint32_t>& thin, std::unordered_map<std::uint32_t, Tally>* kept,
                  const std::unordered_map<std::uint32_t, Vec3>* origin) {
  // Every occupied cube once (of each piece, with `pieces`), with the sum of its vertices (over all parts).
  struct KeyHash {
    std::size_t operator()(const std::pair<std::uint64_t, std::uint32_t>& k) const {
      return std::hash<std::uint64_t>()(k.first * 0x9E3779B97F4A7C15ull ^ k.second);
    }
  };
  std::unordered_map<std::pair<std::uint64_t, std::uint32_t>, std::uint32_t, KeyHash> cube_of;
  std::vector<Vec3> sums;
  std::vector<int> counts;
  std::vector<std::vector<std::uint32_t>> vertex_cube(mesh.parts.size());
  // A piece that would fall into fewer than four cubes (a bed's leg, a handle) would collapse to a sliver or
  // vanish, and a simulator's bed sank 10 cm onto its frame: such a piece keeps its own vertices.
  std::unordered_set<std::uint32_t> exact = thin;
  if (pieces) {
    std::unordered_map<std::uint32_t, std::unordered_set<std::uint64_t>> cubes;
    for (std::size_t k = 0; k < mesh.parts.size(); ++k)
      for (std::size_t i = 0; i < mesh.parts[k].mesh.vertices.size(); ++i) {
        std::unordered_set<std::uint64_t>& c = cubes[(*pieces)[k][i]];
        if (c.size() < 4) c.insert(CubeKey(mesh.parts[k].mesh.vertices[i], cell));
      }
    for (const auto& [piece, c] : cubes)
      if (c.size() < 4) exact.insert(piece);
  }
  std::uint64_t own = 0;  // a kept vertex's own key
  for (std::size_t k = 0; k < mesh.parts.size(); ++k) {
    const auto& vertices = mesh.parts[k].mesh.vertices;
    vertex_cube[k].resize(vertices.size());
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      const std::uint32_t piece = pieces ? (*pieces)[k][i] : 0u;
      const bool keep = pieces && exact.count(piece);
      const std::pair<std::uint64_t, std::uint32_t> key{keep ? own++ : CubeKey(vertices[i], cell), keep ? piece | 0x80000000u : piece};
      auto [it, fresh] = cube_of.try_emplace(key, static_cast<std::uint32_t>(sums.size()));
      if (fresh) {
        sums.push_back({});
        counts.push_back(0);
      }
      sums[it->second] = sums[it->second] + vertices[i];
      ++counts[it->second];
      vertex_cube[k][i] = it->second;
    }
  }
  AssetMesh out;
  std::vector<int> local(sums.size(), -1);
  for (std::size_t k = 0; k < mesh.parts.size(); ++k) {
    const AssetMeshPart& part = mesh.parts[k];
    AssetMeshPart simple;
    simple.material = part.material;
    std::vector<std::uint32_t> touched;
    auto vertex = [&](int original) {
      std::uint32_t cube = vertex_cube[k][original];
      if (local[cube] < 0) {
        local[cube] = static_cast<int>(simple.mesh.vertices.size());
        simple.mesh.vertices.push_back(sums[cube] * (1.0 / counts[cube]));
        touched.push_back(cube);
      }
      return local[cube];
    };
    std::unordered_set<std::uint64_t> seen;
    for (const auto& t : part.mesh.triangles) {
      int a = vertex(t[0]), b = vertex(t[1]), c = vertex(t[2]);
      if (a == b || b == c || a == c) continue;
      // The same three corners in the same turning sense are one triangle: rotate the smallest first.
      int first = std::min({a, b, c});
      std::array<std::uint64_t, 3> r = first == a ? std::array<std::uint64_t, 3>{std::uint64_t(a), std::uint64_t(b), std::uint64_t(c)}
                                      : first == b ? std::array<std::uint64_t, 3>{std::uint64_t(b), std::uint64_t(c), std::uint64_t(a)}
                                                   : std::array<std::uint64_t, 3>{std::uint64_t(c), std::uint64_t(a), std::uint64_t(b)};
      if (!seen.insert(r[0] << 42 | r[1] << 21 | r[2]).second) continue;  // parts hold < 2^21 vertices
      simple.mesh.AddTriangle(a, b, c);
      if (kept && pieces) {
        const std::uint32_t piece = (*pieces)[k][t[0]];
        Tally& tally = (*kept)[piece];
        const Vec3 &pa = simple.mesh.vertices[a], &pb = simple.mesh.vertices[b], &pc = simple.mesh.vertices[c];
        tally.area += Area(pa, pb, pc);
        tally.volume += Cone(origin->at(piece), pa, pb, pc);
        ++tally.count;
      }
    }
    for (std::uint32_t cube : touched) local[cube] = -1;
    // Vertices no triangle uses any more are left in place: harmless, and rare.
    if (!simple.mesh.triangles.empty()) out.parts.push_back(std::move(simple));
  }
  return out;
}

}  // namespace

AssetMesh ClusterVertices(const AssetMesh& mesh, double cell, const std::vector<std::vector<std::uint32_t>>* pieces) {
  if (!pieces) return Cluster(mesh, cell, nullptr, {}, nullptr, nullptr);
  // A piece clustering would all but erase (a thin tube frame, a tap: 21,632 triangles to 216, and the
  // simulator's bed sank 10 cm onto its mattress) keeps its triangles.
  std::unordered_map<std::uint32_t, Tally> before, kept;
  std::unordered_map<std::uint32_t, Vec3> origin;
  for (std::size_t k = 0; k < mesh.parts.size(); ++k) {
    const TriangleMesh& m = mesh.parts[k].mesh;
    for (const auto& t : m.triangles) {
      const std::uint32_t piece = (*pieces)[k][t[0]];
      const Vec3 r = origin.try_emplace(piece, m.vertices[t[0]]).first->second;
      Tally& tally = before[piece];
      tally.area += Area(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]);
      tally.volume += Cone(r, m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]);
      ++tally.count;
    }
  }
  AssetMesh out = Cluster(mesh, cell, pieces, {}, &kept, &origin);
  // Erased: less than half its area left, or half the volume it encloses (a tube flattened to a ribbon
  // keeps most of its area), or fewer than a quarter of the share of triangles the whole mesh keeps.
  const double share = static_cast<double>(out.TriangleCount()) / std::max(1, mesh.TriangleCount());
  std::unordered_set<std::uint32_t> thin;
  for (const auto& [piece, was] : before) {
    const Tally& now = kept[piece];
    const bool encloses = std::abs(was.volume) > 1e-4 * was.area;  // thicker than 0.1 mm on average: a solid, not a sheet
    if (now.area < 0.5 * was.area || (encloses && std::abs(now.volume) < 0.5 * std::abs(was.volume)) ||
        now.count < 0.25 * share * was.count)
      thin.insert(piece);
  }
  return thin.empty() ? out : Cluster(mesh, cell, pieces, thin, nullptr, nullptr);
}

namespace {

// `simple` moved and stretched along each axis so that its box is `box` again: a cluster's vertex is the
// mean of its cube's, so a model's bottom rose off the floor (a bed floating 2 cm) and its sides came in.
void KeepBox(AssetMesh& simple, const Box3& box) {
  const Box3 now = simple.Bounds();
  auto fit = [](double v, double lo, double hi, double to_lo, double to_hi) {
    return hi - lo > 1e-12 ? to_lo + (v - lo) * (to_hi - to_lo) / (hi - lo) : v;
  };
  for (AssetMeshPart& part : simple.parts)
    for (Vec3& v : part.mesh.vertices)
      v = {fit(v.x, now.min.x, now.max.x, box.min.x, box.max.x), fit(v.y, now.min.y, now.max.y, box.min.y, box.max.y),
           fit(v.z, now.min.z, now.max.z, box.min.z, box.max.z)};
}

}  // namespace

Result<AssetMesh> DecimateToBudget(const AssetMesh& mesh, int max_triangles, bool best_effort) {
  if (mesh.TriangleCount() <= max_triangles) return mesh;
  Box3 box = mesh.Bounds();
  double longest = std::max({box.max.x - box.min.x, box.max.y - box.min.y, box.max.z - box.min.z});
  if (!(longest > 0)) return Error{"decimation: the mesh has no extent"};
  double fine = longest / 4096, coarse = longest / 4;
  // Each solid piece clustered on its own first (issue 31: a bookcase's shelves and sides fused into one
  // piece, whose hull in a simulator swallowed its books; twice as many pieces moved on the rooms bench);
  // cubes shared by all pieces when that cannot meet the budget (a plant of a thousand leaves).
  const std::vector<std::vector<std::uint32_t>> ids = SolidPieceIds(mesh);
  const std::vector<std::vector<std::uint32_t>>* pieces = &ids;
  AssetMesh best = ClusterVertices(mesh, coarse, pieces);
  if (best.TriangleCount() > max_triangles && best_effort && best.TriangleCount() < mesh.TriangleCount()) {
    // The thin pieces kept leave more than the budget: as near to it as they allow.
    max_triangles = static_cast<int>(1.25 * best.TriangleCount());
  } else if (best.TriangleCount() > max_triangles) {
    pieces = nullptr;
    best = ClusterVertices(mesh, coarse, nullptr);
  }
  if (best.TriangleCount() > max_triangles)
    return Error{"decimation: even cubes of " + std::to_string(coarse) + " m leave " +
                 std::to_string(best.TriangleCount()) + " triangles, over the budget of " + std::to_string(max_triangles)};
  // Bisection on the logarithm of the cube size (the triangle count falls, roughly, as cubes grow), to
  // within 3 % of the finest size that meets the budget.
  while (coarse / fine > 1.03) {
    double middle = std::sqrt(fine * coarse);
    AssetMesh trial = ClusterVertices(mesh, middle, pieces);
    if (trial.TriangleCount() <= max_triangles) {
      coarse = middle;
      best = std::move(trial);
    } else {
      fine = middle;
    }
  }
  KeepBox(best, box);
  return best;
}

}  // namespace villa
