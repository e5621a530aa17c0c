#include "solver/reach.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <set>

#include "layout/geometry.h"
#include "mesh/geometry2d.h"
#include "solver/free_space.h"
#include "solver/reach_paths.h"
#include "solver/reach_raster.h"

namespace villa::solver {
namespace {

using namespace villa::geo;
using Clock = std::chrono::steady_clock;

constexpr std::string_view kObstacleKindNames[] = {"wall", "door_leaf", "window", "stair", "stair_hole", "object"};
constexpr std::string_view kTargetKindNames[] = {"room", "zone"};
constexpr double kStepOn = 0.12;  // m beyond touching the flight within which a cell steps onto a stair
constexpr double kGoalRoom = 0.4; // m of clearance beyond the radius that makes a goal no better

double Since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

double Round4(double v) { return std::round(v * 1e4) / 1e4; }

std::string Fixed(double v, int digits) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, v);
  return buffer;
}

// One level at work: its free spaces (the building alone, and with the objects), cells and roadmap.
struct Level {
  const ReachLevel* input = nullptr;
  double z0 = 0.0, z1 = 0.0;  // the walking band (world m)
  std::unique_ptr<FreeSpace> building, full;
  Point lo, hi;
  LevelCells cells;
  std::unique_ptr<LevelRoadmap> roadmap;
  std::vector<Point> anchors;
  LevelStats stats;
};

PlanShape ShapeOf(const Ring& piece) { return {piece, 0.0}; }

Status CheckInput(const ReachInput& in) {
  if (in.levels.empty()) return Error{"reach input: no levels"};
  for (size_t k = 0; k < in.levels.size(); ++k) {
    if (in.levels[k].level != static_cast<int>(k)) {
      return Error{"reach input: levels[" + std::to_string(k) + "].level is " + std::to_string(in.levels[k].level) +
                   ", must be " + std::to_string(k)};
    }
    if (in.levels[k].floor.empty()) return Error{"reach input: level " + std::to_string(k) + " has no floor"};
  }
  const int n = static_cast<int>(in.levels.size());
  for (const ReachObstacle& o : in.obstacles) {
    if (o.level < 0 || o.level >= n) return Error{"reach input: obstacle \"" + o.name + "\" is on level " + std::to_string(o.level) + ", which does not exist"};
  }
  for (const StairLink& s : in.stairs) {
    if (s.level < 0 || s.level + 1 >= n) return Error{"reach input: the stair in " + s.room + " rises from level " + std::to_string(s.level) + " to a level that does not exist"};
  }
  for (const ReachTarget& t : in.targets) {
    if (t.level < 0 || t.level >= n) return Error{"reach input: target \"" + t.name + "\" is on level " + std::to_string(t.level) + ", which does not exist"};
    if (t.areas.empty()) return Error{"reach input: target \"" + t.name + "\" has no area"};
  }
  if (Length(in.entrance) <= 0.0) return Error{"reach input: the entrance has no length"};
  return Status::Ok();
}

// The cell of `level` nearest p within `within` m whose state passes `ok`, or -1.
template <class Ok>
long NearestCell(const LevelCells& lc, Point p, double within, Ok ok) {
  const Grid& g = lc.grid;
  int i0, i1, j0, j1;
  g.Range({p.x - within, p.y - within}, {p.x + within, p.y + within}, &i0, &i1, &j0, &j1);
  long best = -1;
  double best_d = within;
  for (int j = j0; j <= j1; ++j) {
    for (int i = i0; i <= i1; ++i) {
      const long c = static_cast<long>(j) * g.nx + i;
      const double d = Dist(g.Centre(c), p);
      if (d <= best_d && ok(lc.cell[c]) && (best < 0 || d < best_d)) best = c, best_d = d;
    }
  }
  return best;
}

