#pragma once
// Where the solver put one object (SCENE.md "Frames and units"): world pose, uniform scale, and the
// discrete choices made for it (which wall, which surface or cavity of its parent).
#include <numbers>

namespace villa::solver {

struct Pose {
  double x = 0.0;      // footprint centre, world (m)
  double y = 0.0;
  double z = 0.0;      // world height of the object's bottom (m)
  double yaw = 0.0;    // rad, counter-clockwise from above, in (-pi, pi]
  double scale = 1.0;  // uniform scale of the asset
};

struct ObjectPlacement {
  Pose pose;
  int wall = -1;     // against_wall / on_wall: index into RoomProblem::walls
  int surface = -1;  // ontop an object: index into the parent's support surfaces
  int cavity = -1;   // inside: index into the parent's cavities
  bool placed = false;
  // m above its parent's support surface (issue 28): a simulator rests it on the parent's collision hull,
  // which over an imported model's non-convex piece stands a few mm above the surface read off the mesh.
  double lift = 0.0;
};

// An angle wrapped to (-pi, pi] (yaws drift without it: 9081 degrees was seen in a trial).
inline double WrapAngle(double a) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  while (a > std::numbers::pi) a -= kTwoPi;
  while (a <= -std::numbers::pi) a += kTwoPi;
  return a;
}

}  // namespace villa::solver
