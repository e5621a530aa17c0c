#pragma once
// Whether a bathroom's fixtures fit its floor together with the floor a person uses in front of each
// (PRIORS.md clearances: toilet 0.6 m, basin 0.7 m in front): the planner asks before it settles the
// fixture set of a small bathroom (a shower instead of a bath, no separate cabinet, a smaller basin), so
// that it does not plan what the solver can only place by standing one fixture in another's use zone.
//
// The test is a small exhaustive search, not the solver: every fixture stands with its back to a wall
// (facing into the room, 2 cm off it, as the solver puts against_wall objects), on the wall's free
// intervals, 5-10 cm steps along it. A layout is found when
//  - every footprint and every zone lies on the free floor;
//  - no footprint meets another footprint or another fixture's zone (zones may share floor: a person
//    stands in one at a time, and relations.cpp and the solver count only objects in a zone, never zones);
//  - no footprint enters a keep-out zone at its height (door sweeps, windows for what is taller than the
//    sill, stairs); a zone may (a person may stand where a door swings);
//  - the basin's wall above it is free of windows over the width of its mirror (the mirror hangs centred
//    over it), and the companions (the bin) stand beside their fixture along its wall.
// Plan metres, the room context's frame (scene/room_context.h).

#include <string>
#include <vector>

#include "layout/geometry.h"
#include "scene/room_context.h"

namespace villa::scene {

// The room as the search sees it, in plain geometry (the planner builds it from a room context; nothing
// else asks yet: a critic move laying all fixtures out from this search was tried and dropped, see
// docs/BENCHMARKS.md "Bathrooms").
struct FitWall {
  Point a, b;                     // the wall's inner face, the room on its left (CCW like the free floor)
  std::vector<Interval> free;     // m along a -> b where something may stand against it
  std::vector<Interval> windows;  // m along a -> b: windows (nothing hangs over them)
};
struct FitKeepOut {
  Ring polygon;                   // CCW or not, plan m
  double z_min = 0.0, z_max = 0.0;  // world m
};
struct FitRoom {
  std::vector<Ring> free_floor;
  std::vector<FitWall> walls;
  std::vector<FitKeepOut> keep_outs;  // doors' sweeps, windows for what is taller than the sill, stairs,
                                      // and for the critic what stays where it is
  double floor_z = 0.0;               // world m
};
FitRoom FitRoomOf(const RoomContext& room);

struct BathFixture {
  std::string category;   // for the caller's messages; "washbasin" is the one the mirror hangs over
  double width = 0.0;     // m along the wall
  double depth = 0.0;     // m out from the wall
  double height = 0.0;    // m (keep-outs have height ranges: a low fixture may stand under a window)
  double zone = 0.0;      // m of free floor in front, 0 for none
  double mirror = 0.0;    // m of window-free wall centred above it (the mirror's width), 0 for none
  int companion_of = -1;  // index of the fixture it stands beside on the same wall (the bin by the toilet)
};

// Where a fixture stands in a found layout: its wall and the interval [t0, t0 + width] along it.
struct BathPlace {
  int wall = -1;
  double t0 = 0.0;
};

struct BathFitOptions {
  double step = 0.1;       // m between positions along a wall, (0.01, 1]
  double wall_gap = 0.02;  // m between a fixture's back and its wall (the solver's default), [0, 0.2]
  double companion_gap = 0.05;  // m between a companion and its fixture, [0, 0.5]
  long budget = 200000;    // positions tried before giving up (the answer is then "does not fit"), >= 1
  std::string Check() const;  // "" when valid, else what is wrong
};

struct BathFitResult {
  bool fits = false;
  bool exhausted = false;  // the budget ran out before an answer: treated as not fitting
  long tried = 0;          // positions evaluated
  std::vector<BathPlace> places;  // when it fits: one per fixture, in the fixtures' order
};

// Whether the fixtures fit the room as described above. Deterministic (fixed search order).
BathFitResult FitBathFixtures(const FitRoom& room, const std::vector<BathFixture>& fixtures,
                              const BathFitOptions& options = {});
BathFitResult FitBathFixtures(const RoomContext& room, const std::vector<BathFixture>& fixtures,
                              const BathFitOptions& options = {});

}  // namespace villa::scene
