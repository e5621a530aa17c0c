// Vertex normals with a crease angle (issue 31: "smooth where smooth"): curved parts shade smooth, box
// edges stay sharp, duplicated vertices at one position weld.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "mesh/mesh.h"

using namespace villa;

namespace {

// An axis-aligned box, 8 shared vertices, CCW from outside.
TriangleMesh Box() {
  TriangleMesh m;
  for (int k = 0; k < 8; ++k) m.vertices.push_back({k & 1 ? 1.0 : 0.0, k & 2 ? 1.0 : 0.0, k & 4 ? 1.0 : 0.0});
  for (const auto& f : std::vector<std::array<int, 3>>{{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                                                      {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}})
    m.AddTriangle(f[0], f[1], f[2]);
  return m;
}

// A closed cylinder of `sides` sides, radius 1, height 1, its side's quads as two triangles; `duplicate`:
// every side quad with its own four vertices (as imported meshes often come), not shared.
TriangleMesh Cylinder(int sides, bool duplicate) {
  TriangleMesh m;
  auto at = [&](int k, double z) {
    const double a = 2.0 * std::numbers::pi * k / sides;
    return Vec3{std::cos(a), std::sin(a), z};
  };
  for (int k = 0; k < sides; ++k) {
    const int n = (k + 1) % sides;
    const int b0 = m.AddVertex(at(k, 0.0), duplicate ? -1.0 : 1e-9), b1 = m.AddVertex(at(n, 0.0), duplicate ? -1.0 : 1e-9);
    const int t0 = m.AddVertex(at(k, 1.0), duplicate ? -1.0 : 1e-9), t1 = m.AddVertex(at(n, 1.0), duplicate ? -1.0 : 1e-9);
    m.AddTriangle(b0, b1, t1);
    m.AddTriangle(b0, t1, t0);
    const int cb = m.AddVertex({0, 0, 0}), ct = m.AddVertex({0, 0, 1});
    m.AddTriangle(cb, b1, b0);
    m.AddTriangle(ct, t0, t1);
  }
  return m;
}

}  // namespace

TEST_CASE("A box keeps its edges: every corner takes its own face's normal", "[mesh][issue31]") {
  const ShadedMesh s = ShadeSmooth(Box());
  CHECK(s.triangles.size() == 12);
  CHECK(s.vertices.size() == 24);  // 6 faces x 4 corners
  REQUIRE(s.normals.size() == s.vertices.size());
  for (const auto& t : s.triangles) {
    const Vec3 face = Normalized(Cross(s.vertices[t[1]] - s.vertices[t[0]], s.vertices[t[2]] - s.vertices[t[0]]));
    for (int v : t) CHECK(Dot(s.normals[v], face) == Approx(1.0));
  }
}

TEST_CASE("A 16-sided cylinder is round on its side and sharp at its rims, welded or not", "[mesh][issue31]") {
  for (bool duplicate : {false, true}) {
    INFO("duplicated vertices: " << duplicate);
    const ShadedMesh s = ShadeSmooth(Cylinder(16, duplicate));
    REQUIRE(s.normals.size() == s.vertices.size());
    int side = 0, cap = 0;
    for (size_t v = 0; v < s.vertices.size(); ++v) {
      const Vec3 p = s.vertices[v], n = s.normals[v];
      CHECK(Norm(n) == Approx(1.0));
      if (std::abs(n.z) > 0.999) {
        ++cap;  // a cap's corner: straight up or down
        continue;
      }
      ++side;
      // The side's normal at a rim vertex is radial: the average of the two faces meeting there.
      CHECK(std::abs(n.z) < 1e-9);
      CHECK(n.x == Approx(p.x).margin(1e-6));
      CHECK(n.y == Approx(p.y).margin(1e-6));
    }
    CHECK(side == 32);     // one per rim vertex: the side is one smooth surface
    CHECK(cap == 2 * 16 + 2);  // the rims again for each cap, and the two centres
  }
  // With a crease of 10 degrees, the 22.5-degree edges between side faces stay sharp.
  CHECK(ShadeSmooth(Cylinder(16, false), 10.0).vertices.size() == 16 * 4 + 2 * 16 + 2);
}

TEST_CASE("A degenerate triangle takes its neighbours' normal and nothing is lost", "[mesh][issue31]") {
  TriangleMesh m = Box();
  m.AddTriangle(0, 0, 1);  // no area
  const ShadedMesh s = ShadeSmooth(m);
  CHECK(s.triangles.size() == 13);
  for (const Vec3& n : s.normals) CHECK(Norm(n) == Approx(1.0));
}
