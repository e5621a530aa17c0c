// villa synth --count N --out DIR [--seed S] [--floors 2:4:4] [--grid 0.5] [--threads T] [--shard i/n]
//             [--previews K] [--force]
// --shard auto takes the shard from a Slurm array task or a Kubernetes indexed job (util/shard.h).
// Synthesizes a layout dataset with the procedural partitioner: DIR/layouts.jsonl, DIR/manifest.json,
// DIR/stats.json and optional preview pictures. Byte-identical for any --threads; shards concatenated in
// order equal the unsharded run.
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/command.h"
#include "cli/flags.h"
#include "partitioner/dataset.h"
#include "util/number.h"
#include "util/progress.h"
#include "util/shard.h"
#ifdef VILLA_HAVE_RENDER
#include "render/plan_render.h"
#endif

namespace villa::cli {
namespace {

struct SynthCommand {
  uint64_t count = 0;
  std::string out;
  uint64_t seed = 0;
  std::string floors = "2:4:4";
  std::string shapes;  // empty: the default mix
  double grid = 0.5;
  int threads = 0;
  std::string shard = "0/1";
  int previews = 0;
  bool force = false;
};

// "2:4:4" -> weights of single, two and three story buildings.
void ParseFloors(const std::string& text, double weights[3]) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t colon = text.find(':', start);
    parts.push_back(text.substr(start, colon == std::string::npos ? std::string::npos : colon - start));
    if (colon == std::string::npos) break;
    start = colon + 1;
  }
  if (parts.size() != 3)
    throw UsageError("synth: --floors \"" + text + "\": expected three weights A:B:C (single:two:three stories)");
  for (int i = 0; i < 3; ++i) {
    const std::optional<double> w = ParseNumber(parts[static_cast<std::size_t>(i)]);
    if (!w || *w < 0.0)
      throw UsageError("synth: --floors \"" + text + "\": \"" + parts[static_cast<std::size_t>(i)] +
                       "\" is not a non-negative number");
    weights[i] = *w;
  }
}

void Run(const SynthCommand& command) {
  SynthOptions options;
  options.count = command.count;
  options.seed = command.seed;
  ParseFloors(command.floors, options.floor_weights);
  options.floors_text = command.floors;
  if (!command.shapes.empty())
    if (Status parsed = ParseShapeWeights(command.shapes, options.partition.shape_weights); !parsed)
      throw UsageError("synth: " + parsed.error());
  Result<Shard> shard = ParseShard(command.shard);
  if (!shard) throw UsageError("synth: " + shard.error());
  options.shard_index = shard->index;
  options.shard_count = shard->count;
  options.threads = command.threads;
  options.previews = command.previews;
  options.force = command.force;
  options.partition.grid = command.grid;
  options.out = command.out;
  std::string problem;
  if (!options.IsValid(&problem)) throw UsageError("synth: " + problem);
  Result<bool> done = CheckSynthOutput(options);
  if (!done) throw UsageError("synth: " + done.error());
  if (*done) {
    std::cout << "villa synth: shard " << shard->Text() << " in " << options.out.string()
              << " is already done (its manifest has this recipe and layouts.jsonl verifies); nothing to do\n";
    return;
  }

  // Previews are floor plans (render/): the partitioner itself draws nothing.
  PreviewWriter preview;
#ifdef VILLA_HAVE_RENDER
  preview = [](const Layout& layout, const std::string& title, const std::filesystem::path& png) {
    PlanRenderOptions render;
    render.source_name = title;
    return RenderPlan(layout, png, render);
  };
#else
  if (options.previews > 0) throw UsageError("synth: --previews needs the render component, which this build lacks");
#endif
  ProgressBar bar("synth", shard->Last(options.count) - shard->First(options.count));
  Result<SynthSummary> summary = SynthesizeDataset(options, preview, [&](std::size_t n) { bar.Advance(n); });
  bar.Finish();
  if (!summary) throw std::runtime_error(summary.error());

  std::cout << summary->stats.Report();
  for (const std::string& f : summary->failures) std::cerr << "villa synth: no valid layout: " << f << "\n";
  std::cout << "wrote " << (options.out / "layouts.jsonl").string() << ", manifest.json, stats.json";
  if (!summary->preview_files.empty()) std::cout << ", " << summary->preview_files.size() << " previews";
  std::cout << "\n";
  SetExitCode(summary->ok() ? kExitOk : kExitFailure);
}

Registration registration{30, [](CLI::App& app) {
  auto command = std::make_shared<SynthCommand>();
  CLI::App* sub = app.add_subcommand(
      "synth",
      "Synthesize a dataset of valid multi-story layouts with the procedural spatial partitioner.\n"
      "Writes DIR/layouts.jsonl (one record a line: id, seed, shape, floors, layout), DIR/manifest.json\n"
      "(the recipe and tool version) and DIR/stats.json; prints a summary. The same seed and count give\n"
      "byte-identical layouts.jsonl for any --threads, and shards concatenated in order equal the\n"
      "unsharded run. Exit status: 0 done, 1 some seed failed, 2 usage.");
  sub->add_option("--count", command->count, "layouts in the whole dataset")->required()->transform(WholeIn<uint64_t>(1, 1000000000));
  sub->add_option("--out", command->out, "output directory (must be empty unless --force)")->required()->check(PathName());
  sub->add_option("--seed", command->seed, "dataset seed (default 0)")->transform(Seed());
  sub->add_option("--floors", command->floors,
                  "ratio of single:two:three story buildings, exact by index (default 2:4:4)");
  sub->add_option("--shapes", command->shapes,
                  "footprint mix as class=weight,... (rectangle, L, U, T, H, irregular, hexagon, octagon, trapezoid, "
                  "cross, bay, angled-wing; unnamed classes 0; default: about half with a slanted outside edge)");
  sub->add_option("--grid", command->grid, "coordinate grid in metres (default 0.5)")->check(NumberIn(0.01, 1.0));
  sub->add_option("--threads", command->threads, "worker threads (default 0 = all cores)")->transform(WholeIn(0, 1024));
  sub->add_option("--shard", command->shard,
                  "write only shard i of n, e.g. 3/8 (default 0/1); auto: this Slurm array task's (SLURM_ARRAY_TASK_ID of "
                  "SLURM_ARRAY_TASK_COUNT) or Kubernetes indexed job's (JOB_COMPLETION_INDEX of auto/n or VILLA_SHARD_COUNT). A "
                  "shard already done with the same recipe is skipped; a torn one is redone");
  sub->add_option("--previews", command->previews, "render the first K layouts to DIR/previews/*.png")
      ->transform(WholeIn(0, 100000));
  sub->add_flag("--force", command->force, "write into a non-empty directory, replacing its dataset files");
  sub->callback([command] { Run(*command); });
}};

}  // namespace
}  // namespace villa::cli
