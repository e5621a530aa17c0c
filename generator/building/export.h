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
#include <string>

#include "generator/building/building.h"
#include "util/result.h"

namespace villa {

enum class MeshFormat { kGlb, kObj };

// "glb" / "obj"; nullopt for anything else.
std::optional<MeshFormat> ParseMeshFormat(std::string_view name);

// The .glb file's bytes (OBJ is several files: use ExportBuilding).
Result<std::string> BuildingToGlb(const BuildingMesh& building);

// Writes `out` atomically; OBJ also writes the .mtl beside it (same stem). Errors name the file.
Status ExportBuilding(const BuildingMesh& building, const std::filesystem::path& out, MeshFormat format);

}  // namespace villa
