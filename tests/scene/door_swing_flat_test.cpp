// A door leaf opened 180 degrees (layout/door_swing.h, where no leaf can stand at 90 degrees) lies flat
// against the wall in the built building, and the furnishing keeps its half disc clear: the square over the
// opening and the one over the wall it folds onto.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "building/building.h"
#include "layout/door_swing.h"
#include "layout/geometry.h"
#include "layout/layout_io.h"
#include "scene/door_swing.h"

namespace villa::scene {
namespace {

TEST_CASE("a leaf opened flat against the wall keeps its half disc clear of furniture", "[scene][door]") {
  auto layout = LoadLayout(std::string(VILLA_FIXTURE_DIR) + "/layouts/two_halls.json");
  REQUIRE(layout.ok());
  const BuildOptions options;
  auto building = BuildBuilding(*layout, options);
  REQUIRE(building.ok());
  const villa::DoorSwing rule = SwingOfDoor(*layout, layout->doors[0], 0);
  REQUIRE(rule.flat);

  // The leaf in the building: 4 cm off the wall face on the rule's side, one door width beside the opening.
  const MeshPart* leaf = nullptr;
  for (const MeshPart& p : building->parts)
    if (p.kind == PartKind::kDoorLeaf && p.element == "office0_office0-1") leaf = &p;
  REQUIRE(leaf);
  double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
  for (const Vec3& v : leaf->mesh.vertices)
    x0 = std::min(x0, v.x), x1 = std::max(x1, v.x), y0 = std::min(y0, v.y), y1 = std::max(y1, v.y);
  CHECK(x0 == Approx(std::min(rule.hinge.x, rule.leaf_end.x)).margin(0.01));
  CHECK(x1 == Approx(std::max(rule.hinge.x, rule.leaf_end.x)).margin(0.01));
  CHECK(y1 - y0 == Approx(options.door_leaf_thickness).margin(1e-6));
  const double face = options.interior_wall_thickness / 2.0;
  // On the rule's side of the wall, its near face 2 mm off the wall's face.
  CHECK((y0 + y1 - 3.0) * rule.leaf_side.y > 0.0);
  CHECK(std::min(std::abs(y0 - 1.5), std::abs(y1 - 1.5)) == Approx(face + 0.002).margin(1e-6));

  // What the furnishing reads off it: the leaf's side and hinge, a sweep of 2 x 1 door widths on that side,
  // and the strip on the other.
  const auto swings = DoorSwings(*layout, *building, options, 0);
  const DoorSwing* door = nullptr;
  for (const DoorSwing& s : swings)
    if (s.element == "office0_office0-1") door = &s;
  REQUIRE(door);
  CHECK(door->side == (rule.leaf_side.y > 0 ? 1 : -1));
  CHECK(door->hinge == (rule.hinge.x == Approx(2.5) ? 0 : 1));
  CHECK(std::abs(Area(door->sweep)) == Approx(2.0).margin(1e-6));
  Box2 box = BoundingBox(door->sweep);
  CHECK(std::min(box.min_x, box.max_x) == Approx(std::min(rule.leaf_end.x, rule.free_end.x)));
  CHECK(std::max(box.min_x, box.max_x) == Approx(std::max(rule.leaf_end.x, rule.free_end.x)));
  REQUIRE(door->strips.size() == 1);
}

}  // namespace
}  // namespace villa::scene
