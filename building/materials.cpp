#include "building/materials.h"

#include <array>
#include <string_view>

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

PartMaterial CeilingMaterial() { return {"ceiling", {0.96, 0.96, 0.94}, 1.0, 0.95}; }

PartMaterial PbrByName(PartMaterial m) {
  const std::string_view name = m.name;
  auto has = [&](std::string_view w) { return name.find(w) != std::string_view::npos; };
  // Finishes that cover the metal, and fabrics named after one.
  for (std::string_view cover : {"paint", "lacquer", "enamel", "brocade", "velvet", "fabric", "wool", "leather"})
    if (has(cover)) return m;
  struct Metal {
    std::string_view word;
    double roughness;
  };
  static constexpr std::array<Metal, 12> kMetals = {{{"mirror", 0.05}, {"chrome", 0.15}, {"stainless", 0.3}, {"steel", 0.4},
                                                     {"brass", 0.3}, {"gold", 0.3}, {"copper", 0.35}, {"bronze", 0.45},
                                                     {"silver", 0.25}, {"aluminium", 0.35}, {"iron", 0.6}, {"metal", 0.5}}};
  for (const Metal& metal : kMetals)
    if (has(metal.word)) {
      m.metallic = 1.0;
      m.roughness = metal.roughness;
      return m;
    }
  return m;
}

}  // namespace villa
