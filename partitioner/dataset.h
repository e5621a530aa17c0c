#pragma once
// Synthesized datasets (`villa synth`): DIR/layouts.jsonl, one record a line, compact, keys in this order:
//   {"id": "villa-000042", "seed": <uint64>, "shape": "L", "floors": 2, "layout": {...LayoutToJson...}}
// plus DIR/manifest.json (the recipe and tool version) and DIR/stats.json. The annotator reads exactly
// these records.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "layout/layout_io.h"
#include "partitioner/partitioner.h"
#include "util/result.h"

namespace villa {

// "villa-000042": the dataset-wide index, at least six digits.
std::string DatasetRecordId(uint64_t index);
// The record of layout `index` (summary.ok() required).
Json DatasetRecord(uint64_t index, uint64_t seed, const PartitionSummary& summary);
// The record as one compact line, without the newline.
std::string DatasetRecordLine(uint64_t index, uint64_t seed, const PartitionSummary& summary);

struct SynthOptions {
  uint64_t count = 0;          // layouts in the whole dataset
  uint64_t seed = 0;           // dataset seed; layout i uses DatasetLayoutSeed(seed, i)
  double floor_weights[3] = {2.0, 4.0, 4.0};  // single : two : three stories, exact by index
  int threads = 0;             // 0: all hardware threads
  uint64_t shard_index = 0;    // this run writes layouts [count*i/n, count*(i+1)/n)
  uint64_t shard_count = 1;
  int previews = 0;            // preview PNGs of the first layouts of this shard (needs the renderer)
  bool force = false;          // write into a non-empty directory
  PartitionOptions partition;  // grid and priors; floors and shape are set per layout
  std::filesystem::path out;
  std::string floors_text = "2:4:4";  // floor_weights as the user wrote them, for the manifest's recipe

  bool IsValid(std::string* message) const;
};

// Parses --shapes "hexagon=2,octagon=1,L=3" (class names as ShapeClassName writes them, any
// non-negative weights; classes not named get 0) into `weights` (kShapeClassCount, ShapeClass order).
// An error names the bad part ("--shapes \"star=1\": \"star\" is not a footprint class (...)").
Status ParseShapeWeights(const std::string& text, double* weights);

// What the dataset holds (stats.json and the printed summary).
struct SynthStats {
  uint64_t layouts = 0;
  uint64_t first_index = 0;    // shard range [first_index, first_index + layouts)
  uint64_t failures = 0;       // seeds with no valid layout (written nowhere; should be 0)
  uint64_t retries = 0;        // discarded attempts over all layouts
  uint64_t validated = 0;      // layouts that passed ValidateLayout
  uint64_t angled = 0;         // layouts whose footprint has an angled edge
  uint64_t angled_interior = 0;  // layouts with a slanted wall between two rooms (an interior wall, door or open)
  uint64_t chamfered = 0;      // layouts whose ground footprint has a 45-degree chamfered corner
  std::map<int, uint64_t> floors;                // floors -> layouts
  std::map<std::string, uint64_t> shapes;        // shape class -> layouts
  std::map<int, uint64_t> rooms_per_floor;       // rooms on a floor -> floors
  std::map<std::string, uint64_t> categories;    // category -> rooms
  double seconds = 0.0;

  Json ToJson() const;
  static SynthStats FromJson(const Json& j);  // stats.json read back (`villa dataset merge` sums shards')
  SynthStats& operator+=(const SynthStats& o);  // counts summed; first_index kept
  std::string Report() const;  // the summary printed by `villa synth`
};

// Generates the shard's layouts with `threads` workers. `write_line(line)` receives each record line
// (without newline) in index order regardless of threads; `on_progress(n)` is called after layouts are
// done (from worker threads). Failed seeds (no valid layout) are counted in stats and listed in
// `failures` ("villa-000042 (seed 123): message"); they are not written.
SynthStats SynthesizeShard(const SynthOptions& options, const std::function<void(const std::string&)>& write_line,
                           const std::function<void(std::size_t)>& on_progress,
                           std::vector<std::string>* failures = nullptr);

// Whether `options.out` can take this shard: false (write it: a missing or empty folder, --force, or only
// the torn files of a run killed midway), true (already done: its manifest has this very recipe and tool
// version and layouts.jsonl matches the manifest's checksum and record count; nothing to do), or a usage
// error ("exists and is not a directory", "directory is not empty (use --force to write into it)", "holds
// another dataset"). Nothing is written.
Result<bool> CheckSynthOutput(const SynthOptions& options);

// The manifest's "recipe" of a shard (count, seed, floors, grid, shard "i/n", index_range) and the whole
// manifest.json as SynthesizeDataset writes it (`floors_text` as the user wrote --floors; `checksum` the
// FNV-1a of layouts.jsonl). `villa dataset merge` writes a merged dataset's manifest with these, so it
// equals the one-machine run's byte for byte.
Json SynthRecipe(const SynthOptions& options);
Json SynthManifest(const Json& recipe, const std::string& floors_text, uint64_t records, uint64_t checksum,
                   const std::vector<std::string>& previews);
// A synth folder whose manifest.json is a synth manifest and whose layouts.jsonl matches its checksum and
// record count (and whose listed previews exist); the manifest is returned through `manifest`.
Status VerifySynthFolder(const std::filesystem::path& dir, Json* manifest = nullptr);

// Draws the preview of one layout into a PNG file (the CLI passes the floor-plan renderer; the
// partitioner does not depend on render/).
using PreviewWriter =
    std::function<Status(const Layout& layout, const std::string& title, const std::filesystem::path& png)>;

// What SynthesizeDataset wrote.
struct SynthSummary {
  SynthStats stats;
  std::vector<std::string> failures;       // seeds with no valid layout, as SynthesizeShard lists them
  std::vector<std::string> preview_files;  // relative to the folder: "previews/villa-000000.png"
  Json manifest;                           // manifest.json as written
  bool ok() const { return stats.failures == 0; }
};

// The whole of `villa synth`: creates options.out and writes layouts.jsonl (atomically, with its FNV-1a
// checksum in the manifest), previews/ID.png of the first options.previews layouts through `preview`
// (required when previews > 0), stats.json and manifest.json (the recipe, the tool version and the
// command that regenerates the shard). `on_progress` as for SynthesizeShard. Fails (naming the file) when
// a file cannot be written or a preview cannot be drawn; options must be valid.
Result<SynthSummary> SynthesizeDataset(const SynthOptions& options, const PreviewWriter& preview,
                                       const std::function<void(std::size_t)>& on_progress);

}  // namespace villa
