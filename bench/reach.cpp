// Reachability cost and outcome: time per level (raster, PRM roadmap, path queries) and per villa, over the
// bundled examples and synthesized villas (the partitioner's dataset recipe), each built by BuildBuilding.
//   villa_bench_reach [villas] [radius]
// Prints one line per villa that has an unreachable room (with the rooms), then the totals.
#include <time.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "building/building.h"
#include "layout/layout_io.h"
#include "partitioner/partitioner.h"
#include "solver/reach.h"

namespace {

double ThreadSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

struct Totals {
  int villas = 0, levels = 0, rooms = 0, rooms_reached = 0, paths = 0, structural = 0, leaves = 0;
  int stair_caused = 0;  // closed by walls, stairs or holes, but reached once stairs and holes are floor
  double raster = 0, roadmap = 0, queries = 0, villa_cpu = 0, worst_villa = 0;
};

void Run(const std::string& name, const villa::Layout& layout, const villa::solver::ReachOptions& options, Totals& t) {
  const villa::BuildOptions build_options;
  auto building = villa::BuildBuilding(layout, build_options);
  if (!building.ok()) {
    std::printf("  %s: not built: %s\n", name.c_str(), building.error().c_str());
    return;
  }
  const double cpu = ThreadSeconds();
  auto input = villa::solver::BuildingReachInput(layout, *building, build_options, options);
  if (!input.ok()) {
    std::printf("  %s: %s\n", name.c_str(), input.error().c_str());
    return;
  }
  auto report = villa::solver::CheckReach(*input, options);
  const double used = ThreadSeconds() - cpu;
  if (!report.ok()) {
    std::printf("  %s: %s\n", name.c_str(), report.error().c_str());
    return;
  }
  ++t.villas;
  t.villa_cpu += used;
  t.worst_villa = std::max(t.worst_villa, used);
  t.rooms += report->rooms;
  t.rooms_reached += report->rooms_reachable;
  t.paths += report->paths_drawn;
  for (const auto& l : report->levels) {
    ++t.levels;
    t.raster += l.seconds_raster;
    t.roadmap += l.seconds_roadmap;
    t.queries += l.seconds_queries;
  }
  // Diagnosis of what the building closes: the same check with the staircases and their holes as floor.
  std::set<std::string> open_without_stairs;
  if (report->rooms_reachable < report->rooms) {
    villa::solver::ReachInput flat = *input;
    std::erase_if(flat.obstacles, [](const villa::solver::ReachObstacle& o) {
      return o.kind == villa::solver::ObstacleKind::kStair || o.kind == villa::solver::ObstacleKind::kStairHole;
    });
    villa::solver::ReachOptions quick = options;
    quick.paths = false;
    if (auto r = villa::solver::CheckReach(flat, quick); r.ok()) {
      for (const auto& target : r->targets) {
        if (target.reachable) open_without_stairs.insert(target.name);
      }
    }
  }
  if (report->rooms_reachable < report->rooms) {
    std::printf("  %s: %d/%d rooms reached;", name.c_str(), report->rooms_reachable, report->rooms);
    for (const auto& r : report->targets) {
      if (r.reachable) continue;
      t.structural += r.structural;
      t.leaves += !r.structural && r.blockers.empty();
      t.stair_caused += r.structural && open_without_stairs.count(r.name);
      std::printf(" %s%s", r.name.c_str(), r.structural ? " (walls/stairs)" : r.blockers.empty() ? " (door leaves)" : "");
    }
    std::printf("\n");
  }
}

}  // namespace

int main(int argc, char** argv) {
  const int count = argc > 1 ? std::atoi(argv[1]) : 50;
  villa::solver::ReachOptions options;
  if (argc > 2) options.radius = std::atof(argv[2]);
  Totals t;
  std::printf("reach: radius %.2f m, cells %.0f mm, one thread (CPU seconds)\n", options.radius, options.cell * 1000);
  const std::filesystem::path examples = std::filesystem::path(VILLA_SOURCE_DIR) / "examples";
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(examples)) {
    if (e.path().extension() == ".json") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    auto layout = villa::LoadLayout(f);
    if (layout.ok()) Run(f.filename().string(), *layout, options, t);
  }
  const double weights[3] = {2.0, 4.0, 4.0};
  const std::vector<int> floors = villa::DatasetFloorPlan(count, weights);
  villa::PartitionOptions popts;
  for (int i = 0; i < count; ++i) {
    popts.floors = floors[i];
    const villa::PartitionSummary s = villa::GenerateLayout(popts, villa::DatasetLayoutSeed(1, i));
    if (s.ok()) Run("synth " + std::to_string(i) + " (" + std::to_string(floors[i]) + " floors)", s.layout, options, t);
  }
  std::printf("  villas %d, levels %d: rooms reached %d/%d, paths drawn %d\n", t.villas, t.levels, t.rooms_reached, t.rooms, t.paths);
  std::printf("  unreached: %d closed by walls, stairs or holes (%d of them reached when stairs and holes are floor), %d by open "
              "door leaves\n",
              t.structural, t.stair_caused, t.leaves);
  std::printf("  per level: raster %.3f s, roadmap %.3f s, queries %.3f s\n", t.raster / t.levels, t.roadmap / t.levels,
              t.queries / t.levels);
  std::printf("  per villa: %.3f s (worst %.3f s)\n", t.villa_cpu / t.villas, t.worst_villa);
  return 0;
}
