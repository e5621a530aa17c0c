// Each step of the partitioner on its own (partitioner/steps.h): footprint classes shaped as named,
// staircase placement, upper floors, BSP splits, door placement.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>

#include "partitioner/steps.h"

using namespace villa;
using namespace villa::partition;

namespace {

const Scale kScale{0.5};

// Reflex (concave) corners of a counter-clockwise ring.
int ReflexCorners(const IRing& ring) {
  int n = 0;
  for (std::size_t i = 0; i < ring.size(); ++i)
    n += Cross(ring[(i + ring.size() - 1) % ring.size()], ring[i], ring[(i + 1) % ring.size()]) < 0;
  return n;
}

// Which corners of the W x H rectangle are still vertices: bit 0 (0,0), 1 (W,0), 2 (W,H), 3 (0,H).
int CornersKept(const IRing& ring, int64_t W, int64_t H) {
  const IPoint corners[4] = {{0, 0}, {W, 0}, {W, H}, {0, H}};
  int mask = 0;
  for (int c = 0; c < 4; ++c)
    if (std::find(ring.begin(), ring.end(), corners[c]) != ring.end()) mask |= 1 << c;
  return mask;
}

int Bits(int mask) { return __builtin_popcount(static_cast<unsigned>(mask)); }

// The notched sides of an orthogonal footprint: a side has a notch when some vertex lies strictly
// inside the bounding box on it... measured as: sides of the box not fully covered by the ring's edges.
std::set<int> NotchedSides(const IRing& ring, int64_t W, int64_t H) {
  std::set<int> sides;
  int64_t covered[4] = {0, 0, 0, 0};
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const IPoint a = ring[i], b = ring[(i + 1) % ring.size()];
    if (a.y == 0 && b.y == 0) covered[0] += std::llabs(b.x - a.x);
    if (a.x == W && b.x == W) covered[1] += std::llabs(b.y - a.y);
    if (a.y == H && b.y == H) covered[2] += std::llabs(b.x - a.x);
    if (a.x == 0 && b.x == 0) covered[3] += std::llabs(b.y - a.y);
  }
  const int64_t full[4] = {W, H, W, H};
  for (int s = 0; s < 4; ++s)
    if (covered[s] < full[s]) sides.insert(s);
  return sides;
}

IRing Footprint(ShapeClass shape, uint64_t seed, int64_t W = 36, int64_t H = 30) {
  for (uint64_t k = 0; k < 50; ++k) {
    Rng rng(MixSeed(seed, k));
    IRing ring = FootprintShape(shape, W, H, kScale, rng);
    if (!ring.empty()) return ring;
  }
  return {};
}

}  // namespace

TEST_CASE("Footprint classes look like their names", "[partitioner][footprint]") {
  const int64_t W = 36, H = 30;
  for (uint64_t seed = 0; seed < 60; ++seed) {
    INFO("seed " << seed);
    const IRing rect = Footprint(ShapeClass::kRectangle, seed);
    CHECK(rect.size() == 4);
    CHECK(TwiceArea(rect) == 2 * W * H);

    const IRing l = Footprint(ShapeClass::kL, seed);
    REQUIRE(!l.empty());
    CHECK(IsSimple(l));
    CHECK(l.size() == 6);
    CHECK(ReflexCorners(l) == 1);
    CHECK(Bits(CornersKept(l, W, H)) == 3);  // one corner notched away
    CHECK(NotchedSides(l, W, H).size() == 2);  // the notch takes parts of two adjacent sides

    const IRing u = Footprint(ShapeClass::kU, seed);
    REQUIRE(!u.empty());
    CHECK(u.size() == 8);
    CHECK(ReflexCorners(u) == 2);
    CHECK(CornersKept(u, W, H) == 15);  // all corners there: the notch is in the middle of a side
    CHECK(NotchedSides(u, W, H).size() == 1);

    const IRing t = Footprint(ShapeClass::kT, seed);
    REQUIRE(!t.empty());
    CHECK(t.size() == 8);
    CHECK(ReflexCorners(t) == 2);
    const int kept = CornersKept(t, W, H);
    CHECK(Bits(kept) == 2);
    // The two missing corners are the ends of one side (adjacent in the corner cycle).
    const int missing = 15 & ~kept;
    CHECK((missing == 3 || missing == 6 || missing == 12 || missing == 9));

    const IRing h = Footprint(ShapeClass::kH, seed);
    REQUIRE(!h.empty());
    CHECK(h.size() == 12);
    CHECK(ReflexCorners(h) == 4);
    CHECK(CornersKept(h, W, H) == 15);
    const std::set<int> sides = NotchedSides(h, W, H);
    CHECK(sides.size() == 2);
    CHECK((sides == std::set<int>{0, 2} || sides == std::set<int>{1, 3}));  // opposite sides

    const IRing irregular = Footprint(ShapeClass::kIrregular, seed);
    REQUIRE(!irregular.empty());
    CHECK(IsSimple(irregular));
    CHECK(HasAngledEdge(irregular));
    CHECK(TwiceArea(irregular) < 2 * W * H);
  }
}

