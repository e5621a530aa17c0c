// villa_bench_reach: reachability (docs/REACH.md) over the bundled examples and the villas of
// `villa synth --count N --seed S` (the villas bench/furnish.cpp furnishes), in two parts:
//  1. the bare buildings (BuildBuilding, no furniture): time per level (raster, PRM roadmap, path queries)
//     and per villa (thread CPU seconds), and which rooms the building itself closes, split by cause;
//  2. the furnished villas (`villa furnish` with procedural assets, seed S, one room at a time, the
//     reachability check and its feedback loop on, as by default): RCH and ACC before and after the
//     feedback, what is still unreachable by cause (the building: walls, stairs, holes; open door leaves;
//     furniture), the actions the rooms' agents took, and the seconds of the check and the loop a villa.
//   villa_bench_reach [--villas N] [--seed S] [--radius R] [--bare | --furnished] [--verbose]
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "bench/support/villas.h"
#include "building/building.h"
#include "scene/acquire.h"
#include "solver/furnish.h"
#include "solver/reach.h"

using namespace villa;


namespace {

double ThreadSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

// Level times summed over the levels checked.
struct LevelTimes {
  int levels = 0;
  double raster = 0, roadmap = 0, queries = 0;
  void Add(const std::vector<solver::LevelStats>& stats) {
    for (const solver::LevelStats& l : stats) {
      ++levels;
      raster += l.seconds_raster;
      roadmap += l.seconds_roadmap;
      queries += l.seconds_queries;
    }
  }
  void Print(const char* what) const {
    if (levels == 0) return;
    std::printf("  per level (%d levels%s): raster %.4f s, roadmap %.4f s, queries %.4f s\n", levels, what, raster / levels,
                roadmap / levels, queries / levels);
  }
};

void Bare(const std::vector<bench::BenchVilla>& villas, const solver::ReachOptions& options, bool verbose) {
  int rooms = 0, reached = 0, paths = 0, structural = 0, leaves = 0, stair_caused = 0;
  double cpu = 0.0, worst = 0.0;
  LevelTimes times;
  std::printf("\n1. bare buildings (no furniture), radius %.2f m, cells %.0f mm; thread CPU seconds\n", options.radius,
              options.cell * 1000);
  for (const bench::BenchVilla& v : villas) {
    const BuildOptions build;
    auto building = BuildBuilding(v.layout, build);
    if (!building.ok()) {
      std::printf("  %s: not built: %s\n", v.name.c_str(), building.error().c_str());
      continue;
    }
    const double t = ThreadSeconds();
    auto input = solver::BuildingReachInput(v.layout, *building, build, options);
    if (!input.ok()) {
      std::printf("  %s: %s\n", v.name.c_str(), input.error().c_str());
      continue;
    }
    auto report = solver::CheckReach(*input, options);
    const double used = ThreadSeconds() - t;
    if (!report.ok()) {
      std::printf("  %s: %s\n", v.name.c_str(), report.error().c_str());
      continue;
    }
    cpu += used;
    worst = std::max(worst, used);
    rooms += report->rooms;
    reached += report->rooms_reachable;
    paths += report->paths_drawn;
    times.Add(report->levels);
    if (report->rooms_reachable == report->rooms) continue;
    // Diagnosis: the same check with the staircases and their holes as floor.
    std::set<std::string> open_without_stairs;
    solver::ReachInput flat = *input;
    std::erase_if(flat.obstacles, [](const solver::ReachObstacle& o) {
      return o.kind == solver::ObstacleKind::kStair || o.kind == solver::ObstacleKind::kStairHole;
    });
    solver::ReachOptions quick = options;
    quick.paths = false;
    if (auto r = solver::CheckReach(flat, quick); r.ok()) {
      for (const auto& target : r->targets)
        if (target.reachable) open_without_stairs.insert(target.name);
    }
    std::string line = "  " + v.name + ": " + std::to_string(report->rooms_reachable) + "/" + std::to_string(report->rooms) + " rooms;";
    for (const auto& r : report->targets) {
      if (r.reachable) continue;
      structural += r.structural;
      leaves += !r.structural && r.blockers.empty();
      stair_caused += r.structural && open_without_stairs.count(r.name);
      line += " " + r.name + (r.structural ? (open_without_stairs.count(r.name) ? " (stairs)" : " (walls)") : " (door leaves)");
    }
    if (verbose) std::printf("%s\n", line.c_str());
  }
  std::printf("  %zu villas: rooms reached %d/%d, paths drawn %d\n", villas.size(), reached, rooms, paths);
  std::printf("  unreached: %d closed by walls, stairs or holes (%d of them reached when stairs and holes are floor), %d by "
              "open door leaves\n",
              structural, stair_caused, leaves);
  times.Print("");
  std::printf("  per villa: %.3f s CPU (worst %.3f s)\n", cpu / std::max<size_t>(1, villas.size()), worst);
}

void Furnished(const std::vector<bench::BenchVilla>& villas, uint64_t seed, const solver::ReachOptions& reach, bool verbose) {
  auto library = scene::OpenFurnishingLibrary("", true);
  if (!library.ok()) {
    std::fprintf(stderr, "%s\n", library.error().c_str());
    std::exit(1);
  }
  std::printf("\n2. furnished (procedural assets, seed %llu, one room at a time, the feedback loop on), radius %.2f m; wall "
              "seconds\n",
              static_cast<unsigned long long>(seed), reach.radius);
  int rooms = 0, zones = 0, rooms_before = 0, zones_before = 0, rooms_after = 0, zones_after = 0, not_measured = 0;
  std::map<std::string, int> rooms_by_cause, zones_by_cause, actions, statuses;
  int removed = 0, villas_changed = 0, walkways = 0, spots = 0, checks = 0;
  double share_sum = 0.0;  // ACC: the zones' reachable shares, summed
  double seconds = 0.0, worst = 0.0, furnish_seconds = 0.0;
  LevelTimes times;
  for (const bench::BenchVilla& v : villas) {
    solver::FurnishOptions options;
    options.jobs = 1;
    options.seed = seed;
    options.reach.reach = reach;
    auto f = solver::FurnishLayout(v.layout, {v.name, std::string(64, '0')}, library->library, library->file, options);
    if (!f.ok()) {
      std::fprintf(stderr, "%s: %s\n", v.name.c_str(), f.error().c_str());
      std::exit(1);
    }
    furnish_seconds += f->summary.seconds;
    if (!f->reach) {
      ++not_measured;
      std::printf("  %s: %s\n", v.name.c_str(), f->summary.reach_note.c_str());
      continue;
    }
    const solver::ReachFigures& r = *f->reach;
    const nlohmann::json record = nlohmann::json::parse(r.record.dump());
    seconds += r.seconds;
    worst = std::max(worst, r.seconds);
    times.Add(r.levels);
    rooms += r.rooms;
    zones += r.zones;
    rooms_after += r.rooms_reachable;
    zones_after += r.zones_reachable;
    share_sum += r.acc_mean * r.zones;
    const nlohmann::json& fb = record["feedback"];
    rooms_before += fb["rooms_reachable_before"].get<int>();
    zones_before += fb["zones_reachable_before"].get<int>();
    checks += 1 + static_cast<int>(fb["rounds"].size());
    bool changed = false;
    for (const nlohmann::json& round : fb["rounds"]) {
      for (const nlohmann::json& w : round["walkways"]) (w["kind"] == "spot" ? spots : walkways) += 1;
      for (const nlohmann::json& a : round["actions"]) {
        changed = true;
        ++actions[a["action"].get<std::string>()];
        ++statuses[a["status"].get<std::string>()];
        if (a.contains("removed")) removed += static_cast<int>(a["removed"].size());
      }
    }
    villas_changed += changed;
    std::string line;
    for (const char* kind : {"rooms", "zones"}) {
      for (const nlohmann::json& t : record[kind]) {
        if (t["reachable"].get<bool>()) continue;
        const std::string cause = t["structural"].get<bool>() ? "building"
                                  : t["blockers"].empty()     ? "door leaves"
                                                              : "furniture";
        ++(std::string(kind) == "rooms" ? rooms_by_cause : zones_by_cause)[cause];
        line += ' ';
        line += t[std::string(kind) == "rooms" ? "room" : "object"].get<std::string>();
        line += " (";
        line += cause;
        line += ')';
      }
    }
    if (verbose && !line.empty()) std::printf("  %s:%s\n", v.name.c_str(), line.c_str());
  }
  auto pct = [](int n, int d) { return d ? 100.0 * n / d : 100.0; };
  const int measured = static_cast<int>(villas.size()) - not_measured;
  std::printf("  %d villas measured (%d not): rooms %d, V_int zones %d\n", measured, not_measured, rooms, zones);
  std::printf("  before the feedback: rooms reachable %.1f %% (%d), zones reachable %.1f %% (%d)\n", pct(rooms_before, rooms),
              rooms_before, pct(zones_before, zones), zones_before);
  std::printf("  after:               rooms reachable %.1f %% (%d), zones reachable %.1f %% (%d); RCH %.3f, ACC %.3f (mean "
              "share of a zone reachable)\n",
              pct(rooms_after, rooms), rooms_after, pct(zones_after, zones), zones_after,
              rooms ? static_cast<double>(rooms_after) / rooms : 1.0, zones ? share_sum / zones : 1.0);
  for (const auto* by : {&rooms_by_cause, &zones_by_cause}) {
    std::printf("  %s still unreachable by cause:", by == &rooms_by_cause ? "rooms" : "zones");
    if (by->empty()) std::printf(" none");
    for (const auto& [cause, n] : *by) std::printf(" %s %d;", cause.c_str(), n);
    std::printf("\n");
  }
  std::printf("  feedback: %d villas changed, %d walkways and %d spots laid; actions:", villas_changed, walkways, spots);
  for (const auto& [kind, n] : actions) std::printf(" %s %d;", kind.c_str(), n);
  std::printf(" (");
  for (const auto& [status, n] : statuses) std::printf(" %s %d", status.c_str(), n);
  std::printf(" ); objects removed %d\n", removed);
  times.Print(", the last check of each villa");
  std::printf("  per villa: %.3f s for the checks and the loop (worst %.3f s, %.2f checks a villa); the whole furnish %.3f s\n",
              seconds / std::max(1, measured), worst, static_cast<double>(checks) / std::max(1, measured),
              furnish_seconds / std::max<size_t>(1, villas.size()));
}

}  // namespace

