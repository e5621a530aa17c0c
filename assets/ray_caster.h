#pragma once
// Nearest-hit ray casts against one triangle mesh (Embree 3 inside the .cpp), for the facts the importer
// reads off an asset's geometry: which horizontal faces have free space above, how high that space is,
// whether a box inside the asset is empty. Const queries are safe from several threads.
#include <memory>
#include <optional>
#include <vector>

#include "mesh/mesh.h"

namespace villa {

class RayCaster {
 public:
  explicit RayCaster(const TriangleMesh& mesh);  // copies the mesh into the BVH (single precision)
  ~RayCaster();
  RayCaster(const RayCaster&) = delete;
  RayCaster& operator=(const RayCaster&) = delete;

  struct Hit {
    double t = 0.0;   // distance along the (unit) direction, m
    Vec3 normal;      // unit geometric normal of the triangle hit, from its winding (a, b, c CCW)
    int triangle = -1;
  };
  // The nearest hit with t in (t_min, t_max], `direction` a unit vector; nullopt when nothing is hit.
  std::optional<Hit> Cast(Vec3 origin, Vec3 direction, double t_max, double t_min = 0.0) const;
  // Every crossing along a segment, in order of distance (repeated casts, each starting just past the
  // previous hit): the boundaries a probe line passes through.
  std::vector<double> Crossings(Vec3 origin, Vec3 direction, double length) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace villa