namespace {
// Inside angles of a counter-clockwise ring, degrees.
std::vector<double> InsideAngles(const IRing& ring) {
  std::vector<double> out;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const IPoint a = ring[(i + n - 1) % n], b = ring[i], c = ring[(i + 1) % n];
    const double ux = double(a.x - b.x), uy = double(a.y - b.y), vx = double(c.x - b.x), vy = double(c.y - b.y);
    double deg = std::atan2(vx * uy - vy * ux, vx * ux + vy * uy) * 180.0 / M_PI;
    out.push_back(deg <= 0.0 ? deg + 360.0 : deg);
  }
  return out;
}
int SlantedEdges(const IRing& ring) {
  int n = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const IPoint a = ring[i], b = ring[(i + 1) % ring.size()];
    n += a.x != b.x && a.y != b.y;
  }
  return n;
}
}  // namespace

TEST_CASE("Polygonal footprint classes have the sides and corners of their names", "[partitioner][footprint]") {
  for (uint64_t seed = 0; seed < 40; ++seed) {
    INFO("seed " << seed);
    for (auto [W, H] : {std::pair<int64_t, int64_t>{36, 30}, {30, 40}}) {
      const IRing hex = Footprint(ShapeClass::kHexagon, seed, W, H);
      REQUIRE(hex.size() == 6);
      CHECK(SlantedEdges(hex) == 4);
      for (double a : InsideAngles(hex)) CHECK((a >= 105.0 && a <= 145.0));
      const IRing oct = Footprint(ShapeClass::kOctagon, seed, W, H);
      REQUIRE(oct.size() == 8);
      CHECK(SlantedEdges(oct) == 4);
      for (double a : InsideAngles(oct)) CHECK(a == Approx(135.0));
      const IRing trap = Footprint(ShapeClass::kTrapezoid, seed, W, H);
      REQUIRE(trap.size() == 4);
      CHECK(SlantedEdges(trap) >= 1);
      for (double a : InsideAngles(trap)) CHECK((a >= 45.0 - 1e-9 && a <= 135.0 + 1e-9));
      const IRing cross = Footprint(ShapeClass::kCross, seed, W, H);
      REQUIRE(cross.size() == 12);
      CHECK(ReflexCorners(cross) == 4);
      CHECK(CornersKept(cross, W, H) == 0);  // every corner notched away
      const IRing bay = Footprint(ShapeClass::kBay, seed, W, H);
      REQUIRE(bay.size() == 8);
      CHECK(SlantedEdges(bay) == 2);
      CHECK(ReflexCorners(bay) == 2);
      const IRing wing = Footprint(ShapeClass::kAngledWing, seed, W, H);
      REQUIRE(wing.size() == 7);
      CHECK(SlantedEdges(wing) == 3);
      // The hexagon's flat sides are at least 8 m (a staircase 2 m from both ends; its frame grows for that).
      for (std::size_t i = 0; i < hex.size(); ++i) {
        const IPoint a = hex[i], b = hex[(i + 1) % hex.size()];
        if (a.x == b.x || a.y == b.y) CHECK(std::llabs(b.x - a.x) + std::llabs(b.y - a.y) >= 16);
      }
      for (const IRing* ring : {&hex, &oct, &trap, &cross, &bay, &wing}) {
        CHECK(IsSimple(*ring));
        CHECK(TwiceArea(*ring) > 0);
        const IBox box = BoundingBox(*ring);
        CHECK((box.min_x >= 0 && box.min_y >= 0));
        if (ring != &hex && ring != &wing) CHECK((box.max_x <= W && box.max_y <= H));  // those two frames may grow
      }
    }
  }
}

