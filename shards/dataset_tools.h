#pragma once
// `villa dataset merge|verify|status` (issue 30; docs/CLUSTER.md): shards of one `villa synth` or
// `villa scenes` run joined into one dataset, a dataset re-hashed against its manifest and index, and a
// running job's progress over all its shards.
#include <filesystem>
#include <string>
#include <vector>

#include "util/result.h"

namespace villa::shards {

struct MergeSummary {
  std::string kind;   // "synth" or "scenes"
  int shards = 0;
  uint64_t records = 0;  // layouts or villas
  uint64_t failed = 0;   // scenes: villas that could not be furnished
};

// Joins the shards (folders of one recipe, every shard i/n once, each complete and verified) into `out`,
// which must not exist or be empty. synth: layouts.jsonl concatenated in shard order, manifest.json as
// the one-machine run writes it (both byte-identical to it), stats.json summed (its seconds are the
// shards' sum), previews/ gathered. scenes: scenes/<id>/ hard-linked (copied across file systems),
// scenes.jsonl concatenated, manifest.json for shard 0/1. Refuses, naming the folder: a shard of another
// recipe or tool version, a shard twice, a missing shard, an incomplete or torn shard. Written under a
// temporary name and renamed: a failed merge leaves nothing.
Result<MergeSummary> MergeShards(const std::filesystem::path& out, const std::vector<std::filesystem::path>& shards);

struct VerifySummary {
  std::string kind;
  uint64_t records = 0;
  uint64_t files = 0;  // files hashed
  uint64_t failed = 0;
};
// Re-hashes every file of a synth or scenes folder (a shard or a merged dataset) against its manifest and
// index; the first problem is the error ("scenes/villa-000003/furnished.glb: SHA-256 ... differs from
// the index's ...").
Result<VerifySummary> VerifyDataset(const std::filesystem::path& dir);

// One line a shard and a total: villas (layouts) done, failed and left, the rate and the ETA of the
// running ones, a state (complete, running, stopped, not started). A folder with no manifest of its own is
// searched one level down for shard folders. `now` is the Unix time (tests pass theirs).
Result<std::string> DatasetStatus(const std::vector<std::filesystem::path>& dirs, int64_t now);

}  // namespace villa::shards
