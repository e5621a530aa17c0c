#include "annotator/fixes.h"

#include <algorithm>
#include <cmath>

#include "annotator/relabel.h"
#include "layout/shape_codec.h"
#include "layout/topology.h"
#include "layout/validate.h"
#include "layout/walls.h"

namespace villa::annotator {
namespace {

constexpr double kWindowWidth = 1.2;     // m, an ordinary window
constexpr double kPanoramicWidth = 3.0;  // m, the widest panoramic window placed
constexpr double kDoorWidth = 0.9;       // m
constexpr double kOpenWidth = 1.6;       // m, the widest open placed
constexpr double kMargin = 0.1;          // m kept clear of corners and other elements

std::vector<int> WindowsOf(const Layout& layout, int room) {
  std::vector<int> out;
  for (int i = 0; i < static_cast<int>(layout.windows.size()); ++i) {
    const Element& w = layout.windows[i];
    if (w.OnLevel(layout.rooms[room].level) && RingHoldsSegment(layout.rooms[room].polygon, w.shape, kOnWallTolerance))
      out.push_back(i);
  }
  return out;
}

struct Link {
  int other;
  bool door;
  std::string element;
};
std::vector<Link> LinksOf(const std::vector<Connection>& connections, int room) {
  std::vector<Link> out;
  for (const Connection& c : connections) {
    if (c.via == Via::kStair) continue;
    if (c.room_a == room) out.push_back({c.room_b, c.via == Via::kDoor, c.element});
    if (c.room_b == room) out.push_back({c.room_a, c.via == Via::kDoor, c.element});
  }
  return out;
}

// The wall pieces of `room` that are exterior (other < 0) or shared with room `other`.
std::vector<Segment> Stretches(const Layout& layout, int room, int other) {
  std::vector<Segment> out;
  for (const WallPiece& piece : RoomWallPieces(layout, room))
    if (piece.neighbour == (other < 0 ? kExterior : other)) out.push_back(piece.segment);
  return out;
}
std::vector<Segment> ExteriorStretches(const Layout& layout, int room) { return Stretches(layout, room, -1); }
std::vector<Segment> SharedStretches(const Layout& layout, int room, int other) { return Stretches(layout, room, other); }

// The intervals along `stretch` (metres from its start) not covered by the given elements.
std::vector<std::pair<double, double>> FreeIntervals(const Segment& stretch, const std::vector<const Element*>& blockers) {
  const Point& a = stretch.a;
  const Point& b = stretch.b;
  double len = Length(stretch);
  std::vector<std::pair<double, double>> cuts;
  for (const Element* e : blockers) {
    Segment s = e->shape;
    double da = std::abs((b.x - a.x) * (s.a.y - a.y) - (b.y - a.y) * (s.a.x - a.x)) / len;
    double db = std::abs((b.x - a.x) * (s.b.y - a.y) - (b.y - a.y) * (s.b.x - a.x)) / len;
    if (da > 1e-6 || db > 1e-6) continue;
    double t0 = ((s.a.x - a.x) * (b.x - a.x) + (s.a.y - a.y) * (b.y - a.y)) / len;
    double t1 = ((s.b.x - a.x) * (b.x - a.x) + (s.b.y - a.y) * (b.y - a.y)) / len;
    if (t0 > t1) std::swap(t0, t1);
    cuts.push_back({t0 - kMargin, t1 + kMargin});
  }
  std::sort(cuts.begin(), cuts.end());
  std::vector<std::pair<double, double>> out;
  double cursor = kMargin;
  for (auto [lo, hi] : cuts) {
    if (lo > cursor) out.push_back({cursor, lo});
    cursor = std::max(cursor, hi);
  }
  if (len - kMargin > cursor) out.push_back({cursor, len - kMargin});
  return out;
}

// A point of `stretch` at distance t from its start, on the 2-decimal grid and exactly on the stretch's
// line (within 1e-7 m), or nothing when rounding would move it off the wall.
std::optional<Point> GridPointAt(const Segment& stretch, double t) {
  const Point& a = stretch.a;
  const Point& b = stretch.b;
  double len = Length(stretch);
  Point p{RoundToFormat(a.x + (b.x - a.x) * t / len), RoundToFormat(a.y + (b.y - a.y) * t / len)};
  double off = std::abs((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)) / len;
  if (off > 1e-7) return std::nullopt;
  return p;
}

// Places a segment of width in [min_width, want] centred in the widest free interval of the stretches.
std::optional<Segment> Place(const std::vector<Segment>& stretches, const std::vector<const Element*>& blockers,
                             double min_width, double want) {
  struct Candidate {
    const Segment* stretch;
    double lo, hi;
  };
  std::vector<Candidate> candidates;
  for (const Segment& s : stretches)
    for (auto [lo, hi] : FreeIntervals(s, blockers))
      if (hi - lo >= min_width + 0.02) candidates.push_back({&s, lo, hi});
  // Axis-aligned walls first (their points round exactly), then the widest room.
  std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
    auto axis = [](const Segment* s) { return std::abs(s->a.x - s->b.x) < 1e-9 || std::abs(s->a.y - s->b.y) < 1e-9; };
    if (axis(x.stretch) != axis(y.stretch)) return axis(x.stretch);
    return (x.hi - x.lo) > (y.hi - y.lo);
  });
  for (const Candidate& c : candidates) {
    double width = std::min(want, c.hi - c.lo);
    double mid = (c.lo + c.hi) / 2;
    // Try the centred placement, then shrinking it, then the interval's own ends.
    for (double w = width; w >= min_width + 0.01; w -= 0.05) {
      auto p = GridPointAt(*c.stretch, mid - w / 2);
      auto q = GridPointAt(*c.stretch, mid + w / 2);
      if (p && q && Length({*p, *q}) >= min_width + 1e-6) return Segment{*p, *q};
    }
    auto p = GridPointAt(*c.stretch, c.lo);
    auto q = GridPointAt(*c.stretch, c.hi);
    if (p && q && Length({*p, *q}) >= min_width + 1e-6) return Segment{*p, *q};
  }
  return std::nullopt;
}

