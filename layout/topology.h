#pragma once
// Who connects to whom: the layout graph of the paper (rooms as nodes; doors, opens, the staircase and
// the entrance as edges). The validator (rules 8, 10), the metrics (RR), the annotator's room list and
// the generator's brief checks all read it from here, so they agree.
#include <string>
#include <vector>

#include "layout/layout.h"

namespace villa {

enum class Via { kDoor, kOpen, kStair };

struct Connection {
  int room_a = -1;  // indices into Layout::rooms
  int room_b = -1;
  Via via = Via::kDoor;
  std::string element;  // the door / open name; "stair" for a staircase link
};

// Doors and opens matched to the two rooms of their level whose shared boundary holds them (an element
// that does not lie on exactly two rooms gives no connection), plus staircase links between utility
// rooms with identical polygons on adjacent levels.
std::vector<Connection> RoomConnections(const Layout& layout, double tolerance = kOnWallTolerance);

// The rooms of one level along a segment: those whose boundary holds all of it (within tolerance) and
// those whose boundary holds a part longer than tolerance. A door is in place when `holding` has exactly
// two rooms; a window or the entrance when `touching` is exactly one room that also holds it.
struct SegmentRooms {
  std::vector<int> holding;   // indices into Layout::rooms
  std::vector<int> touching;  // includes `holding`
};
SegmentRooms RoomsAlongSegment(const Layout& layout, int level, const Segment& segment,
                               double tolerance = kOnWallTolerance);

// The rooms holding `element` (RoomsAlongSegment's `holding`) on every level it belongs to, in room order:
// a door in place has two, a window or the entrance in place one.
std::vector<int> RoomsHolding(const Layout& layout, const Element& element, double tolerance = kOnWallTolerance);

// Indices of rooms touching the entrance segment(s) (normally one).
std::vector<int> EntranceRooms(const Layout& layout, double tolerance = kOnWallTolerance);

// Reachable[i] is true when room i is reached from any of `start` through `connections`.
std::vector<bool> ReachableRooms(const Layout& layout, const std::vector<Connection>& connections,
                                 const std::vector<int>& start);

}  // namespace villa
