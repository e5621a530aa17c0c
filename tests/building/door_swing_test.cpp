// The 3D building opens every door as layout/door_swing.h's rule says, the rule the floor plan draws:
// into the same room, hinged at the same jamb. Checked on the three-floor fixture and, when the
// partitioner is part of the build, on synthesized layouts of every footprint class and floor count.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "building/building.h"
#include "layout/door_swing.h"
#include "layout/geometry.h"
#include "test_support.h"
#ifdef VILLA_TEST_WITH_PARTITIONER
#include "synthesized_layouts.h"
#endif

namespace villa {
namespace {

struct SwingCount {
  int open = 0;
  int closed = 0;
  int flat = 0;  // open 180 degrees, flat against the wall
};

// Checks every door leaf of `building` against the rule; returns how many stand open and closed.
SwingCount CheckLeaves(const Layout& layout, const BuildingMesh& building, const std::string& what) {
  SwingCount count;
  for (const MeshPart& part : building.parts) {
    if (part.kind != PartKind::kDoorLeaf) continue;
    const Element* element = nullptr;
    for (const auto* list : {&layout.entrances, &layout.doors})
      for (const Element& e : *list)
        if (e.name == part.element) element = &e;
    REQUIRE(element);
    const DoorSwing swing = SwingOfDoor(layout, *element, part.level);
    // The leaf in the door's frame: t along the opening from the hinge, q out to the rule's leaf side.
    const double w = swing.width();
    const Point u{(swing.free_end.x - swing.hinge.x) / w, (swing.free_end.y - swing.hinge.y) / w};
    double t_min = 1e9, t_max = -1e9, q_sum = 0;
    for (const Vec3& v : part.mesh.vertices) {
      const double t = (v.x - swing.hinge.x) * u.x + (v.y - swing.hinge.y) * u.y;
      t_min = std::min(t_min, t), t_max = std::max(t_max, t);
      q_sum += (v.x - swing.hinge.x) * swing.leaf_side.x + (v.y - swing.hinge.y) * swing.leaf_side.y;
    }
    const double q = q_sum / part.mesh.vertices.size();
    INFO(what << ": " << part.name << " on level " << part.level << ", leaf t in [" << t_min << ", " << t_max << "], q " << q
              << "; rule: into " << (swing.into >= 0 ? layout.rooms[swing.into].name() : "nothing") << ", hinge ("
              << swing.hinge.x << ", " << swing.hinge.y << ")");
    if (swing.flat && t_min < -0.3) {
      // Opened 180 degrees: flat against the wall beside the hinge, on the rule's side, just off the wall face.
      ++count.flat;
      CHECK(t_max < 0.01);
      CHECK(t_min == Approx(-w).margin(0.01));
      CHECK(q > 0.0);
      CHECK(q < 0.3);
      continue;
    }
    if (t_max - t_min > 0.3) {
      // Closed across its opening: only where the rule's sweep is blocked, and the builder says so.
      ++count.closed;
      bool warned = std::any_of(building.warnings.begin(), building.warnings.end(), [&](const std::string& warning) {
        return warning.find(" " + part.name + ":") != std::string::npos && warning.find("hung closed") != std::string::npos;
      });
      CHECK(warned);
      continue;
    }
    ++count.open;
    // Open: standing at the rule's hinge jamb, reaching out on the rule's side into the rule's room.
    CHECK(t_max < 0.1);
    CHECK(t_min > -0.1);
    CHECK(q > 0.3);
    if (swing.into >= 0) {
      const Point tip{swing.hinge.x + swing.leaf_side.x * q, swing.hinge.y + swing.leaf_side.y * q};
      CHECK(PointInRing(tip, layout.rooms[swing.into].polygon, 0));
    }
  }
  return count;
}

}  // namespace

TEST_CASE("the building opens every door of the fixture as the plan's rule says") {
  const SwingCount count = CheckLeaves(testing::ThreeFloorLayout(), testing::ThreeFloorBuilding(), "three-floor fixture");
  CHECK(count.open > 0);
  CHECK(count.closed == 0);
}

#ifdef VILLA_TEST_WITH_PARTITIONER
TEST_CASE("the building and the plan open every door of synthesized layouts the same way") {
  SwingCount total;
  const int layouts = testing::ForEachSynthesizedLayout(2, 7919, [&](const Layout& layout, const std::string& what) {
    auto building = BuildBuilding(layout);
    REQUIRE(building.ok());
    const SwingCount count = CheckLeaves(layout, *building, what);
    total.open += count.open;
    total.closed += count.closed;
    total.flat += count.flat;
  });
  CHECK(layouts >= 30);
  // A leaf hangs closed only where its sweep would hit a wall or a staircase: a rare door.
  INFO(total.open << " doors open, " << total.flat << " flat against the wall, " << total.closed << " closed");
  CHECK(total.closed * 20 <= total.open);
  // Most leaves stand at 90 degrees; folding one flat is the rule's last way out.
  CHECK(total.flat * 10 <= total.open);
}
#endif

}  // namespace villa
