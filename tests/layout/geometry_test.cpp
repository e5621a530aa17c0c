// The segment-based geometry of the validator checked against Boost.Geometry on many generated cases:
// random guillotine tilings (the partitioner's kind of floor), the same with a room taken out (a hole, a
// notch or two pieces), random rings (the fast validity test never accepts what Boost rejects), and
// random garbage layouts (the validator reports, never crashes).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include <boost/geometry.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>

#include "layout/geometry.h"
#include "layout/metrics.h"
#include "test_support.h"

using namespace villa;
using namespace villa::test;

namespace {

// Own uniform helpers: std::*_distribution differs between standard libraries.
double Uniform(std::mt19937_64& rng, double lo, double hi) { return lo + (hi - lo) * (rng() >> 11) * 0x1.0p-53; }
int UniformInt(std::mt19937_64& rng, int lo, int hi) { return lo + static_cast<int>(rng() % static_cast<unsigned>(hi - lo + 1)); }
double Grid(double v) { return std::round(v * 4) / 4; }  // quarter metres, exact in binary

// Splits a box recursively (axis-aligned cuts on a 0.25 m grid, parts at least 1.5 m) into `target` rooms.
std::vector<Ring> Guillotine(std::mt19937_64& rng, int target) {
  struct Cell {
    double x0, y0, x1, y1;
  };
  std::vector<Cell> cells{{0, 0, Grid(Uniform(rng, 8, 16)), Grid(Uniform(rng, 6, 12))}};
  for (int guard = 0; static_cast<int>(cells.size()) < target && guard < 200; ++guard) {
    std::size_t pick = UniformInt(rng, 0, static_cast<int>(cells.size()) - 1);
    Cell c = cells[pick];
    bool vertical = (c.x1 - c.x0 > c.y1 - c.y0) ? UniformInt(rng, 0, 3) > 0 : UniformInt(rng, 0, 3) == 0;
    double lo = vertical ? c.x0 : c.y0, hi = vertical ? c.x1 : c.y1;
    if (hi - lo < 3) continue;
    double cut = Grid(Uniform(rng, lo + 1.5, hi - 1.5));
    if (cut - lo < 1.5 || hi - cut < 1.5) continue;
    Cell a = c, b = c;
    if (vertical) a.x1 = b.x0 = cut;
    else a.y1 = b.y0 = cut;
    cells[pick] = a;
    cells.push_back(b);
  }
  std::vector<Ring> rings;
  for (const auto& c : cells) rings.push_back({{c.x0, c.y0}, {c.x1, c.y0}, {c.x1, c.y1}, {c.x0, c.y1}});
  return rings;
}

Layout RoomsOnly(const std::vector<Ring>& rings) {
  Layout layout;
  for (std::size_t i = 0; i < rings.size(); ++i) layout.rooms.push_back({Category::kRoom, 0, static_cast<int>(i), rings[i]});
  return layout;
}

}  // namespace

TEST_CASE("guillotine tilings form one footprint, the outline matches Boost's union", "[geometry]") {
  std::mt19937_64 rng(20240601);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Ring> rooms = Guillotine(rng, UniformInt(rng, 2, 8));
    ValidationReport report = ValidateLayout(RoomsOnly(rooms));
    INFO("trial " << trial << "\n" << Describe(report));
    CHECK(report.CountRule(1) == 0);
    ExteriorBoundary boundary = ExteriorBoundaryOf(rooms, kTolerance);
    REQUIRE(boundary.rings.size() == 1);
    double area = 0, perimeter = 0, shared = 0, outline = 0;
    for (const auto& r : rooms) {
      area += Area(r);
      for (std::size_t i = 0; i < r.size(); ++i) perimeter += Length({r[i], r[(i + 1) % r.size()]});
    }
    for (std::size_t a = 0; a < rooms.size(); ++a)
      for (std::size_t b = a + 1; b < rooms.size(); ++b) shared += SharedBoundaryLength(rooms[a], rooms[b], kTolerance);
    for (const auto& piece : boundary.pieces) outline += Length(piece);
    CHECK(boundary.rings[0].signed_area == Approx(area));
    // Every edge is either outline or shared with exactly one other room (counted from both sides).
    CHECK(perimeter == Approx(outline + 2 * shared));
    auto footprint = UnionOfRings(rooms);
    REQUIRE(footprint.size() == 1);
    CHECK(footprint[0].holes.empty());
    CHECK(Area(footprint[0].outer) == Approx(area));
    CHECK(outline == Approx(2 * (BoundingBox(footprint[0].outer).max_x + BoundingBox(footprint[0].outer).max_y)));
  }
}

