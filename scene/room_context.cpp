#include "scene/room_context.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

// Boost 1.74's rescaling policy trips GCC 12's -Wmaybe-uninitialized at -O3 (a false positive inside
// Boost); the rescaling itself is what makes the overlay robust here, so it stays on and the warning off.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#pragma GCC diagnostic pop

#include "layout/geometry.h"
#include "mesh/geometry2d.h"
#include "scene/door_swing.h"

namespace villa::scene {
namespace {

using namespace villa::geo;
namespace bg = boost::geometry;
using BPoint = bg::model::d2::point_xy<double>;
using BPolygon = bg::model::polygon<BPoint, false, true>;  // CCW, closed
using BMulti = bg::model::multi_polygon<BPolygon>;

constexpr double kWindowZoneDepth = 0.5;   // m in front of the wall's inner face (PRIORS.md)
constexpr double kPassageDepth = 0.6;      // m each side of an open connection
constexpr double kFloorReach = 0.3;        // m: a zone starting this low above the floor blocks floor objects
constexpr double kWallProbeStep = 0.05;    // m between samples along a wall when finding its free stretches
constexpr double kArrivalMax = 1.2;        // m: the longest arrival strip kept in front of a staircase

BPolygon ToBoost(const Ring& ring) {
  BPolygon poly;
  for (const Point& p : ring) poly.outer().push_back({p.x, p.y});
  if (!ring.empty()) poly.outer().push_back({ring[0].x, ring[0].y});
  bg::correct(poly);
  return poly;
}

std::vector<Ring> FromBoost(const BMulti& multi, std::vector<std::string>* warnings) {
  std::vector<Ring> out;
  for (const BPolygon& poly : multi) {
    Ring ring;
    for (size_t i = 0; i + 1 < poly.outer().size(); ++i) ring.push_back({poly.outer()[i].x(), poly.outer()[i].y()});
    ring = WithoutCollinearCorners(CleanRing(ring, 1e-9), 1e-9);
    if (ring.size() < 3 || Area(ring) < 1e-4) continue;
    if (!poly.inners().empty() && warnings) warnings->push_back("free floor has a hole; its outline is kept");
    out.push_back(std::move(ring));
  }
  return out;
}

BMulti UnionOf(const std::vector<Ring>& rings) {
  BMulti acc;
  for (const Ring& r : rings) {
    if (r.size() < 3) continue;
    BMulti next;
    bg::union_(acc, ToBoost(r), next);
    acc = std::move(next);
  }
  return acc;
}

double AreaOf(const BMulti& multi) { return std::abs(bg::area(multi)); }

// Intersection of the lines p + s d and q + t e; nullopt when parallel.
std::optional<Point> LineMeet(Point p, Point d, Point q, Point e) {
  double den = Cross(d, e);
  if (std::abs(den) < 1e-9) return std::nullopt;
  return Add(p, Scale(d, Cross(Sub(q, p), e) / den));
}

struct PieceFrame {
  Point a, b;     // the piece on the room edge
  Point dir, in;  // along the edge; into the room
  double depth;
};

PieceFrame FrameOf(const Ring& polygon, const EdgePiece& piece) {
  Point a = polygon[piece.edge], b = polygon[(piece.edge + 1) % polygon.size()];
  Point dir = Unit(Sub(b, a));
  return {Add(a, Scale(dir, piece.t0)), Add(a, Scale(dir, piece.t1)), dir, Left(dir), piece.depth};
}

// The wall band of each piece: between the piece and its inset line, cut along the mitre where two pieces
// meet at a corner of the room, squared off where the wall depth changes along a straight edge.
std::vector<Ring> WallBands(const Ring& polygon, const std::vector<EdgePiece>& pieces) {
  const size_t n = pieces.size();
  std::vector<PieceFrame> f;
  for (const EdgePiece& p : pieces) f.push_back(FrameOf(polygon, p));
  // corner[k]: the inner point where piece k-1 meets piece k (nullopt: no mitre, square caps).
  std::vector<std::optional<Point>> corner(n);
  for (size_t k = 0; k < n; ++k) {
    const PieceFrame& prev = f[(k + n - 1) % n];
    const PieceFrame& cur = f[k];
    if (Dist(prev.b, cur.a) > 1e-9) continue;  // not adjacent (cannot happen for a closed ring)
    auto m = LineMeet(Add(prev.b, Scale(prev.in, prev.depth)), prev.dir, Add(cur.a, Scale(cur.in, cur.depth)), cur.dir);
    // A mitre far beyond both depths (a needle-sharp corner) is replaced by square caps.
    if (m && Dist(*m, cur.a) <= 4.0 * std::max(prev.depth, cur.depth) + 1e-9) corner[k] = *m;
  }
  std::vector<Ring> bands;
  for (size_t k = 0; k < n; ++k) {
    const PieceFrame& p = f[k];
    const double d = p.depth;
    if (d <= 0.0) continue;
    auto square_start = [&] { return std::pair{Sub(p.a, Scale(p.dir, d)), Add(Sub(p.a, Scale(p.dir, d)), Scale(p.in, d))}; };
    auto square_end = [&] { return std::pair{Add(p.b, Scale(p.dir, d)), Add(Add(p.b, Scale(p.dir, d)), Scale(p.in, d))}; };
    auto [base0, inner0] = corner[k] ? std::pair{p.a, *corner[k]} : square_start();
    auto [base1, inner1] = corner[(k + 1) % n] ? std::pair{p.b, *corner[(k + 1) % n]} : square_end();
    Ring band = {base0, base1, inner1, inner0};
    if (Dot(Sub(inner1, inner0), p.dir) <= 1e-9 || SignedArea(band) <= 1e-12) {
      // The inset line of a short piece between two converging mitres has vanished: a plain rectangle.
      auto s0 = square_start();
      auto s1 = square_end();
      band = {s0.first, s1.first, s1.second, s0.second};
    }
    bands.push_back(band);
  }
  return bands;
}

// Rooms of `level` (indices) and their polygons.
std::vector<Ring> LevelRings(const Layout& layout, int level) {
  std::vector<Ring> rings;
  for (int i : layout.RoomsOnLevel(level)) rings.push_back(layout.rooms[i].polygon);
  return rings;
}

bool OnRoomBoundary(const Segment& s, const Ring& polygon) { return LengthOnBoundary(s, polygon, kTolerance) > 0.01; }

// The parameter interval of `s` projected onto the line of `inner` (m from inner.a), clipped to it.
std::optional<Interval> ProjectOnto(const Segment& s, const Segment& inner) {
  Point dir = Unit(Sub(inner.b, inner.a));
  double len = Length(inner);
  double t0 = Dot(Sub(s.a, inner.a), dir), t1 = Dot(Sub(s.b, inner.a), dir);
  if (t0 > t1) std::swap(t0, t1);
  t0 = std::max(t0, 0.0);
  t1 = std::min(t1, len);
  if (t1 - t0 <= 1e-6) return std::nullopt;
  return Interval{t0, t1};
}

// Does `s` lie on room edge `edge` (collinear, overlapping)?
bool OnEdge(const Segment& s, const Ring& polygon, int edge) {
  Segment e{polygon[edge], polygon[(edge + 1) % polygon.size()]};
  Interval overlap;
  return CollinearOverlapInterval(s, e, kTolerance, &overlap) && overlap.second - overlap.first > 0.01;
}

bool InAnyRing(Point p, const std::vector<Ring>& rings) {
  for (const Ring& r : rings)
    if (PointInRing(p, r, 0)) return true;
  return false;
}

// Distance along the ray p + t d to the first crossing of the free floor's boundary (t > 0).
double RayToBoundary(Point p, Point d, const std::vector<Ring>& rings) {
  double best = 1e300;
  for (const Ring& r : rings) {
    for (size_t i = 0; i < r.size(); ++i) {
      Point a = r[i], b = r[(i + 1) % r.size()];
      Point e = Sub(b, a);
      double den = Cross(d, e);
      if (std::abs(den) < 1e-12) continue;
      double t = Cross(Sub(a, p), e) / den;
      double u = Cross(Sub(a, p), d) / den;
      if (t > 1e-9 && u >= -1e-9 && u <= 1 + 1e-9) best = std::min(best, t);
    }
  }
  return best;
}

// The strip in front of a staircase where people step on and off: beside the footprint edge that faces
// open floor, as deep as that floor reaches (at most kArrivalMax).
std::optional<Ring> ArrivalStrip(const Ring& footprint, const std::vector<Ring>& free_floor) {
  Ring ring = CleanRing(footprint, 1e-9);
  double best_depth = 0.0;
  std::optional<Ring> best;
  for (size_t i = 0; i < ring.size(); ++i) {
    Point a = ring[i], b = ring[(i + 1) % ring.size()];
    Point out = Scale(Left(Unit(Sub(b, a))), -1.0);  // outward of a CCW ring
    Point mid = Lerp(a, b, 0.5);
    Point probe = Add(mid, Scale(out, 0.3));
    if (!InAnyRing(probe, free_floor)) continue;
    double depth = std::min(kArrivalMax, RayToBoundary(Add(mid, Scale(out, 1e-6)), out, free_floor));
    if (depth > best_depth) {
      best_depth = depth;
      best = CleanRing({a, Add(a, Scale(out, depth)), Add(b, Scale(out, depth)), b}, 1e-9);
    }
  }
  return best;
}

// The stretches of a wall where nothing floor-level is in the way: sampled every kWallProbeStep, each
// sample probed a little and a wardrobe's depth in front of the wall.
std::vector<Interval> FreeStretches(const WallEdge& wall, const std::vector<KeepOut>& zones, double floor_z) {
  const double len = Length(wall.inner);
  Point dir = Unit(Sub(wall.inner.b, wall.inner.a));
  Point in = Left(dir);
  std::vector<Interval> free;
  for (double t = kWallProbeStep / 2.0; t < len; t += kWallProbeStep) {
    bool blocked = false;
    for (const Interval& o : wall.openings) blocked = blocked || (t >= o.first && t <= o.second);
    Point base = Add(wall.inner.a, Scale(dir, t));
    for (const KeepOut& z : zones) {
      if (blocked) break;
      if (z.z_min > floor_z + kFloorReach) continue;
      for (double depth : {0.05, 0.3, 0.55})
        blocked = blocked || PointInRing(Add(base, Scale(in, depth)), z.polygon, 0);
    }
    if (!blocked) free.push_back({std::max(0.0, t - kWallProbeStep / 2.0), std::min(len, t + kWallProbeStep / 2.0)});
  }
  // Openings are exact: cut them out of the sampled stretches.
  std::vector<Interval> out;
  for (Interval f : MergeIntervals(free, 1e-9)) {
    for (const Interval& o : wall.openings) {
      if (o.second <= f.first || o.first >= f.second) continue;
      if (o.first > f.first) out.push_back({f.first, o.first});
      f.first = std::max(f.first, o.second);
    }
    if (f.second - f.first > 1e-6) out.push_back(f);
  }
  return MergeIntervals(out, 1e-6);
}

Ring Rectangle(const Segment& s, Point normal, double q0, double q1) {
  return CleanRing({Add(s.a, Scale(normal, q0)), Add(s.b, Scale(normal, q0)), Add(s.b, Scale(normal, q1)),
                    Add(s.a, Scale(normal, q1))},
                   1e-9);
}

class ContextBuilder {
 public:
  ContextBuilder(const Layout& layout, const BuildingMesh& building, const BuildOptions& options)
      : layout_(layout), building_(building), options_(options) {}

