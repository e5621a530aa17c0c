#include "render/palette.h"

#include <algorithm>
#include <cmath>

namespace villa {
namespace {

constexpr Rgb Hex(unsigned value) {
  return {((value >> 16) & 0xff) / 255.0, ((value >> 8) & 0xff) / 255.0, (value & 0xff) / 255.0};
}

}  // namespace

Rgb CategoryColor(Category category) {
  // Hand-tuned pastels: warm hues for the day rooms (living, dining, kitchen), cool for the night and
  // wet rooms (bedroom, bathroom), distinct hues for work rooms, neutral for utility and unlabelled.
  switch (category) {
    case Category::kLivingRoom: return Hex(0xFBBF7E);    // apricot
    case Category::kBedroom: return Hex(0x9EC1EE);       // soft blue
    case Category::kKitchen: return Hex(0xF7A08F);       // salmon
    case Category::kBathroom: return Hex(0x8ED6D6);      // aqua
    case Category::kDiningRoom: return Hex(0xF8E57A);    // butter yellow
    case Category::kChildrenRoom: return Hex(0xF6BCD8);  // pink
    case Category::kOffice: return Hex(0xC7B6EA);        // lavender
    case Category::kMeetingRoom: return Hex(0xB5DA8E);   // leaf green
    case Category::kUtilityRoom: return Hex(0xCFCFCC);   // warm grey
    case Category::kBalcony: return Hex(0xDCCBA8);       // decking tan
    case Category::kRoom: return Hex(0xEEEEE8);          // off-white
  }
  return Hex(0xEEEEE8);
}

Rgb CategoryInk(Category category) {
  const Rgb fill = CategoryColor(category);
  return {fill.r * 0.55, fill.g * 0.55, fill.b * 0.55};
}

Rgb InvalidElementColor() { return Hex(0xDB1C17); }

int ToByte(double channel) { return static_cast<int>(std::lround(std::clamp(channel, 0.0, 1.0) * 255.0)); }

}  // namespace villa
