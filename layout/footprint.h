#pragma once
// A level's footprint and the class of the ground floor's outline. LevelFootprint is villa's one
// footprint routine (the building's slabs and walls stand on it); ClassifyFootprint is the one classifier
// (the dataset records, the fine-tune export, the generator's brief check and its procedural search).
#include <optional>
#include <string_view>
#include <vector>

#include "layout/geometry.h"
#include "layout/layout.h"

namespace villa {

// The footprint classes. Their names (ShapeClassName) go into dataset records ("shape") and the
// annotator's descriptions: exactly "rectangle", "L", "U", "T", "H", "irregular", "hexagon", "octagon",
// "trapezoid", "cross", "bay", "angled-wing".
//   rectangle: the sampled rectangle itself.
//   L: one rectangular notch at one corner.
//   U: one rectangular notch in the middle of one side.
//   T: two rectangular notches at the two corners of the same side.
//   H: rectangular notches in the middle of two opposite sides.
//   irregular: cuts at arbitrary angles (chamfers, slanted edges, triangular bites; slopes such as 1:1,
//              1:2, 2:3 with grid end points), possibly combined with a rectangular notch.
//   hexagon: six sides, all corners 105-145 degrees (regular, about 120, or stretched along one axis).
//   octagon: eight sides, all corners 120-150 degrees (a rectangle with four 45-degree corners).
//   trapezoid: four sides, two of them parallel, one or both of the others slanted.
//   cross: four wings round a central hall (a rectangular notch at each of the four corners); the
//          planner's "star-shaped" and "cross-shaped".
//   bay: a rectangle with a bay projection: three sides, the outer two at 45 degrees, on one side.
//   angled-wing: a rectangular body with a wing turned 45 degrees from one of its sides.
// Any orthogonal class may also have 45-degree chamfered corners (FootprintChamfered).
enum class ShapeClass {
  kRectangle, kL, kU, kT, kH, kIrregular, kHexagon, kOctagon, kTrapezoid, kCross, kBay, kAngledWing
};
inline constexpr int kShapeClassCount = 12;

std::string_view ShapeClassName(ShapeClass shape);
// Accepts exactly the names above (and lower-case "l", "u", "t", "h").
std::optional<ShapeClass> ParseShapeClass(std::string_view name);
// The classes in the order of the enum.
const std::vector<ShapeClass>& AllShapeClasses();
// True for the classes whose outline always has a slanted edge (irregular, hexagon, octagon, trapezoid,
// bay, angled-wing).
bool ShapeClassIsAngled(ShapeClass shape);

// The footprint of the rooms `rings` (one level), by cancelling the edge parts two rings share
// (geometry.h's ExteriorBoundaryOf, the validator's rule-1 boundary): each outline counter-clockwise with
// the holes inside it, corners only (collinear points and repeats within `tolerance` dropped). Empty when
// the boundary does not close (overlapping or broken rooms). Rings flagged in `subtract` (same size as
// `rings`, or empty for none) are taken away instead of added: with the lower level's footprint and the
// upper level's given that way, the result is the part of the lower level the upper one leaves open (the
// building's roof terraces). Meant for rooms that tile (FORMAT.md rule 1) and upper floors that stand
// on lower ones (rule 2); a tolerance above the validator's lets the building adapt nearly-valid input.
std::vector<PolygonWithHoles> FootprintOf(const std::vector<Ring>& rings, double tolerance = kTolerance,
                                          const std::vector<bool>& subtract = {});

// FootprintOf the rooms of `level`.
std::vector<PolygonWithHoles> LevelFootprint(const Layout& layout, int level, double tolerance = kTolerance);

// The class of `level`'s outline (ShapeClass names), by its geometry. With slanted outside edges: a convex
// hexagon, octagon or trapezoid as defined above; a bay (three sides out of a straight side, the outer
// two slanted); an angled wing (three consecutive slanted edges, the first and last parallel, the middle
// square to them, the rest axis-parallel); else, once 45-degree chamfers at convex corners are read as
// the corners they cut, the orthogonal class of what is left; else irregular. Orthogonal outlines: the
// parts of the bounding box the rooms leave empty decide (none: rectangle; one at a corner: L; one notch
// in a side: U; two at the corners of one side: T; notches in two opposite sides: H; one at each of the
// four corners: cross; anything else, a courtyard included: irregular). Empty for a level without rooms.
std::optional<ShapeClass> ClassifyFootprint(const Layout& layout, int level = 0);

// True when some wall between two rooms (an interior wall, a door or an open) is neither horizontal nor
// vertical (the stats of `villa synth` and the data card of `villa finetune export` count these layouts).
bool HasSlantedWallBetweenRooms(const Layout& layout);
// True when `level`'s outline has an edge that is neither horizontal nor vertical.
bool HasSlantedOutsideEdge(const Layout& layout, int level = 0);

// True when `level`'s outline has a 45-degree chamfer at a convex corner between a horizontal and a
// vertical side (an octagon's corners count; a hexagon's or an irregular cut's slopes do not).
bool FootprintChamfered(const Layout& layout, int level = 0);

}  // namespace villa
