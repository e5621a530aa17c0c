#pragma once
// A room's context: everything the planner and the solver need to know about the space one room offers,
// derived from the layout and the built building (building/building.h), in plain types.
//
// Frame: the layout's plan (metres), z up as the building: the floor surface of level L is at
// zf(L) = 2.8 L + slab (0.175 by default) and the clear height is 2.8 - slab (2.625). Rings are CCW.
//
// - free floor: the room polygon inset by the walls standing on its edges: exterior walls 0.25 m inward
//   from the footprint edge, interior walls 0.06 m (half of 0.12) either side of their segment. Each edge
//   piece's wall band is the quadrilateral between the edge and its inset line, cut at the corners along
//   the mitre (as the building cuts its walls), so non-convex and angled rooms come out exact; the free
//   floor is the polygon minus the bands (Boost.Geometry, inside room_context.cpp).
// - walls: the free floor's edges that lie on a wall's inner face, each naming its room polygon edge,
//   exterior or interior, the intervals doors and opens take, the intervals free of floor-level keep-outs
//   (where an against_wall object may stand) and the windows with their sills.
// - keep-out zones: polygons with a height range that no object may enter (door swing square + the strip on
//   the other side, open passages, windows for objects taller than the sill, staircases with their landing
//   and arrival strip, the stair hole of the staircase from below).
#include <string>
#include <string_view>
#include <vector>

#include "building/building.h"
#include "layout/geometry.h"
#include "layout/layout.h"
#include "util/result.h"

namespace villa::scene {

struct WallWindow {
  std::string name;      // layout element
  Interval span;         // along the wall's inner segment, m from its first point
  double sill = 0.0;     // m above the floor surface
  double head = 0.0;     // m above the floor surface
  bool panoramic = false;
};

struct WallEdge {
  int edge = 0;          // the room polygon's edge (vertex edge -> edge + 1) this wall stands on
  bool exterior = false;
  double thickness = 0.0;  // m the wall takes from the room (0.25 exterior, 0.06 interior)
  Segment inner;         // the wall's inner face along the free floor, CCW like the free floor
  std::vector<Interval> openings;  // doors and opens, along `inner` (m from inner.a)
  std::vector<Interval> free;      // where an object may stand against this wall: not an opening, not in a
                                   // floor-level keep-out zone (door sweeps, stairs, panoramic windows)
  std::vector<WallWindow> windows;
  double length() const;
};

enum class KeepOutKind {
  kDoorSweep,      // the square the open leaf sweeps (door width x door width, leaf side)
  kDoorStrip,      // door width x 0.6 m on the other side (both sides when the leaf stays closed)
  kOpenPassage,    // open connection: width x 0.6 m on each side
  kWindow,         // 0.5 m in front of the wall's inner face, from the sill to the head
  kStair,          // the staircase rising from this level (flights and landing)
  kStairHole,      // the hole in this floor the staircase from below comes up through
  kStairArrival,   // the floor strip where the stairs are entered and left
};
std::string_view KeepOutKindName(KeepOutKind kind);  // "door-sweep", "door-strip", ...

struct KeepOut {
  KeepOutKind kind = KeepOutKind::kDoorSweep;
  std::string element;  // the layout element or the stair room it comes from
  Ring polygon;         // CCW, plan m (not clipped to the room: parts beyond the walls are harmless)
  double z_min = 0.0;   // world heights, m: an object enters the zone when its box overlaps this range
  double z_max = 0.0;
};

// A door, open or window on the room's boundary (entrance included, as a door).
struct ContextOpening {
  std::string name;
  ElementKind kind = ElementKind::kDoor;
  Segment shape;
};

struct RoomContext {
  std::string name;      // "living-room_0/0"
  Category category = Category::kRoom;
  int level = 0;
  Ring polygon;          // as the layout gives it (CCW); wall.edge indices refer to its edges
  double area = 0.0;     // m2, of the polygon
  std::vector<Ring> free_floor;  // usually one ring; a room with a neck narrower than its walls gives more
  double free_area = 0.0;        // m2
  // m2 of free floor outside staircase zones (stair, hole, arrival strip): what furniture may use.
  double furnishable_area = 0.0;
  std::vector<WallEdge> walls;
  std::vector<KeepOut> keep_outs;
  std::vector<ContextOpening> openings;
  double floor_z = 0.0;       // m, zf(level)
  double clear_height = 0.0;  // m, floor surface to the ceiling
  int ordinal = 0;  // its place among the layout's rooms of its category, in layout order (0: the first):
                    // "a TV in one of the bedrooms" goes to the first
  std::vector<Category> level_categories;  // categories of every room on this level (the planner asks
                                           // "is there a dining room on this floor?")
  std::vector<std::string> warnings;       // what the context had to approximate

  // Total length of wall where against_wall objects may stand (sum of `free`).
  double FreeWallLength() const;
  bool HasWindow() const;
};

// The context of every room of the layout, in layout order. `building` must be BuildBuilding(layout,
// options) with the same options. Fails only for a room whose polygon is degenerate.
Result<std::vector<RoomContext>> RoomContexts(const Layout& layout, const BuildingMesh& building,
                                              const BuildOptions& options);
// One room by name ("living-room_0/0"); an error names the room when the layout has no such room.
Result<RoomContext> RoomContextOf(const Layout& layout, const BuildingMesh& building, const BuildOptions& options,
                                  std::string_view room);

// The free floor in two steps, exposed for tests: WallPieces splits each edge of `polygon` into pieces of
// constant wall depth (exterior where the edge lies on `exterior_boundary`, the level's footprint outline;
// interior elsewhere, open gaps included: an open is a passage, not floor to furnish); FreeFloor subtracts
// the pieces' wall bands from the polygon.
struct EdgePiece {
  int edge = 0;       // room polygon edge
  double t0 = 0.0;    // m along the edge from its first vertex
  double t1 = 0.0;
  double depth = 0.0; // m the wall takes from the room along this piece
  bool exterior = false;
};
std::vector<EdgePiece> WallPieces(const Ring& polygon, const std::vector<Segment>& exterior_boundary,
                                  const BuildOptions& options);
std::vector<Ring> FreeFloor(const Ring& polygon, const std::vector<EdgePiece>& pieces);
// Third step: the free floor kept inside `wall_inner` (BuildingMesh::wall_inner of its level), where an
// exterior wall beside the room reaches into its corner; unchanged where it does not.
std::vector<Ring> InsideWalls(std::vector<Ring> free_floor, const Ring& wall_inner);

}  // namespace villa::scene
