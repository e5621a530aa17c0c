#pragma once
// The paths of the reachability check (internal to villa_solver): OMPL on one level's floor, in plain
// types. The state space is RealVectorStateSpace(2) over the level's bounds; a state is valid when the
// person's disc there keeps clear of everything, and a motion when the straight walk (a capsule) does, both
// asked of the shared clearance query (solver/free_space.h), so a drawn segment is exact, not sampled.
// A PRM roadmap is built once per level (samples from the raster's reached cells, the level's passages and
// every query's end points first) and searched (A*) for each query; RRTConnect answers what the roadmap
// does not join. Paths are then shortened by cutting corners while the straight walk stays free.
// Deterministic: samples come from SplitMix64 seeded per level, neighbours from a linear search, and the
// roadmap grows to a milestone count, not for a time.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "solver/free_space.h"

namespace villa::solver {

struct RoadmapSpec {
  const FreeSpace* space = nullptr;  // the level's obstacles (objects included) and floor
  double z0 = 0.0, z1 = 2.0;         // world heights the person occupies (m)
  double radius = 0.2;               // m
  Point lo, hi;                      // plan bounds of the state space
  std::vector<Point> cells;          // centres of the free raster cells the samples come from
  double cell = 0.02;                // m, their side
  std::vector<Point> anchors;        // made milestones first when free (passages, query ends)
  int milestones = 1000;             // the roadmap grows to this many
  int rrt_iterations = 20000;
  uint64_t seed = 1;
};

class LevelRoadmap {
 public:
  explicit LevelRoadmap(RoadmapSpec spec);
  ~LevelRoadmap();
  LevelRoadmap(const LevelRoadmap&) = delete;
  LevelRoadmap& operator=(const LevelRoadmap&) = delete;

  // A free polyline from a to b (both free points), shortened, and which planner found it ("prm",
  // "rrt_connect", "straight"); nullopt when neither joined them.
  std::optional<std::vector<Point>> Path(Point a, Point b, std::string* planner);
  // The person's disc at p / the straight walk from a to b keeps its radius from everything.
  bool FreeAt(Point p) const;
  bool FreeWalk(Point a, Point b) const;

  int milestones() const;
  int edges() const;
  double seconds_build() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace villa::solver