// Cells where a person steps onto a stair across `step`: within the radius and kStepOn of its line on its
// `out` side, opposite the stretch (the cells themselves are free of the stair: the disc does not touch it).
std::vector<long> StepCells(const LevelCells& lc, const StairStep& step, double radius) {
  std::vector<long> cells;
  const Segment& seg = step.along;
  const double len = Length(seg);
  if (len <= 0.0) return cells;
  const Point u = Unit(Sub(seg.b, seg.a));
  const double reach = radius + kStepOn;
  const Point far = Add(seg.a, Scale(step.out, reach));
  const Point far_b = Add(seg.b, Scale(step.out, reach));
  const Point lo = {std::min({seg.a.x, seg.b.x, far.x, far_b.x}), std::min({seg.a.y, seg.b.y, far.y, far_b.y})};
  const Point hi = {std::max({seg.a.x, seg.b.x, far.x, far_b.x}), std::max({seg.a.y, seg.b.y, far.y, far_b.y})};
  const Grid& g = lc.grid;
  int i0, i1, j0, j1;
  g.Range(lo, hi, &i0, &i1, &j0, &j1);
  for (int j = j0; j <= j1; ++j) {
    for (int i = i0; i <= i1; ++i) {
      const long c = static_cast<long>(j) * g.nx + i;
      const Point d = Sub(g.Centre(c), seg.a);
      const double t = Dot(d, u), s = Dot(d, step.out);
      if (t >= 0.0 && t <= len && s >= 0.0 && s <= reach && lc.cell[c] != Cell::kBuilding) cells.push_back(c);
    }
  }
  return cells;
}

// The cells of a target's areas on its level.
std::vector<long> TargetCells(const LevelCells& lc, const ReachTarget& t, double radius) {
  std::vector<long> cells;
  const Grid& g = lc.grid;
  for (const TargetArea& a : t.areas) {
    if (a.polygon.empty()) continue;
    const double grow = a.mode == TargetArea::Mode::kTouch ? radius + a.reach : 0.0;
    Point lo{1e300, 1e300}, hi{-1e300, -1e300};
    for (const Point& p : a.polygon) lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)}, hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    int i0, i1, j0, j1;
    g.Range({lo.x - grow, lo.y - grow}, {hi.x + grow, hi.y + grow}, &i0, &i1, &j0, &j1);
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) {
        const long c = static_cast<long>(j) * g.nx + i;
        const Point p = g.Centre(c);
        const bool in = PointInRing(p, a.polygon, 0);
        if (in || (a.mode == TargetArea::Mode::kTouch && DistanceToBoundary(p, a.polygon) <= grow)) cells.push_back(c);
      }
    }
  }
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  return cells;
}

// Where the person stands for a target: a reached cell inside one of its polygons with the most room
// around it (up to a point), else the reached cell nearest a polygon; ties to the nearest polygon centroid.
long GoalCell(const LevelCells& lc, const ReachTarget& t, const std::vector<long>& cells, const std::vector<float>& dist,
              long offset, double radius) {
  long best = -1;
  double key[3] = {0, 0, 0};
  for (long c : cells) {
    if (!std::isfinite(dist[offset + c])) continue;
    const Point p = lc.grid.Centre(c);
    double outside = 1e300, to_centroid = 1e300;
    for (const TargetArea& a : t.areas) {
      const double d = PointInRing(p, a.polygon, 0) ? 0.0 : DistanceToBoundary(p, a.polygon);
      outside = std::min(outside, d);
      Point m{0, 0};
      for (const Point& q : a.polygon) m = Add(m, q);
      to_centroid = std::min(to_centroid, Dist(p, Scale(m, 1.0 / a.polygon.size())));
    }
    const double room = -std::min(static_cast<double>(lc.clearance[c]), radius + kGoalRoom);
    const double k[3] = {outside > 0.0 ? 1.0 + outside : 0.0, outside > 0.0 ? 0.0 : Round4(room), to_centroid};
    if (best < 0 || std::lexicographical_compare(k, k + 3, key, key + 3)) {
      best = c;
      std::copy(k, k + 3, key);
    }
  }
  return best;
}

