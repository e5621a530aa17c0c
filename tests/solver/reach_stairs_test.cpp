// Reachability through a stack of staircases whose room has doors on more than one side: the builder
// leaves every door of the stair room on the floor beside the flights, so the bare building closes
// nothing (issue 13; docs/BUILDING.md "Staircases").
#include <catch2/catch.hpp>

#include "reach_checks.h"
#include "solver/reach.h"

namespace villa::solver {

TEST_CASE("every room of a three-floor stack with doors on two sides of the stair room is reachable", "[reach]") {
  ReachOptions options;
  options.paths = false;  // the raster's verdict is what is asserted
  const Built built = BuildFixture("stair_doors_around.json", options);
  REQUIRE(built.input.stairs.size() == 2);
  auto report = CheckReach(built.input, options);
  REQUIRE(report.ok());
  INFO(report->BriefReport());
  CHECK(report->rooms == 7);
  for (const TargetResult& t : report->targets) {
    INFO(t.name << ": " << t.note);
    CHECK(t.reachable);
  }
  CHECK(report->rooms_reachable == report->rooms);
}

}  // namespace villa::solver
