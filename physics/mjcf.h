#pragma once
// A furnished .glb as a MuJoCo scene (MJCF, issue 28): `DIR/villa.xml` and its meshes in `DIR/meshes/`
// (binary STL, one a convex part, since MuJoCo collides a mesh as its convex hull); a part that is a box is
// a box geom (MuJoCo touches two meshes at one point only, and they rock). The building is the
// world's static geoms (one a connected piece of its meshes); every object is a body named by its scene
// id at its box's centre, with a free joint unless it is welded (hung on a wall or from the ceiling, on a
// rail), one geom a convex part (density and friction as physics::SettleOptions), rugs left out as
// decals, as `villa physics` reads the file (physics/glb_settle.h). Door leaves are static (no hinges yet).
#include <filesystem>

#include "physics/settle.h"
#include "util/result.h"

namespace villa::physics {

struct MjcfSummary {
  int bodies = 0, free = 0, geoms = 0, static_geoms = 0, meshes = 0;
  int boxes = 0;  // geoms written as boxes (pieces that are boxes); the rest are meshes
};

// Writes the scene; the folder is created, its villa.xml and meshes/ replaced.
Result<MjcfSummary> WriteMjcf(const std::filesystem::path& glb, const std::filesystem::path& dir,
                              const SettleOptions& options = {});

}  // namespace villa::physics
