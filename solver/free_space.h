#pragma once
// One answer to "is this free": the signed plan clearance between convex shapes, and the obstacles of a
// floor indexed for it. The pose solver's energy asks it which boxes overlap what (E_col's pairs, which the
// rule agent reads as its culprits); the reachability check asks it whether a person (a disc) or a straight
// walk (a capsule) keeps its radius from everything (OMPL's StateValidityChecker and MotionValidator, and
// every cell of the raster). One function decides for both, so the two never disagree about "free".
//
// Frame: world plan x, y in metres; heights are world z in metres. Rings are CCW without a closing point.
#include <vector>

#include "layout/layout.h"

namespace villa::solver {

// The points within `radius` of the convex hull of `points`: one point is a disc, two a capsule (a
// straight walk of a disc), three or more a convex polygon (CCW), rounded when radius > 0.
struct PlanShape {
  std::vector<Point> points;
  double radius = 0.0;  // m, >= 0

  static PlanShape Disc(Point centre, double radius);
  static PlanShape Capsule(Point a, Point b, double radius);
  static PlanShape Polygon(Ring convex);  // convex and CCW (ConvexPieces makes any ring so)
};

// Signed clearance between two shapes (m): > 0 they are that far apart; <= 0 they touch or overlap, and
// the value is minus the depth of the overlap along the best separating axis (the separating-axis depth of
// two polygons, the distance to the nearest edge for a point inside a polygon), minus both radii.
double PlanClearance(const PlanShape& a, const PlanShape& b);

// A simple ring (CCW, any shape) as convex pieces covering it exactly: itself when convex, else triangles.
std::vector<Ring> ConvexPieces(const Ring& ring);

// Something standing on the floor: a convex plan shape between two world heights.
struct PlanObstacle {
  PlanShape shape;
  double z0 = 0.0;  // m, world height of its bottom
  double z1 = 0.0;  // m, world height of its top
  int owner = -1;   // the caller's number for it (an object, a building part, a keep-out)
};

// The obstacles of one floor and the region shapes must stay in, with a uniform grid over both so a
// query reads only what is near. Immutable after construction; queries are const and thread-safe.
class FreeSpace {
 public:
  // `region`: rings whose inside (even-odd over all of them, so a ring inside another is a hole) is where
  // shapes may be; empty: no region, only obstacles. `index_cell`: m, side of the index's cells, > 0.
  FreeSpace(std::vector<Ring> region, std::vector<PlanObstacle> obstacles, double index_cell = 0.5);

  static constexpr int kRegion = -1;  // Nearest::obstacle: the region's outside is nearest
  static constexpr int kNone = -2;    // nothing within the reach asked for

  struct Nearest {
    double clearance = 0.0;  // m, signed as PlanClearance
    int obstacle = kNone;    // index into obstacles(), kRegion or kNone
  };
  // The smallest clearance of `shape`, standing between heights z0 and z1, to the region's outside and to
  // every obstacle whose height range overlaps (z0, z1) by more than zero. Looks no farther than `reach` m
  // (>= 0): when nothing is nearer, {reach, kNone}.
  Nearest Clearance(const PlanShape& shape, double z0, double z1, double reach) const;
  // The same for obstacles only, and for the region only (kRegion or kNone in `obstacle`).
  Nearest ObstacleClearance(const PlanShape& shape, double z0, double z1, double reach) const;
  Nearest RegionClearance(const PlanShape& shape, double reach) const;
  // Every obstacle the shape overlaps (clearance < 0) between z0 and z1, by index, ascending.
  std::vector<int> Overlapping(const PlanShape& shape, double z0, double z1) const;
  // Whether a point lies inside the region (true when there is no region).
  bool InRegion(Point p) const;

  const std::vector<PlanObstacle>& obstacles() const { return obstacles_; }
  const std::vector<Ring>& region() const { return region_; }

 private:
  struct Index {
    double x0 = 0.0, y0 = 0.0, cell = 0.5;
    int nx = 0, ny = 0;
    std::vector<std::vector<int>> cells;  // item numbers per cell, row-major
  };
  void Build(Index& index, const std::vector<std::pair<Point, Point>>& boxes) const;  // item bounding boxes
  void Candidates(const Index& index, Point lo, Point hi, std::vector<int>& out) const;

  std::vector<Ring> region_;
  std::vector<std::pair<Point, Point>> edges_;  // the region's boundary segments
  std::vector<PlanObstacle> obstacles_;
  double cell_ = 0.5;
  Point lo_, hi_;  // bounds of everything indexed
  Index obstacle_index_, edge_index_;
};

}  // namespace villa::solver
