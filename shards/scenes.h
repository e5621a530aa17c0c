#pragma once
// `villa scenes`: every layout of a dataset furnished, one folder a villa, sharded and resumable
// (issue 30; docs/CLUSTER.md). A shard's folder:
//   manifest.json      the recipe (input file and its SHA-256, seed, furnishing options, library, tool version,
//                      shard i/n and its index range); "complete": true and scenes.jsonl's SHA-256 once every
//                      villa of the range is done
//   scenes.jsonl       one index line a villa, in input order (ScenesEntry)
//   progress.json      done, failed and left, the rate and the ETA, rewritten after each villa
//   scenes/<id>/       layout.json, scene.json, furnished.glb, report.json, CREDITS (when a model needs
//                      credit), plan.png and rooms/*.png (--pictures), entry.json (the villa's index line)
// Every villa's folder is made under a temporary name and renamed into place whole, entry.json last, so a
// killed run leaves either a whole villa or a temporary a rerun removes. A rerun skips the villas whose
// files still match their entry's SHA-256 and redoes the rest.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "solver/furnish.h"
#include "util/result.h"
#include "util/shard.h"

namespace villa::shards {

using Json = nlohmann::ordered_json;

inline constexpr const char* kScenesIndex = "scenes.jsonl";
inline constexpr const char* kScenesFolder = "scenes";
inline constexpr const char* kManifest = "manifest.json";
inline constexpr const char* kProgress = "progress.json";
inline constexpr const char* kEntry = "entry.json";
inline constexpr const char* kItemLayout = "layout.json";

// One layout of the input: its id and its layout as canonical FORMAT.md JSON (one line).
struct LayoutItem {
  std::string id;
  std::string layout_json;  // LayoutToString(layout, -1)
  int line = 0;             // in the input file, for messages
};

// The layouts of a JSONL file: `villa synth`'s layouts.jsonl (id, layout), an annotator export (id, status,
// layout; rejected layouts are left out and counted in `rejected`), or a fine-tune export's train/val/test
// file (messages, conversations or alpaca lines: the answer is the layout; ids "sample-<line>"). Errors name
// the file, the line and what is wrong; two records with one id are an error.
struct LayoutInput {
  std::vector<LayoutItem> items;
  int rejected = 0;
  std::string sha256;  // of the file's bytes
};
Result<LayoutInput> ReadLayoutInput(const std::filesystem::path& file);

struct ScenesOptions {
  std::filesystem::path input;   // the layouts (ReadLayoutInput)
  std::filesystem::path out;     // the shard's folder
  Shard shard;
  uint64_t seed = 0;             // each villa's furnishing seed is VillaSeed(seed, id)
  std::string critic = "offline";  // offline or none
  solver::FurnishOptions furnish;  // reach, physics, pictures, jobs, library, procedural_only, allow_invalid
  bool force = false;            // start over in a folder that holds another recipe's shard
  // After each villa (from the calling thread): its entry and the shard's counts.
  std::function<void(const Json& entry, int done, int failed, int total)> on_villa;
};

// Why `id` cannot name a villa's folder ("" when it can): empty, over 200 bytes, a '/', a leading '.', or a
// control byte (a NUL would cut the path short: "scenes/\0x" is "scenes/").
std::string VillaIdProblem(const std::string& id);

// The furnishing seed of one villa: the same for a villa whatever the shard that furnishes it.
uint64_t VillaSeed(uint64_t seed, const std::string& id);

// The manifest's recipe for these options and input (without the shard and range: ScenesManifest adds
// them). Two shards merge only when their recipes are equal.
Json ScenesRecipe(const ScenesOptions& options, const LayoutInput& input, const std::optional<scene::FileRef>& library);
// manifest.json for a shard of `recipe` covering [first, last) of `total` layouts; complete with the index's
// SHA-256 and its line count.
Json ScenesManifest(const Json& recipe, const Shard& shard, uint64_t first, uint64_t last, uint64_t total,
                    const std::string& index_sha256 = "", uint64_t records = 0);

struct ScenesSummary {
  int total = 0;     // villas in the shard's range
  int skipped = 0;   // done before (verified) and kept
  int done = 0;      // furnished now
  int failed = 0;    // could not be furnished (their entries say why), now or before
  double seconds = 0.0;
  bool complete = false;  // every villa of the range has an entry
};

// Runs (or resumes) one shard. Usage problems (a folder of another recipe without force, another process
// on the same shard) start with "usage: ".
Result<ScenesSummary> RunScenesShard(const ScenesOptions& options);

// Every file under `dir` (recursively, "rooms/x.png" style, sorted) with its SHA-256, leaving out `skip`.
Result<Json> HashFolder(const std::filesystem::path& dir, const std::string& skip = kEntry);

}  // namespace villa::shards
