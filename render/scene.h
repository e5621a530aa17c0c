#pragma once
// A picture as a flat list of drawing items in pixel coordinates (x right, y down), built once and
// written out by either backend: cairo for PNG (scene_png.cpp) or plain SVG text (scene_svg.cpp).
// Internal to render/. Curves are flattened to polylines by the builder, so both backends draw the
// same geometry.
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "render/palette.h"

namespace villa::plan {

struct Px {
  double x = 0.0;
  double y = 0.0;
};

enum class LineCap { kButt, kRound, kSquare };
enum class LineJoin { kMiter, kRound, kBevel };

struct Fill {
  Rgb color;
  double alpha = 1.0;
};

struct Stroke {
  Rgb color;
  double width = 1.0;          // px
  double alpha = 1.0;
  std::vector<double> dash;    // on/off lengths in px; empty = solid
  LineCap cap = LineCap::kButt;
  LineJoin join = LineJoin::kMiter;
};

struct SubPath {
  std::vector<Px> points;
  bool closed = false;
};

struct PathItem {
  std::vector<SubPath> subpaths;
  std::optional<Fill> fill;     // non-zero winding
  std::optional<Stroke> stroke;
};

enum class TextAnchor { kStart, kMiddle, kEnd };

struct TextItem {
  std::string text;   // UTF-8
  Px at;              // the anchor point on the baseline
  double size = 12.0; // px
  bool bold = false;
  Rgb color;
  TextAnchor anchor = TextAnchor::kStart;
  double angle_deg = 0.0;  // rotation about `at`, clockwise on screen (-90: reads bottom to top)
};

// Structure for the SVG (a <g> with an id and a <title> tooltip); the PNG ignores it.
struct GroupBegin {
  std::string id;
  std::string title;
};
struct GroupEnd {};

using SceneItem = std::variant<PathItem, TextItem, GroupBegin, GroupEnd>;

struct Scene {
  int width = 0;   // px
  int height = 0;  // px
  Rgb background{1.0, 1.0, 1.0};
  std::string font_family;
  std::string title;  // the picture's title (SVG <title>)
  std::vector<SceneItem> items;
};

// Text measurement with the same fonts the PNG backend draws with (cairo toy API).
class TextMeasure {
 public:
  explicit TextMeasure(const std::string& font_family);
  ~TextMeasure();
  TextMeasure(const TextMeasure&) = delete;
  TextMeasure& operator=(const TextMeasure&) = delete;
  // Advance width of `text` at `size` px.
  double Width(const std::string& text, double size, bool bold) const;
  // Height of a capital letter at `size` px (for centring a line of text vertically).
  double CapHeight(double size) const;

 private:
  struct Impl;
  Impl* impl_;
};

// The PNG file bytes of the scene (cairo, libpng) at zlib `compression_level` 1..9.
std::optional<std::string> SceneToPng(const Scene& scene, int compression_level, std::string* error);
// The SVG document of the scene.
std::string SceneToSvg(const Scene& scene);

}  // namespace villa::plan
