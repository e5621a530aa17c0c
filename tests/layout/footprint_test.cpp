// The one footprint routine (FootprintOf / LevelFootprint) and the one footprint classifier.
#include <catch2/catch.hpp>

#include "layout/footprint.h"
#include "layout/layout_io.h"

using namespace villa;

namespace {
Layout Rooms(const std::vector<Ring>& rings, int level = 0) {
  Layout layout;
  int index = 0;
  for (const auto& ring : rings) layout.rooms.push_back({Category::kRoom, level, index++, ring});
  return layout;
}
Ring Box(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }
Layout Load(const std::string& name) {
  auto layout = LoadLayout(std::string(VILLA_FIXTURE_DIR) + "/finetune/" + name);
  REQUIRE(layout.ok());
  return *layout;
}
double TotalArea(const std::vector<PolygonWithHoles>& polygons) {
  double area = 0;
  for (const auto& p : polygons) {
    area += Area(p.outer);
    for (const Ring& h : p.holes) area -= Area(h);
  }
  return area;
}
}  // namespace

TEST_CASE("The footprint of a level is the union of its rooms, corners only", "[layout][footprint]") {
  const Layout one = Load("one_floor.json");
  auto footprint = LevelFootprint(one, 0);
  REQUIRE(footprint.size() == 1);
  CHECK(footprint[0].outer.size() == 6);  // an L: the rooms' collinear corners are gone
  CHECK(footprint[0].holes.empty());
  CHECK(SignedArea(footprint[0].outer) == Approx(68.0));  // 10 x 6 plus the 4 x 2 wing, counter-clockwise
  const Layout two = Load("two_floors.json");
  CHECK(TotalArea(LevelFootprint(two, 0)) == Approx(96.0));
  CHECK(TotalArea(LevelFootprint(two, 1)) == Approx(64.0));
  CHECK(LevelFootprint(two, 2).empty());
}

TEST_CASE("A courtyard comes out as a hole of the outline", "[layout][footprint]") {
  auto footprint = LevelFootprint(Rooms({Box(0, 0, 3, 1), Box(0, 2, 3, 3), Box(0, 1, 1, 2), Box(2, 1, 3, 2)}), 0);
  REQUIRE(footprint.size() == 1);
  CHECK(Area(footprint[0].outer) == Approx(9.0));
  REQUIRE(footprint[0].holes.size() == 1);
  CHECK(SignedArea(footprint[0].holes[0]) == Approx(1.0));  // counter-clockwise like every ring
}

TEST_CASE("A subtracted ring leaves the terrace around it", "[layout][footprint]") {
  // The upper floor covers the middle of the lower one's south side: the terrace is a U around it.
  const Ring lower = Box(0, 0, 10, 8), upper = Box(3, 0, 7, 5);
  auto terrace = FootprintOf({lower, upper}, kTolerance, {false, true});
  REQUIRE(terrace.size() == 1);
  CHECK(terrace[0].holes.empty());
  CHECK(terrace[0].outer.size() == 8);
  CHECK(SignedArea(terrace[0].outer) == Approx(80.0 - 20.0));
  // Inside without touching: a hole.
  auto ring = FootprintOf({lower, Box(3, 2, 7, 5)}, kTolerance, {false, true});
  REQUIRE(ring.size() == 1);
  REQUIRE(ring[0].holes.size() == 1);
  CHECK(TotalArea(ring) == Approx(68.0));
  // Two terraces touching at a point come out as two simple outlines.
  const Ring diamond{{5, 0}, {10, 4}, {5, 8}, {0, 4}};
  auto corners = FootprintOf({lower, diamond}, kTolerance, {false, true});
  CHECK(corners.size() == 4);
  for (const auto& p : corners) CHECK(p.outer.size() == 3);
  CHECK(TotalArea(corners) == Approx(40.0));
}

