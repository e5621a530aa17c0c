// villa_bench_scenes: what a furnished-scenes dataset costs (issue 30). Synthesizes N villas as
// `villa synth --count N --seed S` does and furnishes them as one `villa scenes` shard does (one room at a
// time: --jobs 1, so the figure is per core), then prints villas a core-hour and the projected core-hours
// (and the Slurm array a 30-minute task size gives) for 10,000 furnished villas.
//   villa_bench_scenes [--villas N] [--seed S] [--library DIR] [--no-physics] [--no-reach]
#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <string>

#include "partitioner/dataset.h"
#include "shards/scenes.h"

using namespace villa;
namespace fs = std::filesystem;

namespace {
double ProcessCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + t.tv_nsec * 1e-9;
}
}  // namespace

int main(int argc, char** argv) {
  uint64_t villas = 6, seed = 2027;
  std::string library;
  bool physics = true, reach = true;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--villas" && i + 1 < argc) villas = std::strtoull(argv[++i], nullptr, 10);
    else if (a == "--seed" && i + 1 < argc) seed = std::strtoull(argv[++i], nullptr, 10);
    else if (a == "--library" && i + 1 < argc) library = argv[++i];
    else if (a == "--no-physics") physics = false;
    else if (a == "--no-reach") reach = false;
    else {
      std::fprintf(stderr, "usage: villa_bench_scenes [--villas N] [--seed S] [--library DIR] [--no-physics] [--no-reach]\n");
      return 2;
    }
  }
  const fs::path dir = fs::temp_directory_path() / ("villa_bench_scenes_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  SynthOptions synth;
  synth.count = villas;
  synth.seed = seed;
  synth.threads = 1;
  synth.out = dir / "synth";
  if (auto s = SynthesizeDataset(synth, nullptr, nullptr); !s) {
    std::fprintf(stderr, "synth: %s\n", s.error().c_str());
    return 1;
  }
  shards::ScenesOptions o;
  o.input = dir / "synth" / "layouts.jsonl";
  o.out = dir / "scenes";
  o.seed = seed;
  o.furnish.jobs = 1;
  o.furnish.pictures = false;
  o.furnish.check_physics = physics;
  o.furnish.check_reach = reach;
  o.furnish.library = library;
  o.furnish.procedural_only = library.empty();
  const double cpu0 = ProcessCpuSeconds();
  auto summary = shards::RunScenesShard(o);
  const double cpu = ProcessCpuSeconds() - cpu0;
  if (!summary) {
    std::fprintf(stderr, "scenes: %s\n", summary.error().c_str());
    fs::remove_all(dir);
    return 1;
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const double per_villa = cpu / std::max(1, summary->done);
  const double per_hour = 3600.0 / per_villa;
  const double core_hours = 10000.0 * per_villa / 3600.0;
  const long tasks = std::lround(std::ceil(10000.0 * per_villa / 1800.0));
  std::printf("scenes: %d villas of `villa synth --count %llu --seed %llu` (%s, physics %s, reach %s), one core: %.1f s wall, %.1f CPU s, "
              "%.2f CPU s a villa, %d failed, peak RSS %.0f MB\n",
              summary->done, static_cast<unsigned long long>(villas), static_cast<unsigned long long>(seed),
              library.empty() ? "procedural assets" : ("library " + library).c_str(), physics ? "on" : "off", reach ? "on" : "off",
              summary->seconds, cpu, per_villa, summary->failed, usage.ru_maxrss / 1024.0);
  std::printf("scenes: %.0f villas a core-hour; 10,000 furnished villas: %.1f core-hours (a Slurm array of %ld one-core tasks of ~30 min)\n",
              per_hour, core_hours, tasks);
  fs::remove_all(dir);
  return 0;
}
