// The procedural backend on 100+ varied requests (tests/fixtures/prompts/varied.jsonl, five styles):
// every layout valid, every requirement of the brief met, and the parsed brief equal to what the prompt
// was written to ask (floors, footprint class, rooms per category, rooms per floor).
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>

#include <catch2/catch.hpp>

#include "generator/text/backends.h"
#include "layout/footprint.h"
#include "generator/text/plan.h"
#include "layout/layout_io.h"

namespace villa {
namespace {

struct PromptCase {
  int line = 0;
  Json record;
};

std::vector<PromptCase> LoadPrompts() {
  std::vector<PromptCase> out;
  Status status = ReadJsonl(std::string(VILLA_FIXTURE_DIR) + "/prompts/varied.jsonl", [&](const Json& record, int line) {
    out.push_back({line, record});
    return true;
  });
  REQUIRE(status.ok());
  return out;
}

std::map<std::string, int> CountCategories(const Layout& layout, int level) {
  std::map<std::string, int> out;
  for (const Room& r : layout.rooms)
    if (level < 0 || r.level == level) ++out[std::string(CategoryName(r.category))];
  return out;
}

}  // namespace

TEST_CASE("the procedural backend meets every brief of the varied prompts with valid layouts") {
  const auto prompts = LoadPrompts();
  REQUIRE(prompts.size() >= 100);
  PlanOptions options;
  options.time_budget_s = 4.0;  // a ceiling for slow machines; most briefs are met in a few attempts
  int met = 0;
  std::map<std::string, int> styles;
  for (const auto& p : prompts) {
    const std::string text = p.record.at("text").get<std::string>();
    const Json& expect = p.record.at("expect");
    options.seed = static_cast<std::uint64_t>(p.line);
    PlanSummary plan = PlanLayout(text, options);
    INFO("line " << p.line << ": " << text << "\n" << plan.BriefReport());
    REQUIRE(plan.layout.has_value());
    CHECK(plan.violations.empty());
    CHECK(plan.valid());
    CHECK(plan.brief.unparsed.empty());
    CHECK(plan.brief.conflicts.empty());
    CHECK(plan.outcome == PlanOutcome::kMet);
    met += plan.outcome == PlanOutcome::kMet;
    ++styles[p.record.at("style").get<std::string>()];
    // What the prompt was written to ask, read back from the layout that meets the parsed brief.
    CHECK(plan.layout->LevelCount() == expect.at("floors").get<int>());
    CHECK(plan.brief.shape.has_value());
    if (plan.brief.shape) CHECK(std::string(ShapeClassName(*plan.brief.shape)) == expect.at("shape").get<std::string>());
    const auto counts = CountCategories(*plan.layout, -1);
    for (const auto& [category, n] : expect.at("rooms").items()) {
      INFO(category);
      auto it = counts.find(category);
      CHECK((it == counts.end() ? 0 : it->second) == n.get<int>());
    }
    if (expect.contains("levels")) {
      for (const auto& [level, rooms] : expect.at("levels").items()) {
        const auto on_level = CountCategories(*plan.layout, std::stoi(level));
        for (const auto& [category, n] : rooms.items()) {
          INFO(category << " on level " << level);
          auto it = on_level.find(category);
          CHECK((it == on_level.end() ? 0 : it->second) == n.get<int>());
        }
      }
    }
  }
  CHECK(met == static_cast<int>(prompts.size()));
  CHECK(styles.size() >= 5);
}

TEST_CASE("the procedural backend is deterministic for a seed") {
  PlanOptions options;
  options.seed = 7;
  const std::string text = "A two-story L-shaped house with a living room, a kitchen, a dining room, two bedrooms, "
                           "a bathroom on each floor and a balcony.";
  PlanSummary a = PlanLayout(text, options);
  PlanSummary b = PlanLayout(text, options);
  REQUIRE(a.valid());
  REQUIRE(b.valid());
  CHECK(LayoutToString(*a.layout) == LayoutToString(*b.layout));
  options.seed = 8;
  PlanSummary c = PlanLayout(text, options);
  REQUIRE(c.valid());
  CHECK(LayoutToString(*a.layout) != LayoutToString(*c.layout));
}

TEST_CASE("polygonal footprints asked in words are made and meet the rest of the brief") {
  PlanOptions options;
  options.time_budget_s = 2.0;
  const std::pair<const char*, ShapeClass> cases[] = {
      {"A hexagonal two-storey villa with a kitchen, a living room and three bedrooms.", ShapeClass::kHexagon},
      {"An octagonal single-storey house with two bedrooms, a kitchen and a bathroom.", ShapeClass::kOctagon},
      {"A star-shaped pavilion with a living room, a dining room and a kitchen.", ShapeClass::kCross},
      {"A trapezoidal two-storey home with an office and two bedrooms.", ShapeClass::kTrapezoid},
      {"A villa with an angled wing: three bedrooms, a kitchen and a living room.", ShapeClass::kAngledWing},
      {"A cottage with a bay window, a kitchen, a bathroom and two bedrooms.", ShapeClass::kBay},
  };
  for (const auto& [text, shape] : cases) {
    INFO(text);
    PlanSummary plan = PlanLayout(text, options);
    REQUIRE(plan.valid());
    std::string unmet;
    for (const auto& u : plan.unmet) unmet += u.requirement + "; ";
    INFO("unmet: " << unmet);
    CHECK(ClassifyFootprint(*plan.layout, 0) == shape);
    CHECK(plan.outcome == PlanOutcome::kMet);
  }
}

TEST_CASE("requirements the partitioner cannot meet are reported, and the layout is still valid") {
  PlanOptions options;
  options.time_budget_s = 0.5;
  SECTION("a round footprint") {
    PlanSummary plan = PlanLayout("A round two-story villa with a kitchen and three bedrooms.", options);
    REQUIRE(plan.valid());
    CHECK(plan.outcome == PlanOutcome::kPartial);
    REQUIRE(plan.brief.unsupported_shape.has_value());
    CHECK(plan.brief.unsupported_shape->text == "round");
    bool reported = false;
    for (const auto& u : plan.unmet) reported |= u.requirement.find("round") != std::string::npos;
    CHECK(reported);
  }
  SECTION("more floors than the format allows") {
    PlanSummary plan = PlanLayout("A five-storey tower house with a kitchen.", options);
    REQUIRE(plan.valid());
    CHECK(plan.layout->LevelCount() == 3);
    CHECK(plan.outcome == PlanOutcome::kPartial);
    REQUIRE(!plan.brief.conflicts.empty());
    CHECK(plan.brief.conflicts[0].find("at most 3") != std::string::npos);
    REQUIRE(plan.unmet.size() >= 1);
    CHECK(plan.unmet[0].requirement == "5 floors");
    CHECK(plan.unmet[0].detail == "has 3");
  }
}

TEST_CASE("'upstairs' in a three-floor villa is met on the upper floors together") {
  PlanOptions options;
  options.time_budget_s = 2.0;
  PlanSummary plan = PlanLayout("A three-storey villa. Downstairs a living room and a kitchen; upstairs three bedrooms "
                                "and two bathrooms.", options);
  INFO(plan.BriefReport());
  REQUIRE(plan.valid());
  CHECK(plan.outcome == PlanOutcome::kMet);
  int upper_bedrooms = 0;
  for (const Room& r : plan.layout->rooms) upper_bedrooms += r.category == Category::kBedroom && r.level > 0;
  CHECK(upper_bedrooms == 3);
}

TEST_CASE("a brief that cannot be met stops the search once no variant does better, not at the time budget") {
  PlanOptions options;  // the default budget: 5 s, 4,000 attempts
  // Nine rooms on one floor: FORMAT.md allows six.
  PlanSummary plan = PlanLayout("Bungalow, 1 flr: liv rm, kit, din rm, 3 bdrm, 2 bthrm, office.", options);
  INFO(plan.BriefReport());
  REQUIRE(plan.valid());
  CHECK(plan.outcome == PlanOutcome::kPartial);
  CHECK_FALSE(plan.brief.conflicts.empty());
  CHECK(plan.attempts <= 12);  // one round of variants past the best (it ran all 4,000 before)
}

TEST_CASE("rooms on a named upper floor count toward an 'upstairs' requirement of their kind") {
  PlanOptions options;
  options.time_budget_s = 2.0;
  // "only the upstairs one" is the first floor's bathroom: one there, not a second one besides it.
  PlanSummary plan = PlanLayout("Three floors. Ground: kitchen, dining room, living room, bathroom. First: two bedrooms and a "
                                "second bathroom. Second: office and terrace. Both bathrooms with a bathtub... on second "
                                "thought only the upstairs one; the downstairs bathroom gets a shower instead.", options);
  INFO(plan.BriefReport());
  REQUIRE(plan.valid());
  CHECK(plan.outcome == PlanOutcome::kMet);
  CHECK(plan.brief.unparsed.empty());
  std::map<int, int> bathrooms;
  for (const Room& r : plan.layout->rooms) bathrooms[r.level] += r.category == Category::kBathroom;
  CHECK(bathrooms[0] == 1);
  CHECK(bathrooms[1] == 1);
  CHECK(bathrooms[2] == 0);
}

TEST_CASE("whole-building counts are spread over the floors without losing a room") {
  Brief brief = ParseBrief("A three-story villa with a living room, a kitchen, a dining room, four bedrooms, "
                           "two bathrooms, an office and two balconies.");
  PartitionOptions o = PartitionOptionsForBrief(brief, 3, true);
  DistributeRooms(o, 42);
  std::map<int, int> per_level;
  std::map<Category, int> per_category;
  for (const auto& r : o.rooms) {
    if (r.category == Category::kUtilityRoom) continue;
    REQUIRE(r.level >= 0);
    per_level[r.level] += r.count;
    per_category[r.category] += r.count;
    if (r.category == Category::kBalcony) CHECK(r.level > 0);
  }
  CHECK(per_category[Category::kBedroom] == 4);
  CHECK(per_category[Category::kBathroom] == 2);
  CHECK(per_category[Category::kBalcony] == 2);
  CHECK(per_category[Category::kLivingRoom] == 1);
  for (const auto& [level, n] : per_level) {
    CHECK(n >= 2);
    CHECK(n <= kMaxRoomsPerFloor - 1);
  }
}

}  // namespace villa

