#pragma once
// Convex parts of a building's solid, for simulators that collide a mesh as its convex hull (MuJoCo): a
// wall with a door cut out is one connected solid, whose hull fills the doorway. Every piece of our
// buildings is a stack of prisms along one direction: a wall with its openings is prisms up (below a door's
// head: the wall each side of it; above: the whole wall), a slab is its outline (holes and all) extruded up,
// flights of steps are their profiles extruded across their width (two flights side by side: two prisms).
#include <optional>
#include <vector>

#include "mesh/mesh.h"

namespace villa {

// The convex prisms whose union is `piece` (one connected closed solid), or nullopt when it is no stack of
// prisms. A direction d is found along which every face lies (a side) or across which it lies (a cap, at
// some height along d); between consecutive cap heights the piece's cross-section is the same polygon
// (holes and all), which is cut into convex polygons (its triangles merged across shared edges while they
// stay convex, Hertel and Mehlhorn's rule: at most four times the fewest) and extruded over the slab. The
// parts' volume is checked against the piece's.
// `slope` (radians): faces within it of along / across d count as sides / caps, and cap heights within
// `snap` metres as one (the highest); the parts' volume within `volume_share` of the piece's. The defaults
// are exact (our buildings); an imported model's tray, its rim 0.2 mm out of level, takes a little slack.
struct PrismTolerance {
  double slope = 1.4e-3;  // cos = 1 - 1e-6
  double snap = 1e-7;
  double volume_share = 1e-6;
};
std::optional<std::vector<TriangleMesh>> ConvexPrismParts(const TriangleMesh& piece, const PrismTolerance& tolerance = {});
// The slack for imported models: 3 degrees, 2 mm, 2 % of the volume.
inline constexpr PrismTolerance kModelTolerance{0.05, 0.002, 0.02};

// A body's mesh as solids. Vertices at one position (to 0.1 um) are one, whatever their indices (a file
// with vertex normals repeats a box's corner for each face); triangles are of one piece across an edge that
// one triangle runs each way, so that two boxes stacked or touching at an edge stay two solids. Pieces that
// are not closed are joined with the others they meet at the same positions: an imported model's tray top
// is an open shell over a separate glass sheet, and one solid together.
std::vector<TriangleMesh> SolidPiecesOf(const TriangleMesh& mesh);
// `mesh` with the vertices at one position (to 0.1 um) made one, and triangles that collapse dropped.
TriangleMesh WeldedByPosition(const TriangleMesh& mesh);

}  // namespace villa
