// Requests as people write them (issue 32): tests/fixtures/prompts/voices.jsonl, 477 requests in eight
// voices (terse lists, long emails, British and American floor naming, spec sheets, "each"/"per"
// distributions, ordinals, negations), numbers in words and digits, each with what it asks: floors, the
// footprint when named, the rooms of each kind (utility rooms aside) and, where pinned, per floor. One table:
// every request is planned offline and its layout compared with what it asks.
//
// The requests the planner does not yet read right are listed below with what goes wrong, so that the
// table holds the line: a request off the list that stops matching fails, and so does one on the list
// that starts to match (take it off). `kFalseMet` are those whose report still says "met": every other
// mismatch must be reported as partial.
#include <map>
#include <set>
#include <string>

#include <catch2/catch.hpp>

#include "generator/text/plan.h"
#include "layout/layout_io.h"

namespace villa {
namespace {

// Known gaps: id -> what the parser or planner gets wrong today.
const std::map<std::string, std::string>& KnownGaps() {
  static const std::map<std::string, std::string> gaps = {
      {"voices-012", "'1st - ... 2nd -' without 'floor' does not pin floors"},
      {"voices-037", "a correction ('scrap what I said') is not read as replacing the earlier floors"},
      {"voices-040", "'a bedroom with an en-suite, so that's three bedrooms and three en-suites' counted twice"},
      {"voices-091", "'the second floor is bedrooms, three of them'"},
      {"voices-124", "'Bathrooms: 2, one on each floor' read as two on each floor"},
      {"voices-136", "'two bedrooms on each of the upper floors, each pair sharing a bathroom'"},
      {"voices-143", "'each floor has its own bathroom and living room': the planner adds an office and a bedroom"},
      {"voices-145", "'each family gets a living room ..., one family per floor'"},
      {"voices-153", "'split evenly between the floors'"},
      {"voices-173", "'the first bedroom ..., and the second bedroom ...' as two rooms"},
      {"voices-182", "'another one on the top floor' ('one' for a bathroom)"},
      {"voices-190", "'not a fan of balconies so please leave them out'"},
      // 219-278: written by a helper that saw none of the corpus, as unseen requests for issue 32 (first
      // reading 96.3 % of their requirements and 2 false "met"; after the fixes of that stop 98.4 %, 0).
      {"voices-230", "'Two bedrooms, one of them a guest bedroom' counts the guest bedroom again; 'a west-facing terrace'"},
      {"voices-238", "spec 'storeys 2; NOTES: office on the ground floor, all bedrooms upstairs'"},
      {"voices-255", "'a family room and a separate living room': the dining room lost; '2.5 baths (two full baths plus a powder room)' read as 4"},
      // 279-318: written by a helper that saw none of the corpus and none of the code, as unseen requests for
      // issue 32 (ten of them first cut to the six rooms a floor FORMAT.md allows); first reading 90.8 % of
      // their requirements and 1 false "met"; after the fixes of that stop 99.5 %, 0.
      {"voices-299", "12 rooms on 2 floors: the planner finds no layout with the office and the balcony"},
      // 319-357: the third unseen set (a helper that saw nothing of the project wrote 48; the 39 within
      // FORMAT.md's floors and rooms a floor are here, storage rooms left out of the counts, a star read as
      // the cross class); first reading 84.0 % of their requirements and 4 false "met"; after the fixes of
      // that stop 95.2 %, 1.
      {"voices-330", "'a box room for storage' read as a bedroom"},
      {"voices-334", "'two-up two-down: lounge and kitchen on the ground floor, two bedrooms on the first floor'"},
      // 358-405: the fourth unseen set (a helper that saw nothing of the project wrote 48 within FORMAT.md,
      // six in each voice); first reading 97.4 % of their stated requirements (96.2 % counting each kind
      // the layout adds unasked as a miss), 1 false "met"; after the fixes of this stop 99.8 % (98.6 %).
      {"voices-395", "'half a dozen bedrooms ..., plus a kitchen and a lounge': the planner completes the house with rooms not named"},
      {"voices-401", "a single floor of bedrooms, a bathroom and a kitchen: the planner adds the living room not named"},
      // 406-441: the sixth unseen set (a helper that saw nothing of the project wrote 36 within FORMAT.md, six in
      // each of six voices, with 97 furnishing wishes); first reading 92.0 % of their 450 stated requirements
      // (counting each kind the layout adds unasked as a miss), 0 false "met"; after the fixes of that stop 100 %:
      // none is listed.
      // 442-477: the seventh unseen set (the same way, 36 requests with 94 wishes); first reading 92.6 % of their
      // 443 stated requirements, 0 false "met"; after the fixes of that stop these two are left.
      {"voices-467", "'The two upper floors are identical: 2 bedrooms, 1 bathroom and 1 balcony per floor - so 4 bedrooms ... in total'"},
      {"voices-477", "'Floor above that:' as a floor heading; 'bedrooms for the two founders' read with children's rooms"},
  };
  return gaps;
}

// Known gaps whose report still says "met" (the count check does not catch them: it reads the most a kind
// is named, never a sum).
const std::set<std::string>& KnownFalseMet() {
  // 395, 401: "met" for every room named, with rooms added that the text does not name (the strict count
  // of this table calls any kind added unasked a miss).
  static const std::set<std::string> ids = {"voices-395", "voices-401"};
  return ids;
}

std::map<std::string, int> Count(const Layout& layout, int level) {
  std::map<std::string, int> out;
  for (const Room& r : layout.rooms)
    if (r.category != Category::kUtilityRoom && (level < 0 || r.level == level)) ++out[std::string(CategoryName(r.category))];
  return out;
}

// What differs between the layout and what the request asks; empty when it matches.
std::string Mismatch(const Json& expect, const PlanSummary& plan) {
  if (!plan.layout) return "no layout";
  std::string out;
  auto note = [&](const std::string& s) { out += (out.empty() ? "" : "; ") + s; };
  const Layout& layout = *plan.layout;
  if (layout.LevelCount() != expect.at("floors").get<int>())
    note("floors " + std::to_string(layout.LevelCount()) + ", asked " + std::to_string(expect.at("floors").get<int>()));
  if (expect.contains("shape")) {
    const std::string asked = expect.at("shape").get<std::string>();
    const std::string read = plan.brief.shape ? std::string(ShapeClassName(*plan.brief.shape)) : "none";
    if (read != asked) note("shape " + read + ", asked " + asked);
  }
  std::map<std::string, int> asked;
  for (const auto& [category, n] : expect.at("rooms").items()) asked[category] = n.get<int>();
  const std::map<std::string, int> has = Count(layout, -1);
  std::set<std::string> kinds;
  for (const auto& [k, n] : asked) kinds.insert(k);
  for (const auto& [k, n] : has) kinds.insert(k);
  for (const std::string& k : kinds) {
    const int a = asked.count(k) ? asked.at(k) : 0, h = has.count(k) ? has.at(k) : 0;
    if (a != h) note(k + " " + std::to_string(h) + ", asked " + std::to_string(a));
  }
  if (expect.contains("levels"))
    for (const auto& [level, rooms] : expect.at("levels").items()) {
      const std::map<std::string, int> on = Count(layout, std::stoi(level));
      for (const auto& [k, n] : rooms.items()) {
        const int h = on.count(k) ? on.at(k) : 0;
        if (h != n.get<int>()) note(k + " on level " + level + " " + std::to_string(h) + ", asked " + std::to_string(n.get<int>()));
      }
    }
  return out;
}

}  // namespace

TEST_CASE("Requests in eight voices: every one off the known-gaps list is planned as asked, and none is a false met",
          "[generator][corpus]") {
  std::vector<std::pair<int, Json>> requests;
  const Status read = ReadJsonl(std::string(VILLA_FIXTURE_DIR) + "/prompts/voices.jsonl", [&](const Json& record, int line) {
    requests.push_back({line, record});
    return true;
  });
  REQUIRE(read.ok());
  REQUIRE(requests.size() >= 300);
  PlanOptions options;
  options.time_budget_s = 2.0;
  std::map<std::string, std::pair<int, int>> by_style;  // matched, total
  int matched = 0, false_met = 0;
  std::set<std::string> ids;
  for (const auto& [line, record] : requests) {
    const std::string id = record.at("id").get<std::string>();
    CHECK(ids.insert(id).second);  // ids are unique
    options.seed = static_cast<std::uint64_t>(line);
    const PlanSummary plan = PlanLayout(record.at("text").get<std::string>(), options);
    const std::string mismatch = Mismatch(record.at("expect"), plan);
    INFO(id << ": " << record.at("text").get<std::string>() << "\n" << plan.BriefReport() << "mismatch: " << mismatch);
    CHECK(plan.valid());
    auto& [ok, total] = by_style[record.at("style").get<std::string>()];
    ++total;
    const bool known = KnownGaps().count(id) > 0;
    if (mismatch.empty()) {
      ++matched, ++ok;
      CHECK_FALSE(known);  // it matches now: take it off the list
    } else {
      CHECK(known);
      const bool met = plan.outcome == PlanOutcome::kMet;
      false_met += met;
      CHECK(met == KnownFalseMet().count(id) > 0);
    }
  }
  std::string table = "style          matched\n";
  for (const auto& [style, counts] : by_style)
    table += style + std::string(15 - std::min<size_t>(14, style.size()), ' ') + std::to_string(counts.first) + "/" +
             std::to_string(counts.second) + "\n";
  table += "all            " + std::to_string(matched) + "/" + std::to_string(requests.size()) + ", false met " +
           std::to_string(false_met) + "\n";
  WARN(table);
  CHECK(by_style.size() >= 8);
  CHECK(matched == static_cast<int>(requests.size() - KnownGaps().size()));
}

}  // namespace villa

