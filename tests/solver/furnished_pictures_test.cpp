// The pictures of a furnished villa (solver/furnish.h): plan.png's overlay holds every placed object's
// footprint on its level, lowest first, in its room's tone, and the walking paths once reachability has
// run; the 3D preview shows the furniture over the bare building.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>

#include "building/view_scene.h"
#include "layout/layout_io.h"
#include "render/palette.h"
#include "scene/acquire.h"
#include "solver/furnish.h"

using namespace villa;

namespace {

solver::FurnishedVilla Furnished() {
  auto layout = LoadLayout(std::string(VILLA_FIXTURE_DIR) + "/layouts/house_one_floor.json");
  REQUIRE(layout.ok());
  auto library = scene::OpenFurnishingLibrary("", true);
  REQUIRE(library.ok());
  solver::FurnishOptions options;
  options.seed = 2;
  options.jobs = 2;
  options.check_reach = false;  // the paths are added by hand below
  auto villa = solver::FurnishLayout(*layout, {"house_one_floor.json", std::string(64, '0')}, library->library, std::nullopt, options);
  INFO((villa.ok() ? "" : villa.error()));
  REQUIRE(villa.ok());
  return std::move(*villa);
}

}  // namespace

TEST_CASE("plan.png's overlay: every standing or hung object's footprint, lowest first, and the walking paths", "[solver][pictures]") {
  solver::FurnishedVilla villa = Furnished();
  const PlanOverlay overlay = solver::FurnishedPlanOverlay(villa);
  std::map<std::string, const scene::SceneObject*> drawn;
  int hanging = 0;
  for (const scene::SceneObject& o : villa.scene.objects) {
    REQUIRE(o.pose);
    if (o.relation == scene::Relation::kHanging) ++hanging;
  }
  REQUIRE(overlay.shapes.size() == villa.scene.objects.size() - hanging);
  CHECK(overlay.paths.empty());
  // Each shape is an object's box: its area is the object's footprint, its fill a darker tone of its room's
  // colour; shapes come lowest first.
  double footprint = 0.0, shapes = 0.0;
  for (const scene::SceneObject& o : villa.scene.objects)
    if (o.relation != scene::Relation::kHanging) footprint += o.size.x * o.size.y;
  for (const PlanOverlay::Shape& s : overlay.shapes) {
    REQUIRE(s.outline.size() == 4);
    shapes += Area(s.outline);
    CHECK(s.level == 0);
  }
  CHECK(shapes == Approx(footprint).epsilon(1e-9));
  const Rgb living = CategoryColor(Category::kLivingRoom);
  bool living_tone = false;
  for (const PlanOverlay::Shape& s : overlay.shapes)
    living_tone = living_tone || (s.fill.r < living.r && s.fill.g < living.g && std::abs(s.fill.r - living.r) < 0.35);
  CHECK(living_tone);

  const auto plain = solver::FurnishedPlanPng(villa);
  REQUIRE(plain.ok());
  solver::ReachFigures reach;
  reach.paths.push_back({0, {{1.0, 1.0}, {3.0, 1.0}, {3.0, 4.0}}});
  villa.reach = reach;
  const PlanOverlay with_paths = solver::FurnishedPlanOverlay(villa);
  REQUIRE(with_paths.paths.size() == 1);
  CHECK(with_paths.paths[0].points.size() == 3);
  const auto walked = solver::FurnishedPlanPng(villa);
  REQUIRE(walked.ok());
  CHECK(*walked != *plain);
}

TEST_CASE("The furnished preview shows the furniture over the bare building, at the same size", "[solver][pictures]") {
  const solver::FurnishedVilla villa = Furnished();
  PreviewOptions options;
  options.panel_width = 240;
  options.panel_height = 200;
  options.samples = 1;
  auto bare = RenderPreview(ViewSceneOf(villa.building), options);
  auto furnished = solver::RenderFurnishedPreview(villa, options);
  REQUIRE(bare.ok());
  REQUIRE(furnished.ok());
  REQUIRE(furnished->width == bare->width);
  REQUIRE(furnished->height == bare->height);
  size_t changed = 0;
  for (size_t i = 0; i < bare->rgb.size(); i += 3)
    changed += bare->rgb[i] != furnished->rgb[i] || bare->rgb[i + 1] != furnished->rgb[i + 1] || bare->rgb[i + 2] != furnished->rgb[i + 2];
  // The exterior panel is the same building; the cut-away shows a room full of furniture.
  CHECK(changed > bare->rgb.size() / 3 / 50);
}
