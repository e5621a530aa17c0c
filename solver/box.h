#pragma once
// Upright oriented boxes in the plan (the optimiser's proxies and the E_col of SCENE.md), plain doubles.
// A box is a rectangle (centre, yaw, half extents along its own x and y) swept from z0 to z1 (m).
#include <array>
#include <vector>

#include "layout/layout.h"

namespace villa::solver {

struct OrientedBox {
  Point c;
  double yaw = 0.0;  // rad: the box's x axis is (cos yaw, sin yaw)
  double hx = 0.0;   // half extents (m)
  double hy = 0.0;
  double z0 = 0.0;
  double z1 = 0.0;

  Point U() const;  // unit x axis
  Point V() const;  // unit y axis (U turned +90 degrees): an object's back (SCENE.md)
  Point Front() const;  // -V: the way an object faces
  Point Local(Point p) const;  // p in the box's frame (x along U, y along V)
  Ring Footprint() const;  // the four corners, CCW
  bool ContainsPlan(Point p, double tolerance = 0.0) const;
};

// Separating-axis depth in plan: > 0 the footprints overlap by that much along the best axis, < 0 they are
// apart (minus the widest gap along a face normal).
double PlanDepth(const OrientedBox& a, const OrientedBox& b);
// The gap between two footprints (m, > 0 apart, < 0 overlapping): -PlanDepth.
inline double PlanGap(const OrientedBox& a, const OrientedBox& b) { return -PlanDepth(a, b); }
// Distance (m) from a point to a footprint, 0 inside.
double DistanceToBox(const OrientedBox& box, Point p);
// Overlap of the z ranges (m, negative when apart).
double HeightOverlap(const OrientedBox& a, const OrientedBox& b);
// Volume of the intersection of two upright boxes (m3).
double OverlapVolume(const OrientedBox& a, const OrientedBox& b);
// Area of `subject` (any simple polygon) inside the convex CCW polygon `clip` (m2).
double ClippedArea(const Ring& subject, const Ring& clip);
// The reflex (inner-corner) vertices of a CCW polygon.
std::vector<Point> ReflexVertices(const Ring& ring);

}  // namespace villa::solver
