#pragma once
// How well-formed an imported mesh is, and the paper's complexity filter: meshes above a triangle budget
// are simplified by vertex clustering (or skipped, the importer's choice).
#include <cstdint>
#include <vector>

#include "assets/asset_mesh.h"
#include "util/result.h"

namespace villa {

// Edges of the whole asset (every part together), vertices at the same position (within 1e-6 m) welded.
struct EdgeStatistics {
  int edges = 0;         // distinct undirected edges
  int two_sided = 0;     // used by exactly two triangles
  int boundary = 0;      // used by one
  int non_manifold = 0;  // used by three or more
  // Closed: every edge shared by exactly two triangles (orientation not required: many models mix it).
  bool Watertight() const { return edges > 0 && two_sided == edges; }
  double ManifoldShare() const { return edges > 0 ? static_cast<double>(two_sided) / edges : 0.0; }
};
EdgeStatistics MeshEdgeStatistics(const AssetMesh& mesh);

// Vertex clustering: space is cut into cubes of side `cell` m; every vertex moves to the mean of the
// vertices in its cube (the same point in every part, so parts still meet), triangles whose corners fall
// in fewer than three cubes vanish, repeated triangles are kept once. Materials and parts are kept.
// With `pieces` (SolidPieceIds), a cube is one per solid piece: pieces stay apart (their own means).
AssetMesh ClusterVertices(const AssetMesh& mesh, double cell, const std::vector<std::vector<std::uint32_t>>* pieces = nullptr);
// Each vertex's solid piece (parallel to the parts' vertices): connected through triangles and through
// vertices at one position (to 0.1 um), across parts.
std::vector<std::vector<std::uint32_t>> SolidPieceIds(const AssetMesh& mesh);

// The finest clustering with at most `max_triangles` triangles (bisection on the cube size, between
// 1/4096 and 1/4 of the bounding box's longest side). The mesh itself when it is already within budget.
// Fails only when even the coarsest grid leaves too many (the budget is below a handful of triangles).
// The result keeps the source's box (moved and stretched per axis back onto it): it stands where the source did.
// `best_effort`: each solid piece is clustered on its own and pieces clustering would all but erase are
// kept, so the result may stay over the budget (up to a quarter over the least those pieces allow).
Result<AssetMesh> DecimateToBudget(const AssetMesh& mesh, int max_triangles, bool best_effort = false);

}  // namespace villa
