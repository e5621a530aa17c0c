// ValidateLayout: the rules 1-10 of FORMAT.md, made precise. docs/RULES.md says the same for users.
//
// Tolerance t (options.tolerance, 1e-6 m): lengths and distances within t are equal; areas within t
// (read as m2) are zero.
//
//  1. Every room polygon is valid (Boost.Geometry is_valid: simple, no spikes, >= 3 corners) with positive
//     area; every 1D element is longer than t. Levels are 0..n-1 with rooms on each, and every element's
//     level names one of them (or is absent: every level). Rooms of a level pairwise overlap by at most t
//     m2 (the overlap area is reported). Their union is one polygon without holes: rooms joined through
//     shared edges longer than t form one piece (else the pieces and their areas are reported), and the
//     exterior boundary (every edge part not shared with another room) closes into rings of which none
//     is a hole (a clockwise ring, reported with its area and the rooms around it).
//  2. For each level L+1: the area of its footprint outside level L's footprint is at most t m2 (summed
//     over room pairs, rooms of a level being disjoint), which also makes it no larger.
//  3. Doors, opens and interior walls: exactly two rooms of their level hold the whole segment on their
//     boundaries (reported: the rooms it touches and how far it is off the nearest shared boundary, or how
//     much of it runs past one). Windows and the entrance: exactly one room of their level touches the
//     segment and holds all of it (so it lies on the footprint's exterior boundary). The entrance is on
//     level 0; a layout has at most one entrance (none breaks rule 8: nothing is reachable).
//  4. Every shared boundary between two rooms of a level is covered by the union of the interior walls
//     and opens of that level (doors sit inside walls and do not count); the uncovered length is reported.
//  5. Doors and opens are >= 0.8 m long, windows >= 0.6 m; a room's width (RoomWidth in geometry.h: the
//     convex hull's minimum caliper width, and the gap between facing anti-parallel edges of a thin arm)
//     is >= 1.0 m. A triangle is as wide as its smallest height: sharp corners alone are fine.
//  6. At most 3 levels; at most 6 rooms a level.
//  7. With two or more levels: every level has a 4 x 4 m utility-room (a square of side 4 within t,
//     any orientation); one such room stands at the same coordinates on every level (same polygon within
//     t); its centroid is more than t away from its level's footprint centroid.
//  8. The layout has an entrance; every room is reachable from the rooms the entrance touches through
//     doors, opens (each in place by rule 3) and staircase links (utility rooms with the same polygon on
//     adjacent levels).
//  9. Every kitchen and bathroom holds a window; every balcony holds a panoramic window, has at least one
//     door connection and no open connection.
// 10. On a level with a dining room, every kitchen connects directly (door or open) to one; on a level
//     with a kitchen or dining room, every living room connects directly to one of them. A nested room
//     (exactly one door/open connection, no staircase link, not touched by the entrance, of a private
//     category: bedroom, bathroom, children-room, office, meeting-room, balcony) is joined by a door, not an open
//     (for a balcony rule 9 reports it already, so rule 10 does not repeat it).
//
// Speed: rooms are cached with their bounding boxes, areas and shapes; all boundary work is on segments
// (shared boundaries are collinear overlapping edge pairs); polygon booleans only for non-convex pairs.
#include "layout/validate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "layout/geometry.h"
#include "layout/shape_codec.h"
#include "layout/topology.h"

namespace villa {
namespace {

std::string Fixed2(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.2f", std::abs(value) < 0.005 ? 0.0 : value);
  return buffer;
}

std::string PointText(const Point& p) { return "(" + FormatNumber(p.x) + ", " + FormatNumber(p.y) + ")"; }

std::string KindWord(ElementKind kind) {
  switch (kind) {
    case ElementKind::kEntrance: return "entrance";
    case ElementKind::kDoor: return "door";
    case ElementKind::kOpen: return "open";
    case ElementKind::kWindow: return "window";
    case ElementKind::kInterior: return "interior wall";
  }
  return "element";
}

bool IsPrivate(Category c) {
  return c == Category::kBedroom || c == Category::kBathroom || c == Category::kChildrenRoom || c == Category::kOffice ||
         c == Category::kMeetingRoom || c == Category::kBalcony;
}

struct RoomInfo {
  Box2 box;
  double area = 0;
  Point centroid;
  bool valid = false;
};

struct SharedPiece {
  int a = -1, b = -1;  // room indices, a < b
  Segment segment;
};

struct LevelInfo {
  std::vector<int> rooms;
  bool analysable = false;  // every polygon valid and no overlaps: footprint work makes sense
  double area = 0;
  Point centroid;
  std::vector<SharedPiece> shared;
  ExteriorBoundary exterior;
  bool has_exterior = false;
};

class Validator {
 public:
  Validator(const Layout& layout, const ValidateOptions& options)
      : layout_(layout), options_(options), tol_(options.tolerance), on_wall_(options.on_wall_tolerance) {}

