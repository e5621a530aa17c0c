// villa synth --count N --out DIR [--seed S] [--floors 2:4:4] [--grid 0.5] [--threads T] [--shard i/n]
//             [--previews K] [--force]
// Synthesizes a layout dataset with the procedural partitioner: DIR/layouts.jsonl, DIR/manifest.json,
// DIR/stats.json and optional preview pictures. Byte-identical for any --threads; shards concatenated in
// order equal the unsharded run.
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cli/command.h"
#include "partitioner/dataset.h"
#include "util/atomic_file.h"
#include "util/hash.h"
#include "util/progress.h"
#include "util/version.h"
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
  double grid = 0.5;
  int threads = 0;
  std::string shard = "0/1";
  int previews = 0;
  bool force = false;
};

bool ParseUnsigned(std::string_view text, uint64_t* value) {
  if (text.empty()) return false;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), *value);
  return ec == std::errc() && end == text.data() + text.size();
}

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
    std::size_t used = 0;
    double w = -1.0;
    try {
      w = std::stod(parts[static_cast<std::size_t>(i)], &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != parts[static_cast<std::size_t>(i)].size() || !(w >= 0.0))
      throw UsageError("synth: --floors \"" + text + "\": \"" + parts[static_cast<std::size_t>(i)] +
                       "\" is not a non-negative number");
    weights[i] = w;
  }
}

void ParseShard(const std::string& text, uint64_t* index, uint64_t* count) {
  const std::size_t slash = text.find('/');
  if (slash == std::string::npos || !ParseUnsigned(std::string_view(text).substr(0, slash), index) ||
      !ParseUnsigned(std::string_view(text).substr(slash + 1), count))
    throw UsageError("synth: --shard \"" + text + "\": expected i/n, e.g. 0/4");
}

