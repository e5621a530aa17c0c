#include "mesh/mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>

namespace villa {

void Box3::Add(Vec3 p) {
  min = {std::min(min.x, p.x), std::min(min.y, p.y), std::min(min.z, p.z)};
  max = {std::max(max.x, p.x), std::max(max.y, p.y), std::max(max.z, p.z)};
}

void Box3::Add(const Box3& b) {
  if (b.empty()) return;
  Add(b.min);
  Add(b.max);
}

int TriangleMesh::AddVertex(Vec3 p, double weld, int first) {
  for (int i = static_cast<int>(vertices.size()) - 1; i >= first; --i) {
    const Vec3& v = vertices[i];
    if (std::abs(v.x - p.x) <= weld && std::abs(v.y - p.y) <= weld && std::abs(v.z - p.z) <= weld) return i;
  }
  vertices.push_back(p);
  return static_cast<int>(vertices.size()) - 1;
}

void TriangleMesh::Append(const TriangleMesh& other) {
  int offset = static_cast<int>(vertices.size());
  vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
  for (const auto& t : other.triangles) triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
}

Box3 TriangleMesh::Bounds() const {
  Box3 box;
  for (const Vec3& v : vertices) box.Add(v);
  return box;
}

double TriangleMesh::SignedVolume() const {
  double six_v = 0.0;
  for (const auto& t : triangles) six_v += Dot(vertices[t[0]], Cross(vertices[t[1]], vertices[t[2]]));
  return six_v / 6.0;
}

double TriangleMesh::SurfaceArea() const {
  double area = 0.0;
  for (const auto& t : triangles)
    area += Norm(Cross(vertices[t[1]] - vertices[t[0]], vertices[t[2]] - vertices[t[0]])) / 2.0;
  return area;
}

SolidCheck CheckSolid(const TriangleMesh& mesh, double weld) {
  // Weld by position on a grid of `weld` metres (the builder makes shared corners from one formula).
  std::map<std::tuple<long long, long long, long long>, int> ids;
  std::vector<int> id(mesh.vertices.size());
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec3& v = mesh.vertices[i];
    auto key = std::make_tuple(std::llround(v.x / weld), std::llround(v.y / weld), std::llround(v.z / weld));
    id[i] = ids.emplace(key, static_cast<int>(ids.size())).first->second;
  }
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{id[t[k]], id[t[(k + 1) % 3]]}];
  SolidCheck check;
  for (const auto& [edge, count] : directed) {
    auto reverse = directed.find({edge.second, edge.first});
    int back = reverse == directed.end() ? 0 : reverse->second;
    if (count > 1 || back > 1) ++check.non_manifold_edges;
    else if (back == 0) ++check.boundary_edges;
  }
  check.closed = check.boundary_edges == 0 && check.non_manifold_edges == 0 && !mesh.triangles.empty();
  check.volume = mesh.SignedVolume();
  return check;
}

std::vector<int> PieceRoots(const TriangleMesh& mesh) {
  std::vector<int> parent(mesh.vertices.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const auto& t : mesh.triangles) {
    parent[find(t[1])] = find(t[0]);
    parent[find(t[2])] = find(t[0]);
  }
  for (size_t v = 0; v < parent.size(); ++v) parent[v] = find(static_cast<int>(v));
  return parent;
}

std::vector<TriangleMesh> SplitPieces(const TriangleMesh& mesh) {
  const std::vector<int> root = PieceRoots(mesh);
  std::vector<int> piece_of(mesh.vertices.size(), -1), index(mesh.vertices.size(), -1);
  std::vector<TriangleMesh> out;
  for (const auto& t : mesh.triangles) {
    int& p = piece_of[root[t[0]]];
    if (p < 0) {
      p = static_cast<int>(out.size());
      out.emplace_back();
    }
    TriangleMesh& piece = out[p];
    std::array<int, 3> local;
    for (int k = 0; k < 3; ++k) {
      if (index[t[k]] < 0) {
        index[t[k]] = static_cast<int>(piece.vertices.size());
        piece.vertices.push_back(mesh.vertices[t[k]]);
      }
      local[k] = index[t[k]];
    }
    piece.triangles.push_back(local);
  }
  return out;
}

}  // namespace villa