TEST_CASE("Footprints are classed as the paper names them", "[layout][footprint]") {
  auto shape = [](const Layout& l) { return std::string(ShapeClassName(ClassifyFootprint(l).value())); };
  CHECK(shape(Rooms({Box(0, 0, 4, 4), Box(4, 0, 8, 4)})) == "rectangle");
  CHECK(shape(Load("one_floor.json")) == "L");
  CHECK(shape(Load("two_floors.json")) == "rectangle");
  CHECK(shape(Rooms({Box(0, 0, 10, 5), Box(0, 5, 5, 10)})) == "L");
  CHECK(shape(Rooms({Box(0, 0, 2, 4), Box(2, 0, 4, 2), Box(4, 0, 6, 4)})) == "U");
  CHECK(shape(Rooms({Box(0, 0, 12, 4), Box(0, 4, 4, 10), Box(8, 4, 12, 10)})) == "U");
  CHECK(shape(Rooms({Box(0, 2, 6, 4), Box(2, 0, 4, 2)})) == "T");
  CHECK(shape(Rooms({Box(0, 0, 2, 6), Box(2, 2, 4, 4), Box(4, 0, 6, 6)})) == "H");
  // Two notches in the same side: not an H.
  CHECK(shape(Rooms({Box(0, 0, 2, 6), Box(2, 0, 4, 4), Box(4, 0, 6, 6), Box(6, 0, 8, 4), Box(8, 0, 10, 6)})) == "irregular");
  // Two opposite corners cut: a step, not a T.
  CHECK(shape(Rooms({Box(0, 0, 4, 2), Box(0, 2, 6, 4), Box(2, 4, 6, 6)})) == "irregular");
  // Slanted outside edges that make no named class (a gable of slope 1:3): irregular.
  CHECK(shape(Rooms({Ring{{0, 0}, {6, 0}, {6, 4}, {3, 5}, {0, 4}}})) == "irregular");
  // A slanted wall between two rooms of a rectangle is not a slanted footprint.
  CHECK(shape(Rooms({Ring{{0, 0}, {6, 0}, {4, 10}, {0, 10}}, Ring{{6, 0}, {10, 0}, {10, 10}, {4, 10}}})) == "rectangle");
  // A courtyard: irregular.
  CHECK(shape(Rooms({Box(0, 0, 3, 1), Box(0, 2, 3, 3), Box(0, 1, 1, 2), Box(2, 1, 3, 2)})) == "irregular");
  CHECK_FALSE(ClassifyFootprint(Layout{}).has_value());
  CHECK_FALSE(ClassifyFootprint(Rooms({Box(0, 0, 4, 4)}, 1), 0).has_value());
}

TEST_CASE("Shape class names parse back", "[layout][footprint]") {
  for (ShapeClass s : AllShapeClasses()) CHECK(ParseShapeClass(ShapeClassName(s)) == s);
  CHECK(ParseShapeClass("l") == ShapeClass::kL);
  CHECK(ParseShapeClass("octagon") == ShapeClass::kOctagon);
  CHECK(ParseShapeClass("angled-wing") == ShapeClass::kAngledWing);
  CHECK_FALSE(ParseShapeClass("star").has_value());
  CHECK_FALSE(ParseShapeClass("Hexagon").has_value());
}

TEST_CASE("Polygonal footprints are classed by their sides and corners", "[layout][footprint]") {
  auto shape = [](const Layout& l) { return std::string(ShapeClassName(ClassifyFootprint(l).value())); };
  // A near-regular hexagon (slopes 7:4, corners 120 and 121 degrees), split into three rooms.
  const Ring left{{4, 0}, {8, 0}, {8, 14}, {4, 14}, {0, 7}}, mid = Box(8, 0, 12, 14), right{{12, 0}, {16, 0}, {20, 7}, {16, 14}, {12, 14}};
  CHECK(shape(Rooms({left, mid, right})) == "hexagon");
  // A rectangle with two chamfered corners is six-sided too, but has right angles: a chamfered rectangle.
  const Layout two_chamfers = Rooms({Ring{{2, 0}, {10, 0}, {10, 6}, {2, 6}, {0, 4}, {0, 2}}});
  CHECK(shape(two_chamfers) == "rectangle");
  CHECK(FootprintChamfered(two_chamfers));
  CHECK_FALSE(FootprintChamfered(Rooms({left, mid, right})));  // slopes of 7:4 are not 45-degree chamfers
  // An octagon (all four corners cut at 45 degrees), in two rooms split along a diagonal.
  CHECK(shape(Rooms({Ring{{3, 0}, {7, 0}, {10, 3}, {10, 7}, {7, 10}, {3, 7}}, Ring{{3, 7}, {7, 10}, {3, 10}, {0, 7}, {0, 3}, {3, 0}}})) ==
        "octagon");
  // Trapezoids: one slanted side or two.
  CHECK(shape(Rooms({Ring{{0, 0}, {10, 0}, {10, 6}, {4, 6}}})) == "trapezoid");
  CHECK(shape(Rooms({Ring{{0, 0}, {12, 0}, {9, 6}, {3, 6}}})) == "trapezoid");
  // A cross: a notch at each of the four corners.
  CHECK(shape(Rooms({Box(3, 0, 7, 3), Box(0, 3, 10, 7), Box(3, 7, 7, 10)})) == "cross");
  // A bay: three sides out of the bottom side, the outer two at 45 degrees.
  CHECK(shape(Rooms({Ring{{0, 1}, {3, 1}, {4, 0}, {6, 0}, {7, 1}, {10, 1}, {10, 8}, {0, 8}}})) == "bay");
  // A wing turned 45 degrees off the body's right side.
  CHECK(shape(Rooms({Ring{{0, 0}, {10, 0}, {16, 6}, {12, 10}, {10, 8}, {10, 12}, {0, 12}}})) == "angled-wing");
  // An L with one chamfered corner is still an L.
  CHECK(shape(Rooms({Ring{{0, 0}, {8, 0}, {10, 2}, {10, 5}, {5, 5}, {5, 10}, {0, 10}}})) == "L");
}
