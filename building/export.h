#pragma once
// Writing a built villa as a 3D file through assimp: glTF 2.0 binary (.glb) or Wavefront OBJ (+ .mtl).
//
// Scene: root "villa" -> "level_L" (one per floor) -> the room nodes (each room's floor, named after
// the room: "kitchen_0/0") and the groups "walls_L", "doors_L", "windows_L", "stairs_L", "terraces_L"
// holding one node per wall piece / door leaf / pane / staircase, named after the layout element
// ("living0_kitchen0"); the roof hangs under the top level. Materials per room category and part
// (glass: alpha 0.35, blend). glTF frame: metres, +Y up; plan (x, y) at height z becomes (x, z, -y).
// Room nodes carry metadata (category, area_m2, level), written as glTF node extras where the
// exporter supports it (see docs/BUILDING.md for what survives a re-import).
#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "building/building.h"
#include "render/palette.h"
#include "util/result.h"

namespace villa {

enum class MeshFormat { kGlb, kObj };

// "glb" / "obj"; nullopt for anything else.
std::optional<MeshFormat> ParseMeshFormat(std::string_view name);

// The .glb file's bytes (OBJ is several files: use ExportBuilding).
Result<std::string> BuildingToGlb(const BuildingMesh& building);

// Writes `out` atomically; OBJ also writes the .mtl beside it (same stem). Errors name the file.
Status ExportBuilding(const BuildingMesh& building, const std::filesystem::path& out, MeshFormat format);

// What a 3D file holds, read back through assimp (for tests and `villa build` checks): the node tree,
// per-mesh bounds in the file's own frame, materials, and node metadata as text.
struct SceneNodeInfo {
  std::string name;
  std::string path;                 // "villa/level_0/walls_0/exterior_0_1"
  std::vector<int> meshes;          // indices into SceneInfo::meshes
  std::map<std::string, std::string> metadata;  // key -> value as text ("utility-room", "16", "0")
};
struct SceneMeshInfo {
  std::string name;
  int material = 0;
  int vertices = 0;
  int triangles = 0;
  Box3 bounds;  // file frame (glTF: +Y up)
};
struct SceneMaterialInfo {
  std::string name;
  Rgb color;
  double alpha = 1.0;      // base colour alpha times opacity, as the importer reports them
  std::string alpha_mode;  // glTF: "OPAQUE", "BLEND", ... ("" when the format has none)
};
struct SceneInfo {
  std::vector<SceneNodeInfo> nodes;  // depth first, root first
  std::vector<SceneMeshInfo> meshes;
  std::vector<SceneMaterialInfo> materials;
  Box3 bounds;  // of all meshes, file frame
  const SceneNodeInfo* Find(std::string_view name) const;
};
Result<SceneInfo> ReadSceneInfo(const std::filesystem::path& path);

}  // namespace villa
