#include "assets/texture_colour.h"

#include <stb_image.h>

namespace villa {

Result<std::array<double, 3>> MeanTextureColour(std::string_view encoded, const std::string& where) {
  int width = 0, height = 0, channels = 0;
  stbi_uc* pixels = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(encoded.data()),
                                          static_cast<int>(encoded.size()), &width, &height, &channels, 3);
  if (!pixels) {
    const char* why = stbi_failure_reason();
    return Error{where + ": unreadable image (" + std::string(why ? why : "unknown reason") + ")"};
  }
  double sum[3] = {0, 0, 0};
  std::size_t count = static_cast<std::size_t>(width) * height;
  for (std::size_t i = 0; i < count; ++i)
    for (int c = 0; c < 3; ++c) sum[c] += pixels[3 * i + c];
  stbi_image_free(pixels);
  if (count == 0) return Error{where + ": image has no pixels"};
  return std::array<double, 3>{sum[0] / (255.0 * count), sum[1] / (255.0 * count), sum[2] / (255.0 * count)};
}

}  // namespace villa