std::vector<const Element*> ElementsOnLevel(const Layout& layout, int level, std::initializer_list<ElementKind> kinds) {
  std::vector<const Element*> out;
  for (ElementKind kind : kinds)
    for (const Element& e : layout.elements(kind))
      if (e.OnLevel(level)) out.push_back(&e);
  return out;
}

int FindElement(const std::vector<Element>& elements, const std::string& name) {
  for (int i = 0; i < static_cast<int>(elements.size()); ++i)
    if (elements[i].name == name) return i;
  return -1;
}

bool CanPlaceExterior(const Layout& layout, int room, double min_width, double want) {
  int level = layout.rooms[room].level;
  return Place(ExteriorStretches(layout, room), ElementsOnLevel(layout, level, {ElementKind::kWindow, ElementKind::kEntrance}),
               min_width, want)
      .has_value();
}

bool CanPlaceShared(const Layout& layout, int room, int other, double min_width, double want) {
  int level = layout.rooms[room].level;
  return Place(SharedStretches(layout, room, other), ElementsOnLevel(layout, level, {ElementKind::kDoor, ElementKind::kOpen}),
               min_width, want)
      .has_value();
}

}  // namespace

std::vector<Fix> FindFixes(const Layout& layout) {
  std::vector<Fix> fixes;
  auto connections = RoomConnections(layout);
  int n = static_cast<int>(layout.rooms.size());
  for (int r = 0; r < n; ++r) {
    const Room& room = layout.rooms[r];
    std::string name = room.name();
    auto windows = WindowsOf(layout, r);
    auto links = LinksOf(connections, r);
    if ((room.category == Category::kKitchen || room.category == Category::kBathroom) && windows.empty() &&
        CanPlaceExterior(layout, r, 0.6, kWindowWidth))
      fixes.push_back({FixKind::kAddWindow, 9, name, "", "add a window on " + name + "'s exterior wall"});
    if (room.category == Category::kBalcony) {
      bool panoramic = std::any_of(windows.begin(), windows.end(), [&](int w) { return layout.windows[w].panoramic; });
      if (!panoramic && !windows.empty()) {
        // The longest window becomes panoramic.
        int best = *std::max_element(windows.begin(), windows.end(), [&](int x, int y) {
          return Length(layout.windows[x].shape) < Length(layout.windows[y].shape);
        });
        fixes.push_back({FixKind::kMakePanoramic, 9, name, layout.windows[best].name,
                         "make window " + layout.windows[best].name + " of " + name + " panoramic"});
      } else if (!panoramic && CanPlaceExterior(layout, r, 0.6, kPanoramicWidth)) {
        fixes.push_back({FixKind::kAddPanoramic, 9, name, "", "add a panoramic window on " + name + "'s exterior wall"});
      }
      bool door = std::any_of(links.begin(), links.end(), [](const Link& l) { return l.door; });
      bool open = false;
      for (const Link& l : links) {
        if (l.door) continue;
        open = true;
        fixes.push_back({FixKind::kOpenToDoor, 9, name, l.element, "make the open " + l.element + " of " + name + " a door"});
      }
      if (!door && !open) {
        // The neighbour sharing the longest wall (not another balcony).
        int best = -1;
        double best_len = 0;
        for (int o : layout.RoomsOnLevel(room.level)) {
          if (o == r || layout.rooms[o].category == Category::kBalcony) continue;
          double len = 0;
          for (const Segment& s : SharedStretches(layout, r, o)) len = std::max(len, Length(s));
          if (len > best_len && CanPlaceShared(layout, r, o, 0.8, kDoorWidth)) {
            best = o;
            best_len = len;
          }
        }
        if (best >= 0)
          fixes.push_back({FixKind::kAddDoor, 9, name, layout.rooms[best].name(),
                           "add a door between " + name + " and " + layout.rooms[best].name()});
      }
    }
    if (room.category == Category::kKitchen) {
      std::vector<int> dining;
      for (int o : layout.RoomsOnLevel(room.level))
        if (layout.rooms[o].category == Category::kDiningRoom) dining.push_back(o);
      bool linked = std::any_of(links.begin(), links.end(),
                                [&](const Link& l) { return layout.rooms[l.other].category == Category::kDiningRoom; });
      if (!dining.empty() && !linked) {
        for (int d : dining)
          if (CanPlaceShared(layout, r, d, 0.8, kOpenWidth)) {
            fixes.push_back({FixKind::kAddOpen, 10, name, layout.rooms[d].name(),
                             "open " + name + " to " + layout.rooms[d].name()});
            break;
          }
      }
    }
    if (room.category == Category::kLivingRoom) {
      bool linked = std::any_of(links.begin(), links.end(), [&](const Link& l) {
        Category c = layout.rooms[l.other].category;
        return c == Category::kKitchen || c == Category::kDiningRoom;
      });
      if (!linked) {
        for (int o : layout.RoomsOnLevel(room.level)) {
          Category c = layout.rooms[o].category;
          if ((c == Category::kKitchen || c == Category::kDiningRoom) && CanPlaceShared(layout, r, o, 0.8, kDoorWidth)) {
            fixes.push_back({FixKind::kAddDoor, 10, name, layout.rooms[o].name(),
                             "add a door between " + name + " and " + layout.rooms[o].name()});
            break;
          }
        }
      }
    }
  }
  // Rule 10, nested rooms: a violation naming an open means that open must be a door.
  for (const Violation& v : ValidateLayout(layout).violations) {
    if (v.rule != 10) continue;
    for (const std::string& element : v.elements) {
      if (FindElement(layout.opens, element) < 0) continue;
      bool dup = std::any_of(fixes.begin(), fixes.end(),
                             [&](const Fix& f) { return f.kind == FixKind::kOpenToDoor && f.other == element; });
      if (!dup) {
        std::string room = v.elements.empty() ? "" : v.elements.front();
        fixes.push_back({FixKind::kOpenToDoor, 10, room, element, "make the open " + element + " a door"});
      }
    }
  }
  return fixes;
}

