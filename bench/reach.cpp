// villa_bench_reach: reachability (docs/REACH.md) over the bundled examples and the villas of
// `villa synth --count N --seed S` (the villas bench/furnish.cpp furnishes), in two parts:
//  1. the bare buildings (BuildBuilding, no furniture): time per level (raster, PRM roadmap, path queries)
//     and per villa (thread CPU seconds), and which rooms the building itself closes, split by cause;
//  2. the furnished villas (`villa furnish` with procedural assets, seed S, one room at a time, the
//     reachability check and its feedback loop on, as by default): RCH and ACC before and after the
//     feedback, what is still unreachable by cause (the building: walls, stairs, holes and open door leaves;
//     furniture), the actions the rooms' agents took, and the seconds of the check and the loop a villa.
//   villa_bench_reach [--villas N] [--seed S] [--radius R] [--bare | --furnished] [--closed-doors] [--no-last-resort] [--critic]
//                     [--verbose]
// --critic: each room reviewed by the offline critic (critic/) before the reachability check, as `villa
// furnish` does by default. --closed-doors: the furnished villas with every door leaf shut in its opening (no leaf is an obstacle),
// so what is left unreachable is the building's stairs and the furniture's. --no-last-resort: the feedback's
// rounds only (ReachFeedbackOptions::last_resort off), to compare.
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
#include "critic/critic.h"
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
    // Diagnosis: the same check without some of the building's obstacles (bare buildings have no movable
    // cells, so every unreached room is structural): the targets it then reaches.
    solver::ReachOptions quick = options;
    quick.paths = false;
    auto reached_without = [&](auto drop) {
      std::set<std::string> open;
      solver::ReachInput without = *input;
      std::erase_if(without.obstacles, drop);
      if (auto r = solver::CheckReach(without, quick); r.ok())
        for (const auto& target : r->targets)
          if (target.reachable) open.insert(target.name);
      return open;
    };
    const std::set<std::string> open_without_stairs = reached_without([](const solver::ReachObstacle& o) {
      return o.kind == solver::ObstacleKind::kStair || o.kind == solver::ObstacleKind::kStairHole;
    });
    const std::set<std::string> open_without_leaves =
        reached_without([](const solver::ReachObstacle& o) { return o.kind == solver::ObstacleKind::kDoorLeaf; });
    std::string line = "  " + v.name + ": " + std::to_string(report->rooms_reachable) + "/" + std::to_string(report->rooms) + " rooms;";
    for (const auto& r : report->targets) {
      if (r.reachable) continue;
      const bool by_stairs = open_without_stairs.count(r.name) > 0;
      const bool by_leaves = !by_stairs && open_without_leaves.count(r.name) > 0;
      structural += !by_leaves;
      leaves += by_leaves;
      stair_caused += by_stairs;
      std::string leaves_named;
      if (verbose && by_leaves) {
        // Which leaves, taken away one at a time, open the room.
        for (const solver::ReachObstacle& leaf : input->obstacles) {
          if (leaf.kind != solver::ObstacleKind::kDoorLeaf) continue;
          if (reached_without([&](const solver::ReachObstacle& o) { return o.name == leaf.name; }).count(r.name))
            leaves_named += (leaves_named.empty() ? ": " : ", ") + leaf.name;
        }
      }
      line += " " + r.name + (by_stairs ? " (stairs)" : by_leaves ? " (door leaves" + leaves_named + ")" : " (walls)");
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

void Furnished(const std::vector<bench::BenchVilla>& villas, uint64_t seed, const solver::ReachOptions& reach, bool closed_doors, bool last_resort,
               const solver::RoomCritic& critic, bool verbose) {
  auto library = scene::OpenFurnishingLibrary("", true);
  if (!library.ok()) {
    std::fprintf(stderr, "%s\n", library.error().c_str());
    std::exit(1);
  }
  std::printf("\n2. furnished (procedural assets, seed %llu, one room at a time, the feedback loop on%s), radius %.2f m; wall "
              "seconds\n",
              static_cast<unsigned long long>(seed),
              ((closed_doors ? std::string(", door leaves shut") : std::string()) + (last_resort ? "" : ", no last resort") +
               (critic ? ", the offline critic" : ""))
                  .c_str(),
              reach.radius);
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
    options.build.door_leaves_open = !closed_doors;
    options.reach.last_resort = last_resort;
    options.critic = critic;
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
        // Structural: the building, its open door leaves included (the bare part tells them apart).
        const std::string cause = t["structural"].get<bool>() ? "building or door leaves"
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
  bool bare = true, furnished = true, verbose = false, closed_doors = false, last_resort = true, with_critic = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--villas" && i + 1 < argc) count = std::strtoull(argv[++i], nullptr, 10);
    else if (a == "--seed" && i + 1 < argc) seed = std::strtoull(argv[++i], nullptr, 10);
    else if (a == "--radius" && i + 1 < argc) options.radius = std::atof(argv[++i]);
    else if (a == "--bare") furnished = false;
    else if (a == "--furnished") bare = false;
    else if (a == "--verbose") verbose = true;
    else if (a == "--closed-doors") closed_doors = true;
    else if (a == "--no-last-resort") last_resort = false;
    else if (a == "--critic") with_critic = true;
    else {
      std::fprintf(stderr, "usage: villa_bench_reach [--villas N] [--seed S] [--radius R] [--bare | --furnished] [--closed-doors] [--no-last-resort] [--critic] [--verbose]\n");
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
  if (furnished) Furnished(villas, seed, options, closed_doors, last_resort, with_critic ? critic::MakeRoomCritic({}) : solver::RoomCritic{}, verbose);
  return 0;
}
