#include "layout/topology.h"

#include <algorithm>
#include <deque>

#include "layout/geometry.h"

namespace villa {

namespace {

// The rooms of each level with their bounding boxes, made once for the many segment queries of a layout
// (every door and open), so a query costs the rooms of its level, not a pass over the whole building.
struct RoomsByLevel {
  std::vector<std::vector<int>> rooms;  // [level]: indices into Layout::rooms, in order
  std::vector<Box2> boxes;              // [room]
  explicit RoomsByLevel(const Layout& layout) : rooms(std::max(layout.LevelCount(), 0)) {
    boxes.reserve(layout.rooms.size());
    for (std::size_t i = 0; i < layout.rooms.size(); ++i) {
      boxes.push_back(BoundingBox(layout.rooms[i].polygon));
      const int level = layout.rooms[i].level;
      if (level >= 0 && level < static_cast<int>(rooms.size())) rooms[level].push_back(static_cast<int>(i));
    }
  }
};

SegmentRooms Along(const Layout& layout, const RoomsByLevel& index, int level, const Segment& segment, double tolerance) {
  SegmentRooms out;
  if (level < 0 || level >= static_cast<int>(index.rooms.size())) return out;
  double length = Length(segment);
  Box2 box = BoundingBox(segment);
  for (int i : index.rooms[level]) {
    if (!index.boxes[i].Touches(box, tolerance)) continue;
    double on = LengthOnBoundary(segment, layout.rooms[i].polygon, tolerance);
    if (on <= tolerance) continue;
    out.touching.push_back(i);
    if (on >= length - tolerance) out.holding.push_back(i);
  }
  return out;
}

}  // namespace

SegmentRooms RoomsAlongSegment(const Layout& layout, int level, const Segment& segment, double tolerance) {
  return Along(layout, RoomsByLevel(layout), level, segment, tolerance);
}

std::vector<int> RoomsHolding(const Layout& layout, const Element& element, double tolerance) {
  const RoomsByLevel index(layout);
  std::vector<int> out;
  for (int level = 0; level < layout.LevelCount(); ++level)
    if (element.OnLevel(level))
      for (int room : Along(layout, index, level, element.shape, tolerance).holding) out.push_back(room);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<Connection> RoomConnections(const Layout& layout, double tolerance) {
  std::vector<Connection> out;
  const int levels = layout.LevelCount();
  const RoomsByLevel index(layout);
  for (ElementKind kind : {ElementKind::kDoor, ElementKind::kOpen}) {
    for (const Element& element : layout.elements(kind)) {
      for (int level = 0; level < levels; ++level) {
        if (!element.OnLevel(level)) continue;
        SegmentRooms rooms = Along(layout, index, level, element.shape, tolerance);
        if (rooms.holding.size() != 2) continue;
        out.push_back({rooms.holding[0], rooms.holding[1], kind == ElementKind::kDoor ? Via::kDoor : Via::kOpen,
                       element.name});
      }
    }
  }
  // Staircase links: utility rooms with the same polygon on adjacent levels.
  for (int level = 0; level + 1 < levels; ++level)
    for (int i : index.rooms[level]) {
      if (layout.rooms[i].category != Category::kUtilityRoom) continue;
      for (int j : index.rooms[level + 1])
        if (layout.rooms[j].category == Category::kUtilityRoom && SameRing(layout.rooms[i].polygon, layout.rooms[j].polygon, tolerance))
          out.push_back({i, j, Via::kStair, "stair"});
    }
  return out;
}

std::vector<int> EntranceRooms(const Layout& layout, double tolerance) {
  const RoomsByLevel index(layout);
  std::vector<int> out;
  for (const Element& entrance : layout.entrances) {
    for (int room : Along(layout, index, 0, entrance.shape, tolerance).touching)
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
