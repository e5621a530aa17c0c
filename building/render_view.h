#pragma once
// Headless CPU pictures of a built villa (Embree 3 ray casting): any camera to an RGB image or PNG,
// with per-material colour, Lambert + ambient shading, optional shadow rays, glass blended, and a
// cut-away mode (hide the levels above one, cut its walls at a height and fill the cut dark). The
// same renderer gives the preview of `villa build --preview` and, later, the critic's views.
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "building/building.h"
#include "render/palette.h"
#include "util/result.h"

namespace villa {

// Building frame (mesh.h): metres, z up.
struct Camera {
  Vec3 position{-10, -12, 14};
  Vec3 target{0, 0, 0};
  Vec3 up{0, 0, 1};
  double fov_deg = 45.0;        // vertical field of view (perspective), degrees, (0, 170)
  bool orthographic = false;    // parallel projection (isometric views)
  double ortho_height = 20.0;   // m of the scene spanning the image height (orthographic only)
  int width = 800;              // px
  int height = 600;             // px
  std::string Check() const;    // empty when usable
};

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // row-major from the top, 3 bytes a pixel
  Rgb At(int x, int y) const;
};

struct RenderOptions {
  Rgb background{1.0, 1.0, 1.0};
  Vec3 light_direction{-0.55, -0.85, 0.8};  // towards the light (sun), need not be unit
  double ambient = 0.45;                    // share of light that reaches every surface, [0, 1]
  bool shadows = true;
  int samples = 1;                          // per axis per pixel (2 = 4 rays a pixel, anti-aliased), 1..4
  // Cut-away: levels above `top_level` are hidden (the roof too unless top_level is the top), and the
  // walls, doors, glass and stairs of `top_level` are cut at `cut_height` m above its floor surface,
  // the cut faces drawn in `section_color`. top_level < 0: everything shown, nothing cut.
  int top_level = -1;
  double cut_height = 1.5;
  Rgb section_color{0.22, 0.22, 0.25};
  int threads = 0;  // 0: all hardware threads
};

// Renders the building as seen by `camera`.
Result<Image> RenderView(const BuildingMesh& building, const Camera& camera, const RenderOptions& options = {});

// An orthographic camera looking at the whole building from `azimuth_deg` (0 = from -y, the plan's
// south, growing counter-clockwise) and `elevation_deg` above the horizon, framing it with a margin.
Camera FramingCamera(const BuildingMesh& building, double azimuth_deg, double elevation_deg, int width, int height);

struct PreviewOptions {
  int panel_width = 560;   // px, each panel
  int panel_height = 460;  // px
  double azimuth_deg = -35.0;
  double elevation_deg = 38.0;
  double cut_height = 1.5;  // m above each floor
  bool exterior_panel = true;  // first panel: the whole building from outside
  int samples = 2;
  int gap = 8;  // px of background between panels
};

// Side by side: the whole building (optional), then an isometric cut-away of each level.
Result<Image> RenderPreview(const BuildingMesh& building, const PreviewOptions& options = {});

Result<std::string> EncodePng(const Image& image);
Status WritePng(const Image& image, const std::filesystem::path& path);  // atomic

}  // namespace villa