// The share of a zone's boxes (its areas touched from outside, not the owner's footprint reached within
// arm's reach) covered by the disc of a person standing on a reached cell: the cells whose centres lie in
// a box, and of them those within the radius of a reached cell.
double ZoneShare(const LevelCells& lc, const ReachTarget& t, const std::vector<float>& dist, long offset, double radius) {
  const Grid& g = lc.grid;
  const int k = static_cast<int>(std::ceil(radius / g.cell));
  long inside = 0, covered = 0;
  for (const TargetArea& a : t.areas) {
    if (a.mode != TargetArea::Mode::kTouch || a.reach > 0.0 || a.polygon.empty()) continue;
    Point lo = a.polygon[0], hi = a.polygon[0];
    for (const Point& p : a.polygon) lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)}, hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    int i0, i1, j0, j1;
    g.Range(lo, hi, &i0, &i1, &j0, &j1);
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) {
        const long c = static_cast<long>(j) * g.nx + i;
        const Point p = g.Centre(c);
        if (!PointInRing(p, a.polygon, 0)) continue;
        ++inside;
        bool hit = false;
        for (int dj = -k; dj <= k && !hit; ++dj) {
          for (int di = -k; di <= k && !hit; ++di) {
            const int ii = i + di, jj = j + dj;
            if (ii < 0 || jj < 0 || ii >= g.nx || jj >= g.ny) continue;
            const long n = static_cast<long>(jj) * g.nx + ii;
            hit = std::isfinite(dist[offset + n]) && Dist(g.Centre(n), p) <= radius;
          }
        }
        covered += hit;
      }
    }
  }
  return inside ? static_cast<double>(covered) / inside : 0.0;
}

// Keeps the corners of a polyline of cell centres (Douglas-Peucker, `tolerance` m).
std::vector<Point> Corners(const std::vector<Point>& p, double tolerance) {
  if (p.size() <= 2) return p;
  std::vector<char> keep(p.size(), 0);
  keep.front() = keep.back() = 1;
  std::vector<std::pair<size_t, size_t>> stack = {{0, p.size() - 1}};
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    double worst = 0.0;
    size_t at = a;
    for (size_t k = a + 1; k < b; ++k) {
      const double d = PointSegmentDistance(p[k], {p[a], p[b]});
      if (d > worst) worst = d, at = k;
    }
    if (worst > tolerance) {
      keep[at] = 1;
      stack.push_back({a, at});
      stack.push_back({at, b});
    }
  }
  std::vector<Point> out;
  for (size_t k = 0; k < p.size(); ++k) {
    if (keep[k]) out.push_back(p[k]);
  }
  return out;
}

// One stretch of a way on one level, between two cells.
struct Leg {
  int level = 0;
  long from = 0, to = 0;  // cells
};
// A way (graph nodes) as legs and the stairs between them (stair index, upward?).
void SplitWay(const WayGraph& graph, const std::vector<long>& nodes, std::vector<Leg>* legs,
              std::vector<std::pair<int, bool>>* stairs, const std::vector<StairLink>& links) {
  int level = -1;
  long first = -1, last = -1;
  for (long node : nodes) {
    int l = 0;
    long c = 0;
    if (graph.Locate(node, &l, &c)) {
      if (level < 0) level = l, first = c;
      last = c;
      continue;
    }
    const int s = static_cast<int>(node - graph.offset.back());
    legs->push_back({level, first, last});
    stairs->push_back({s, links[s].level == level});
    level = -1;
  }
  if (level >= 0) legs->push_back({level, first, last});
}

}  // namespace

std::string_view ObstacleKindName(ObstacleKind kind) { return kObstacleKindNames[static_cast<int>(kind)]; }
std::string_view TargetKindName(TargetKind kind) { return kTargetKindNames[static_cast<int>(kind)]; }

