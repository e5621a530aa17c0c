#pragma once
// The geometry of an asset: triangle meshes in the asset frame (metres, z up, origin at the bottom centre
// of the asset's box, front = -y; SCENE.md), one part per material. Imported models are stored once in a
// small binary file (.vmesh) that loads with no parsing; procedural assets are rebuilt from their id.
//
// .vmesh layout (little-endian): "VMESH1\0\0", u32 part count, then per part: u32 name length, name bytes,
// f32 r, g, b, alpha (sRGB colour, [0, 1]), u32 vertex count, f32 x, y, z per vertex, u32 triangle count,
// u32 a, b, c per triangle (indices into the part's vertices, counter-clockwise seen from outside).
#include <filesystem>
#include <string>
#include <vector>

#include "mesh/mesh.h"
#include "util/result.h"

namespace villa {

struct MeshMaterial {
  std::string name;  // "wood", "fabric", the source material's name
  double r = 0.8, g = 0.8, b = 0.8;  // sRGB, [0, 1]
  double alpha = 1.0;                // < 1: transparent
  friend bool operator==(const MeshMaterial&, const MeshMaterial&) = default;
};

struct AssetMeshPart {
  MeshMaterial material;
  TriangleMesh mesh;  // asset frame
};

struct AssetMesh {
  std::vector<AssetMeshPart> parts;

  Box3 Bounds() const;
  int TriangleCount() const;
  // All parts in one mesh (vertices not welded across parts): for collision checks and ray casts.
  TriangleMesh Merged() const;
};

Result<AssetMesh> ReadAssetMesh(const std::filesystem::path& path);
Status WriteAssetMesh(const std::filesystem::path& path, const AssetMesh& mesh);  // atomic

}  // namespace villa
