#include "building/materials.h"

namespace villa {

PartMaterial MaterialOf(const MeshPart& part) {
  switch (part.kind) {
    case PartKind::kFloor:
      return {"floor-" + std::string(CategoryName(part.category)), CategoryColor(part.category), 1.0, 0.8};
    case PartKind::kTerrace: return {"terrace", {0.72, 0.70, 0.66}, 1.0, 0.95};
    case PartKind::kRoof: return {"roof", {0.55, 0.36, 0.30}, 1.0, 0.9};
    case PartKind::kExteriorWall: return {"exterior-wall", {0.93, 0.90, 0.84}, 1.0, 0.9};
    case PartKind::kInteriorWall: return {"interior-wall", {0.97, 0.97, 0.95}, 1.0, 0.9};
    case PartKind::kDoorLeaf: return {"door", {0.55, 0.38, 0.22}, 1.0, 0.6};
    case PartKind::kWindowGlass: return {"glass", {0.62, 0.80, 0.92}, 0.35, 0.05};
    case PartKind::kStair: return {"stair", {0.62, 0.60, 0.58}, 1.0, 0.85};
  }
  return {"default", {0.8, 0.8, 0.8}, 1.0, 0.9};
}

}  // namespace villa
