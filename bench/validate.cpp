// ValidateLayout and MeasureLayout speed on the layout fixtures: microseconds per layout, single thread.
// The partitioner validates every layout it writes (> 3,000 layouts/s/core), so a 3-floor, 18-room villa
// must validate in well under 100 us.
// Then the path of `villa validate` on absurd element counts (issue 17): the bungalow example with 2,000,
// 20,000 and 50,000 doors (copies of its own), text to report: reading, the ten rules, the metrics. Time
// must grow linearly with the doors (no step meets every pair of elements).
// `villa_bench_validate --write-many DIR` writes those layouts as DIR/doors<N>k.json, to time two
// binaries on them (docs/BENCHMARKS.md, "Validator").
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "layout/layout_io.h"
#include "layout/metrics.h"
#include "layout/validate.h"

namespace {

// CPU time of this thread: the machines are shared, and wall time counts the time others hold the core.
double ThreadSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + t.tv_nsec * 1e-9;
}

template <class F>
double MicrosecondsPerCall(F&& f, double min_seconds = 0.3) {
  long calls = 0;
  double start = ThreadSeconds(), elapsed = 0;
  do {
    for (int i = 0; i < 100; ++i) f();
    calls += 100;
    elapsed = ThreadSeconds() - start;
  } while (elapsed < min_seconds);
  return elapsed * 1e6 / calls;
}

// The bungalow example with `doors` doors: its own, repeated under new names.
villa::Layout ManyDoors(const villa::Layout& base, int doors) {
  villa::Layout out = base;
  out.doors.clear();
  for (int i = 0; i < doors; ++i) {
    villa::Element door = base.doors[static_cast<std::size_t>(i) % base.doors.size()];
    door.name += '_';
    door.name += std::to_string(i);
    out.doors.push_back(door);
  }
  return out;
}

int ManyElements(const std::string& write_dir) {
  auto base = villa::LoadLayout(std::string(VILLA_SOURCE_DIR) + "/examples/u-shaped-bungalow.json");
  if (!base) {
    std::fprintf(stderr, "%s\n", base.error().c_str());
    return 1;
  }
  if (!write_dir.empty()) {
    for (int k : {20, 50}) {
      const std::filesystem::path path = std::filesystem::path(write_dir) / ("doors" + std::to_string(k) + "k.json");
      std::ofstream(path) << villa::LayoutToString(ManyDoors(*base, k * 1000), -1) << "\n";
      std::printf("wrote %s\n", path.string().c_str());
    }
    return 0;
  }
  std::printf("\n`villa validate` on the bungalow with many doors (thread CPU s, best of 3)\n");
  std::printf("%8s %10s %10s %10s %10s %12s\n", "doors", "read s", "rules s", "metrics s", "total s", "us a door");
  for (int doors : {2000, 20000, 50000}) {
    const std::string text = villa::LayoutToString(ManyDoors(*base, doors), -1);
    double read = 1e9, rules = 1e9, metrics = 1e9;
    for (int run = 0; run < 3; ++run) {
      double t0 = ThreadSeconds();
      auto layout = villa::ParseLayoutText(text, "many");
      double t1 = ThreadSeconds();
      auto report = villa::ValidateLayout(*layout);
      double t2 = ThreadSeconds();
      auto measured = villa::MeasureLayout(*layout, report);
      double t3 = ThreadSeconds();
      if (!report.valid() || measured.rooms != static_cast<int>(layout->rooms.size())) {
        std::fprintf(stderr, "the many-door bungalow should be valid\n");
        return 1;
      }
      read = std::min(read, t1 - t0), rules = std::min(rules, t2 - t1), metrics = std::min(metrics, t3 - t2);
    }
    const double total = read + rules + metrics;
    std::printf("%8d %10.3f %10.3f %10.3f %10.3f %12.2f\n", doors, read, rules, metrics, total, total * 1e6 / doors);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 2 && std::string(argv[1]) == "--write-many") return ManyElements(argv[2]);
  // The fixtures beside this source file (CMake passes absolute paths), or the folder given.
  const std::string dir = argc > 1 ? std::string(argv[1]) + "/" : std::string(VILLA_SOURCE_DIR) + "/tests/fixtures/layouts/";
  const std::vector<std::string> names = {"villa_three_floors.json", "house_two_floors.json", "bungalow_angled.json",
                                          "house_one_floor.json", "paper_example.json", "rule1_courtyard_hole.json"};
  std::printf("thread CPU time per call, best of 3 runs of >= 0.3 s\n");
  std::printf("%-28s %6s %6s %6s %12s %12s %14s\n", "fixture", "floors", "rooms", "viol.", "validate us", "geom-only us",
              "MeasureLayout us");
  volatile std::size_t sink = 0;
  for (const auto& name : names) {
    auto layout = villa::LoadLayout(dir + name);
    if (!layout) {
      std::fprintf(stderr, "%s\n", layout.error().c_str());
      return 1;
    }
    villa::ValidateOptions geometric;
    geometric.check_architecture = false;
    std::size_t violations = villa::ValidateLayout(*layout).violations.size();
    auto best = [](auto&& f) {
      double b = MicrosecondsPerCall(f);
      for (int i = 0; i < 2; ++i) b = std::min(b, MicrosecondsPerCall(f));
      return b;
    };
    double full = best([&] { sink = sink + villa::ValidateLayout(*layout).violations.size(); });
    double geom = best([&] { sink = sink + villa::ValidateLayout(*layout, geometric).violations.size(); });
    double metrics = best([&] { sink = sink + villa::MeasureLayout(*layout).rooms; });
    std::printf("%-28s %6d %6zu %6zu %12.1f %12.1f %14.1f\n", name.c_str(), layout->LevelCount(), layout->rooms.size(),
                violations, full, geom, metrics);
  }
  return ManyElements("");
}
