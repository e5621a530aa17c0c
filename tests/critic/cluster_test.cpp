// Rooms after the offline critic (issue 14) where an edge no single move mends is mended by moving several
// objects together: the sofa carried with its cluster as one piece, the side table re-seated at the end the
// move made room for, a desk and its chair both made smaller to fit a narrow arm.
#include <set>
#include <string>

#include <catch2/catch.hpp>

#include "furnish_fixture.h"

namespace villa {

TEST_CASE("The sofa carried with its coffee table makes room for the side table at its end", "[critic][offline][cluster]") {
  // villa-000030 of `villa synth --count 50 --seed 7`: the solver leaves the side table beside the sofa's
  // back corner (neither left of it nor within 10 cm), the coffee table short of its gap, and the sofa's
  // zone entered; the side table alone has no free place at the sofa's left end.
  // Seed 1: since issue 27's planner changes, seed 7 leaves the side table where it belongs.
  const testing::FurnishedRoom f = testing::FurnishFixtureRoom("living_side_table_cluster.json", "living-room_0/0", false, 1);
  const auto& [room, record, totals, first_round] = f;
  INFO(record.dump(1));
  // The solver alone: the side table is not left of the sofa, one of its two next_to fails.
  REQUIRE(f.Count("relations_before", "left_of", "satisfied") == 0);
  REQUIRE(f.Count("relations_before", "next_to", "satisfied") < f.Count("relations_before", "next_to", "measured"));
  // After the critic both hold, nothing was lost, and the sofa moved as the hub of a cluster move.
  CHECK(f.Count("relations_after", "left_of", "satisfied") >= 1);
  CHECK(f.Count("relations_after", "left_of", "satisfied") == f.Count("relations_after", "left_of", "measured"));
  CHECK(f.Count("relations_after", "next_to", "satisfied") == f.Count("relations_after", "next_to", "measured"));
  CHECK(f.Count("relations_after", "left_of", "lost") == 0);
  bool sofa_carried = false;
  for (const auto& a : room["actions"])
    sofa_carried = sofa_carried || (a.value("id", "") == "living-room_0/0/sofa-0" && a.value("status", "") == "applied" &&
                                    a.value("reason", "").find("(moved with living-room_0/0/sofa-0)") != std::string::npos);
  CHECK(sofa_carried);
  CHECK(totals["CR"] == 0.0);
  CHECK(totals["FR"] == 0.0);
  CHECK(totals["OBR"] == 0.0);
}

TEST_CASE("The sofa is carried to the long wall across from the TV stand, the armchair in the way making way",
          "[critic][offline][cluster]") {
  // villa-000016 of `villa synth --count 50 --seed 7`: a 3.5 x 6.7 m living room whose solver put the sofa on
  // the short end wall and the TV stand on a long side wall, 3.8 m before it and off its side, facing 64
  // degrees away. The sofa belongs on the other long wall, 3.5 m across; an armchair and a plant stand where
  // the stand goes. Before the make-way moves (a4e0f5b) the critic left the TV stand's three edges unmet.
  // Seed 5: since issue 27's planner changes, seed 7's solver already puts the sofa across from the stand.
  const auto [room, record, totals, first_round] = testing::FurnishFixtureRoom("living_tv_across.json", "living-room_0/0", false, 5);
  INFO(record.dump(1));
  const auto unmet_of = [&](const char* when, const std::string& start) {
    int n = 0;
    for (const auto& line : record[when]["unmet"]) n += line.get<std::string>().rfind(start, 0) == 0;
    return n;
  };
  const std::string stand = "living-room_0/0/tv-stand-0 ";
  REQUIRE(unmet_of("relations_before", stand + "front_of") == 1);
  REQUIRE(unmet_of("relations_before", stand + "face_to") == 1);
  // After: the stand is 2-3 m before the sofa, within its width, and they face each other (the TV too).
  CHECK(unmet_of("relations_after", stand) == 0);
  CHECK(record["relations_after"]["by_relation"]["face_to"]["satisfied"] == record["relations_after"]["by_relation"]["face_to"]["measured"]);
  CHECK(2 * record["relations_after"]["unmet"].size() < record["relations_before"]["unmet"].size());
  bool made_way = false;
  for (const auto& a : room["actions"])
    made_way = made_way || (a.value("id", "").find("/armchair-") != std::string::npos && a.value("status", "") == "applied" &&
                            a.value("reason", "").find("(re-placed by the solver around the group)") != std::string::npos);
  CHECK(made_way);
  CHECK(totals["CR"] == 0.0);
  CHECK(totals["FR"] == 0.0);
  CHECK(totals["OBR"] == 0.0);
}

TEST_CASE("The coffee table follows the carried sofa, seated before it with its rug and armchairs", "[critic][offline][cluster]") {
  // villa-000016 again: once the sofa is carried across, the coffee table must come to stand before it.
  // The solver alone, re-placing it around the armchairs still standing where it belongs, put it 1.3 m off
  // and 2.7 m off the sofa's axis (before the seated ring members and satellite moves); now it stands
  // 0.45-0.60 m before the sofa, centred, with the rug centred under it.
  const auto [room, record, totals, first_round] = testing::FurnishFixtureRoom("living_tv_across.json", "living-room_0/0", false);
  INFO(record.dump(1));
  const auto unmet_of = [&](const std::string& start) {
    int n = 0;
    for (const auto& line : record["relations_after"]["unmet"]) n += line.get<std::string>().rfind(start, 0) == 0;
    return n;
  };
  CHECK(unmet_of("living-room_0/0/coffee-table-0 ") == 0);
  CHECK(unmet_of("living-room_0/0/rug-0 ") == 0);
  CHECK(unmet_of("living-room_0/0/armchair-") == 0);
  CHECK(record["relations_after"]["by_relation"]["front_of"]["satisfied"] == record["relations_after"]["by_relation"]["front_of"]["measured"]);
  CHECK(record["relations_after"]["by_relation"]["centered"]["satisfied"] == record["relations_after"]["by_relation"]["centered"]["measured"]);
  CHECK(totals["CR"] == 0.0);
  CHECK(totals["FR"] == 0.0);
  CHECK(totals["OBR"] == 0.0);
}

TEST_CASE("A desk and its chair both made smaller to fit the narrow arm of an L-shaped office", "[critic][offline][cluster]") {
  // villa-000030 again, its office: the desk stands against the end wall of a 1.19 m arm, 0.68 m deep, and a
  // 0.61 m chair does not fit before it, even at 0.8 (1.17 m with the clearance); the solver put the chair
  // beside the desk. Both at their smallest scale fit, the monitor turned to the chair. Seed 2: since issue
  // 27's planner changes, seed 7's chair fits once the desk alone is smaller.
  const testing::FurnishedRoom f = testing::FurnishFixtureRoom("living_side_table_cluster.json", "office_1/0", false, 2);
  const auto& [room, record, totals, first_round] = f;
  INFO(record.dump(1));
  REQUIRE(f.Count("relations_before", "front_of", "satisfied") == 0);
  CHECK(f.Count("relations_after", "front_of", "satisfied") == 1);
  CHECK(f.Count("relations_after", "face_to", "satisfied") == f.Count("relations_after", "face_to", "measured"));
  CHECK(record["relations_after"]["unmet"].empty());
  std::set<std::string> shrunk;
  for (const auto& a : room["actions"])
    if (a.value("action", "") == "update_scale" && a.value("status", "") == "applied" &&
        a.value("reason", "").find("(both smaller)") != std::string::npos)
      shrunk.insert(a.value("id", ""));
  CHECK(shrunk == std::set<std::string>{"office_1/0/desk-0", "office_1/0/office-chair-0"});
  CHECK(totals["CR"] == 0.0);
  CHECK(totals["FR"] == 0.0);
  CHECK(totals["OBR"] == 0.0);
}

}  // namespace villa
