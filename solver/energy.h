#pragma once
// The energy of an arrangement (SCENE.md "Energies", paper Eq. 1-2), evaluated on the placed objects:
//   E = 5 E_col + 2 E_sup + 1 E_sem
//   E_col: sum of box-intersection volumes (m3) over pairs that are not parent and child (rugs excepted:
//          objects stand on them), plus each object against the building: the volume of its box outside
//          the free floor (walls), inside a keep-out prism (door sweeps and strips, window zones, the
//          staircase) or in front of a wall opening;
//   E_sup: over V_con objects (all but on_wall and hanging), |z_bottom - z_surface| plus P = 1 when the
//          footprint centre lies outside its support region (free floor, S_parent, the cavity's floor);
//   E_sem: the geometric proxy (no critic here): per semantic edge the violated amount (angles in units of
//          30 degrees, distances in m) plus every interaction-zone intrusion depth (m).
#include <string>
#include <utility>
#include <vector>

#include "solver/placement.h"
#include "solver/problem.h"

namespace villa::solver {

struct RoomState;

struct EnergyTerms {
  double collision = 0.0;  // E_col (m3)
  double support = 0.0;    // E_sup
  double semantic = 0.0;   // E_sem (proxy)
  double total = 0.0;      // 5 E_col + 2 E_sup + E_sem
  // Per object (parallel to the objects): its share of each term, a pair's volume counted for both.
  std::vector<double> object_collision;
  std::vector<double> object_support;
  std::vector<double> object_semantic;
  std::vector<double> edge_violation;  // per semantic edge, parallel to the edges
  // Overlapping pairs: two object ids, or an object id and "walls" / a keep-out's name / "wall opening".
  std::vector<std::pair<std::string, std::string>> overlaps;
  std::vector<std::string> findings;   // one line per non-zero contribution ("a x b: 0.0123 m3")
};

inline constexpr double kWeightCollision = 5.0;
inline constexpr double kWeightSupport = 2.0;
inline constexpr double kWeightSemantic = 1.0;

// E_sem's term for one semantic edge between `source` and `target` as placed (0: it holds).
double EdgeViolation(const SemanticEdge& edge, const ProblemObject& source, const ObjectPlacement& at_source, const ProblemObject& target,
                     const ObjectPlacement& at_target);
// The energy of `placements` (parallel to problem.objects; every object placed).
EnergyTerms ArrangementEnergy(const RoomProblem& problem, const std::vector<ObjectPlacement>& placements);
// The same on the solver's working state.
EnergyTerms StateEnergy(const RoomState& state);

}  // namespace villa::solver
