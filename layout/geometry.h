#pragma once
// 2D helpers on the layout's plain types (Point, Segment, Ring), shared by the validator, the topology and
// anyone who needs the same answers: shared boundaries between rooms, a segment's length on a room's
// boundary, overlap areas, floor footprints, room widths. Units are metres; rings are counter-clockwise
// without a repeated closing point (a clockwise ring is accepted and treated as its reverse).
// Boost.Geometry stays inside geometry.cpp.
#include <string>
#include <utility>
#include <vector>

#include "layout/layout.h"

namespace villa {

struct Box2 {
  double min_x = 0, min_y = 0, max_x = 0, max_y = 0;
  double width() const { return max_x - min_x; }
  double height() const { return max_y - min_y; }
  // True when the boxes, each grown by `margin`, share a point.
  bool Touches(const Box2& other, double margin) const {
    return min_x <= other.max_x + margin && other.min_x <= max_x + margin && min_y <= other.max_y + margin &&
           other.min_y <= max_y + margin;
  }
};
Box2 BoundingBox(const Ring& ring);
Box2 BoundingBox(const Segment& segment);
// The box around every room of `level` (all zero when it has none), and around every room of the layout.
Box2 LevelBounds(const Layout& layout, int level);
Box2 LayoutBounds(const Layout& layout);

double Distance(const Point& a, const Point& b);
double PointSegmentDistance(const Point& p, const Segment& s);
// Largest distance from a point of `s` to `target` (the Hausdorff distance from s to target): how far s is
// "off" the target segment.
double SegmentOffDistance(const Segment& s, const Segment& target);

// A closed interval [from, to] of a segment's arc length, in m from its first point.
using Interval = std::pair<double, double>;
// Sorts and merges overlapping intervals; drops those not longer than `tolerance`.
std::vector<Interval> MergeIntervals(std::vector<Interval> intervals, double tolerance);
double TotalLength(const std::vector<Interval>& intervals);
std::vector<Interval> IntersectIntervals(const std::vector<Interval>& a, const std::vector<Interval>& b,
                                         double tolerance);
// The parts of [0, length] not covered by `covered` (sorted and merged, as MergeIntervals gives them),
// dropping gaps not longer than `tolerance`.
std::vector<Interval> ComplementIntervals(const std::vector<Interval>& covered, double length, double tolerance);

// The part of `s` that lies on `edge` (both endpoints of the overlap within `tolerance` of the other's
// line), as an interval of s's arc length; empty when they are not collinear or overlap by <= tolerance.
std::vector<Interval> CollinearOverlap(const Segment& s, const Segment& edge, double tolerance);
// The same without allocating: true and the interval in *out when they overlap.
bool CollinearOverlapInterval(const Segment& s, const Segment& edge, double tolerance, Interval* out);
// The parts of `s` that lie on any of `segments` (CollinearOverlap's test), merged, as intervals of s's
// arc length.
std::vector<Interval> IntervalsOnSegments(const Segment& s, const std::vector<Segment>& segments, double tolerance);
// True when `segments` together cover all of `s` (one merged interval from its start to its end, within
// tolerance); false for a segment not longer than the tolerance.
bool SegmentsCover(const std::vector<Segment>& segments, const Segment& s, double tolerance);
// The part of `s` between arc lengths along.first and along.second (PointAt at both ends).
Segment SubSegment(const Segment& s, const Interval& along);
// The parts of `s` that lie on the boundary of `ring`, merged, as intervals of s's arc length.
std::vector<Interval> IntervalsOnBoundary(const Segment& s, const Ring& ring, double tolerance);
// Length of `s` lying on the boundary of `ring`.
double LengthOnBoundary(const Segment& s, const Ring& ring, double tolerance);
// True when the boundary of `ring` holds all of `s`: the parts of s on its edges add up to s's length
// (within tolerance), so a segment running across a collinear corner lies on the ring as much as one on
// a single edge. The test of rule 3 (RoomsAlongSegment's `holding`); false for a segment not longer than
// the tolerance.
bool RingHoldsSegment(const Ring& ring, const Segment& s, double tolerance);
// The point of `s` at arc length t.
Point PointAt(const Segment& s, double t);

// Pieces of boundary two rings share: collinear, overlapping edge parts longer than `tolerance`.
std::vector<Segment> SharedBoundaries(const Ring& a, const Ring& b, double tolerance);
double SharedBoundaryLength(const Ring& a, const Ring& b, double tolerance);

// Polygon measures.
Point Centroid(const Ring& ring);  // area centroid
bool IsConvex(const Ring& ring);   // no reflex corner (collinear corners allowed)
bool IsAxisAlignedBox(const Ring& ring, double tolerance);
// The ring without corners whose edges continue straight on (within tolerance).
Ring WithoutCollinearCorners(const Ring& ring, double tolerance);
// Same point set: equal vertex lists up to a cyclic shift and collinear corners, within tolerance.
bool SameRing(const Ring& a, const Ring& b, double tolerance);
// Inside or on the boundary (within tolerance). The one point-in-polygon of villa: even-odd crossings, so
// with tolerance 0 a point exactly on the boundary may go either way (what drawing and probing want).
bool PointInRing(const Point& p, const Ring& ring, double tolerance);
// On the boundary (within tolerance of an edge).
bool PointOnBoundary(const Point& p, const Ring& ring, double tolerance);
// Distance from p to the nearest edge of `ring` (m); infinity for an empty ring.
double DistanceToBoundary(const Point& p, const Ring& ring);

// Empty when `ring` is a valid simple polygon with positive area; otherwise why not ("self-intersecting",
// "has spikes", "has fewer than 3 distinct corners", "has zero area", ...). Boost.Geometry's is_valid.
std::string RingProblem(const Ring& ring);

// Area of the intersection of two simple polygons (exact clipping when one is convex, Boost.Geometry when
// both are not). Meant for valid rings (RingProblem empty); for two invalid non-convex rings it may be 0.
double IntersectionArea(const Ring& a, const Ring& b);

// The footprint of a floor from its rooms by polygon union (Boost.Geometry): each polygon of the union
// with its holes. Rooms may overlap or not touch at all; a floor that tiles properly gives exactly one
// polygon with no holes. Rings should be valid (RingProblem empty); one Boost cannot merge is left out.
struct PolygonWithHoles {
  Ring outer;
  std::vector<Ring> holes;  // counter-clockwise like every Ring here; subtract their areas
};
std::vector<PolygonWithHoles> UnionOfRings(const std::vector<Ring>& rings);

// The exterior boundary of a set of non-overlapping rooms without polygon booleans: every room edge part
// not shared with another room, chained into closed rings. Outer rings come out counter-clockwise
// (positive area), holes clockwise (negative area). Each piece of a ring remembers its room. The pieces
// of rings flagged in `subtract` are reversed before chaining: a ring inside the others then cuts its
// area out of them (footprint.h's FootprintOf uses this for roof terraces).
//
// Where several pieces start at one point (a pinch), `pinch` decides how the chain goes on:
//   kKeepHolesApart   the first piece counter-clockwise from the way back: a hole touching the outline at
//                     a point still comes out as its own ring (the validator's rule 1).
//   kKeepRegionsApart the sharpest left turn among the pieces not used yet: two regions touching at a point
//                     come out as two simple rings (what a mesh needs).
struct BoundaryRing {
  std::vector<Segment> pieces;
  std::vector<int> owners;  // index into the input rooms for each piece
  double signed_area = 0;
};
struct ExteriorBoundary {
  std::vector<Segment> pieces;  // every exterior piece
  std::vector<int> owners;
  std::vector<BoundaryRing> rings;
  bool closed = true;  // false when a piece could not be chained (rooms overlap or are broken)
};
enum class PinchRule { kKeepHolesApart, kKeepRegionsApart };
ExteriorBoundary ExteriorBoundaryOf(const std::vector<Ring>& rooms, double tolerance,
                                    const std::vector<bool>& subtract = {},
                                    PinchRule pinch = PinchRule::kKeepHolesApart);

// Width of a room, the narrowest of two measures (m):
//  - the minimum caliper width of its convex hull (a thin sliver, a thin parallelogram);
//  - for a non-convex room, the distance between two facing anti-parallel edges (within 1 degree) whose
//    projections overlap by more than tolerance and with the strip between them inside the room
//    (a thin arm of an L or a U).
// An acute corner alone does not make a room narrow: a triangle is as wide as its smallest height.
double RoomWidth(const Ring& ring, double tolerance);

// Side lengths of a rectangle (width along its first edge, then the other), or {0, 0} when `ring` is not a
// rectangle within tolerance.
std::pair<double, double> RectangleSides(const Ring& ring, double tolerance);

}  // namespace villa
