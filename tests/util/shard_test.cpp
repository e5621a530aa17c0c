#include <catch2/catch.hpp>

#include <map>
#include <string>

#include "util/shard.h"

using namespace villa;

namespace {
Environment Env(std::map<std::string, std::string> vars) {
  auto held = std::make_shared<std::map<std::string, std::string>>(std::move(vars));
  return [held](const char* name) -> const char* {
    auto it = held->find(name);
    return it == held->end() ? nullptr : it->second.c_str();
  };
}
}  // namespace

TEST_CASE("shards split N items into contiguous ranges that cover them once", "[shard]") {
  for (uint64_t n : {1, 3, 8}) {
    uint64_t next = 0;
    for (uint64_t i = 0; i < n; ++i) {
      const Shard s{i, n};
      CHECK(s.First(2000) == next);
      CHECK(s.Last(2000) - s.First(2000) >= 2000 / n);
      next = s.Last(2000);
    }
    CHECK(next == 2000);
  }
  CHECK(Shard{3, 8}.FolderName() == "shard-0003-of-0008");
  CHECK(Shard{3, 8}.Text() == "3/8");
}

TEST_CASE("the shard flag reads i/n, a Slurm array task and a Kubernetes indexed job", "[shard]") {
  const Environment none = Env({});
  auto two = ParseShard("2/5", none);
  REQUIRE(two.ok());
  CHECK((two->index == 2 && two->count == 5));
  CHECK(ParseShard("5/5", none).error() == "--shard 5/5: shard 5 does not exist among 5 (shards count from 0)");
  CHECK(ParseShard("1/0", none).error() == "--shard 1/0: the number of shards must be at least 1");
  CHECK(ParseShard("x", none).error() == "--shard \"x\": expected i/n (e.g. 0/4), auto or auto/n");
  CHECK(ParseShard("auto", none).error().find("neither SLURM_ARRAY_TASK_ID") != std::string::npos);

  // Slurm: --array=1-8 has IDs 1..8, MIN 1, COUNT 8.
  auto slurm = ParseShard("auto", Env({{"SLURM_ARRAY_TASK_ID", "4"}, {"SLURM_ARRAY_TASK_MIN", "1"}, {"SLURM_ARRAY_TASK_COUNT", "8"}}));
  REQUIRE(slurm.ok());
  CHECK((slurm->index == 3 && slurm->count == 8));
  // auto/n: the task id is the shard, so task 3 resubmitted alone (--array=3: MIN 3, COUNT 1) stays shard 3.
  auto alone = ParseShard("auto/8", Env({{"SLURM_ARRAY_TASK_ID", "3"}, {"SLURM_ARRAY_TASK_MIN", "3"}, {"SLURM_ARRAY_TASK_COUNT", "1"}}));
  REQUIRE(alone.ok());
  CHECK((alone->index == 3 && alone->count == 8));
  // A stepped array (--array=0-14:2): ids 0, 2, ..., 14 are shards 0..7.
  auto stepped = ParseShard("auto", Env({{"SLURM_ARRAY_TASK_ID", "6"}, {"SLURM_ARRAY_TASK_MIN", "0"}, {"SLURM_ARRAY_TASK_STEP", "2"},
                                          {"SLURM_ARRAY_TASK_COUNT", "8"}}));
  REQUIRE(stepped.ok());
  CHECK((stepped->index == 3 && stepped->count == 8));
  CHECK(ParseShard("auto/0", Env({{"SLURM_ARRAY_TASK_ID", "0"}})).error() == "--shard \"auto/0\": expected auto/n with n a whole number of at least 1");
  CHECK(ParseShard("auto", Env({{"SLURM_ARRAY_TASK_ID", "0"}})).error().find("SLURM_ARRAY_TASK_COUNT is not set") != std::string::npos);
  CHECK(ParseShard("auto", Env({{"SLURM_ARRAY_TASK_ID", "9"}, {"SLURM_ARRAY_TASK_COUNT", "8"}})).error() ==
        "--shard auto: shard 9 does not exist among 8 (shards count from 0)");
  CHECK(ParseShard("auto", Env({{"SLURM_ARRAY_TASK_ID", "x1"}, {"SLURM_ARRAY_TASK_COUNT", "8"}})).error() ==
        "--shard auto: SLURM_ARRAY_TASK_ID=\"x1\" is not a whole number");

  // Kubernetes: the index from JOB_COMPLETION_INDEX, the count from auto/n or VILLA_SHARD_COUNT.
  auto k8s = ParseShard("auto/6", Env({{"JOB_COMPLETION_INDEX", "5"}}));
  REQUIRE(k8s.ok());
  CHECK((k8s->index == 5 && k8s->count == 6));
  auto k8s_env = ParseShard("auto", Env({{"JOB_COMPLETION_INDEX", "1"}, {"VILLA_SHARD_COUNT", "2"}}));
  REQUIRE(k8s_env.ok());
  CHECK((k8s_env->index == 1 && k8s_env->count == 2));
  CHECK(ParseShard("auto", Env({{"JOB_COMPLETION_INDEX", "1"}})).error().find("VILLA_SHARD_COUNT is not set") != std::string::npos);
}
