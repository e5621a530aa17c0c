#pragma once
// Nearest-hit ray casts against triangle meshes (Embree 3 inside the .cpp; the one place villa casts single
// rays). Two users: the asset importer reads facts off an asset's geometry (which horizontal faces have free
// space above, how high that space is, whether a box inside the asset is empty), and the 3D view
// (render/view3d.cpp) traces its pictures through a scene of many meshes. The BVH holds single-precision
// copies of the meshes; rays are cast in single precision. Const queries are safe from several threads.
#include <memory>
#include <optional>
#include <vector>

#include "mesh/mesh.h"

namespace villa {

class RayCaster {
 public:
  RayCaster();                                   // an empty scene: add meshes, then Commit
  explicit RayCaster(const TriangleMesh& mesh);  // one mesh (id 0), committed
  ~RayCaster();
  RayCaster(const RayCaster&) = delete;
  RayCaster& operator=(const RayCaster&) = delete;

  // Copies `mesh` into the scene and returns its id: 0, 1, 2... in the order added; -1 for a mesh without
  // triangles (nothing to hit; it takes no id). Only before Commit.
  int Add(const TriangleMesh& mesh);
  // Builds the BVH over the meshes added; casts need it.
  void Commit();
  // False when Embree could not start (no device or scene); casts then hit nothing.
  bool ok() const;

  struct Hit {
    double t = 0.0;   // distance along the direction (in units of its length; m for a unit direction)
    Vec3 normal;      // unit geometric normal of the triangle hit, from its winding (a, b, c CCW)
    int mesh = -1;    // the id Add returned
    int triangle = -1;
  };
  // The nearest hit with t in [t_min, t_max] (Embree's tnear/tfar, in single precision); nullopt when
  // nothing is hit.
  std::optional<Hit> Cast(Vec3 origin, Vec3 direction, double t_max, double t_min = 0.0) const;
  // Every crossing along a segment, in order of distance (repeated casts, each starting just past the
  // previous hit): the boundaries a probe line passes through.
  std::vector<double> Crossings(Vec3 origin, Vec3 direction, double length) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace villa