namespace villa {

TEST_CASE("villa eval --json on procedural prompts reports every prompt and the overall metrics") {
  auto dir = std::filesystem::temp_directory_path() / ("villa-eval-test-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  {
    std::ofstream prompts(dir / "p.jsonl");
    prompts << R"({"text": "A two-story L-shaped house with a kitchen open to the dining room and three bedrooms."})" << "\n"
            << R"({"id": "round", "text": "A round single-storey house with a garage."})" << "\n";
  }
  std::string command = std::string(VILLA_BINARY) + " eval " + (dir / "p.jsonl").string() + " --budget 1 --json > " +
                        (dir / "out.json").string();
  int status = std::system(command.c_str());
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  std::ifstream in(dir / "out.json");
  Json out = Json::parse(in);
  REQUIRE(out["prompts"].size() == 2);
  CHECK(out["prompts"][0]["outcome"] == "met");
  CHECK(out["prompts"][1]["outcome"] == "partial");
  CHECK(out["prompts"][1]["id"] == "round");
  CHECK(out["prompts"][1]["unparsed"] == Json::array({"garage"}));
  CHECK(out["overall"]["fsr"] == 1.0);
  CHECK(out["overall"]["rr"] == 1.0);
  CHECK(out["overall"]["brief_adherence"].get<double>() < 1.0);
  std::filesystem::remove_all(dir);
}

}  // namespace villa