int main(int argc, char** argv) {
  uint64_t count = 50, seed = 7;
  solver::ReachOptions options;
  bool bare = true, furnished = true, verbose = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--villas" && i + 1 < argc) count = std::strtoull(argv[++i], nullptr, 10);
    else if (a == "--seed" && i + 1 < argc) seed = std::strtoull(argv[++i], nullptr, 10);
    else if (a == "--radius" && i + 1 < argc) options.radius = std::atof(argv[++i]);
    else if (a == "--bare") furnished = false;
    else if (a == "--furnished") bare = false;
    else if (a == "--verbose") verbose = true;
    else {
      std::fprintf(stderr, "usage: villa_bench_reach [--villas N] [--seed S] [--radius R] [--bare | --furnished] [--verbose]\n");
      return 2;
    }
  }
  std::string message;
  if (!options.IsValid(&message)) {
    std::fprintf(stderr, "villa_bench_reach: %s\n", message.c_str());
    return 2;
  }
  const std::vector<bench::BenchVilla> villas = bench::BenchVillas(count, seed);
  std::printf("reach: the 4 examples and the %llu villas of `villa synth --count %llu --seed %llu`\n",
              static_cast<unsigned long long>(count), static_cast<unsigned long long>(count),
              static_cast<unsigned long long>(seed));
  if (bare) Bare(villas, options, verbose);
  if (furnished) Furnished(villas, seed, options, verbose);
  return 0;
}
