#include "render/view3d.h"

#include <cairo.h>
#include <png.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <thread>

#include "mesh/ray_caster.h"
#include "util/atomic_file.h"

namespace villa {
namespace {

class Tracer {
 public:
  Tracer(const ViewScene& scene, const RenderOptions& options) : scene_meshes_(scene.meshes), options_(options) {
    int top = options.top_level;
    for (size_t i = 0; i < scene.meshes.size(); ++i) {
      const ViewMesh& view = scene.meshes[i];
      if (top >= 0 && view.level > top) continue;
      if (top >= 0 && view.cut == CutAway::kRemove) continue;
      if (!view.mesh) continue;
      const int id = rays_.Add(*view.mesh);
      if (id < 0) continue;
      if (id >= static_cast<int>(mesh_of_.size())) mesh_of_.resize(id + 1, -1);
      mesh_of_[id] = static_cast<int>(i);
    }
    rays_.Commit();
    light_ = Normalized(options.light_direction);
    cut_z_ = top >= 0 ? scene.floor_z[top] + options.cut_height : std::numeric_limits<double>::infinity();
  }

  bool ok() const { return rays_.ok(); }

  Rgb Trace(Vec3 origin, Vec3 dir) const {
    Rgb color{0, 0, 0};
    double transmit = 1.0;
    float tnear = 0.0f;
    int inside = -1;  // the cut solid the ray is in, entered above the cut plane
    for (int bounce = 0; bounce < 24 && transmit > 0.01; ++bounce) {
      const std::optional<RayCaster::Hit> h = rays_.Cast(origin, dir, std::numeric_limits<float>::infinity(), tnear);
      if (!h) {
        Add(color, inside >= 0 ? options_.section_color : options_.background, transmit);
        break;
      }
      const int mesh_index = mesh_of_[h->mesh];
      const ViewMesh& view = scene_meshes_[mesh_index];
      Vec3 p = origin + dir * h->t;
      tnear = static_cast<float>(h->t) + 1e-4f;  // t is a float widened: stepping on stays in float
      Vec3 n = h->normal;
      bool back = Dot(n, dir) > 0.0;
      const bool glass = view.alpha < 1.0;
      // Entered a solid above the cut and now below it: the cut face is what shows. (The solid's own
      // exit may coincide with another mesh's face, e.g. a wall's bottom on the slab's top.)
      if (inside >= 0 && p.z <= cut_z_) {
        Add(color, options_.section_color, transmit);
        break;
      }
      if (view.cut == CutAway::kCut && p.z > cut_z_ && view.level == options_.top_level) {
        if (!back && !glass) inside = mesh_index;
        else if (back && inside == mesh_index) inside = -1;
        continue;
      }
      if (glass) {
        if (back) continue;
        Add(color, Mix(view.color, Shade(p, n)), transmit * view.alpha);
        transmit *= 1.0 - view.alpha;
        continue;
      }
      if (back) {  // inside a solid: we came in through a cut
        Add(color, options_.section_color, transmit);
        break;
      }
      // A floor's colour belongs on its top; the slab's edges (on the facade, round stair holes) may have
      // their own.
      Rgb base = view.side_color && std::abs(n.z) < 0.5 ? *view.side_color : view.color;
      Add(color, Mix(base, Shade(p, n)), transmit);
      break;
    }
    return color;
  }

 private:
  static void Add(Rgb& acc, Rgb c, double w) {
    acc.r += c.r * w;
    acc.g += c.g * w;
    acc.b += c.b * w;
  }
  static Rgb Mix(Rgb c, double light) { return {c.r * light, c.g * light, c.b * light}; }

  double Shade(Vec3 p, Vec3 n) const {
    double lambert = std::max(0.0, Dot(n, light_));
    if (lambert > 0.0 && options_.shadows && Occluded(p + n * 1e-3, light_)) lambert = 0.0;
    return options_.ambient + (1.0 - options_.ambient) * lambert;
  }

  bool Occluded(Vec3 origin, Vec3 dir) const {
    float tnear = 0.0f;
    for (int k = 0; k < 24; ++k) {
      const std::optional<RayCaster::Hit> h = rays_.Cast(origin, dir, 1e4, tnear);
      if (!h) return false;
      const ViewMesh& view = scene_meshes_[mesh_of_[h->mesh]];
      Vec3 p = origin + dir * h->t;
      tnear = static_cast<float>(h->t) + 1e-4f;
      if (view.alpha < 1.0) continue;
      if (view.cut == CutAway::kCut && p.z > cut_z_ && view.level == options_.top_level) continue;
      return true;
    }
    return false;
  }