  RoomContext Build(const Room& room) {
    RoomContext c;
    c.name = room.name();
    c.category = room.category;
    c.level = room.level;
    c.polygon = room.polygon;
    c.area = Area(room.polygon);
    c.floor_z = room.level * kLevelHeight + options_.slab_thickness;
    c.clear_height = kLevelHeight - options_.slab_thickness;
    for (const Room& other : layout_.rooms) {
      if (&other == &room) break;
      c.ordinal += other.category == room.category;
    }
    for (int i : layout_.RoomsOnLevel(room.level)) c.level_categories.push_back(layout_.rooms[i].category);

    const std::vector<Segment>& exterior = Exterior(room.level);
    std::vector<EdgePiece> pieces = WallPieces(room.polygon, exterior, options_);
    c.free_floor = FreeFloor(room.polygon, pieces);
    if (room.level < static_cast<int>(building_.wall_inner.size()))
      c.free_floor = InsideWalls(std::move(c.free_floor), building_.wall_inner[room.level]);
    for (const Ring& r : c.free_floor) c.free_area += Area(r);
    if (c.free_floor.size() > 1) c.warnings.push_back("the free floor falls into " + std::to_string(c.free_floor.size()) + " pieces");

    Openings(room, c);
    KeepOuts(room, c);
    Walls(room, pieces, c);

    std::vector<Ring> stairs;
    for (const KeepOut& z : c.keep_outs)
      if (z.kind == KeepOutKind::kStair || z.kind == KeepOutKind::kStairHole || z.kind == KeepOutKind::kStairArrival)
        stairs.push_back(z.polygon);
    c.furnishable_area = c.free_area;
    if (!stairs.empty()) {
      BMulti free_multi = UnionOf(c.free_floor), rest;
      bg::difference(free_multi, UnionOf(stairs), rest);
      c.furnishable_area = AreaOf(rest);
    }
    return c;
  }

