// The 3D view on neutral scenes (no building): colours, see-through meshes, cut-aways, framing and top
// views, labels, PNG encoding, bad cameras.
#include <catch2/catch.hpp>

#include <cmath>

#include "mesh/solids.h"
#include "render/view3d.h"

using namespace villa;

namespace {

TriangleMesh Block(double x0, double y0, double x1, double y1, double z0, double z1) {
  return ExtrudePlan({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}, z0, z1);
}

bool Near(Rgb a, Rgb b, double tol = 2.0 / 255) {
  return std::abs(a.r - b.r) <= tol && std::abs(a.g - b.g) <= tol && std::abs(a.b - b.b) <= tol;
}

ViewMesh Show(const TriangleMesh& mesh, Rgb color, double alpha = 1.0, int level = 0, CutAway cut = CutAway::kKeep) {
  ViewMesh view;
  view.mesh = &mesh;
  view.color = color;
  view.alpha = alpha;
  view.level = level;
  view.cut = cut;
  return view;
}

RenderOptions Flat() {
  RenderOptions o;
  o.ambient = 1.0;  // flat colours: the picture shows the colours as they are
  o.shadows = false;
  o.threads = 2;
  return o;
}

Rgb At(const Image& image, const Camera& camera, Vec3 p) {
  const auto px = ProjectToPixel(camera, p);
  REQUIRE(px);
  return image.At(static_cast<int>(px->x), static_cast<int>(px->y));
}

const Rgb kRed{0.9, 0.1, 0.1}, kBlue{0.1, 0.2, 0.9}, kGreen{0.1, 0.7, 0.2};

}  // namespace

TEST_CASE("a top view of a neutral scene shows each mesh in its colour where it stands") {
  const TriangleMesh floor = Block(0, 0, 4, 3, 0, 0.1), table = Block(1, 1, 2, 2, 0.1, 0.8);
  ViewScene scene;
  scene.meshes.push_back(Show(floor, kBlue));
  scene.meshes.push_back(Show(table, kRed));
  scene.floor_z = {0.1};
  const Camera top = FramingCamera(scene.Bounds(), 0, 90, 200, 160);
  auto image = RenderView(scene, top, Flat());
  REQUIRE(image);
  CHECK(Near(At(*image, top, {1.5, 1.5, 0.8}), kRed));
  CHECK(Near(At(*image, top, {3.5, 2.5, 0.1}), kBlue));
  // North is up the picture: the table's top edge (y = 2) lands above its bottom edge (y = 1).
  CHECK(ProjectToPixel(top, {1.5, 2, 0.8})->y < ProjectToPixel(top, {1.5, 1, 0.8})->y);
  // The whole box is in the picture, with a margin.
  for (Vec3 corner : {Vec3{0, 0, 0}, Vec3{4, 3, 0.8}}) {
    const auto px = ProjectToPixel(top, corner);
    CHECK(px->x > 0);
    CHECK(px->x < 200);
    CHECK(px->y > 0);
    CHECK(px->y < 160);
  }
}

TEST_CASE("a cut-away cuts the cut meshes of its level, removes what may go and hides the levels above") {
  const TriangleMesh floor = Block(0, 0, 4, 4, 0, 0.1), wall = Block(0, 0, 4, 0.2, 0.1, 2.8),
                     roof = Block(0, 0, 4, 4, 2.8, 3.0), upper = Block(0, 0, 4, 4, 2.8, 2.9);
  ViewScene scene;
  scene.meshes.push_back(Show(floor, kBlue, 1.0, 0, CutAway::kKeep));
  scene.meshes.push_back(Show(wall, kGreen, 1.0, 0, CutAway::kCut));
  scene.meshes.push_back(Show(roof, kRed, 1.0, 0, CutAway::kRemove));
  scene.meshes.push_back(Show(upper, kRed, 1.0, 1, CutAway::kKeep));
  scene.floor_z = {0.1, 2.9};
  const Camera top = FramingCamera(scene.Bounds(), 0, 90, 160, 160);
  auto whole = RenderView(scene, top, Flat());
  REQUIRE(whole);
  CHECK(Near(At(*whole, top, {2, 2, 3}), kRed));  // roof and upper floor on top
  RenderOptions cut = Flat();
  cut.top_level = 0;
  auto image = RenderView(scene, top, cut);
  REQUIRE(image);
  CHECK(Near(At(*image, top, {2, 2, 0.1}), kBlue));               // the floor under the removed roof
  CHECK(Near(At(*image, top, {2, 0.1, 1.6}), cut.section_color));  // the wall, cut at 1.5 m
  cut.top_level = 2;
  CHECK_FALSE(RenderView(scene, top, cut));  // no floor height for level 2
}

