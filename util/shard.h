#pragma once
// Which part of a dataset job this process does: shard i of n takes the items [N*i/n, N*(i+1)/n) of N,
// so shards concatenated in order are the whole job and every shard differs in size by at most one.
// `--shard` takes "i/n", or "auto" on a cluster: Slurm's job array (SLURM_ARRAY_TASK_ID counted from
// SLURM_ARRAY_TASK_MIN in steps of SLURM_ARRAY_TASK_STEP, of SLURM_ARRAY_TASK_COUNT tasks; with "auto/n" the
// task id itself of n shards, so one task resubmitted alone keeps its shard), else a Kubernetes indexed job
// (JOB_COMPLETION_INDEX, of VILLA_SHARD_COUNT or "auto/n"'s n shards).
#include <cstdint>
#include <functional>
#include <string>

#include "util/result.h"

namespace villa {

struct Shard {
  uint64_t index = 0;
  uint64_t count = 1;

  uint64_t First(uint64_t items) const { return Split(items, index); }
  uint64_t Last(uint64_t items) const { return Split(items, index + 1); }
  std::string Text() const { return std::to_string(index) + "/" + std::to_string(count); }
  // "shard-0003-of-0008": the folder a cluster script gives this shard.
  std::string FolderName() const;

 private:
  uint64_t Split(uint64_t items, uint64_t k) const {
    return static_cast<uint64_t>((static_cast<unsigned __int128>(items) * k) / count);
  }
};

// An environment lookup (nullptr when unset); tests pass their own.
using Environment = std::function<const char*(const char* name)>;
const char* ProcessEnvironment(const char* name);

// Parses "i/n" (0 <= i < n, n >= 1), "auto" or "auto/n". Errors say what was wrong and, for "auto",
// which variables were looked at: "--shard auto: SLURM_ARRAY_TASK_ID is not set (not a Slurm array task?)".
Result<Shard> ParseShard(const std::string& text, const Environment& env = ProcessEnvironment);

}  // namespace villa
