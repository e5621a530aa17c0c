#include "mesh/mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <numeric>
#include <tuple>
#include <unordered_map>

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

namespace {

// Hash of a few 64-bit words (the keys ShadeSmooth welds by).
struct WordsHash {
  template <size_t N>
  size_t operator()(const std::array<std::int64_t, N>& words) const {
    std::uint64_t h = 1469598103934665603ull;
    for (std::int64_t w : words) h = (h ^ static_cast<std::uint64_t>(w)) * 1099511628211ull;
    return static_cast<size_t>(h ^ (h >> 29));
  }
};

std::int64_t Bits(double v) {
  if (v == 0.0) v = 0.0;  // -0 and +0 weld
  std::int64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

}  // namespace

ShadedMesh ShadeSmooth(const TriangleMesh& mesh, double crease_deg) {
  ShadedMesh out;
  const size_t faces = mesh.triangles.size();
  std::vector<Vec3> unit(faces);  // each face's unit normal, 0 for a degenerate face
  std::vector<std::array<double, 3>> angle(faces);  // its interior angle at each corner
  for (size_t t = 0; t < faces; ++t) {
    const auto& f = mesh.triangles[t];
    const Vec3 n = Cross(mesh.vertices[f[1]] - mesh.vertices[f[0]], mesh.vertices[f[2]] - mesh.vertices[f[0]]);
    unit[t] = Norm(n) > 0.0 ? Normalized(n) : Vec3{};
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = Normalized(mesh.vertices[f[(k + 1) % 3]] - mesh.vertices[f[k]]);
      const Vec3 b = Normalized(mesh.vertices[f[(k + 2) % 3]] - mesh.vertices[f[k]]);
      angle[t][k] = std::acos(std::clamp(Dot(a, b), -1.0, 1.0));
    }
  }
  // Positions welded exactly, and the face corners round each.
  std::unordered_map<std::array<std::int64_t, 3>, int, WordsHash> where;
  std::vector<int> position(mesh.vertices.size());
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Vec3& p = mesh.vertices[v];
    position[v] = where.emplace(std::array<std::int64_t, 3>{Bits(p.x), Bits(p.y), Bits(p.z)}, static_cast<int>(where.size())).first->second;
  }
  std::vector<std::vector<std::pair<int, int>>> around(where.size());  // face, corner
  for (size_t t = 0; t < faces; ++t)
    for (int k = 0; k < 3; ++k) around[position[mesh.triangles[t][k]]].push_back({static_cast<int>(t), k});
  const double cos_crease = std::cos(crease_deg * 3.14159265358979323846 / 180.0) - 1e-12;
  // (position, normal to 1e-5) -> vertex of the result.
  std::unordered_map<std::array<std::int64_t, 4>, int, WordsHash> shared;
  out.triangles.reserve(faces);
  for (size_t t = 0; t < faces; ++t) {
    std::array<int, 3> corner{};
    const bool degenerate = Norm(unit[t]) == 0.0;
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles[t][k], at = position[v];
      // The faces round the position within the crease of this one, each weighted by its angle there (so a
      // quad's two triangles count as the quad, whichever way it was cut).
      Vec3 sum{};
      for (const auto& [f, c] : around[at])
        if (degenerate || Dot(unit[f], unit[t]) >= cos_crease) sum = sum + unit[f] * angle[f][c];
      const Vec3 n = Norm(sum) > 0.0 ? Normalized(sum) : degenerate ? Vec3{0.0, 0.0, 1.0} : unit[t];
      const std::array<std::int64_t, 4> key{at, std::llround(n.x * 1e5), std::llround(n.y * 1e5), std::llround(n.z * 1e5)};
      auto [it, added] = shared.emplace(key, static_cast<int>(out.vertices.size()));
      if (added) {
        out.vertices.push_back(mesh.vertices[v]);
        out.normals.push_back(n);
      }
      corner[k] = it->second;
    }
    out.triangles.push_back(corner);
  }
  return out;
}

}  // namespace villa
