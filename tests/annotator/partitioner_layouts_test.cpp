// The drafter and the fixes on what `villa synth` really makes: partitioner layouts of every footprint
// class and floor count. Built when the partitioner is in the build (tests/annotator/extra.cmake).
#ifdef VILLA_TEST_WITH_PARTITIONER
#include <catch2/catch.hpp>

#include <algorithm>

#include "annotator/describe.h"
#include "annotator/fixes.h"
#include "annotator/relabel.h"
#include "layout/footprint.h"
#include "layout/topology.h"
#include "layout/validate.h"
#include "partitioner/partitioner.h"
#include "synthesized_layouts.h"

using namespace villa;
using namespace villa::annotator;

// Checks of facts against a layout, shared with describe_test.cpp.
std::string CheckDescriptionFact(const Layout& l, const std::string& shape, const Fact& f);

TEST_CASE("drafts of partitioner layouts state only true facts", "[describe][partitioner]") {
  const int layouts = testing::ForEachSynthesizedLayout(4, 7919, [](const Layout& layout, const std::string& what) {
    const std::string shape = what.substr(0, what.find(' '));
    for (std::uint64_t draft = 0; draft < 6; ++draft) {
      Drafts d = DraftDescriptions(layout, shape, draft);
      for (const auto* facts : {&d.coarse_facts, &d.fine_facts})
        for (const Fact& f : *facts) {
          INFO(what << ": " << DescribeFact(f) << "\n" << d.fine);
          CHECK(CheckDescriptionFact(layout, shape, f) == "");
        }
    }
  });
  CHECK(layouts >= 60);
}

TEST_CASE("relabelling partitioner layouts and fixing them keeps them valid where a fix exists", "[fixes][partitioner]") {
  int fixed_count = 0;
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    PartitionOptions options;
    PartitionSummary summary = GenerateLayout(options, seed);
    if (!summary.ok()) continue;
    Layout l = summary.layout;
    // Turn the first room with a window that is not a kitchen into a bathroom, and a bathroom into a
    // kitchen when one has no window: the fixes must leave no rule-9 violation of the relabelled rooms.
    for (int r = 0; r < static_cast<int>(l.rooms.size()); ++r) {
      if (l.rooms[r].category != Category::kBedroom) continue;
      bool has_window = false;  // an inner bedroom has no exterior wall a window fix could use
      for (const Element& w : l.windows)
        has_window |= w.OnLevel(l.rooms[r].level) &&
                      PointOnBoundary({(w.shape.a.x + w.shape.b.x) / 2, (w.shape.a.y + w.shape.b.y) / 2}, l.rooms[r].polygon, 1e-6);
      if (!has_window) continue;
      RelabelRoom(l, r, Category::kBathroom);
      break;
    }
    ApplyAllFixes(l);
    for (const Violation& v : ValidateLayout(l).violations) {
      INFO("seed " << seed << ": rule " << v.rule << ": " << v.message);
      CHECK(v.message.find("has no window") == std::string::npos);
    }
    ++fixed_count;
  }
  CHECK(fixed_count >= 25);
}

// Every fix FindFixes offers repairs a violation ValidateLayout reports: its rule, naming its room. Fresh
// layouts (valid: no fix at all) and the same layouts with rooms relabelled (kitchens, bathrooms,
// balconies, dining rooms where there were none) so that rules 9 and 10 break in many ways.
TEST_CASE("the fixes agree with the validator on synthesized layouts", "[fixes][partitioner]") {
  int offered = 0;
  auto check = [&](const Layout& l, const std::string& what) {
    const std::vector<Violation> violations = ValidateLayout(l).violations;
    for (const Fix& fix : FindFixes(l)) {
      ++offered;
      bool matched = false;
      for (const Violation& v : violations)
        matched = matched || (v.rule == fix.rule && std::find(v.elements.begin(), v.elements.end(), fix.room) != v.elements.end());
      INFO(what << ": fix \"" << fix.title << "\" (rule " << fix.rule << ") but the validator reports no rule-" << fix.rule
                << " violation of " << fix.room);
      CHECK(matched);
    }
  };
  const Category relabels[] = {Category::kKitchen, Category::kBathroom, Category::kBalcony, Category::kDiningRoom};
  const int layouts = testing::ForEachSynthesizedLayout(3, 104729, [&](const Layout& layout, const std::string& what) {
    CHECK(FindFixes(layout).empty());  // a valid layout needs none
    for (Category to : relabels)
      for (int r = 0; r < static_cast<int>(layout.rooms.size()); r += 2) {
        Layout l = layout;
        if (l.rooms[r].category == to || l.rooms[r].category == Category::kUtilityRoom) continue;
        RelabelRoom(l, r, to);
        check(l, what + " room " + std::to_string(r) + " made " + std::string(CategoryName(to)));
      }
  });
  CHECK(layouts >= 40);
  CHECK(offered >= 100);  // the relabelled layouts do need fixes
}
#endif
