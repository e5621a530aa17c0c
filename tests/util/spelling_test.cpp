// util/spelling.h: one edit apart, the words worth correcting, and the one name a misspelling means.
#include <catch2/catch.hpp>

#include "util/spelling.h"

using namespace villa;

TEST_CASE("One edit apart: a letter changed, left out, added or two swapped, but not equal words nor two edits", "[util][spelling]") {
  CHECK(OneEditApart("bedroms", "bedrooms"));   // left out
  CHECK(OneEditApart("dinning", "dining"));     // one too many
  CHECK(OneEditApart("wardorbe", "wardrobe"));  // swapped
  CHECK(OneEditApart("bathroam", "bathroom"));  // changed
  CHECK_FALSE(OneEditApart("bathroom", "bathroom"));
  CHECK_FALSE(OneEditApart("wradorbe", "wardrobe"));  // two edits
  CHECK_FALSE(OneEditApart("desk", "desks s"));
}

TEST_CASE("A misspelling means the one name it is near, the plural where that is meant, nothing when two are near",
          "[util][spelling]") {
  const std::vector<std::string> names = {"bookcase", "wardrobe", "dishwasher", "dresser"};
  CHECK(OneEditFrom("dishwaser", names) == std::optional<std::string>("dishwasher"));
  CHECK(OneEditFrom("bookcaes", names) == std::optional<std::string>("bookcases"));  // near both, ends in s
  CHECK(OneEditFrom("wardrobs", names) == std::optional<std::string>("wardrobes"));
  CHECK_FALSE(OneEditFrom("cupboard", names).has_value());
  CHECK_FALSE(OneEditFrom("bead", {"bed", "bear"}).has_value());  // near two names
  CHECK(MaybeMisspeltNoun("dishwaser"));
  CHECK_FALSE(MaybeMisspeltNoun("dressed"));
  CHECK_FALSE(MaybeMisspeltNoun("starting"));
  CHECK_FALSE(MaybeMisspeltNoun("desks"));  // too short to guess at
}
