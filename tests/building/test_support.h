#pragma once
// Helpers of the building tests: the shared fixture built once, and a plain ray/triangle caster
// (Moller-Trumbore) independent of the Embree renderer.
#include <functional>
#include <limits>
#include <optional>

#include "building/building.h"
#include "layout/layout_io.h"
#include "test_layouts.h"

namespace villa::testing {

inline const Layout& ThreeFloorLayout() {
  static const Layout layout = [] {
    auto parsed = ParseLayoutText(kThreeFloorVilla, "three-floor fixture");
    if (!parsed) throw std::runtime_error(parsed.error());
    return *parsed;
  }();
  return layout;
}

inline const BuildingMesh& ThreeFloorBuilding() {
  static const BuildingMesh building = [] {
    auto built = BuildBuilding(ThreeFloorLayout());
    if (!built) throw std::runtime_error(built.error());
    return *built;
  }();
  return building;
}

// Distance along `dir` (unit) to the first triangle hit within (0, max_t], over the parts `keep` accepts.
inline std::optional<double> FirstHit(const BuildingMesh& building, Vec3 origin, Vec3 dir, double max_t,
                                      const std::function<bool(const MeshPart&)>& keep,
                                      const MeshPart** hit_part = nullptr) {
  double best = std::numeric_limits<double>::infinity();
  for (const MeshPart& part : building.parts) {
    if (!keep(part)) continue;
    const auto& v = part.mesh.vertices;
    for (const auto& t : part.mesh.triangles) {
      Vec3 e1 = v[t[1]] - v[t[0]], e2 = v[t[2]] - v[t[0]];
      Vec3 p = Cross(dir, e2);
      double det = Dot(e1, p);
      if (std::abs(det) < 1e-14) continue;
      Vec3 s = origin - v[t[0]];
      double u = Dot(s, p) / det;
      if (u < 0.0 || u > 1.0) continue;
      Vec3 q = Cross(s, e1);
      double w = Dot(dir, q) / det;
      if (w < 0.0 || u + w > 1.0) continue;
      double dist = Dot(e2, q) / det;
      if (dist > 1e-9 && dist <= max_t && dist < best) {
        best = dist;
        if (hit_part) *hit_part = &part;
      }
    }
  }
  if (best == std::numeric_limits<double>::infinity()) return std::nullopt;
  return best;
}

inline bool IsWall(const MeshPart& p) { return p.kind == PartKind::kExteriorWall || p.kind == PartKind::kInteriorWall; }
inline bool IsSlab(const MeshPart& p) {
  return p.kind == PartKind::kFloor || p.kind == PartKind::kTerrace || p.kind == PartKind::kRoof;
}

}  // namespace villa::testing
