#pragma once
// Plane geometry that is only about drawing: where a label fits (pole of inaccessibility, rectangles in
// rings), clipping a stroke to a room, chaining wall strokes into polylines. Every question about the plan
// itself (point in polygon, distances, collinear overlaps, wall pieces, door swings) is layout/'s.
// Plain doubles in metres. Internal to render/.
#include <vector>

#include "layout/layout.h"

namespace villa::plan {

// Distance to the ring's boundary, positive inside, negative outside (layout/geometry.h's
// PointInRing and DistanceToBoundary).
double SignedDistanceToRing(Point p, const Ring& ring);

// The interior point farthest from the boundary (Mapbox polylabel: best-first search over square cells),
// within `precision` m. For a degenerate ring (< 3 points or no area) the vertex average.
Point PoleOfInaccessibility(const Ring& ring, double precision);

// Segments joined end to end into polylines: a chain runs through points where exactly two segments
// meet and stops at ends and junctions. A chain whose last point is its first is a closed loop (the
// first point is then not repeated and `closed` is set).
struct Polyline {
  std::vector<Point> points;
  bool closed = false;
};
std::vector<Polyline> ChainSegments(const std::vector<Segment>& segments, double tolerance);

// The parts of segment a-b that lie inside `ring` (even-odd), in order from a.
std::vector<Segment> ClipSegmentToRing(Point a, Point b, const Ring& ring);

// True when the axis-aligned rectangle [min, max] lies inside `ring`: its corners are inside and no
// edge of the ring crosses it.
bool RectInsideRing(Point min, Point max, const Ring& ring);

// True when the axis-aligned rectangle [min, max] and `ring` share interior points (approximately:
// a corner of one inside the other, or crossing edges).
bool RectOverlapsRing(Point min, Point max, const Ring& ring);

}  // namespace villa::plan
