#pragma once
// How well-formed an imported mesh is, and the paper's complexity filter: meshes above a triangle budget
// are simplified by vertex clustering (or skipped, the importer's choice).
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
AssetMesh ClusterVertices(const AssetMesh& mesh, double cell);

// The finest clustering with at most `max_triangles` triangles (bisection on the cube size, between
// 1/4096 and 1/4 of the bounding box's longest side). The mesh itself when it is already within budget.
// Fails only when even the coarsest grid leaves too many (the budget is below a handful of triangles).
Result<AssetMesh> DecimateToBudget(const AssetMesh& mesh, int max_triangles);

}  // namespace villa
