#include "layout/topology.h"

#include <algorithm>
#include <deque>

#include "layout/geometry.h"

namespace villa {

SegmentRooms RoomsAlongSegment(const Layout& layout, int level, const Segment& segment, double tolerance) {
  SegmentRooms out;
  double length = Length(segment);
  Box2 box = BoundingBox(segment);
  for (std::size_t i = 0; i < layout.rooms.size(); ++i) {
    const Room& room = layout.rooms[i];
    if (room.level != level || !BoundingBox(room.polygon).Touches(box, tolerance)) continue;
    double on = LengthOnBoundary(segment, room.polygon, tolerance);
    if (on <= tolerance) continue;
    out.touching.push_back(static_cast<int>(i));
    if (on >= length - tolerance) out.holding.push_back(static_cast<int>(i));
  }
  return out;
}

std::vector<int> RoomsHolding(const Layout& layout, const Element& element, double tolerance) {
  std::vector<int> out;
  for (int level = 0; level < layout.LevelCount(); ++level)
    if (element.OnLevel(level))
      for (int room : RoomsAlongSegment(layout, level, element.shape, tolerance).holding) out.push_back(room);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<Connection> RoomConnections(const Layout& layout, double tolerance) {
  std::vector<Connection> out;
  const int levels = layout.LevelCount();
  for (ElementKind kind : {ElementKind::kDoor, ElementKind::kOpen}) {
    for (const Element& element : layout.elements(kind)) {
      for (int level = 0; level < levels; ++level) {
        if (!element.OnLevel(level)) continue;
        SegmentRooms rooms = RoomsAlongSegment(layout, level, element.shape, tolerance);
        if (rooms.holding.size() != 2) continue;
        out.push_back({rooms.holding[0], rooms.holding[1], kind == ElementKind::kDoor ? Via::kDoor : Via::kOpen,
                       element.name});
      }
    }
  }
  // Staircase links: utility rooms with the same polygon on adjacent levels.
  for (std::size_t i = 0; i < layout.rooms.size(); ++i) {
    const Room& lower = layout.rooms[i];
    if (lower.category != Category::kUtilityRoom) continue;
    for (std::size_t j = 0; j < layout.rooms.size(); ++j) {
      const Room& upper = layout.rooms[j];
      if (upper.category != Category::kUtilityRoom || upper.level != lower.level + 1) continue;
      if (SameRing(lower.polygon, upper.polygon, tolerance))
        out.push_back({static_cast<int>(i), static_cast<int>(j), Via::kStair, "stair"});
    }
  }
  return out;
}

std::vector<int> EntranceRooms(const Layout& layout, double tolerance) {
  std::vector<int> out;
  for (const Element& entrance : layout.entrances) {
    for (int room : RoomsAlongSegment(layout, 0, entrance.shape, tolerance).touching)
      if (std::find(out.begin(), out.end(), room) == out.end()) out.push_back(room);
  }
  return out;
}

std::vector<bool> ReachableRooms(const Layout& layout, const std::vector<Connection>& connections,
                                 const std::vector<int>& start) {
  const std::size_t n = layout.rooms.size();
  std::vector<std::vector<int>> adjacent(n);
  for (const auto& c : connections) {
    if (c.room_a < 0 || c.room_b < 0 || static_cast<std::size_t>(c.room_a) >= n || static_cast<std::size_t>(c.room_b) >= n) continue;
    adjacent[c.room_a].push_back(c.room_b);
    adjacent[c.room_b].push_back(c.room_a);
  }
  std::vector<bool> reached(n, false);
  std::deque<int> queue;
  for (int s : start)
    if (s >= 0 && static_cast<std::size_t>(s) < n && !reached[s]) reached[s] = true, queue.push_back(s);
  while (!queue.empty()) {
    int room = queue.front();
    queue.pop_front();
    for (int next : adjacent[room])
      if (!reached[next]) reached[next] = true, queue.push_back(next);
  }
  return reached;
}

}  // namespace villa
