// The independent room count of a request (generator/text/recount.h, issue 32): what it reads from the
// phrases people write, what it leaves out, and that a plan whose layout has fewer rooms than it reads is
// never reported as met.
#include <map>
#include <string>

#include <catch2/catch.hpp>

#include "generator/text/plan.h"
#include "generator/text/recount.h"

namespace villa {
namespace {

std::map<std::string, int> Counts(const std::string& text, int floors) {
  std::map<std::string, int> out;
  for (const RoomRecount& r : RecountRooms(text, floors)) out[std::string(CategoryName(r.category))] = r.count;
  return out;
}

}  // namespace

TEST_CASE("The recount reads numbers in words and digits, articles and bare singulars in lists", "[generator][recount]") {
  using M = std::map<std::string, int>;
  CHECK(Counts("Four bedrooms, 2 bathrooms and a kitchen.", 2) == M{{"bedroom", 4}, {"bathroom", 2}, {"kitchen", 1}});
  CHECK(Counts("kitchen, lounge, 3 guest rooms, WC, 2 kids' rooms and 2 terraces", 2) ==
        M{{"kitchen", 1}, {"living-room", 1}, {"bedroom", 3}, {"bathroom", 1}, {"children-room", 2}, {"balcony", 2}});
  CHECK(Counts("a two-bedroom cottage with a couple of offices", 1) == M{{"bedroom", 2}, {"office", 2}});
  CHECK(Counts("an open-plan kitchen and a large sunny sitting room", 1) == M{{"kitchen", 1}, {"living-room", 1}});
  // A bare plural gives no number.
  CHECK(Counts("bedrooms upstairs", 2).empty());
}

TEST_CASE("The recount distributes: each with, on each floor, per bedroom, a second and another", "[generator][recount]") {
  using M = std::map<std::string, int>;
  CHECK(Counts("Four bedrooms upstairs, each with an en-suite bathroom.", 2) == M{{"bedroom", 4}, {"bathroom", 4}});
  CHECK(Counts("Three bedrooms; each bedroom has its own balcony.", 2) == M{{"bedroom", 3}, {"balcony", 3}});
  CHECK(Counts("A kitchen, a bathroom on each floor, and a second bedroom.", 3) == M{{"kitchen", 1}, {"bathroom", 3}, {"bedroom", 2}});
  CHECK(Counts("three bedrooms and a balcony per bedroom", 2) == M{{"bedroom", 3}, {"balcony", 3}});
  CHECK(Counts("a study on both floors", 2) == M{{"office", 2}});
  // The floors named before the verb: "both upper floors get a balcony", "each floor has a bathroom".
  CHECK(Counts("Three floors. Both upper floors get a balcony.", 3) == M{{"balcony", 2}});
  CHECK(Counts("Two floors; each floor has a bathroom.", 2) == M{{"bathroom", 2}});
  CHECK(Counts("a bathroom on both upper floors", 3) == M{{"bathroom", 2}});
  CHECK(Counts("Three floors with a bathroom on each one.", 3) == M{{"bathroom", 3}});
  CHECK(Counts("Floors: 2. Bedrooms: 3. Bathrooms (2), offices x2", 2) == M{{"bedroom", 3}, {"bathroom", 2}, {"office", 2}});
  CHECK(Counts("a living room and another living room for the kids", 2) == M{{"living-room", 2}});
  // An ordinal of a floor is no count: "a second-floor bedroom" is one bedroom.
  CHECK(Counts("a second-floor bedroom and a third floor office", 3) == M{{"bedroom", 1}, {"office", 1}});
}

TEST_CASE("The recount leaves out negations and references", "[generator][recount]") {
  using M = std::map<std::string, int>;
  CHECK(Counts("Two bedrooms, no dining room, without a balcony, and I don't want a study.", 2) == M{{"bedroom", 2}});
  CHECK(Counts("No need for a balcony. We want neither a study nor a dining room. Kitchen not needed. One lounge.", 2) ==
        M{{"living-room", 1}});
  // A floor's number or ordinal is not the room's: "level 3 - office", "2nd - office".
  CHECK(Counts("Level 3 \u2013 office; 2nd - bedroom, 1st - kitchen", 3) == M{{"office", 1}, {"bedroom", 1}, {"kitchen", 1}});
  CHECK(Counts("Put a TV in one of the bedrooms; the kitchen should be bright and its balcony large.", 2).empty());
  // Within a sentence a list's rooms add up; a later sentence naming them again does not.
  CHECK(Counts("a lounge, a separate sitting room and a kitchen", 1) == M{{"living-room", 2}, {"kitchen", 1}});
  CHECK(Counts("two bedrooms, including a master bedroom, and a bathroom and another one upstairs", 2) ==
        M{{"bedroom", 2}, {"bathroom", 2}});
  CHECK(Counts("no bathroom upstairs; put both bathrooms on the ground floor", 2) == M{{"bathroom", 2}});
  CHECK(Counts("3 bedrooms, 2 of which have en-suites", 2) == M{{"bedroom", 3}, {"bathroom", 2}});
  // A kind named in two sentences counts as the most one of them reads, not the sum.
  CHECK(Counts("three bedrooms. The largest bedroom faces south; a bedroom upstairs has a view.", 2) == M{{"bedroom", 3}});
}

TEST_CASE("A layout with fewer rooms than the recount reads is never met, and the report names the phrase",
          "[generator][recount]") {
  // The layout of a plan for one bathroom, checked against a text that asks for one on each of two floors.
  PlanOptions options;
  options.seed = 3;
  PlanSummary plan = PlanLayout("A two-story house with a kitchen, a living room, two bedrooms and a bathroom.", options);
  REQUIRE(plan.valid());
  REQUIRE(plan.layout.has_value());
  int bathrooms = 0;
  for (const Room& r : plan.layout->rooms) bathrooms += r.category == Category::kBathroom;
  const std::vector<RecountDisagreement> off =
      CheckRecount("A two-story house with a kitchen, a living room, two bedrooms and a bathroom on each floor.", *plan.layout);
  REQUIRE(bathrooms == 1);
  REQUIRE(off.size() == 1);
  CHECK(off[0].category == Category::kBathroom);
  CHECK(off[0].asked == 2);
  CHECK(off[0].has == 1);
  CHECK(off[0].Message() == "the text may ask for 2 bathrooms (\"a bathroom on each floor\"); the layout has 1");
  // A kind named once with a number of two or more is an exact count: a layout with more has misread it too;
  // named twice, it is not.
  PlanSummary four = PlanLayout("A two-story house with a kitchen, a living room, four bedrooms and two bathrooms.", options);
  REQUIRE(four.valid());
  int bedrooms = 0;
  for (const Room& r : four.layout->rooms) bedrooms += r.category == Category::kBedroom;
  REQUIRE(bedrooms == 4);
  const std::vector<RecountDisagreement> over =
      CheckRecount("A two-story house with a kitchen, a living room, three bedrooms and two bathrooms.", *four.layout);
  REQUIRE(over.size() == 1);
  CHECK(over[0].exact);
  CHECK(over[0].Message() == "the text may ask for exactly 3 bedrooms (\"three bedrooms\"); the layout has 4");
  CHECK(CheckRecount("A two-story house with a kitchen, a living room, three bedrooms and two bathrooms. "
                     "A bedroom upstairs has a balcony.", *four.layout).empty() == false);  // the balcony is missing
  for (const RecountDisagreement& d : CheckRecount("Three bedrooms. A kitchen, a living room, a bedroom upstairs and "
                                                   "two bathrooms.", *four.layout))
    CHECK(d.category != Category::kBedroom);  // bedrooms named twice: at least three, not exactly
  // The plan itself agrees with its own recount: met, and nothing in its count check.
  CHECK(plan.recount.empty());
  CHECK(plan.outcome == PlanOutcome::kMet);
  const auto json = PlanReportJson(plan);
  CHECK(json.at("count_check").empty());
}

}  // namespace villa
