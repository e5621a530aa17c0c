#include "layout/door_swing.h"

#include <algorithm>
#include <cmath>
#include <map>
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


bool IsStaircaseHall(const Layout& layout, int room) {
  return room >= 0 && layout.LevelCount() > 1 && layout.rooms[room].category == Category::kUtilityRoom;
}

// Whether a point just outside `s` (on the side opposite `inward`) lies in another room of the level: an
// interior wall stands there, else an exterior one.
bool InteriorAt(const Layout& layout, const std::vector<int>& rooms, int room, const Point& mid, const Point& inward) {
  const Point out{mid.x - inward.x * kDoorProbe, mid.y - inward.y * kDoorProbe};
  for (int r : rooms)
    if (r != room && PointInRing(out, layout.rooms[r].polygon, 0)) return true;
  return false;
}

// The walking floor of one room on a raster: cell centres inside the room at least the person's radius plus
// the margin from its walls' faces. Walls have their gaps ignored (conservative); where the doors and
// opens are, their mouths (a point just inside each, snapped to the floor) say what must stay joined.
class RoomFloor {
 public:
  RoomFloor(const Layout& layout, const std::vector<int>& rooms, int room, int level, const SwingClearance& c)
      : c_(c), ring_(CounterClockwise(layout.rooms[room].polygon)), keep_(c.person_radius + c.margin) {
    double x1 = -1e300, y1 = -1e300;
    x0_ = y0_ = 1e300;
    for (const Point& p : ring_) x0_ = std::min(x0_, p.x), y0_ = std::min(y0_, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
    nx_ = std::max(1, static_cast<int>(std::ceil((x1 - x0_) / c.cell)));
    ny_ = std::max(1, static_cast<int>(std::ceil((y1 - y0_) / c.cell)));
    for (size_t i = 0; i < ring_.size(); ++i) {
      const Segment e{ring_[i], ring_[(i + 1) % ring_.size()]};
      const Point mid{(e.a.x + e.b.x) / 2.0, (e.a.y + e.b.y) / 2.0};
      edges_.push_back(e);
      depths_.push_back(InteriorAt(layout, rooms, room, mid, LeftNormal(e)) ? c.interior_wall / 2.0 : c.exterior_wall);
    }
    base_.assign(static_cast<size_t>(nx_) * ny_, 0);
    for (int j = 0; j < ny_; ++j)
      for (int i = 0; i < nx_; ++i) {
        const Point p = Centre(static_cast<long>(j) * nx_ + i);
        bool free = PointInRing(p, ring_, 0);
        for (size_t k = 0; free && k < edges_.size(); ++k) free = PointSegmentDistance(p, edges_[k]) >= depths_[k] + keep_;
        base_[static_cast<size_t>(j) * nx_ + i] = free;
      }
  }

  // m from the element's line to the face of the wall it is cut in, on this room's side.
  double WallDepth(const Layout& layout, const std::vector<int>& rooms, int room, const Segment& s, const Point& inward) const {
    const Point mid{(s.a.x + s.b.x) / 2.0, (s.a.y + s.b.y) / 2.0};
    return InteriorAt(layout, rooms, room, mid, inward) ? c_.interior_wall / 2.0 : c_.exterior_wall;
  }

  // Where a person steps in through `s` (an opening of this room): its middle, in past the wall and the disc.
  Point Mouth(const Segment& s, const Point& inward, double depth) const {
    const double in = depth + keep_ + c_.cell;
    return {(s.a.x + s.b.x) / 2.0 + inward.x * in, (s.a.y + s.b.y) / 2.0 + inward.y * in};
  }
  void AddMouth(const Point& p) { mouths_.push_back(p); }

  // Whether `leaf` keeps off the room's walls (the builder would find its sweep in one and hang it closed):
  // inside the room, no nearer any edge than that wall's face.
  bool ClearOfWalls(const Segment& leaf) const {
    const Point mid{(leaf.a.x + leaf.b.x) / 2.0, (leaf.a.y + leaf.b.y) / 2.0};
    if (!PointInRing(leaf.a, ring_, 0) || !PointInRing(mid, ring_, 0) || !PointInRing(leaf.b, ring_, 0)) return false;
    for (size_t k = 0; k < edges_.size(); ++k) {
      const double d = std::min({PointSegmentDistance(leaf.a, edges_[k]), PointSegmentDistance(leaf.b, edges_[k]),
                                 PointSegmentDistance(edges_[k].a, leaf), PointSegmentDistance(edges_[k].b, leaf)});
      if (d < depths_[k] - 1e-3) return false;
    }
    return true;
  }

  // What `leaf` (a thin segment), standing beside the leaves already in the room, costs the floor as seen
  // from `from` (the door's own mouth): 1000 for every mouth reached before and not after, plus the m2 of
  // floor reached before and cut off after (beyond the cells the leaf itself covers); 0 when nothing is lost.
  double Damage(const Point& from, const std::vector<Segment>& standing, const Segment& leaf) const {
    constexpr double kMouth = 1000.0;
    const std::vector<char> before = Free(standing);
    std::vector<Segment> with = standing;
    with.push_back(leaf);
    const std::vector<char> after = Free(with);
    const long s0 = Snap(from, before);
    if (s0 < 0) return 0.0;  // no floor to keep
    const long s1 = Snap(from, after);
    if (s1 < 0) return kMouth * (static_cast<double>(mouths_.size()) + 1.0);
    const std::vector<char> r0 = Reached(before, s0), r1 = Reached(after, s1);
    double damage = 0.0;
    for (const Point& m : mouths_) {
      const long c0 = Snap(m, before);
      if (c0 < 0 || !r0[c0]) continue;
      const long c1 = Snap(m, after);
      if (c1 < 0 || !r1[c1]) damage += kMouth;
    }
    long lost = 0;
    for (size_t k = 0; k < r0.size(); ++k) lost += r0[k] && after[k] && !r1[k];
    return damage + lost * c_.cell * c_.cell;
  }

 private:
  Point Centre(long k) const { return {x0_ + (k % nx_ + 0.5) * c_.cell, y0_ + (k / nx_ + 0.5) * c_.cell}; }

  std::vector<char> Free(const std::vector<Segment>& leaves) const {
    std::vector<char> free = base_;
    const double keep = keep_ + c_.leaf_thickness / 2.0;
    for (size_t k = 0; k < free.size(); ++k)
      for (const Segment& l : leaves)
        if (free[k] && PointSegmentDistance(Centre(static_cast<long>(k)), l) < keep) free[k] = 0;
    return free;
  }

  // The free cell nearest `p` within 0.3 m, or -1.
  long Snap(const Point& p, const std::vector<char>& free) const {
    const int ci = static_cast<int>(std::floor((p.x - x0_) / c_.cell)), cj = static_cast<int>(std::floor((p.y - y0_) / c_.cell));
    const int reach = static_cast<int>(std::ceil(0.3 / c_.cell));
    long best = -1;
    double best_d = 0.3;
    for (int j = std::max(0, cj - reach); j <= std::min(ny_ - 1, cj + reach); ++j)
      for (int i = std::max(0, ci - reach); i <= std::min(nx_ - 1, ci + reach); ++i) {
        const long k = static_cast<long>(j) * nx_ + i;
        if (!free[k]) continue;
        const Point q = Centre(k);
        const double d = std::hypot(q.x - p.x, q.y - p.y);
        if (d <= best_d) best_d = d, best = k;
      }
    return best;
  }

  // Cells 4-connected to `start` through free cells.
  std::vector<char> Reached(const std::vector<char>& free, long start) const {
    std::vector<char> seen(free.size(), 0);
    std::vector<long> stack = {start};
    seen[start] = 1;
    while (!stack.empty()) {
      const long k = stack.back();
      stack.pop_back();
      const int i = static_cast<int>(k % nx_), j = static_cast<int>(k / nx_);
      const long next[4] = {i > 0 ? k - 1 : -1, i + 1 < nx_ ? k + 1 : -1, j > 0 ? k - nx_ : -1, j + 1 < ny_ ? k + nx_ : -1};
      for (long n : next)
        if (n >= 0 && free[n] && !seen[n]) seen[n] = 1, stack.push_back(n);
    }
    return seen;
  }

  SwingClearance c_;
  Ring ring_;
  double keep_ = 0.0;
  double x0_ = 0.0, y0_ = 0.0;
  int nx_ = 1, ny_ = 1;
  std::vector<Segment> edges_;
  std::vector<double> depths_;
  std::vector<char> base_;
  std::vector<Point> mouths_;
};

// One way to open a door: the leaf's side (+1: left of the segment), the hinge jamb, 90 or 180 degrees.
struct Candidate {
  double side = 1.0;
  bool hinge_at_a = true;
  bool flat = false;
};

DoorSwing MakeSwing(const Element& element, int level, int left, int right, const Candidate& k) {
  const Segment& s = element.shape;
  const Point n = LeftNormal(s);
  DoorSwing swing;
  swing.element = &element;
  swing.level = level;
  swing.into = k.side > 0 ? left : right;
  swing.other = k.side > 0 ? right : left;
  swing.hinge = k.hinge_at_a ? s.a : s.b;
  swing.free_end = k.hinge_at_a ? s.b : s.a;
  swing.flat = k.flat;
  const double width = Length(s);
  swing.leaf_side = Scaled(n, k.side);
  const Point reach = Scaled(swing.leaf_side, width), back = Scaled(swing.leaf_side, -kDoorStripDepth);
  const Point away = Scaled({swing.hinge.x - swing.free_end.x, swing.hinge.y - swing.free_end.y}, 1.0 / std::max(width, 1e-12));
  const Point folded{swing.hinge.x + away.x * width, swing.hinge.y + away.y * width};
  swing.leaf_end = k.flat ? folded : Point{swing.hinge.x + reach.x, swing.hinge.y + reach.y};
  const Point from = k.flat ? folded : swing.hinge;
  swing.sweep = CounterClockwise({from, swing.free_end, {swing.free_end.x + reach.x, swing.free_end.y + reach.y},
                                  {from.x + reach.x, from.y + reach.y}});
  swing.strip = CounterClockwise({swing.hinge, swing.free_end, {swing.free_end.x + back.x, swing.free_end.y + back.y},
                                  {swing.hinge.x + back.x, swing.hinge.y + back.y}});
  return swing;
}

}  // namespace

