#pragma once
// The geometric parsing module of the paper: a layout (FORMAT.md) turned into a multi-story building
// volume of closed triangle meshes: floor slabs with stair holes, a roof, exterior and interior walls
// with openings, door leaves, window glass and staircases.
//
// Frame: metres, x and y as in the layout, z up (see mesh.h). Vertically, level L occupies
//   slab  z in [L*2.8, L*2.8 + slab]            (floor surface at L*2.8 + slab)
//   walls z in [L*2.8 + slab, (L+1)*2.8]        (the next slab, or the roof, rests on them)
// and the roof covers the top level, z in [N*2.8, N*2.8 + slab]: a building of N floors is
// N*2.8 + slab tall. The slab of level L >= 1 covers the footprint of level L-1 (it is the ceiling of
// the floor below; the part outside level L's footprint is a flat roof terrace).
#include <optional>
#include <array>
#include <string>
#include <vector>

#include "mesh/mesh.h"
#include "layout/layout.h"
#include "util/result.h"

namespace villa {

struct BuildOptions {
  double slab_thickness = 0.175;         // m; also the roof. Equal to one stair riser so the top step is flush.
  double exterior_wall_thickness = 0.25; // m, offset inward: the outer face is the footprint edge
  double interior_wall_thickness = 0.12; // m, centred on each `interiors` segment
  double door_height = 2.1;              // m above the floor surface
  double window_sill = 0.9;              // m above the floor surface
  double window_head = 2.1;              // m above the floor surface
  double panoramic_sill = 0.05;          // m: panoramic windows run nearly floor to ceiling
  double panoramic_head_gap = 0.1;       // m left below the ceiling above a panoramic window
  double door_leaf_thickness = 0.04;     // m
  double glass_thickness = 0.02;         // m
  int stair_risers = 16;                 // per floor, two flights of half each (2.8 m / 16 = 0.175 m)
  bool door_leaves_open = true;          // leaves swung 90 degrees into a room (the opening stays free)

  // Empty when usable, else what is wrong ("exterior_wall_thickness = 0: must be in (0, 1]").
  std::string Check() const;
};

// What a mesh part is; decides its material and node group.
enum class PartKind {
  kFloor,         // a room's floor: the slab under that room (closed prism)
  kTerrace,       // slab over the floor below that lies outside this level's rooms (flat roof)
  kRoof,          // the roof over the top level
  kExteriorWall,
  kInteriorWall,
  kDoorLeaf,      // doors and the entrance
  kWindowGlass,
  kStair,
  kRailing,       // issue 31: round stair holes and along terraces' open edges (posts and two rails, 1 m)
  kWindowFrame,   // issue 31: a window's frame round its pane, within the wall's opening
};
std::string_view PartKindName(PartKind kind);  // "floor", "terrace", "roof", "exterior-wall", ...

struct MeshPart {
  std::string name;     // node name: the room / element name ("kitchen_0/0", "living0_kitchen0"), see BUILDING.md
  PartKind kind = PartKind::kFloor;
  int level = 0;        // the level it belongs to (the roof: the top level)
  Category category = Category::kRoom;  // floors: the room's category
  std::string element;  // the layout element it comes from ("" for exterior walls, terraces, the roof)
  TriangleMesh mesh;    // closed solid(s), CCW from outside
  // Door leaves: the vertical axis the leaf turns about (plan point, at its edge by the jamb, on the face
  // that meets the wall) and the turns (radians, counter-clockwise seen from above, from where it hangs)
  // that close it and that open it to 90 degrees into its room; a simulator's hinge runs between them.
  struct Hinge {
    Point at;
    double to_closed = 0.0, to_open = 0.0;
  };
  std::optional<Hinge> hinge;
};

struct BuiltRoom {
  std::string name;
  Category category = Category::kRoom;
  int level = 0;
  double area = 0.0;  // m2, of the room polygon
};

// A staircase rising from `level` to level + 1, and the hole it passes through in the slab above.
struct BuiltStair {
  int level = 0;
  std::string room;      // the utility room holding it
  Ring footprint;        // plan outline of flights and landing, CCW
  Ring hole;             // the hole cut into the slab of level + 1 (empty when there is none)
  std::array<Point, 2> arrival{};  // the edge of the hole where the upper flight arrives (no railing there)
};

struct BuildingMesh {
  int levels = 0;
  double slab_thickness = 0.0;
  std::vector<MeshPart> parts;
  std::vector<BuiltRoom> rooms;
  std::vector<BuiltStair> stairs;
  // Slab holes by level (index = level; holes[0] is always empty).
  std::vector<std::vector<Ring>> slab_holes;
  // By level: the inner faces of the exterior walls as one ring (the footprint inset by the walls'
  // thickness, mitred at every corner, thinned where short edges ask for it). Where the footprint turns at
  // a room's corner (an octagon's 45-degree edge beside a square room), the wall's inner face crosses that
  // corner: the furnishing's free floor stays inside this ring.
  std::vector<Ring> wall_inner;
  // Things the builder had to adapt: "door living0_kitchen0: no wall under it, leaf only".
  std::vector<std::string> warnings;
  // The villa's style (issue 31: its floor finishes and paint, building/materials.h); "" reads as modern.
  // The builder leaves it empty; the furnishing sets the style its assets were chosen in.
  std::string style;

  Box3 Bounds() const;
  int CountParts(PartKind kind) const;
  // Floor surface height of `level`, m.
  double FloorZ(int level) const;
};

// Builds the building. Fails (message naming the element) when the layout cannot become one: no rooms,
// a level without rooms, rooms of a level that do not tile one polygon, or a degenerate room.
// The geometric rules 1-5 are assumed (run ValidateLayout first); what breaks them beyond that is
// adapted and reported in `warnings` rather than crashing.
Result<BuildingMesh> BuildBuilding(const Layout& layout, const BuildOptions& options = {});

// VCR measured on the built geometry (paper, appendix "Custom Metrics"): for each pair of adjacent
// levels, whether the staircase footprint of the lower level overlaps a slab hole of the upper level.
struct VerticalConnection {
  int lower_level = 0;
  double overlap_area = 0.0;  // m2, staircase footprint of lower ∩ slab holes of upper
  bool connected() const { return overlap_area > 0.0; }
};
struct VcrReport {
  std::vector<VerticalConnection> pairs;  // levels - 1 entries
  int floor_pairs() const { return static_cast<int>(pairs.size()); }
  int connected_pairs() const;
  // connected / pairs; 1 for a one-floor building (no pair to fail), by the paper's convention of
  // reporting VCR over multi-story outputs only the caller decides whether to count it.
  double vcr() const;
};
VcrReport MeasureVcr(const BuildingMesh& building);

// Area of the intersection of two convex polygons (CCW), m2.
double ConvexOverlapArea(const Ring& a, const Ring& b);

}  // namespace villa
