#pragma once
// Writing a built villa as a 3D file: glTF 2.0 binary (.glb, our own writer: building/glb_writer.h) or
// Wavefront OBJ (+ .mtl, through assimp).
//
// Scene: root "villa" -> "level_L" (one per floor) -> the room nodes (each room's floor, named after
// the room: "kitchen_0/0") and the groups "walls_L", "doors_L", "windows_L", "stairs_L", "terraces_L"
// holding one node per wall piece / door leaf / pane / staircase, named after the layout element
// ("living0_kitchen0"); the roof hangs under the top level. Materials per room category and part
// (glass: alpha 0.35, blend). glTF frame: metres, +Y up; plan (x, y) at height z becomes (x, z, -y).
// In the .glb every named node carries its exact name in `extras.name` (viewers such as three.js strip
// "/", ":" and "." from names); room nodes also carry category, area_m2 and level. Base colour factors
// are linear (the palette's sRGB inverted), as glTF defines them. A floor slab's edges (its steep faces,
// on the facade and round stair holes) take the exterior wall's material, so the facade shows no band of
// room colour at the floor lines. Furniture (villa furnish) hangs under the room nodes, one node per
// object sharing one mesh per asset.
#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "building/building.h"
#include "building/materials.h"
#include "render/palette.h"
#include "util/result.h"

namespace villa {

enum class MeshFormat { kGlb, kObj };

// "glb" / "obj"; nullopt for anything else.
std::optional<MeshFormat> ParseMeshFormat(std::string_view name);

// Objects placed in the building (villa furnish), written into the .glb with it.
struct ExportAssetMesh {
  std::string name;  // the asset id
  struct Part {
    const TriangleMesh* mesh = nullptr;  // borrowed; asset frame (metres, z up, origin bottom centre)
    PartMaterial material;               // sRGB colour (written linear)
  };
  std::vector<Part> parts;  // parts without triangles are skipped
};
struct ExportObject {
  std::string name;     // the object id: the node's name and extras.name
  std::string room;     // the room node it hangs under (a room of the building)
  int mesh = -1;        // index into ExportFurniture::meshes (shared: instancing)
  Vec3 position;        // world, building frame (z up): where the asset's origin goes
  double yaw = 0.0;     // rad, counter-clockwise about +z
  Vec3 scale{1.0, 1.0, 1.0};  // along the asset's x, y, z
  nlohmann::ordered_json extras = nlohmann::ordered_json::object();  // written first; "name" added
};
struct ExportFurniture {
  std::vector<ExportAssetMesh> meshes;
  std::vector<ExportObject> objects;
  nlohmann::ordered_json asset_extras;  // glTF asset.extras (credits), written when not null
};

// The .glb file's bytes (OBJ is several files: use ExportBuilding). `furniture` may be null. Fails for an
// object naming a room or mesh that does not exist.
Result<std::string> BuildingToGlb(const BuildingMesh& building, const ExportFurniture* furniture = nullptr);

// Writes `out` atomically; OBJ also writes the .mtl beside it (same stem). Errors name the file.
Status ExportBuilding(const BuildingMesh& building, const std::filesystem::path& out, MeshFormat format);

// What a 3D file holds, read back through assimp (for tests and `villa build` checks): the node tree,
// per-mesh bounds in the file's own frame, materials, and node metadata as text.
struct SceneNodeInfo {
  std::string name;
  std::string path;                 // "villa/level_0/walls_0/exterior_0_1"
  std::vector<int> meshes;          // indices into SceneInfo::meshes
  std::map<std::string, std::string> metadata;  // key -> value as text ("utility-room", "16", "0")
  std::array<double, 16> local{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};   // row-major, to the parent's frame
  std::array<double, 16> global{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};  // row-major, to the file's frame
  std::string Meta(const std::string& key) const;  // the metadata value, "" when absent
};
struct SceneMeshInfo {
  std::string name;
  int material = 0;
  int vertices = 0;
  int triangles = 0;
  Box3 bounds;        // the mesh's own frame (glTF: +Y up)
  TriangleMesh mesh;  // its triangles in that frame
  std::vector<Vec3> normals;  // one per vertex as the file gives them; empty when it gives none
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
// Reads a .glb (or any file assimp reads) as node and mesh lists. A .glb is checked first
// (CheckGlbStructure): a file whose extension says .glb must be one.
Result<SceneInfo> ReadSceneInfo(const std::filesystem::path& path);
// What a reader of an untrusted .glb checks before the importer sees it (issue 33), naming `name` and the
// bad value: the GLB header (magic "glTF", version 2, the declared length the file's), a JSON chunk that
// parses; at most kMaxGlbNodes nodes, each child index in range and a child of one parent only, no cycle,
// the hierarchy at most kMaxGlbDepth deep; buffers embedded (no uri, or a data: uri: an external path such
// as /etc/passwd is refused); node translations, matrices and scales finite and within kMaxGlbCoordinate;
// POSITION accessors' min and max finite and within it (NaN and 1e38 m vertices).
inline constexpr std::size_t kMaxGlbNodes = 200000;
inline constexpr int kMaxGlbDepth = 256;
inline constexpr double kMaxGlbCoordinate = 1.0e5;  // m
Status CheckGlbStructure(std::string_view bytes, const std::string& name);
// A node's meshes in the plan frame (z up; glTF's file frame is +Y up: file (x, y, z) is plan (x, -z, y)),
// in the node's own frame (`world` false) or moved by its global transform.
TriangleMesh PlanFrameMesh(const SceneInfo& info, const SceneNodeInfo& node, bool world);
// The same from a file's bytes; `extension` tells the format ("glb": checked first); `name` for messages.
Result<SceneInfo> ReadSceneInfoFromMemory(const std::string& bytes, const std::string& extension, const std::string& name = "");

}  // namespace villa
