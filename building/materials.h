#pragma once
// The look of each part: one material per room category (floors, from the shared palette) and per
// part kind. The exporters and the preview renderer read the same table.
#include <string>

#include "building/building.h"
#include "render/palette.h"

namespace villa {

struct PartMaterial {
  std::string name;    // "floor-kitchen", "exterior-wall", "glass", ...
  Rgb color;           // sRGB, [0, 1]
  double alpha = 1.0;  // < 1: transparent (glass)
  double roughness = 0.9;
};

PartMaterial MaterialOf(const MeshPart& part);

}  // namespace villa