 private:
  const std::vector<Segment>& Exterior(int level) {
    auto it = exterior_.find(level);
    if (it == exterior_.end())
      it = exterior_.emplace(level, ExteriorBoundaryOf(LevelRings(layout_, level), kTolerance).pieces).first;
    return it->second;
  }

  const std::vector<DoorSwing>& Swings(int level) {
    auto it = swings_.find(level);
    if (it == swings_.end()) it = swings_.emplace(level, DoorSwings(layout_, building_, options_, level)).first;
    return it->second;
  }

  void Openings(const Room& room, RoomContext& c) {
    auto add = [&](const std::vector<Element>& list, ElementKind kind) {
      for (const Element& e : list)
        if ((kind == ElementKind::kEntrance ? room.level == 0 : e.OnLevel(room.level)) && OnRoomBoundary(e.shape, room.polygon))
          c.openings.push_back({e.name, kind, e.shape});
    };
    add(layout_.entrances, ElementKind::kEntrance);
    add(layout_.doors, ElementKind::kDoor);
    add(layout_.opens, ElementKind::kOpen);
    add(layout_.windows, ElementKind::kWindow);
  }

  // The room edge an opening lies on, and the normal into the room there.
  std::optional<Point> InwardNormal(const Segment& s, const Ring& polygon) const {
    for (size_t i = 0; i < polygon.size(); ++i)
      if (OnEdge(s, polygon, static_cast<int>(i))) return Left(Unit(Sub(polygon[(i + 1) % polygon.size()], polygon[i])));
    return std::nullopt;
  }