  ValidationReport Run() {
    Prepare();
    CheckRule1();
    CheckRule2();
    CheckElements();  // rules 3 and 5 for 1D elements
    CheckRule4();
    CheckRoomWidths();
    if (options_.check_architecture) {
      CheckRule6();
      CheckRule7();
      CheckTopology();  // rules 8, 9, 10
    }
    std::stable_sort(report_.violations.begin(), report_.violations.end(),
                     [](const Violation& a, const Violation& b) { return a.rule < b.rule; });
    return std::move(report_);
  }

 private:
  void Add(int rule, std::vector<std::string> elements, std::string message, double figure = 0) {
    report_.violations.push_back({rule, std::move(elements), std::move(message), figure});
  }
  // Names are built only for messages: most layouts are valid and need none.
  const std::string& Name(int room) const {
    if (names_.empty()) names_.resize(layout_.rooms.size());
    if (names_[room].empty()) names_[room] = layout_.rooms[room].name();
    return names_[room];
  }
  std::string Names(const std::vector<int>& rooms, const char* joint = ", ") const {
    std::string out;
    for (std::size_t i = 0; i < rooms.size(); ++i) out += (i ? joint : "") + Name(rooms[i]);
    return out;
  }
  std::vector<std::string> NameList(const std::vector<int>& rooms) const {
    std::vector<std::string> out;
    for (int r : rooms) out.push_back(Name(r));
    return out;
  }

  void Prepare() {
    levels_count_ = layout_.LevelCount();
    levels_.resize(levels_count_);
    rooms_.resize(layout_.rooms.size());
    for (std::size_t i = 0; i < layout_.rooms.size(); ++i) {
      const Room& room = layout_.rooms[i];
      RoomInfo& info = rooms_[i];
      info.box = BoundingBox(room.polygon);
      info.area = Area(room.polygon);
      info.centroid = Centroid(room.polygon);
      if (room.level >= 0 && room.level < levels_count_) levels_[room.level].rooms.push_back(static_cast<int>(i));
    }
    int offset = 0;
    for (ElementKind kind : kAllElementKinds) {
      offsets_[static_cast<int>(kind)] = offset;
      offset += static_cast<int>(layout_.elements(kind).size());
    }
    along_.resize(static_cast<std::size_t>(offset) * std::max(levels_count_, 1));
    along_done_.assign(along_.size(), false);
  }

  // The rooms of `level` along an element: RoomsAlongSegment's rule (topology.h), on the cached boxes and
  // computed once however many rules ask.
  const SegmentRooms& Along(const Element& e, int level) {
    const auto& group = layout_.elements(e.kind);
    std::size_t index = static_cast<std::size_t>(offsets_[static_cast<int>(e.kind)] + (&e - group.data())) * levels_count_ + level;
    if (along_done_[index]) return along_[index];
    along_done_[index] = true;
    SegmentRooms& out = along_[index];
    double length = Length(e.shape);
    Box2 box = BoundingBox(e.shape);
    for (int r : levels_[level].rooms) {
      if (!rooms_[r].box.Touches(box, on_wall_)) continue;
      double on = LengthOnBoundary(e.shape, layout_.rooms[r].polygon, on_wall_);
      if (on <= on_wall_) continue;
      out.touching.push_back(r);
      if (on >= length - on_wall_) out.holding.push_back(r);
    }
    return out;
  }

  // ---- rule 1 ----
  void CheckRule1() {
    if (layout_.rooms.empty()) Add(1, {}, "the layout has no rooms");
    for (int l = 0; l < levels_count_; ++l)
      if (levels_[l].rooms.empty())
        Add(1, {}, "level " + std::to_string(l) + " has no rooms (levels must be 0.." + std::to_string(levels_count_ - 1) +
                       " with rooms on each)");
    for (std::size_t i = 0; i < layout_.rooms.size(); ++i) {
      const Room& room = layout_.rooms[i];
      if (room.level < 0) Add(1, {Name(i)}, Name(i) + " has a negative level");
      std::string problem = RingProblem(room.polygon);
      if (problem.empty()) {
        rooms_[i].valid = true;
      } else {
        // Boost's messages can run long; the first sentence is what a person needs.
        if (auto dot = problem.find(". "); dot != std::string::npos) problem.resize(dot);
        Add(1, {Name(i)}, Name(i) + " is not a valid polygon: " + problem);
      }
    }
    for (ElementKind kind : kAllElementKinds)
      for (const Element& e : layout_.elements(kind)) {
        if (e.level != kAllLevels && (e.level < 0 || e.level >= levels_count_))
          Add(1, {e.name},
              KindWord(kind) + " " + e.name + " is on level " + std::to_string(e.level) +
                  (levels_count_ > 0 ? ", but the layout has levels 0.." + std::to_string(levels_count_ - 1)
                                     : ", but the layout has no levels"));
        if (Length(e.shape) <= tol_) Add(1, {e.name}, KindWord(kind) + " " + e.name + " has zero length");
      }
    for (int l = 0; l < levels_count_; ++l) CheckLevelFootprint(l);
  }

