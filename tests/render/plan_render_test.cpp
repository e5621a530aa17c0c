// Floor-plan pictures: sizes, colours where the rooms are, labels in the SVG, invalid layouts drawn with
// their faults in red, file handling.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>

#include "layout/geometry.h"
#include "render/plan_geometry.h"
#include "render/plan_render.h"
#include "render_test_support.h"

using namespace villa;
using villa::test::DecodePng;
using villa::test::ExampleNames;
using villa::test::LoadExample;
using villa::test::PaperExample;

namespace {

std::string Hex(const Rgb& c) {
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", ToByte(c.r), ToByte(c.g), ToByte(c.b));
  return buffer;
}

std::string XmlEscaped(std::string text) {
  std::string out;
  for (char c : text) out += c == '\'' ? std::string("&apos;") : std::string(1, c);
  return out;
}

struct TempDir {
  std::filesystem::path path;
  TempDir() {
    path = std::filesystem::temp_directory_path() /
           ("villa-render-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
  std::set<std::string> Files() const {
    std::set<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(path)) names.insert(entry.path().filename().string());
    return names;
  }
  static inline int counter = 0;
};

}  // namespace

TEST_CASE("the bundled examples are there: three or more, one of them with three floors", "[render]") {
  const auto names = ExampleNames();
  REQUIRE(names.size() >= 3);
  int three_floors = 0;
  for (const std::string& name : names) three_floors += LoadExample(name).LevelCount() == 3;
  CHECK(three_floors >= 1);
}

TEST_CASE("every example renders to a PNG of the frame's size, each room filled with its category colour", "[render]") {
  for (const std::string& name : ExampleNames()) {
    INFO(name);
    const Layout layout = LoadExample(name);
    PlanRenderOptions options;
    options.source_name = name;
    const Result<PlanFrame> frame = ComputePlanFrame(layout, options);
    REQUIRE(frame.ok());
    const Result<std::string> png = RenderPlanPng(layout, options);
    REQUIRE(png.ok());
    const test::Picture picture = DecodePng(*png);
    CHECK(picture.width == frame->width_px);
    CHECK(picture.height == frame->height_px);
    REQUIRE(frame->panels.size() == static_cast<size_t>(layout.LevelCount()));
    CHECK(picture.Is(1, 1, {1, 1, 1}));  // the margin is white

    for (const Room& room : layout.rooms) {
      INFO(room.name());
      // The label point is inside the room, clear of its walls.
      const Point label = RoomLabelPoint(room.polygon);
      CHECK(plan::SignedDistanceToRing(label, room.polygon) > 0.5);
      // Sample the room's interior (away from the walls): most of it shows the category colour; the
      // rest is the label, door swings, stair treads.
      int samples = 0, matches = 0;
      for (double x = -20; x <= 40; x += 0.25) {
        for (double y = -20; y <= 40; y += 0.25) {
          if (plan::SignedDistanceToRing({x, y}, room.polygon) < 0.35) continue;
          const Point px = frame->ToPixel(room.level, {x, y});
          ++samples;
          matches += picture.Is(static_cast<int>(px.x), static_cast<int>(px.y), CategoryColor(room.category));
        }
      }
      REQUIRE(samples >= 8);
      CHECK(matches >= samples * 0.6);
    }
  }
}

TEST_CASE("panels share one scale and sit side by side in level order", "[render]") {
  const Layout layout = LoadExample("three-floor-villa.json");
  const Result<PlanFrame> frame = ComputePlanFrame(layout);
  REQUIRE(frame.ok());
  REQUIRE(frame->panels.size() == 3);
  CHECK(frame->pixels_per_metre == Approx(40.0));
  const double step = frame->panels[1].plan_left_px - frame->panels[0].plan_left_px;
  CHECK(step > 16.0 * 40.0);  // wider than the 16 m plan
  for (int i = 0; i < 3; ++i) {
    CHECK(frame->panels[i].level == i);
    CHECK(frame->panels[i].plan_left_px == Approx(frame->panels[0].plan_left_px + i * step));
    CHECK(frame->panels[i].plan_top_px == Approx(frame->panels[0].plan_top_px));
  }
  // The same plan point lands at the same place within each panel (the staircase lines up).
  const Point a = frame->ToPixel(0, {4, 8}), b = frame->ToPixel(2, {4, 8});
  CHECK(b.x - a.x == Approx(2 * step));
  CHECK(b.y == Approx(a.y));
  CHECK(frame->ToPixel(7, {0, 0}).x == -1.0);
}

TEST_CASE("a target width sets the picture width and the scale", "[render]") {
  const Layout layout = LoadExample("three-floor-villa.json");
  PlanRenderOptions options;
  options.target_width_px = 1200;
  const Result<std::string> png = RenderPlanPng(layout, options);
  REQUIRE(png.ok());
  const test::Picture picture = DecodePng(*png);
  CHECK(picture.width == 1200);
  const Result<PlanFrame> frame = ComputePlanFrame(layout, options);
  REQUIRE(frame.ok());
  CHECK(frame->pixels_per_metre < 40.0);
  CHECK(frame->pixels_per_metre > 15.0);
}

TEST_CASE("the SVG holds every room's label, area and JSON name as text", "[render]") {
  for (const std::string& name : ExampleNames()) {
    INFO(name);
    const Layout layout = LoadExample(name);
    PlanRenderOptions options;
    options.source_name = name;
    const Result<std::string> svg = RenderPlanSvg(layout, options);
    REQUIRE(svg.ok());
    CHECK(svg->rfind("<?xml", 0) == 0);
    CHECK(svg->find("</svg>") != std::string::npos);
    CHECK(svg->find(">" + name + "</text>") != std::string::npos);
    for (const Room& room : layout.rooms) {
      INFO(room.name());
      const std::string label = std::string(CategoryDisplayName(room.category)) + " " + std::to_string(room.index);
      CHECK(svg->find(">" + XmlEscaped(label) + "</text>") != std::string::npos);
      char area[32];
      std::snprintf(area, sizeof area, ">%.1f m\u00b2</text>", Area(room.polygon));
      CHECK(svg->find(area) != std::string::npos);
      CHECK(svg->find("<title>" + room.name() + "</title>") != std::string::npos);
      CHECK(svg->find(Hex(CategoryColor(room.category))) != std::string::npos);
    }
    // Valid layouts have nothing to mark.
    CHECK(svg->find(Hex(InvalidElementColor())) == std::string::npos);
  }
}

TEST_CASE("the paper's invalid example renders, with its hanging doors and entrance in red", "[render]") {
  const Layout layout = PaperExample();
  const Result<std::string> svg = RenderPlanSvg(layout);
  REQUIRE(svg.ok());
  CHECK(svg->find(Hex(InvalidElementColor())) != std::string::npos);
  CHECK(svg->find("Not on a wall (invalid)") != std::string::npos);

  const Result<PlanFrame> frame = ComputePlanFrame(layout);
  REQUIRE(frame.ok());
  const Result<std::string> png = RenderPlanPng(layout);
  REQUIRE(png.ok());
  const test::Picture picture = DecodePng(*png);
  CHECK(picture.width == frame->width_px);
  auto is_red = [&](int level, Point p) {
    const Point px = frame->ToPixel(level, p);
    const Rgb c = picture.At(static_cast<int>(std::lround(px.x)), static_cast<int>(std::lround(px.y)));
    return c.r > 0.7 && c.g < 0.35 && c.b < 0.35;
  };
  // living0_kitchen0 lies on the kitchen's top edge, which no other ground-floor room shares.
  CHECK(is_red(0, {6, 4}));
  // living0_bathroom0 lies on the bathroom's left edge only.
  CHECK(is_red(0, {10, 6}));
  // meeting1_bedroom1 lies on a boundary both rooms share: drawn normally.
  CHECK_FALSE(is_red(1, {6, 4}));
  // Every room still shows its colour at its label point's side.
  for (const Room& room : layout.rooms) {
    const Point p = RoomLabelPoint(room.polygon);
    CHECK(PointInRing(p, room.polygon, 0));
  }
}

TEST_CASE("layouts with nothing or odd things in them still render", "[render]") {
  SECTION("no rooms at all") {
    const Result<std::string> png = RenderPlanPng(Layout{});
    REQUIRE(png.ok());
    CHECK(DecodePng(*png).width > 100);
  }
  SECTION("a degenerate room and a zero-length door") {
    Layout layout;
    layout.rooms.push_back({Category::kKitchen, 0, 0, {{0, 0}, {4, 0}, {8, 0}}});
    layout.rooms.push_back({Category::kBedroom, 0, 0, {{0, 1}, {4, 1}, {4, 5}, {0, 5}}});
    layout.doors.push_back({"d", ElementKind::kDoor, {{2, 1}, {2, 1}}, 0, false});
    layout.windows.push_back({"w", ElementKind::kWindow, {{0, 2}, {0, 3}}, kAllLevels, true});
    CHECK(RenderPlanPng(layout).ok());
    CHECK(RenderPlanSvg(layout).ok());
  }
  SECTION("a coordinate that is not a number is an error naming the room") {
    Layout layout;
    layout.rooms.push_back({Category::kKitchen, 0, 0, {{0, 0}, {4, 0}, {4, std::nan("")}}});
    const Result<std::string> png = RenderPlanPng(layout);
    REQUIRE_FALSE(png.ok());
    CHECK(png.error().find("kitchen_0/0") != std::string::npos);
  }
}

TEST_CASE("bad options and levels are errors that name the value", "[render]") {
  const Layout layout = LoadExample("three-floor-villa.json");
  PlanRenderOptions options;
  options.pixels_per_metre = 0;
  Result<std::string> png = RenderPlanPng(layout, options);
  REQUIRE_FALSE(png.ok());
  CHECK(png.error().find("pixels_per_metre = 0") != std::string::npos);

  options = {};
  options.levels = {0, 5};
  png = RenderPlanPng(layout, options);
  REQUIRE_FALSE(png.ok());
  CHECK(png.error().find("level 5") != std::string::npos);

  options = {};
  options.levels = {2};
  const Result<PlanFrame> frame = ComputePlanFrame(layout, options);
  REQUIRE(frame.ok());
  REQUIRE(frame->panels.size() == 1);
  CHECK(frame->panels[0].level == 2);
}

TEST_CASE("rendering is deterministic", "[render]") {
  const Layout layout = LoadExample("three-floor-villa.json");
  const Result<std::string> a = RenderPlanPng(layout), b = RenderPlanPng(layout);
  REQUIRE(a.ok());
  REQUIRE(b.ok());
  CHECK(*a == *b);
  CHECK(*RenderPlanSvg(layout) == *RenderPlanSvg(layout));
}

TEST_CASE("RenderPlan picks the format by extension and writes atomically", "[render]") {
  const Layout layout = LoadExample("two-floor-house.json");
  TempDir dir;
  REQUIRE(RenderPlan(layout, dir.path / "plan.png").ok());
  REQUIRE(RenderPlan(layout, dir.path / "PLAN.SVG").ok());
  CHECK(dir.Files() == std::set<std::string>{"plan.png", "PLAN.SVG"});
  {
    std::ifstream in(dir.path / "plan.png", std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    CHECK(bytes == *RenderPlanPng(layout));
  }
  {
    std::ifstream in(dir.path / "PLAN.SVG", std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    CHECK(text.rfind("<?xml", 0) == 0);
  }
  // Writing again replaces the file whole, still without leftovers.
  REQUIRE(RenderPlan(LoadExample("l-shaped-house.json"), dir.path / "plan.png").ok());
  CHECK(dir.Files() == std::set<std::string>{"plan.png", "PLAN.SVG"});

  const Status gif = RenderPlan(layout, dir.path / "plan.gif");
  REQUIRE_FALSE(gif.ok());
  CHECK(gif.error().find("plan.gif") != std::string::npos);
  CHECK(gif.error().find(".png or .svg") != std::string::npos);
  const Status none = RenderPlan(layout, dir.path / "plan");
  REQUIRE_FALSE(none.ok());
  CHECK(dir.Files() == std::set<std::string>{"plan.png", "PLAN.SVG"});

  const Status missing_dir = RenderPlan(layout, dir.path / "no" / "such" / "plan.png");
  REQUIRE_FALSE(missing_dir.ok());
  CHECK(missing_dir.error().find("plan.png") != std::string::npos);
}

TEST_CASE("the palette tells the categories apart", "[render][palette]") {
  std::vector<Category> all = LabelledCategories();
  all.push_back(Category::kRoom);
  REQUIRE(all.size() == static_cast<size_t>(kCategoryCount));
  for (size_t i = 0; i < all.size(); ++i) {
    const Rgb a = CategoryColor(all[i]);
    // Light enough for dark text: relative luminance above 0.45.
    CHECK(0.2126 * a.r + 0.7152 * a.g + 0.0722 * a.b > 0.45);
    for (size_t j = i + 1; j < all.size(); ++j) {
      const Rgb b = CategoryColor(all[j]);
      INFO(CategoryName(all[i]) << " vs " << CategoryName(all[j]));
      const double distance = std::abs(ToByte(a.r) - ToByte(b.r)) + std::abs(ToByte(a.g) - ToByte(b.g)) +
                              std::abs(ToByte(a.b) - ToByte(b.b));
      CHECK(distance >= 40);
    }
    CHECK_FALSE(CategoryDisplayName(all[i]).empty());
  }
}

TEST_CASE("absurd sizes are drawn at a scale that fits, quickly", "[render]") {
  // A 3 km long two-floor building: the picture is scaled down to the size limit, the 3 km "staircase"
  // gets a bounded number of treads.
  Layout layout;
  for (int level = 0; level < 2; ++level) {
    layout.rooms.push_back({Category::kUtilityRoom, level, 0, {{0, 0}, {3000, 0}, {3000, 4}, {0, 4}}});
    layout.rooms.push_back({Category::kBedroom, level, 0, {{0, 4}, {3000, 4}, {3000, 5.5}, {0, 5.5}}});
  }
  layout.doors.push_back({"d", ElementKind::kDoor, {{0, 4}, {2000, 4}}, 0, false});
  PlanRenderOptions options;
  options.max_side_px = 4000;
  const Result<PlanFrame> frame = ComputePlanFrame(layout, options);
  REQUIRE(frame.ok());
  CHECK(frame->width_px <= 4000);
  CHECK(frame->pixels_per_metre < 1.0);
  const Result<std::string> png = RenderPlanPng(layout, options);
  REQUIRE(png.ok());
  CHECK(DecodePng(*png).width == frame->width_px);
}

TEST_CASE("an overlay draws furniture footprints over the room fills and walking paths as lines", "[render]") {
  const Layout layout = LoadExample("l-shaped-house.json");
  const Room* living = nullptr;
  for (const Room& r : layout.rooms)
    if (r.category == Category::kLivingRoom) living = &r;
  REQUIRE(living);
  // A spot well inside the room, far from its label: a 0.8 m square goes there.
  const Point label = RoomLabelPoint(living->polygon);
  Point spot{1e9, 1e9};
  for (double x = -20; x <= 40 && spot.x > 1e8; x += 0.1)
    for (double y = -20; y <= 40 && spot.x > 1e8; y += 0.1)
      if (plan::SignedDistanceToRing({x, y}, living->polygon) > 1.2 &&
          plan::SignedDistanceToRing({x + 1.0, y}, living->polygon) > 0.6 && Distance({x, y}, label) > 1.5 &&
          Distance({x + 1.0, y}, label) > 1.5)
        spot = {x, y};
  REQUIRE(spot.x < 1e8);
  const Rgb fill{0.2, 0.55, 0.3}, line{0.1, 0.2, 0.8};
  PlanOverlay overlay;
  overlay.shapes.push_back({living->level, {{spot.x - 0.4, spot.y - 0.4}, {spot.x + 0.4, spot.y - 0.4},
                                            {spot.x + 0.4, spot.y + 0.4}, {spot.x - 0.4, spot.y + 0.4}},
                            fill, 1.0, {0, 0, 0}});
  overlay.shapes.push_back({7, {{0, 0}, {1, 0}, {1, 1}}, fill, 1.0, {0, 0, 0}});  // no such level: not drawn
  // A path through the room's label point, 4 px wide, passing right of the square.
  overlay.paths.push_back({living->level, {{spot.x + 1.0, spot.y - 0.3}, {spot.x + 1.0, spot.y + 0.3}}, line, 4.0});

  const Result<PlanFrame> frame = ComputePlanFrame(layout);
  REQUIRE(frame.ok());
  const Result<std::string> bare = RenderPlanPng(layout);
  const Result<std::string> drawn = RenderPlanPng(layout, overlay);
  REQUIRE(bare.ok());
  REQUIRE(drawn.ok());
  const test::Picture a = DecodePng(*bare), b = DecodePng(*drawn);
  // The panels stay where the frame puts them (the overlay only adds legend entries below them).
  const Point centre = frame->ToPixel(living->level, spot);
  const Point beside = frame->ToPixel(living->level, {spot.x + 0.6, spot.y});
  const Point on_path = frame->ToPixel(living->level, {spot.x + 1.0, spot.y});
  CHECK(a.Is(static_cast<int>(centre.x), static_cast<int>(centre.y), CategoryColor(Category::kLivingRoom)));
  CHECK(b.Is(static_cast<int>(centre.x), static_cast<int>(centre.y), fill, 2));
  CHECK(b.Is(static_cast<int>(beside.x), static_cast<int>(beside.y), CategoryColor(Category::kLivingRoom)));
  CHECK(b.Is(static_cast<int>(on_path.x), static_cast<int>(on_path.y), line, 8));
  CHECK(a.Is(static_cast<int>(on_path.x), static_cast<int>(on_path.y), CategoryColor(Category::kLivingRoom)));
  // The legend names what the overlay drew; the SVG groups it per level.
  const Result<std::string> svg = RenderPlanSvg(layout, overlay);
  REQUIRE(svg.ok());
  CHECK(svg->find("Furniture") != std::string::npos);
  CHECK(svg->find("Walking path") != std::string::npos);
  CHECK(svg->find("furniture-0") != std::string::npos);
  CHECK(RenderPlanSvg(layout)->find("Walking path") == std::string::npos);
}
