// Layout -> building volume. Per level: the footprint (layout/footprint.h), exterior walls along it
// (mitred at every corner), interior walls along `interiors` (cut at junctions by the bisectors between
// neighbouring walls, so any angle and any number of walls meet without overlap), openings cut through
// them, door leaves and glass, staircases in the utility rooms and slabs with their stair holes.
#include "building/building.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <numbers>
#include <sstream>

#include "layout/door_swing.h"
#include "layout/footprint.h"
#include "layout/geometry.h"
#include "mesh/geometry2d.h"
#include "mesh/solids.h"

namespace villa {
namespace {

using namespace geo;

// m: a point this close to a line or node is on it. The building snaps more generously than the rules
// (layout.h's tolerance policy) so that nearly-valid input (--allow-invalid) still becomes solids.
constexpr double kOnLine = 1e-4;

std::string Fmt(double v) {
  std::ostringstream out;
  out.precision(3);
  out << v;
  return out.str();
}

using Key = std::pair<long long, long long>;
Key KeyOf(Point p) { return {std::llround(p.x * 1e5), std::llround(p.y * 1e5)}; }

// Starts the ring at its lowest, then leftmost vertex: wall names do not depend on room order.
Ring Canonical(Ring ring) {
  auto it = std::min_element(ring.begin(), ring.end(), [](Point a, Point b) {
    return a.y < b.y - 1e-9 || (std::abs(a.y - b.y) <= 1e-9 && a.x < b.x);
  });
  std::rotate(ring.begin(), it, ring.end());
  return ring;
}

// ---------------------------------------------------------------------------------------------------
// Walls

struct WallPiece {
  std::string name;
  std::string element;  // layout element ("" for exterior walls)
  bool exterior = false;
  Ring plan;
  WallFrame frame;
  SRange full;
  std::vector<WallOpening> openings;
};

// Intersection of the lines p + s d and q + t e.
std::optional<Point> LineIntersection(Point p, Point d, Point q, Point e) {
  double den = Cross(d, e);
  if (std::abs(den) < 1e-12) return std::nullopt;
  double s = Cross(Sub(q, p), e) / den;
  return Add(p, Scale(d, s));
}

// Exterior walls along `footprint` (CCW): returns the pieces and the inner outline (their inner faces).
std::vector<WallPiece> ExteriorWalls(const Ring& footprint, int level, double thickness, Ring& inner,
                                     std::vector<std::string>& warnings) {
  size_t n = footprint.size();
  double t = thickness;
  for (int attempt = 0; attempt < 8; ++attempt) {
    inner.assign(n, Point{});
    for (size_t i = 0; i < n; ++i) {
      size_t prev = (i + n - 1) % n;
      Point d0 = Unit(Sub(footprint[i], footprint[prev]));
      Point d1 = Unit(Sub(footprint[(i + 1) % n], footprint[i]));
      auto q = LineIntersection(Add(footprint[prev], Scale(Left(d0), t)), d0, Add(footprint[i], Scale(Left(d1), t)), d1);
      inner[i] = q ? *q : Add(footprint[i], Scale(Left(d1), t));
    }
    bool ok = true;
    for (size_t i = 0; i < n && ok; ++i) {
      Point d = Unit(Sub(footprint[(i + 1) % n], footprint[i]));
      ok = Dot(Sub(inner[(i + 1) % n], inner[i]), d) > 0.05;
    }
    if (ok) break;
    t *= 0.7;
  }
  if (t < thickness)
    warnings.push_back("level " + std::to_string(level) + ": exterior walls thinned to " + Fmt(t) +
                       " m to fit short footprint edges");
  std::vector<WallPiece> pieces;
  for (size_t i = 0; i < n; ++i) {
    Point a = footprint[i], b = footprint[(i + 1) % n];
    Point d = Unit(Sub(b, a));
    WallPiece piece;
    piece.name = "exterior_" + std::to_string(level) + "_" + std::to_string(i);
    piece.exterior = true;
    piece.frame = {Add(a, Scale(Left(d), t / 2.0)), d, Left(d), t};
    piece.plan = CleanRing({a, b, inner[(i + 1) % n], inner[i]}, 1e-9);
    if (piece.plan.empty()) continue;
    piece.full = FullSection(piece.plan, piece.frame);
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

struct Span {
  std::string name;
  std::string element;
  Point a;
  Point b;
};

// Interior walls of one level: `interiors` minus `opens`, de-duplicated, split at junctions, each cut by
// the bisectors with its neighbours at both ends and clipped to the inner outline of the exterior walls.
std::vector<WallPiece> InteriorWalls(const Layout& layout, int level, const Ring& footprint, const Ring& inner,
                                     double thickness, std::vector<std::string>& warnings) {
  const std::string suffix_all = "@" + std::to_string(level);
  std::vector<Span> spans;
  for (const Element& wall : layout.interiors) {
    if (!wall.OnLevel(level)) continue;
    std::string base = wall.name + (wall.level == kAllLevels ? suffix_all : "");
    Point a = wall.shape.a, b = wall.shape.b;
    double len = Dist(a, b);
    if (len < 0.02) continue;
    Point d = Scale(Sub(b, a), 1.0 / len);
    if (DistanceToBoundary(Lerp(a, b, 0.5), footprint) < kOnLine && DistanceToBoundary(a, footprint) < kOnLine &&
        DistanceToBoundary(b, footprint) < kOnLine) {
      warnings.push_back("interior " + base + ": lies on the exterior boundary; the exterior wall stands there");
      continue;
    }
    // Intervals of [0, len] left after removing opens and walls already placed on the same line.
    std::vector<std::pair<double, double>> keep = {{0.0, len}};
    auto subtract = [&](Point p, Point q) {
      if (std::abs(Cross(d, Sub(p, a))) > kOnLine || std::abs(Cross(d, Sub(q, a))) > kOnLine) return;
      double s0 = Dot(Sub(p, a), d), s1 = Dot(Sub(q, a), d);
      if (s0 > s1) std::swap(s0, s1);
      std::vector<std::pair<double, double>> next;
      for (auto [k0, k1] : keep) {
        if (s1 <= k0 || s0 >= k1) {
          next.push_back({k0, k1});
          continue;
        }
        if (s0 > k0) next.push_back({k0, s0});
        if (s1 < k1) next.push_back({s1, k1});
      }
      keep = next;
    };
    for (const Element& open : layout.opens)
      if (open.OnLevel(level)) subtract(open.shape.a, open.shape.b);
    for (const Span& s : spans) subtract(s.a, s.b);
    int part = 0;
    for (auto [k0, k1] : keep) {
      if (k1 - k0 < 0.02) continue;
      ++part;
      spans.push_back({part == 1 ? base : base + ":" + std::to_string(part), base, Add(a, Scale(d, k0)),
                       Add(a, Scale(d, k1))});
    }
  }
  // Split at T-junctions (another span's end inside this one) and crossings.
  std::vector<Span> split;
  for (size_t i = 0; i < spans.size(); ++i) {
    const Span& s = spans[i];
    double len = Dist(s.a, s.b);
    Point d = Scale(Sub(s.b, s.a), 1.0 / len);
    std::vector<double> cuts;
    for (size_t j = 0; j < spans.size(); ++j) {
      if (j == i) continue;
      const Span& o = spans[j];
      for (Point p : {o.a, o.b}) {
        double t = Dot(Sub(p, s.a), d);
        if (t > kOnLine && t < len - kOnLine && std::abs(Cross(d, Sub(p, s.a))) < kOnLine) cuts.push_back(t);
      }
      Point e = Sub(o.b, o.a);
      double den = Cross(d, e);
      if (std::abs(den) > 1e-9) {
        double t = Cross(Sub(o.a, s.a), e) / den;
        double u = Cross(Sub(o.a, s.a), d) / den;
        double olen = Len(e);
        if (t > kOnLine && t < len - kOnLine && u * olen > kOnLine && u * olen < olen - kOnLine) cuts.push_back(t);
      }
    }
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end(), [](double x, double y) { return y - x < kOnLine; }), cuts.end());
    Point from = s.a;
    int part = 0;
    for (size_t k = 0; k <= cuts.size(); ++k) {
      Point to = k < cuts.size() ? Add(s.a, Scale(d, cuts[k])) : s.b;
      ++part;
      split.push_back({cuts.empty() ? s.name : s.name + "#" + std::to_string(part), s.element, from, to});
      from = to;
    }
  }
  // Nodes: span ends within kOnLine are one.
  std::vector<Point> nodes;
  auto node_of = [&](Point p) {
    for (size_t i = 0; i < nodes.size(); ++i)
      if (Dist(nodes[i], p) < kOnLine) return static_cast<int>(i);
    nodes.push_back(p);
    return static_cast<int>(nodes.size()) - 1;
  };
  struct End {
    int span;
    Point direction;  // away from the node, along the span
  };
  std::map<int, std::vector<End>> at_node;
  std::vector<std::array<int, 2>> span_nodes;
  for (size_t i = 0; i < split.size(); ++i) {
    Point d = Unit(Sub(split[i].b, split[i].a));
    int na = node_of(split[i].a), nb = node_of(split[i].b);
    at_node[na].push_back({static_cast<int>(i), d});
    at_node[nb].push_back({static_cast<int>(i), Scale(d, -1.0)});
    span_nodes.push_back({na, nb});
  }
  const double half = thickness / 2.0;
  std::vector<WallPiece> pieces;
  for (size_t i = 0; i < split.size(); ++i) {
    const Span& s = split[i];
    Point d = Unit(Sub(s.b, s.a));
    Point n = Left(d);
    double len = Dist(s.a, s.b);
    bool on_boundary[2];
    double extend[2];
    for (int e = 0; e < 2; ++e) {
      int node = span_nodes[i][e];
      on_boundary[e] = DistanceToBoundary(nodes[node], footprint) < kOnLine;
      // A junction needs room for the bisector cuts; an end on the facade needs none: the inner
      // face of the exterior wall lies inside the footprint, so clipping to it trims the piece there.
      extend[e] = on_boundary[e] ? 0.0 : at_node[node].size() > 1 ? 2.0 : 0.0;
    }
    WallFrame frame{s.a, d, n, thickness};
    Ring plan = {frame.ToPlan(-extend[0], -half), frame.ToPlan(len + extend[1], -half),
                 frame.ToPlan(len + extend[1], half), frame.ToPlan(-extend[0], half)};
    for (int e = 0; e < 2; ++e) {
      int node = span_nodes[i][e];
      Point p = nodes[node];
      Point away = e == 0 ? d : Scale(d, -1.0);
      const auto& ends = at_node[node];
      if (ends.size() == 1) {
        if (!on_boundary[e]) plan = ClipHalfPlane(plan, p, away);
        continue;
      }
      // Neighbours next counter-clockwise and clockwise; cut along the bisector of each gap.
      double own = std::atan2(away.y, away.x);
      double ccw = 10.0, cw = -10.0;
      for (const End& other : ends) {
        if (other.span == static_cast<int>(i)) continue;
        double gap = std::atan2(other.direction.y, other.direction.x) - own;
        while (gap <= 1e-9) gap += 2.0 * std::numbers::pi;
        while (gap > 2.0 * std::numbers::pi) gap -= 2.0 * std::numbers::pi;
        ccw = std::min(ccw, gap);
        cw = std::max(cw, gap);
      }
      for (double angle : {own + ccw / 2.0, own - (2.0 * std::numbers::pi - cw) / 2.0}) {
        Point b = {std::cos(angle), std::sin(angle)};
        Point m = Left(b);
        double side = Dot(m, away);
        if (std::abs(side) < 1e-9) continue;
        plan = ClipHalfPlane(plan, p, side > 0 ? m : Scale(m, -1.0));
      }
    }
    plan = CleanRing(plan, 1e-9);
    if (!plan.empty() && (on_boundary[0] || on_boundary[1])) plan = CleanRing(ClipConvex(inner, plan), 1e-9);
    if (plan.empty() || Area(plan) < 1e-6) {
      // A stub between an open and the facade lies inside the exterior wall: nothing is lost.
      if (len > 0.4) warnings.push_back("interior " + s.name + ": nothing left of it between the other walls");
      continue;
    }
    WallPiece piece;
    piece.name = s.name;
    piece.element = s.element;
    piece.plan = plan;
    piece.frame = frame;
    piece.full = FullSection(plan, frame);
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

// ---------------------------------------------------------------------------------------------------
// Openings, leaves and glass

struct PlacedOpening {
  const Element* element = nullptr;
  std::string name;
  int piece = -1;
  WallOpening cut;
};

// The wall piece an element lies on: parallel, within the wall's thickness, overlapping its full section.
int FindWall(const std::vector<WallPiece>& walls, const Segment& seg, bool prefer_exterior) {
  int best = -1;
  double best_overlap = 0.0;
  for (int pass = 0; pass < 2 && best < 0; ++pass) {
    for (int i = 0; i < static_cast<int>(walls.size()); ++i) {
      const WallPiece& w = walls[i];
      if ((pass == 0) != (w.exterior == prefer_exterior)) continue;
      const WallFrame& f = w.frame;
      double limit = f.thickness / 2.0 + 1e-3;
      if (std::abs(f.Q(seg.a)) > limit || std::abs(f.Q(seg.b)) > limit) continue;
      double s0 = std::min(f.S(seg.a), f.S(seg.b)), s1 = std::max(f.S(seg.a), f.S(seg.b));
      double overlap = std::min(s1, w.full.hi) - std::max(s0, w.full.lo);
      if (overlap > best_overlap) {
        best_overlap = overlap;
        best = i;
      }
    }
  }
  return best;
}

TriangleMesh BoxInFrame(const WallFrame& f, double s0, double s1, double q0, double q1, double z0, double z1) {
  Ring ring = {f.ToPlan(s0, q0), f.ToPlan(s1, q0), f.ToPlan(s1, q1), f.ToPlan(s0, q1)};
  return ExtrudePlan(CleanRing(ring, 1e-9), {}, z0, z1);
}

// ---------------------------------------------------------------------------------------------------
// Staircases
//
// A switchback stair fills its room: flight 1 on one half of the width from the near side's strip to a
// landing at the far side, flight 2 back on the other half. The only floor left at each level is the
// strip along the near side, so every door of the stair room, on every level of its stack, must open onto
// that strip: the near side is chosen once per stack from the doors of all its levels (ChooseStairSide).

constexpr double kServedOverlap = 0.45;  // m of a side door's width that must open onto the strip (> 2 x 0.2 m person radius)
constexpr double kMinGoing = 0.25;       // m, the shortest going a deeper strip may shorten the treads to
constexpr double kMinLanding = 0.8;      // m, the shallowest landing a deeper strip may leave at the far side
constexpr double kSideTolerance = 0.05;  // m an opening's ends may lie off a side of the room's rectangle
constexpr double kMinStairWidth = 1.8;   // m, two flights of 0.9 m when a passage runs beside them
constexpr double kMinPassage = 0.9;      // m, the narrowest passage left beside narrowed flights

// The room's minimum-area bounding rectangle over its edge directions, and the free rectangle inside
// its walls (`f*`) the flights fill. Sides: 0 = v0 (bottom), 1 = u1 (right), 2 = v1 (top), 3 = u0 (left).
struct StairBox {
  Point u{1, 0}, v{0, 1};
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
  double fu0 = 0, fu1 = 0, fv0 = 0, fv1 = 0;
  double inset[4] = {0, 0, 0, 0};  // m from the room's side to the free rectangle (the wall there + 2 cm)
  bool rectangular = true;
  Point At(double a, double b) const { return Add(Scale(u, a), Scale(v, b)); }
  Point SideMid(int k) const {
    switch (k) {
      case 0: return At((u0 + u1) / 2, v0);
      case 1: return At(u1, (v0 + v1) / 2);
      case 2: return At((u0 + u1) / 2, v1);
      default: return At(u0, (v0 + v1) / 2);
    }
  }
  // Distance of `p` into the room from side k's line (m; negative outside).
  double FromSide(int k, Point p) const {
    switch (k) {
      case 0: return Dot(p, v) - v0;
      case 1: return u1 - Dot(p, u);
      case 2: return v1 - Dot(p, v);
      default: return Dot(p, u) - u0;
    }
  }
  double Depth(int near) const { return near % 2 == 0 ? fv1 - fv0 : fu1 - fu0; }
  double Width(int near) const { return near % 2 == 0 ? fu1 - fu0 : fv1 - fv0; }
};

StairBox StairBoxOf(const Ring& poly, const Ring& footprint, const BuildOptions& options) {
  StairBox box;
  double best_area = 1e300;
  for (size_t i = 0; i < poly.size(); ++i) {
    Point du = Unit(Sub(poly[(i + 1) % poly.size()], poly[i]));
    Point dv = Left(du);
    double a0 = 1e300, a1 = -1e300, b0 = 1e300, b1 = -1e300;
    for (Point p : poly) {
      a0 = std::min(a0, Dot(p, du));
      a1 = std::max(a1, Dot(p, du));
      b0 = std::min(b0, Dot(p, dv));
      b1 = std::max(b1, Dot(p, dv));
    }
    if ((a1 - a0) * (b1 - b0) < best_area - 1e-9) {
      best_area = (a1 - a0) * (b1 - b0);
      box.u = du, box.v = dv, box.u0 = a0, box.u1 = a1, box.v0 = b0, box.v1 = b1;
    }
  }
  box.rectangular = Area(poly) >= 0.98 * best_area;
  for (int k = 0; k < 4; ++k)
    box.inset[k] = (DistanceToBoundary(box.SideMid(k), footprint) < kOnLine ? options.exterior_wall_thickness
                                                                          : options.interior_wall_thickness / 2.0) + 0.02;
  box.fu0 = box.u0 + box.inset[3], box.fu1 = box.u1 - box.inset[1];
  box.fv0 = box.v0 + box.inset[0], box.fv1 = box.v1 - box.inset[2];
  return box;
}

// Tread going and strip depth of the flights across a free depth. The default strip is half of what the
// treads leave (the landing takes the other half); `strip` asks for a deeper one (m from the free
// rectangle's near edge), paid for by shorter treads (down to kMinGoing) and a shallower landing (down to
// kMinLanding). nullopt when the depth does not allow the strip asked for, or no stair at all.
struct FlightSizes {
  double going = 0.0;    // m per tread
  double arrival = 0.0;  // m, the strip's depth from the free rectangle's near edge
};

std::optional<FlightSizes> SizeFlights(double depth, int treads, double strip) {
  FlightSizes f;
  f.going = std::min(0.28, (depth - 1.4) / treads);
  if (f.going < 0.15) return std::nullopt;
  f.arrival = (depth - treads * f.going) / 2.0;
  if (strip <= f.arrival + 1e-9) return f;
  f.going = std::min(f.going, (depth - strip - kMinLanding) / treads);
  if (f.going < kMinGoing - 1e-9) return std::nullopt;
  f.arrival = strip;
  return f;
}

// A door or open of a stair room, on one level of its stack.
struct StairDoor {
  const Element* element = nullptr;
  int level = 0;
  int side = -1;  // side of the room's rectangle it lies on, -1 when on none (a room that is not a rectangle)
  bool entrance = false;  // the building's entrance: everything is reached through it
};

// The near side of a stack, the strip depth it gets, and the passage left beside narrowed flights.
struct StairSide {
  int near = 0;
  double strip = 0.0;          // m from the free rectangle's near edge; 0 keeps the default
  int passage = -1;            // the side (adjacent to `near`) a passage runs along, the full depth; -1: none
  double passage_width = 0.0;  // m of the free rectangle's width the passage takes (each, when both)
  bool both = false;           // passages along both sides adjacent to `near` (`passage` names one of them)
  bool OnPassage(int side) const { return passage >= 0 && (side == passage || (both && side == (passage + 2) % 4)); }
  int Passages() const { return passage < 0 ? 0 : both ? 2 : 1; }
};

// The sides of the free rectangle at across = 0 and at across = width of near side `near`'s frame
// (PlanStair): the two sides adjacent to `near`.
int AcrossStart(int near) { return (near + 3) % 4; }
int AcrossEnd(int near) { return (near + 1) % 4; }

// The strip depth (m from the free rectangle's near edge) `side` needs to serve `door`: 0 when the
// default strip does (a door on the near side itself, or on the passage's side), +inf when no strip can
// (the far side beyond the passage, a side door too narrow, or a door on no side).
double StripNeeded(const StairBox& box, const StairSide& side, const StairDoor& door) {
  constexpr double kNever = std::numeric_limits<double>::infinity();
  const int near = side.near;
  // Where the door starts (m from side k's line, >= 0) and how much of [0, hi] it covers.
  auto overlap = [&](int k, double hi) {
    double d0 = box.FromSide(k, door.element->shape.a), d1 = box.FromSide(k, door.element->shape.b);
    if (d0 > d1) std::swap(d0, d1);
    return std::pair{std::max(d0, 0.0), std::min(d1, hi) - std::max(d0, 0.0)};
  };
  if (door.side == near || side.OnPassage(door.side)) return 0.0;
  if (door.side < 0) return kNever;
  if (door.side == (near + 2) % 4) {
    for (int k : {AcrossStart(near), AcrossEnd(near)})
      if (side.OnPassage(k) && overlap(k, box.inset[k] + side.passage_width).second >= kServedOverlap) return 0.0;
    return kNever;
  }
  auto [d0, width] = overlap(near, 1e300);
  if (width < kServedOverlap) return kNever;
  return std::max(0.0, d0 + kServedOverlap - box.inset[near]);
}

// Chooses the near side of a stair stack from the doors and opens of its room on every level the strip
// serves (`levels`, ascending: the stairs' levels and the one above the top stair): the side that serves
// the entrance (a stair room the entrance opens into: nothing is reached if it opens onto the flights),
// then the most levels, then the most doors, then the most doors on the near side or the passage's side (whole
// doors on floor, not a corner of one), then a door on the lowest level, then full-width flights, then the
// shallower strip, then the side lowest in the plan (y, then x) -- geometry only, never the order of
// elements in the file. Warns, naming the room and the door, for each door the chosen side leaves out.
StairSide ChooseStairSide(const Layout& layout, const Room& room, const StairBox& box, const std::vector<int>& levels,
                          int treads, std::vector<std::string>& warnings) {
  const Ring& poly = room.polygon;
  std::vector<StairDoor> doors;
  for (int l : levels)
    for (const auto* list : {&layout.entrances, &layout.doors, &layout.opens})
      for (const Element& e : *list) {
        if (!e.OnLevel(l) || DistanceToBoundary(Lerp(e.shape.a, e.shape.b, 0.5), poly) >= kOnLine) continue;
        StairDoor d{&e, l, -1, list == &layout.entrances};
        for (int k = 0; k < 4 && d.side < 0; ++k)
          if (std::abs(box.FromSide(k, e.shape.a)) < kSideTolerance && std::abs(box.FromSide(k, e.shape.b)) < kSideTolerance)
            d.side = k;
        doors.push_back(d);
      }
  struct Score {
    int entrances = 0, levels = 0, doors = 0, whole = 0, lowest = 0;
    int passages = 0;
    double strip = 0.0;
    Point mid;
  };
  auto better = [](const Score& a, const Score& b) {
    if (a.entrances != b.entrances) return a.entrances > b.entrances;
    if (a.levels != b.levels) return a.levels > b.levels;
    if (a.doors != b.doors) return a.doors > b.doors;
    if (a.whole != b.whole) return a.whole > b.whole;
    if (a.lowest != b.lowest) return a.lowest > b.lowest;
    if (a.passages != b.passages) return a.passages < b.passages;
    if (std::abs(a.strip - b.strip) > 1e-9) return a.strip < b.strip;
    if (std::abs(a.mid.y - b.mid.y) > 1e-6) return a.mid.y < b.mid.y;
    return a.mid.x < b.mid.x;
  };
  StairSide best_side;
  Score best;
  bool have = false;
  for (int k = 0; k < 4; ++k) {
    // The deepest strip this side allows.
    const double depth = box.Depth(k), width = box.Width(k);
    double deepest = 0.0;
    if (auto f = SizeFlights(depth, treads, 0.0)) deepest = std::max(f->arrival, depth - treads * kMinGoing - kMinLanding);
    // Full-width flights, flights narrowed to leave a passage along either adjacent side, or narrowed in
    // the middle with a passage along both (for doors on three sides).
    const double flights = std::max(kMinStairWidth, width / 2.0);
    const double passage_width = width - flights, half_width = (width - flights) / 2.0;
    const StairSide candidates[] = {{k, 0.0, -1, 0.0, false},
                                    {k, 0.0, AcrossStart(k), passage_width, false},
                                    {k, 0.0, AcrossEnd(k), passage_width, false},
                                    {k, 0.0, AcrossStart(k), half_width, true}};
    for (StairSide candidate : candidates) {
      if (candidate.passage >= 0 && candidate.passage_width < kMinPassage) continue;
      Score s;
      s.mid = box.SideMid(k);
      s.passages = candidate.Passages();
      std::vector<bool> level_served(levels.size(), false);
      for (const StairDoor& d : doors) {
        double need = StripNeeded(box, candidate, d);
        if (need > deepest + 1e-9) continue;
        s.strip = std::max(s.strip, need);
        ++s.doors;
        s.entrances += d.entrance;
        s.whole += d.side == k || candidate.OnPassage(d.side);
        s.lowest += d.level == levels.front();
        level_served[std::find(levels.begin(), levels.end(), d.level) - levels.begin()] = true;
      }
      s.levels = static_cast<int>(std::count(level_served.begin(), level_served.end(), true));
      candidate.strip = s.strip;
      if (!have || better(s, best)) best = s, best_side = candidate, have = true;
    }
  }
  // Name the doors left opening onto the flights or the hole.
  std::optional<FlightSizes> sizes = SizeFlights(box.Depth(best_side.near), treads, best_side.strip);
  for (const StairDoor& d : doors)
    if (!sizes || StripNeeded(box, best_side, d) > sizes->arrival + 1e-9)
      warnings.push_back("staircase in " + room.name() + ": " + d.element->name + " (level " + std::to_string(d.level) +
                         ") opens onto the flights or their hole, not onto the floor left beside them");
  return best_side;
}

struct StairPlan {
  Ring footprint;
  TriangleMesh mesh;
  std::array<Point, 2> arrival{};  // where the upper flight meets the slab above: the hole's open edge
};

// The stair of one level of a stack, starting from `side`'s strip (the one the stair below arrives on).
std::optional<StairPlan> PlanStair(const Room& room, const StairBox& box, StairSide side, double z0,
                                   const BuildOptions& options, std::vector<std::string>& warnings) {
  if (!box.rectangular)
    warnings.push_back("staircase in " + room.name() + ": the room is not a rectangle; the stair uses its bounding box");
  auto at = [&](double a, double b) { return box.At(a, b); };
  const double fu0 = box.fu0, fu1 = box.fu1, fv0 = box.fv0, fv1 = box.fv1;
  // Frame of the stair: origin at a corner of the free rectangle on the near side, `along` into the
  // room, `across` along the near side (so along x across points up: the solid maker orients faces).
  Point origin, along, across;
  const Point u = box.u, v = box.v;
  switch (side.near) {
    case 0: origin = at(fu0, fv0), along = v, across = u; break;
    case 1: origin = at(fu1, fv0), along = Scale(u, -1), across = v; break;
    case 2: origin = at(fu1, fv1), along = Scale(v, -1), across = Scale(u, -1); break;
    default: origin = at(fu0, fv1), along = u, across = Scale(v, -1); break;
  }
  const double depth = box.Depth(side.near);
  double width = box.Width(side.near);
  // A passage beside the flights: they narrow, and shift off it when it runs along the across = 0 side;
  // passages on both sides leave them in the middle.
  if (side.passage >= 0) {
    width -= side.Passages() * side.passage_width;
    if (side.OnPassage(AcrossStart(side.near))) origin = Add(origin, Scale(across, side.passage_width));
  }
  const int risers = options.stair_risers / 2;  // per flight
  const int treads = risers - 1;
  const double r = kLevelHeight / options.stair_risers;
  std::optional<FlightSizes> sizes = SizeFlights(depth, treads, side.strip);
  if (!sizes || width < 1.2) {
    warnings.push_back("staircase in " + room.name() + ": the room is too small for two flights (" + Fmt(depth) +
                       " x " + Fmt(width) + " m free); no staircase");
    return std::nullopt;
  }
  const double g = sizes->going;
  const double arrival = sizes->arrival;
  double run_end = arrival + treads * g;  // where flight 1 meets the landing
  auto profile = [&](double a_start, double z_base) {
    Ring ring = {{a_start, z_base}, {a_start + g, z_base}, {a_start + treads * g, z_base + (treads - 1) * r}};
    for (int k = treads - 1; k >= 0; --k) {
      ring.push_back({a_start + (k + 1) * g, z_base + (k + 1) * r});
      ring.push_back({a_start + k * g, z_base + (k + 1) * r});
    }
    return CleanRing(ring, 1e-9);
  };
  StairPlan plan;
  plan.mesh = ExtrudeProfile(profile(arrival, z0), origin, along, across, 0.0, width / 2.0);
  Point back = Add(origin, Scale(along, run_end));
  plan.mesh.Append(ExtrudeProfile(profile(0.0, z0 + risers * r), back, Scale(along, -1.0), across, width / 2.0, width));
  Ring landing = {Add(origin, Add(Scale(along, run_end), Scale(across, 0.0))),
                  Add(origin, Add(Scale(along, depth), Scale(across, 0.0))),
                  Add(origin, Add(Scale(along, depth), Scale(across, width))),
                  Add(origin, Add(Scale(along, run_end), Scale(across, width)))};
  plan.mesh.Append(ExtrudePlan(CleanRing(landing, 1e-9), {}, z0 + (risers - 2) * r, z0 + risers * r));
  plan.arrival = {Add(origin, Add(Scale(along, arrival), Scale(across, width / 2.0))), Add(origin, Add(Scale(along, arrival), Scale(across, width)))};
  plan.footprint = CleanRing({Add(origin, Scale(along, arrival)), Add(origin, Scale(along, depth)),
                              Add(origin, Add(Scale(along, depth), Scale(across, width))),
                              Add(origin, Add(Scale(along, arrival), Scale(across, width)))},
                             1e-9);
  return plan;
}

// Issue 31: a railing along a to b standing on a floor at z: posts at most 1.0 m apart (one at each end),
// a handrail at 1.0 m and a mid rail at 0.5 m, `inward` (a unit vector across the line) putting the posts
// kRailInset inside the line. Rails and posts are separate boxes (closed solids).
constexpr double kRailHeight = 1.0, kRailPost = 0.04, kRailBar = 0.05, kRailInset = 0.05;
TriangleMesh RailingAlong(Point a, Point b, Point inward, double z) {
  TriangleMesh out;
  const double length = Distance(a, b);
  if (length < 0.3) return out;
  const Point d = Scale(Sub(b, a), 1.0 / length);
  const WallFrame f{a, d, {-d.y, d.x}, 0.0};
  const double side = Dot(inward, f.normal) >= 0.0 ? 1.0 : -1.0;  // `inward` is +q or -q of the frame
  auto box = [&](double t0, double t1, double w, double z0, double z1) {
    const double q0 = side * (kRailInset - w / 2.0), q1 = side * (kRailInset + w / 2.0);
    out.Append(BoxInFrame(f, t0, t1, std::min(q0, q1), std::max(q0, q1), z0, z1));
  };
  const int spans = std::max(1, static_cast<int>(std::ceil((length - kRailPost) / 1.0)));
  for (int k = 0; k <= spans; ++k) {
    const double t = kRailPost / 2.0 + (length - kRailPost) * k / spans;
    box(t - kRailPost / 2.0, t + kRailPost / 2.0, kRailPost, z, z + kRailHeight - kRailBar);
  }
  box(0.0, length, kRailBar, z + kRailHeight - kRailBar, z + kRailHeight);
  box(0.0, length, kRailBar * 0.6, z + 0.5 - kRailBar * 0.3, z + 0.5 + kRailBar * 0.3);
  return out;
}

// The parts of segment a-b farther than `gap` from every edge of `rings` (sampled every 5 cm): where no
// wall already stands.
std::vector<std::array<Point, 2>> Unwalled(Point a, Point b, const std::vector<const Ring*>& rings, double gap) {
  std::vector<std::array<Point, 2>> out;
  const double length = Distance(a, b);
  const int n = std::max(2, static_cast<int>(std::ceil(length / 0.05)));
  int start = -1;
  auto free_at = [&](int k) {
    const Point p = Add(a, Scale(Sub(b, a), static_cast<double>(k) / n));
    for (const Ring* r : rings)
      if (DistanceToBoundary(p, *r) < gap) return false;
    return true;
  };
  for (int k = 0; k <= n + 1; ++k) {
    const bool free = k <= n && free_at(k);
    if (free && start < 0) start = k;
    if (!free && start >= 0) {
      const Point p0 = Add(a, Scale(Sub(b, a), static_cast<double>(start) / n));
      const Point p1 = Add(a, Scale(Sub(b, a), static_cast<double>(k - 1) / n));
      if (Distance(p0, p1) >= 0.3) out.push_back({p0, p1});
      start = -1;
    }
  }
  return out;
}

bool RingInside(const Ring& inner, const Ring& outer) {
  for (Point p : inner)
    if (!PointInRing(p, outer, 0) && DistanceToBoundary(p, outer) > kOnLine) return false;
  return true;
}

}  // namespace

// ---------------------------------------------------------------------------------------------------

std::string BuildOptions::Check() const {
  auto range = [](const char* name, double v, double lo, double hi) -> std::string {
    if (!(v > lo && v <= hi))
      return std::string(name) + " = " + Fmt(v) + ": must be in (" + Fmt(lo) + ", " + Fmt(hi) + "]";
    return "";
  };
  for (std::string m : {range("slab_thickness", slab_thickness, 0.0, 0.5),
                        range("exterior_wall_thickness", exterior_wall_thickness, 0.0, 1.0),
                        range("interior_wall_thickness", interior_wall_thickness, 0.0, 0.5),
                        range("door_height", door_height, 1.0, kLevelHeight - slab_thickness - 0.05),
                        range("window_head", window_head, window_sill, kLevelHeight - slab_thickness - 0.05),
                        range("door_leaf_thickness", door_leaf_thickness, 0.0, 0.2),
                        range("glass_thickness", glass_thickness, 0.0, 0.1)})
    if (!m.empty()) return m;
  if (window_sill <= 0.0) return "window_sill = " + Fmt(window_sill) + ": must be > 0";
  if (panoramic_sill <= 0.0 || panoramic_sill >= window_head)
    return "panoramic_sill = " + Fmt(panoramic_sill) + ": must be in (0, window_head)";
  if (panoramic_head_gap <= 0.0 || panoramic_head_gap > 1.0)
    return "panoramic_head_gap = " + Fmt(panoramic_head_gap) + ": must be in (0, 1]";
  if (stair_risers < 8 || stair_risers % 2 != 0 || stair_risers > 40)
    return "stair_risers = " + std::to_string(stair_risers) + ": must be even, in [8, 40]";
  return "";
}

std::string_view PartKindName(PartKind kind) {
  switch (kind) {
    case PartKind::kFloor: return "floor";
    case PartKind::kTerrace: return "terrace";
    case PartKind::kRoof: return "roof";
    case PartKind::kExteriorWall: return "exterior-wall";
    case PartKind::kInteriorWall: return "interior-wall";
    case PartKind::kDoorLeaf: return "door";
    case PartKind::kWindowGlass: return "glass";
    case PartKind::kStair: return "stair";
    case PartKind::kRailing: return "railing";
    case PartKind::kWindowFrame: return "window-frame";
  }
  return "part";
}

Box3 BuildingMesh::Bounds() const {
  Box3 box;
  for (const MeshPart& p : parts) box.Add(p.mesh.Bounds());
  return box;
}

int BuildingMesh::CountParts(PartKind kind) const {
  return static_cast<int>(std::count_if(parts.begin(), parts.end(), [kind](const MeshPart& p) { return p.kind == kind; }));
}

double BuildingMesh::FloorZ(int level) const { return level * kLevelHeight + slab_thickness; }

Result<BuildingMesh> BuildBuilding(const Layout& layout, const BuildOptions& options) {
  if (std::string problem = options.Check(); !problem.empty()) return Error{"build options: " + problem};
  const int levels = layout.LevelCount();
  if (levels == 0) return Error{"layout has no rooms"};
  BuildingMesh building;
  building.levels = levels;
  building.slab_thickness = options.slab_thickness;
  building.slab_holes.assign(levels, {});
  const double ts = options.slab_thickness;

  // Rooms, cleaned, and the footprint of each level.
  std::vector<Ring> room_rings(layout.rooms.size());
  std::vector<Ring> footprints(levels);
  for (int level = 0; level < levels; ++level) {
    std::vector<Ring> rings;
    for (int i : layout.RoomsOnLevel(level)) {
      const Room& room = layout.rooms[i];
      room_rings[i] = CleanRing(room.polygon);
      if (room_rings[i].empty() || Area(room_rings[i]) < 1e-4)
        return Error{"rooms[\"" + room.name() + "\"].shape: degenerate polygon (area " + Fmt(Area(room.polygon)) + " m2)"};
      rings.push_back(room_rings[i]);
      building.rooms.push_back({room.name(), room.category, level, Area(room_rings[i])});
    }
    if (rings.empty()) return Error{"level " + std::to_string(level) + " has no rooms (levels must stack from 0)"};
    auto regions = FootprintOf(rings, kOnLine);
    size_t holes = 0;
    for (const PolygonWithHoles& r : regions) holes += r.holes.size();
    if (regions.size() != 1 || holes != 0)
      return Error{"level " + std::to_string(level) + ": rooms do not tile one polygon (" + std::to_string(regions.size()) +
                   " outline(s), " + std::to_string(holes) + " hole(s)); run `villa validate`"};
    footprints[level] = Canonical(CleanRing(regions[0].outer));
  }

  // Staircases: one in each utility room below the top level, with the hole it needs in the slab above.
  // A stack is a run of utility rooms with the same outline on consecutive levels; its stairs share one
  // near side (each starts where the one below arrives), chosen from the doors of every level it serves.
  std::map<std::vector<Key>, std::vector<int>> by_outline;  // sorted outline -> room indices, level ascending
  for (int level = 0; level < levels; ++level)
    for (int i : layout.RoomsOnLevel(level)) {
      if (layout.rooms[i].category != Category::kUtilityRoom) continue;
      std::vector<Key> outline;
      for (Point p : room_rings[i]) outline.push_back(KeyOf(p));
      std::sort(outline.begin(), outline.end());
      by_outline[outline].push_back(i);
    }
  std::map<int, StairSide> stair_side;  // stair room index -> the near side of its stack
  for (const auto& [outline, rooms] : by_outline) {
    for (size_t first = 0; first < rooms.size();) {
      size_t last = first;
      while (last + 1 < rooms.size() && layout.rooms[rooms[last + 1]].level == layout.rooms[rooms[last]].level + 1) ++last;
      // The stairs of the run (every room below the top level) and the levels their strips serve.
      std::vector<int> stairs, served;
      for (size_t k = first; k <= last; ++k)
        if (layout.rooms[rooms[k]].level + 1 < levels) stairs.push_back(rooms[k]);
      if (!stairs.empty()) {
        for (int i : stairs) served.push_back(layout.rooms[i].level);
        served.push_back(served.back() + 1);
        Room clean = layout.rooms[stairs.front()];
        clean.polygon = room_rings[stairs.front()];
        StairBox box = StairBoxOf(clean.polygon, footprints[clean.level], options);
        StairSide side = ChooseStairSide(layout, clean, box, served, options.stair_risers / 2 - 1, building.warnings);
        for (int i : stairs) stair_side[i] = side;
      }
      first = last + 1;
    }
  }
  for (int level = 0; level + 1 < levels; ++level) {
    for (int i : layout.RoomsOnLevel(level)) {
      const Room& room = layout.rooms[i];
      if (room.category != Category::kUtilityRoom) continue;
      Room clean = room;
      clean.polygon = room_rings[i];
      auto stair = PlanStair(clean, StairBoxOf(clean.polygon, footprints[level], options), stair_side.at(i),
                             building.FloorZ(level), options, building.warnings);
      if (!stair) continue;
      bool above = false;
      for (int j : layout.RoomsOnLevel(level + 1))
        above = above || (layout.rooms[j].category == Category::kUtilityRoom && RingInside(stair->footprint, room_rings[j]));
      if (!above)
        building.warnings.push_back("staircase in " + room.name() + ": no utility room above it on level " +
                                    std::to_string(level + 1) + "; it rises into whatever is there");
      MeshPart part;
      part.name = "stair_" + room.name();
      part.kind = PartKind::kStair;
      part.level = level;
      part.category = room.category;
      part.element = room.name();
      part.mesh = std::move(stair->mesh);
      building.parts.push_back(std::move(part));
      building.stairs.push_back({level, room.name(), stair->footprint, stair->footprint, stair->arrival});
      building.slab_holes[level + 1].push_back(stair->footprint);
    }
  }

  // Slabs: room floors (with the holes inside them), terraces over the part of the level below that this
  // level does not cover, and the roof.
  struct TerraceOutline {
    std::string name;
    int level;
    Ring outer;
  };
  std::vector<TerraceOutline> terrace_outlines;
  for (int level = 0; level < levels; ++level) {
    const double z0 = level * kLevelHeight;
    std::vector<bool> hole_used(building.slab_holes[level].size(), false);
    auto holes_in = [&](const Ring& outer) {
      std::vector<Ring> inside;
      for (size_t h = 0; h < hole_used.size(); ++h)
        if (!hole_used[h] && RingInside(building.slab_holes[level][h], outer)) {
          inside.push_back(building.slab_holes[level][h]);
          hole_used[h] = true;
        }
      return inside;
    };
    for (int i : layout.RoomsOnLevel(level)) {
      const Room& room = layout.rooms[i];
      MeshPart part;
      part.name = room.name();
      part.kind = PartKind::kFloor;
      part.level = level;
      part.category = room.category;
      part.element = room.name();
      part.mesh = ExtrudePlan(room_rings[i], holes_in(room_rings[i]), z0, z0 + ts);
      building.parts.push_back(std::move(part));
    }
    if (level > 0) {
      // The roof terraces: what this level leaves open of the one below.
      int k = 0;
      for (const PolygonWithHoles& region : FootprintOf({footprints[level - 1], footprints[level]}, kOnLine, {false, true})) {
        std::vector<Ring> holes;
        for (const Ring& h : region.holes) holes.push_back(CleanRing(h));
        for (Ring& h : holes_in(region.outer)) holes.push_back(h);
        MeshPart part;
        part.name = "terrace_" + std::to_string(level) + (k > 0 ? ":" + std::to_string(k + 1) : "");
        part.kind = PartKind::kTerrace;
        part.level = level;
        part.mesh = ExtrudePlan(CleanRing(region.outer), holes, z0, z0 + ts);
        terrace_outlines.push_back({part.name, level, CleanRing(region.outer)});
        building.parts.push_back(std::move(part));
        ++k;
      }
    }
    for (size_t h = 0; h < hole_used.size(); ++h) {
      if (hole_used[h]) continue;
      building.warnings.push_back("level " + std::to_string(level) + ": a stair hole straddles rooms; not cut");
      for (BuiltStair& s : building.stairs)
        if (s.level + 1 == level && s.hole == building.slab_holes[level][h]) s.hole.clear();
    }
    std::vector<Ring> kept;
    for (size_t h = 0; h < hole_used.size(); ++h)
      if (hole_used[h]) kept.push_back(building.slab_holes[level][h]);
    building.slab_holes[level] = kept;
  }
  {
    MeshPart roof;
    roof.name = "roof";
    roof.kind = PartKind::kRoof;
    roof.level = levels - 1;
    roof.mesh = ExtrudePlan(footprints[levels - 1], {}, levels * kLevelHeight, levels * kLevelHeight + ts);
    building.parts.push_back(std::move(roof));
  }
  // Railings (issue 31): round each stair hole on the floor above, but where the upper flight arrives and
  // where a wall stands; along each terrace's edges but where the level's own walls rise from it.
  auto add_railing = [&](const std::string& of, int level, std::optional<Category> category, TriangleMesh rail) {
    if (rail.triangles.empty()) return;
    MeshPart part;
    part.name = "railing_" + of;
    part.kind = PartKind::kRailing;
    part.level = level;
    if (category) part.category = *category;
    part.element = of;
    part.mesh = std::move(rail);
    building.parts.push_back(std::move(part));
  };
  for (const BuiltStair& st : building.stairs) {
    if (st.hole.size() < 3) continue;
    const int up = st.level + 1;
    std::vector<const Ring*> walls;
    for (int j : layout.RoomsOnLevel(up)) walls.push_back(&room_rings[j]);
    TriangleMesh rail;
    const bool ccw = SignedArea(st.hole) > 0;
    for (size_t k = 0; k < st.hole.size(); ++k) {
      const Point a = st.hole[k], b = st.hole[(k + 1) % st.hole.size()];
      const Point d = Scale(Sub(b, a), 1.0 / std::max(Distance(a, b), 1e-12));
      const Point out_of_hole = ccw ? Point{d.y, -d.x} : Point{-d.y, d.x};  // onto the floor beside the hole
      // The edge the upper flight arrives on stays open along the arrival: guarded on either side of it.
      std::vector<std::array<Point, 2>> spans = {{a, b}};
      if (PointSegmentDistance(st.arrival[0], {a, b}) < kOnLine && PointSegmentDistance(st.arrival[1], {a, b}) < kOnLine) {
        const double t0 = Dot(Sub(st.arrival[0], a), d), t1 = Dot(Sub(st.arrival[1], a), d);
        spans = {{a, Add(a, Scale(d, std::min(t0, t1)))}, {Add(a, Scale(d, std::max(t0, t1))), b}};
      }
      for (const auto& [p, q] : spans)
        if (Distance(p, q) >= 0.3)
          for (const auto& [s0, s1] : Unwalled(p, q, walls, 0.25)) rail.Append(RailingAlong(s0, s1, out_of_hole, building.FloorZ(up)));
    }
    add_railing(st.room, up, Category::kUtilityRoom, std::move(rail));
  }
  for (const auto& [name, level, outer] : terrace_outlines) {
    const std::vector<const Ring*> walls = {&footprints[level]};
    TriangleMesh rail;
    const bool ccw = SignedArea(outer) > 0;
    for (size_t k = 0; k < outer.size(); ++k) {
      const Point a = outer[k], b = outer[(k + 1) % outer.size()];
      const Point d = Scale(Sub(b, a), 1.0 / std::max(Distance(a, b), 1e-12));
      const Point in = ccw ? Point{-d.y, d.x} : Point{d.y, -d.x};  // into the terrace
      for (const auto& [s0, s1] : Unwalled(a, b, walls, 0.2)) rail.Append(RailingAlong(s0, s1, in, building.FloorZ(level)));
    }
    add_railing(name, level, std::nullopt, std::move(rail));
  }

  // Walls, openings, leaves and glass, level by level.
  for (int level = 0; level < levels; ++level) {
    const double zb = building.FloorZ(level);
    const double zt = (level + 1) * kLevelHeight;
    Ring inner;
    auto walls = ExteriorWalls(footprints[level], level, options.exterior_wall_thickness, inner, building.warnings);
    building.wall_inner.push_back(inner);
    auto interior = InteriorWalls(layout, level, footprints[level], inner, options.interior_wall_thickness, building.warnings);
    walls.insert(walls.end(), std::make_move_iterator(interior.begin()), std::make_move_iterator(interior.end()));

    std::vector<PlacedOpening> placed;
    auto place = [&](const std::vector<Element>& elements, ElementKind kind) {
      for (const Element& e : elements) {
        if (!(e.OnLevel(level) || (kind == ElementKind::kEntrance && level == 0))) continue;
        std::string name = e.name + (e.level == kAllLevels && kind != ElementKind::kEntrance ? "@" + std::to_string(level) : "");
        bool exterior = kind == ElementKind::kWindow || kind == ElementKind::kEntrance;
        int w = FindWall(walls, e.shape, exterior);
        if (w < 0) {
          building.warnings.push_back(std::string(ElementKindKey(kind)) + " " + name + ": no wall under it; left out");
          continue;
        }
        const WallPiece& wall = walls[w];
        double s0 = std::min(wall.frame.S(e.shape.a), wall.frame.S(e.shape.b));
        double s1 = std::max(wall.frame.S(e.shape.a), wall.frame.S(e.shape.b));
        double lo = wall.full.lo + 0.03, hi = wall.full.hi - 0.03;
        if (s0 < lo || s1 > hi) {
          // Reaching into the corner (where the walls meet) is normal; say so only when much is lost.
          double lost = std::max(0.0, lo - s0) + std::max(0.0, s1 - hi);
          s0 = std::max(s0, lo);
          s1 = std::min(s1, hi);
          if (lost > 0.35) building.warnings.push_back(std::string(ElementKindKey(kind)) + " " + name + ": runs into a wall junction; narrowed to " +
                                      Fmt(std::max(0.0, s1 - s0)) + " m");
        }
        if (s1 - s0 < 0.3) {
          building.warnings.push_back(std::string(ElementKindKey(kind)) + " " + name + ": no room for it on wall " + wall.name + "; left out");
          continue;
        }
        WallOpening cut{s0, s1, zb, zb + options.door_height};
        if (kind == ElementKind::kWindow) {
          cut.z0 = zb + (e.panoramic ? options.panoramic_sill : options.window_sill);
          cut.z1 = e.panoramic ? zt - options.panoramic_head_gap : zb + options.window_head;
        }
        placed.push_back({&e, name, w, cut});
      }
    };
    place(layout.entrances, ElementKind::kEntrance);
    place(layout.doors, ElementKind::kDoor);
    place(layout.windows, ElementKind::kWindow);

    for (int w = 0; w < static_cast<int>(walls.size()); ++w) {
      std::vector<WallOpening> cuts;
      for (const PlacedOpening& p : placed)
        if (p.piece == w) cuts.push_back(p.cut);
      std::sort(cuts.begin(), cuts.end(), [](const WallOpening& a, const WallOpening& b) { return a.s0 < b.s0; });
      std::vector<WallOpening> merged;
      for (const WallOpening& c : cuts) {
        if (!merged.empty() && c.s0 < merged.back().s1 + 0.05) {
          building.warnings.push_back("wall " + walls[w].name + ": overlapping openings merged into one");
          merged.back().s1 = std::max(merged.back().s1, c.s1);
          merged.back().z0 = std::min(merged.back().z0, c.z0);
          merged.back().z1 = std::max(merged.back().z1, c.z1);
        } else {
          merged.push_back(c);
        }
      }
      MeshPart part;
      part.name = walls[w].name;
      part.kind = walls[w].exterior ? PartKind::kExteriorWall : PartKind::kInteriorWall;
      part.level = level;
      part.element = walls[w].element;
      part.mesh = WallSolid(walls[w].plan, walls[w].frame, zb, zt, merged);
      building.parts.push_back(std::move(part));
    }
    for (const PlacedOpening& p : placed) {
      const WallFrame& f = walls[p.piece].frame;
      const double half = f.thickness / 2.0;
      const double gap = 0.002;  // m between a leaf or pane and the reveals: no touching faces
      MeshPart part;
      part.name = p.name;
      part.level = level;
      part.element = p.element->name;
      if (p.element->kind == ElementKind::kWindow) {
        part.kind = PartKind::kWindowGlass;
        double g = options.glass_thickness / 2.0;
        part.mesh = BoxInFrame(f, p.cut.s0 + gap, p.cut.s1 - gap, -g, g, p.cut.z0 + gap, p.cut.z1 - gap);
        // Its frame (issue 31): jambs, head and bottom rail round the pane, 6 cm wide and 7 cm deep (within
        // the wall's thickness: nothing stands out into the room), a separate solid each.
        const double fw = 0.06, fd = std::min(0.07, f.thickness - 0.02) / 2.0;
        const double s0 = p.cut.s0 + gap, s1 = p.cut.s1 - gap, z0 = p.cut.z0 + gap, z1 = p.cut.z1 - gap;
        if (s1 - s0 > 3 * fw && z1 - z0 > 3 * fw) {
          MeshPart frame;
          frame.name = "frame_" + p.name;
          frame.kind = PartKind::kWindowFrame;
          frame.level = level;
          frame.element = p.element->name;
          frame.mesh = BoxInFrame(f, s0, s0 + fw, -fd, fd, z0, z1);
          frame.mesh.Append(BoxInFrame(f, s1 - fw, s1, -fd, fd, z0, z1));
          frame.mesh.Append(BoxInFrame(f, s0 + fw + gap, s1 - fw - gap, -fd, fd, z1 - fw, z1));
          frame.mesh.Append(BoxInFrame(f, s0 + fw + gap, s1 - fw - gap, -fd, fd, z0, z0 + fw));
          building.parts.push_back(std::move(frame));
        }
      } else {
        part.kind = PartKind::kDoorLeaf;
        double lt = options.door_leaf_thickness;
        double width = p.cut.s1 - p.cut.s0 - 2 * gap;
        // Swung open as layout/door_swing.h's rule says (the floor plan draws the same swing): into its
        // room, hinged at the jamb it names, 90 degrees, or 180 degrees flat against the wall beside the
        // hinge. Hung closed in its opening when the leaf's sweep would hit a wall or a staircase.
        SwingClearance clearance;
        clearance.exterior_wall = options.exterior_wall_thickness;
        clearance.interior_wall = options.interior_wall_thickness;
        clearance.leaf_thickness = lt;
        const DoorSwing swing = SwingOfDoor(layout, *p.element, level, clearance);
        const int side = Dot(swing.leaf_side, f.normal) >= 0.0 ? 1 : -1;
        const double s_hinge = f.S(swing.hinge);
        const int hinge = std::abs(s_hinge - p.cut.s0) <= std::abs(s_hinge - p.cut.s1) ? 0 : 1;
        // The leaf's direction from its hinge (s, q: a right-handed frame, so turns there are turns in the
        // plan) closed, open at 90 degrees and flat; the turn from one to another.
        const double closed_dir = hinge == 0 ? 0.0 : std::numbers::pi, open_dir = side > 0 ? std::numbers::pi / 2 : -std::numbers::pi / 2;
        const double flat_dir = hinge == 0 ? std::numbers::pi : 0.0;
        auto turn = [](double from, double to) { return std::remainder(to - from, 2 * std::numbers::pi); };
        bool placed_open = false;
        if (options.door_leaves_open) {
          // The leaf's box in the wall's frame: s along it, q across (from the centre line).
          double s0 = hinge == 0 ? p.cut.s0 + gap : p.cut.s1 - gap - lt, s1 = s0 + lt;
          double q0 = side > 0 ? half + gap : -half - gap - width, q1 = q0 + width;
          // The swept quarter disc lies within this square beside the opening; a flat leaf's half disc
          // within the square and the one beside it over the wall it folds onto.
          double sweep_s0 = hinge == 0 ? p.cut.s0 : p.cut.s1 - width - 2 * gap;
          double sweep_s1 = sweep_s0 + width + 2 * gap;
          if (swing.flat) {
            // Its hinge edge 2 mm inside the jamb's line, as a 90 degree leaf's is: swung shut it keeps 2 mm
            // from both reveals (flush with the near one, a simulator's hinge bound).
            s0 = hinge == 0 ? p.cut.s0 + gap - width : p.cut.s1 - gap;
            s1 = s0 + width;
            q0 = side > 0 ? half + gap : -half - gap - lt;
            q1 = q0 + lt;
            if (hinge == 0) sweep_s0 -= width;
            else sweep_s1 += width;
          }
          const double sq0 = side > 0 ? half + gap : -half - gap - width;
          Ring sweep = CleanRing({f.ToPlan(sweep_s0, sq0), f.ToPlan(sweep_s1, sq0), f.ToPlan(sweep_s1, sq0 + width),
                                  f.ToPlan(sweep_s0, sq0 + width)},
                                 1e-9);
          std::string blocker;
          for (const WallPiece& w : walls)
            if (blocker.empty() && ConvexOverlapArea(w.plan, sweep) > 1e-4) blocker = "wall " + w.name;
          for (const BuiltStair& st : building.stairs)
            if (blocker.empty() && st.level == level && ConvexOverlapArea(st.footprint, sweep) > 1e-4)
              blocker = "the staircase in " + st.room;
          if (blocker.empty()) {
            part.mesh = BoxInFrame(f, s0, s1, q0, q1, p.cut.z0 + 0.01, p.cut.z1 - gap);
            placed_open = true;
            // The hinge: the leaf's edge by the opening, on the face toward the wall it stands off.
            const double hs = swing.flat ? (hinge == 0 ? s1 : s0) : (hinge == 0 ? s0 : s1);
            const double hq = side > 0 ? q0 : q1;
            const double from = swing.flat ? flat_dir : open_dir;
            // A flat leaf closes through the open position (the way it came), not through the wall.
            const double to_open = turn(from, open_dir);
            part.hinge = MeshPart::Hinge{f.ToPlan(hs, hq), to_open + turn(open_dir, closed_dir), to_open};
          } else {
            building.warnings.push_back(std::string(ElementKindKey(p.element->kind)) + " " + p.name + ": its swing" +
                                        (swing.into >= 0 ? " into " + layout.rooms[swing.into].name() : "") + " would hit " +
                                        blocker + "; hung closed");
          }
        }
        if (!placed_open) {
          part.mesh = BoxInFrame(f, p.cut.s0 + gap, p.cut.s1 - gap, -lt / 2, lt / 2, p.cut.z0 + 0.01, p.cut.z1 - gap);
          const double hs = hinge == 0 ? p.cut.s0 + gap : p.cut.s1 - gap, hq = side > 0 ? lt / 2 : -lt / 2;
          part.hinge = MeshPart::Hinge{f.ToPlan(hs, hq), 0.0, turn(closed_dir, open_dir)};
        }
      }
      building.parts.push_back(std::move(part));
    }
  }
  return building;
}

// ---------------------------------------------------------------------------------------------------

double ConvexOverlapArea(const Ring& a, const Ring& b) {
  if (a.size() < 3 || b.size() < 3) return 0.0;
  Ring clip = b;
  if (SignedArea(clip) < 0) std::reverse(clip.begin(), clip.end());
  Ring result = ClipConvex(a, clip);
  return result.size() < 3 ? 0.0 : std::abs(SignedArea(result));
}

int VcrReport::connected_pairs() const {
  return static_cast<int>(std::count_if(pairs.begin(), pairs.end(), [](const auto& p) { return p.connected(); }));
}

double VcrReport::vcr() const { return pairs.empty() ? 1.0 : static_cast<double>(connected_pairs()) / pairs.size(); }

VcrReport MeasureVcr(const BuildingMesh& building) {
  VcrReport report;
  for (int level = 0; level + 1 < building.levels; ++level) {
    VerticalConnection pair;
    pair.lower_level = level;
    for (const MeshPart& part : building.parts) {
      if (part.kind != PartKind::kStair || part.level != level) continue;
      // The staircase's plan outline from its mesh: the convex hull of its vertices.
      std::vector<Point> pts;
      for (const Vec3& v : part.mesh.vertices) pts.push_back({v.x, v.y});
      std::sort(pts.begin(), pts.end(), [](Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
      Ring hull;
      for (int pass = 0; pass < 2; ++pass) {
        size_t start = hull.size();
        for (Point p : pts) {
          while (hull.size() >= start + 2 && Cross(Sub(hull.back(), hull[hull.size() - 2]), Sub(p, hull.back())) <= 0)
            hull.pop_back();
          hull.push_back(p);
        }
        hull.pop_back();
        std::reverse(pts.begin(), pts.end());
      }
      for (const Ring& hole : building.slab_holes[level + 1]) pair.overlap_area += ConvexOverlapArea(hull, hole);
    }
    report.pairs.push_back(pair);
  }
  return report;
}

}  // namespace villa