  void CheckLevelFootprint(int l) {
    LevelInfo& level = levels_[l];
    const auto& ids = level.rooms;
    bool ok = !ids.empty();
    for (int r : ids) ok = ok && rooms_[r].valid;
    // Overlaps (only between valid polygons: an invalid one has no meaningful area).
    for (std::size_t x = 0; x < ids.size(); ++x)
      for (std::size_t y = x + 1; y < ids.size(); ++y) {
        int a = ids[x], b = ids[y];
        if (!rooms_[a].valid || !rooms_[b].valid) continue;
        const Box2& ba = rooms_[a].box;
        const Box2& bb = rooms_[b].box;
        if (std::min(ba.max_x, bb.max_x) - std::max(ba.min_x, bb.min_x) <= tol_ ||
            std::min(ba.max_y, bb.max_y) - std::max(ba.min_y, bb.min_y) <= tol_)
          continue;
        double overlap = IntersectionArea(layout_.rooms[a].polygon, layout_.rooms[b].polygon);
        if (overlap > tol_) {
          ok = false;
          Add(1, {Name(a), Name(b)}, "rooms " + Name(a) + " and " + Name(b) + " overlap by " + Fixed2(overlap) + " m2",
              overlap);
        }
      }
    // Shared boundaries (also wanted by rules 3 and 4 when the level is broken).
    for (std::size_t x = 0; x < ids.size(); ++x)
      for (std::size_t y = x + 1; y < ids.size(); ++y) {
        int a = ids[x], b = ids[y];
        if (!rooms_[a].box.Touches(rooms_[b].box, tol_)) continue;
        for (const Segment& s : SharedBoundaries(layout_.rooms[a].polygon, layout_.rooms[b].polygon, tol_))
          level.shared.push_back({a, b, s});
      }
    level.analysable = ok;
    if (!ok) return;

    double area = 0, cx = 0, cy = 0;
    for (int r : ids) area += rooms_[r].area, cx += rooms_[r].area * rooms_[r].centroid.x, cy += rooms_[r].area * rooms_[r].centroid.y;
    level.area = area;
    level.centroid = {cx / area, cy / area};

    // Pieces: rooms joined through shared edges.
    std::vector<int> parent(ids.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](int i) {
      while (parent[i] != i) i = parent[i] = parent[parent[i]];
      return i;
    };
    auto local = [&](int room) { return static_cast<int>(std::find(ids.begin(), ids.end(), room) - ids.begin()); };
    for (const auto& piece : level.shared) parent[find(local(piece.a))] = find(local(piece.b));
    std::vector<std::vector<int>> pieces;
    std::vector<int> piece_of(ids.size(), -1);
    for (std::size_t i = 0; i < ids.size(); ++i) {
      int root = find(static_cast<int>(i));
      if (piece_of[root] < 0) piece_of[root] = static_cast<int>(pieces.size()), pieces.emplace_back();
      pieces[piece_of[root]].push_back(ids[i]);
    }
    if (pieces.size() > 1) {
      std::string text;
      double largest = 0;
      for (std::size_t p = 0; p < pieces.size(); ++p) {
        double piece_area = 0;
        for (int r : pieces[p]) piece_area += rooms_[r].area;
        largest = std::max(largest, piece_area);
        text += (p == 0 ? "" : p + 1 == pieces.size() ? " and " : ", ") + Names(pieces[p], " + ") + " (" +
                Fixed2(piece_area) + " m2)";
      }
      Add(1, NameList(ids),
          "level " + std::to_string(l) + " rooms do not form one footprint: " + std::to_string(pieces.size()) +
              " separate pieces, " + text,
          area - largest);
    }

    std::vector<Ring> rings;
    rings.reserve(ids.size());
    for (int r : ids) rings.push_back(layout_.rooms[r].polygon);
    level.exterior = ExteriorBoundaryOf(rings, tol_);
    level.has_exterior = true;
    for (auto& owner : level.exterior.owners) owner = ids[owner];
    for (auto& ring : level.exterior.rings) {
      for (auto& owner : ring.owners) owner = ids[owner];
      if (ring.signed_area < -tol_) {
        std::vector<int> around;
        for (int r : ring.owners)
          if (std::find(around.begin(), around.end(), r) == around.end()) around.push_back(r);
        Add(1, NameList(around),
            "level " + std::to_string(l) + " footprint has a hole of " + Fixed2(-ring.signed_area) +
                " m2 enclosed by " + Names(around),
            -ring.signed_area);
      }
    }
    if (!level.exterior.closed && pieces.size() == 1)
      Add(1, NameList(ids), "level " + std::to_string(l) + " rooms do not close into one footprint outline");
  }

