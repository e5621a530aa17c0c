#pragma once
// What a mesh offers to other objects, read off its geometry by ray casts (SCENE.md "Asset record"):
// support surfaces S (horizontal faces with free space above) and containment cavities C (empty boxes
// with a surface below and geometry above: a shelf compartment, the inside of a cabinet).
//
// Everything is in the asset frame: metres, z up, origin at the bottom centre of the asset's box,
// front = -y. Polygons are counter-clockwise seen from above.
#include <optional>
#include <string>
#include <vector>

#include "assets/asset.h"
#include "mesh/mesh.h"

namespace villa {

struct AffordanceOptions {
  // ---- support surfaces from the mesh
  double min_normal_z = 0.95;     // |n_z| above which a face counts as horizontal, (0, 1]
  double bin = 0.02;              // m: horizontal faces within this height of each other form one level
  double min_share = 0.15;        // a level counts when its faces cover this share of the footprint, (0, 1]
  double min_clearance = 0.05;    // m of free space above a face for anything to stand on it, > 0
  double min_part_area = 0.01;    // m2: a separate piece of a level smaller than this is left out, >= 0
  double min_part_width = 0.05;   // m: so is a piece narrower than this (a rim, the top of a panel), >= 0
  double min_z = 0.02;            // m: faces lower than this are the asset's base, >= 0
  double storey_clear_height = 2.625;  // m: the clear height written for a top surface is this minus its z
  // ---- SH3D's dropOnTopElevation
  double drop_tolerance = 0.03;   // m: geometry within this of the drop height is the drop surface, > 0
  double min_drop_share = 0.05;   // share of the footprint an explicit drop surface must cover, (0, 1]
  // ---- cavities
  Vec3 min_cavity{0.08, 0.08, 0.06};  // m: the smallest compartment kept (width, depth, height)
  double margin = 0.005;          // m kept between a cavity and the geometry around it, >= 0

  std::string Check() const;      // empty when usable, else what is wrong
};

struct MeshAffordances {
  std::vector<SupportSurface> surfaces;  // sorted by height
  std::vector<Cavity> cavities;          // floor_surface indexes `surfaces`
};

// `size` is the asset's box (w, d, h); the mesh is expected to fill it. `drop_on_top` is SH3D's
// dropOnTopElevation in metres: nullopt when the catalog gives none (SH3D's default is the top: kept when
// the mesh has a top level), negative for "nothing lands on it" (mesh levels are still read).
MeshAffordances AffordancesFromMesh(const TriangleMesh& mesh, Vec3 size, std::optional<double> drop_on_top,
                                    const AffordanceOptions& options = {});

}  // namespace villa