TEST_CASE("Chamfered corners are 45 degrees and keep the class's other corners", "[partitioner][footprint]") {
  int chamfered = 0;
  for (uint64_t seed = 0; seed < 40; ++seed) {
    Rng rng(MixSeed(seed, 7));
    const IRing l = Footprint(ShapeClass::kL, seed);
    const IRing cut = ChamferCorners(l, kScale, rng);
    REQUIRE(IsSimple(cut));
    CHECK(TwiceArea(cut) <= TwiceArea(l));
    const int added = static_cast<int>(cut.size()) - static_cast<int>(l.size());
    CHECK((added >= 0 && added <= 2));
    chamfered += added > 0;
    CHECK(ReflexCorners(cut) == 1);
    for (std::size_t i = 0; i < cut.size(); ++i) {
      const IPoint a = cut[i], b = cut[(i + 1) % cut.size()];
      if (a.x != b.x && a.y != b.y) {
        CHECK(std::llabs(b.x - a.x) == std::llabs(b.y - a.y));  // 45 degrees
        CHECK(std::llabs(b.x - a.x) >= 3);                      // legs of at least 1.5 m
      }
    }
  }
  CHECK(chamfered >= 30);
}

TEST_CASE("BSP in slanted pieces makes walls parallel to the slanted sides, no corner under 45 degrees",
          "[partitioner][bsp]") {
  // Octagons and angled wings split into 3-5 rooms: every room without a corner under 45 degrees, the rooms
  // tiling the outline, and some floors with a slanted wall between two rooms.
  int floors = 0, with_angled_wall = 0;
  for (ShapeClass shape : {ShapeClass::kOctagon, ShapeClass::kAngledWing})
    for (uint64_t seed = 0; seed < 40; ++seed) {
      INFO(ShapeClassName(shape) << " seed " << seed);
      const IRing outline = Footprint(shape, seed, 26, 22);  // 13 x 11 m
      Rng rng(MixSeed(seed, 3));
      BspLimits limits;
      limits.min_area2 = 2 * 24;
      limits.min_side = 5;
      limits.min_width = 2.4;
      const std::vector<ILine> follow = SlantedLines(outline);  // as the partitioner passes them
      const std::vector<IRing> rooms = SplitRoomBsp({outline}, 4 + static_cast<int>(seed % 2), limits, rng, {}, follow);
      int64_t total = 0;
      for (const IRing& r : rooms) {
        total += TwiceArea(r);
        CHECK(IsSimple(r));
        CHECK_FALSE(HasSharpCorner(r));
      }
      CHECK(total == TwiceArea(outline));
      IRing doubled;
      for (const IPoint& p : outline) doubled.push_back({2 * p.x, 2 * p.y});
      bool angled = false;
      for (const IRing& r : rooms)
        for (std::size_t i = 0; i < r.size(); ++i) {
          const IPoint a = r[i], b = r[(i + 1) % r.size()];
          if (a.x != b.x && a.y != b.y && PointInRing(doubled, {a.x + b.x, a.y + b.y}) == 1) angled = true;
        }
      ++floors;
      with_angled_wall += angled;
    }
  CHECK(with_angled_wall * 6 >= floors);  // 18 of 80 when written; whole layouts reach 30 % (layout_properties_test)
}

TEST_CASE("Irregular footprints cut at many angles, not only 45 degrees", "[partitioner][footprint]") {
  std::set<std::pair<int64_t, int64_t>> slopes;
  for (uint64_t seed = 0; seed < 200; ++seed) {
    const IRing ring = Footprint(ShapeClass::kIrregular, seed);
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const IPoint a = ring[i], b = ring[(i + 1) % ring.size()];
      if (a.x == b.x || a.y == b.y) continue;
      const int64_t dx = std::llabs(b.x - a.x), dy = std::llabs(b.y - a.y), g = Gcd(dx, dy);
      slopes.insert({std::min(dx, dy) / g, std::max(dx, dy) / g});
    }
  }
  CHECK(slopes.size() >= 6);
  CHECK(slopes.count({1, 1}) == 1);
  CHECK(slopes.size() > slopes.count({1, 1}));
}

