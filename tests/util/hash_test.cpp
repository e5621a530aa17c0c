// The shared hashes against published reference values: a change here would change every seeded dataset.
#include <catch2/catch.hpp>

#include <string>

#include "util/hash.h"

using namespace villa;

TEST_CASE("SplitMix64 gives the reference stream", "[util][hash]") {
  // The first outputs of the reference splitmix64.c seeded with 1234567.
  SplitMix64 rng(1234567);
  CHECK(rng.Next() == 6457827717110365317ULL);
  CHECK(rng.Next() == 3203168211198807973ULL);
  CHECK(rng.Next() == 9817491932198370423ULL);
  // The hash is the first output of a stream seeded with its argument.
  CHECK(SplitMix64Hash(1234567) == 6457827717110365317ULL);
  static_assert(SplitMix64Hash(0) == 0xe220a8397b1dcdafULL);
}

TEST_CASE("SplitMix64 draws stay in their ranges", "[util][hash]") {
  SplitMix64 rng(7);
  int low = 0, high = 0;
  for (int i = 0; i < 2000; ++i) {
    const std::int64_t v = rng.Int(-3, 4);
    REQUIRE(v >= -3);
    REQUIRE(v <= 4);
    low += v == -3, high += v == 4;
    const double u = rng.Unit();
    REQUIRE(u >= 0.0);
    REQUIRE(u < 1.0);
  }
  CHECK(low > 150);  // both ends are drawn (about 250 each)
  CHECK(high > 150);
  CHECK(rng.Int(5, 5) == 5);
  CHECK(rng.Int(5, 2) == 5);
  const double weights[] = {0.0, 1.0, 0.0};
  for (int i = 0; i < 20; ++i) CHECK(rng.Weighted(weights, 3) == 1);
}

TEST_CASE("FNV-1a 64 gives the reference values and streams", "[util][hash]") {
  CHECK(Fnv1a64("") == kFnv1a64Offset);
  CHECK(Fnv1a64("a") == 0xaf63dc4c8601ec8cULL);
  CHECK(Fnv1a64("foobar") == 0x85944171f73967e8ULL);
  CHECK(Fnv1a64("bar", Fnv1a64("foo")) == Fnv1a64("foobar"));
  CHECK(Fnv1a64(std::string("\xff\x01", 2)) != Fnv1a64(std::string("\x01\xff", 2)));
}
