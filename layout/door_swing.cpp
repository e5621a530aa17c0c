#include "layout/door_swing.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "layout/geometry.h"

namespace villa {
namespace {

Point LeftNormal(const Segment& s) {
  const double length = std::max(Length(s), 1e-12);
  return {-(s.b.y - s.a.y) / length, (s.b.x - s.a.x) / length};
}

Point Scaled(const Point& p, double f) { return {p.x * f, p.y * f}; }

// The rooms of `rooms` holding the points kDoorProbe m off the middle of `s` (left = the side of its left
// normal); -1 where none does.
void RoomsBeside(const Layout& layout, const std::vector<int>& rooms, const Segment& s, int* left, int* right) {
  *left = *right = -1;
  const double length = Length(s);
  if (length <= 0.0) return;
  const Point n{-(s.b.y - s.a.y) / length, (s.b.x - s.a.x) / length};
  const Point mid{(s.a.x + s.b.x) / 2.0, (s.a.y + s.b.y) / 2.0};
  const Point off = Scaled(n, kDoorProbe);
  for (int r : rooms) {
    const Ring& ring = layout.rooms[r].polygon;
    if (*left < 0 && PointInRing({mid.x + off.x, mid.y + off.y}, ring, 0)) *left = r;
    if (*right < 0 && PointInRing({mid.x - off.x, mid.y - off.y}, ring, 0)) *right = r;
  }
}

// Unit direction out of the building across `s`: towards the side without a room; where both or neither
// side has one, away from the floor's middle (the mean of its rooms' corners).
Point Outward(const Layout& layout, const std::vector<int>& rooms, const Segment& s) {
  const Point n = LeftNormal(s);
  int left = -1, right = -1;
  RoomsBeside(layout, rooms, s, &left, &right);
  if ((left >= 0) != (right >= 0)) return left >= 0 ? Scaled(n, -1.0) : n;
  Point centre;
  int corners = 0;
  for (int r : rooms)
    for (const Point& p : layout.rooms[r].polygon) centre = {centre.x + p.x, centre.y + p.y}, ++corners;
  if (corners > 0) centre = Scaled(centre, 1.0 / corners);
  const Point mid{(s.a.x + s.b.x) / 2.0, (s.a.y + s.b.y) / 2.0};
  const Point away{mid.x - centre.x, mid.y - centre.y};
  return away.x * n.x + away.y * n.y >= 0.0 ? n : Scaled(n, -1.0);
}

// Lower ranks are opened into first (see the header).
int Rank(const Room& room, bool staircase_hall) {
  switch (room.category) {
    case Category::kBalcony: return 3;
    case Category::kUtilityRoom: return staircase_hall ? 2 : 0;
    case Category::kLivingRoom:
    case Category::kDiningRoom:
    case Category::kMeetingRoom: return 1;
    default: return 0;
  }
}

Ring CounterClockwise(Ring ring) {
  if (SignedArea(ring) < 0) std::reverse(ring.begin(), ring.end());
  return ring;
}

}  // namespace

double DoorSwing::width() const { return element ? Length(element->shape) : 0.0; }

DoorSwing SwingOfDoor(const Layout& layout, const Element& element, int level) {
  const Segment& s = element.shape;
  const std::vector<int> rooms = layout.RoomsOnLevel(level);
  const Point n = LeftNormal(s);
  int left = -1, right = -1;
  RoomsBeside(layout, rooms, s, &left, &right);
  int into = left >= 0 ? left : right;
  if (left >= 0 && right >= 0) {
    bool staircase_hall = false;
    if (layout.LevelCount() > 1)
      for (int r : rooms) staircase_hall = staircase_hall || layout.rooms[r].category == Category::kUtilityRoom;
    const Room& l = layout.rooms[left];
    const Room& r = layout.rooms[right];
    if (Rank(l, staircase_hall) != Rank(r, staircase_hall)) {
      into = Rank(l, staircase_hall) < Rank(r, staircase_hall) ? left : right;
    } else {
      into = Area(l.polygon) <= Area(r.polygon) ? left : right;
    }
  }
  double side = (into >= 0 && into == right) ? -1.0 : 1.0;
  if (element.kind == ElementKind::kEntrance) {
    const Point in = Scaled(Outward(layout, rooms, s), -1.0);
    side = (in.x * n.x + in.y * n.y) >= 0.0 ? 1.0 : -1.0;
    into = side > 0 ? left : right;
  }

  DoorSwing swing;
  swing.element = &element;
  swing.level = level;
  swing.into = into;
  swing.other = into == left ? right : left;
  swing.hinge = s.a;
  swing.free_end = s.b;
  if (into >= 0) {
    double da = 1e300, db = 1e300;
    for (const Point& p : layout.rooms[into].polygon) {
      da = std::min(da, Length({p, s.a}));
      db = std::min(db, Length({p, s.b}));
    }
    if (db < da) std::swap(swing.hinge, swing.free_end);
  }
  const double width = Length(s);
  swing.leaf_side = Scaled(n, side);
  swing.leaf_end = {swing.hinge.x + n.x * (side * width), swing.hinge.y + n.y * (side * width)};
  const Point reach = Scaled(swing.leaf_side, width), back = Scaled(swing.leaf_side, -kDoorStripDepth);
  swing.sweep = CounterClockwise({swing.hinge, swing.free_end, {swing.free_end.x + reach.x, swing.free_end.y + reach.y},
                                  {swing.hinge.x + reach.x, swing.hinge.y + reach.y}});
  swing.strip = CounterClockwise({swing.hinge, swing.free_end, {swing.free_end.x + back.x, swing.free_end.y + back.y},
                                  {swing.hinge.x + back.x, swing.hinge.y + back.y}});
  return swing;
}

std::vector<DoorSwing> DoorSwings(const Layout& layout, int level) {
  std::vector<DoorSwing> out;
  for (const auto* list : {&layout.entrances, &layout.doors})
    for (const Element& e : *list)
      if (e.OnLevel(level)) out.push_back(SwingOfDoor(layout, e, level));
  return out;
}

}  // namespace villa
