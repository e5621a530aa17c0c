// Reachability through a stack of staircases whose room has doors on more than one side: the builder
// leaves every door of the stair room on the floor beside the flights, so the bare building closes
// nothing (issue 13; docs/BUILDING.md "Staircases").
#include <catch2/catch.hpp>

#include "reach_checks.h"
#include "solver/reach.h"

namespace villa::solver {

namespace {

// Builds the fixture and checks with the raster alone (no paths) that every one of its `rooms` rooms is
// reached from the entrance over its two staircases.
void CheckEveryRoomReached(const char* fixture, int rooms) {
  ReachOptions options;
  options.paths = false;  // the raster's verdict is what is asserted
  const Built built = BuildFixture(fixture, options);
  REQUIRE(built.input.stairs.size() == 2);
  auto report = CheckReach(built.input, options);
  REQUIRE(report.ok());
  INFO(report->BriefReport());
  CHECK(report->rooms == rooms);
  for (const TargetResult& t : report->targets) {
    INFO(t.name << ": " << t.note);
    CHECK(t.reachable);
  }
  CHECK(report->rooms_reachable == report->rooms);
}

}  // namespace

TEST_CASE("every room of a three-floor stack with doors on two sides of the stair room is reachable", "[reach]") {
  CheckEveryRoomReached("stair_doors_around.json", 7);
}

// A stair room with doors on three sides (villa-000046 of `villa synth --count 50 --seed 7`; before the
// passages on both sides of the flights, the builder left two of its upstairs rooms opening onto the hole).
TEST_CASE("every room is reached through a stair room with doors on three sides", "[reach][stairs]") {
  CheckEveryRoomReached("stair_doors_three_sides.json", 15);
}

}  // namespace villa::solver
