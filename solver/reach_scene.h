#pragma once
// Reachability of a furnished scene file (`villa reach DIR/scene.json`): the layout the scene names
// (relative to the scene's folder), built again with the scene's build record, and the placed objects as
// boxes from their pose and size (SCENE.md stores the scaled size, so the asset library is not needed).
#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "solver/reach.h"
#include "util/result.h"

namespace villa::solver {

struct SceneReach {
  ReachReport report;
  std::filesystem::path layout;       // the layout file read
  std::vector<std::string> warnings;  // the layout's bytes differ from the scene's record, ...
};

// The scene's placed objects (those with a pose) as reachability sees them: floor coverings marked, each
// V_int object's interaction zone, with whether the objects allowed in it stand there.
std::vector<ReachObject> ReachObjectsOfScene(const scene::SceneFile& scene);

// Reads, builds and checks. Errors name the file (an unreadable scene or layout, a layout that cannot be
// built, bad options).
Result<SceneReach> ReachOfScene(const std::filesystem::path& scene_file, const ReachOptions& options);

}  // namespace villa::solver
