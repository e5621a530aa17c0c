// The offline critic: it mends a relation the solver left unmet through the solver's actions, never at the
// price of physics (the exact check stays clean), never losing an edge by removing its object, the same
// result for the same seed; and the furnish pipeline with it (report and logs).
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "critic/critic.h"
#include "critic/relations.h"
#include "furnish_fixture.h"
#include "room_fixture.h"
#include "solver/furnish.h"

namespace villa {
namespace {

namespace fs = std::filesystem;

int Satisfied(const nlohmann::ordered_json& relations) { return relations["satisfied"].get<int>(); }

}  // namespace

TEST_CASE("The offline critic leaves every room at least as related as the solver did, physically valid, deterministic", "[critic][offline]") {
  for (const char* name : {"living-room_0/0", "bedroom_0/0", "dining-room_0/0", "kitchen_0/0", "bathroom_0/0", "office_0/0"}) {
    auto room = testing::MakeCriticRoom(name);
    critic::CriticOptions options;
    auto a = critic::CritiqueRoom(room->input, options);
    REQUIRE(a.ok());
    auto b = critic::CritiqueRoom(room->input, options);
    REQUIRE(b.ok());
    INFO(name << ": " << a->figures.record.dump());
    const auto& record = a->figures.record;
    CHECK(Satisfied(record["relations_after"]) >= Satisfied(record["relations_before"]));
    CHECK(record["relations_after"]["zones_clear"].get<int>() >= record["relations_before"]["zones_clear"].get<int>());
    CHECK(a->solution.summary.metrics.Clean());
    CHECK(a->solution.summary.energy.collision == 0.0);
    CHECK(a->solution.summary.energy.support == 0.0);
    REQUIRE(a->solution.placements.size() == b->solution.placements.size());
    for (size_t i = 0; i < a->solution.placements.size(); ++i) {
      CHECK(a->solution.objects[i].id == b->solution.objects[i].id);
      CHECK(a->solution.placements[i].pose.x == b->solution.placements[i].pose.x);
      CHECK(a->solution.placements[i].pose.yaw == b->solution.placements[i].pose.yaw);
    }
    // No edge of the graph was lost to the critic.
    CHECK(record["relations_after"]["measured"] == record["relations_before"]["measured"]);
  }
}

TEST_CASE("A relation the solver was not told about is mended by the offline critic with update_pose", "[critic][offline]") {
  auto room = testing::MakeCriticRoom("living-room_0/0");
  // The graph wants the armchair to face the sofa; the solver's problem does not say so. (It was the TV
  // stand until the sofa of this deep room stood free: facing the stand now breaks the armchair's face_to
  // the coffee table, so no move leaves fewer relations unmet.)
  std::vector<scene::SemanticEdge> graph = room->plan.edges;
  graph.push_back({"living-room_0/0/armchair-0", scene::SemanticRelation::kFaceTo, "living-room_0/0/sofa-0", {}});
  room->input.edges = &graph;
  auto before = critic::CritiqueRoom(room->input, [] {
    critic::CriticOptions o;
    o.kind = critic::CriticKind::kNone;
    return o;
  }());
  REQUIRE(before.ok());
  const auto unmet = [&](const solver::RoomSolution& s) {
    for (const critic::EdgeCheck& c : critic::MeasureRelations(s.objects, s.placements, {graph.back()}).edges)
      return !c.satisfied;
    return true;
  };
  REQUIRE(unmet(before->solution));
  auto after = critic::CritiqueRoom(room->input, critic::CriticOptions{});
  REQUIRE(after.ok());
  CHECK_FALSE(unmet(after->solution));
  CHECK(after->solution.summary.metrics.Clean());
  bool moved = false;
  for (const solver::ActionResult& a : after->solution.summary.actions)
    moved = moved || (a.action.id == "living-room_0/0/armchair-0" && a.action.kind == solver::ActionKind::kUpdatePose &&
                      a.status == solver::ActionStatus::kApplied);
  CHECK(moved);
}

TEST_CASE("villa furnish with the offline critic reports the relations before and after and logs each round", "[critic][offline][furnish]") {
  const fs::path dir = fs::temp_directory_path() / ("villa_critic_furnish_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  solver::FurnishOptions options;
  options.rooms = {"living-room_0/0", "bathroom_0/0"};
  options.procedural_only = true;
  options.jobs = 2;
  critic::CriticOptions c;
  c.log_dir = dir / "critic";
  options.critic = critic::MakeRoomCritic(c);
  auto summary = solver::FurnishLayoutFile(testing::kHouse, dir, options);
  REQUIRE(summary.ok());
  std::ifstream in(dir / "report.json");
  const nlohmann::json report = nlohmann::json::parse(in);
  CHECK(report["totals"]["critic"]["critic"] == "offline");
  CHECK(report["totals"]["critic"]["rounds"].get<int>() >= 2);
  for (const auto& room : report["rooms"]) {
    if (!room["asked"].get<bool>()) {
      CHECK_FALSE(room.contains("critic"));
      continue;
    }
    const auto& critic = room["critic"];
    CHECK(critic["record"]["relations_before"]["by_relation"].is_object());
    CHECK(critic["record"]["relations_after"]["satisfied"].get<int>() >= critic["record"]["relations_before"]["satisfied"].get<int>());
    const std::string folder = critic::RoomLogFolder(room["room"]);
    CHECK(fs::exists(dir / "critic" / folder / "round-1" / "state.txt"));
    CHECK(fs::exists(dir / "critic" / folder / "critic.json"));
    CHECK_FALSE(fs::exists(dir / "critic" / folder / "round-1" / "view-top.png"));  // the offline critic looks at no picture
  }
  CHECK(report["totals"]["CR"] == 0.0);
  CHECK(report["totals"]["FR"] == 0.0);
  CHECK(report["totals"]["OBR"] == 0.0);
  fs::remove_all(dir);
}

}  // namespace villa

namespace villa {

TEST_CASE("A room's earlier round logs are replaced, not mixed with the new ones, and nothing else in the folder goes", "[critic][offline]") {
  auto room = testing::MakeCriticRoom("bathroom_0/0");
  testing::TempDir logs("relog");
  const std::filesystem::path folder = logs.path / "bathroom_0_0";
  std::filesystem::create_directories(folder / "round-17");
  std::filesystem::create_directories(folder / "notes");
  { std::ofstream(folder / "round-17" / "round.json") << "{}"; }
  { std::ofstream(folder / "mine.txt") << "a person's note"; }
  critic::CriticOptions options;
  options.log_dir = logs.path;
  REQUIRE(critic::CritiqueRoom(room->input, options).ok());
  CHECK_FALSE(std::filesystem::exists(folder / "round-17"));
  CHECK(std::filesystem::exists(folder / "round-1" / "round.json"));
  CHECK(std::filesystem::exists(folder / "critic.json"));
  CHECK(std::filesystem::exists(folder / "mine.txt"));
  CHECK(std::filesystem::exists(folder / "notes"));
}

}  // namespace villa

namespace villa {

// villa-000006 of `villa synth --count 50 --seed 7` (the bench's set): its 11.2 m2 bedroom_0/0 puts the bed
// where its wall has no room for a nightstand beside it and the painting cannot hang centred above it.
// No single move mends that, and the group move that did shrank the bed to 0.8 (1.6-1.7 m long: no adult's
// bed; half the rooms bench's beds were so). A double is not shrunk below a single's 1.95 m length for its
// group: the nightstand stays unmended rather than the bed too short (issue 27).
TEST_CASE("The offline critic does not shrink a bed below a single bed's length to lay out its nightstand and painting", "[critic][offline][bed]") {
  const auto [room, record, totals, first] = testing::FurnishFixtureRoom("bedroom_no_wall_for_nightstand.json", "bedroom_0/0", false);
  INFO(record.dump(1));
  const auto lines = [](const nlohmann::json& unmet, const std::string& what) {
    int n = 0;
    for (const auto& line : unmet) n += line.get<std::string>().find(what) != std::string::npos;
    return n;
  };
  // The solver alone leaves the nightstand away from the bed and the painting off its axis ...
  REQUIRE(lines(record["relations_before"]["unmet"], "nightstand-0 next_to bedroom_0/0/bed-0") == 1);
  REQUIRE(lines(record["relations_before"]["unmet"], "painting-0 centered bedroom_0/0/bed-0") == 1);
  // ... the critic does not shrink the bed for them, and leaves nothing worse.
  int shrunk = 0;
  for (const auto& a : room["actions"])
    shrunk += a.value("id", "") == "bedroom_0/0/bed-0" && a.value("action", "") == "update_scale" &&
              a.value("reason", "").rfind("critic:", 0) == 0;
  CHECK(shrunk == 0);
  CHECK(record["relations_after"]["satisfied"].get<int>() >= record["relations_before"]["satisfied"].get<int>());
  CHECK(totals["CR"] == 0.0);
  CHECK(totals["FR"] == 0.0);
  CHECK(totals["OBR"] == 0.0);
}

}  // namespace villa