  // ---- rule 2 ----
  void CheckRule2() {
    for (int l = 0; l + 1 < levels_count_; ++l) {
      const LevelInfo& lower = levels_[l];
      const LevelInfo& upper = levels_[l + 1];
      if (!lower.analysable || !upper.analysable) continue;
      double outside_total = 0;
      std::vector<int> sticking_out;
      for (int u : upper.rooms) {
        double inside = 0;
        for (int d : lower.rooms)
          if (rooms_[u].box.Touches(rooms_[d].box, 0))
            inside += IntersectionArea(layout_.rooms[u].polygon, layout_.rooms[d].polygon);
        double outside = std::max(0.0, rooms_[u].area - inside);
        if (outside > tol_) sticking_out.push_back(u), outside_total += outside;
      }
      if (outside_total <= tol_) continue;
      std::string message = "level " + std::to_string(l + 1) + " footprint reaches " + Fixed2(outside_total) +
                            " m2 beyond level " + std::to_string(l) + "'s footprint (" + Names(sticking_out) + ")";
      if (upper.area > lower.area + tol_)
        message += "; it is also larger (" + Fixed2(upper.area) + " > " + Fixed2(lower.area) + " m2)";
      Add(2, NameList(sticking_out), message, outside_total);
    }
  }

  // ---- rules 3 and 5 for 1D elements ----
  void CheckElements() {
    if (layout_.entrances.size() > 1) {
      std::vector<std::string> names;
      std::string text;
      for (const auto& e : layout_.entrances) names.push_back(e.name), text += (text.empty() ? "" : ", ") + e.name;
      Add(3, names, "the layout has " + std::to_string(names.size()) + " entrances (" + text + "); it has exactly one",
          static_cast<double>(names.size()));
    }
    for (ElementKind kind : kAllElementKinds)
      for (const Element& e : layout_.elements(kind)) {
        double length = Length(e.shape);
        if (length <= tol_) continue;  // rule 1 has it
        double minimum = kind == ElementKind::kDoor || kind == ElementKind::kOpen ? 0.8
                         : kind == ElementKind::kWindow                          ? 0.6
                                                                                 : 0.0;
        if (length < minimum - tol_)
          Add(5, {e.name},
              KindWord(kind) + " " + e.name + " is " + Fixed2(length) + " m wide; " + KindWord(kind) +
                  "s need at least " + Fixed2(minimum) + " m",
              length);
        if (kind == ElementKind::kEntrance) {
          if (e.level != 0 && e.level != kAllLevels) {
            Add(3, {e.name}, "entrance " + e.name + " is on level " + std::to_string(e.level) + "; the entrance is on level 0",
                e.level);
            continue;
          }
          if (levels_count_ > 0) CheckOnOneRoom(e, 0);
          continue;
        }
        for (int l = 0; l < levels_count_; ++l) {
          if (!e.OnLevel(l)) continue;
          if (kind == ElementKind::kWindow)
            CheckOnOneRoom(e, l);
          else
            CheckOnTwoRooms(e, l);
        }
      }
  }

  std::string LevelSuffix(const Element& e, int l) const {
    return e.level == kAllLevels ? " (no level given: checked on level " + std::to_string(l) + ")" : "";
  }

  // The largest length of `s` on the shared boundary of two rooms among `touching`.
  double BestPairCover(const Segment& s, const std::vector<int>& touching, int* a, int* b) const {
    double best = -1;
    for (std::size_t x = 0; x < touching.size(); ++x)
      for (std::size_t y = x + 1; y < touching.size(); ++y) {
        auto ia = IntervalsOnBoundary(s, layout_.rooms[touching[x]].polygon, tol_);
        auto ib = IntervalsOnBoundary(s, layout_.rooms[touching[y]].polygon, tol_);
        double both = TotalLength(IntersectIntervals(ia, ib, tol_));
        if (both > best) best = both, *a = touching[x], *b = touching[y];
      }
    return best;
  }