namespace villa {

// The office villa of examples/prompts-scenes.jsonl once came out (seeds 5-7) with its 4 x 4 m staircase
// room holding a door on each of its four sides; the stair serves at most three, so the bathroom behind
// the fourth could not be entered (RCH 99.4 % on the prompt set). The search now prefers layouts without
// such a room: no utility room of these plans has an opening on every side of its box.
TEST_CASE("the procedural backend leaves a side of every staircase room without a door") {
  const std::string text =
      "A two-floor office villa: a meeting room and an office with a desk by the window, a kitchen and a bathroom "
      "on the ground floor; a meeting room, two offices and a bathroom upstairs. Put a TV in the meeting room.";
  for (std::uint64_t seed : {5u, 6u, 7u}) {
    PlanOptions options;
    options.seed = seed;
    PlanSummary plan = PlanLayout(text, options);
    INFO("seed " << seed << "\n" << plan.BriefReport());
    REQUIRE(plan.layout.has_value());
    CHECK(plan.valid());
    const Layout& layout = *plan.layout;
    REQUIRE(layout.LevelCount() == 2);
    for (const Room& room : layout.rooms) {
      if (room.category != Category::kUtilityRoom) continue;
      double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
      for (const Point& p : room.polygon) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
      std::set<int> sides;
      for (const auto* list : {&layout.entrances, &layout.doors, &layout.opens})
        for (const Element& e : *list) {
          if (!e.OnLevel(room.level)) continue;
          const double mx = (e.shape.a.x + e.shape.b.x) / 2, my = (e.shape.a.y + e.shape.b.y) / 2;
          const bool inside_x = mx > x0 - 0.05 && mx < x1 + 0.05, inside_y = my > y0 - 0.05 && my < y1 + 0.05;
          if (inside_y && std::abs(mx - x0) < 0.05) sides.insert(0);
          if (inside_y && std::abs(mx - x1) < 0.05) sides.insert(1);
          if (inside_x && std::abs(my - y0) < 0.05) sides.insert(2);
          if (inside_x && std::abs(my - y1) < 0.05) sides.insert(3);
        }
      INFO(room.name());
      CHECK(sides.size() < 4);
    }
  }
}

}  // namespace villa