TEST_CASE("a room taken out of a tiling: hole, notch or split, as Boost's union says", "[geometry]") {
  std::mt19937_64 rng(77);
  int holes = 0, splits = 0, notches = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<Ring> rooms = Guillotine(rng, UniformInt(rng, 4, 9));
    std::size_t out = UniformInt(rng, 0, static_cast<int>(rooms.size()) - 1);
    double hole_area = Area(rooms[out]);
    rooms.erase(rooms.begin() + out);
    auto footprint = UnionOfRings(rooms);
    ValidationReport report = ValidateLayout(RoomsOnly(rooms));
    INFO("trial " << trial << "\n" << Describe(report));
    int expected_holes = 0;
    for (const auto& p : footprint) expected_holes += static_cast<int>(p.holes.size());
    int reported_holes = 0, reported_splits = 0;
    for (const auto& v : report.violations) {
      if (v.rule != 1) continue;
      if (v.message.find("hole") != std::string::npos) {
        ++reported_holes;
        CHECK(v.figure == Approx(hole_area));
      }
      if (v.message.find("separate pieces") != std::string::npos) ++reported_splits;
    }
    CHECK(reported_holes == expected_holes);
    CHECK(reported_splits == (footprint.size() > 1 ? 1 : 0));
    holes += expected_holes > 0;
    splits += footprint.size() > 1;
    notches += footprint.size() == 1 && expected_holes == 0;
  }
  // The generator reaches all three outcomes.
  CHECK(holes > 10);
  CHECK(splits > 10);
  CHECK(notches > 10);
}

TEST_CASE("the fast validity test never accepts a ring Boost.Geometry rejects", "[geometry]") {
  namespace bg = boost::geometry;
  using P = bg::model::d2::point_xy<double>;
  using Polygon = bg::model::polygon<P, false, false>;
  std::mt19937_64 rng(5);
  int valid = 0, invalid = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    Ring ring;
    int n = UniformInt(rng, 3, 8);
    for (int i = 0; i < n; ++i) ring.push_back({static_cast<double>(UniformInt(rng, 0, 4)), static_cast<double>(UniformInt(rng, 0, 4))});
    if (SignedArea(ring) < 0) std::reverse(ring.begin(), ring.end());
    Polygon polygon;
    for (const auto& p : ring) polygon.outer().emplace_back(p.x, p.y);
    bool boost_valid = bg::is_valid(polygon) && Area(ring) > 0;
    std::string problem = RingProblem(ring);
    INFO("trial " << trial << ": " << problem);
    CHECK(problem.empty() == boost_valid);
    (boost_valid ? valid : invalid)++;
  }
  CHECK(valid > 100);
  CHECK(invalid > 100);
}

TEST_CASE("garbage layouts get violations, never a crash", "[geometry]") {
  std::mt19937_64 rng(99);
  for (int trial = 0; trial < 300; ++trial) {
    Layout layout;
    int levels = UniformInt(rng, 1, 3);
    int rooms = UniformInt(rng, 1, 7);
    for (int i = 0; i < rooms; ++i) {
      Ring ring;
      int n = UniformInt(rng, 3, 6);
      for (int k = 0; k < n; ++k) ring.push_back({Grid(Uniform(rng, 0, 10)), Grid(Uniform(rng, 0, 10))});
      Category category = LabelledCategories()[UniformInt(rng, 0, 9)];
      layout.rooms.push_back({category, UniformInt(rng, 0, levels - 1), i, ring});
    }
    for (ElementKind kind : kAllElementKinds) {
      int count = UniformInt(rng, 0, 4);
      for (int i = 0; i < count; ++i) {
        Element e;
        e.name = std::string(ElementKindKey(kind)) + std::to_string(i);
        e.kind = kind;
        e.shape = {{Grid(Uniform(rng, 0, 10)), Grid(Uniform(rng, 0, 10))}, {Grid(Uniform(rng, 0, 10)), Grid(Uniform(rng, 0, 10))}};
        e.level = UniformInt(rng, -1, levels);
        e.panoramic = UniformInt(rng, 0, 1) == 1;
        layout.elements(kind).push_back(e);
      }
    }
    ValidationReport report = ValidateLayout(layout);
    for (const auto& v : report.violations) {
      CHECK(v.rule >= 1);
      CHECK(v.rule <= 10);
      CHECK_FALSE(v.message.empty());
      CHECK(std::isfinite(v.figure));
    }
    LayoutMetrics m = MeasureLayout(layout);
    CHECK(m.rooms_reached_per_floor <= m.rooms);
    CHECK(m.rooms_reached_from_entrance <= m.rooms);
    CHECK(m.floor_pairs_connected <= m.floor_pairs);
  }
}