  void CheckOnTwoRooms(const Element& e, int l) {
    const SegmentRooms& rooms = Along(e, l);
    if (rooms.holding.size() == 2) return;
    std::string head = KindWord(e.kind) + " " + e.name;
    std::string where = LevelSuffix(e, l);
    if (rooms.holding.size() > 2) {
      Add(3, {e.name}, head + " lies on the boundaries of " + std::to_string(rooms.holding.size()) + " rooms (" +
                           Names(rooms.holding) + "); it must join exactly two" + where);
      return;
    }
    if (rooms.touching.size() >= 2) {
      int a = -1, b = -1;
      double both = BestPairCover(e.shape, rooms.touching, &a, &b);
      double off = Length(e.shape) - std::max(0.0, both);
      Add(3, {e.name, Name(a), Name(b)},
          head + " runs " + Fixed2(off) + " m past the shared boundary of " + Name(a) + " and " + Name(b) + where, off);
      return;
    }
    // Off every shared boundary: how far from the nearest one.
    const LevelInfo& level = levels_[l];
    const SharedPiece* nearest = nullptr;
    double distance = INFINITY;
    for (const auto& piece : level.shared) {
      double d = SegmentOffDistance(e.shape, piece.segment);
      if (d < distance) distance = d, nearest = &piece;
    }
    std::string touches = rooms.touching.empty() ? " touches no room of level " + std::to_string(l)
                                                 : " touches only " + Name(rooms.touching[0]);
    std::vector<std::string> elements{e.name};
    for (int r : rooms.touching) elements.push_back(Name(r));
    if (!nearest) {
      Add(3, elements, head + touches + "; level " + std::to_string(l) + " has no shared boundary between rooms" + where);
      return;
    }
    Add(3, elements,
        head + touches + "; it is " + Fixed2(distance) + " m off the nearest shared boundary, of " + Name(nearest->a) +
            " and " + Name(nearest->b) + where,
        distance);
  }

  void CheckOnOneRoom(const Element& e, int l) {
    const SegmentRooms& rooms = Along(e, l);
    if (rooms.holding.size() == 1 && rooms.touching.size() == 1) return;
    std::string head = KindWord(e.kind) + " " + e.name;
    std::string where = LevelSuffix(e, l);
    std::vector<std::string> elements{e.name};
    for (int r : rooms.touching) elements.push_back(Name(r));
    if (rooms.touching.size() >= 2) {
      int a = -1, b = -1;
      double both = BestPairCover(e.shape, rooms.touching, &a, &b);
      if (both > tol_)
        Add(3, elements,
            head + " lies on the wall between " + Name(a) + " and " + Name(b) + " for " + Fixed2(both) +
                " m, not on an outside wall" + where,
            both);
      else
        Add(3, elements, head + " spans " + Names(rooms.touching) + "; it must lie on the outside wall of one room" + where);
      return;
    }
    if (rooms.touching.size() == 1) {
      double off = Length(e.shape) - LengthOnBoundary(e.shape, layout_.rooms[rooms.touching[0]].polygon, tol_);
      Add(3, elements, head + " runs " + Fixed2(off) + " m past the outside wall of " + Name(rooms.touching[0]) + where, off);
      return;
    }
    // Touches nothing: distance to the nearest outside wall (every room edge when the level is broken).
    double distance = INFINITY;
    int owner = -1;
    const LevelInfo& level = levels_[l];
    if (level.has_exterior) {
      for (std::size_t i = 0; i < level.exterior.pieces.size(); ++i) {
        double d = SegmentOffDistance(e.shape, level.exterior.pieces[i]);
        if (d < distance) distance = d, owner = level.exterior.owners[i];
      }
    } else {
      for (int r : level.rooms) {
        const Ring& ring = layout_.rooms[r].polygon;
        for (std::size_t k = 0; k < ring.size(); ++k) {
          double d = SegmentOffDistance(e.shape, {ring[k], ring[(k + 1) % ring.size()]});
          if (d < distance) distance = d, owner = r;
        }
      }
    }
    if (owner < 0) {
      Add(3, elements, head + " touches no room of level " + std::to_string(l) + where);
      return;
    }
    Add(3, elements,
        head + " touches no room of level " + std::to_string(l) + "; it is " + Fixed2(distance) +
            " m off the nearest outside wall, of " + Name(owner) + where,
        distance);
  }