TEST_CASE("The staircase square sits inside the footprint, on its boundary, off its centroid",
          "[partitioner][staircase]") {
  for (ShapeClass shape : AllShapeClasses()) {
    for (uint64_t seed = 0; seed < 20; ++seed) {
      INFO(ShapeClassName(shape) << " seed " << seed);
      const IRing ring = Footprint(shape, seed);
      REQUIRE(!ring.empty());
      Rng rng(seed);
      const auto stair = PlaceStaircase(ring, 8, kScale, rng);
      REQUIRE(stair);
      CHECK(stair->width() == 8);
      CHECK(stair->height() == 8);
      std::vector<IRing> rest;
      REQUIRE(SubtractInside(ring, BoxRing(*stair), &rest));
      REQUIRE(rest.size() == 1);  // no hole: it touches the boundary
      CHECK(TwiceArea(rest[0]) == TwiceArea(ring) - 2 * 64);
      double cx, cy;
      Centroid(ring, &cx, &cy);
      const double sx = (stair->min_x + stair->max_x) / 2.0, sy = (stair->min_y + stair->max_y) / 2.0;
      CHECK((std::abs(sx - cx) > 1e-6 || std::abs(sy - cy) > 1e-6));
    }
  }
}

TEST_CASE("Upper footprints lie inside the floor below and keep the staircase", "[partitioner][floors]") {
  int smaller = 0;
  for (uint64_t seed = 0; seed < 60; ++seed) {
    const IRing ground = Footprint(seed % 2 ? ShapeClass::kL : ShapeClass::kIrregular, seed);
    Rng rng(seed);
    const auto stair = PlaceStaircase(ground, 8, kScale, rng);
    REQUIRE(stair);
    const IRing upper = UpperFootprint(ground, stair, 2 * 100, kScale, rng);
    REQUIRE(!upper.empty());
    CHECK(IsSimple(upper));
    CHECK(TwiceArea(upper) <= TwiceArea(ground));
    for (const IPoint& p : upper) CHECK(PointInRing(ground, p) >= 0);
    std::vector<IRing> rest;
    CHECK(SubtractInside(upper, BoxRing(*stair), &rest));  // the staircase is inside it
    smaller += TwiceArea(upper) < TwiceArea(ground);
  }
  CHECK(smaller >= 20);  // most upper floors are cut back
}

TEST_CASE("BSP splits tile the floor with connected, usable rooms", "[partitioner][bsp]") {
  BspLimits limits;
  limits.min_area2 = 2 * 24;  // 6 m2 in 0.5 m units
  limits.min_side = 4;
  limits.min_width = 2.4;
  for (ShapeClass shape : AllShapeClasses()) {
    for (uint64_t seed = 0; seed < 30; ++seed) {
      INFO(ShapeClassName(shape) << " seed " << seed);
      const IRing ring = Footprint(shape, seed);
      Rng rng(seed);
      const int target = 3 + static_cast<int>(seed % 4);
      const std::vector<IRing> rooms = SplitRoomBsp({ring}, target, limits, rng);
      CHECK(static_cast<int>(rooms.size()) <= target);
      CHECK(rooms.size() >= 2);
      int64_t area = 0;
      for (const IRing& room : rooms) {
        CHECK(IsSimple(room));  // one ring: a connected room
        CHECK(PieceUsable(room, limits));
        area += TwiceArea(room);
        for (const IPoint& p : room) CHECK(PointInRing(ring, p) >= 0);
      }
      CHECK(area == TwiceArea(ring));  // no gap, no overlap (all inside, areas add up)
      CHECK(UnionTiles(rooms).size() == 1);
      // New edges (those not on the footprint) are axis-aligned split lines or parallel to a slanted side
      // of the footprint.
      for (const IRing& room : rooms)
        for (std::size_t i = 0; i < room.size(); ++i) {
          const IPoint a = room[i], b = room[(i + 1) % room.size()];
          if (a.x != b.x && a.y != b.y) {
            const IPoint mid2{a.x + b.x, a.y + b.y};
            IRing doubled;
            for (const IPoint& p : ring) doubled.push_back({2 * p.x, 2 * p.y});
            if (PointInRing(doubled, mid2) == 0) continue;  // part of the footprint's slanted edge
            bool parallel = false;
            for (std::size_t j = 0; j < ring.size(); ++j) {
              const IPoint c = ring[j], d = ring[(j + 1) % ring.size()];
              parallel |= (b.x - a.x) * (d.y - c.y) == (b.y - a.y) * (d.x - c.x);
            }
            CHECK(parallel);
          }
        }
    }
  }
}

