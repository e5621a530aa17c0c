#pragma once
// The category palette shared by every picture villa makes: floor plans, the 3D view, the annotator's
// terminal colours and the glTF materials (the words for a category are layout.h's). Fill colours are light enough for dark text on top and far enough
// apart (hue and lightness) to tell the ten categories and `room` apart side by side.
#include <string_view>

#include "layout/layout.h"

namespace villa {

// A colour with channels in [0, 1] (sRGB).
struct Rgb {
  double r = 0.0;
  double g = 0.0;
  double b = 0.0;
  friend bool operator==(const Rgb&, const Rgb&) = default;
};

// The fill colour of a room of `category`.
Rgb CategoryColor(Category category);

// A darker shade of CategoryColor for outlines and text in that hue (legend swatch borders).
Rgb CategoryInk(Category category);

// The colour of what is wrong: elements that are not where the format puts them.
Rgb InvalidElementColor();

// 0..255 channel value of a [0, 1] channel, rounded (what an 8-bit PNG stores).
int ToByte(double channel);

}  // namespace villa
