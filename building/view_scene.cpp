#include "building/view_scene.h"

#include "building/materials.h"

namespace villa {
namespace {

// The concrete of a slab's edges (on the facade, round stair holes): a floor's colour belongs on its top.
constexpr Rgb kSlabEdge{0.80, 0.78, 0.74};

CutAway CutAwayOf(PartKind kind) {
  switch (kind) {
    case PartKind::kExteriorWall:
    case PartKind::kInteriorWall:
    case PartKind::kDoorLeaf:
    case PartKind::kWindowGlass:
    case PartKind::kWindowFrame:
    case PartKind::kStair: return CutAway::kCut;
    case PartKind::kRoof: return CutAway::kRemove;
    case PartKind::kFloor:
    case PartKind::kTerrace:
    case PartKind::kRailing: return CutAway::kKeep;
  }
  return CutAway::kKeep;
}

}  // namespace

ViewScene ViewSceneOf(const BuildingMesh& building) {
  ViewScene scene;
  scene.meshes.reserve(building.parts.size());
  for (const MeshPart& part : building.parts) {
    const PartMaterial material = MaterialOf(part, building.style);
    ViewMesh view;
    view.mesh = &part.mesh;
    view.color = material.color;
    view.alpha = material.alpha;
    if (part.kind == PartKind::kFloor) view.side_color = kSlabEdge;
    view.level = part.level;
    view.cut = CutAwayOf(part.kind);
    scene.meshes.push_back(view);
  }
  for (int level = 0; level < building.levels; ++level) scene.floor_z.push_back(building.FloorZ(level));
  return scene;
}

}  // namespace villa