  void KeepOuts(const Room& room, RoomContext& c) {
    auto overlaps = [&](const Ring& r) { return r.size() >= 3 && IntersectionArea(r, room.polygon) > 1e-3; };
    const double door_top = c.floor_z + options_.door_height;
    for (const DoorSwing& s : Swings(room.level)) {
      if (overlaps(s.sweep)) c.keep_outs.push_back({KeepOutKind::kDoorSweep, s.element, s.sweep, c.floor_z, door_top});
      for (const Ring& strip : s.strips)
        if (overlaps(strip)) c.keep_outs.push_back({KeepOutKind::kDoorStrip, s.element, strip, c.floor_z, door_top});
    }
    const double half = options_.interior_wall_thickness / 2.0;
    for (const ContextOpening& o : c.openings) {
      auto in = InwardNormal(o.shape, room.polygon);
      if (!in) continue;
      if (o.kind == ElementKind::kOpen) {
        Ring passage = Rectangle(o.shape, *in, -(half + kPassageDepth), half + kPassageDepth);
        c.keep_outs.push_back({KeepOutKind::kOpenPassage, o.name, passage, c.floor_z, door_top});
      } else if (o.kind == ElementKind::kWindow) {
        const Element* e = FindElement(layout_.windows, o.name);
        bool panoramic = e && e->panoramic;
        double sill = panoramic ? options_.panoramic_sill : options_.window_sill;
        double head = panoramic ? c.clear_height - options_.panoramic_head_gap : options_.window_head;
        Ring zone = Rectangle(o.shape, *in, 0.0, options_.exterior_wall_thickness + kWindowZoneDepth);
        c.keep_outs.push_back({KeepOutKind::kWindow, o.name, zone, c.floor_z + sill, c.floor_z + head});
      }
    }
    const double top = c.floor_z + c.clear_height;
    for (const BuiltStair& st : building_.stairs) {
      bool here = st.level == room.level && st.room == c.name && st.footprint.size() >= 3;
      bool from_below = st.level + 1 == room.level && st.hole.size() >= 3 && overlaps(st.hole);
      if (!here && !from_below) continue;
      const Ring& ring = here ? st.footprint : st.hole;
      c.keep_outs.push_back({here ? KeepOutKind::kStair : KeepOutKind::kStairHole, st.room, CleanRing(ring, 1e-9), c.floor_z, top});
      if (auto arrival = ArrivalStrip(ring, c.free_floor))
        c.keep_outs.push_back({KeepOutKind::kStairArrival, st.room, *arrival, c.floor_z, top});
    }
  }