  const std::vector<ViewMesh>& scene_meshes_;
  const RenderOptions& options_;
  RayCaster rays_;
  std::vector<int> mesh_of_;  // caster mesh id -> index into scene_meshes_
  Vec3 light_;
  double cut_z_ = 0.0;
};

// The camera's frame: unit forward, right and up, and the half height of the picture (m for an
// orthographic camera, the tangent of half the field of view for a perspective one).
struct CameraFrame {
  Vec3 forward, right, up;
  double half_h = 0.0, aspect = 1.0;
  explicit CameraFrame(const Camera& camera) {
    forward = Normalized(camera.target - camera.position);
    right = Normalized(Cross(forward, camera.up));
    up = Cross(right, forward);
    aspect = static_cast<double>(camera.width) / camera.height;
    half_h = camera.orthographic ? camera.ortho_height / 2.0 : std::tan(camera.fov_deg * std::numbers::pi / 360.0);
  }
};
std::uint8_t Byte(double c) { return static_cast<std::uint8_t>(std::clamp(std::lround(c * 255.0), 0L, 255L)); }

}  // namespace

std::string Camera::Check() const {
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    return "image size " + std::to_string(width) + " x " + std::to_string(height) + ": each side must be in [1, 16384]";
  if (Norm(target - position) < 1e-9) return "camera position equals its target";
  if (Norm(Cross(target - position, up)) < 1e-9) return "camera up is parallel to the viewing direction";
  if (!orthographic && !(fov_deg > 0.0 && fov_deg < 170.0)) return "fov_deg must be in (0, 170)";
  if (orthographic && !(ortho_height > 0.0)) return "ortho_height must be > 0";
  return "";
}

Rgb Image::At(int x, int y) const {
  size_t i = (static_cast<size_t>(y) * width + x) * 3;
  return {rgb[i] / 255.0, rgb[i + 1] / 255.0, rgb[i + 2] / 255.0};
}

Box3 ViewScene::Bounds() const {
  Box3 box;
  for (const ViewMesh& m : meshes)
    if (m.mesh) box.Add(m.mesh->Bounds());
  return box;
}

Result<Image> RenderView(const ViewScene& scene, const Camera& camera, const RenderOptions& options) {
  if (std::string problem = camera.Check(); !problem.empty()) return Error{"camera: " + problem};
  if (options.samples < 1 || options.samples > 4) return Error{"render: samples must be in [1, 4]"};
  if (options.top_level >= static_cast<int>(scene.floor_z.size()))
    return Error{"render: cut-away of level " + std::to_string(options.top_level) + ", but the scene has floor heights for " +
                 std::to_string(scene.floor_z.size()) + " level(s)"};
  Tracer tracer(scene, options);
  if (!tracer.ok()) return Error{"render: Embree device could not be created"};
  const CameraFrame frame(camera);
  const Vec3 forward = frame.forward, right = frame.right, up = frame.up;
  const double aspect = frame.aspect, half_h = frame.half_h;
  Image image{camera.width, camera.height, std::vector<std::uint8_t>(size_t{3} * camera.width * camera.height)};
  const int s = options.samples;
  std::atomic<int> next_row{0};
  auto work = [&] {
    for (int y; (y = next_row++) < camera.height;) {
      for (int x = 0; x < camera.width; ++x) {
        Rgb sum{0, 0, 0};
        for (int sy = 0; sy < s; ++sy)
          for (int sx = 0; sx < s; ++sx) {
            double u = (2.0 * (x + (sx + 0.5) / s) / camera.width - 1.0) * aspect * half_h;
            double v = (1.0 - 2.0 * (y + (sy + 0.5) / s) / camera.height) * half_h;
            Rgb c = camera.orthographic
                        ? tracer.Trace(camera.position + right * u + up * v, forward)
                        : tracer.Trace(camera.position, Normalized(forward + right * u + up * v));
            sum.r += c.r, sum.g += c.g, sum.b += c.b;
          }
        size_t i = (static_cast<size_t>(y) * camera.width + x) * 3;
        double w = 1.0 / (s * s);
        image.rgb[i] = Byte(sum.r * w);
        image.rgb[i + 1] = Byte(sum.g * w);
        image.rgb[i + 2] = Byte(sum.b * w);
      }
    }
  };
  int threads = options.threads > 0 ? options.threads : std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  return image;
}

Camera FramingCamera(const Box3& box, double azimuth_deg, double elevation_deg, int width, int height) {
  Vec3 centre = (box.min + box.max) * 0.5;
  double az = azimuth_deg * std::numbers::pi / 180.0, el = elevation_deg * std::numbers::pi / 180.0;
  // From -y (south) at azimuth 0, turning counter-clockwise.
  Vec3 towards_camera{-std::sin(-az) * std::cos(el), -std::cos(az) * std::cos(el), std::sin(el)};
  double radius = Norm(box.max - box.min);
  Camera cam;
  cam.orthographic = true;
  cam.width = width;
  cam.height = height;
  cam.target = centre;
  cam.position = centre + towards_camera * (2.0 * radius + 10.0);
  // Looking straight down, "up" in the picture is the way the camera faces (north at azimuth 0).
  cam.up = std::abs(std::cos(el)) < 1e-6 ? Vec3{-std::sin(az), std::cos(az), 0} : Vec3{0, 0, 1};
  Vec3 forward = Normalized(cam.target - cam.position);
  Vec3 right = Normalized(Cross(forward, cam.up));
  Vec3 up = Cross(right, forward);
  double w = 0.0, h = 0.0;
  for (int k = 0; k < 8; ++k) {
    Vec3 c{k & 1 ? box.max.x : box.min.x, k & 2 ? box.max.y : box.min.y, k & 4 ? box.max.z : box.min.z};
    w = std::max(w, std::abs(Dot(c - centre, right)));
    h = std::max(h, std::abs(Dot(c - centre, up)));
  }
  double aspect = static_cast<double>(width) / height;
  cam.ortho_height = 2.0 * std::max(h, w / aspect) * 1.06;
  return cam;
}

std::vector<Camera> RoomCameras(const Box3& box, int size_px, double elevation_deg) {
  std::vector<Camera> cameras{FramingCamera(box, 0.0, 90.0, size_px, size_px)};
  for (double azimuth : {45.0, 135.0, 225.0, 315.0})
    cameras.push_back(FramingCamera(box, azimuth, elevation_deg, size_px, size_px));
  return cameras;
}

Result<Image> RenderPreview(const ViewScene& scene, const PreviewOptions& options) {
  if (options.panel_width < 16 || options.panel_height < 16) return Error{"preview: panels must be at least 16 px"};
  Camera cam = FramingCamera(scene.Bounds(), options.azimuth_deg, options.elevation_deg, options.panel_width,
                             options.panel_height);
  std::vector<Image> panels;
  RenderOptions ro;
  ro.samples = options.samples;
  if (options.exterior_panel) {
    auto full = RenderView(scene, cam, ro);
    if (!full) return Error{full.error()};
    panels.push_back(std::move(*full));
  }
  for (int level = 0; level < static_cast<int>(scene.floor_z.size()); ++level) {
    ro.top_level = level;
    ro.cut_height = options.cut_height;
    auto img = RenderView(scene, cam, ro);
    if (!img) return Error{img.error()};
    panels.push_back(std::move(*img));
  }
  if (panels.empty()) return Error{"preview: nothing to draw (no exterior panel and no levels)"};
  int n = static_cast<int>(panels.size());
  Image out{n * options.panel_width + (n - 1) * options.gap, options.panel_height, {}};
  out.rgb.assign(size_t{3} * out.width * out.height, 255);
  for (int k = 0; k < n; ++k)
    for (int y = 0; y < out.height; ++y)
      std::copy_n(panels[k].rgb.begin() + size_t{3} * y * options.panel_width, 3 * options.panel_width,
                  out.rgb.begin() + (size_t{3} * y * out.width + size_t{3} * k * (options.panel_width + options.gap)));
  return out;
}

std::optional<Point> ProjectToPixel(const Camera& camera, Vec3 p) {
  const CameraFrame f(camera);
  const Vec3 d = p - camera.position;
  double u = Dot(d, f.right), v = Dot(d, f.up);
  if (!camera.orthographic) {
    const double depth = Dot(d, f.forward);
    if (depth <= 1e-9) return std::nullopt;
    u /= depth, v /= depth;
  }
  // RenderView's pixel mapping turned round: pixel x's centre is at u = (2 (x + 0.5) / width - 1) aspect half_h.
  return Point{(u / (f.aspect * f.half_h) + 1.0) * camera.width / 2.0, (1.0 - v / f.half_h) * camera.height / 2.0};
}

Status DrawLabels(Image& image, const Camera& camera, const std::vector<ViewLabel>& labels, const LabelStyle& style) {
  if (image.width < 1 || image.height < 1 || image.rgb.size() != size_t{3} * image.width * image.height)
    return Error{"labels: empty or inconsistent image"};
  if (!(style.font_px >= 6.0 && style.font_px <= 48.0)) return Error{"labels: font_px must be in [6, 48]"};
  if (labels.empty()) return Status{};
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, image.width, image.height);
  if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(surface);
    return Error{"labels: cairo could not make a " + std::to_string(image.width) + " x " + std::to_string(image.height) +
                 " surface"};
  }
  // RGB24 keeps a pixel in a native-endian 32-bit word 0x00RRGGBB.
  unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  cairo_surface_flush(surface);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* px = &image.rgb[(static_cast<size_t>(y) * image.width + x) * 3];
      *reinterpret_cast<std::uint32_t*>(data + static_cast<size_t>(y) * stride + 4 * x) =
          (std::uint32_t{px[0]} << 16) | (std::uint32_t{px[1]} << 8) | px[2];
    }
  cairo_surface_mark_dirty(surface);
  cairo_t* cr = cairo_create(surface);
  cairo_select_font_face(cr, style.font_family.c_str(), CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
  cairo_set_font_size(cr, style.font_px);
  for (const ViewLabel& label : labels) {
    const std::optional<Point> at = ProjectToPixel(camera, label.at);
    if (!at || at->x < 0 || at->y < 0 || at->x > image.width || at->y > image.height || label.text.empty()) continue;
    cairo_text_extents_t extents;
    cairo_text_extents(cr, label.text.c_str(), &extents);
    const double x = at->x - extents.width / 2.0 - extents.x_bearing, y = at->y - extents.height / 2.0 - extents.y_bearing;
    const double pad = style.padding_px;
    cairo_rectangle(cr, x + extents.x_bearing - pad, y + extents.y_bearing - pad, extents.width + 2 * pad,
                    extents.height + 2 * pad);
    cairo_set_source_rgba(cr, style.background.r, style.background.g, style.background.b, style.background_alpha);
    cairo_fill(cr);
    cairo_move_to(cr, x, y);
    cairo_set_source_rgb(cr, style.text.r, style.text.g, style.text.b);
    cairo_show_text(cr, label.text.c_str());
  }
  cairo_destroy(cr);
  cairo_surface_flush(surface);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint32_t word = *reinterpret_cast<const std::uint32_t*>(data + static_cast<size_t>(y) * stride + 4 * x);
      std::uint8_t* px = &image.rgb[(static_cast<size_t>(y) * image.width + x) * 3];
      px[0] = static_cast<std::uint8_t>(word >> 16), px[1] = static_cast<std::uint8_t>(word >> 8),
      px[2] = static_cast<std::uint8_t>(word);
    }
  cairo_surface_destroy(surface);
  return Status{};
}

Result<std::string> EncodePng(const Image& image) {
  if (image.width < 1 || image.height < 1 || image.rgb.size() != size_t{3} * image.width * image.height)
    return Error{"PNG: empty or inconsistent image"};
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (!png) return Error{"PNG: libpng could not start"};
  png_infop info = png_create_info_struct(png);
  std::string bytes;
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return Error{"PNG: encoding failed"};
  }
  png_set_write_fn(
      png, &bytes,
      [](png_structp p, png_bytep data, png_size_t length) {
        static_cast<std::string*>(png_get_io_ptr(p))->append(reinterpret_cast<const char*>(data), length);
      },
      nullptr);
  png_set_IHDR(png, info, image.width, image.height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < image.height; ++y)
    png_write_row(png, const_cast<png_bytep>(image.rgb.data() + size_t{3} * y * image.width));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return bytes;
}

Status WritePng(const Image& image, const std::filesystem::path& path) {
  auto bytes = EncodePng(image);
  if (!bytes) return Error{path.string() + ": " + bytes.error()};
  return WriteFileAtomic(path, *bytes);
}

}  // namespace villa
