#pragma once
// How every door and the entrance open: the one rule the floor plan (its leaf and arc), the 3D building
// (its open leaf) and the furnishing (keep-out zones, PRIORS.md clearances) share, so a plan, its model
// and its furniture never open a door into different rooms.
//
// The rule, for the element's segment on one level:
//  - the rooms beside it are those holding a point kDoorProbe m off its middle on either side;
//  - the entrance opens into the building (away from the side without a room; where both or neither side
//    has one, away from the middle of the floor);
//  - a door between two rooms opens into the room one enters from the common spaces: never onto a balcony
//    (rank 3), nor into a staircase hall (rank 2, a utility room of a building with several floors) or a
//    living, dining or meeting room (rank 1) when the other side ranks lower; between two of a rank, into
//    the smaller (the first of the two, left of the segment, on a tie);
//  - the hinge is the end of the opening nearer a corner of that room, so the open leaf rests along a wall;
//  - the leaf must not close the floor it stands on (issue 13): of the candidate swings, in this order of
//    preference -- the side above with its hinge, the same side with the other hinge, the other side with
//    either hinge (the entrance only opens in), each open 90 degrees -- the first whose leaf leaves the
//    room's walking floor connected is taken. Where no 90 degree leaf can stand, the
//    leaf opens 180 degrees, flat against the wall beside its hinge (ordinary butt hinges open that far
//    when the wall is straight and free for a leaf's width), in the same order. Where neither can, the
//    90 degree leaf that fits its room and costs the floor least stands (ways closed, then area cut off),
//    else the first candidate; the builder hangs a leaf closed when its sweep hits a wall or a stair.
//    A staircase hall's floor is mostly flights and their hole, which the layout does not know, so a leaf is
//    never found to stand well in one: it swings elsewhere when any other candidate does.
//    Doors are decided in order (the entrance first, then `doors` in layout order); the leaves already
//    standing in a room count as obstacles for the next door's leaf (two leaves meeting in a passage).
// Metres, plan frame; rings counter-clockwise.
#include <vector>

#include "layout/layout.h"

namespace villa {

inline constexpr double kDoorProbe = 0.05;        // m off the door's middle to find the rooms beside it
inline constexpr double kDoorStripDepth = 0.6;    // m, the clearance strip on the side away from the leaf

// What "the leaf leaves the floor connected" means. The layout has no wall thicknesses, so
// the builder's defaults (BuildOptions) stand here; the person is the reachability check's (docs/REACH.md).
struct SwingClearance {
  double person_radius = 0.2;    // m, the walking person's disc
  double margin = 0.03;          // m beyond the disc a passage keeps (a passage is 2 x (radius + margin) wide)
  double exterior_wall = 0.25;   // m, an exterior wall's depth inward of the footprint edge
  double interior_wall = 0.12;   // m, an interior wall's thickness (centred on its segment)
  double leaf_thickness = 0.04;  // m
  double cell = 0.04;            // m, the raster the floor is checked on
  double lost_area = 0.1;        // m2 of a room's free floor a leaf may cut off (a corner behind it)
};

struct DoorSwing {
  const Element* element = nullptr;  // the door or entrance (points into the layout it was made from)
  int level = 0;
  int into = -1;   // room the leaf swings into (index into Layout::rooms), -1: no room on that side
  int other = -1;  // room on the other side, -1: none (outside, for the entrance)
  Point hinge;     // the jamb the leaf turns about (an end of the element's segment)
  Point free_end;  // the other jamb
  Point leaf_end;  // the open leaf's tip: hinge + width * leaf_side
  Point leaf_side; // unit normal of the segment pointing to the side the leaf opens to (into `into`)
  bool flat = false;  // opened 180 degrees: the leaf lies along the wall beside the hinge, away from the opening
  // The swept area on the leaf side (a 90 degree leaf: the square width x width over the opening, which
  // holds its quarter disc; a flat leaf: 2 width x width, over the opening and the wall it folds onto, which
  // holds its half disc) and the clearance strip, width x kDoorStripDepth on the other side: keep-out
  // zones for furniture.
  Ring sweep;
  Ring strip;
  double width() const;  // m, the segment's length
  double open_angle() const;  // radians the leaf turned from the closed position: pi/2, or pi when flat
  // The arc the leaf's tip sweeps, from leaf_end round to free_end through the leaf side, as `segments` + 1
  // points (the floor plan draws it).
  std::vector<Point> SwingArc(int segments) const;
};

// The swing of `element` (a door or the entrance) on `level`: the one DoorSwings gives it.
DoorSwing SwingOfDoor(const Layout& layout, const Element& element, int level, const SwingClearance& clearance = {});

// The swings of every entrance (level 0 only) and door of `level`, entrances first, in layout order.
std::vector<DoorSwing> DoorSwings(const Layout& layout, int level, const SwingClearance& clearance = {});

}  // namespace villa
