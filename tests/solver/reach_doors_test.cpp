// Door leaves and walking (issue 13, layout/door_swing.h): a door off a 1.2 m corridor gets a swing whose
// open leaf leaves the corridor passable for the 0.2 m person, checked on the built building with the
// reachability raster; the same leaf standing across the corridor would close it (the check can fail).
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "building/building.h"
#include "layout/door_swing.h"
#include "layout/geometry.h"
#include "layout/layout_io.h"
#include "mesh/geometry2d.h"
#include "solver/reach.h"

namespace villa::solver {
namespace {

// A corridor 1.2 m wide along the south wall (0.89 m free between its walls' faces) with a bedroom and a
// kitchen off it and a bathroom at its end, reached only along it. The bedroom and the kitchen are larger
// than the corridor, so by room size alone their doors would open into it.
constexpr const char* kCorridorHouse = R"json({
  "rooms": {
    "room_0/0": {"shape": "shapely.box(0, 0, 8, 1.2)"},
    "bedroom_0/0": {"shape": "shapely.box(0, 1.2, 4, 5)"},
    "kitchen_0/0": {"shape": "shapely.box(4, 1.2, 8, 5)"},
    "bathroom_0/0": {"shape": "shapely.box(8, 0, 10, 5)"}
  },
  "entrance": {"main_door": {"shape": "shapely.LineString([(0, 0.1), (0, 1.1)])", "level": 0}},
  "doors": {
    "room0_bedroom0": {"shape": "shapely.LineString([(1.5, 1.2), (2.5, 1.2)])", "level": 0},
    "room0_kitchen0": {"shape": "shapely.LineString([(5, 1.2), (6, 1.2)])", "level": 0},
    "room0_bathroom0": {"shape": "shapely.LineString([(8, 0.2), (8, 1.0)])", "level": 0}
  },
  "opens": {},
  "windows": {},
  "interiors": {
    "wall_room0_bedroom0": {"shape": "shapely.LineString([(0, 1.2), (4, 1.2)])", "level": 0},
    "wall_room0_kitchen0": {"shape": "shapely.LineString([(4, 1.2), (8, 1.2)])", "level": 0},
    "wall_bedroom0_kitchen0": {"shape": "shapely.LineString([(4, 1.2), (4, 5)])", "level": 0},
    "wall_bathroom0": {"shape": "shapely.LineString([(8, 0), (8, 5)])", "level": 0}
  }
})json";

const Element& DoorNamed(const Layout& layout, const std::string& name) {
  for (const Element& e : layout.doors)
    if (e.name == name) return e;
  FAIL("no door " << name);
  return layout.doors.front();
}

TEST_CASE("a door off a 1.2 m corridor swings so that the corridor stays passable at radius 0.2", "[reach][door]") {
  auto layout = ParseLayoutText(kCorridorHouse, "corridor house");
  REQUIRE(layout.ok());
  const int corridor = layout->FindRoom("room_0/0");
  const int bathroom = layout->FindRoom("bathroom_0/0");

  // The rule: the side doors open into their rooms, not across the corridor; every leaf is open (90
  // degrees) and its tip lies in the room it opens into.
  for (const char* name : {"room0_bedroom0", "room0_kitchen0"}) {
    const DoorSwing swing = SwingOfDoor(*layout, DoorNamed(*layout, name), 0);
    INFO(name);
    CHECK(swing.into != corridor);
    CHECK(swing.other == corridor);
    CHECK_FALSE(swing.flat);
    CHECK(PointInRing(swing.leaf_end, layout->rooms[swing.into].polygon, 0));
    CHECK(Distance(swing.hinge, swing.leaf_end) == Approx(1.0));
  }

  // The built building, checked with the reachability raster (flood fill, no paths): every room reached.
  const BuildOptions build;
  auto building = BuildBuilding(*layout, build);
  REQUIRE(building.ok());
  for (const std::string& w : building->warnings) CHECK(w.find("hung closed") == std::string::npos);
  ReachOptions options;
  options.radius = 0.2;
  options.paths = false;
  auto input = BuildingReachInput(*layout, *building, build, options);
  REQUIRE(input.ok());
  int leaves = 0;
  for (const ReachObstacle& o : input->obstacles) leaves += o.kind == ObstacleKind::kDoorLeaf;
  CHECK(leaves == 4);  // the entrance and the three doors, all standing open
  auto report = CheckReach(*input, options);
  REQUIRE(report.ok());
  CHECK(report->rooms == 4);
  CHECK(report->rooms_reachable == 4);
  for (const auto& t : report->targets) {
    INFO(t.name);
    CHECK(t.reachable);
  }

  // The bedroom's leaf standing open across the corridor instead (what the room sizes alone chose): a 4 cm
  // slab from the hinge 1 m towards the south wall. The bathroom at the corridor's end is then cut off.
  ReachInput across = *input;
  const double z0 = across.levels[0].floor_z;
  across.obstacles.push_back({"leaf across the corridor", ObstacleKind::kDoorLeaf, 0, "",
                              {Ring{{1.48, 1.14}, {1.52, 1.14}, {1.52, 0.14}, {1.48, 0.14}}}, z0, z0 + 2.1});
  auto closed = CheckReach(across, options);
  REQUIRE(closed.ok());
  bool bathroom_reached = true;
  for (const auto& t : closed->targets)
    if (t.name == layout->rooms[bathroom].name()) bathroom_reached = t.reachable;
  CHECK_FALSE(bathroom_reached);
}

}  // namespace
}  // namespace villa::solver
