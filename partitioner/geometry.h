#pragma once
// Exact integer polygon operations of the partitioner. Coordinates are whole grid units (1 unit = the
// grid, 0.5 m by default), so every vertex is on the grid by construction and no operation rounds:
// splitting by an axis-aligned line is accepted only where it crosses slanted edges at grid points.
// Rings are simple, counter-clockwise, without a repeated closing point and (after Normalize) without
// collinear or duplicate consecutive vertices.
#include <cstdint>
#include <vector>

namespace villa::partition {

struct IPoint {
  int64_t x = 0;
  int64_t y = 0;
  friend bool operator==(const IPoint&, const IPoint&) = default;
};
using IRing = std::vector<IPoint>;

struct ISegment {
  IPoint a;
  IPoint b;
};

struct IBox {
  int64_t min_x = 0, min_y = 0, max_x = 0, max_y = 0;
  int64_t width() const { return max_x - min_x; }
  int64_t height() const { return max_y - min_y; }
};

enum class Axis { kX, kY };  // kX: the vertical line x = k; kY: the horizontal line y = k

inline int64_t Cross(IPoint o, IPoint a, IPoint b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

// Twice the signed area (positive for counter-clockwise).
int64_t TwiceArea(const IRing& ring);
IBox BoundingBox(const IRing& ring);
IRing BoxRing(const IBox& box);  // counter-clockwise from (min_x, min_y)
// Drops repeated and collinear consecutive vertices (including spikes).
IRing Normalize(const IRing& ring);
// True when no two non-adjacent edges touch and adjacent edges meet only at their common vertex.
bool IsSimple(const IRing& ring);
// True when some edge is neither horizontal nor vertical.
bool HasAngledEdge(const IRing& ring);
// True when some corner's inside angle is under 45 degrees (exact: integer dot and cross products).
bool HasSharpCorner(const IRing& ring);
// 1 inside, 0 on the boundary, -1 outside, exactly (integer grid units, no tolerance: the partitioner's
// tiling must be exact). Plans in metres use layout/geometry.h's PointInRing.
int PointInRing(const IRing& ring, IPoint point);

// The line a*x + b*y = k, (a, b) primitive (gcd 1): an axis line, a 45-degree diagonal, or a line parallel
// to any slanted edge with grid end points. Its low side is a*x + b*y <= k.
struct ILine {
  int64_t a = 1, b = 0, k = 0;
};
ILine AxisLine(Axis axis, int64_t k);
// The line through p and q (p != q). Its normal (a, b) points left of p -> q, so the inside of a
// counter-clockwise ring's edge p -> q is on the line's high side.
ILine LineThrough(IPoint p, IPoint q);
// a*x + b*y of a point (which side of the line it is on).
inline int64_t LineValue(const ILine& line, IPoint p) { return line.a * p.x + line.b * p.y; }
// The lines through the ring's slanted edges (neither horizontal nor vertical), one an edge, in ring order.
std::vector<ILine> SlantedLines(const IRing& ring);

// True when the line (axis, k) crosses every edge it cuts at a grid point (so a split is exact).
bool SplitIsOnGrid(const IRing& ring, Axis axis, int64_t k);
bool SplitIsOnGrid(const IRing& ring, const ILine& line);
// Splits `ring` by the line (axis, k): `low` gets the connected parts with coordinate <= k, `high` those
// >= k (each part a normalized simple ring). False (outputs untouched) when a crossing is off the grid.
bool SplitRing(const IRing& ring, Axis axis, int64_t k, std::vector<IRing>* low, std::vector<IRing>* high);
// The same for any line: a unimodular map (integer, determinant 1, so grid points stay grid points and
// orientation is kept) turns it into a vertical line, the ring is split there and the parts mapped back.
// `low` gets the parts with a*x + b*y <= k.
bool SplitRing(const IRing& ring, const ILine& line, std::vector<IRing>* low, std::vector<IRing>* high);
// The union of tiles that meet only along edges (T-junctions allowed): boundary loops after cancelling
// shared edges. One counter-clockwise ring for a simply connected union; a hole gives a clockwise ring.
std::vector<IRing> UnionTiles(const std::vector<IRing>& tiles);
// ring minus the axis-aligned box, as connected rings. False when a cut would be off the grid or the
// result has a hole.
bool SubtractBox(const IRing& ring, const IBox& box, std::vector<IRing>* out);

// ring minus `inner`, a ring lying inside it (touching its boundary allowed): boundary edges of both
// (inner's reversed) with coincident opposite parts cancelled. Unlike SubtractBox no line is extended
// across the ring, so slanted edges elsewhere do not matter. False when `inner` is not inside `ring`
// or the result has a hole (inner touches the boundary nowhere).
bool SubtractInside(const IRing& ring, const IRing& inner, std::vector<IRing>* out);

// The shared boundary of two rings that do not overlap: their collinear edge overlaps of positive length,
// each given in `a`'s direction.
std::vector<ISegment> SharedSegments(const IRing& a, const IRing& b);
// Smallest distance between two non-adjacent edges (in units; a ring with fewer than 4 edges: the
// smallest altitude). A room narrower than this is a corridor sliver.
double MinWidth(const IRing& ring);
// MinWidth(ring) < width, faster (stops at the first narrow place, skips far edge pairs).
bool NarrowerThan(const IRing& ring, double width);
// Centroid (units, not rounded).
void Centroid(const IRing& ring, double* x, double* y);

int64_t Gcd(int64_t a, int64_t b);

}  // namespace villa::partition