bool ReachOptions::IsValid(std::string* message) const {
  auto fail = [&](const std::string& m) {
    if (message) *message = m;
    return false;
  };
  auto in = [](double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; };
  if (!in(radius, 0.05, 1.0)) return fail("radius must be in [0.05, 1] m, is " + Fixed(radius, 3));
  if (!in(cell, 0.005, 0.1)) return fail("cell must be in [0.005, 0.1] m, is " + Fixed(cell, 3));
  if (!in(head_height, 0.5, 2.6) || head_height == 0.5) return fail("head_height must be in (0.5, 2.6] m, is " + Fixed(head_height, 3));
  if (!in(arm_reach, 0.0, 1.0)) return fail("arm_reach must be in [0, 1] m, is " + Fixed(arm_reach, 3));
  if (!in(entrance_snap, 0.0, 3.0) || entrance_snap == 0.0) return fail("entrance_snap must be in (0, 3] m, is " + Fixed(entrance_snap, 3));
  if (!in(block_cost, 2.0, 1e5)) return fail("block_cost must be in [2, 1e5], is " + Fixed(block_cost, 1));
  if (roadmap_density < 1 || roadmap_density > 200) return fail("roadmap_density must be in [1, 200], is " + std::to_string(roadmap_density));
  if (roadmap_min < 10 || roadmap_min > 1000000) return fail("roadmap_min must be in [10, 1e6], is " + std::to_string(roadmap_min));
  if (roadmap_max < roadmap_min || roadmap_max > 1000000) return fail("roadmap_max must be in [roadmap_min, 1e6], is " + std::to_string(roadmap_max));
  if (rrt_iterations < 0 || rrt_iterations > 10000000) return fail("rrt_iterations must be in [0, 1e7], is " + std::to_string(rrt_iterations));
  return true;
}

