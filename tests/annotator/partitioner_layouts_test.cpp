// The drafter and the fixes on what `villa synth` really makes: partitioner layouts of every footprint
// class and floor count. Built when the partitioner is in the build (tests/annotator/extra.cmake).
#ifdef VILLA_TEST_WITH_PARTITIONER
#include <catch2/catch.hpp>

#include "annotator/describe.h"
#include "annotator/fixes.h"
#include "annotator/relabel.h"
#include "layout/topology.h"
#include "layout/validate.h"
#include "partitioner/partitioner.h"

using namespace villa;
using namespace villa::annotator;

// Checks of facts against a layout, shared with describe_test.cpp.
std::string CheckDescriptionFact(const Layout& l, const std::string& shape, const Fact& f);

TEST_CASE("drafts of partitioner layouts state only true facts", "[describe][partitioner]") {
  int layouts = 0;
  for (ShapeClass shape : AllShapeClasses()) {
    for (int floors = 1; floors <= 3; ++floors) {
      for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        PartitionOptions options;
        options.shape = shape;
        options.floors = floors;
        PartitionSummary summary = GenerateLayout(options, seed * 7919 + floors);
        if (!summary.ok()) continue;
        ++layouts;
        std::string name(ShapeClassName(shape));
        for (std::uint64_t draft = 0; draft < 6; ++draft) {
          Drafts d = DraftDescriptions(summary.layout, name, draft);
          for (const auto* facts : {&d.coarse_facts, &d.fine_facts})
            for (const Fact& f : *facts) {
              INFO(name << " floors " << floors << " seed " << seed << ": " << DescribeFact(f) << "\n" << d.fine);
              CHECK(CheckDescriptionFact(summary.layout, name, f) == "");
            }
        }
      }
    }
  }
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
#endif
