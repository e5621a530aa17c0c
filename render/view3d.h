#pragma once
// The 3D view: headless CPU pictures (Embree 3 ray casting) of a neutral scene, a list of triangle meshes
// each with a colour (and alpha), a level, and what a cut-away may do with it. The same renderer draws a
// whole villa (building/view_scene.h turns a BuildingMesh into a scene: `villa build --preview`),
// furniture, one room from its corners, or a top view; labels (object ids) can be written over a picture
// at 3D points. Lambert + ambient shading, optional shadow rays, see-through meshes blended, and a
// cut-away mode: the levels above one hidden, the cuttable meshes of that level cut at a height above its
// floor with the cut faces filled dark. Frame: mesh.h's (metres, z up). Embree and cairo stay inside
// view3d.cpp.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "layout/layout.h"
#include "mesh/mesh.h"
#include "render/palette.h"
#include "util/result.h"

namespace villa {

// What a cut-away (RenderOptions::top_level >= 0) does with a mesh of the shown levels.
enum class CutAway {
  kKeep,    // drawn whole (floor slabs, terraces, furniture)
  kCut,     // on the top shown level, cut at the cut height: the part above is gone, the cut faces are
            // filled (walls, door leaves, glass, stairs)
  kRemove,  // left out of every cut-away (the roof)
};

struct ViewMesh {
  const TriangleMesh* mesh = nullptr;  // borrowed: must outlive the scene's use; CCW from outside
  Rgb color;                           // sRGB, [0, 1]
  // < 1: see-through (glass): blended over what lies behind, seen from its front only, casting no shadow.
  double alpha = 1.0;
  // Faces steeper than 60 degrees (|normal.z| < 0.5) take this colour instead (the edges of a floor slab).
  std::optional<Rgb> side_color;
  int level = 0;                 // hidden in a cut-away of a lower level
  CutAway cut = CutAway::kKeep;
};

struct ViewScene {
  std::vector<ViewMesh> meshes;
  // Floor surface height of each level, m: a cut-away of level L cuts at floor_z[L] + cut_height.
  std::vector<double> floor_z;
  Box3 Bounds() const;  // of every mesh
};

struct Camera {
  Vec3 position{-10, -12, 14};
  Vec3 target{0, 0, 0};
  Vec3 up{0, 0, 1};
  double fov_deg = 45.0;        // vertical field of view (perspective), degrees, (0, 170)
  bool orthographic = false;    // parallel projection (isometric and top views)
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
  // Cut-away: meshes of levels above `top_level` are hidden (kRemove ones at every level), and the kCut
  // meshes of `top_level` are cut at `cut_height` m above its floor, the cut faces drawn in
  // `section_color`. top_level < 0: everything shown, nothing cut.
  int top_level = -1;
  double cut_height = 1.5;
  Rgb section_color{0.22, 0.22, 0.25};
  int threads = 0;  // 0: all hardware threads
};

// Renders the scene as seen by `camera`. Fails for an unusable camera or options, or a cut-away level
// the scene has no floor height for.
Result<Image> RenderView(const ViewScene& scene, const Camera& camera, const RenderOptions& options = {});

// An orthographic camera looking at `box` from `azimuth_deg` (0 = from -y, the plan's south, growing
// counter-clockwise) and `elevation_deg` above the horizon (90: straight down, the plan's north up the
// picture at azimuth 0), framing the box with a small margin.
Camera FramingCamera(const Box3& box, double azimuth_deg, double elevation_deg, int width, int height);

// The views a critic looks at a room with: a top view, then views from its four corners (azimuth 45,
// 135, 225, 315 degrees, `elevation_deg` up), each `size_px` square, framing `box` (the room's floor and
// what stands on it). Draw them with a cut-away of the room's level so its walls are cut open.
std::vector<Camera> RoomCameras(const Box3& box, int size_px = 768, double elevation_deg = 40.0);

struct PreviewOptions {
  int panel_width = 560;   // px, each panel
  int panel_height = 460;  // px
  double azimuth_deg = -35.0;
  double elevation_deg = 38.0;
  double cut_height = 1.5;  // m above each floor
  bool exterior_panel = true;  // first panel: the whole scene from outside
  int samples = 2;
  int gap = 8;  // px of background between panels
};

// Side by side: the whole scene (optional), then an isometric cut-away of each level of scene.floor_z.
Result<Image> RenderPreview(const ViewScene& scene, const PreviewOptions& options = {});

// Where `p` lands in the picture of `camera` (x right, y down, pixels); nothing when it lies behind a
// perspective camera.
std::optional<Point> ProjectToPixel(const Camera& camera, Vec3 p);

// A short text written over a picture at a 3D point (an object id).
struct ViewLabel {
  Vec3 at;
  std::string text;
};
struct LabelStyle {
  double font_px = 13.0;                // 6..48
  std::string font_family = "DejaVu Sans";  // cairo "toy" font selection (fontconfig name)
  Rgb text{0.08, 0.09, 0.11};
  Rgb background{1.0, 1.0, 1.0};
  double background_alpha = 0.8;        // of the box behind the text, [0, 1]
  double padding_px = 2.0;
};
// Writes each label centred on its point's projection (labels off the picture or behind the camera are
// skipped), on a light box so it reads over any surface. Labels are drawn in order, later ones on top.
Status DrawLabels(Image& image, const Camera& camera, const std::vector<ViewLabel>& labels,
                  const LabelStyle& style = {});

Result<std::string> EncodePng(const Image& image);
Status WritePng(const Image& image, const std::filesystem::path& path);  // atomic

}  // namespace villa