Result<ReachReport> CheckReach(const ReachInput& input, const ReachOptions& options) {
  const auto start = Clock::now();
  std::string message;
  if (!options.IsValid(&message)) return Error{"reach options: " + message};
  if (Status s = CheckInput(input); !s.ok()) return Error{s.error()};
  const double r = options.radius;
  const int n = static_cast<int>(input.levels.size());

  // ---- free spaces and cells, level by level
  std::vector<Level> levels(n);
  for (int l = 0; l < n; ++l) {
    const auto t = Clock::now();
    Level& L = levels[l];
    L.input = &input.levels[l];
    L.z0 = L.input->floor_z - kBelowFloor;
    L.z1 = L.input->floor_z + options.head_height;
    std::vector<PlanObstacle> building, full;
    for (size_t k = 0; k < input.obstacles.size(); ++k) {
      const ReachObstacle& o = input.obstacles[k];
      if (o.level != l) continue;
      for (const Ring& piece : o.pieces) {
        const PlanObstacle p{ShapeOf(piece), o.z0, o.z1, static_cast<int>(k)};
        full.push_back(p);
        // Door leaves are fixed like walls: the person does not push a leaf and the solver cannot move
        // one, so the search for blockers goes round them (naming the furniture beside them), not through.
        if (o.kind != ObstacleKind::kObject) building.push_back(p);
      }
    }
    L.building = std::make_unique<FreeSpace>(L.input->floor, std::move(building));
    L.full = std::make_unique<FreeSpace>(L.input->floor, std::move(full));
    L.lo = {1e300, 1e300};
    L.hi = {-1e300, -1e300};
    for (const Ring& ring : L.input->floor) {
      for (const Point& p : ring) L.lo = {std::min(L.lo.x, p.x), std::min(L.lo.y, p.y)}, L.hi = {std::max(L.hi.x, p.x), std::max(L.hi.y, p.y)};
    }
    const double margin = 2.0 * options.cell;
    L.lo = {L.lo.x - margin, L.lo.y - margin};
    L.hi = {L.hi.x + margin, L.hi.y + margin};
    L.cells = ClassifyCells(*L.building, *L.full, L.lo, L.hi, options.cell, r, L.z0, L.z1);
    L.stats.level = l;
    L.stats.cells = L.cells.grid.size();
    L.stats.seconds_raster = Since(t);
  }

  // ---- the graph over all levels and the stairs
  std::vector<const LevelCells*> cell_levels;
  for (const Level& L : levels) cell_levels.push_back(&L.cells);
  WayGraph graph = MakeWayGraph(cell_levels);
  for (size_t s = 0; s < input.stairs.size(); ++s) {
    const StairLink& link = input.stairs[s];
    WayGraph::Stair stair;
    stair.length = link.length;
    std::set<long> ends;  // a cell near two stretches joins once
    for (const StairStep& step : link.entries)
      for (long c : StepCells(levels[link.level].cells, step, r)) ends.insert(graph.offset[link.level] + c);
    for (const StairStep& step : link.exits)
      for (long c : StepCells(levels[link.level + 1].cells, step, r)) ends.insert(graph.offset[link.level + 1] + c);
    stair.ends.assign(ends.begin(), ends.end());
    for (long e : stair.ends) graph.stairs_at[e].push_back(static_cast<int>(s));
    graph.stairs.push_back(std::move(stair));
  }

  // ---- from the entrance: reached cells
  ReachReport report;
  const Point door = Lerp(input.entrance.a, input.entrance.b, 0.5);
  const Point in_point = Add(door, Scale(input.inside, input.depth + r + 0.05));
  const LevelCells& ground = levels[0].cells;
  const long free_start = NearestCell(ground, in_point, options.entrance_snap, [](Cell c) { return c == Cell::kFree; });
  const long open_start = NearestCell(ground, in_point, options.entrance_snap, [](Cell c) { return c != Cell::kBuilding; });
  report.entrance_free = free_start >= 0;
  const Ways ways = ShortestWays(graph, free_start >= 0 ? std::vector<long>{free_start} : std::vector<long>{},
                                 std::numeric_limits<double>::infinity());
  const double cell_area = options.cell * options.cell;
  for (int l = 0; l < n; ++l) {
    const LevelCells& lc = levels[l].cells;
    long free_cells = 0, reached = 0;
    for (long c = 0; c < lc.grid.size(); ++c) {
      free_cells += lc.cell[c] == Cell::kFree;
      reached += std::isfinite(ways.dist[graph.offset[l] + c]);
    }
    levels[l].stats.free_area = free_cells * cell_area;
    levels[l].stats.reached_area = reached * cell_area;
    ReachedCells rc;
    rc.level = l;
    rc.x0 = lc.grid.x0, rc.y0 = lc.grid.y0, rc.cell = lc.grid.cell, rc.nx = lc.grid.nx, rc.ny = lc.grid.ny;
    rc.reached.resize(lc.grid.size());
    for (long c = 0; c < lc.grid.size(); ++c) rc.reached[c] = std::isfinite(ways.dist[graph.offset[l] + c]) ? 1 : 0;
    report.reached.push_back(std::move(rc));
  }

  // ---- targets: reached or not, and where the person stands
  std::vector<long> goals(input.targets.size(), -1);
  std::vector<std::vector<long>> target_cells(input.targets.size());
  for (size_t k = 0; k < input.targets.size(); ++k) {
    const ReachTarget& t = input.targets[k];
    TargetResult res;
    res.kind = t.kind;
    res.name = t.name;
    res.room = t.room;
    res.level = t.level;
    const LevelCells& lc = levels[t.level].cells;
    target_cells[k] = TargetCells(lc, t, r);
    goals[k] = GoalCell(lc, t, target_cells[k], ways.dist, graph.offset[t.level], r);
    if (goals[k] < 0 && t.kind == TargetKind::kRoom) {
      // A staircase hall its flights fill: reached when its stairs are, standing where they are stepped on.
      for (size_t si = 0; si < input.stairs.size(); ++si) {
        const StairLink& link = input.stairs[si];
        const bool here = (link.room == t.name && link.level == t.level) || (link.upper_room == t.name && link.level + 1 == t.level);
        if (!here || !std::isfinite(ways.dist[graph.StairNode(static_cast<int>(si))])) continue;
        for (long node : graph.stairs[si].ends) {
          int l = 0;
          long c = 0;
          if (!graph.Locate(node, &l, &c) || l != t.level || !std::isfinite(ways.dist[node])) continue;
          if (goals[k] < 0 || ways.dist[node] < ways.dist[graph.offset[l] + goals[k]]) goals[k] = c;
        }
        if (goals[k] >= 0) res.note = "reached on its stairs";
      }
    }
    if (goals[k] >= 0) {
      res.reachable = true;
      res.goal = lc.grid.Centre(goals[k]);
      res.raster_length = Round4(ways.dist[graph.offset[t.level] + goals[k]]);
    }
    if (t.kind == TargetKind::kRoom) {
      res.share = res.reachable ? 1.0 : 0.0;
    } else {
      bool shared = false;
      for (const TargetArea& a : t.areas) shared |= a.reach > 0.0;
      res.share = shared && res.reachable ? 1.0 : Round4(ZoneShare(lc, t, ways.dist, graph.offset[t.level], r));
      report.zone_share += res.share;
    }
    (t.kind == TargetKind::kRoom ? report.rooms : report.zones) += 1;
    if (res.reachable) (t.kind == TargetKind::kRoom ? report.rooms_reachable : report.zones_reachable) += 1;
    report.targets.push_back(std::move(res));
  }

  // ---- what blocks the others: the cheapest way when objects may be crossed at a price
  const auto t_block = Clock::now();
  bool any_unreachable = false;
  for (const TargetResult& res : report.targets) any_unreachable |= !res.reachable;
  if (any_unreachable) {
    const Ways through = ShortestWays(graph, open_start >= 0 ? std::vector<long>{open_start} : std::vector<long>{},
                                      options.block_cost);
    for (size_t k = 0; k < input.targets.size(); ++k) {
      TargetResult& res = report.targets[k];
      if (res.reachable) continue;
      // The way's end: the nearest cell of the target, for a room one well inside it (clear of its walls by
      // kGoalRoom), so the walkway the feedback lays leads into the room, not just over its threshold.
      const long off = graph.offset[res.level];
      const LevelCells& lc = levels[res.level].cells;
      long best = -1;
      bool best_inside = false;
      for (long c : target_cells[k]) {
        if (!std::isfinite(through.dist[off + c])) continue;
        const bool inside = res.kind == TargetKind::kRoom && lc.clearance_fixed[c] >= r + kGoalRoom;
        if (best < 0 || (inside && !best_inside) || (inside == best_inside && through.dist[off + c] < through.dist[off + best])) {
          best = c;
          best_inside = inside;
        }
      }
      if (best < 0) {
        res.structural = true;
        res.note = open_start < 0 ? "no free floor at the entrance, even without furniture"
                                  : "no way in even without furniture: walls, stairs, holes or open door leaves close it";
        continue;
      }
      std::set<std::string> seen;
      int way_level = -1;
      std::vector<Point> way;
      auto flush = [&] {
        if (!way.empty()) res.blocked_way.push_back({way_level, Corners(way, options.cell)});
        way.clear();
      };
      for (long node : WayTo(through, off + best)) {
        int l = 0;
        long c = 0;
        if (!graph.Locate(node, &l, &c)) {
          flush();
          continue;
        }
        if (l != way_level) flush();
        way_level = l;
        const Point p = levels[l].cells.grid.Centre(c);
        way.push_back(p);
        if (levels[l].cells.cell[c] != Cell::kObjects) continue;
        for (int o : levels[l].full->Overlapping(PlanShape::Disc(p, r), levels[l].z0, levels[l].z1)) {
          const ReachObstacle& ob = input.obstacles[levels[l].full->obstacles()[o].owner];
          if (!seen.insert(ob.name).second) continue;
          if (ob.kind == ObstacleKind::kObject) res.blockers.push_back(ob.name);
          if (ob.kind == ObstacleKind::kDoorLeaf) res.door_leaves.push_back(ob.name);
        }
      }
      flush();
      res.note = res.blockers.empty()    ? "open door leaves close the way"
                 : res.door_leaves.empty() ? "blocked by furniture"
                                           : "blocked by furniture and open door leaves";
      if (!report.entrance_free) res.note += " (at the entrance)";
    }
  }
  report.seconds_blockers = Since(t_block);

  // ---- paths: OMPL on each level, the stairs' walks between
  if (options.paths) {
    std::vector<std::vector<Leg>> legs(input.targets.size());
    std::vector<std::vector<std::pair<int, bool>>> crossings(input.targets.size());
    for (size_t k = 0; k < input.targets.size(); ++k) {
      if (goals[k] < 0) continue;
      SplitWay(graph, WayTo(ways, graph.offset[input.targets[k].level] + goals[k]), &legs[k], &crossings[k], input.stairs);
      for (const Leg& leg : legs[k]) {
        levels[leg.level].anchors.push_back(levels[leg.level].cells.grid.Centre(leg.from));
        levels[leg.level].anchors.push_back(levels[leg.level].cells.grid.Centre(leg.to));
      }
    }
    for (const auto& [level, p] : input.anchors) {
      if (level >= 0 && level < n) levels[level].anchors.push_back(p);
    }
    // Ways to many targets share their first legs (the entrance to the stairs): each leg is planned once.
    std::map<std::tuple<int, long, long>, std::pair<std::vector<Point>, std::string>> cache;
    for (size_t k = 0; k < input.targets.size(); ++k) {
      if (goals[k] < 0) continue;
      TargetResult& res = report.targets[k];
      ReachPath path;
      bool ok = true;
      std::set<std::string> planners;
      for (size_t i = 0; i < legs[k].size() && ok; ++i) {
        const Leg& leg = legs[k][i];
        Level& L = levels[leg.level];
        if (!L.roadmap) {
          RoadmapSpec spec;
          spec.space = L.full.get();
          spec.z0 = L.z0;
          spec.z1 = L.z1;
          spec.radius = r;
          spec.lo = L.lo;
          spec.hi = L.hi;
          spec.cell = options.cell;
          for (long c = 0; c < L.cells.grid.size(); ++c) {
            if (std::isfinite(ways.dist[graph.offset[leg.level] + c])) spec.cells.push_back(L.cells.grid.Centre(c));
          }
          spec.anchors = L.anchors;
          spec.milestones = std::clamp(static_cast<int>(options.roadmap_density * L.stats.reached_area), options.roadmap_min,
                                       options.roadmap_max);
          spec.rrt_iterations = options.rrt_iterations;
          spec.seed = options.seed * 0x9E3779B97F4A7C15ull + static_cast<uint64_t>(leg.level) + 1;
          L.roadmap = std::make_unique<LevelRoadmap>(std::move(spec));
          L.stats.seconds_roadmap = L.roadmap->seconds_build();
        }
        const auto tq = Clock::now();
        auto hit = cache.find({leg.level, leg.from, leg.to});
        if (hit == cache.end()) {
          std::string planner;
          auto points = L.roadmap->Path(L.cells.grid.Centre(leg.from), L.cells.grid.Centre(leg.to), &planner);
          hit = cache.emplace(std::make_tuple(leg.level, leg.from, leg.to),
                              std::make_pair(points ? *points : std::vector<Point>{}, planner)).first;
        }
        L.stats.seconds_queries += Since(tq);
        if (hit->second.first.empty()) {
          ok = false;
          res.note = "reachable, but OMPL drew no path on level " + std::to_string(leg.level) + " within its budget";
          break;
        }
        planners.insert(hit->second.second);
        for (const Point& p : hit->second.first) {
          path.points.push_back({p.x, p.y, L.input->floor_z});
          path.level.push_back(leg.level);
        }
        if (i < crossings[k].size()) {
          const auto [s, up] = crossings[k][i];
          std::vector<Vec3> walk = input.stairs[s].walk;
          if (!up) std::reverse(walk.begin(), walk.end());
          path.points.insert(path.points.end(), walk.begin(), walk.end());
          path.level.insert(path.level.end(), walk.size(), -1);
        }
      }
      if (!ok) continue;
      for (size_t i = 0; i + 1 < path.points.size(); ++i) path.length += Norm(path.points[i + 1] - path.points[i]);
      path.length = Round4(path.length);
      path.planner = planners.count("rrt_connect") ? "rrt_connect" : planners.count("prm") ? "prm" : "straight";
      res.path = std::move(path);
      ++report.paths_drawn;
    }
  }
  for (Level& L : levels) {
    if (L.roadmap) {
      L.stats.milestones = L.roadmap->milestones();
      L.stats.roadmap_edges = L.roadmap->edges();
    }
    report.levels.push_back(L.stats);
  }
  report.seconds = Since(start);
  return report;
}

