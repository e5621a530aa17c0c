// Exact integer polygon operations of the partitioner (partitioner/geometry.h).
#include <catch2/catch.hpp>

#include <algorithm>

#include "partitioner/geometry.h"

using namespace villa::partition;

namespace {
int64_t TotalTwiceArea(const std::vector<IRing>& rings) {
  int64_t sum = 0;
  for (const IRing& r : rings) sum += TwiceArea(r);
  return sum;
}
// A U open at the top: 10 x 8 with a 4 x 5 notch from the top middle.
IRing UShape() { return {{0, 0}, {10, 0}, {10, 8}, {7, 8}, {7, 3}, {3, 3}, {3, 8}, {0, 8}}; }
}  // namespace

TEST_CASE("SplitRing of a rectangle gives two rectangles of the exact areas", "[partitioner][geometry]") {
  const IRing rect = BoxRing({0, 0, 10, 6});
  std::vector<IRing> low, high;
  REQUIRE(SplitRing(rect, Axis::kX, 4, &low, &high));
  REQUIRE(low.size() == 1);
  REQUIRE(high.size() == 1);
  CHECK(TwiceArea(low[0]) == 2 * 4 * 6);
  CHECK(TwiceArea(high[0]) == 2 * 6 * 6);
  CHECK(BoundingBox(low[0]).max_x == 4);
  CHECK(BoundingBox(high[0]).min_x == 4);
  low.clear(), high.clear();
  REQUIRE(SplitRing(rect, Axis::kY, 2, &low, &high));
  REQUIRE(low.size() == 1);
  REQUIRE(high.size() == 1);
  CHECK(BoundingBox(low[0]).max_y == 2);
  CHECK(TwiceArea(high[0]) == 2 * 10 * 4);
}

TEST_CASE("SplitRing across the arms of a U gives separate connected parts", "[partitioner][geometry]") {
  const IRing u = UShape();
  std::vector<IRing> low, high;
  // y = 5 cuts both arms above the base: two parts above, one below.
  REQUIRE(SplitRing(u, Axis::kY, 5, &low, &high));
  CHECK(low.size() == 1);
  CHECK(high.size() == 2);
  CHECK(TotalTwiceArea(low) + TotalTwiceArea(high) == TwiceArea(u));
  for (const IRing& r : high) CHECK(TwiceArea(r) == 2 * 3 * 3);
  for (const IRing& r : low) CHECK(IsSimple(r));
}

TEST_CASE("SplitRing along an edge of the notch keeps the parts simple", "[partitioner][geometry]") {
  const IRing u = UShape();
  std::vector<IRing> low, high;
  REQUIRE(SplitRing(u, Axis::kY, 3, &low, &high));  // the notch's floor lies on the line
  REQUIRE(low.size() == 1);
  CHECK(TwiceArea(low[0]) == 2 * 10 * 3);
  CHECK(high.size() == 2);
  CHECK(TotalTwiceArea(low) + TotalTwiceArea(high) == TwiceArea(u));
}

TEST_CASE("SplitRing refuses a line crossing a slanted edge off the grid", "[partitioner][geometry]") {
  // A chamfer from (0, 2) to (4, 0): slope 1:2.
  const IRing ring{{4, 0}, {10, 0}, {10, 6}, {0, 6}, {0, 2}};
  CHECK(SplitIsOnGrid(ring, Axis::kX, 2));   // crosses at (2, 1)
  CHECK_FALSE(SplitIsOnGrid(ring, Axis::kX, 1));  // would cross at (1, 1.5)
  std::vector<IRing> low, high;
  CHECK_FALSE(SplitRing(ring, Axis::kX, 1, &low, &high));
  CHECK(low.empty());
  REQUIRE(SplitRing(ring, Axis::kX, 2, &low, &high));
  CHECK(TotalTwiceArea(low) + TotalTwiceArea(high) == TwiceArea(ring));
  CHECK(std::find(low[0].begin(), low[0].end(), IPoint{2, 1}) != low[0].end());
}

TEST_CASE("SplitRing along a diagonal cuts a corner off an octagon", "[partitioner][geometry]") {
  // A 10 x 10 octagon with 3-unit 45-degree corners; the line x + y = 7 runs from (7, 0) to (0, 7).
  const IRing oct{{3, 0}, {7, 0}, {10, 3}, {10, 7}, {7, 10}, {3, 10}, {0, 7}, {0, 3}};
  const ILine diag{1, 1, 7};
  REQUIRE(SplitIsOnGrid(oct, diag));
  CHECK_FALSE(SplitIsOnGrid(oct, ILine{1, 1, 10}));  // would cross the chamfers at (1.5, 8.5) and (8.5, 1.5)
  std::vector<IRing> low, high;
  REQUIRE(SplitRing(oct, diag, &low, &high));
  REQUIRE(low.size() == 1);
  REQUIRE(high.size() == 1);
  CHECK(TwiceArea(low[0]) == 2 * 20);   // the corner triangle of 24.5 less the chamfer's 4.5
  CHECK(TwiceArea(high[0]) == 2 * 62);
  for (const IPoint& p : low[0]) CHECK(p.x + p.y <= 7);
  for (const IPoint& p : high[0]) CHECK(p.x + p.y >= 7);
  CHECK(IsSimple(low[0]));
  CHECK(IsSimple(high[0]));
  CHECK(low[0].size() == 4);
  // The shared edge is the cut, from (7, 0) to (0, 7).
  const auto shared = SharedSegments(low[0], high[0]);
  REQUIRE(shared.size() == 1);
  CHECK(std::abs(shared[0].a.x - shared[0].b.x) == 7);
}

