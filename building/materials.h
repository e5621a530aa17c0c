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
  double metallic = 0.0;  // glTF's metallicFactor: 1 for bare metal and mirrors (PbrByName)
};

PartMaterial MaterialOf(const MeshPart& part);
// The underside of a floor slab (issue 31): one white ceiling for every room, whatever the room above.
PartMaterial CeilingMaterial();
// A material as what it is made of, read from its name: bare metals ("chrome", "stainless-steel", "brass",
// "copper", "wrought-iron", "...-metal") metallic, polished ones smoother; a mirror a smooth metal; painted,
// lacquered and enamelled finishes and fabrics ("gold-brocade") stay dielectric. Other fields unchanged.
PartMaterial PbrByName(PartMaterial m);

}  // namespace villa