  // ---- rule 4 ----
  void CheckRule4() {
    for (int l = 0; l < levels_count_; ++l) {
      const LevelInfo& level = levels_[l];
      // Group the shared pieces by room pair (they come out grouped already).
      for (std::size_t i = 0; i < level.shared.size();) {
        std::size_t j = i;
        double uncovered = 0;
        const Segment* first_gap = nullptr;
        Interval first_gap_at{0, 0};
        while (j < level.shared.size() && level.shared[j].a == level.shared[i].a && level.shared[j].b == level.shared[i].b) {
          const Segment& piece = level.shared[j].segment;
          double len = Length(piece);
          Box2 box = BoundingBox(piece);
          std::vector<Interval> covered;
          for (ElementKind kind : {ElementKind::kInterior, ElementKind::kOpen})
            for (const Element& e : layout_.elements(kind)) {
              if (!e.OnLevel(l) || !BoundingBox(e.shape).Touches(box, tol_)) continue;
              for (const auto& iv : CollinearOverlap(piece, e.shape, tol_)) covered.push_back(iv);
            }
          covered = MergeIntervals(std::move(covered), tol_);
          double at = 0;
          auto gap = [&](double from, double to) {
            if (to - from <= tol_) return;
            uncovered += to - from;
            if (!first_gap) first_gap = &piece, first_gap_at = {from, to};
          };
          for (const auto& iv : covered) gap(at, iv.first), at = std::max(at, iv.second);
          gap(at, len);
          ++j;
        }
        if (uncovered > tol_) {
          int a = level.shared[i].a, b = level.shared[i].b;
          Add(4, {Name(a), Name(b)},
              "the boundary between " + Name(a) + " and " + Name(b) + " has no interior wall or open for " +
                  Fixed2(uncovered) + " m (first gap from " + PointText(PointAt(*first_gap, first_gap_at.first)) +
                  " to " + PointText(PointAt(*first_gap, first_gap_at.second)) + ")",
              uncovered);
        }
        i = j;
      }
    }
  }

  // ---- rule 5 for rooms ----
  void CheckRoomWidths() {
    for (std::size_t i = 0; i < layout_.rooms.size(); ++i) {
      if (!rooms_[i].valid) continue;
      double width = RoomWidth(layout_.rooms[i].polygon, tol_);
      if (width < 1.0 - tol_)
        Add(5, {Name(i)}, Name(i) + " is " + Fixed2(width) + " m wide at its narrowest; rooms need at least 1.00 m", width);
    }
  }

  // ---- rule 6 ----
  void CheckRule6() {
    if (levels_count_ > kMaxFloors)
      Add(6, {}, "the building has " + std::to_string(levels_count_) + " floors; at most " + std::to_string(kMaxFloors),
          levels_count_);
    for (int l = 0; l < levels_count_; ++l)
      if (static_cast<int>(levels_[l].rooms.size()) > kMaxRoomsPerFloor)
        Add(6, NameList(levels_[l].rooms),
            "level " + std::to_string(l) + " has " + std::to_string(levels_[l].rooms.size()) + " rooms; at most " +
                std::to_string(kMaxRoomsPerFloor) + " a floor",
            static_cast<double>(levels_[l].rooms.size()));
  }

  // ---- rule 7 ----
  bool IsStairSquare(int room) const {
    auto [w, h] = RectangleSides(layout_.rooms[room].polygon, tol_);
    return std::abs(w - kStairRoomSize) <= tol_ && std::abs(h - kStairRoomSize) <= tol_;
  }