TEST_CASE("SplitRing along a line of any slope refuses off-grid crossings", "[partitioner][geometry]") {
  const IRing rect = BoxRing({0, 0, 10, 6});
  // 2x - y = 4 crosses y = 0 at x = 2 and y = 6 at x = 5: on the grid.
  const ILine steep{2, -1, 4};
  REQUIRE(SplitIsOnGrid(rect, steep));
  std::vector<IRing> low, high;
  REQUIRE(SplitRing(rect, steep, &low, &high));
  REQUIRE(low.size() == 1);
  REQUIRE(high.size() == 1);
  CHECK(TwiceArea(low[0]) == 2 * 21);  // the trapezoid (0,0)-(2,0)-(5,6)-(0,6): (2 + 5) / 2 * 6
  CHECK(TotalTwiceArea(low) + TotalTwiceArea(high) == TwiceArea(rect));
  // 2x - y = 5 crosses y = 0 at x = 2.5: refused, outputs untouched.
  const ILine off{2, -1, 5};
  CHECK_FALSE(SplitIsOnGrid(rect, off));
  std::vector<IRing> l2, h2;
  CHECK_FALSE(SplitRing(rect, off, &l2, &h2));
  CHECK(l2.empty());
  // LineThrough gives the same line, its inside on the high side of a counter-clockwise edge.
  const ILine through = LineThrough({2, 0}, {5, 6});
  CHECK((through.a == -2 && through.b == 1 && through.k == -4));
  CHECK(LineValue(through, {9, 1}) < through.k);  // right of (2,0) -> (5,6): the low side
  CHECK(LineValue(through, {0, 5}) > through.k);
}

TEST_CASE("UnionTiles merges tiles with T-junctions into one outline", "[partitioner][geometry]") {
  // A 4 x 4 square beside two 4 x 2 tiles (T-junction at (4, 2)).
  const std::vector<IRing> tiles{BoxRing({0, 0, 4, 4}), BoxRing({4, 0, 8, 2}), BoxRing({4, 2, 8, 4})};
  const std::vector<IRing> merged = UnionTiles(tiles);
  REQUIRE(merged.size() == 1);
  CHECK(merged[0].size() == 4);
  CHECK(TwiceArea(merged[0]) == 2 * 32);
}

TEST_CASE("SubtractInside cuts a square on the boundary out of a ring with slanted edges", "[partitioner][geometry]") {
  const IRing ring{{4, 0}, {20, 0}, {20, 12}, {0, 12}, {0, 2}};  // chamfered corner
  std::vector<IRing> out;
  REQUIRE(SubtractInside(ring, BoxRing({12, 0, 20, 8}), &out));
  REQUIRE(out.size() == 1);
  CHECK(TwiceArea(out[0]) == TwiceArea(ring) - 2 * 64);
  CHECK(IsSimple(out[0]));
  // Not inside: refused.
  CHECK_FALSE(SubtractInside(ring, BoxRing({16, 8, 24, 16}), &out));
  // Strictly inside: the result would have a hole, refused.
  CHECK_FALSE(SubtractInside(ring, BoxRing({8, 4, 10, 6}), &out));
}

TEST_CASE("SharedSegments finds the common wall, and none across a corner", "[partitioner][geometry]") {
  const IRing a = BoxRing({0, 0, 4, 4});
  const IRing b = BoxRing({4, 2, 8, 8});
  const auto shared = SharedSegments(a, b);
  REQUIRE(shared.size() == 1);
  CHECK(shared[0].a.x == 4);
  CHECK(shared[0].b.x == 4);
  CHECK(std::min(shared[0].a.y, shared[0].b.y) == 2);
  CHECK(std::max(shared[0].a.y, shared[0].b.y) == 4);
  CHECK(SharedSegments(a, BoxRing({4, 4, 8, 8})).empty());
}

TEST_CASE("MinWidth measures thin arms through the interior only", "[partitioner][geometry]") {
  CHECK(MinWidth(BoxRing({0, 0, 10, 3})) == Approx(3.0));
  // An L with a 1-unit arm.
  const IRing thin{{0, 0}, {10, 0}, {10, 1}, {1, 1}, {1, 10}, {0, 10}};
  CHECK(MinWidth(thin) == Approx(1.0));
  CHECK(NarrowerThan(thin, 1.5));
  CHECK_FALSE(NarrowerThan(thin, 0.5));
  // A V bite 2 wide into a 10 x 10 square: the gap across the bite is outside and does not count.
  const IRing bite{{0, 0}, {4, 0}, {5, 2}, {6, 0}, {10, 0}, {10, 10}, {0, 10}};
  CHECK(MinWidth(bite) == Approx(5.0));  // the apex to the sides, not the 1-2 units across the bite
}

TEST_CASE("IsSimple rejects self-intersections and touching edges", "[partitioner][geometry]") {
  CHECK(IsSimple(UShape()));
  CHECK_FALSE(IsSimple({{0, 0}, {4, 4}, {4, 0}, {0, 4}}));              // bow tie
  CHECK_FALSE(IsSimple({{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}}));      // vertex on an edge
  CHECK(HasAngledEdge({{0, 0}, {4, 0}, {4, 4}, {1, 4}, {0, 2}}));
  CHECK_FALSE(HasAngledEdge(UShape()));
}
