// Geometry keys (what the export treats as one layout) and the split hash.
#include <catch2/catch.hpp>

#include "finetune/geometry_key.h"
#include "finetune_test_util.h"
#include "util/hash.h"

using namespace villa;
using namespace villa::testing;

TEST_CASE("The geometry key ignores names and labels but not geometry", "[finetune][geometry]") {
  const Layout two = LoadFixture("two_floors.json");
  Layout relabelled = two;
  relabelled.rooms[6].category = Category::kOffice;  // bedroom_1/0 -> office_1/0
  relabelled.doors[0].name = "some other name";
  std::reverse(relabelled.windows.begin(), relabelled.windows.end());
  std::swap(relabelled.interiors[0].shape.a, relabelled.interiors[0].shape.b);
  CHECK(GeometryKey(relabelled) == GeometryKey(two));

  Layout moved_door = two;
  moved_door.doors[0].shape.a.x += 0.5, moved_door.doors[0].shape.b.x += 0.5;
  CHECK(GeometryKey(moved_door) != GeometryKey(two));
  Layout panoramic = two;
  panoramic.windows[0].panoramic = true;
  CHECK(GeometryKey(panoramic) != GeometryKey(two));
  CHECK(GeometryKey(Moved(two, 0.01, 0)) != GeometryKey(two));
}

TEST_CASE("StableHash is fixed across machines", "[finetune][geometry]") {
  // Values pinned: a change here would reshuffle every committed split.
  CHECK(StableHash("") == SplitMix64Hash(kFnv1a64Offset));
  CHECK(StableHash("villa") == StableHash(std::string("vil") + "la"));
  CHECK(StableHash("villa") != StableHash("villb"));
  CHECK(SplitMix64Hash(0) == 0xe220a8397b1dcdafULL);
}