  void CheckRule7() {
    if (levels_count_ < 2) return;
    std::vector<std::vector<int>> squares(levels_count_);
    bool all_levels = true;
    for (int l = 0; l < levels_count_; ++l) {
      std::vector<int> utilities;
      for (int r : levels_[l].rooms)
        if (layout_.rooms[r].category == Category::kUtilityRoom) {
          utilities.push_back(r);
          if (IsStairSquare(r)) squares[l].push_back(r);
        }
      if (!squares[l].empty()) continue;
      all_levels = false;
      if (utilities.empty()) {
        Add(7, {}, "level " + std::to_string(l) + " has no utility-room; a multi-story building has a 4 x 4 m staircase room on every floor");
        continue;
      }
      for (int r : utilities) {
        auto [w, h] = RectangleSides(layout_.rooms[r].polygon, tol_);
        Box2 box = rooms_[r].box;
        std::string size = w > 0 ? Fixed2(w) + " x " + Fixed2(h) + " m"
                                 : "not a rectangle (" + Fixed2(box.max_x - box.min_x) + " x " + Fixed2(box.max_y - box.min_y) + " m box)";
        double off = w > 0 ? std::max(std::abs(w - kStairRoomSize), std::abs(h - kStairRoomSize)) : 0;
        Add(7, {Name(r)}, Name(r) + " is " + size + "; the staircase room is 4 x 4 m", off);
      }
    }
    if (!all_levels) return;
    // One 4 x 4 room at the same place on every level.
    int best = -1;
    std::vector<int> stack;
    std::size_t best_matched = 0;
    for (int candidate : squares[0]) {
      std::vector<int> matched{candidate};
      for (int l = 1; l < levels_count_; ++l)
        for (int r : squares[l])
          if (SameRing(layout_.rooms[candidate].polygon, layout_.rooms[r].polygon, tol_)) {
            matched.push_back(r);
            break;
          }
      if (best < 0 || matched.size() > best_matched) best = candidate, best_matched = matched.size(), stack = matched;
    }
    if (static_cast<int>(stack.size()) < levels_count_) {
      for (int l = 1; l < levels_count_; ++l) {
        bool has = false;
        for (int r : stack) has = has || layout_.rooms[r].level == l;
        if (has) continue;
        int nearest = squares[l][0];
        double offset = Distance(rooms_[nearest].centroid, rooms_[best].centroid);
        for (int r : squares[l]) {
          double d = Distance(rooms_[r].centroid, rooms_[best].centroid);
          if (d < offset) offset = d, nearest = r;
        }
        Add(7, {Name(best), Name(nearest)},
            Name(nearest) + " is not at the place of " + Name(best) + " (" + Fixed2(offset) +
                " m off): the staircase rises through the same 4 x 4 m on every floor",
            offset);
      }
      return;
    }
    for (int r : stack) {
      const LevelInfo& level = levels_[layout_.rooms[r].level];
      if (!level.analysable) continue;
      double d = Distance(rooms_[r].centroid, level.centroid);
      if (d <= tol_)
        Add(7, {Name(r)},
            Name(r) + " sits at the exact centre " + PointText(level.centroid) + " of level " +
                std::to_string(layout_.rooms[r].level) + "'s footprint; the staircase goes off centre",
            d);
    }
  }

