#pragma once
// Plane geometry the floor-plan drawing needs: where walls run, which parts of a room's edge are shared
// with a neighbour, whether an element lies on a wall, where a label fits. Plain doubles in metres;
// tolerances are explicit. Internal to render/ (not a general geometry library: the validator has its
// own, exact rules in layout/validate.cpp).
#include <vector>

#include "layout/layout.h"

namespace villa::plan {

// A stretch [lo, hi] of a segment, measured in metres from its first point.
struct Interval {
  double lo = 0.0;
  double hi = 0.0;
};

double Distance(Point a, Point b);
double PointSegmentDistance(Point p, Point a, Point b);

// Even-odd rule; points on the boundary may go either way.
bool PointInRing(Point p, const Ring& ring);
// Distance to the ring's boundary, positive inside, negative outside.
double SignedDistanceToRing(Point p, const Ring& ring);

// The interior point farthest from the boundary (Mapbox polylabel: best-first search over square cells),
// within `precision` m. For a degenerate ring (< 3 points or no area) the vertex average.
Point PoleOfInaccessibility(const Ring& ring, double precision);

// The edges of a ring, in order, closing edge included.
std::vector<Segment> RingEdges(const Ring& ring);

// The stretches of `s` that overlap a segment of `others` lying on the same line (both its ends within
// `tolerance` of the line through `s`), merged and sorted.
std::vector<Interval> CollinearOverlaps(const Segment& s, const std::vector<Segment>& others, double tolerance);

// The parts of [0, length] not covered by `covered` (sorted, merged), dropping parts shorter than `min_length`.
std::vector<Interval> Complement(const std::vector<Interval>& covered, double length, double min_length);

// The sub-segment of `s` for a stretch of it.
Segment SubSegment(const Segment& s, const Interval& stretch);

// True when `s` lies, within `tolerance`, on the union of the collinear segments of `by`.
bool CoveredBy(const Segment& s, const std::vector<Segment>& by, double tolerance);

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
