#pragma once
// Shared by the render tests: the bundled examples, the paper's invalid example, PNG decoding.
#include <catch2/catch.hpp>

#include <stb_image.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "layout/layout_io.h"
#include "render/palette.h"

namespace villa::test {

inline std::filesystem::path ExamplePath(const std::string& name) {
  return std::filesystem::path(VILLA_SOURCE_DIR) / "examples" / name;
}

inline std::vector<std::string> ExampleNames() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(VILLA_SOURCE_DIR) / "examples")) {
    if (entry.path().extension() == ".json") names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

inline Layout LoadExample(const std::string& name) {
  Result<Layout> layout = LoadLayout(ExamplePath(name));
  INFO(name << ": " << (layout.ok() ? "" : layout.error()));
  REQUIRE(layout.ok());
  return *layout;
}

// The paper's own example ("A text-JSON pair", without its "..." line): ground-floor rooms that do not
// touch, doors and opens on one room's boundary only, upper floors without interior walls. The same
// fixture the validator's tests use.
inline Layout PaperExample() {
  Result<Layout> layout = LoadLayout(std::filesystem::path(VILLA_FIXTURE_DIR) / "layouts" / "paper_example.json");
  INFO((layout.ok() ? "" : layout.error()));
  REQUIRE(layout.ok());
  return *layout;
}

// A decoded 8-bit RGB picture.
struct Picture {
  int width = 0;
  int height = 0;
  std::vector<unsigned char> rgb;
  Rgb At(int x, int y) const {
    const size_t i = (static_cast<size_t>(y) * width + x) * 3;
    return {rgb[i] / 255.0, rgb[i + 1] / 255.0, rgb[i + 2] / 255.0};
  }
  // Channel values 0..255 equal within `tolerance`.
  bool Is(int x, int y, const Rgb& color, int tolerance = 1) const {
    const size_t i = (static_cast<size_t>(y) * width + x) * 3;
    return std::abs(rgb[i] - ToByte(color.r)) <= tolerance && std::abs(rgb[i + 1] - ToByte(color.g)) <= tolerance &&
           std::abs(rgb[i + 2] - ToByte(color.b)) <= tolerance;
  }
};

inline Picture DecodePng(const std::string& png) {
  REQUIRE(png.size() > 8);
  REQUIRE(png.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);
  int w = 0, h = 0, channels = 0;
  unsigned char* data = stbi_load_from_memory(reinterpret_cast<const unsigned char*>(png.data()),
                                              static_cast<int>(png.size()), &w, &h, &channels, 3);
  REQUIRE(data != nullptr);
  Picture picture{w, h, std::vector<unsigned char>(data, data + static_cast<size_t>(w) * h * 3)};
  stbi_image_free(data);
  return picture;
}

}  // namespace villa::test
