#pragma once
// A furnished .glb as a MuJoCo scene (MJCF, issue 28): `DIR/villa.xml` and its meshes in `DIR/meshes/`
// (binary STL, one a convex part, since MuJoCo collides a mesh as its convex hull; a part that is a box is
// one 8-corner mesh per size, not a box geom, whose collider makes phantom deep contacts). The building is the
// world's static geoms (one a connected piece of its meshes); every object is a body named by its scene
// id at its box's centre, with a free joint unless it is welded (hung on a wall or from the ceiling, on a
// rail), one geom a convex part (density and friction as physics::SettleOptions), rugs left out as
// decals, as `villa physics` reads the file (physics/glb_settle.h). Door leaves are bodies on a vertical hinge
// joint at their jamb (the .glb's door extras, BUILDING.md), free between closed and open.
#include <filesystem>

#include "physics/settle.h"
#include "util/result.h"

namespace villa::physics {

// MuJoCo 2.2 allocates njmax^2 numbers and more (the rows' matrix, a row's Jacobian): past about 12,500
// rows mjData cannot be made (2 GB), so the constraint buffer stays under this.
inline constexpr int kMjcfMaxRows = 12000;

struct MjcfSummary {
  int bodies = 0, free = 0, geoms = 0, static_geoms = 0, meshes = 0;
  int boxes = 0;   // geoms that are boxes (pieces that are boxes), written as box-shaped meshes
  int merged = 0;  // object boxes merged into a neighbour (a book's pages and covers: one box)
  int doors = 0;   // door leaves, bodies on hinges
  int prisms = 0;  // building pieces cut into convex prisms
  int hulls = 0;   // building pieces neither prism nor wall, written whole (MuJoCo collides their hulls)
  int sheets = 0;  // pieces left out: their hull holds under 1 cm3 or is under 2 mm thick
  int nconmax = 0, njmax = 0;  // the contact and constraint buffers written
};

// Writes the scene; the folder is created, its villa.xml and meshes/ replaced. The contact and constraint
// buffers are estimated from the geoms (physics/mujoco_run.h's ExportMjcf fits them to a run).
Result<MjcfSummary> WriteMjcf(const std::filesystem::path& glb, const std::filesystem::path& dir,
                              const SettleOptions& options = {});
// Sets villa.xml's buffers (its <size nconmax njmax> line), the file replaced atomically.
Status SetMjcfBuffers(const std::filesystem::path& xml, int nconmax, int njmax);

}  // namespace villa::physics
