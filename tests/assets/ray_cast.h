#pragma once
// Rays against triangle meshes for the asset tests: Moller-Trumbore over every triangle (brute force; the
// test meshes are small).
#include <cmath>
#include <optional>

#include "mesh/mesh.h"

namespace villa::test {

struct Ray {
  Vec3 origin;
  Vec3 dir;  // unit
};

// Distance along the ray to the nearest triangle it crosses (t > 0); nullopt when it crosses none. Edges
// count as hits (a small tolerance), so a ray through the shared edge of two triangles is not lost.
inline std::optional<double> FirstHit(const TriangleMesh& mesh, const Ray& ray) {
  std::optional<double> best;
  for (const auto& t : mesh.triangles) {
    const Vec3 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
    const Vec3 e1 = b - a, e2 = c - a, p = Cross(ray.dir, e2);
    const double det = Dot(e1, p);
    if (std::abs(det) < 1e-15) continue;
    const double inv = 1.0 / det;
    const Vec3 s = ray.origin - a;
    const double u = Dot(s, p) * inv;
    if (u < -1e-9 || u > 1 + 1e-9) continue;
    const Vec3 q = Cross(s, e1);
    const double v = Dot(ray.dir, q) * inv;
    if (v < -1e-9 || u + v > 1 + 1e-9) continue;
    const double dist = Dot(e2, q) * inv;
    if (dist > 1e-12 && (!best || dist < *best)) best = dist;
  }
  return best;
}

}  // namespace villa::test
