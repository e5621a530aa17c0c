// Partitioner throughput: valid layouts per second on one core, over 10,000 layouts of the default dataset
// recipe (floors 2:4:4 by index, every layout validated with ValidateLayout), plus the split of the time
// between generation and validation and the retry causes.
//   villa_bench_partitioner [count]
#include <time.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

#include "layout/validate.h"
#include "partitioner/partitioner.h"

// CPU seconds of this thread: the machines are shared, so wall time overstates the cost when other
// work competes for the cores; both are printed.
double ThreadSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

int main(int argc, char** argv) {
  using Clock = std::chrono::steady_clock;
  const uint64_t count = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 10000;
  const double weights[3] = {2.0, 4.0, 4.0};
  const std::vector<int> floors = villa::DatasetFloorPlan(count, weights);

  // Pass 1: the full pipeline as `villa synth` runs it (generation + validation inside GenerateLayout).
  villa::PartitionOptions options;
  uint64_t valid = 0, retries = 0, rooms = 0;
  std::map<std::string, int> reasons;
  auto start = Clock::now();
  double cpu = ThreadSeconds();
  for (uint64_t i = 0; i < count; ++i) {
    options.floors = floors[i];
    const villa::PartitionSummary s = villa::GenerateLayout(options, villa::DatasetLayoutSeed(1, i));
    if (!s.ok()) continue;
    ++valid;
    retries += static_cast<uint64_t>(s.retries);
    rooms += s.layout.rooms.size();
    for (const std::string& r : s.retry_reasons) {
      const auto colon = r.rfind(": ");
      reasons[r.substr(0, colon)] += std::atoi(r.c_str() + colon + 2);
    }
  }
  const double full = std::chrono::duration<double>(Clock::now() - start).count();
  const double full_cpu = ThreadSeconds() - cpu;

  // Pass 2: generation only (validation off), the same seeds.
  options.validate = false;
  std::vector<villa::Layout> layouts;
  layouts.reserve(count);
  start = Clock::now();
  cpu = ThreadSeconds();
  for (uint64_t i = 0; i < count; ++i) {
    options.floors = floors[i];
    layouts.push_back(villa::GenerateLayout(options, villa::DatasetLayoutSeed(1, i)).layout);
  }
  const double gen = std::chrono::duration<double>(Clock::now() - start).count();
  const double gen_cpu = ThreadSeconds() - cpu;
  // Pass 3: validation alone of those layouts.
  start = Clock::now();
  cpu = ThreadSeconds();
  uint64_t still_valid = 0;
  for (const villa::Layout& l : layouts) still_valid += villa::ValidateLayout(l).valid() ? 1 : 0;
  const double val = std::chrono::duration<double>(Clock::now() - start).count();
  const double val_cpu = ThreadSeconds() - cpu;

  std::printf("partitioner: %llu layouts (floors 2:4:4, grid 0.5 m), one thread; rates per CPU second (per wall second)\n",
              static_cast<unsigned long long>(count));
  std::printf("  valid layouts/s/core, generate + validate: %7.0f  (%.0f wall)  %llu valid, %.2f retries and %.2f rooms a layout\n",
              static_cast<double>(valid) / full_cpu, static_cast<double>(valid) / full, static_cast<unsigned long long>(valid),
              static_cast<double>(retries) / static_cast<double>(count), static_cast<double>(rooms) / static_cast<double>(count));
  std::printf("  generation alone (validation off):        %7.0f  (%.0f wall)\n", static_cast<double>(count) / gen_cpu,
              static_cast<double>(count) / gen);
  std::printf("  ValidateLayout alone on those layouts:    %7.0f  (%.0f wall)  %llu of them valid\n",
              static_cast<double>(count) / val_cpu, static_cast<double>(count) / val, static_cast<unsigned long long>(still_valid));
  std::printf("  vs the Python baseline (~300 layouts/s/core): %.1fx\n", static_cast<double>(valid) / full_cpu / 300.0);
  std::printf("  retry causes:\n");
  for (const auto& [r, n] : reasons) std::printf("    %6d  %s\n", n, r.c_str());
  if (valid != count)
    std::printf("  WARNING: %llu seeds gave no valid layout\n", static_cast<unsigned long long>(count - valid));
  return 0;
}