  static const Element* FindElement(const std::vector<Element>& list, const std::string& name) {
    for (const Element& e : list)
      if (e.name == name) return &e;
    return nullptr;
  }

  void Walls(const Room& room, const std::vector<EdgePiece>& pieces, RoomContext& c) {
    for (const Ring& ring : c.free_floor) {
      for (size_t i = 0; i < ring.size(); ++i) {
        Segment seg{ring[i], ring[(i + 1) % ring.size()]};
        double len = Length(seg);
        if (len < 0.05) continue;
        Point dir = Unit(Sub(seg.b, seg.a));
        Point mid = Lerp(seg.a, seg.b, 0.5);
        const EdgePiece* on = nullptr;
        for (const EdgePiece& p : pieces) {
          PieceFrame f = FrameOf(room.polygon, p);
          if (Dot(dir, f.dir) < 1.0 - 1e-9) continue;
          Point base = Add(f.a, Scale(f.in, f.depth));
          if (std::abs(Cross(f.dir, Sub(seg.a, base))) > 1e-6 || std::abs(Cross(f.dir, Sub(seg.b, base))) > 1e-6) continue;
          double t = Dot(Sub(mid, base), f.dir);
          if (t < -f.depth - 1e-6 || t > Length({f.a, f.b}) + f.depth + 1e-6) continue;
          on = &p;
          break;
        }
        if (!on) continue;  // a cap or mitre step, not a wall face
        WallEdge w;
        w.edge = on->edge;
        w.exterior = on->exterior;
        w.thickness = on->depth;
        w.inner = seg;
        for (const ContextOpening& o : c.openings) {
          if (!OnEdge(o.shape, room.polygon, w.edge)) continue;
          auto span = ProjectOnto(o.shape, w.inner);
          if (!span) continue;
          if (o.kind == ElementKind::kWindow) {
            const Element* e = FindElement(layout_.windows, o.name);
            bool pano = e && e->panoramic;
            w.windows.push_back({o.name, *span, pano ? options_.panoramic_sill : options_.window_sill,
                                 pano ? c.clear_height - options_.panoramic_head_gap : options_.window_head, pano});
          } else {
            w.openings.push_back(*span);
          }
        }
        w.openings = MergeIntervals(w.openings, 1e-9);
        w.free = FreeStretches(w, c.keep_outs, c.floor_z);
        c.walls.push_back(std::move(w));
      }
    }
  }

