#pragma once
// The solver's options (Ceres-style: a plain struct, every field with its unit, range and trade-off,
// checked by IsValid). Shared by the layers, the placement search, the agent and SolveRoom.
#include <cstdint>
#include <string>

namespace villa::solver {

enum class LinearSolverChoice {
  kAuto,                  // dense QR below `sparse_from_objects` movable objects, sparse normal Cholesky above
  kDenseQr,               // Ceres DENSE_QR
  kSparseNormalCholesky,  // Ceres SPARSE_NORMAL_CHOLESKY (SuiteSparse)
};

struct SolveOptions {
  // Seed of every random choice (candidate tie-breaks, restart jitter). Same seed, same arrangement.
  uint64_t seed = 0;
  // Constructive starts tried for the floor layer while the best one still has a hard violation, [1, 16].
  // Each costs one candidate search and one Ceres solve of the floor layer.
  int restarts = 4;
  // Rule-agent iterations (exact check + actions + re-solve) after the first solve, [0, 200]. The paper's
  // loop converges within about 20.
  int agent_iterations = 20;
  // Convergence: E <= energy_threshold with E_col = E_sup = 0 and the exact check clean (SCENE.md: 1.0).
  double energy_threshold = 1.0;

  // Clearance the optimiser keeps between floor, wall and ceiling objects' boxes (m), [0, 0.2]. Larger is
  // more robust against meshes that overfill their box, smaller packs tighter.
  double object_gap = 0.02;
  // Clearance between small objects on a surface or in a cavity, and to the surface's edge (m), [0, 0.05].
  double child_gap = 0.005;
  // How far footprints stay inside the free floor (m), [0, 0.1]; keep it below the walls' gaps.
  double bounds_margin = 0.01;
  // Half width of the yaw window around an object's 90-degree class (rad), [0, pi/4].
  double max_yaw_offset = 0.35;
  // Pairs farther apart than this (m, beyond their bounding circles) at the start of a solve are left
  // out of it; a pair that meets during the solve is added and the layer solved again. [0, 100].
  double pair_slack = 0.75;
  // Let Ceres shrink or grow objects within their scale range (a weak prior pulls the scale back to 1).
  // Off: scale changes only through the agent's update_scale.
  bool optimise_scale = false;

  // Issue 27: functional groups are the unit of placement and repair. A member (a chair of a table, a desk's
  // chair, a nightstand, the coffee table, side tables, armchairs, the TV stand) takes its poses from its
  // group's template around its hub (solver/place.h), a hub moved by an action carries its members, and an
  // action that would carry a member out of its group's rules (solver/group_rules.h) is refused; and the
  // way through a room between its doors (KeepOutKind::kCirculation) is kept clear where it can be. Off: the
  // semantic relations alone, as before issue 27 (to measure, or to test the critic on its own).
  bool functional_groups = true;

  // Ceres: iterations per solve [1, 1000] and the linear solver (measured: 35 objects, sparse normal
  // Cholesky 23 ms vs dense QR 122 ms).
  int ceres_max_iterations = 60;
  LinearSolverChoice linear_solver = LinearSolverChoice::kAuto;
  int sparse_from_objects = 30;  // [1, 100000]

  // Residual weights (per m, per m of depth; semantic per m or per rad), each (0, 1000]. Hard terms are
  // weighted well above soft ones so a relation never pushes an object into another.
  double weight_collision = 10.0;
  double weight_bounds = 10.0;
  double weight_keep_out = 10.0;
  double weight_containment = 10.0;
  double weight_zone = 2.0;
  double weight_semantic = 1.0;

  // False, with the reason in *message, when a field is out of its range.
  bool IsValid(std::string* message) const;
};

}  // namespace villa::solver
