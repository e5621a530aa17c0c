#include "assets/asset_views.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "mesh/solids.h"

namespace villa {
namespace {

constexpr Rgb kSurfaceColours[] = {{0.10, 0.62, 0.36}, {0.16, 0.45, 0.85}, {0.90, 0.55, 0.10}, {0.62, 0.25, 0.75}, {0.85, 0.20, 0.30}};
constexpr Rgb kCavityColour{0.95, 0.75, 0.10};

std::string Fixed(double v, int digits) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", digits, v);
  return text;
}

// A point of the scene that lands on pixel (px, py) of an orthographic camera's picture.
Vec3 AtPixel(const Camera& c, double px, double py) {
  const Vec3 forward = Normalized(c.target - c.position);
  const Vec3 right = Normalized(Cross(forward, c.up));
  const Vec3 up = Cross(right, forward);
  const double h = c.ortho_height, w = h * c.width / c.height;
  return c.target + right * ((px / c.width - 0.5) * w) + up * ((0.5 - py / c.height) * h);
}

// The record's surfaces as 6 mm slabs and its cavities as boxes, with their labels.
struct Overlays {
  std::vector<TriangleMesh> meshes;
  std::vector<Rgb> colours;
  std::vector<double> alphas;
  std::vector<ViewLabel> labels;
};

Overlays OverlaysOf(const AssetRecord& r) {
  Overlays o;
  for (size_t i = 0; i < r.support_surfaces.size(); ++i) {
    const SupportSurface& s = r.support_surfaces[i];
    if (s.polygon.size() < 3) continue;
    o.meshes.push_back(ExtrudePlan(s.polygon, {}, s.z, s.z + 0.006));
    o.colours.push_back(kSurfaceColours[i % std::size(kSurfaceColours)]);
    o.alphas.push_back(0.75);
    Point c{0, 0};
    for (const Point& p : s.polygon) c.x += p.x / s.polygon.size(), c.y += p.y / s.polygon.size();
    std::string label = "S";
    label += std::to_string(i);
    label += ' ';
    label += Fixed(s.z, 2);
    o.labels.push_back({Vec3{c.x, c.y, s.z + 0.02}, label});
  }
  for (size_t k = 0; k < r.cavities.size(); ++k) {
    const Cavity& c = r.cavities[k];
    const Ring box{{c.min.x, c.min.y}, {c.max.x, c.min.y}, {c.max.x, c.max.y}, {c.min.x, c.max.y}};
    o.meshes.push_back(ExtrudePlan(box, {}, c.min.z, c.max.z));
    o.colours.push_back(kCavityColour);
    o.alphas.push_back(0.3);
    std::string label = "C";
    label += std::to_string(k);
    o.labels.push_back({(c.min + c.max) * 0.5, label});
  }
  return o;
}

}  // namespace

std::string AssetViewOptions::Check() const {
  if (size_px < 64 || size_px > 4096) return "view size " + std::to_string(size_px) + " px: must be in [64, 4096]";
  if (!(elevation_deg >= 0.0 && elevation_deg <= 80.0)) return "view elevation: must be in [0, 80] degrees";
  if (samples < 1 || samples > 4) return "samples " + std::to_string(samples) + ": must be in [1, 4]";
  if (threads < 0) return "threads: must be >= 0";
  return "";
}

Result<std::vector<AssetView>> RenderAssetViews(const AssetRecord& record, const AssetMesh& mesh, const AssetViewOptions& options) {
  if (std::string problem = options.Check(); !problem.empty()) return Error{record.id + ": asset views: " + problem};
  if (mesh.parts.empty()) return Error{record.id + ": asset views: the mesh is empty"};
  ViewScene scene;
  scene.floor_z = {0.0};
  for (const AssetMeshPart& part : mesh.parts)
    scene.meshes.push_back({&part.mesh, Rgb{part.material.r, part.material.g, part.material.b}, part.material.alpha, std::nullopt, 0,
                            CutAway::kKeep});
  const Overlays overlays = options.overlays ? OverlaysOf(record) : Overlays{};
  for (size_t k = 0; k < overlays.meshes.size(); ++k)
    scene.meshes.push_back({&overlays.meshes[k], overlays.colours[k], overlays.alphas[k], std::nullopt, 0, CutAway::kKeep});
  // The asset's box (what the record says) and its mesh, framed together.
  Box3 box = mesh.Bounds();
  box.Add(Vec3{-0.5 * record.size.x, -0.5 * record.size.y, 0.0});
  box.Add(Vec3{0.5 * record.size.x, 0.5 * record.size.y, record.size.z});
  RenderOptions render;
  render.samples = options.samples;
  render.threads = options.threads;
  render.shadows = false;  // shadows of the thing on itself hide shelves
  render.ambient = 0.55;
  LabelStyle style;
  style.font_px = std::clamp(options.size_px / 36.0, 9.0, 20.0);
  const char* sides[4] = {"-y", "+x", "+y", "-x"};
  std::vector<AssetView> out;
  for (int k = 0; k < 4; ++k) {
    AssetView view;
    view.side = sides[k];
    view.azimuth_deg = 90.0 * k;
    view.camera = FramingCamera(box, view.azimuth_deg, options.elevation_deg, options.size_px, options.size_px);
    auto image = RenderView(scene, view.camera, render);
    if (!image.ok()) return Error{record.id + ": asset views: " + image.error()};
    view.image = std::move(*image);
    if (!overlays.labels.empty())
      if (Status s = DrawLabels(view.image, view.camera, overlays.labels, style); !s.ok()) return Error{s.error()};
    out.push_back(std::move(view));
  }
  return out;
}

Result<Image> AssetViewSheet(const std::vector<AssetView>& views, int gap) {
  if (views.size() != 4) return Error{"asset view sheet: expected 4 views, got " + std::to_string(views.size())};
  const int w = views[0].image.width, h = views[0].image.height;
  for (const AssetView& v : views)
    if (v.image.width != w || v.image.height != h) return Error{"asset view sheet: the views differ in size"};
  Image out{2 * w + gap, 2 * h + gap, {}};
  out.rgb.assign(size_t{3} * out.width * out.height, 255);
  LabelStyle caption;
  caption.font_px = std::clamp(w / 30.0, 9.0, 22.0);
  for (int k = 0; k < 4; ++k) {
    Image panel = views[k].image;
    const std::string words = "seen from " + views[k].side + (views[k].side == "-y" ? " (recorded front)" : "");
    const Vec3 at = AtPixel(views[k].camera, 0.5 * w, 0.5 * caption.font_px + 6.0);
    if (Status s = DrawLabels(panel, views[k].camera, {{at, words}}, caption); !s.ok()) return Error{s.error()};
    const int x0 = (k % 2) * (w + gap), y0 = (k / 2) * (h + gap);
    for (int y = 0; y < h; ++y)
      std::copy_n(panel.rgb.begin() + size_t{3} * y * w, size_t{3} * w, out.rgb.begin() + size_t{3} * (size_t(y0 + y) * out.width + x0));
  }
  return out;
}

}  // namespace villa
