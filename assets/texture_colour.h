#pragma once
// The mean colour of a texture image (PNG, JPEG, BMP, TGA, GIF: what stb_image reads), for a textured
// material of an imported model: our meshes carry one colour per material.
#include <array>
#include <string>
#include <string_view>

#include "util/result.h"

namespace villa {

// sRGB in [0, 1], the plain mean over the pixels (alpha ignored). The error names `where`.
Result<std::array<double, 3>> MeanTextureColour(std::string_view encoded, const std::string& where);

}  // namespace villa
