#pragma once
// Independent re-checks of drawn reachability paths for the tests: plain segment-to-polygon distances,
// written here without the solver's clearance query, so a path the query passed is judged a second time.
#include <string>
#include <vector>

#include "building/building.h"
#include "solver/reach.h"

namespace villa::solver {

// A fixture layout (tests/fixtures/layouts/<file>) built with the default options, and its reachability
// input (no objects).
struct Built {
  BuildingMesh building;
  ReachInput input;
};
Built BuildFixture(const std::string& file, const ReachOptions& options = {});

// The smallest plan distance from any walking segment of `path` on `level` to the input's obstacles of that
// level (their pieces, between their heights and the walking band) and to the outside of its floor.
double PathClearance(const ReachPath& path, const ReachInput& input, int level);
// The smallest plan distance from any walking segment of `path` to the building's meshes (walls, door
// leaves, panes, stairs) cut to the walking band of the segment's level, to its slab holes, and to the
// objects' boxes.
double MeshClearance(const ReachPath& path, const BuildingMesh& building, const std::vector<ReachObject>& objects);

}  // namespace villa::solver