namespace villa {
namespace {

TEST_CASE("A plan reports the rooms it adds beyond the brief, and only those", "[generator][corpus]") {
  // voices-395: six bedrooms, a kitchen and a lounge on three floors; the planner fills the floors with more.
  PlanOptions options;
  options.seed = 1;
  const PlanSummary plan = PlanLayout("half a dozen bedrooms across three floors, plus a kitchen and a lounge on the ground floor.", options);
  REQUIRE(plan.layout);
  INFO(plan.BriefReport());
  REQUIRE_FALSE(plan.added.empty());
  int added = 0;
  for (const auto& [category, n] : plan.added) {
    CHECK(n > 0);
    CHECK(category != Category::kBedroom);  // as many as asked
    CHECK(category != Category::kKitchen);
    CHECK(category != Category::kUtilityRoom);
    added += n;
  }
  int rooms = 0;
  for (const Room& r : plan.layout->rooms) rooms += r.category != Category::kUtilityRoom;
  CHECK(rooms == 6 + 1 + 1 + added);
  CHECK(PlanReportJson(plan)["added"].size() == plan.added.size());
  CHECK(plan.BriefReport().find("added beyond the brief") != std::string::npos);
  // A brief that names no room adds nothing to report.
  CHECK(PlanLayout("a two-storey house", options).added.empty());
}

}  // namespace
}  // namespace villa
