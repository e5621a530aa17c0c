#pragma once
// One room of a fixture layout furnished as `villa furnish LAYOUT --room ROOM --seed 7` does with procedural
// assets and the offline critic (its log under the run's critic/), and what the run's report.json says of
// it: the room's entry, the critic's record, the totals, and the critic's log of its first round. The run's
// folder is removed afterwards.
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "critic/critic.h"
#include "solver/furnish.h"

namespace villa::testing {

struct FurnishedRoom {
  nlohmann::json room, record, totals;
  nlohmann::json first_round;  // critic/<room>/round-1/round.json (null when there is none)
  // The critic record's count `what` ("satisfied", "measured", "lost") of a relation type, `when`
  // "relations_before" or "relations_after".
  int Count(const char* when, const char* relation, const char* what) const { return record[when]["by_relation"][relation][what].get<int>(); }
};

// `layout`: a file under tests/fixtures/layouts/; `reach`: the reachability feedback loop on; `seed`: the
// furnishing's seed.
inline FurnishedRoom FurnishFixtureRoom(const std::string& layout, const std::string& room, bool reach, uint64_t seed = 7) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("villa_critic_fixture_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  solver::FurnishOptions options;
  options.rooms = {room};
  options.seed = seed;
  options.procedural_only = true;
  options.pictures = false;
  options.check_reach = reach;
  options.jobs = 1;
  // The critic on its own: the solver's arrangement without issue 27's group templates, the arrangements
  // these fixtures were chosen for (what the critic must mend).
  options.solve.functional_groups = false;
  // ... and the plans they were chosen with: the paper's 22-30 objects, no dressing (issue 27 plans more).
  options.planner.rich_min_objects = 22;
  options.planner.rich_max_objects = 30;
  options.planner.dress = false;
  critic::CriticOptions c;
  c.log_dir = dir / "critic";
  options.critic = critic::MakeRoomCritic(c);
  auto summary = solver::FurnishLayoutFile(std::string(VILLA_FIXTURE_DIR) + "/layouts/" + layout, dir, options);
  REQUIRE(summary.ok());
  std::ifstream in(dir / "report.json");
  const nlohmann::json report = nlohmann::json::parse(in);
  FurnishedRoom out;
  out.totals = report["totals"];
  for (const auto& r : report["rooms"])
    if (r.value("room", "") == room) out.room = r;
  std::string folder = room;
  for (char& ch : folder)
    if (ch == '/') ch = '_';
  if (std::ifstream round{dir / "critic" / folder / "round-1" / "round.json"}) out.first_round = nlohmann::json::parse(round);
  fs::remove_all(dir);
  REQUIRE(out.room.is_object());
  REQUIRE(out.room.contains("critic"));
  out.record = out.room["critic"]["record"];
  return out;
}

}  // namespace villa::testing
