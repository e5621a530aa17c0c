#pragma once
// The exact check after every solve (SCENE.md "Metrics"): mesh-level tests on the placed assets, never
// the optimiser's box proxies. FCL stays inside exact_check.cpp.
//   CR  share of objects in collision: the meshes of i and j (rugs excepted) collide (FCL, BVH of OBBRSS)
//       and still collide after j moves `nudge` m away from the mean contact point (SceneEval's
//       CollisionMetric); the building's parts count as j (the object moves); a parent and its child
//       collide when they still do after the child is lifted `nudge` m off its support (a hanger's hook
//       off its rail): a book may touch its shelf, not enter the shelf above (issue 28);
//   FR  share of V_con objects whose lowest vertex is more than `tau` from their support height;
//   OBR share of objects with less than `in_bound_share` of their sampled surface points projecting (down
//       along -z) into their support region: free floor for floor and ceiling objects, S_parent for ontop,
//       the cavity's floor for inside; on_wall objects must lie along their wall piece, floor to ceiling;
//   CSR over inside edges: the child's box within cavity k (`containment_tolerance`), no mesh collision
//       with the parent (after the same nudge: a book resting on the shelf touches it) and its lowest
//       vertex within `tau` of the cavity floor;
//   NO  the number of objects.
// FCL's mesh-mesh penetration depth is not used (it reported 6 mm for a 5 cm overlap in our trial); the
// decisions are boolean collisions, and distances only for the clearance figure.
#include <memory>
#include <string>
#include <vector>

#include "solver/placement.h"
#include "solver/problem.h"

namespace villa::solver {

struct RoomState;

struct ExactCheckOptions {
  double tau = 0.01;                     // m, support distance tolerance (FR, CSR), [0, 0.1]
  double nudge = 0.005;                  // m, SceneEval's move before a collision counts, [0, 0.05]
  double in_bound_share = 0.99;          // OBR: share of points that must project inside, (0, 1]
  double containment_tolerance = 0.005;  // m, CSR box-in-cavity slack, [0, 0.05]
  int obr_samples = 1000;                // surface points sampled per object (OBR), [16, 100000]
  double clearance_probe = 0.05;         // m: pairs whose boxes come this close get an FCL distance, [0, 1]
  bool IsValid(std::string* message) const;
};

struct CollisionPair {
  std::string a;
  std::string b;  // an object id or a building part's name
  bool building = false;
};

struct ObjectCheck {
  std::string id;
  bool colliding = false;
  bool floating = false;        // V_con only
  bool out_of_bounds = false;
  bool inside_edge = false;     // its relation is inside
  bool contained = false;       // CSR holds (inside edges only)
  double support_gap = 0.0;     // m, |z_min - z_support| (V_con only)
  double in_bound_share = 1.0;  // share of its sampled points inside its support region
};

struct ExactMetrics {
  int objects = 0;  // NO
  int colliding = 0, floating = 0, out_of_bounds = 0;
  int consumers = 0;     // V_con objects (FR's denominator)
  int inside_edges = 0, contained = 0;
  double cr = 0.0, fr = 0.0, obr = 0.0;
  double csr = 1.0;      // 1 when the room has no inside edge
  double min_clearance = -1.0;  // m, smallest FCL distance between close non-colliding pairs; -1 none probed
  std::vector<CollisionPair> pairs;
  std::vector<ObjectCheck> per_object;  // parallel to the objects
  double seconds = 0.0;
  // CR = FR = OBR = 0 and CSR = 1.
  bool Clean() const { return colliding == 0 && floating == 0 && out_of_bounds == 0 && contained == inside_edges; }
};

// Holds the FCL models of the room's building parts and of every asset mesh (per scale) between checks.
class ExactChecker {
 public:
  ExactChecker(const RoomProblem& problem, const ExactCheckOptions& options);
  ~ExactChecker();
  ExactChecker(const ExactChecker&) = delete;
  ExactChecker& operator=(const ExactChecker&) = delete;
  // `measure_clearance`: also the FCL distance of close, non-colliding pairs (min_clearance); the solver
  // asks for it on the state it keeps, not on every iteration.
  ExactMetrics Check(const RoomState& state, bool measure_clearance = true);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// One exact check of `placements` (parallel to problem.objects; every object placed).
ExactMetrics CheckArrangement(const RoomProblem& problem, const std::vector<ObjectPlacement>& placements,
                              const ExactCheckOptions& options = {});

}  // namespace villa::solver
