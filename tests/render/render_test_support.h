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
// touch, doors and opens on one room's boundary only, upper floors without interior walls.
inline const char* kPaperExample = R"json({
  "rooms": {
      "utility-room_0/0": {"shape": "shapely.box(0, 0, 4, 4)"},
      "kitchen_0/0": {"shape": "shapely.box(4, 0, 8, 4)"},
      "dining-room_0/0": {"shape": "shapely.Polygon([(8, 0), (12, 0), (10, 4), (8, 4)])"},
      "living-room_0/0": {"shape": "shapely.box(0, 8, 20, 16)"},
      "bathroom_0/0": {"shape": "shapely.Polygon([(10, 4), (13, 4), (13, 8), (10, 8)])"},
      "utility-room_1/0": {"shape": "shapely.box(0, 0, 4, 4)"},
      "bedroom_1/0": {"shape": "shapely.box(4, 0, 8, 4)"},
      "meeting-room_1/0": {"shape": "shapely.box(0, 4, 8, 8)"},
      "office_1/0": {"shape": "shapely.Polygon([(8, 4), (11, 4), (11, 8), (8, 8)])"},
      "balcony_1/0": {"shape": "shapely.Polygon([(8, 0), (10, 2), (8, 4)])"},
      "utility-room_2/0": {"shape": "shapely.box(0, 0, 4, 4)"},
      "children-room_2/0": {"shape": "shapely.box(0, 4, 8, 8)"},
      "bathroom_2/0": {"shape": "shapely.box(4, 0, 8, 4)"},
      "balcony_2/0": {"shape": "shapely.Polygon([(8, 4), (10, 6), (8, 8)])"}
  },
  "entrance": {
      "main_door": {"shape": "shapely.LineString([(0, 5), (0, 7)])", "level": 0}
  },
  "doors": {
      "living0_kitchen0": {"shape": "shapely.LineString([(5, 4), (7, 4)])", "level": 0},
      "living0_bathroom0": {"shape": "shapely.LineString([(10, 5), (10, 7)])", "level": 0},
      "meeting1_bedroom1": {"shape": "shapely.LineString([(5, 4), (7, 4)])", "level": 1},
      "meeting1_office1": {"shape": "shapely.LineString([(8, 5), (8, 7)])", "level": 1},
      "bedroom1_balcony1": {"shape": "shapely.LineString([(8, 1), (8, 3)])", "level": 1},
      "children2_bathroom2": {"shape": "shapely.LineString([(5, 4), (7, 4)])", "level": 2},
      "children2_balcony2": {"shape": "shapely.LineString([(8, 5), (8, 7)])", "level": 2}
  },
  "opens": {
      "utility0_living0": {"shape": "shapely.LineString([(1, 4), (3, 4)])", "level": 0},
      "kitchen0_dining0": {"shape": "shapely.LineString([(8, 1), (8, 3)])", "level": 0},
      "utility1_meeting1": {"shape": "shapely.LineString([(1, 4), (3, 4)])", "level": 1},
      "utility2_children2": {"shape": "shapely.LineString([(1, 4), (3, 4)])", "level": 2}
  },
  "windows": {
      "kitchen0_window": {"shape": "shapely.LineString([(5, 0), (7, 0)])", "is_panoramic": 0, "level": 0},
      "bathroom0_window": {"shape": "shapely.LineString([(13, 5), (13, 7)])", "is_panoramic": 0, "level": 0},
      "office1_window": {"shape": "shapely.LineString([(11, 6), (11, 7)])", "is_panoramic": 0, "level": 1},
      "balcony1_pano": {"shape": "shapely.LineString([(8, 0), (10, 2)])", "is_panoramic": 1, "level": 1},
      "bathroom2_window": {"shape": "shapely.LineString([(5, 0), (7, 0)])", "is_panoramic": 0, "level": 2},
      "balcony2_pano": {"shape": "shapely.LineString([(8, 4), (10, 6)])", "is_panoramic": 1, "level": 2}
  },
  "interiors": {
      "wall_utility0_kitchen0": {"shape": "shapely.LineString([(4, 0), (4, 4)])", "level": 0},
      "wall_utility0_living0": {"shape": "shapely.LineString([(0, 4), (4, 4)])", "level": 0},
      "wall_living0_kitchen0": {"shape": "shapely.LineString([(4, 4), (8, 4)])", "level": 0},
      "wall_living0_dining0": {"shape": "shapely.LineString([(8, 4), (10, 4)])", "level": 0},
      "wall_kitchen0_dining0": {"shape": "shapely.LineString([(8, 0), (8, 4)])", "level": 0}
  }
})json";

inline Layout PaperExample() {
  Result<Layout> layout = ParseLayoutText(kPaperExample, "paper.json");
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
