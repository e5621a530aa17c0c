#include "assets/mesh_quality.h"

#include <algorithm>
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

AssetMesh ClusterVertices(const AssetMesh& mesh, double cell) {
  // Every occupied cube once, with the sum of its vertices (over all parts).
  std::unordered_map<std::uint64_t, std::uint32_t> cube_of;
  std::vector<Vec3> sums;
  std::vector<int> counts;
  std::vector<std::vector<std::uint32_t>> vertex_cube(mesh.parts.size());
  for (std::size_t k = 0; k < mesh.parts.size(); ++k) {
    const auto& vertices = mesh.parts[k].mesh.vertices;
    vertex_cube[k].resize(vertices.size());
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      auto [it, fresh] = cube_of.try_emplace(CubeKey(vertices[i], cell), static_cast<std::uint32_t>(sums.size()));
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
    }
    for (std::uint32_t cube : touched) local[cube] = -1;
    // Vertices no triangle uses any more are left in place: harmless, and rare.
    if (!simple.mesh.triangles.empty()) out.parts.push_back(std::move(simple));
  }
  return out;
}

Result<AssetMesh> DecimateToBudget(const AssetMesh& mesh, int max_triangles) {
  if (mesh.TriangleCount() <= max_triangles) return mesh;
  Box3 box = mesh.Bounds();
  double longest = std::max({box.max.x - box.min.x, box.max.y - box.min.y, box.max.z - box.min.z});
  if (!(longest > 0)) return Error{"decimation: the mesh has no extent"};
  double fine = longest / 4096, coarse = longest / 4;
  AssetMesh best = ClusterVertices(mesh, coarse);
  if (best.TriangleCount() > max_triangles)
    return Error{"decimation: even cubes of " + std::to_string(coarse) + " m leave " +
                 std::to_string(best.TriangleCount()) + " triangles, over the budget of " + std::to_string(max_triangles)};
  // Bisection on the logarithm of the cube size (the triangle count falls, roughly, as cubes grow), to
  // within 3 % of the finest size that meets the budget.
  while (coarse / fine > 1.03) {
    double middle = std::sqrt(fine * coarse);
    AssetMesh trial = ClusterVertices(mesh, middle);
    if (trial.TriangleCount() <= max_triangles) {
      coarse = middle;
      best = std::move(trial);
    } else {
      fine = middle;
    }
  }
  return best;
}

}  // namespace villa
