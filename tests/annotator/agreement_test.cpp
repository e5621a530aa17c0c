// Agreement figures (kappa against worked examples) and the categories a description names.
#include <cmath>

#include <catch2/catch.hpp>

#include "annotator/agreement.h"
#include "annotator/mentions.h"
#include "test_support.h"

using namespace villa;
using namespace villa::annotator;

namespace {

// 50 items rated yes (1) / no (0): both yes 20, only the first yes 5, only the second yes 10, both no 15.
std::vector<std::pair<int, int>> TextbookPairs() {
  std::vector<std::pair<int, int>> pairs;
  for (int i = 0; i < 20; ++i) pairs.push_back({1, 1});
  for (int i = 0; i < 5; ++i) pairs.push_back({1, 0});
  for (int i = 0; i < 10; ++i) pairs.push_back({0, 1});
  for (int i = 0; i < 15; ++i) pairs.push_back({0, 0});
  return pairs;
}

}  // namespace

TEST_CASE("kappa: Cohen's and Fleiss' (Scott's pi) on a worked example", "[agreement]") {
  auto pairs = TextbookPairs();
  // p_o = 35/50 = 0.7. Cohen: p_e = 0.5 * 0.6 + 0.5 * 0.4 = 0.5, kappa = 0.4.
  CHECK(Kappa(pairs, 2, false) == Approx(0.4));
  // Pooled: yes share 55/100, p_e = 0.55^2 + 0.45^2 = 0.505, pi = 0.195 / 0.495.
  CHECK(Kappa(pairs, 2, true) == Approx(0.195 / 0.495));
  // Perfect agreement over two categories is 1; one category throughout is undefined.
  CHECK(Kappa({{0, 0}, {1, 1}}, 2, false) == Approx(1.0));
  CHECK(std::isnan(Kappa({{1, 1}, {1, 1}}, 2, false)));
  CHECK(std::isnan(Kappa({}, 2, false)));
  // Systematic disagreement is below zero.
  CHECK(Kappa({{0, 1}, {1, 0}}, 2, false) < 0);
}

TEST_CASE("agreement per pair of annotators and pooled, rooms matched by outline", "[agreement]") {
  Layout a = test::FixtureLayout("villa-000000");
  Layout relabelled = a;
  int bedroom = relabelled.FindRoom("bedroom_0/0");
  REQUIRE(bedroom >= 0);
  relabelled.rooms[bedroom].category = Category::kOffice;
  std::vector<std::vector<Rating>> ratings = {
      {{"alice", true, a}, {"bob", true, relabelled}},  // both accept, one room differs
      {{"bob", false, a}, {"alice", true, a}},          // decisions differ (order does not matter)
      {{"carol", false, a}, {"alice", false, a}},       // agree on rejecting
      {{"alice", true, a}},                             // rated once: not counted
  };
  Agreement g = ComputeAgreement(ratings);
  REQUIRE(g.pairs.size() == 2);
  CHECK(g.pairs[0].who == "alice / bob");
  CHECK(g.pairs[0].layouts == 2);
  CHECK(g.pairs[0].decisions_agreed == 1);
  CHECK(g.pairs[0].rooms == static_cast<int>(a.rooms.size()));
  CHECK(g.pairs[0].rooms_agreed == static_cast<int>(a.rooms.size()) - 1);
  CHECK(g.pairs[1].who == "alice / carol");
  CHECK(g.pairs[1].layouts == 1);
  CHECK(g.pairs[1].decisions_agreed == 1);
  CHECK(g.pairs[1].rooms == 0);  // nobody accepted it: its labels are not compared
  CHECK(g.all.layouts == 3);
  CHECK(g.all.decisions_agreed == 2);
  CHECK(g.all.decision_agreement() == Approx(2.0 / 3));
  // Decisions: (1,1) (1,0) (0,0) pooled: yes share 3/6, p_e = 0.5, p_o = 2/3, kappa = 1/3.
  CHECK(g.all.decision_kappa == Approx(1.0 / 3));
}

TEST_CASE("the categories a description names, and those the layout no longer has", "[mentions]") {
  auto named = CategoriesNamed("I'd like a lounge, two bedrooms, a kids’ room and a study; no balcony, without an office.");
  CHECK(named == std::vector<Category>{Category::kLivingRoom, Category::kBedroom, Category::kChildrenRoom, Category::kOffice});
  CHECK(CategoriesNamed("A WC upstairs and an open-plan Kitchen.") ==
        std::vector<Category>{Category::kKitchen, Category::kBathroom});
  // Words inside other words are not rooms.
  CHECK(CategoriesNamed("officers studying the balconyless bedroomish plan").empty());
  Layout layout = test::FixtureLayout("villa-000000");  // living, kitchen, dining, bedroom, bathroom
  CHECK(CategoriesNamedButMissing("A bedroom, a kitchen and a dining room.", layout).empty());
  CHECK(CategoriesNamedButMissing("A bedroom, an office and a balcony.", layout) ==
        std::vector<Category>{Category::kOffice, Category::kBalcony});
}
