// A brief's requirements checked against a layout, and the footprint classifier they use.
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

bool PointInRing(const Ring& ring, Point p) {
  bool inside = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Point& a = ring[i];
    const Point& b = ring[j];
    if ((a.y > p.y) != (b.y > p.y)) {
      double x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (p.x < x) inside = !inside;
    }
  }
  return inside;
}

double DistanceToSegment(Point p, Point a, Point b) {
  double dx = b.x - a.x, dy = b.y - a.y;
  double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
  double qx = a.x + t * dx - p.x, qy = a.y + t * dy - p.y;
  return std::sqrt(qx * qx + qy * qy);
}

bool OnRingBoundary(const Ring& ring, Point p, double tolerance) {
  for (std::size_t i = 0; i < ring.size(); ++i)
    if (DistanceToSegment(p, ring[i], ring[(i + 1) % ring.size()]) <= tolerance) return true;
  return false;
}

}  // namespace

std::optional<ShapeClass> ClassifyFootprint(const Layout& layout, int level) {
  std::vector<int> rooms = layout.RoomsOnLevel(level);
  if (rooms.empty()) return std::nullopt;
  const double tol = 1e-6;
  // A slanted edge on the outside (not shared with another room of the level) makes it irregular.
  for (int r : rooms) {
    const Ring& ring = layout.rooms[r].polygon;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      Point a = ring[i], b = ring[(i + 1) % ring.size()];
      if (std::abs(a.x - b.x) <= tol || std::abs(a.y - b.y) <= tol) continue;
      Point mid{(a.x + b.x) / 2, (a.y + b.y) / 2};
      bool shared = false;
      for (int o : rooms)
        if (o != r && OnRingBoundary(layout.rooms[o].polygon, mid, 1e-4)) shared = true;
      if (!shared) return ShapeClass::kIrregular;
    }
  }
  // Orthogonal: which cells of the compressed grid are empty, and where do the empty parts touch the
  // bounding box?
  std::vector<double> xs, ys;
  for (int r : rooms)
    for (const Point& p : layout.rooms[r].polygon) {
      xs.push_back(p.x);
      ys.push_back(p.y);
    }
  auto unique_sorted = [&](std::vector<double>& v) {
    std::sort(v.begin(), v.end());
    std::vector<double> out;
    for (double x : v)
      if (out.empty() || x - out.back() > 1e-6) out.push_back(x);
    v = out;
  };
  unique_sorted(xs);
  unique_sorted(ys);
  int nx = static_cast<int>(xs.size()) - 1, ny = static_cast<int>(ys.size()) - 1;
  if (nx <= 0 || ny <= 0) return ShapeClass::kIrregular;
  std::vector<int> cell(nx * ny, 0);  // 1 = inside the footprint
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      Point c{(xs[i] + xs[i + 1]) / 2, (ys[j] + ys[j + 1]) / 2};
      for (int r : rooms)
        if (PointInRing(layout.rooms[r].polygon, c)) {
          cell[i * ny + j] = 1;
          break;
        }
    }
  struct Part {
    bool left = false, right = false, bottom = false, top = false;
    int sides() const { return left + right + bottom + top; }
  };
  std::vector<Part> parts;
  std::vector<int> seen(nx * ny, 0);
  for (int start = 0; start < nx * ny; ++start) {
    if (cell[start] || seen[start]) continue;
    Part part;
    std::vector<int> stack{start};
    seen[start] = 1;
    while (!stack.empty()) {
      int c = stack.back();
      stack.pop_back();
      int i = c / ny, j = c % ny;
      if (i == 0) part.left = true;
      if (i == nx - 1) part.right = true;
      if (j == 0) part.bottom = true;
      if (j == ny - 1) part.top = true;
      const int di[4] = {1, -1, 0, 0}, dj[4] = {0, 0, 1, -1};
      for (int d = 0; d < 4; ++d) {
        int a = i + di[d], b = j + dj[d];
        if (a < 0 || b < 0 || a >= nx || b >= ny) continue;
        int n = a * ny + b;
        if (!cell[n] && !seen[n]) {
          seen[n] = 1;
          stack.push_back(n);
        }
      }
    }
    parts.push_back(part);
  }
  auto corner = [](const Part& p) { return p.sides() == 2 && !(p.left && p.right) && !(p.top && p.bottom); };
  auto notch = [](const Part& p) { return p.sides() == 1; };
  if (parts.empty()) return ShapeClass::kRectangle;
  if (parts.size() == 1) {
    if (corner(parts[0])) return ShapeClass::kL;
    if (notch(parts[0])) return ShapeClass::kU;
    return ShapeClass::kIrregular;
  }
  if (parts.size() == 2) {
    const Part& a = parts[0];
    const Part& b = parts[1];
    if (corner(a) && corner(b) &&
        ((a.left && b.left) || (a.right && b.right) || (a.top && b.top) || (a.bottom && b.bottom)))
      return ShapeClass::kT;
    if (notch(a) && notch(b) && ((a.left && b.right) || (a.right && b.left) || (a.top && b.bottom) || (a.bottom && b.top)))
      return ShapeClass::kH;
  }
  return ShapeClass::kIrregular;
}

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
         "the partitioner makes rectangle, L, U, T, H and irregular (polygonal) footprints only",
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
