// The data card's length statistics and the token estimate behind the configs' cutoff length.
#include <catch2/catch.hpp>

#include "finetune/export.h"

using namespace villa;

TEST_CASE("ApproxTokens counts digits and punctuation one by one and words by four letters", "[finetune][stats]") {
  CHECK(ApproxTokens("") == 0);
  CHECK(ApproxTokens("12") == 2);
  CHECK(ApproxTokens("hello world") == 4);  // 5 letters -> 2 tokens, twice
  CHECK(ApproxTokens("a, b") == 3);
  // shapely(2) .(1) box(1) ((1) 0(1) ,(1) 11(2) .(1) 5(1) ,(1) 4(1) ,(1) 15(2) .(1) 5(1) )(1)
  CHECK(ApproxTokens("shapely.box(0, 11.5, 4, 15.5)") == 19);
  CHECK(ApproxTokens("line\nbreak") == 1 + 1 + 2);
  // Never fewer than a character-per-four estimate for JSON answers: a cutoff from it does not truncate.
  const std::string answer = R"j({"rooms":{"kitchen_0/0":{"shape":"shapely.box(6, 0, 10, 3)"}}})j";
  CHECK(ApproxTokens(answer) >= answer.size() / 4);
}

TEST_CASE("Length statistics: min, median, mean, max", "[finetune][stats]") {
  LengthStats s = ComputeLengthStats({30, 10, 20, 40});
  CHECK(s.count == 4);
  CHECK(s.min == 10);
  CHECK(s.max == 40);
  CHECK(s.median == 20);  // the lower middle of an even count
  CHECK(s.mean == Approx(25.0));
  CHECK(ComputeLengthStats({}).count == 0);
  CHECK(ComputeLengthStats({7}).median == 7);
}
