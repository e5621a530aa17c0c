#include "util/shard.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace villa {
namespace {

bool Whole(std::string_view text, uint64_t* value) {
  if (text.empty()) return false;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), *value);
  return ec == std::errc() && end == text.data() + text.size();
}

// A variable that must hold a whole number.
Result<uint64_t> WholeVariable(const Environment& env, const char* name, const std::string& why_missing) {
  const char* value = env(name);
  if (!value) return Error{"--shard auto: " + std::string(name) + " is not set" + why_missing};
  uint64_t v = 0;
  if (!Whole(value, &v)) return Error{"--shard auto: " + std::string(name) + "=\"" + value + "\" is not a whole number"};
  return v;
}

Result<Shard> Checked(Shard s, const std::string& text) {
  if (s.count == 0) return Error{"--shard " + text + ": the number of shards must be at least 1"};
  if (s.index >= s.count)
    return Error{"--shard " + text + ": shard " + std::to_string(s.index) + " does not exist among " + std::to_string(s.count) +
                 " (shards count from 0)"};
  return s;
}

}  // namespace

std::string Shard::FolderName() const {
  char name[64];
  std::snprintf(name, sizeof name, "shard-%04llu-of-%04llu", static_cast<unsigned long long>(index),
                static_cast<unsigned long long>(count));
  return name;
}

const char* ProcessEnvironment(const char* name) { return std::getenv(name); }

Result<Shard> ParseShard(const std::string& text, const Environment& env) {
  const std::size_t slash = text.find('/');
  const std::string_view head = std::string_view(text).substr(0, slash);
  const std::string_view tail = slash == std::string::npos ? std::string_view() : std::string_view(text).substr(slash + 1);
  if (head != "auto") {
    Shard s;
    if (slash == std::string::npos || !Whole(head, &s.index) || !Whole(tail, &s.count))
      return Error{"--shard \"" + text + "\": expected i/n (e.g. 0/4), auto or auto/n"};
    return Checked(s, text);
  }
  uint64_t stated = 0;
  if (slash != std::string::npos && (!Whole(tail, &stated) || stated == 0))
    return Error{"--shard \"" + text + "\": expected auto/n with n a whole number of at least 1"};
  Shard s;
  if (env("SLURM_ARRAY_TASK_ID")) {
    auto id = WholeVariable(env, "SLURM_ARRAY_TASK_ID", "");
    if (!id) return Error{id.error()};
    if (stated) {
      // auto/n: the task ids are the shard indices (an array 0..n-1, or one task resubmitted alone with
      // --array=3, whose MIN and COUNT speak of that submission only).
      s.index = *id;
      s.count = stated;
    } else {
      auto count = WholeVariable(env, "SLURM_ARRAY_TASK_COUNT", " (Slurm sets it for job arrays: sbatch --array=0-N)");
      if (!count) return Error{count.error()};
      uint64_t min = 0, step = 1;
      if (env("SLURM_ARRAY_TASK_MIN")) {
        auto m = WholeVariable(env, "SLURM_ARRAY_TASK_MIN", "");
        if (!m) return Error{m.error()};
        min = *m;
      }
      if (env("SLURM_ARRAY_TASK_STEP")) {
        auto st = WholeVariable(env, "SLURM_ARRAY_TASK_STEP", "");
        if (!st) return Error{st.error()};
        step = std::max<uint64_t>(1, *st);
      }
      if (*id < min) return Error{"--shard auto: SLURM_ARRAY_TASK_ID " + std::to_string(*id) + " is below SLURM_ARRAY_TASK_MIN " + std::to_string(min)};
      s.index = (*id - min) / step;
      s.count = *count;
    }
  } else if (env("JOB_COMPLETION_INDEX")) {
    auto index = WholeVariable(env, "JOB_COMPLETION_INDEX", "");
    if (!index) return Error{index.error()};
    s.index = *index;
    if (stated) {
      s.count = stated;
    } else {
      auto count = WholeVariable(env, "VILLA_SHARD_COUNT", " (a Kubernetes indexed job: give the completions as --shard auto/n or VILLA_SHARD_COUNT)");
      if (!count) return Error{count.error()};
      s.count = *count;
    }
  } else {
    return Error{"--shard " + text +
                 ": neither SLURM_ARRAY_TASK_ID (a Slurm job array task) nor JOB_COMPLETION_INDEX (a Kubernetes indexed job) is set; "
                 "give the shard as i/n"};
  }
  return Checked(s, text);
}

}  // namespace villa