TEST_CASE("points and segments on a room's boundary", "[geometry]") {
  const Ring l_shape{{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}};
  CHECK(PointOnBoundary({3, 2}, l_shape, kTolerance));
  CHECK(PointOnBoundary({2, 3}, l_shape, kTolerance));
  CHECK_FALSE(PointOnBoundary({1, 1}, l_shape, kTolerance));
  CHECK(PointInRing({1, 1}, l_shape, kTolerance));
  CHECK_FALSE(PointInRing({3, 3}, l_shape, kTolerance));  // in the notch
  // A door across the inner corner lies on the boundary for 1 m of its 2 m.
  CHECK(LengthOnBoundary({{1, 2}, {3, 2}}, l_shape, kTolerance) == Approx(1.0));
  CHECK(LengthOnBoundary({{2.5, 2}, {3.5, 2}}, l_shape, kTolerance) == Approx(1.0));
  CHECK(LengthOnBoundary({{2.5, 2.1}, {3.5, 2.1}}, l_shape, kTolerance) == 0);
  // Shared boundary of the L and the box over its notch: two collinear pieces, 2 m each.
  auto shared = SharedBoundaries(l_shape, {{2, 2}, {4, 2}, {4, 4}, {2, 4}}, kTolerance);
  REQUIRE(shared.size() == 2);
  CHECK(Length(shared[0]) + Length(shared[1]) == Approx(4.0));
  // 1e-7 m off still counts as on; 1e-5 m off does not.
  CHECK(LengthOnBoundary({{1, 1e-7}, {3, 1e-7}}, l_shape, kTolerance) == Approx(2.0));
  CHECK(LengthOnBoundary({{1, 1e-5}, {3, 1e-5}}, l_shape, kTolerance) == 0);
}

TEST_CASE("a room touching another's outline at one point encloses a hole", "[geometry]") {
  // A bar along the bottom, a column on the right, and a room whose corner (5, 2) touches the bar's top
  // edge in its middle: the triangle (5,2)-(10,2)-(10,4), 5 m2, is enclosed.
  std::vector<Ring> rooms = {{{0, 0}, {10, 0}, {10, 2}, {0, 2}},
                             {{10, 0}, {12, 0}, {12, 6}, {10, 6}},
                             {{5, 2}, {10, 4}, {10, 6}, {4, 6}}};
  ExteriorBoundary boundary = ExteriorBoundaryOf(rooms, kTolerance);
  CHECK(boundary.closed);
  double holes = 0;
  for (const auto& ring : boundary.rings)
    if (ring.signed_area < 0) holes += -ring.signed_area;
  CHECK(holes == Approx(5.0));
  ValidationReport report = ValidateLayout(RoomsOnly(rooms));
  INFO(Describe(report));
  CHECK(Find(report, "level 0 footprint has a hole of 5.00 m2 enclosed by room_0/0, room_0/2, room_0/1"));
}

TEST_CASE("collinear overlaps with a list of segments find the shared stretch and nothing else", "[geometry]") {
  const Segment edge{{0, 0}, {10, 0}};
  const std::vector<Segment> others = {{{2, 0}, {4, 0}}, {{6, 0}, {3, 0}}, {{5, 1}, {7, 1}}, {{8, 0}, {8, 3}}, {{9, 0}, {12, 0}}};
  const auto overlaps = IntervalsOnSegments(edge, others, kTolerance);
  REQUIRE(overlaps.size() == 2);
  CHECK(overlaps[0].first == Approx(2));
  CHECK(overlaps[0].second == Approx(6));
  CHECK(overlaps[1].first == Approx(9));
  CHECK(overlaps[1].second == Approx(10));
  const auto gaps = ComplementIntervals(overlaps, 10, kTolerance);
  REQUIRE(gaps.size() == 2);
  CHECK(gaps[0].second == Approx(2));
  CHECK(gaps[1].first == Approx(6));
  CHECK(gaps[1].second == Approx(9));
  const Segment middle = SubSegment(edge, gaps[1]);
  CHECK(middle.a.x == Approx(6));
  CHECK(middle.b.x == Approx(9));

  CHECK(SegmentsCover(others, {{2.5, 0}, {5.5, 0}}, kTolerance));
  CHECK_FALSE(SegmentsCover(others, {{5, 0}, {7, 0}}, kTolerance));
  CHECK_FALSE(SegmentsCover(others, {{5, 1e-3}, {6, 1e-3}}, kTolerance));
  // On a slanted wall.
  CHECK(SegmentsCover({{{13, 0}, {16, 3}}}, {{13.5, 0.5}, {15.5, 2.5}}, kTolerance));
}

TEST_CASE("a ring holds a segment across its collinear corner as on one edge", "[geometry]") {
  // The bottom edge runs through a collinear corner at (2, 0).
  const Ring room{{0, 0}, {2, 0}, {4, 0}, {4, 3}, {0, 3}};
  CHECK(RingHoldsSegment(room, {{1, 0}, {3, 0}}, kOnWallTolerance));
  CHECK(RingHoldsSegment(room, {{3, 0}, {1, 0}}, kOnWallTolerance));
  CHECK_FALSE(RingHoldsSegment(room, {{3, 0}, {5, 0}}, kOnWallTolerance));  // runs past the corner
  CHECK_FALSE(RingHoldsSegment(room, {{1, 1}, {3, 1}}, kOnWallTolerance));  // inside
  CHECK_FALSE(RingHoldsSegment(room, {{1, 0}, {1, 0}}, kOnWallTolerance));  // no length
  CHECK(DistanceToBoundary({1, 1}, room) == Approx(1.0));
  CHECK(DistanceToBoundary({5, 1.5}, room) == Approx(1.0));
}
