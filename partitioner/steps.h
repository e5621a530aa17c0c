#pragma once
// The partitioner's steps, one function each, in grid units (exact integers). GenerateLayout chains them;
// the tests check each on its own. Internal to villa_partitioner and its tests.
#include <cstdint>
#include <optional>
#include <vector>

#include "partitioner/geometry.h"
#include "partitioner/partitioner.h"
#include "util/hash.h"

namespace villa::partition {

// The partitioner's random stream: util's SplitMix64, the same numbers on every standard library.
using Rng = SplitMix64;

uint64_t MixSeed(uint64_t a, uint64_t b);

// Grid units for metres (the grid divides every length used: 4 m, door widths...).
struct Scale {
  double grid = 0.5;
  int64_t Units(double metres) const;      // nearest whole number of units
  int64_t UnitsUp(double metres) const;    // at least `metres`
  double Metres(int64_t units) const { return static_cast<double>(units) * grid; }
};

// Step 1: the ground footprint of class `shape` inside a width x height rectangle at the origin (units).
// Empty when the random cuts did not fit (the caller retries).
IRing FootprintShape(ShapeClass shape, int64_t width, int64_t height, const Scale& scale, Rng& rng);

// Step 1b: 45-degree chamfers (legs 1.5-2 m) at one or two convex corners between axis-parallel sides,
// each leaving at least 2 m of both sides (an orthogonal class keeps its class: ClassifyFootprint reads a
// chamfer as the corner it cuts). The ring unchanged when none fits.
IRing ChamferCorners(IRing ring, const Scale& scale, Rng& rng);

// Step 3: the staircase square (side `size` units) inside `footprint`, with one side on its boundary (so
// the rest of the floor has no hole) and its centre away from the footprint's centroid. Nullopt if none.
std::optional<IBox> PlaceStaircase(const IRing& footprint, int64_t size, const Scale& scale, Rng& rng);

// Step 2: the footprint of the floor above: `lower` minus zero to two rectangular cuts at corners or
// sides, one connected piece, containing `stair` (when given), at least `min_area2` (twice-area units).
IRing UpperFootprint(const IRing& lower, const std::optional<IBox>& stair, int64_t min_area2, const Scale& scale,
                     Rng& rng);

// Usability threshold of a BSP piece (units): a future room of any type fits, and no corner of it is
// sharper than 45 degrees.
struct BspLimits {
  int64_t min_area2 = 0;      // twice the area
  int64_t min_side = 0;       // bounding box, both sides
  double min_width = 0.0;     // MinWidth of the ring
  // A part narrower than this (0: no such width) is allowed but scored kNarrowPenalty worse: few rooms
  // keep a strip under 1.8 m (a room people live in needs more), without refusing the splits that make one.
  double comfortable_width = 0.0;
  // Past the target room count, pieces larger than max_area2 (twice the area; 0: no limit) are split
  // further while there are fewer than max_pieces (an oversized room becomes two).
  int64_t max_area2 = 0;
  int max_pieces = 0;
};
bool PieceUsable(const IRing& piece, const BspLimits& limits);

// How badly a piece is proportioned as a room: 0 for a bounding-box aspect up to 2 that the piece fills to
// at least 75 %; grows with the square of the aspect beyond 2 (2.5: 1, 3: 4) and with the unfilled share
// (a thin L wrapped round a corner or the staircase). The box is taken in the axis frame or along one of
// the piece's slanted edges, whichever fits best (a room in a wing turned 45 degrees is a rectangle).
double ShapePenalty(const IRing& piece);
inline constexpr double kNarrowPenalty = 4.0;
// The ShapePenalty of the parts of a split, plus kNarrowPenalty for each under limits.comfortable_width;
// `worst` (when given) is raised to the largest ShapePenalty of a part.
double PartsPenalty(const std::vector<IRing>& parts, const BspLimits& limits, double* worst = nullptr);

// Step 4: splits `pieces` recursively by grid lines into at most `target` connected rooms, each usable:
// axis-parallel lines, and lines parallel to a slanted edge of the piece or to one of `follow` (the slanted
// edges of the floor's outline: a hexagon's ends, a chamfered corner, an angled wing, a bay), so interior
// walls follow the building's angles (slopes 1:1, 1:2 and 2:1 only, whose grid steps hold a door); such a
// line wins over an axis-parallel one of up to 1 more ShapePenalty while each of its parts stays at 1.6 or
// better. Splits crossing edges off the grid are skipped. `wanted_area2` (twice-area units)
// lists room sizes the floor's plan asks for (a bathroom, a kitchen...): while some are missing, most
// splits cut one of them off an end of the piece; the rest of the area goes to the big rooms. Returns
// the rooms (fewer than `target` when no usable split was left). Each split tries a few candidate lines
// (mostly across the piece's longer side, half of them through a reflex corner of a non-convex piece),
// plus a corner carve of the smallest wanted room (the rest an L), and keeps the one whose parts have the
// least ShapePenalty.
std::vector<IRing> SplitRoomBsp(std::vector<IRing> pieces, int target, const BspLimits& limits, Rng& rng,
                                std::vector<int64_t> wanted_area2 = {}, const std::vector<ILine>& follow = {});

// Step 6: a door (or open) of `width` grid steps on the wall segment, at least `clearance` steps from both
// of its ends, at a random grid position. A step is the wall's direction over the gcd of its extents: one
// unit on an axis-parallel wall, (1, 1) on a 45-degree one. Nullopt when the wall is too short.
std::optional<ISegment> PlaceDoor(const ISegment& wall, int64_t width, int64_t clearance, Rng& rng);

}  // namespace villa::partition