  // ---- rules 8, 9, 10 ----
  void CheckTopology() {
    const std::size_t n = layout_.rooms.size();
    // The same connections and entrance rooms as RoomConnections() and EntranceRooms() in topology.h,
    // from the classifications already made for rule 3.
    std::vector<Connection> connections;
    for (ElementKind kind : {ElementKind::kDoor, ElementKind::kOpen})
      for (const Element& e : layout_.elements(kind))
        for (int l = 0; l < levels_count_; ++l) {
          if (!e.OnLevel(l) || Length(e.shape) <= tol_) continue;
          const SegmentRooms& rooms = Along(e, l);
          if (rooms.holding.size() == 2)
            connections.push_back({rooms.holding[0], rooms.holding[1], kind == ElementKind::kDoor ? Via::kDoor : Via::kOpen, e.name});
        }
    for (int l = 0; l + 1 < levels_count_; ++l)
      for (int lower : levels_[l].rooms) {
        if (layout_.rooms[lower].category != Category::kUtilityRoom) continue;
        for (int upper : levels_[l + 1].rooms)
          if (layout_.rooms[upper].category == Category::kUtilityRoom &&
              SameRing(layout_.rooms[lower].polygon, layout_.rooms[upper].polygon, tol_))
            connections.push_back({lower, upper, Via::kStair, "stair"});
      }
    std::vector<int> entrance_rooms;
    if (levels_count_ > 0)
      for (const Element& e : layout_.entrances) {
        if (Length(e.shape) <= tol_) continue;
        for (int r : Along(e, 0).touching)
          if (std::find(entrance_rooms.begin(), entrance_rooms.end(), r) == entrance_rooms.end()) entrance_rooms.push_back(r);
      }

    // Rule 8.
    if (layout_.entrances.empty()) {
      if (n > 0) Add(8, {}, "the layout has no entrance, so no room is reachable", static_cast<double>(n));
    } else if (entrance_rooms.empty()) {
      if (n > 0) Add(8, {layout_.entrances[0].name}, "the entrance touches no room, so no room is reachable", static_cast<double>(n));
    } else {
      std::vector<bool> reached = ReachableRooms(layout_, connections, entrance_rooms);
      for (std::size_t i = 0; i < n; ++i)
        if (!reached[i]) Add(8, {Name(i)}, Name(i) + " is not reachable from the entrance");
    }

    // Neighbours through doors/opens, and staircase links.
    std::vector<std::vector<const Connection*>> by_room(n);
    std::vector<bool> stair(n, false);
    for (const auto& c : connections) {
      if (c.via == Via::kStair) {
        stair[c.room_a] = stair[c.room_b] = true;
        continue;
      }
      by_room[c.room_a].push_back(&c);
      by_room[c.room_b].push_back(&c);
    }
    auto other = [](const Connection* c, int room) { return c->room_a == room ? c->room_b : c->room_a; };

    // Rule 9: windows.
    std::vector<bool> has_window(n, false), has_panoramic(n, false);
    for (const Element& w : layout_.windows)
      for (int l = 0; l < levels_count_; ++l) {
        if (!w.OnLevel(l)) continue;
        if (Length(w.shape) <= tol_) continue;
        for (int r : Along(w, l).holding) {
          has_window[r] = true;
          if (w.panoramic) has_panoramic[r] = true;
        }
      }
    for (std::size_t i = 0; i < n; ++i) {
      Category c = layout_.rooms[i].category;
      if ((c == Category::kKitchen || c == Category::kBathroom) && !has_window[i])
        Add(9, {Name(i)}, Name(i) + " has no window");
      if (c != Category::kBalcony) continue;
      if (!has_panoramic[i]) Add(9, {Name(i)}, Name(i) + " has no panoramic window");
      bool door = false;
      for (const Connection* k : by_room[i]) {
        if (k->via == Via::kDoor) door = true;
        if (k->via == Via::kOpen)
          Add(9, {Name(i), k->element}, Name(i) + " connects through open " + k->element + "; a balcony connects through doors");
      }
      if (!door) Add(9, {Name(i)}, Name(i) + " has no door");
    }

    // Rule 10.
    for (std::size_t i = 0; i < n; ++i) {
      const Room& room = layout_.rooms[i];
      auto floor_has = [&](Category c) {
        for (int r : levels_[room.level].rooms)
          if (layout_.rooms[r].category == c) return true;
        return false;
      };
      auto connects_to = [&](std::initializer_list<Category> cs) {
        for (const Connection* k : by_room[i])
          for (Category c : cs)
            if (layout_.rooms[other(k, static_cast<int>(i))].category == c) return true;
        return false;
      };
      if (room.level < 0 || room.level >= levels_count_) continue;
      if (room.category == Category::kKitchen && floor_has(Category::kDiningRoom) && !connects_to({Category::kDiningRoom}))
        Add(10, {Name(i)}, Name(i) + " does not connect to a dining room of level " + std::to_string(room.level));
      if (room.category == Category::kLivingRoom && (floor_has(Category::kKitchen) || floor_has(Category::kDiningRoom)) &&
          !connects_to({Category::kKitchen, Category::kDiningRoom}))
        Add(10, {Name(i)}, Name(i) + " connects to neither a kitchen nor a dining room of level " + std::to_string(room.level));
      // Balconies are private too, but rule 9 already holds them to doors only.
      if (!IsPrivate(room.category) || room.category == Category::kBalcony || stair[i] || by_room[i].size() != 1) continue;
      if (std::find(entrance_rooms.begin(), entrance_rooms.end(), static_cast<int>(i)) != entrance_rooms.end()) continue;
      const Connection* only = by_room[i][0];
      if (only->via == Via::kOpen)
        Add(10, {Name(i), only->element},
            Name(i) + " is reached only from " + Name(other(only, static_cast<int>(i))) + ", through open " + only->element +
                  "; a nested room needs a door");
    }
  }

  const Layout& layout_;
  ValidateOptions options_;
  double tol_;
  double on_wall_;  // rule 3's "lies on the boundary" (layout.h's kOnWallTolerance by default)
  int levels_count_ = 0;
  std::vector<RoomInfo> rooms_;
  std::vector<LevelInfo> levels_;
  int offsets_[5] = {0, 0, 0, 0, 0};        // first index of each element kind in along_
  std::vector<SegmentRooms> along_;          // per element and level
  std::vector<bool> along_done_;
  mutable std::vector<std::string> names_;
  ValidationReport report_;
};

}  // namespace

bool ValidationReport::geometric_ok() const {
  for (const auto& v : violations)
    if (v.rule >= 1 && v.rule <= 5) return false;
  return true;
}

int ValidationReport::CountRule(int rule) const {
  int count = 0;
  for (const auto& v : violations) count += v.rule == rule;
  return count;
}

ValidationReport ValidateLayout(const Layout& layout, const ValidateOptions& options) {
  return Validator(layout, options).Run();
}

}  // namespace villa
