// A brief's requirements checked against a layout (the footprint class by layout/footprint.h).
#include <algorithm>
#include <cmath>
#include <set>

#include "generator/text/brief.h"
#include "layout/topology.h"

namespace villa {
namespace {

using Json = nlohmann::ordered_json;

std::string Where(int level) {
  if (level == kAnyLevel) return "";
  if (level == kUpperLevels) return " on the upper floors";
  if (level == kEachLevel) return " on each floor";
  return " on level " + std::to_string(level);
}

std::string CountText(int min, int max) {
  if (max < 0) return "at least " + std::to_string(min);
  if (min == max) return std::to_string(min);
  return std::to_string(min) + " to " + std::to_string(max);
}

// Levels a requirement at `level` is checked on, as groups counted together.
std::vector<std::vector<int>> LevelGroups(int level, int level_count) {
  std::vector<std::vector<int>> groups;
  if (level == kAnyLevel) {
    std::vector<int> all;
    for (int l = 0; l < level_count; ++l) all.push_back(l);
    groups.push_back(all);
  } else if (level == kUpperLevels) {
    std::vector<int> upper;
    for (int l = 1; l < level_count; ++l) upper.push_back(l);
    groups.push_back(upper);
  } else if (level == kEachLevel) {
    for (int l = 0; l < level_count; ++l) groups.push_back({l});
    if (groups.empty()) groups.push_back({});
  } else {
    groups.push_back({level});
  }
  return groups;
}

bool InGroup(const std::vector<int>& group, int level) {
  return std::find(group.begin(), group.end(), level) != group.end();
}

// The room of `level` whose boundary holds the segment (a window): -1 if none or several.
int RoomOfWindow(const Layout& layout, const Element& window) {
  int level = window.level == kAllLevels ? 0 : window.level;
  SegmentRooms rooms = RoomsAlongSegment(layout, level, window.shape);
  if (rooms.holding.size() == 1) return rooms.holding[0];
  return -1;
}

}  // namespace

int BriefCheck::met() const {
  return static_cast<int>(std::count_if(results.begin(), results.end(), [](const auto& r) { return r.met; }));
}

double BriefCheck::adherence() const { return results.empty() ? 1.0 : static_cast<double>(met()) / results.size(); }

std::vector<RequirementResult> BriefCheck::unmet() const {
  std::vector<RequirementResult> out;
  for (const auto& r : results)
    if (!r.met) out.push_back(r);
  return out;
}

BriefCheck CheckBrief(const Brief& brief, const Layout& layout) {
  BriefCheck check;
  const int levels = layout.LevelCount();
  auto push = [&](std::string requirement, bool met, std::string detail, std::string source) {
    check.results.push_back({std::move(requirement), met, std::move(detail), std::move(source)});
  };
  auto count = [&](Category category, const std::vector<int>& group) {
    int n = 0;
    for (const Room& r : layout.rooms)
      if (r.category == category && InGroup(group, r.level)) ++n;
    return n;
  };

  if (brief.floors) {
    push(std::to_string(*brief.floors) + (*brief.floors == 1 ? " floor" : " floors"), levels == *brief.floors,
         "has " + std::to_string(levels), brief.floors_source ? brief.floors_source->text : "");
  } else if (brief.floors_min) {
    push("at least " + std::to_string(*brief.floors_min) + " floors", levels >= *brief.floors_min,
         "has " + std::to_string(levels), "");
  }
  if (brief.shape) {
    auto shape = ClassifyFootprint(layout, 0);
    push(std::string(ShapeClassName(*brief.shape)) + " footprint", shape && *shape == *brief.shape,
         shape ? "footprint is " + std::string(ShapeClassName(*shape)) : "no ground floor",
         brief.shape_source ? brief.shape_source->text : "");
  }
  if (brief.unsupported_shape) {
    push("footprint \"" + brief.unsupported_shape->text + "\"", false,
         "the partitioner makes rectangle, L, U, T, H, cross, hexagon, octagon, trapezoid, bay, angled-wing and irregular (polygonal) footprints only",
         brief.unsupported_shape->text);
  }
  for (const auto& r : brief.rooms) {
    bool met = true;
    std::string detail;
    for (const auto& group : LevelGroups(r.level, levels)) {
      int n = count(r.category, group);
      bool ok = n >= r.min && (r.max < 0 || n <= r.max);
      if (!ok) met = false;
      std::string where = r.level == kEachLevel && group.size() == 1 ? " on level " + std::to_string(group[0]) : "";
      if (!ok || detail.empty()) detail = "found " + std::to_string(n) + where;
    }
    push(CountText(r.min, r.max) + " " + std::string(CategoryName(r.category)) + Where(r.level), met, detail,
         r.source.text);
  }
  const std::vector<Connection> links = RoomConnections(layout);
  for (const auto& c : brief.connections) {
    auto matches_kind = [&](Via via) {
      if (via == Via::kStair) return false;
      if (c.kind == LinkKind::kOpen) return via == Via::kOpen;
      if (c.kind == LinkKind::kDoor) return via == Via::kDoor;
      return true;
    };
    auto is_to = [&](Category cat) { return std::find(c.to.begin(), c.to.end(), cat) != c.to.end(); };
    // Rooms of `from` linked as asked, per room index.
    std::set<int> linked;
    for (const auto& l : links) {
      if (!matches_kind(l.via)) continue;
      const Room& a = layout.rooms[l.room_a];
      const Room& b = layout.rooms[l.room_b];
      if (a.level != b.level) continue;
      if (a.category == c.from && is_to(b.category)) linked.insert(l.room_a);
      if (b.category == c.from && is_to(a.category)) linked.insert(l.room_b);
    }
    bool met = true;
    std::string detail;
    for (const auto& group : LevelGroups(c.level, levels)) {
      int from_rooms = 0, ok_rooms = 0;
      for (int i = 0; i < static_cast<int>(layout.rooms.size()); ++i) {
        const Room& r = layout.rooms[i];
        if (r.category != c.from || !InGroup(group, r.level)) continue;
        ++from_rooms;
        if (linked.count(i)) ++ok_rooms;
      }
      bool ok = c.every ? (from_rooms > 0 && ok_rooms == from_rooms) : ok_rooms > 0;
      if (!ok) {
        met = false;
        detail = from_rooms == 0 ? "no " + std::string(CategoryName(c.from)) +
                                        (group.size() == 1 ? " on level " + std::to_string(group[0]) : "")
                                 : std::to_string(ok_rooms) + " of " + std::to_string(from_rooms) + " " +
                                       std::string(CategoryName(c.from)) + " linked so";
      }
    }
    std::string to;
    for (Category t : c.to) to += (to.empty() ? "" : " or ") + std::string(CategoryName(t));
    std::string how = c.kind == LinkKind::kOpen ? " open to " : c.kind == LinkKind::kDoor ? " with a door to " : " connected to ";
    push(std::string(c.every ? "every " : "") + std::string(CategoryName(c.from)) + how + to + Where(c.level), met,
         met ? "" : detail, c.source.text);
  }
  for (const auto& p : brief.panoramic) {
    bool met = false;
    for (const auto& group : LevelGroups(p.level == kEachLevel ? kAnyLevel : p.level, levels)) {
      for (const Element& w : layout.windows) {
        if (!w.panoramic) continue;
        int room = RoomOfWindow(layout, w);
        if (room < 0) continue;
        const Room& r = layout.rooms[room];
        if (!InGroup(group, r.level)) continue;
        if (p.category == Category::kRoom || r.category == p.category) met = true;
      }
    }
    std::string what = p.category == Category::kRoom ? "a panoramic window" : "a panoramic window in a " + std::string(CategoryName(p.category));
    push(what + Where(p.level), met, met ? "" : "none found", p.source.text);
  }
  if (!brief.entrance.empty()) {
    std::vector<int> entry = EntranceRooms(layout);
    for (const auto& e : brief.entrance) {
      bool met = false;
      std::string found;
      for (int r : entry) {
        if (layout.rooms[r].category == e.category) met = true;
        found += (found.empty() ? "" : ", ") + layout.rooms[r].name();
      }
      push("entrance into a " + std::string(CategoryName(e.category)), met,
           met ? "" : "entrance leads into " + (found.empty() ? std::string("no room") : found), e.source.text);
    }
  }
  for (const auto& s : brief.sides) {
    bool met = false;
    for (const auto& group : LevelGroups(s.level == kEachLevel ? kAnyLevel : s.level, levels)) {
      for (int level : group) {
        double minx = 1e300, maxx = -1e300, miny = 1e300, maxy = -1e300;
        for (int r : layout.RoomsOnLevel(level))
          for (const Point& p : layout.rooms[r].polygon) {
            minx = std::min(minx, p.x); maxx = std::max(maxx, p.x);
            miny = std::min(miny, p.y); maxy = std::max(maxy, p.y);
          }
        for (int r : layout.RoomsOnLevel(level)) {
          const Room& room = layout.rooms[r];
          if (room.category != s.category) continue;
          // centroid of the polygon
          double a = 0, cx = 0, cy = 0;
          const Ring& ring = room.polygon;
          for (std::size_t i = 0; i < ring.size(); ++i) {
            const Point& p = ring[i];
            const Point& q = ring[(i + 1) % ring.size()];
            double cross = p.x * q.y - q.x * p.y;
            a += cross;
            cx += (p.x + q.x) * cross;
            cy += (p.y + q.y) * cross;
          }
          if (std::abs(a) < 1e-12) continue;
          cx /= 3 * a;
          cy /= 3 * a;
          double w = maxx - minx, h = maxy - miny;
          if ((s.side == "north" && cy >= maxy - h / 3) || (s.side == "south" && cy <= miny + h / 3) ||
              (s.side == "east" && cx >= maxx - w / 3) || (s.side == "west" && cx <= minx + w / 3))
            met = true;
        }
      }
    }
    push(std::string(CategoryName(s.category)) + " on the " + s.side + " side" + Where(s.level), met,
         met ? "" : "not in the outer third towards " + s.side, s.source.text);
  }
  return check;
}

nlohmann::ordered_json BriefCheckToJson(const BriefCheck& check) {
  Json results = Json::array();
  for (const auto& r : check.results) {
    Json e{{"requirement", r.requirement}, {"met", r.met}};
    if (!r.detail.empty()) e["detail"] = r.detail;
    if (!r.source.empty()) e["source"] = r.source;
    results.push_back(e);
  }
  return Json{{"met", check.met()}, {"total", check.total()}, {"adherence", check.adherence()}, {"results", results}};
}

}  // namespace villa