TEST_CASE("Doors sit on their wall, clear of its corners", "[partitioner][doors]") {
  Rng rng(7);
  const ISegment wall{{4, 2}, {4, 12}};
  for (int i = 0; i < 200; ++i) {
    const auto door = PlaceDoor(wall, 2, 1, rng);
    REQUIRE(door);
    CHECK(door->a.x == 4);
    CHECK(door->b.x == 4);
    const int64_t lo = std::min(door->a.y, door->b.y), hi = std::max(door->a.y, door->b.y);
    CHECK(hi - lo == 2);
    CHECK(lo >= 3);
    CHECK(hi <= 11);
  }
  CHECK_FALSE(PlaceDoor({{0, 0}, {3, 0}}, 2, 1, rng));  // 3 units: no room for 2 + 2 x 1
  CHECK(PlaceDoor({{0, 0}, {4, 0}}, 2, 1, rng));
}

TEST_CASE("ShapePenalty: compact rooms free, strips and thin Ls penalised", "[partitioner][bsp]") {
  CHECK(ShapePenalty(BoxRing({0, 0, 8, 8})) == 0.0);
  CHECK(ShapePenalty(BoxRing({0, 0, 16, 8})) == 0.0);           // 2:1
  CHECK(ShapePenalty(BoxRing({0, 0, 10, 4})) == Approx(1.0));   // 2.5:1
  CHECK(ShapePenalty(BoxRing({0, 0, 24, 8})) == Approx(4.0));   // 3:1
  // An L of 3-unit arms round a 10 x 10 box fills 51 % of it: 16 * (0.75 - 0.51).
  const IRing thin_l{{0, 0}, {10, 0}, {10, 3}, {3, 3}, {3, 10}, {0, 10}};
  CHECK(ShapePenalty(thin_l) == Approx(16.0 * (0.75 - 0.51)));
  // A wide L (a small corner missing) stays free.
  const IRing wide_l{{0, 0}, {10, 0}, {10, 7}, {7, 7}, {7, 10}, {0, 10}};
  CHECK(ShapePenalty(wide_l) == 0.0);
}

TEST_CASE("BSP carves a small wanted room out of a corner with both parts compact", "[partitioner][bsp]") {
  BspLimits limits;
  limits.min_area2 = 2 * 24;  // 6 m2 in 0.5 m units
  limits.min_side = 5;        // 2.5 m
  limits.min_width = 2.4;
  int small = 0;
  for (uint64_t seed = 0; seed < 40; ++seed) {
    Rng rng(seed);
    // A 10 x 8 m floor into two rooms, one of them wanted at 6.25 m2 (25 units).
    const std::vector<IRing> rooms = SplitRoomBsp({BoxRing({0, 0, 20, 16})}, 2, limits, rng, {2 * 25});
    REQUIRE(rooms.size() == 2);
    CHECK(TwiceArea(rooms[0]) + TwiceArea(rooms[1]) == 2 * 20 * 16);
    for (const IRing& r : rooms) {
      CHECK(PieceUsable(r, limits));
      CHECK(ShapePenalty(r) < 2.0);
      small += TwiceArea(r) <= 2 * 36;  // at most 9 m2
    }
  }
  CHECK(small >= 30);  // a line alone would cut a strip of at least 2.5 x 8 = 20 m2
}
