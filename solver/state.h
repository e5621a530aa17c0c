#pragma once
// The solver's working state of one room (internal to villa_solver): the objects as they stand now (the
// agent adds and removes some), where each one is, the semantic edges, and parent/child indices.
#include <string>
#include <string_view>
#include <vector>

#include "solver/box.h"
#include "solver/placement.h"
#include "solver/problem.h"

namespace villa::solver {

// An object's own frame, metric: origin at its bottom centre, axes its asset axes turned by yaw, lengths
// in metres (the asset's coordinates times the object's scale).
struct Frame {
  Point origin;
  double z = 0.0;
  double yaw = 0.0;
  double scale = 1.0;
  Point ToLocal(Point world) const;
  Point ToWorld(Point local) const;
};

struct RoomState {
  const RoomProblem* problem = nullptr;
  std::vector<ProblemObject> objects;
  std::vector<ObjectPlacement> placements;  // parallel to objects
  std::vector<SemanticEdge> edges;
  std::vector<int> parent;                  // index of the parent object, -1 for floor, wall, ceiling
  std::vector<std::vector<int>> children;

  static RoomState From(const RoomProblem& problem);
  void Reindex();
  int Find(std::string_view id) const;

  // A flat floor object (a rug, <= 3 cm high): part of the floor, others stand on it, no collisions.
  bool IsFloorCovering(int i) const;
  // i is j's parent or j is i's.
  bool ParentChild(int i, int j) const;
  bool Hung(int i) const;  // on_wall or hanging: not a V_con object
  // A garment on a hanger inside its parent's cavity that has a rail: it hangs from the rail by its hook.
  bool HangsOnRail(int i) const;
  std::vector<int> Descendants(int i) const;

  OrientedBox WorldBox(int i) const;
  Frame FrameOf(int i) const;
  // World height of the object's bottom where it rests (floor, its surface, its cavity's floor; a hanging
  // garment's bottom with its hook on the cavity's rail); only for V_con objects.
  double SupportHeight(int i) const;
  // World polygon its footprint must project into: the free floor, the parent's surface, the cavity's floor.
  Ring SupportRegion(int i) const;
  // The parent's scaled surface polygon / cavity box in the parent's frame, for the object's current choice.
  Ring LocalSupportPolygon(int i) const;

  // Moves an object and carries its descendants along rigidly.
  void SetPose(int i, const Pose& pose);
  // Removes an object, its descendants and every edge naming them; returns the removed ids.
  std::vector<std::string> Remove(int i);
};

}  // namespace villa::solver
