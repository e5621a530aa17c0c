// ValidateLayout and MeasureLayout speed on the layout fixtures: microseconds per layout, single thread.
// The partitioner validates every layout it writes (> 3,000 layouts/s/core), so a 3-floor, 18-room villa
// must validate in well under 100 us.
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
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

}  // namespace

int main(int argc, char** argv) {
  // The fixtures beside this source file (CMake passes absolute paths), or the folder given.
  const std::string dir = argc > 1 ? std::string(argv[1]) + "/"
                                   : (std::filesystem::path(__FILE__).parent_path().parent_path() / "tests/fixtures/layouts/").string();
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
  return 0;
}
