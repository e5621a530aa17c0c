#include <catch2/catch.hpp>

#include "mesh/triangulate.h"

using namespace villa;

namespace {

double TriangulatedArea(const Ring& outer, const std::vector<Ring>& holes, bool* all_ccw) {
  std::vector<Point> points = outer;
  for (const Ring& h : holes) points.insert(points.end(), h.begin(), h.end());
  double area = 0.0;
  *all_ccw = true;
  for (const auto& t : TriangulatePolygon(outer, holes)) {
    double a = SignedArea({points[t[0]], points[t[1]], points[t[2]]});
    if (a < 0.0) *all_ccw = false;
    area += a;
  }
  return area;
}

}  // namespace

TEST_CASE("an L-shaped room triangulates to its own area, every triangle counter-clockwise") {
  Ring l = {{0, 0}, {6, 0}, {6, 3}, {3, 3}, {3, 7}, {0, 7}};
  bool ccw = false;
  CHECK(TriangulatedArea(l, {}, &ccw) == Approx(Area(l)));
  CHECK(ccw);
  CHECK(TriangulatePolygon(l).size() == 4);
}

TEST_CASE("a clockwise ring is reoriented, collinear points are kept out of the triangles' area error") {
  Ring cw = {{0, 0}, {0, 4}, {2, 4}, {4, 4}, {4, 0}, {2, 0}};
  bool ccw = false;
  CHECK(TriangulatedArea(cw, {}, &ccw) == Approx(16.0));
  CHECK(ccw);
}

TEST_CASE("a slab with a stair hole: area is the outer minus the hole") {
  Ring outer = {{0, 0}, {14, 0}, {14, 6}, {12, 10}, {0, 10}};
  Ring hole = {{0.5, 0.5}, {3.5, 0.5}, {3.5, 3.0}, {0.5, 3.0}};
  bool ccw = false;
  CHECK(TriangulatedArea(outer, {hole}, &ccw) == Approx(Area(outer) - Area(hole)));
  CHECK(ccw);
}

TEST_CASE("two holes and a notch, as on a wall face with a door and two windows") {
  // Elevation of a wall: door notch in the bottom edge, two window holes.
  Ring outer = {{0, 0}, {1, 0}, {1, 2.1}, {2, 2.1}, {2, 0}, {6, 0}, {6, 2.6}, {0, 2.6}};
  Ring w1 = {{2.5, 0.9}, {3.5, 0.9}, {3.5, 2.1}, {2.5, 2.1}};
  Ring w2 = {{4, 0.9}, {5.5, 0.9}, {5.5, 2.1}, {4, 2.1}};
  bool ccw = false;
  CHECK(TriangulatedArea(outer, {w1, w2}, &ccw) == Approx(Area(outer) - Area(w1) - Area(w2)));
  CHECK(ccw);
}

TEST_CASE("degenerate input gives no triangles") {
  CHECK(TriangulatePolygon({{0, 0}, {1, 0}}).empty());
  CHECK(TriangulatePolygon({{0, 0}, {1, 0}, {2, 0}}).empty());
}
