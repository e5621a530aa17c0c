// The brief parser on the annotator's drafted descriptions: a few hundred partitioner layouts, each
// described coarsely and finely in the annotator's styles; every requirement parsed from a description of
// a layout must be met by that layout, and the facts the drafter states must be read back.
#ifdef VILLA_HAVE_ANNOTATOR
#include <map>

#include <catch2/catch.hpp>

#include "annotator/describe.h"
#include "generator/text/brief.h"
#include "partitioner/partitioner.h"

namespace villa {

TEST_CASE("requirements parsed from drafted descriptions are met by the layout they describe") {
  int descriptions = 0, requirements = 0, with_unparsed = 0;
  std::map<std::string, int> unparsed_words;
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    PartitionOptions options;
    PartitionSummary layout = GenerateLayout(options, seed);
    REQUIRE(layout.ok());
    const std::string shape(ShapeClassName(layout.shape));
    annotator::Drafts drafts = annotator::DraftDescriptions(layout.layout, shape, seed);
    for (const auto& [text, facts] : {std::pair{drafts.coarse, drafts.coarse_facts}, std::pair{drafts.fine, drafts.fine_facts}}) {
      Brief brief = ParseBrief(text);
      BriefCheck check = CheckBrief(brief, layout.layout);
      INFO("seed " << seed << ": " << text << "\nbrief: " << BriefOneLine(brief));
      for (const auto& r : check.results) {
        INFO(r.requirement << " (" << r.detail << ") from \"" << r.source << "\"");
        CHECK(r.met);
      }
      // The stated floors, shape and counts are read back.
      for (const auto& fact : facts) {
        INFO(annotator::DescribeFact(fact));
        if (fact.kind == annotator::FactKind::kFloors) CHECK(brief.floors == fact.value);
        if (fact.kind == annotator::FactKind::kShape) {
          REQUIRE(brief.shape.has_value());
          CHECK(std::string(ShapeClassName(*brief.shape)) == fact.text);
        }
        if (fact.kind == annotator::FactKind::kCount) {
          bool found = false;
          for (const auto& r : brief.rooms)
            if (r.category == fact.category && r.level == kAnyLevel && r.min == fact.value && r.max == fact.value)
              found = true;
          CHECK(found);
        }
      }
      ++descriptions;
      requirements += check.total();
      if (!brief.unparsed.empty()) ++with_unparsed;
      for (const auto& u : brief.unparsed) ++unparsed_words[u.text];
    }
  }
  CHECK(descriptions == 400);
  CHECK(requirements >= 4 * descriptions);
  std::string words;
  for (const auto& [w, n] : unparsed_words) words += w + " (" + std::to_string(n) + ") ";
  INFO("not understood: " << words);
  CHECK(with_unparsed <= descriptions / 10);
}

}  // namespace villa
#endif
