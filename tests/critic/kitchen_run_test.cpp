// The offline critic's run moves in a small kitchen: a 2.2 x 2.7 m room (villa 24 of `villa synth --count 50
// --seed 7`, tests/fixtures/layouts/kitchen_small_corner.json) with a door on one long wall and a window on
// the other, whose fridge, two counters and cooker fit no single wall. Before the L, the chain's
// `cooker-0 next_to counter-1` stayed 1.13 m apart; laid round a corner, every next_to of the chain holds,
// nothing is lost, and the room stays physically clean.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include <nlohmann/json.hpp>

#include "room_fixture.h"
#include "villa_cli.h"

namespace villa {
namespace {

namespace fs = std::filesystem;

nlohmann::json ReadJson(const fs::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

const std::string kSmallKitchen = std::string(VILLA_FIXTURE_DIR) + "/layouts/kitchen_small_corner.json";

std::string Furnish(const std::string& critic, const fs::path& out) {
  return "furnish " + kSmallKitchen + " --procedural -q --seed 7 --no-reach --room kitchen_0/0 --critic " + critic + " -o " +
         out.string();
}

}  // namespace

TEST_CASE("A small kitchen's run is laid round a corner: every next_to of the chain holds, nothing is lost", "[critic][offline][kitchen]") {
  testing::TempDir offline("kitchen_l"), none("kitchen_none");
  auto run = testing::RunVilla(Furnish("offline", offline.path));
  INFO(run.out);
  REQUIRE(run.status == 0);
  auto bare = testing::RunVilla(Furnish("none", none.path));
  REQUIRE(bare.status == 0);

  const nlohmann::json critic = ReadJson(offline.path / "critic" / "kitchen_0_0" / "critic.json");
  INFO(critic.dump(1));
  // The solver alone leaves the chain broken (the room has no wall for it)...
  const nlohmann::json& before = critic["relations_before"]["by_relation"]["next_to"];
  CHECK(before["satisfied"].get<int>() < before["measured"].get<int>());
  // ... the critic mends every link of it.
  const nlohmann::json& after = critic["relations_after"]["by_relation"]["next_to"];
  CHECK(after["measured"].get<int>() == 3);
  CHECK(after["satisfied"].get<int>() == 3);
  CHECK(after["lost"].get<int>() == 0);

  // Round a corner: the fridge, the counters and the cooker face two directions a quarter turn apart.
  const nlohmann::json scene = ReadJson(offline.path / "scene.json");
  std::set<long> yaws;
  for (const char* id : {"fridge-0", "counter-0", "counter-1", "cooker-0"}) {
    const std::string key = std::string("kitchen_0/0/") + id;
    REQUIRE(scene["objects"].contains(key));
    yaws.insert(std::lround(std::fmod(scene["objects"][key]["pose"]["yaw"].get<double>() + 360.0, 360.0)));
  }
  CHECK(yaws.size() == 2);
  if (yaws.size() == 2) CHECK(std::abs(*yaws.rbegin() - *yaws.begin()) % 180 == 90);

  // Nothing the plan put in the room went missing on the way (the things on the counters included).
  const nlohmann::json bare_scene = ReadJson(none.path / "scene.json");
  std::set<std::string> with, without;
  for (const auto& [id, o] : scene["objects"].items()) with.insert(id);
  for (const auto& [id, o] : bare_scene["objects"].items()) without.insert(id);
  CHECK(with == without);

  // Physically clean.
  const nlohmann::json report = ReadJson(offline.path / "report.json");
  const nlohmann::json& totals = report["totals"];
  INFO(totals.dump());
  CHECK(totals["CR"].get<double>() == 0.0);
  CHECK(totals["FR"].get<double>() == 0.0);
  CHECK(totals["OBR"].get<double>() == 0.0);
  CHECK(totals["removed"].get<int>() == 0);
}

}  // namespace villa
