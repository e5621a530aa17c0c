// villa_bench_finetune_export: how fast `villa finetune export` and `check` run over 1,000 annotated
// layouts (every answer parsed, validated against all ten rules, round-tripped and schema-matched).
// The layouts are the system prompt's example moved around a grid, so the benchmark needs no files.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>

#include "finetune/check.h"
#include "finetune/export.h"
#include "finetune/system_prompt.h"
#include "layout/layout_io.h"
#include "util/atomic_file.h"

using namespace villa;
namespace fs = std::filesystem;

int main() {
  const std::string_view prompt = SystemPrompt();
  auto example = ParseLayoutText(prompt.substr(prompt.rfind("\n{\"rooms\"") + 1), "system prompt example");
  if (!example) {
    std::fprintf(stderr, "%s\n", example.error().c_str());
    return 1;
  }
  constexpr int kLayouts = 1000;
  std::string jsonl;
  for (int i = 0; i < kLayouts; ++i) {
    Layout layout = *example;
    const double dx = 20.0 * (i % 40), dy = 20.0 * (i / 40);
    for (auto& room : layout.rooms)
      for (auto& p : room.polygon) p.x += dx, p.y += dy;
    for (ElementKind kind : kAllElementKinds)
      for (auto& e : layout.elements(kind)) e.shape.a.x += dx, e.shape.a.y += dy, e.shape.b.x += dx, e.shape.b.y += dy;
    Json record{{"id", "layout-" + std::to_string(i)}, {"status", "auto"},
                {"descriptions", Json{{"coarse", "A one-floor L-shaped house."}, {"fine", "A one-floor house with a kitchen and a bathroom."}}},
                {"layout", LayoutToJson(layout)}};
    jsonl += record.dump() + "\n";
  }
  const fs::path dir = fs::temp_directory_path() / ("villa-bench-finetune-" + std::to_string(std::random_device{}()));
  fs::create_directories(dir);
  if (!WriteFileAtomic(dir / "annotated.jsonl", jsonl)) return 1;

  using Clock = std::chrono::steady_clock;
  double best_export = 1e9, best_check = 1e9;
  for (int round = 0; round < 3; ++round) {
    ExportOptions options;
    options.force = true;
    auto t0 = Clock::now();
    auto summary = ExportDataset(dir / "annotated.jsonl", dir / "out", options);
    auto t1 = Clock::now();
    auto report = CheckExport(dir / "out");
    auto t2 = Clock::now();
    if (!summary || summary->layouts != kLayouts || !report || !report->ok()) {
      std::fprintf(stderr, "export or check failed\n");
      return 1;
    }
    best_export = std::min(best_export, std::chrono::duration<double>(t1 - t0).count());
    best_check = std::min(best_check, std::chrono::duration<double>(t2 - t1).count());
  }
  std::printf("finetune export: %d layouts in %.3f s (%.0f layouts/s, best of 3)\n", kLayouts, best_export, kLayouts / best_export);
  std::printf("finetune check:  %d samples in %.3f s (%.0f samples/s, best of 3)\n", kLayouts, best_check, kLayouts / best_check);
  fs::remove_all(dir);
  return 0;
}