void Run(const SynthCommand& command) {
  SynthOptions options;
  options.count = command.count;
  options.seed = command.seed;
  ParseFloors(command.floors, options.floor_weights);
  ParseShard(command.shard, &options.shard_index, &options.shard_count);
  options.threads = command.threads;
  options.previews = command.previews;
  options.force = command.force;
  options.partition.grid = command.grid;
  options.out = command.out;
  std::string problem;
  if (!options.IsValid(&problem)) throw UsageError("synth: " + problem);
#ifndef VILLA_HAVE_RENDER
  if (options.previews > 0) throw UsageError("synth: --previews needs the render component, which this build lacks");
#endif

  namespace fs = std::filesystem;
  const fs::path dir(command.out);
  std::error_code ec;
  if (fs::exists(dir, ec)) {
    if (!fs::is_directory(dir, ec)) throw UsageError("synth: --out " + command.out + ": exists and is not a directory");
    if (!fs::is_empty(dir, ec) && !options.force)
      throw UsageError("synth: --out " + command.out + ": directory is not empty (use --force to write into it)");
  }
  fs::create_directories(dir, ec);
  if (ec) throw std::runtime_error(command.out + ": cannot create directory: " + ec.message());

  const uint64_t first = options.count * options.shard_index / options.shard_count;
  const uint64_t last = options.count * (options.shard_index + 1) / options.shard_count;
  AtomicFileWriter layouts(dir / "layouts.jsonl");
  if (!layouts.ok()) throw std::runtime_error(layouts.error());
  uint64_t checksum = kFnv1a64Offset;
  std::vector<std::string> preview_lines;
  std::vector<std::string> failures;
  SynthStats stats;
  {
    ProgressBar bar("synth", last - first);
    stats = SynthesizeShard(
        options,
        [&](const std::string& line) {
          layouts.Write(line);
          layouts.Write("\n");
          checksum = Fnv1a64("\n", Fnv1a64(line, checksum));
          if (static_cast<int>(preview_lines.size()) < options.previews) preview_lines.push_back(line);
        },
        [&](std::size_t n) { bar.Advance(n); }, &failures);
    bar.Finish();
  }

  std::vector<std::string> preview_files;
#ifdef VILLA_HAVE_RENDER
  if (!preview_lines.empty()) {
    fs::create_directories(dir / "previews", ec);
    if (ec) throw std::runtime_error((dir / "previews").string() + ": cannot create directory: " + ec.message());
    for (const std::string& line : preview_lines) {
      const Json record = Json::parse(line);
      const std::string id = record.at("id").get<std::string>();
      Result<Layout> layout = LayoutFromRecord(record, id);
      if (!layout) throw std::runtime_error(layout.error());
      PlanRenderOptions render;
      render.source_name = id + " (" + record.at("shape").get<std::string>() + ")";
      const fs::path png = dir / "previews" / (id + ".png");
      Status written = RenderPlan(*layout, png, render);
      if (!written) throw std::runtime_error(written.error());
      preview_files.push_back("previews/" + id + ".png");
    }
  }
#endif

  Status committed = layouts.Commit();
  if (!committed) throw std::runtime_error(committed.error());
  Json stats_json = stats.ToJson();
  if (!WriteFileAtomic(dir / "stats.json", stats_json.dump(2) + "\n"))
    throw std::runtime_error((dir / "stats.json").string() + ": cannot write");

  Json manifest = Json::object();
  manifest["tool"] = "villa";
  manifest["version"] = kVersion;
  manifest["command"] = "synth";
  char hex[32];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(checksum));
  std::string floors_text = command.floors;
  Json recipe = Json::object();
  recipe["count"] = options.count;
  recipe["seed"] = options.seed;
  recipe["floors"] = {options.floor_weights[0], options.floor_weights[1], options.floor_weights[2]};
  recipe["grid"] = options.partition.grid;
  recipe["shard"] = std::to_string(options.shard_index) + "/" + std::to_string(options.shard_count);
  recipe["index_range"] = {first, last};
  recipe["layout_seed"] = "DatasetLayoutSeed(seed, index); floors by index from DatasetFloorPlan(count, floors)";
  manifest["recipe"] = recipe;
  std::ostringstream grid_text;
  grid_text << options.partition.grid;
  manifest["regenerate"] = "villa synth --count " + std::to_string(options.count) + " --seed " +
                           std::to_string(options.seed) + " --floors " + floors_text + " --grid " + grid_text.str() +
                           " --shard " + recipe["shard"].get<std::string>() + " --out DIR";
  manifest["record"] = "{\"id\", \"seed\", \"shape\", \"floors\", \"layout\"} one a line (layout: FORMAT.md JSON)";
  manifest["files"] = {{"layouts.jsonl", {{"records", stats.layouts}, {"fnv1a64", hex}}},
                       {"stats.json", Json::object()},
                       {"previews", preview_files}};
  if (!WriteFileAtomic(dir / "manifest.json", manifest.dump(2) + "\n"))
    throw std::runtime_error((dir / "manifest.json").string() + ": cannot write");

  std::cout << stats.Report();
  for (const std::string& f : failures) std::cerr << "villa synth: no valid layout: " << f << "\n";
  std::cout << "wrote " << (dir / "layouts.jsonl").string() << ", manifest.json, stats.json";
  if (!preview_files.empty()) std::cout << ", " << preview_files.size() << " previews";
  std::cout << "\n";
  SetExitCode(stats.failures == 0 ? kExitOk : kExitFailure);
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
  sub->add_option("--count", command->count, "layouts in the whole dataset")->required();
  sub->add_option("--out", command->out, "output directory (must be empty unless --force)")->required();
  sub->add_option("--seed", command->seed, "dataset seed (default 0)");
  sub->add_option("--floors", command->floors,
                  "ratio of single:two:three story buildings, exact by index (default 2:4:4)");
  sub->add_option("--grid", command->grid, "coordinate grid in metres (default 0.5)");
  sub->add_option("--threads", command->threads, "worker threads (default 0 = all cores)");
  sub->add_option("--shard", command->shard, "write only shard i of n, e.g. 3/8 (default 0/1)");
  sub->add_option("--previews", command->previews, "render the first K layouts to DIR/previews/*.png");
  sub->add_flag("--force", command->force, "write into a non-empty directory, replacing its dataset files");
  sub->callback([command] { Run(*command); });
}};

}  // namespace
}  // namespace villa::cli
