// The drawing geometry under the floor plans: wall chains, clipping, label points.
#include <catch2/catch.hpp>

#include "layout/geometry.h"
#include "render/plan_geometry.h"
#include "render/plan_render.h"

using namespace villa;
using namespace villa::plan;

namespace {
// An L: 8 x 8 square with a 4 x 4 bite out of the top right... as the living room of the villa example.
const Ring kL = {{0, 0}, {8, 0}, {8, 8}, {4, 8}, {4, 12}, {0, 12}};
// A thin L whose centroid lies outside it.
const Ring kThinL = {{0, 0}, {10, 0}, {10, 1}, {1, 1}, {1, 10}, {0, 10}};
}  // namespace

TEST_CASE("wall pieces chain into loops and stop at junctions", "[geometry]") {
  const auto square = ChainSegments({{{0, 0}, {4, 0}}, {{4, 4}, {4, 0}}, {{4, 4}, {0, 4}}, {{0, 0}, {0, 4}}}, 1e-6);
  REQUIRE(square.size() == 1);
  CHECK(square[0].closed);
  CHECK(square[0].points.size() == 4);

  // A T: three chains meeting at (4, 0).
  const auto tee = ChainSegments({{{0, 0}, {4, 0}}, {{4, 0}, {8, 0}}, {{4, 0}, {4, 5}}, {{4, 5}, {4, 8}}}, 1e-6);
  REQUIRE(tee.size() == 3);
  size_t longest = 0;
  for (const Polyline& chain : tee) {
    CHECK_FALSE(chain.closed);
    longest = std::max(longest, chain.points.size());
  }
  CHECK(longest == 3);  // (4,0) - (4,5) - (4,8) joined through the degree-2 point
}

TEST_CASE("segments clip to the inside of a non-convex ring", "[geometry]") {
  const auto pieces = ClipSegmentToRing({-1, 10}, {9, 10}, kL);
  REQUIRE(pieces.size() == 1);
  CHECK(pieces[0].a.x == Approx(0));
  CHECK(pieces[0].b.x == Approx(4));
  const auto u = ClipSegmentToRing({0.5, -1}, {0.5, 11}, kThinL);
  REQUIRE(u.size() == 1);
  CHECK(u[0].a.y == Approx(0));
  CHECK(u[0].b.y == Approx(10));
  CHECK(ClipSegmentToRing({5, 5}, {9, 9}, kThinL).empty());
}

TEST_CASE("a label rectangle fits only where the room has space", "[geometry]") {
  CHECK(RectInsideRing({1, 1}, {7, 7}, kL));
  CHECK_FALSE(RectInsideRing({3, 7}, {6, 9}, kL));  // over the notch
  CHECK_FALSE(RectInsideRing({2, 2}, {9, 3}, kL));  // through the outer wall
  CHECK(RectOverlapsRing({3, 7}, {6, 9}, kL));
  CHECK_FALSE(RectOverlapsRing({5, 9}, {7, 11}, kL));
}

TEST_CASE("the label point of an L-shaped room is inside its widest part, not at the centroid", "[geometry]") {
  const Point p = RoomLabelPoint(kL);
  CHECK(SignedDistanceToRing(p, kL) > 3.9);  // the 8 x 8 part has an inscribed circle of radius 4
  CHECK(p.y < 8.0);

  const Point thin = RoomLabelPoint(kThinL);
  CHECK(PointInRing(thin, kThinL, 0));
  CHECK(SignedDistanceToRing(thin, kThinL) > 0.45);
  // The centroid of the thin L is outside it.
  double cx = 0, cy = 0, a2 = 0;
  for (size_t i = 0, j = kThinL.size() - 1; i < kThinL.size(); j = i++) {
    const double f = kThinL[j].x * kThinL[i].y - kThinL[i].x * kThinL[j].y;
    cx += (kThinL[j].x + kThinL[i].x) * f;
    cy += (kThinL[j].y + kThinL[i].y) * f;
    a2 += f;
  }
  CHECK_FALSE(PointInRing({cx / (3 * a2), cy / (3 * a2)}, kThinL, 0));

  const Ring triangle = {{10, 0}, {14, 4}, {10, 4}};
  const Point t = RoomLabelPoint(triangle);
  CHECK(SignedDistanceToRing(t, triangle) == Approx(4.0 / (2.0 + std::sqrt(2.0))).margin(0.02));
  // Degenerate input gives a point, not a crash.
  const Point line = RoomLabelPoint({{0, 0}, {2, 0}, {4, 0}});
  CHECK(line.x == Approx(2));
}
