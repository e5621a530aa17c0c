// The cairo backend: text measurement and PNG output. The only file of villa that sees cairo types.
// cairo rasterises; libpng encodes (cairo's own PNG writer filters every row five ways at zlib level 6,
// about 6 times slower than what a flat-coloured plan needs).
#include <cairo.h>
#include <png.h>

#include <csetjmp>
#include <cstdint>
#include <vector>

#include <cmath>
#include <string>

#include "render/scene.h"

namespace villa::plan {
namespace {

void SelectFont(cairo_t* cr, const std::string& family, double size, bool bold) {
  cairo_select_font_face(cr, family.c_str(), CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
}

void SetColor(cairo_t* cr, const Rgb& c, double alpha) {
  if (alpha >= 1.0) {
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
  } else {
    cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha);
  }
}

void DrawPath(cairo_t* cr, const PathItem& item) {
  cairo_new_path(cr);
  for (const SubPath& sub : item.subpaths) {
    if (sub.points.empty()) continue;
    cairo_move_to(cr, sub.points[0].x, sub.points[0].y);
    for (size_t i = 1; i < sub.points.size(); ++i) cairo_line_to(cr, sub.points[i].x, sub.points[i].y);
    if (sub.closed) cairo_close_path(cr);
  }
  if (item.fill) {
    SetColor(cr, item.fill->color, item.fill->alpha);
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
    if (item.stroke) {
      cairo_fill_preserve(cr);
    } else {
      cairo_fill(cr);
    }
  }
  if (item.stroke) {
    const Stroke& s = *item.stroke;
    SetColor(cr, s.color, s.alpha);
    cairo_set_line_width(cr, s.width);
    cairo_set_dash(cr, s.dash.empty() ? nullptr : s.dash.data(), static_cast<int>(s.dash.size()), 0.0);
    cairo_set_line_cap(cr, s.cap == LineCap::kButt    ? CAIRO_LINE_CAP_BUTT
                           : s.cap == LineCap::kRound ? CAIRO_LINE_CAP_ROUND
                                                      : CAIRO_LINE_CAP_SQUARE);
    cairo_set_line_join(cr, s.join == LineJoin::kMiter   ? CAIRO_LINE_JOIN_MITER
                            : s.join == LineJoin::kRound ? CAIRO_LINE_JOIN_ROUND
                                                         : CAIRO_LINE_JOIN_BEVEL);
    cairo_set_miter_limit(cr, 6.0);
    cairo_stroke(cr);
  }
  cairo_new_path(cr);
}

void DrawText(cairo_t* cr, const std::string& family, const TextItem& item) {
  SelectFont(cr, family, item.size, item.bold);
  cairo_text_extents_t extents;
  cairo_text_extents(cr, item.text.c_str(), &extents);
  double dx = 0.0;
  if (item.anchor == TextAnchor::kMiddle) dx = -extents.x_advance / 2.0;
  if (item.anchor == TextAnchor::kEnd) dx = -extents.x_advance;
  cairo_save(cr);
  cairo_translate(cr, item.at.x, item.at.y);
  if (item.angle_deg != 0.0) cairo_rotate(cr, item.angle_deg * M_PI / 180.0);
  SetColor(cr, item.color, 1.0);
  cairo_move_to(cr, dx, 0.0);
  cairo_show_text(cr, item.text.c_str());
  cairo_restore(cr);
  cairo_new_path(cr);
}

void AppendPng(png_structp png, png_bytep data, png_size_t length) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), length);
}
void FlushNothing(png_structp) {}

// 8-bit RGB PNG of a CAIRO_FORMAT_RGB24 surface. Returns false (with `error`) when libpng fails.
bool EncodePng(cairo_surface_t* surface, int compression_level, std::string* out, std::string* error) {
  const int width = cairo_image_surface_get_width(surface);
  const int height = cairo_image_surface_get_height(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  const unsigned char* pixels = cairo_image_surface_get_data(surface);
  std::vector<png_byte> row(static_cast<size_t>(width) * 3);
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info) {
    png_destroy_write_struct(&png, &info);
    *error = "cannot start the PNG encoder";
    return false;
  }
  // Only plain data lives across the jump: the vector and strings were made before it.
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    *error = "PNG encoding failed";
    return false;
  }
  png_set_write_fn(png, out, AppendPng, FlushNothing);
  png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(png, compression_level);
  png_set_filter(png, 0, PNG_FILTER_NONE);  // flat colours compress best unfiltered, and fastest
  png_write_info(png, info);
  for (int y = 0; y < height; ++y) {
    const auto* source = reinterpret_cast<const std::uint32_t*>(pixels + static_cast<size_t>(y) * stride);
    for (int x = 0; x < width; ++x) {
      row[3 * x] = static_cast<png_byte>((source[x] >> 16) & 0xff);
      row[3 * x + 1] = static_cast<png_byte>((source[x] >> 8) & 0xff);
      row[3 * x + 2] = static_cast<png_byte>(source[x] & 0xff);
    }
    png_write_row(png, row.data());
  }
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

struct TextMeasure::Impl {
  cairo_surface_t* surface = nullptr;
  cairo_t* cr = nullptr;
  std::string family;
};

TextMeasure::TextMeasure(const std::string& font_family) : impl_(new Impl) {
  impl_->surface = cairo_image_surface_create(CAIRO_FORMAT_A8, 1, 1);
  impl_->cr = cairo_create(impl_->surface);
  impl_->family = font_family;
}

TextMeasure::~TextMeasure() {
  cairo_destroy(impl_->cr);
  cairo_surface_destroy(impl_->surface);
  delete impl_;
}

double TextMeasure::Width(const std::string& text, double size, bool bold) const {
  SelectFont(impl_->cr, impl_->family, size, bold);
  cairo_text_extents_t extents;
  cairo_text_extents(impl_->cr, text.c_str(), &extents);
  return extents.x_advance;
}

double TextMeasure::CapHeight(double size) const {
  SelectFont(impl_->cr, impl_->family, size, false);
  cairo_text_extents_t extents;
  cairo_text_extents(impl_->cr, "H", &extents);
  return -extents.y_bearing;
}

std::optional<std::string> SceneToPng(const Scene& scene, int compression_level, std::string* error) {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, scene.width, scene.height);
  if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS) {
    *error = std::string("cannot make a ") + std::to_string(scene.width) + " x " + std::to_string(scene.height) +
             " px picture: " + cairo_status_to_string(cairo_surface_status(surface));
    cairo_surface_destroy(surface);
    return std::nullopt;
  }
  cairo_t* cr = cairo_create(surface);
  SetColor(cr, scene.background, 1.0);
  cairo_paint(cr);
  for (const SceneItem& item : scene.items) {
    if (const auto* path = std::get_if<PathItem>(&item)) DrawPath(cr, *path);
    if (const auto* text = std::get_if<TextItem>(&item)) DrawText(cr, scene.font_family, *text);
  }
  cairo_surface_flush(surface);
  const cairo_status_t draw_status = cairo_status(cr);
  cairo_destroy(cr);
  if (draw_status != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(surface);
    *error = std::string("drawing failed: ") + cairo_status_to_string(draw_status);
    return std::nullopt;
  }
  std::string png;
  png.reserve(static_cast<size_t>(scene.width) * scene.height / 8);
  const bool encoded = EncodePng(surface, compression_level, &png, error);
  cairo_surface_destroy(surface);
  if (!encoded) return std::nullopt;
  return png;
}

}  // namespace villa::plan
