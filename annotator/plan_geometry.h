#pragma once
// Plan geometry the annotator needs beyond the topology module: which stretches of a room's outline are
// exterior (on the floor's footprint boundary) or shared with one neighbour, and where a 1D element sits.
// Units are metres; rooms tile each floor (FORMAT.md rule 1), so an edge stretch not shared with another
// room of the level lies on the footprint's exterior boundary.
#include <vector>

#include "layout/layout.h"

namespace villa::annotator {

// A straight stretch of a room's outline.
struct Stretch {
  Segment segment;
  double length() const { return Length(segment); }
};

// True when `segment` lies on the outline of `ring` (both ends on one edge, collinear), within `tol`.
bool SegmentOnRing(const Segment& segment, const Ring& ring, double tol = 1e-6);

// The parts of room `room`'s outline that no other room of its level shares: its exterior walls.
std::vector<Stretch> ExteriorStretches(const Layout& layout, int room, double tol = 1e-6);

// The parts of room `a`'s outline shared with room `b` (same level): the wall between them.
std::vector<Stretch> SharedStretches(const Layout& layout, int a, int b, double tol = 1e-6);

// Indices of the rooms of element `element`'s level whose outline holds it.
std::vector<int> RoomsHolding(const Layout& layout, const Element& element, double tol = 1e-6);

// Area-weighted centroid of a simple polygon (m).
Point Centroid(const Ring& ring);

// Point-in-polygon (even-odd); points on the outline count as inside.
bool PointInRing(const Point& point, const Ring& ring, double tol = 1e-9);

// Axis-aligned bounds of all rooms on `level` (min x, min y, max x, max y).
struct Bounds {
  double min_x = 0, min_y = 0, max_x = 0, max_y = 0;
  double width() const { return max_x - min_x; }
  double height() const { return max_y - min_y; }
};
Bounds LevelBounds(const Layout& layout, int level);
Bounds LayoutBounds(const Layout& layout);

}  // namespace villa::annotator
