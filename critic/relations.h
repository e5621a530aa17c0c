#pragma once
// Whether the semantic edges and interaction zones of a room's A-PSSG hold in an arrangement, measured
// exactly on the objects' boxes (the asset record's size times the object's scale, at its pose): the
// definitions of SCENE.md, the ones the solver's residuals are hinges of, written out with the measured
// value so a critic (and a person) can say by how much an edge fails. docs/CRITIC.md states them:
//
//   face_to   the angle between the source's facing f(yaw) = (sin yaw, -cos yaw) and the direction from
//             its centre to the target's centre is at most max_deg (30)
//   front_of, behind, left_of, right_of   in the target's frame (front = -y, left = +x): the source's
//             centre lies in the target's band on that side: on that side of the target's centre line and
//             within the target's extent across it (|x| <= half width for front and back, |y| <= half depth
//             for left and right); when the edge gives min_gap / max_gap, the gap between the two boxes
//             lies in that range too
//   next_to, near, far   the gap between the two boxes (the widest separation along a face normal of
//             either box in plan; negative when they overlap) lies in [min_gap, max_gap]: next_to [0, 0.5],
//             near [0.5, 1.5], far [1.5, inf) m unless the edge says otherwise
//   align     the yaws agree modulo 90 degrees within max_deg (5)
//   centered  the source's centre lies on the target's front-back axis: the offset along the target's x
//             is at most max_offset (0.05 m)
//   zone      an interaction zone (its owner's full width, `depth` m deep, its height, on its side) holds
//             no part of another object's box: a box overlapping it in plan by more than 1 mm with a
//             height range that meets it; exempt objects, what stands on them, the owner's own things and
//             floor coverings (rugs) do not count (an overlap of 1 mm or less does not either)
// A bound is met within the measures' resolution: 1 mm for lengths, 0.1 degree for angles (the optimiser
// ends a hair past a bound; no person could see it). Angles in degrees, lengths in metres, the world frame
// of SCENE.md.
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene.h"
#include "solver/box.h"
#include "solver/placement.h"
#include "solver/problem.h"

namespace villa::critic {

// An object's box in the world (solver/box.h): footprint centre, yaw, half extents along its own x and y,
// bottom and top heights; the asset record's size times the object's scale at its pose.
using ObjectBox = solver::OrientedBox;
ObjectBox BoxOf(const solver::ProblemObject& object, const solver::ObjectPlacement& placement);

// The plan gap between two boxes: the widest separation along the four face normals (m, < 0: overlap).
using solver::PlanGap;

struct EdgeCheck {
  scene::SemanticEdge edge;
  bool present = true;     // both objects are in the room (else not measured)
  bool satisfied = false;
  double value = 0.0;      // the measured quantity: degrees (face_to, align), m (gap, offset, side margin)
  // How far from holding: degrees past the bound / 30, or metres short of or past the range (0 when held).
  double violation = 0.0;
  std::string detail;      // "angle 42.0 deg > 30" / "gap 0.71 m, wanted [0, 0.5]"
};
EdgeCheck CheckEdge(const scene::SemanticEdge& edge, const ObjectBox& source, const ObjectBox& target);

struct ZoneCheck {
  std::string owner;
  std::string side;                     // "front", "back", "left", "right", "sides"
  double depth = 0.0;                   // m
  std::vector<std::string> intruders;   // objects inside it
  bool clear() const { return intruders.empty(); }
};

// Every edge of `edges` and every zone of the room measured on the arrangement (objects parallel to
// placements, all placed).
struct RoomRelations {
  std::vector<EdgeCheck> edges;  // parallel to the edges given
  std::vector<ZoneCheck> zones;  // one per object that keeps a zone free
  int Satisfied() const;         // edges present and satisfied
  int Present() const;           // edges whose two objects are in the room
  int ZonesClear() const;
};
RoomRelations MeasureRelations(const std::vector<solver::ProblemObject>& objects,
                               const std::vector<solver::ObjectPlacement>& placements,
                               const std::vector<scene::SemanticEdge>& edges);

// Counts per relation type ("face_to" ... "centered", and "zone"): edges satisfied, edges measured, and
// edges lost because an object was removed.
struct RelationCount {
  int satisfied = 0;
  int measured = 0;
  int lost = 0;
};
using RelationTally = std::map<std::string, RelationCount>;
void AddToTally(const RoomRelations& relations, RelationTally& tally);
nlohmann::ordered_json TallyJson(const RelationTally& tally);
RelationTally TallyFromJson(const nlohmann::json& json);  // the inverse of TallyJson (reports, the bench)

}  // namespace villa::critic
