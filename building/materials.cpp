#include "building/materials.h"

#include <array>
#include <string_view>

namespace villa {

namespace {

// A style's finishes, sRGB: wood, tile, stone and carpet floors (name and colour), then interior and
// exterior wall paint.
struct Palette {
  std::string_view style;
  std::array<std::pair<std::string_view, Rgb>, 4> floors;  // by FloorFinish
  Rgb interior_wall, exterior_wall;
};

constexpr std::array<Palette, 4> kPalettes = {{
    {"modern",
     {{{"floor-oak-grey", {0.66, 0.60, 0.53}}, {"floor-porcelain", {0.80, 0.80, 0.78}}, {"floor-concrete", {0.60, 0.60, 0.58}},
       {"floor-carpet-grey", {0.52, 0.53, 0.55}}}},
     {0.95, 0.95, 0.94},
     {0.90, 0.90, 0.88}},
    {"classic",
     {{{"floor-walnut", {0.45, 0.30, 0.20}}, {"floor-marble", {0.90, 0.88, 0.84}}, {"floor-limestone", {0.76, 0.71, 0.62}},
       {"floor-carpet-burgundy", {0.50, 0.24, 0.25}}}},
     {0.94, 0.90, 0.82},
     {0.93, 0.90, 0.84}},
    {"rustic",
     {{{"floor-pine", {0.64, 0.46, 0.30}}, {"floor-terracotta", {0.70, 0.42, 0.30}}, {"floor-flagstone", {0.57, 0.53, 0.47}},
       {"floor-carpet-wool", {0.66, 0.60, 0.50}}}},
     {0.93, 0.89, 0.80},
     {0.86, 0.80, 0.70}},
    {"scandinavian",
     {{{"floor-oak-white", {0.83, 0.74, 0.60}}, {"floor-tile-white", {0.91, 0.91, 0.89}}, {"floor-stone-grey", {0.74, 0.74, 0.72}},
       {"floor-carpet-cream", {0.82, 0.79, 0.73}}}},
     {0.97, 0.97, 0.96},
     {0.96, 0.96, 0.95}},
}};

const Palette& PaletteOf(std::string_view style) {
  for (const Palette& p : kPalettes)
    if (p.style == style) return p;
  return kPalettes[0];
}

// Roughness by finish: oiled wood, glazed tile, honed stone, carpet.
constexpr std::array<double, 4> kFinishRoughness = {0.55, 0.25, 0.8, 1.0};

}  // namespace

FloorFinish FinishOf(Category category, std::string_view style) {
  switch (category) {
    case Category::kKitchen:
    case Category::kBathroom: return FloorFinish::kTile;
    case Category::kUtilityRoom:
    case Category::kBalcony: return FloorFinish::kStone;
    case Category::kChildrenRoom: return FloorFinish::kCarpet;
    case Category::kBedroom: return style == "classic" ? FloorFinish::kCarpet : FloorFinish::kWood;
    default: return FloorFinish::kWood;
  }
}

PartMaterial MaterialOf(const MeshPart& part, std::string_view style) {
  const Palette& palette = PaletteOf(style);
  switch (part.kind) {
    case PartKind::kFloor: {
      const auto finish = static_cast<size_t>(FinishOf(part.category, palette.style));
      const auto& [name, color] = palette.floors[finish];
      return {std::string(name), color, 1.0, kFinishRoughness[finish]};
    }
    case PartKind::kTerrace: return {"terrace", {0.72, 0.70, 0.66}, 1.0, 0.95};
    case PartKind::kRoof: return {"roof", {0.55, 0.36, 0.30}, 1.0, 0.9};
    case PartKind::kExteriorWall: return {"exterior-wall", palette.exterior_wall, 1.0, 0.9};
    case PartKind::kInteriorWall: return {"interior-wall", palette.interior_wall, 1.0, 0.9};
    case PartKind::kDoorLeaf: return {"door", {0.55, 0.38, 0.22}, 1.0, 0.6};
    case PartKind::kWindowGlass: return {"glass", {0.62, 0.80, 0.92}, 0.35, 0.05};
    case PartKind::kStair: return {"stair", {0.62, 0.60, 0.58}, 1.0, 0.85};
    case PartKind::kRailing: return {"railing-steel", {0.30, 0.31, 0.33}, 1.0, 0.4, 1.0};
    case PartKind::kWindowFrame: return {"window-frame", {0.95, 0.95, 0.94}, 1.0, 0.5};
  }
  return {"default", {0.8, 0.8, 0.8}, 1.0, 0.9};
}

PartMaterial CeilingMaterial() { return {"ceiling", {0.96, 0.96, 0.94}, 1.0, 0.95}; }

PartMaterial StairTreadMaterial(std::string_view style) {
  const auto& wood = PaletteOf(style).floors[static_cast<size_t>(FloorFinish::kWood)];
  return {"stair-tread", wood.second, 1.0, kFinishRoughness[static_cast<size_t>(FloorFinish::kWood)]};
}

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
