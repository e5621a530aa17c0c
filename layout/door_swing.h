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
//  - the hinge is the end of the opening nearer a corner of that room, so the open leaf rests along a wall.
// Metres, plan frame; rings counter-clockwise.
#include <vector>

#include "layout/layout.h"

namespace villa {

inline constexpr double kDoorProbe = 0.05;        // m off the door's middle to find the rooms beside it
inline constexpr double kDoorStripDepth = 0.6;    // m, the clearance strip on the side away from the leaf

struct DoorSwing {
  const Element* element = nullptr;  // the door or entrance (points into the layout it was made from)
  int level = 0;
  int into = -1;   // room the leaf swings into (index into Layout::rooms), -1: no room on that side
  int other = -1;  // room on the other side, -1: none (outside, for the entrance)
  Point hinge;     // the jamb the leaf turns about (an end of the element's segment)
  Point free_end;  // the other jamb
  Point leaf_end;  // the open leaf's tip: hinge + width * leaf_side
  Point leaf_side; // unit normal of the segment pointing to the side the leaf opens to (into `into`)
  // The swept square, width x width on the leaf side (the leaf's quarter disc lies within it), and the
  // clearance strip, width x kDoorStripDepth on the other side: keep-out zones for furniture.
  Ring sweep;
  Ring strip;
  double width() const;  // m, the segment's length
};

// The swing of `element` (a door or the entrance) on `level`.
DoorSwing SwingOfDoor(const Layout& layout, const Element& element, int level);

// The swings of every entrance (level 0 only) and door of `level`, entrances first, in layout order.
std::vector<DoorSwing> DoorSwings(const Layout& layout, int level);

}  // namespace villa