Result<Layout> ApplyFix(const Layout& layout, const Fix& fix) {
  Layout out = layout;
  int r = out.FindRoom(fix.room);
  auto fail = [&](const std::string& why) { return Error{fix.room + ": cannot " + fix.title + ": " + why}; };
  switch (fix.kind) {
    case FixKind::kAddWindow:
    case FixKind::kAddPanoramic: {
      if (r < 0) return fail("no such room");
      bool panoramic = fix.kind == FixKind::kAddPanoramic;
      int level = out.rooms[r].level;
      auto segment = Place(ExteriorStretches(out, r), ElementsOnLevel(out, level, {ElementKind::kWindow, ElementKind::kEntrance}),
                           0.6, panoramic ? kPanoramicWidth : kWindowWidth);
      if (!segment) return fail("no free exterior wall of 0.6 m");
      Element window;
      window.kind = ElementKind::kWindow;
      window.shape = *segment;
      window.level = level;
      window.panoramic = panoramic;
      window.name = "window";
      window.name = SchemeElementName(out, window);
      out.windows.push_back(window);
      return out;
    }
    case FixKind::kMakePanoramic: {
      int w = FindElement(out.windows, fix.other);
      if (w < 0) return fail("no window " + fix.other);
      out.windows[w].panoramic = true;
      return out;
    }
    case FixKind::kOpenToDoor: {
      int o = FindElement(out.opens, fix.other);
      if (o < 0) return fail("no open " + fix.other);
      Element door = out.opens[o];
      door.kind = ElementKind::kDoor;
      if (std::any_of(out.doors.begin(), out.doors.end(), [&](const Element& d) { return d.name == door.name; }))
        door.name = SchemeElementName(out, door);
      out.opens.erase(out.opens.begin() + o);
      out.doors.push_back(door);
      return out;
    }
    case FixKind::kAddDoor:
    case FixKind::kAddOpen: {
      int other = out.FindRoom(fix.other);
      if (r < 0 || other < 0) return fail("no such room");
      bool door = fix.kind == FixKind::kAddDoor;
      int level = out.rooms[r].level;
      auto segment = Place(SharedStretches(out, r, other), ElementsOnLevel(out, level, {ElementKind::kDoor, ElementKind::kOpen}),
                           0.8, door ? kDoorWidth : kOpenWidth);
      if (!segment) return fail("no free shared wall of 0.8 m");
      Element e;
      e.kind = door ? ElementKind::kDoor : ElementKind::kOpen;
      e.shape = *segment;
      e.level = level;
      e.name = door ? "door" : "open";
      e.name = SchemeElementName(out, e);
      out.elements(e.kind).push_back(e);
      return out;
    }
  }
  return fail("unknown fix");
}

std::vector<std::string> ApplyAllFixes(Layout& layout) {
  std::vector<std::string> made;
  for (int round = 0; round < 4; ++round) {
    auto fixes = FindFixes(layout);
    if (fixes.empty()) break;
    bool any = false;
    for (const Fix& fix : fixes) {
      auto fixed = ApplyFix(layout, fix);
      if (!fixed) continue;
      layout = std::move(fixed).value();
      made.push_back(fix.title);
      any = true;
    }
    if (!any) break;
  }
  return made;
}

}  // namespace villa::annotator
