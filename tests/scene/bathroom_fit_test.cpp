#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "layout/layout_io.h"
#include "scene/bathroom_fit.h"
#include "scene/planner.h"
#include "scene_test_support.h"

using namespace villa;
using namespace villa::scene;
using namespace villa::scene::testing;

namespace {

// The bench's most common bathroom: 2.5 x 2.5 m in the corner of the plan (2.19 x 2.19 m of free floor
// inside its exterior and interior walls), the door on its north wall, a window on its west wall.
BuiltLayout SmallBathroom() {
  auto layout = ParseLayoutText(R"json({"rooms": {"bathroom_0/0": {"shape": "shapely.box(0, 0, 2.5, 2.5)"},
                                              "living-room_0/0": {"shape": "shapely.box(2.5, 0, 7, 2.5)"},
                                              "bedroom_0/0": {"shape": "shapely.box(0, 2.5, 7, 6)"}},
    "entrance": {"main": {"shape": "shapely.LineString([(4, 0), (5, 0)])", "level": 0}},
    "doors": {"bed_bath": {"shape": "shapely.LineString([(0.56, 2.5), (1.56, 2.5)])", "level": 0},
              "living_bed": {"shape": "shapely.LineString([(4, 2.5), (5, 2.5)])", "level": 0}},
    "opens": {},
    "windows": {"bath_window": {"shape": "shapely.LineString([(0, 0.5), (0, 1.5)])", "is_panoramic": 0, "level": 0}},
    "interiors": {"w1": {"shape": "shapely.LineString([(2.5, 0), (2.5, 2.5)])", "level": 0},
                  "w2": {"shape": "shapely.LineString([(0, 2.5), (7, 2.5)])", "level": 0}}})json",
                                "small-bath.json");
  REQUIRE(layout.ok());
  return Built(std::move(*layout));
}

BathFixture Fixture(const std::string& category, double w, double d, double h, double zone) {
  return {category, w, d, h, zone};
}

const SceneObject* Find(const RoomPlan& plan, const std::string& category) {
  for (const SceneObject& o : plan.objects)
    if (o.category == category && IsRootParent(o.parent)) return &o;
  return nullptr;
}

}  // namespace

TEST_CASE("bathroom fixtures fit only with their use zones on open floor", "[scene][bathroom]") {
  const BuiltLayout b = SmallBathroom();
  const RoomContext bath = ContextOf(b, "bathroom_0/0");
  REQUIRE(bath.free_area == Approx(2.19 * 2.19).epsilon(0.01));
  const BathFixture toilet = Fixture("toilet", 0.4, 0.64, 0.76, 0.6), basin = Fixture("washbasin", 0.6, 0.45, 0.86, 0.7);
  const BathFixture tub = Fixture("bathtub", 1.7, 0.8, 0.58, 0.6), cabinet = Fixture("cabinet", 0.75, 0.47, 1.4, 0.8);
  BathFixture bin = Fixture("bin", 0.28, 0.28, 0.4, 0.0);
  bin.companion_of = 0;

  CHECK(FitBathFixtures(bath, {toilet, basin}).fits);
  CHECK(FitBathFixtures(bath, {toilet, basin, bin}).fits);
  CHECK(FitBathFixtures(bath, {toilet, basin, Fixture("shower", 0.8, 0.8, 2.1, 0.6), bin}).fits);
  // A bath, a cabinet, a toilet and a basin: every arrangement stands one of them in another's zone (the
  // solver used to place them so and leave the zones entered).
  const BathFitResult crowded = FitBathFixtures(bath, {toilet, basin, tub, cabinet, bin});
  CHECK_FALSE(crowded.fits);
  CHECK_FALSE(crowded.exhausted);  // a proof, not a budget running out

  // A fixture as deep as the room with its zone cannot stand anywhere.
  CHECK_FALSE(FitBathFixtures(bath, {Fixture("cabinet", 0.6, 1.0, 1.0, 1.3)}).fits);
  CHECK(FitBathFixtures(bath, {Fixture("cabinet", 0.6, 1.0, 1.0, 1.1)}).fits);

  // The basin's mirror needs a wall without a window above it. The same room with a window high up over
  // the middle of its south and east walls as well: a basin 1.4 m wide (the north wall, 1.19 m beside the
  // door, is too short) stands below a window wherever it goes, which it may, but then no mirror can hang
  // centred over it.
  RoomContext windowed = bath;
  int added = 0;
  for (WallEdge& w : windowed.walls)
    if (w.windows.empty() && w.openings.empty()) {
      w.windows.push_back({"high", {0.8, 1.4}, 1.6, 2.1, false});
      ++added;
    }
  REQUIRE(added == 2);
  BathFixture wide = Fixture("washbasin", 1.4, 0.45, 0.86, 0.7);
  CHECK(FitBathFixtures(windowed, {wide}).fits);
  wide.mirror = 0.6;
  CHECK_FALSE(FitBathFixtures(windowed, {wide}).fits);
  CHECK(FitBathFixtures(bath, {wide}).fits);

  BathFitOptions bad;
  bad.budget = 0;
  CHECK(bad.Check().find("budget") != std::string::npos);
  CHECK(BathFitOptions{}.Check().empty());
}

TEST_CASE("a small bathroom's plan keeps the fixtures whose use zones fit", "[scene][bathroom][planner]") {
  const BuiltLayout b = SmallBathroom();
  const RoomContext bath = ContextOf(b, "bathroom_0/0");
  int changed = 0;
  for (uint64_t seed = 1; seed <= 12; ++seed) {
    auto planned = PriorsPlanner().Plan({&bath, "", seed});
    REQUIRE(planned.ok());
    const RoomPlan& plan = *planned;
    INFO("seed " << seed << "\n" << PlanTable(plan, bath.name));
    // The fixtures as planned (with the bin beside the toilet) fit with their zones.
    std::vector<BathFixture> fixtures;
    for (const char* category : {"toilet", "washbasin", "bathtub", "shower", "cabinet"})
      if (const SceneObject* o = Find(plan, category))
        fixtures.push_back(Fixture(category, o->size.x, o->size.y, o->size.z, o->interaction_zone ? o->interaction_zone->depth : 0.0));
    REQUIRE(Find(plan, "toilet"));
    REQUIRE(Find(plan, "washbasin"));
    CHECK(FitBathFixtures(bath, fixtures).fits);
    // The mirror over the basin is narrower than the basin by the 10 cm wall decor keeps from a wall's end
    // on each side, down to the smallest mirror.
    const SceneObject* mirror = Find(plan, "mirror");
    REQUIRE(mirror);
    CHECK(mirror->size.x <= std::max(0.4, Find(plan, "washbasin")->size.x - 0.2) + 1e-9);
    for (const std::string& note : plan.record.notes) changed += note.rfind("a small bathroom", 0) == 0;
  }
  CHECK(changed > 0);  // the priors alone plan more than this room holds
}
