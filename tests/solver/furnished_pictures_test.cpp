// The pictures of a furnished villa (solver/furnish.h): plan.png's overlay holds every placed object's
// footprint on its level, lowest first, in its room's tone, and the walking paths once reachability has
// run; the 3D preview shows the furniture over the bare building.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>

#include "building/building.h"
#include "building/view_scene.h"
#include "layout/geometry.h"
#include "layout/layout_io.h"
#include "render/palette.h"
#include "scene/acquire.h"
#include "scene/room_context.h"
#include "solver/furnish.h"
#include "solver/room_view.h"

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
  // No walking paths yet: the paths are the functional groups' outlines, one for each group with members,
  // closed rectangles around their hub (green when the group holds, red when not).
  std::vector<const solver::GroupCheck*> groups;
  for (const solver::RoomReport& r : villa.rooms)
    if (r.functional)
      for (const solver::GroupCheck& g : r.functional->groups)
        if (!g.members.empty() && villa.scene.FindObject(g.anchor)) groups.push_back(&g);
  CHECK_FALSE(groups.empty());
  REQUIRE(overlay.paths.size() == groups.size());
  for (size_t k = 0; k < groups.size(); ++k) {
    const PlanOverlay::Path& outline = overlay.paths[k];
    REQUIRE(outline.points.size() == 5);
    CHECK(outline.points.front().x == Approx(outline.points.back().x));
    const scene::SceneObject& hub = *villa.scene.FindObject(groups[k]->anchor);
    CHECK(PointInRing({hub.pose->x, hub.pose->y}, Ring(outline.points.begin(), outline.points.end() - 1), 0.0));
    CHECK((outline.color.g > outline.color.r) == groups[k]->ok());
  }
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
  REQUIRE(with_paths.paths.size() == 1 + groups.size());
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

TEST_CASE("rooms/<room>.png: the top view is flat-lit (no wall shadows on the floor), the corner view keeps its shadows",
          "[solver][pictures]") {
  auto layout = LoadLayout(std::string(VILLA_FIXTURE_DIR) + "/layouts/house_one_floor.json");
  REQUIRE(layout.ok());
  auto building = BuildBuilding(*layout, {});
  REQUIRE(building.ok());
  // The bedroom (a 5 x 4 m box), empty: its middle shows bare floor in both views.
  auto context = scene::RoomContextOf(*layout, *building, {}, "bedroom_0/0");
  REQUIRE(context.ok());
  solver::RoomViewInput input;
  input.building = &*building;
  input.room = context->name;
  input.level = context->level;
  input.polygon = context->polygon;
  input.floor_z = context->floor_z;
  input.clear_height = context->clear_height;
  constexpr int kPanel = 128;
  auto picture = solver::RoomPicture(input, kPanel);
  REQUIRE(picture.ok());
  REQUIRE(picture->width == 2 * kPanel + 8);
  // The top view's middle 30 % (the floor more than a metre from every wall): one colour, no shadow patch.
  std::set<std::array<std::uint8_t, 3>> top;
  for (int y = kPanel * 35 / 100; y < kPanel * 65 / 100; ++y)
    for (int x = kPanel * 35 / 100; x < kPanel * 65 / 100; ++x) {
      const size_t i = (static_cast<size_t>(y) * picture->width + x) * 3;
      top.insert({picture->rgb[i], picture->rgb[i + 1], picture->rgb[i + 2]});
    }
  CHECK(top.size() == 1);
  // The corner view is shaded: the walls' shadows darken part of the floor, so its lower half holds more
  // than one tone of floor colour plus the background.
  std::set<std::array<std::uint8_t, 3>> corner;
  for (int y = kPanel / 2; y < kPanel; ++y)
    for (int x = kPanel + 8; x < picture->width; ++x) {
      const size_t i = (static_cast<size_t>(y) * picture->width + x) * 3;
      corner.insert({picture->rgb[i], picture->rgb[i + 1], picture->rgb[i + 2]});
    }
  CHECK(corner.size() > 3);
}