bool ReachedCells::At(Point p) const {
  const double fi = std::floor((p.x - x0) / cell), fj = std::floor((p.y - y0) / cell);
  if (fi < 0 || fj < 0 || fi >= nx || fj >= ny) return false;
  return reached[static_cast<long>(fj) * nx + static_cast<long>(fi)] != 0;
}

const TargetResult* ReachReport::Find(std::string_view name) const {
  for (const TargetResult& t : targets) {
    if (t.name == name) return &t;
  }
  return nullptr;
}

std::string ReachReport::BriefReport() const {
  std::string out = "reach: rooms " + std::to_string(rooms_reachable) + "/" + std::to_string(rooms) + " (RCH " + Fixed(Rch(), 3) +
                    "), zones " + std::to_string(zones_reachable) + "/" + std::to_string(zones) + " (ACC " + Fixed(Acc(), 3) +
                    "), paths drawn " + std::to_string(paths_drawn) + (entrance_free ? "" : "; the entrance is blocked") + "\n";
  for (const TargetResult& t : targets) {
    if (t.reachable) continue;
    out += "  unreachable " + std::string(TargetKindName(t.kind)) + " " + t.name + ": " + t.note;
    std::vector<std::string> named = t.blockers;
    for (const std::string& leaf : t.door_leaves) named.push_back("door leaf " + leaf);
    if (!named.empty()) {
      out += " (";
      for (size_t k = 0; k < named.size(); ++k) out += (k ? ", " : "") + named[k];
      out += ")";
    }
    out += "\n";
  }
  for (const LevelStats& l : levels) {
    out += "  level " + std::to_string(l.level) + ": free " + Fixed(l.free_area, 1) + " m2, reached " + Fixed(l.reached_area, 1) +
           " m2, roadmap " + std::to_string(l.milestones) + " milestones / " + std::to_string(l.roadmap_edges) + " edges; raster " +
           Fixed(l.seconds_raster, 3) + " s, roadmap " + Fixed(l.seconds_roadmap, 3) + " s, queries " + Fixed(l.seconds_queries, 3) + " s\n";
  }
  out += "  time " + Fixed(seconds, 3) + " s\n";
  return out;
}