  const Layout& layout_;
  const BuildingMesh& building_;
  const BuildOptions& options_;
  std::map<int, std::vector<Segment>> exterior_;
  std::map<int, std::vector<DoorSwing>> swings_;
};

}  // namespace

std::string_view KeepOutKindName(KeepOutKind kind) {
  switch (kind) {
    case KeepOutKind::kDoorSweep: return "door-sweep";
    case KeepOutKind::kDoorStrip: return "door-strip";
    case KeepOutKind::kOpenPassage: return "open-passage";
    case KeepOutKind::kWindow: return "window";
    case KeepOutKind::kStair: return "stair";
    case KeepOutKind::kStairHole: return "stair-hole";
    case KeepOutKind::kStairArrival: return "stair-arrival";
  }
  return "door-sweep";
}

double WallEdge::length() const { return Length(inner); }

double RoomContext::FreeWallLength() const {
  double total = 0.0;
  for (const WallEdge& w : walls) total += TotalLength(w.free);
  return total;
}

bool RoomContext::HasWindow() const {
  return std::any_of(openings.begin(), openings.end(), [](const ContextOpening& o) { return o.kind == ElementKind::kWindow; });
}

std::vector<EdgePiece> WallPieces(const Ring& polygon, const std::vector<Segment>& exterior_boundary,
                                  const BuildOptions& options) {
  std::vector<EdgePiece> pieces;
  const double half = options.interior_wall_thickness / 2.0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    Segment edge{polygon[i], polygon[(i + 1) % polygon.size()]};
    double len = Length(edge);
    if (len < 1e-9) continue;
    std::vector<Interval> outer;
    for (const Segment& piece : exterior_boundary) {
      Interval overlap;
      if (CollinearOverlapInterval(edge, piece, kTolerance, &overlap)) outer.push_back(overlap);
    }
    outer = MergeIntervals(outer, 1e-9);
    double t = 0.0;
    auto push = [&](double t0, double t1, bool ext) {
      if (t1 - t0 <= 1e-6) return;
      pieces.push_back({static_cast<int>(i), t0, t1, ext ? options.exterior_wall_thickness : half, ext});
    };
    for (const Interval& o : outer) {
      push(t, o.first, false);
      push(std::max(t, o.first), std::min(len, o.second), true);
      t = std::min(len, o.second);
    }
    push(t, len, false);
  }
  return pieces;
}

std::vector<Ring> FreeFloor(const Ring& polygon, const std::vector<EdgePiece>& pieces) {
  // One band at a time: the union of all bands is a ring around the free floor (a polygon with a hole),
  // which Boost.Geometry does not always subtract correctly; band by band it does.
  BMulti free;
  free.push_back(ToBoost(polygon));
  for (const Ring& band : WallBands(polygon, pieces)) {
    BMulti next;
    bg::difference(free, ToBoost(band), next);
    free = std::move(next);
  }
  return FromBoost(free, nullptr);
}

std::vector<Ring> InsideWalls(std::vector<Ring> free_floor, const Ring& wall_inner) {
  if (wall_inner.size() < 3) return free_floor;
  BPolygon outline = ToBoost(wall_inner);
  if (!bg::is_valid(outline)) return free_floor;  // a self-crossing inset (a needle footprint): the bands alone
  BMulti free = UnionOf(free_floor), inside;
  bg::intersection(free, outline, inside);
  // Only where the exterior walls reach past the room's own bands (a corner where the footprint turns):
  // elsewhere the free floor stays exactly as its bands cut it.
  if (AreaOf(free) - AreaOf(inside) < 1e-8) return free_floor;
  return FromBoost(inside, nullptr);
}

Result<std::vector<RoomContext>> RoomContexts(const Layout& layout, const BuildingMesh& building,
                                              const BuildOptions& options) {
  ContextBuilder builder(layout, building, options);
  std::vector<RoomContext> out;
  for (const Room& room : layout.rooms) {
    if (Area(room.polygon) < 1e-4) return Error{"rooms[\"" + room.name() + "\"]: degenerate polygon"};
    out.push_back(builder.Build(room));
  }
  return out;
}

Result<RoomContext> RoomContextOf(const Layout& layout, const BuildingMesh& building, const BuildOptions& options,
                                  std::string_view room) {
  int index = layout.FindRoom(room);
  if (index < 0) {
    std::string names;
    for (const Room& r : layout.rooms) names += (names.empty() ? "" : ", ") + r.name();
    return Error{"no room \"" + std::string(room) + "\" in the layout (rooms: " + names + ")"};
  }
  const Room& r = layout.rooms[index];
  if (Area(r.polygon) < 1e-4) return Error{"rooms[\"" + r.name() + "\"]: degenerate polygon"};
  return ContextBuilder(layout, building, options).Build(r);
}

}  // namespace villa::scene
