#include <catch2/catch.hpp>

#include "building/materials.h"
#include "building/view_scene.h"
#include "test_support.h"

using namespace villa;
using namespace villa::testing;

namespace {

// A straight-down orthographic camera over the ground floor: pixel (x, y) <-> plan point.
Camera TopCamera(int px_per_m) {
  Camera cam;
  cam.orthographic = true;
  cam.position = {7.0, 5.0, 30.0};
  cam.target = {7.0, 5.0, 0.0};
  cam.up = {0, 1, 0};
  cam.width = 16 * px_per_m;
  cam.height = 12 * px_per_m;
  cam.ortho_height = 12.0;
  return cam;
}

Rgb PixelAt(const Image& img, const Camera& cam, double x, double y) {
  double ppm = cam.height / cam.ortho_height;
  int px = static_cast<int>((x - (cam.target.x - cam.width / ppm / 2)) * ppm);
  int py = static_cast<int>(((cam.target.y + cam.ortho_height / 2) - y) * ppm);
  return img.At(px, py);
}

bool Near(Rgb a, Rgb b, double tol = 2.0 / 255) {
  return std::abs(a.r - b.r) <= tol && std::abs(a.g - b.g) <= tol && std::abs(a.b - b.b) <= tol;
}

}  // namespace

TEST_CASE("a cut-away seen from above shows each room's floor colour, the cut walls and the background") {
  const ViewScene b = ViewSceneOf(ThreeFloorBuilding());
  Camera cam = TopCamera(10);
  RenderOptions o;
  o.top_level = 0;
  o.ambient = 1.0;  // flat colours: the picture shows the materials as they are
  o.shadows = false;
  o.threads = 2;
  auto img = RenderView(b, cam, o);
  REQUIRE(img);
  CHECK(img->width == 160);
  // Each floor in its finish (issue 31): the kitchen's and the bathroom's tile, the dining and living rooms' oak.
  auto floor = [](Category c) {
    MeshPart part;
    part.category = c;
    return MaterialOf(part).color;
  };
  CHECK(Near(PixelAt(*img, cam, 6.5, 2.0), floor(Category::kKitchen)));
  CHECK(Near(PixelAt(*img, cam, 11.5, 2.0), floor(Category::kDiningRoom)));
  CHECK(Near(PixelAt(*img, cam, 1.5, 8.5), floor(Category::kBathroom)));
  CHECK(Near(PixelAt(*img, cam, 10.0, 7.0), floor(Category::kLivingRoom)));
  CHECK(Near(PixelAt(*img, cam, 14.0 - 0.12, 4.5), o.section_color));  // the cut east wall
  CHECK(Near(PixelAt(*img, cam, 14.6, 2.0), o.background));
  // Without the cut, the roof covers the top floor's rooms.
  RenderOptions whole = o;
  whole.top_level = -1;
  auto roof = RenderView(b, cam, whole);
  REQUIRE(roof);
  CHECK(Near(PixelAt(*roof, cam, 6.5, 2.0), {0.55, 0.36, 0.30}));
}

TEST_CASE("the preview puts the exterior and one cut-away per level side by side, as a PNG") {
  PreviewOptions p;
  p.panel_width = 96;
  p.panel_height = 80;
  p.samples = 1;
  auto img = RenderPreview(ViewSceneOf(ThreeFloorBuilding()), p);
  REQUIRE(img);
  CHECK(img->width == 4 * 96 + 3 * p.gap);
  CHECK(img->height == 80);
  // Each panel has something other than background in it.
  for (int k = 0; k < 4; ++k) {
    int drawn = 0;
    for (int y = 0; y < 80; ++y)
      for (int x = 0; x < 96; ++x)
        if (!Near(img->At(k * (96 + p.gap) + x, y), {1, 1, 1})) ++drawn;
    CHECK(drawn > 500);
  }
}

TEST_CASE("the scene of a building cuts walls, removes the roof and keeps the slabs") {
  const BuildingMesh& b = ThreeFloorBuilding();
  const ViewScene scene = ViewSceneOf(b);
  REQUIRE(scene.meshes.size() == b.parts.size());
  REQUIRE(scene.floor_z.size() == static_cast<size_t>(b.levels));
  for (size_t i = 0; i < b.parts.size(); ++i) {
    const MeshPart& part = b.parts[i];
    const ViewMesh& view = scene.meshes[i];
    CHECK(view.mesh == &part.mesh);
    CHECK(view.level == part.level);
    const CutAway expected = part.kind == PartKind::kRoof                                   ? CutAway::kRemove
                             : part.kind == PartKind::kFloor || part.kind == PartKind::kTerrace ||
                                       part.kind == PartKind::kRailing
                                 ? CutAway::kKeep
                                                                                                : CutAway::kCut;
    CHECK(view.cut == expected);
    CHECK((view.alpha < 1.0) == (part.kind == PartKind::kWindowGlass));
    CHECK(view.side_color.has_value() == (part.kind == PartKind::kFloor));
  }
  CHECK(scene.floor_z[1] == b.FloorZ(1));
  const Box3 box = scene.Bounds(), expected = b.Bounds();
  CHECK(box.min == expected.min);
  CHECK(box.max == expected.max);
}
