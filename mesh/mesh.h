#pragma once
// Triangle meshes of the built villa, in the building frame: metres, x and y exactly as in the layout's
// plan, z up (z = 0 is the underside of the ground slab). Exporters turn this into glTF's +Y-up frame.
// Triangles are counter-clockwise seen from outside, so a closed mesh has outward normals.
#include <array>
#include <cmath>
#include <vector>

namespace villa {

struct Vec3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
  friend bool operator==(const Vec3&, const Vec3&) = default;
};
inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(Vec3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline double Dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 Cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline double Norm(Vec3 a) { return std::sqrt(Dot(a, a)); }
inline Vec3 Normalized(Vec3 a) {
  double n = Norm(a);
  return n > 0.0 ? a * (1.0 / n) : a;
}

struct Box3 {
  Vec3 min{1e300, 1e300, 1e300};
  Vec3 max{-1e300, -1e300, -1e300};
  bool empty() const { return min.x > max.x; }
  void Add(Vec3 p);
  void Add(const Box3& b);
};

struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;  // indices into vertices, CCW from outside

  // Index of a vertex at `p`: an existing one within `weld` metres (searched from `first`), else a new one.
  int AddVertex(Vec3 p, double weld = 1e-9, int first = 0);
  void AddTriangle(int a, int b, int c) { triangles.push_back({a, b, c}); }
  // Appends another mesh (its vertices copied, not welded).
  void Append(const TriangleMesh& other);
  Box3 Bounds() const;
  double SignedVolume() const;  // > 0 for a closed mesh with outward normals, m3
  double SurfaceArea() const;   // m2
};

// For every vertex, the root vertex of its piece (triangles joined through shared vertex indices).
std::vector<int> PieceRoots(const TriangleMesh& mesh);
// The mesh split into those pieces, each with its own vertices (the ones its triangles use), in the order
// of their first triangle.
std::vector<TriangleMesh> SplitPieces(const TriangleMesh& mesh);

// A mesh with a normal per vertex, for shading (issue 31).
struct ShadedMesh {
  std::vector<Vec3> vertices;
  std::vector<Vec3> normals;  // unit, one per vertex
  std::vector<std::array<int, 3>> triangles;
};
// Vertex normals with a crease angle: the corners at one position (vertices welded by exact position, so
// an imported mesh's duplicated vertices count as one) share a normal where their faces meet at
// `crease_deg` or less, so curved parts shade smooth, and split where they meet at more, so a box keeps its
// sharp edges. A corner's normal is the sum of the unit normals of the faces round its position within the
// crease angle of its own face, each weighted by its interior angle there (so a quad's two triangles weigh
// as the quad, however it was cut); a degenerate face takes all its neighbours' (or +z alone). Vertices are
// shared where position and normal agree. Deterministic.
ShadedMesh ShadeSmooth(const TriangleMesh& mesh, double crease_deg = 40.0);

// The result of checking a mesh for being a closed, consistently oriented solid.
struct SolidCheck {
  bool closed = false;         // every edge used by exactly two triangles, once in each direction
  int boundary_edges = 0;      // edges used once
  int non_manifold_edges = 0;  // edges used more than twice, or twice in the same direction
  double volume = 0.0;         // signed volume, m3
  bool ok() const { return closed && volume > 0.0; }
};
// Vertices closer than `weld` metres count as one (meshes of several pieces are checked as a whole).
SolidCheck CheckSolid(const TriangleMesh& mesh, double weld = 1e-7);

}  // namespace villa
