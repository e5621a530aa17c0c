#include "layout/metrics.h"

#include "layout/geometry.h"
#include "layout/topology.h"
#include "layout/validate.h"

namespace villa {

LayoutMetrics MeasureLayout(const Layout& layout) {
  ValidateOptions geometric;
  geometric.check_architecture = false;
  return MeasureLayout(layout, ValidateLayout(layout, geometric));
}

LayoutMetrics MeasureLayout(const Layout& layout, const ValidationReport& report) {
  LayoutMetrics m;
  m.parsed = true;
  m.format_success = report.geometric_ok();

  const int levels = layout.LevelCount();
  const std::vector<Connection> connections = RoomConnections(layout);
  m.rooms = static_cast<int>(layout.rooms.size());

  // RR (paper): per floor, from the floor's utility room through that floor's doors and opens; a
  // one-floor building without a utility room starts from the entrance room.
  std::vector<Connection> flat;
  for (const auto& c : connections)
    if (c.via != Via::kStair) flat.push_back(c);
  const std::vector<int> entrance = EntranceRooms(layout);
  for (int level = 0; level < levels; ++level) {
    std::vector<int> start;
    for (int r : layout.RoomsOnLevel(level))
      if (layout.rooms[r].category == Category::kUtilityRoom) start.push_back(r);
    if (start.empty() && levels == 1) start = entrance;
    std::vector<bool> reached = ReachableRooms(layout, flat, start);
    for (int r : layout.RoomsOnLevel(level)) m.rooms_reached_per_floor += reached[r];
  }

  // RR, whole building from the entrance through doors, opens and stairs.
  std::vector<bool> reached = ReachableRooms(layout, connections, entrance);
  for (bool r : reached) m.rooms_reached_from_entrance += r;

  // VCR: staircase of L (its utility rooms) against the stair hole of L+1 (the utility rooms there).
  if (levels >= 2) {
    m.floor_pairs = levels - 1;
    for (int level = 0; level + 1 < levels; ++level) {
      bool connected = false;
      for (int d : layout.RoomsOnLevel(level)) {
        if (layout.rooms[d].category != Category::kUtilityRoom) continue;
        for (int u : layout.RoomsOnLevel(level + 1))
          if (layout.rooms[u].category == Category::kUtilityRoom && RingProblem(layout.rooms[d].polygon).empty() &&
              RingProblem(layout.rooms[u].polygon).empty() &&
              IntersectionArea(layout.rooms[d].polygon, layout.rooms[u].polygon) > kTolerance)
            connected = true;
      }
      m.floor_pairs_connected += connected;
    }
  }
  return m;
}

void MetricsSummary::Add(const LayoutMetrics& m) {
  ++outputs;
  format_successes += m.parsed && m.format_success;
  rooms += m.rooms;
  rooms_reached_per_floor += m.rooms_reached_per_floor;
  rooms_reached_from_entrance += m.rooms_reached_from_entrance;
  floor_pairs += m.floor_pairs;
  floor_pairs_connected += m.floor_pairs_connected;
}

std::optional<double> MetricsSummary::fsr() const {
  if (outputs == 0) return std::nullopt;
  return static_cast<double>(format_successes) / outputs;
}
std::optional<double> MetricsSummary::rr() const {
  if (rooms == 0) return std::nullopt;
  return static_cast<double>(rooms_reached_per_floor) / rooms;
}
std::optional<double> MetricsSummary::rr_entrance() const {
  if (rooms == 0) return std::nullopt;
  return static_cast<double>(rooms_reached_from_entrance) / rooms;
}
std::optional<double> MetricsSummary::vcr() const {
  if (floor_pairs == 0) return std::nullopt;
  return static_cast<double>(floor_pairs_connected) / floor_pairs;
}

}  // namespace villa
