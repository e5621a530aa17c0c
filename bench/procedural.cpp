// villa_bench_procedural: procedural assets made per second, per generator and category. For each category,
// ids at the middle of its size range in the four styles and eight seeds are made over and over (record,
// mesh and the closed-piece check that sets the record's `watertight`) for at least 0.1 s of thread CPU time.
// Thread CPU time, not wall time: the machines are shared. `make bench` runs it.
#include "assets/procedural.h"

#include <time.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "assets/category.h"

using namespace villa;

namespace {

double ThreadSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

struct Row {
  std::string generator, category;
  double made = 0, seconds = 0, triangles = 0;  // triangles: mean per asset
  double PerSecond() const { return made / seconds; }
};

}  // namespace

int main() {
  std::vector<Row> rows;
  double total_assets = 0, total_seconds = 0;
  for (const ProceduralGenerator& g : ProceduralGenerators()) {
    for (const std::string& name : g.categories) {
      const CategoryInfo* c = FindCategory(name);
      const Vec3 mid = (c->size_min + c->size_max) * 0.5;
      std::vector<std::string> ids;
      for (const std::string& style : ProceduralStyles())
        for (std::uint32_t seed = 0; seed < 8; ++seed) {
          auto id = ProceduralAssetId(name, mid, style, seed);
          if (!id) {
            std::fprintf(stderr, "%s\n", id.error().c_str());
            return 1;
          }
          ids.push_back(*id);
        }
      Row row{g.name, name};
      long made = 0, triangles = 0;
      const double t0 = ThreadSeconds();
      double elapsed = 0;
      while (elapsed < 0.1) {
        for (const std::string& id : ids) {
          auto asset = MakeProceduralAsset(id);
          if (!asset) {
            std::fprintf(stderr, "%s\n", asset.error().c_str());
            return 1;
          }
          triangles += asset->record.mesh.triangles;
          ++made;
        }
        elapsed = ThreadSeconds() - t0;
      }
      row.made = static_cast<double>(made);
      row.seconds = elapsed;
      row.triangles = static_cast<double>(triangles) / made;
      total_assets += made;
      total_seconds += elapsed;
      rows.push_back(row);
    }
  }
  std::printf("%-16s %-18s %12s %10s %10s\n", "generator", "category", "assets/s", "us/asset", "triangles");
  for (const Row& r : rows)
    std::printf("%-16s %-18s %12.0f %10.1f %10.0f\n", r.generator.c_str(), r.category.c_str(), r.PerSecond(),
                1e6 / r.PerSecond(), r.triangles);
  // Per generator: all its categories together.
  std::printf("\n%-16s %12s %10s\n", "generator", "assets/s", "triangles");
  for (size_t i = 0; i < rows.size();) {
    Row sum{rows[i].generator, ""};
    double weighted = 0;
    size_t j = i;
    for (; j < rows.size() && rows[j].generator == rows[i].generator; ++j) {
      sum.made += rows[j].made;
      sum.seconds += rows[j].seconds;
      weighted += rows[j].triangles * rows[j].made;
    }
    std::printf("%-16s %12.0f %10.0f\n", sum.generator.c_str(), sum.PerSecond(), weighted / sum.made);
    i = j;
  }
  std::sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.PerSecond() < b.PerSecond(); });
  std::printf("all %zu categories: %.0f assets/s overall (thread CPU time); slowest %s (%.0f/s), fastest %s (%.0f/s)\n",
              rows.size(), total_assets / total_seconds, rows.front().category.c_str(), rows.front().PerSecond(),
              rows.back().category.c_str(), rows.back().PerSecond());
  return 0;
}
