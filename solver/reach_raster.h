#pragma once
// The raster of the reachability check (internal to villa_solver): every level cut into square cells, each
// one free (the person's disc at its centre touches nothing), taken only by objects, or taken by the
// building; and shortest ways over the cells of all levels, joined by the stairs.
//
// A cell's verdict is the shared clearance query's (solver/free_space.h) at its centre. Asking it for every
// cell would be slow, so obstacles are first drawn into an occupancy raster (cells whose centre an obstacle
// covers, and every cell its outline passes through, sampled an eighth of a cell apart) and a Euclidean
// distance transform gives every centre its distance to the nearest drawn cell's centre. That is within
// cell * (sqrt(2)/2 + 1/16) of the distance to the obstacles themselves (a drawn cell holds an obstacle
// point; the obstacle point nearest a free centre is on an outline, within a sixteenth of a cell of a
// sample), so only cells whose distance is within 1.5 cells of the radius are asked the query itself.

inline constexpr double kBelowFloor = 0.05;  // m: the walking band starts this far under the floor surface,
                                             // so the bottom faces of walls and leaves are in it and the
                                             // parts of the level below (0.175 m lower at least) are not
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "solver/free_space.h"

namespace villa::solver {

struct Grid {
  double x0 = 0.0, y0 = 0.0;  // world corner of cell (0, 0), m
  double cell = 0.02;         // m
  int nx = 0, ny = 0;
  long size() const { return static_cast<long>(nx) * ny; }
  Point Centre(long i) const { return {x0 + (static_cast<double>(i % nx) + 0.5) * cell, y0 + (static_cast<double>(i / nx) + 0.5) * cell}; }
  // The cell holding p, or -1 outside the grid.
  long CellOf(Point p) const;
  // Column and row ranges of the cells whose centres may lie in the box [lo, hi] (clamped; empty when i0 > i1).
  void Range(Point lo, Point hi, int* i0, int* i1, int* j0, int* j1) const;
};

enum class Cell : uint8_t { kBuilding = 0, kObjects = 1, kFree = 2 };

struct LevelCells {
  Grid grid;
  std::vector<Cell> cell;
  std::vector<float> clearance;  // m from the centre to the nearest obstacle, objects included (transform)
  std::vector<float> clearance_fixed;  // the same without objects (the building and its open door leaves)
  long exact = 0;                // cells the query decided itself
};

// Classifies a level's cells over the plan box [lo, hi]: `building` and `full` are the level's free spaces
// without and with objects; the person is a disc of `radius` occupying heights z0 to z1.
LevelCells ClassifyCells(const FreeSpace& building, const FreeSpace& full, Point lo, Point hi, double cell, double radius,
                         double z0, double z1);

// The cells of every level as one graph: node = offset[level] + cell, then one node per stair.
struct WayGraph {
  struct Stair {
    std::vector<long> ends;  // nodes of the cells where the stair is stepped on or off (both levels)
    double length = 0.0;     // m walked on it
  };
  std::vector<const LevelCells*> levels;
  std::vector<long> offset;
  std::vector<Stair> stairs;
  std::unordered_map<long, std::vector<int>> stairs_at;  // node -> the stairs stepped on from it

  long StairNode(int stair) const { return offset.back() + stair; }
  long Nodes() const { return offset.back() + static_cast<long>(stairs.size()); }
  // The level and cell of a cell node; false for a stair node.
  bool Locate(long node, int* level, long* cell) const;
};
// Builds offsets for `levels` (call before adding stairs).
WayGraph MakeWayGraph(std::vector<const LevelCells*> levels);

struct Ways {
  std::vector<float> dist;  // m from the nearest source (stairs counted by their length); +inf: not reached
  std::vector<int32_t> prev;
};
// Dijkstra from `sources` (cell nodes): a step costs its length, times `object_cost` when it enters a cell
// taken only by objects (infinite: such cells are never entered); building cells are never entered.
// A stair costs half its length from a cell where it is stepped on to it, and half again to the other end.
Ways ShortestWays(const WayGraph& graph, const std::vector<long>& sources, double object_cost);
// The nodes from a source to `node` along `prev`.
std::vector<long> WayTo(const Ways& ways, long node);

}  // namespace villa::solver
