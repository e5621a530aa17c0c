#pragma once
// Scoring a furnished .glb, ours or another method's (SCENE.md "The furnished glTF"): per room the micro
// metrics CR, FR, OBR, CSR and NO, computed by the exact check the solver ends with (solver/exact_check.h),
// so scenes made elsewhere and ours are measured by one rule (`villa eval --scenes --glb`).
//
// What the file must hold: one node per object whose extras name at least its `room` (the room node it
// belongs to), and best also `id`, `category`, `asset`, `level`, `parent`, `relation` and `surface` /
// `cavity` / `wall` (ours always do). Missing `parent`/`relation` read as standing on the floor. A room
// node is a node named after the room (extras `name`); its mesh, when it has one, is the room's floor.
//
// Each object's geometry is its node's meshes moved by the node's transform (glTF +Y up read back into
// the plan frame, z up). When that transform is a turn about the vertical, a translation and a scale, the
// mesh is kept in its own frame with that pose (as the solver holds it); otherwise the moved mesh is the
// asset and the pose is the identity at its bottom centre. An asset id that resolves (procedural ids
// always; library ids through the scene's library, `library`, or the installed one) whose size matches
// the mesh (1 cm or 1 %) gives the record's support surfaces and cavities, and the extras' surface and
// cavity indices are used; otherwise they are read off the mesh (assets/mesh_affordances.h) and each child
// takes the surface or cavity of its parent it rests on.
//
// The room's frame (free floor, walls, building parts) comes from the layout when there is one
// (`layout`, else the file the scene names): exactly what `villa furnish` solved against, so our own
// files score as their report says. Without a layout it comes from the .glb: the free floor is the top of
// the room node's floor mesh (the room polygon: wall bands are not subtracted), the floor height its top,
// the clear height 2.625 m, walls along the floor's edges, and the building parts every other mesh node
// (not an object, not a room floor) reaching into the room's height band within 0.5 m of it.
#include <filesystem>
#include <string>
#include <vector>

#include "layout/layout.h"
#include "solver/exact_check.h"
#include "util/result.h"

namespace villa::solver {

struct GlbMetricsOptions {
  std::filesystem::path scene;    // optional scene.json: the layout it names, its wall thicknesses, its library
  std::filesystem::path layout;   // optional layout.json (wins over the scene's)
  std::filesystem::path library;  // optional asset library folder (wins over the scene's and the installed one)
  ExactCheckOptions check;

  std::string Check() const;  // empty when usable
};

// One room's figures.
struct GlbRoomMetrics {
  std::string room;
  Category category = Category::kRoom;
  int level = 0;
  ExactMetrics metrics;      // NO, CR, FR, OBR, CSR with their counts and the colliding pairs
  int records_resolved = 0;  // objects whose asset record was found by id
  int records_from_mesh = 0; // objects whose surfaces and cavities were read off their mesh
};

struct GlbMetricsSummary {
  std::string frame;                 // "layout FILE" or "glb"
  std::vector<GlbRoomMetrics> rooms; // every room node (or layout room), in the file's order
  std::vector<std::string> notes;    // what was assumed ("office_0/0/lamp-0: parent desk-9 not in the file: floor")
  int objects = 0;
  double seconds = 0.0;
};

// Reads `glb` and measures every room. Errors: an unreadable file, a scene or layout that cannot be read,
// a layout whose rooms the file does not match (an object in a room the layout lacks), bad options.
Result<GlbMetricsSummary> MeasureFurnishedGlb(const std::filesystem::path& glb, const GlbMetricsOptions& options = {});

}  // namespace villa::solver