TEST_CASE("a see-through mesh tints what lies behind it") {
  const TriangleMesh floor = Block(0, 0, 2, 2, 0, 0.1), pane = Block(0, 0, 2, 2, 1.0, 1.02);
  ViewScene scene;
  scene.meshes.push_back(Show(floor, {1, 1, 1}));
  scene.meshes.push_back(Show(pane, {0, 0, 1}, 0.5));
  const Camera top = FramingCamera(scene.Bounds(), 0, 90, 64, 64);
  auto image = RenderView(scene, top, Flat());
  REQUIRE(image);
  const Rgb seen = At(*image, top, {1, 1, 0.1});
  CHECK(seen.b == Approx(1.0).margin(0.01));
  CHECK(seen.r == Approx(0.5).margin(0.01));
}

TEST_CASE("a room's cameras frame it from above and from its four corners") {
  Box3 room;
  room.Add(Vec3{2, 3, 0});
  room.Add(Vec3{6, 6, 2.6});
  const std::vector<Camera> cameras = RoomCameras(room, 768);
  REQUIRE(cameras.size() == 5);
  for (const Camera& camera : cameras) {
    CHECK(camera.Check() == "");
    CHECK(camera.width == 768);
    CHECK(camera.height == 768);
    for (int k = 0; k < 8; ++k) {
      const Vec3 c{k & 1 ? room.max.x : room.min.x, k & 2 ? room.max.y : room.min.y, k & 4 ? room.max.z : room.min.z};
      const auto px = ProjectToPixel(camera, c);
      REQUIRE(px);
      CHECK(px->x >= 0);
      CHECK(px->x <= 768);
      CHECK(px->y >= 0);
      CHECK(px->y <= 768);
    }
  }
  // The corner views look at the room from four different sides.
  for (int i = 1; i < 5; ++i)
    for (int j = i + 1; j < 5; ++j) CHECK(Norm(cameras[i].position - cameras[j].position) > 1.0);
}

TEST_CASE("labels are written at the projection of their points, and skipped behind the camera") {
  const TriangleMesh floor = Block(0, 0, 4, 4, 0, 0.1);
  ViewScene scene;
  scene.meshes.push_back(Show(floor, {0.6, 0.6, 0.6}));
  const Camera top = FramingCamera(scene.Bounds(), 0, 90, 240, 240);
  auto image = RenderView(scene, top, Flat());
  REQUIRE(image);
  const Image before = *image;
  LabelStyle style;
  style.background = {1, 1, 1};
  style.background_alpha = 1.0;
  REQUIRE(DrawLabels(*image, top, {{{1, 1, 0.1}, "chair_3"}}, style));
  const auto at = ProjectToPixel(top, {1, 1, 0.1});
  REQUIRE(at);
  // Dark text on a white box around the point; the far corner of the picture is untouched.
  int dark = 0, white = 0;
  for (int y = static_cast<int>(at->y) - 8; y <= static_cast<int>(at->y) + 8; ++y)
    for (int x = static_cast<int>(at->x) - 30; x <= static_cast<int>(at->x) + 30; ++x) {
      const Rgb c = image->At(x, y);
      dark += c.r < 0.3;
      white += c.r > 0.95;
    }
  CHECK(dark > 20);
  CHECK(white > 100);
  CHECK(image->At(230, 230) == before.At(230, 230));
  // Perspective: a point behind the camera has no projection.
  Camera eye;
  eye.position = {0, -10, 2};
  eye.target = {0, 0, 2};
  CHECK_FALSE(ProjectToPixel(eye, {0, -20, 2}));
  CHECK(ProjectToPixel(eye, {0, 0, 2})->x == Approx(eye.width / 2.0));
  Image copy = before;
  CHECK(DrawLabels(copy, eye, {{{0, -20, 2}, "behind"}}));
  CHECK(copy.rgb == before.rgb);
}

TEST_CASE("pictures encode as PNG with their size in the header") {
  Image image{5, 3, std::vector<std::uint8_t>(45, 200)};
  auto png = EncodePng(image);
  REQUIRE(png);
  CHECK(png->compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);
  CHECK(png->compare(12, 4, "IHDR") == 0);
  auto be32 = [&](size_t at) {
    const auto* u = reinterpret_cast<const unsigned char*>(png->data() + at);
    return (u[0] << 24) | (u[1] << 16) | (u[2] << 8) | u[3];
  };
  CHECK(be32(16) == 5);
  CHECK(be32(20) == 3);
  CHECK_FALSE(EncodePng(Image{2, 2, {}}));
}

TEST_CASE("bad cameras are refused with the reason") {
  const TriangleMesh floor = Block(0, 0, 1, 1, 0, 0.1);
  ViewScene scene;
  scene.meshes.push_back(Show(floor, kBlue));
  Camera cam;
  cam.target = cam.position;
  auto img = RenderView(scene, cam);
  REQUIRE_FALSE(img);
  CHECK_THAT(img.error(), Catch::Contains("position equals its target"));
  cam = Camera{};
  cam.width = 0;
  CHECK_FALSE(RenderView(scene, cam));
  cam = Camera{};
  cam.fov_deg = 180;
  CHECK_FALSE(RenderView(scene, cam));
}
