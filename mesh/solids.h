#pragma once
// Closed solids the building is made of: prisms over plan polygons, solids extruded from a vertical
// profile (stair flights) and straight wall pieces with openings cut through them.
#include <vector>

#include "mesh/mesh.h"
#include "layout/layout.h"

namespace villa {

// `outer` (CCW) with `holes`, from z0 up to z1 > z0: a closed prism.
TriangleMesh ExtrudePlan(const Ring& outer, const std::vector<Ring>& holes, double z0, double z1);

// A vertical profile, ring in (a, z) where a runs along `along` (unit, plan) from `origin`, extruded
// across from w0 to w1 along `across` (unit, plan, perpendicular to `along`): a closed solid.
TriangleMesh ExtrudeProfile(const Ring& profile, Point origin, Point along, Point across, double w0, double w1);

// The local frame of a straight wall: s runs along `direction` from `origin` (a point of the
// centreline), q along `normal` (= direction rotated +90 degrees); the faces are q = +-thickness/2.
struct WallFrame {
  Point origin;
  Point direction;
  Point normal;
  double thickness = 0.0;
  Point ToPlan(double s, double q) const {
    return {origin.x + direction.x * s + normal.x * q, origin.y + direction.y * s + normal.y * q};
  }
  double S(Point p) const { return (p.x - origin.x) * direction.x + (p.y - origin.y) * direction.y; }
  double Q(Point p) const { return (p.x - origin.x) * normal.x + (p.y - origin.y) * normal.y; }
};

// An opening through a wall: s in [s0, s1] along the wall, z in [z0, z1] (absolute heights).
struct WallOpening {
  double s0 = 0.0;
  double s1 = 0.0;
  double z0 = 0.0;
  double z1 = 0.0;
};

// The range of s over which the wall piece `plan` has its full cross-section (both faces present):
// openings must lie inside it. Empty (lo >= hi) when `plan` has not exactly one edge on each face.
struct SRange {
  double lo = 0.0;
  double hi = 0.0;
};
SRange FullSection(const Ring& plan, const WallFrame& frame);

// A wall piece: plan polygon `plan` (CCW; two of its edges on the faces q = +-t/2, the others its end
// chains) from zb to zt, with `openings` (disjoint, sorted by s, inside FullSection, z1 < zt; z0 == zb
// for a door) cut through. One closed solid.
TriangleMesh WallSolid(const Ring& plan, const WallFrame& frame, double zb, double zt,
                       const std::vector<WallOpening>& openings);

}  // namespace villa
