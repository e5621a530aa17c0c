#include "bench/support/villas.h"

#include <cstdio>
#include <cstdlib>

#include "layout/layout_io.h"
#include "partitioner/dataset.h"

namespace villa::bench {

std::vector<BenchVilla> ExampleVillas() {
  std::vector<BenchVilla> out;
  for (const char* name : {"l-shaped-house", "two-floor-house", "three-floor-villa", "u-shaped-bungalow"}) {
    auto layout = LoadLayout(std::string(VILLA_SOURCE_DIR) + "/examples/" + name + ".json");
    if (!layout.ok()) {
      std::fprintf(stderr, "%s\n", layout.error().c_str());
      std::exit(1);
    }
    out.push_back({std::string("examples/") + name, *layout});
  }
  return out;
}

std::vector<BenchVilla> SynthesizedVillas(std::uint64_t count, std::uint64_t seed) {
  SynthOptions options;
  options.count = count;
  options.seed = seed;
  std::vector<BenchVilla> out;
  std::vector<std::string> failures;
  SynthesizeShard(
      options,
      [&](const std::string& line) {
        // Json is ordered: the rooms keep the order `villa synth` writes them in.
        const Json record = Json::parse(line);
        auto layout = LayoutFromJson(record["layout"], record["id"].get<std::string>());
        if (layout.ok()) out.push_back({record["id"].get<std::string>(), *layout});
      },
      [](std::size_t) {}, &failures);
  for (const std::string& f : failures) std::fprintf(stderr, "synth: %s\n", f.c_str());
  return out;
}

std::vector<BenchVilla> BenchVillas(std::uint64_t count, std::uint64_t seed) {
  std::vector<BenchVilla> out = ExampleVillas();
  std::vector<BenchVilla> synthesized = SynthesizedVillas(count, seed);
  out.insert(out.end(), synthesized.begin(), synthesized.end());
  return out;
}

}  // namespace villa::bench