double DoorSwing::width() const { return element ? Length(element->shape) : 0.0; }

double DoorSwing::open_angle() const { return flat ? M_PI : M_PI / 2.0; }

std::vector<Point> DoorSwing::SwingArc(int segments) const {
  const double r = Length({hinge, free_end});
  const double a0 = std::atan2(leaf_end.y - hinge.y, leaf_end.x - hinge.x);
  // Turn from the leaf towards the free jamb the way that passes the leaf side.
  const double turn = open_angle();
  const Point mid_dir{std::cos(a0 + turn / 2.0), std::sin(a0 + turn / 2.0)};
  const double sign = flat ? (mid_dir.x * leaf_side.x + mid_dir.y * leaf_side.y >= 0.0 ? 1.0 : -1.0)
                           : ((leaf_end.x - hinge.x) * (free_end.y - hinge.y) - (leaf_end.y - hinge.y) * (free_end.x - hinge.x) >= 0.0 ? 1.0 : -1.0);
  std::vector<Point> arc;
  segments = std::max(1, segments);
  for (int i = 0; i <= segments; ++i) {
    const double a = a0 + sign * turn * i / segments;
    arc.push_back({hinge.x + r * std::cos(a), hinge.y + r * std::sin(a)});
  }
  return arc;
}

std::vector<DoorSwing> DoorSwings(const Layout& layout, int level, const SwingClearance& clearance) {
  const std::vector<int> rooms = layout.RoomsOnLevel(level);
  bool staircase_hall = false;
  if (layout.LevelCount() > 1)
    for (int r : rooms) staircase_hall = staircase_hall || layout.rooms[r].category == Category::kUtilityRoom;
  std::vector<const Element*> elements, openings;
  for (const auto* list : {&layout.entrances, &layout.doors})
    for (const Element& e : *list)
      if (e.OnLevel(level)) elements.push_back(&e);
  for (const auto* list : {&layout.entrances, &layout.doors, &layout.opens})
    for (const Element& e : *list)
      if (e.OnLevel(level)) openings.push_back(&e);

  // Each room's floor, made when a leaf is first tried in it, with the mouths of its openings.
  std::map<int, RoomFloor> floors;
  auto floor_of = [&](int room) -> RoomFloor& {
    auto it = floors.find(room);
    if (it != floors.end()) return it->second;
    RoomFloor f(layout, rooms, room, level, clearance);
    const Ring& ring = layout.rooms[room].polygon;
    for (const Element* o : openings) {
      const Segment& s = o->shape;
      const Point mid{(s.a.x + s.b.x) / 2.0, (s.a.y + s.b.y) / 2.0};
      if (DistanceToBoundary(mid, ring) > 1e-3 || Length(s) <= 0.0) continue;
      Point in = LeftNormal(s);
      if (!PointInRing({mid.x + in.x * kDoorProbe, mid.y + in.y * kDoorProbe}, ring, 0)) in = Scaled(in, -1.0);
      f.AddMouth(f.Mouth(s, in, f.WallDepth(layout, rooms, room, s, in)));
    }
    return floors.emplace(room, std::move(f)).first->second;
  };
  std::map<int, std::vector<Segment>> standing;  // leaves already open in each room

  std::vector<DoorSwing> out;
  for (const Element* element : elements) {
    const Segment& s = element->shape;
    const Point n = LeftNormal(s);
    const double width = Length(s);
    int left = -1, right = -1;
    RoomsBeside(layout, rooms, s, &left, &right);
    int into = left >= 0 ? left : right;
    if (left >= 0 && right >= 0) {
      const Room& l = layout.rooms[left];
      const Room& r = layout.rooms[right];
      if (Rank(l, staircase_hall) != Rank(r, staircase_hall)) {
        into = Rank(l, staircase_hall) < Rank(r, staircase_hall) ? left : right;
      } else {
        into = Area(l.polygon) <= Area(r.polygon) ? left : right;
      }
    }
    double side = (into >= 0 && into == right) ? -1.0 : 1.0;
    const bool entrance = element->kind == ElementKind::kEntrance;
    if (entrance) {
      const Point in = Scaled(Outward(layout, rooms, s), -1.0);
      side = (in.x * n.x + in.y * n.y) >= 0.0 ? 1.0 : -1.0;
    }
    // The hinge a side prefers: the jamb nearer a corner of the room the leaf opens into.
    auto hinge_at_a = [&](double sd) {
      const int room = sd > 0 ? left : right;
      if (room < 0) return true;
      double da = 1e300, db = 1e300;
      for (const Point& p : layout.rooms[room].polygon) {
        da = std::min(da, Length({p, s.a}));
        db = std::min(db, Length({p, s.b}));
      }
      return !(db < da);
    };
    std::vector<Candidate> order;
    for (double sd : {side, -side}) {
      if (sd != side && (entrance || (sd > 0 ? left : right) < 0)) continue;
      order.push_back({sd, hinge_at_a(sd), false});
      order.push_back({sd, !hinge_at_a(sd), false});
    }
    const size_t upright = order.size();
    for (size_t k = 0; k < upright; ++k) order.push_back({order[k].side, order[k].hinge_at_a, true});

    // The first candidate whose leaf keeps its room's floor joined; else the 90 degree leaf that fits its
    // room and costs the floor least (it stands too, for the doors after it); else the first.
    std::optional<DoorSwing> chosen;
    Segment chosen_leaf;
    std::optional<Candidate> least;
    Segment least_leaf;
    double least_damage = 1e300;
    for (const Candidate& k : order) {
      const int room = k.side > 0 ? left : right;
      if (room < 0 || IsStaircaseHall(layout, room) || width <= 0.0) continue;
      RoomFloor& f = floor_of(room);
      const Point in = Scaled(n, k.side);
      const double depth = f.WallDepth(layout, rooms, room, s, in);
      const Point hinge = k.hinge_at_a ? s.a : s.b, free_end = k.hinge_at_a ? s.b : s.a;
      Segment leaf{{hinge.x + in.x * depth, hinge.y + in.y * depth}, {hinge.x + in.x * (depth + width), hinge.y + in.y * (depth + width)}};
      if (k.flat) {
        // On its way to the wall the leaf passes where a 90 degree leaf stands: that must fit the room.
        if (!f.ClearOfWalls(leaf)) continue;
        // Folded onto the wall beside the hinge: the wall must run straight on for the leaf's width and the
        // thickness of a wall meeting it there, with no other opening in it.
        const Point away{(hinge.x - free_end.x) / width, (hinge.y - free_end.y) / width};
        const double q = depth + clearance.leaf_thickness / 2.0;
        leaf = {{hinge.x + in.x * q, hinge.y + in.y * q}, {hinge.x + in.x * q + away.x * width, hinge.y + in.y * q + away.y * width}};
        bool wall = true;
        const double run = width + clearance.exterior_wall;
        for (int i = 1; i <= 10 && wall; ++i) {
          const Point p{hinge.x + away.x * run * i / 10.0, hinge.y + away.y * run * i / 10.0};
          wall = DistanceToBoundary(p, layout.rooms[room].polygon) < 1e-3;
          for (const auto* list : {&layout.entrances, &layout.doors, &layout.opens, &layout.windows})
            for (const Element& o : *list)
              if (&o != element && o.OnLevel(level) && (list != &layout.windows || o.panoramic) &&
                  PointSegmentDistance(p, o.shape) < 0.02)
                wall = false;
        }
        if (!wall) continue;
      }
      const Point mouth = f.Mouth(s, in, depth);
      if (!f.ClearOfWalls(leaf)) continue;
      const double damage = f.Damage(mouth, standing[room], leaf);
      if (damage > clearance.lost_area) {
        if (!k.flat && damage < least_damage) least = k, least_leaf = leaf, least_damage = damage;
        continue;
      }
      chosen = MakeSwing(*element, level, left, right, k);
      chosen_leaf = leaf;
      break;
    }
    if (!chosen && least) chosen = MakeSwing(*element, level, left, right, *least), chosen_leaf = least_leaf;
    if (chosen && !IsStaircaseHall(layout, chosen->into)) standing[chosen->into].push_back(chosen_leaf);
    if (!chosen)
      chosen = MakeSwing(*element, level, left, right, order.empty() ? Candidate{side, hinge_at_a(side), false} : order.front());
    out.push_back(*chosen);
  }
  return out;
}

DoorSwing SwingOfDoor(const Layout& layout, const Element& element, int level, const SwingClearance& clearance) {
  std::vector<DoorSwing> swings = DoorSwings(layout, level, clearance);
  for (const DoorSwing& w : swings)
    if (w.element == &element) return w;
  // An element that is not this layout's own (a copy): the same name and kind.
  for (DoorSwing& w : swings)
    if (w.element->name == element.name && w.element->kind == element.kind) {
      w.element = &element;
      return w;
    }
  int left = -1, right = -1;
  RoomsBeside(layout, layout.RoomsOnLevel(level), element.shape, &left, &right);
  return MakeSwing(element, level, left, right, {left >= 0 ? 1.0 : -1.0, true, false});
}

}  // namespace villa