nlohmann::ordered_json ReachReport::ToJson() const {
  nlohmann::ordered_json j;
  j["rch"] = Round4(Rch());
  j["acc"] = Round4(Acc());
  j["entrance_free"] = entrance_free;
  j["rooms"] = nlohmann::ordered_json::array();
  j["zones"] = nlohmann::ordered_json::array();
  for (const TargetResult& t : targets) {
    nlohmann::ordered_json e;
    e[t.kind == TargetKind::kRoom ? "room" : "object"] = t.name;
    if (t.kind == TargetKind::kZone) e["room"] = t.room;
    e["level"] = t.level;
    e["reachable"] = t.reachable;
    if (t.kind == TargetKind::kZone) e["share"] = t.share;
    if (t.reachable) {
      e["goal"] = {Round4(t.goal.x), Round4(t.goal.y)};
      e["raster_length"] = t.raster_length;
    }
    if (t.path) {
      e["length"] = t.path->length;
      e["planner"] = t.path->planner;
      nlohmann::ordered_json pts = nlohmann::ordered_json::array();
      for (const Vec3& p : t.path->points) pts.push_back({Round4(p.x), Round4(p.y), Round4(p.z)});
      e["path"] = std::move(pts);
    }
    if (!t.reachable) {
      e["blockers"] = t.blockers;
      e["door_leaves"] = t.door_leaves;
      e["structural"] = t.structural;
    }
    if (!t.note.empty()) e["note"] = t.note;
    j[t.kind == TargetKind::kRoom ? "rooms" : "zones"].push_back(std::move(e));
  }
  j["levels"] = nlohmann::ordered_json::array();
  for (const LevelStats& l : levels) {
    j["levels"].push_back({{"level", l.level}, {"free_area", Round4(l.free_area)}, {"reached_area", Round4(l.reached_area)},
                           {"milestones", l.milestones}, {"roadmap_edges", l.roadmap_edges}});
  }
  return j;
}

}  // namespace villa::solver
