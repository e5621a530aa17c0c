#pragma once
// The look of each part: floors by what they are made of (issue 31: oak, tile, stone or carpet by the room's
// type, in the colours of the villa's style), walls, roof, glass, doors and stairs by part kind. The
// exporters and the preview renderer read the same table; the plan's zone colours stay in plan.png.
#include <string>
#include <string_view>

#include "building/building.h"
#include "render/palette.h"

namespace villa {

struct PartMaterial {
  std::string name;    // "floor-oak", "floor-porcelain", "exterior-wall", "glass", ...
  Rgb color;           // sRGB, [0, 1]
  double alpha = 1.0;  // < 1: transparent (glass)
  double roughness = 0.9;
  double metallic = 0.0;  // glTF's metallicFactor: 1 for bare metal and mirrors (PbrByName)
};

// What a floor is made of.
enum class FloorFinish { kWood, kTile, kStone, kCarpet };
// By room type: tile in kitchens and bathrooms, stone in halls (utility rooms) and on balconies, carpet in
// children's rooms and in a classic villa's bedrooms, wood elsewhere.
FloorFinish FinishOf(Category category, std::string_view style);
// `style`: the villa's ("modern", "classic", "rustic", "scandinavian"; anything else reads as modern), which
// colours its floors and its interior and exterior walls.
PartMaterial MaterialOf(const MeshPart& part, std::string_view style = "");
// The underside of a floor slab (issue 31): one white ceiling for every room, whatever the room above.
PartMaterial CeilingMaterial();
// A stair's treads (its up-facing faces; issue 31: the stairs were grey blocks): the style's wood floor,
// named "stair-tread"; risers, strings and soffit stay `stair`.
PartMaterial StairTreadMaterial(std::string_view style = "");
// A material as what it is made of, read from its name: bare metals ("chrome", "stainless-steel", "brass",
// "copper", "wrought-iron", "...-metal") metallic, polished ones smoother; a mirror a smooth metal; painted,
// lacquered and enamelled finishes and fabrics ("gold-brocade") stay dielectric. Other fields unchanged.
PartMaterial PbrByName(PartMaterial m);

}  // namespace villa
