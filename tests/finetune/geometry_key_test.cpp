// Geometry keys (what the export treats as one layout) and footprint classes.
#include <catch2/catch.hpp>

#include "finetune/geometry_key.h"
#include "finetune_test_util.h"
#include "util/hash.h"

using namespace villa;
using namespace villa::testing;

namespace {
Layout Rooms(const std::vector<Ring>& rings, int level = 0) {
  Layout layout;
  int index = 0;
  for (const auto& ring : rings) layout.rooms.push_back({Category::kRoom, level, index++, ring});
  return layout;
}
Ring Box(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }
}  // namespace

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

TEST_CASE("The footprint outline is the union of the rooms", "[finetune][geometry]") {
  const Layout one = LoadFixture("one_floor.json");
  Ring outline = FootprintOutline(one, 0);
  REQUIRE(outline.size() == 6);
  CHECK(Area(outline) == Approx(68.0));  // 10 x 6 plus the 4 x 2 wing
  CHECK(SignedArea(outline) > 0);
  const Layout two = LoadFixture("two_floors.json");
  CHECK(Area(FootprintOutline(two, 0)) == Approx(96.0));
  CHECK(Area(FootprintOutline(two, 1)) == Approx(64.0));
  CHECK(FootprintOutline(two, 2).empty());
  // Rooms that leave a hole have no single outline.
  CHECK(FootprintOutline(Rooms({Box(0, 0, 3, 1), Box(0, 2, 3, 3), Box(0, 1, 1, 2), Box(2, 1, 3, 2)}), 0).empty());
}

TEST_CASE("Footprints are classed as the paper names them", "[finetune][geometry]") {
  CHECK(ClassifyFootprint(Rooms({Box(0, 0, 4, 4), Box(4, 0, 8, 4)})) == "rectangle");
  CHECK(ClassifyFootprint(LoadFixture("one_floor.json")) == "L");
  CHECK(ClassifyFootprint(LoadFixture("two_floors.json")) == "rectangle");
  CHECK(ClassifyFootprint(Rooms({Box(0, 0, 2, 4), Box(2, 0, 4, 2), Box(4, 0, 6, 4)})) == "U");
  CHECK(ClassifyFootprint(Rooms({Box(0, 2, 6, 4), Box(2, 0, 4, 2)})) == "T");
  CHECK(ClassifyFootprint(Rooms({Box(0, 0, 2, 6), Box(2, 2, 4, 4), Box(4, 0, 6, 6)})) == "H");
  // Two notches in the same side: not an H.
  CHECK(ClassifyFootprint(Rooms({Box(0, 0, 2, 6), Box(2, 0, 4, 4), Box(4, 0, 6, 6), Box(6, 0, 8, 4), Box(8, 0, 10, 6)})) == "irregular");
  // Two opposite corners cut: a step, not a T.
  CHECK(ClassifyFootprint(Rooms({Box(0, 0, 4, 2), Box(0, 2, 6, 4), Box(2, 4, 6, 6)})) == "irregular");
  CHECK(ClassifyFootprint(Rooms({Ring{{0, 0}, {6, 0}, {6, 4}, {2, 4}}})) == "irregular");  // a slanted edge
  CHECK(ClassifyFootprint(Layout{}) == "none");
}
