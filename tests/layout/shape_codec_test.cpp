// The shapely-string codec: round trips, canonical writing, and every kind of malformed string.
#include <catch2/catch.hpp>

#include "layout/shape_codec.h"

using namespace villa;

namespace {
Ring MustPolygon(const std::string& text) {
  auto r = ParsePolygonShape(text);
  INFO(text << " -> " << (r ? "" : r.error()));
  REQUIRE(r.ok());
  return *r;
}
Segment MustLine(const std::string& text) {
  auto r = ParseLineShape(text);
  INFO(text << " -> " << (r ? "" : r.error()));
  REQUIRE(r.ok());
  return *r;
}
// parse, write, parse: the geometry and the text are both stable.
void RoundTripPolygon(const std::string& text) {
  Ring first = MustPolygon(text);
  std::string written = FormatPolygonShape(first);
  Ring second = MustPolygon(written);
  CHECK(second == first);
  CHECK(FormatPolygonShape(second) == written);
}
}  // namespace

TEST_CASE("box parses to a counter-clockwise rectangle and writes back as box", "[codec]") {
  Ring ring = MustPolygon("shapely.box(0, 0, 4, 3)");
  CHECK(ring == Ring{{0, 0}, {4, 0}, {4, 3}, {0, 3}});
  CHECK(SignedArea(ring) == Approx(12));
  CHECK(FormatPolygonShape(ring) == "shapely.box(0, 0, 4, 3)");
  // Swapped corners describe the same box.
  CHECK(MustPolygon("shapely.box(4, 3, 0, 0)") == ring);
  RoundTripPolygon("shapely.box(0, 0, 4, 3)");
  RoundTripPolygon("shapely.box(-2.5, -1.25, 3.75, 0.5)");
}

TEST_CASE("Polygon input given clockwise comes back counter-clockwise without the closing point", "[codec]") {
  Ring ring = MustPolygon("shapely.Polygon([(0, 0), (0, 4), (3, 4), (6, 0), (0, 0)])");
  REQUIRE(ring.size() == 4);
  CHECK(SignedArea(ring) == Approx(18));
  CHECK(ring.front() != ring.back());
  CHECK(FormatPolygonShape(ring) == "shapely.Polygon([(0, 0), (6, 0), (3, 4), (0, 4)])");
  RoundTripPolygon("shapely.Polygon([(0, 0), (0, 4), (3, 4), (6, 0), (0, 0)])");
}

TEST_CASE("decimals, negatives and odd spacing parse and round-trip", "[codec]") {
  Ring ring = MustPolygon("  shapely.Polygon( [ ( -1.5 ,2.25),(3,  -0.75 ) ,( 4.125, 6 ) ] )  ");
  REQUIRE(ring.size() == 3);
  CHECK(ring[0] == Point{-1.5, 2.25});
  RoundTripPolygon("shapely.Polygon([(-1.5, 2.25), (3, -0.75), (4.12, 6)])");
  RoundTripPolygon("shapely.Polygon([(8, 0), (10, 2), (8, 4)])");
  // L-shape written as a Polygon, never as a box.
  CHECK(FormatPolygonShape(MustPolygon("shapely.Polygon([(0,0),(6,0),(6,3),(12,3),(12,5),(0,5)])")) ==
        "shapely.Polygon([(0, 0), (6, 0), (6, 3), (12, 3), (12, 5), (0, 5)])");
}

TEST_CASE("LineString parses two points and writes canonically", "[codec]") {
  Segment s = MustLine("shapely.LineString([(5, 4), (7.5, -4)])");
  CHECK(s == Segment{{5, 4}, {7.5, -4}});
  CHECK(FormatLineShape(s) == "shapely.LineString([(5, 4), (7.5, -4)])");
  CHECK(MustLine(FormatLineShape(s)) == s);
  CHECK(MustLine("shapely.LineString([ (0.1,0.20) ,(3 , 4) ])") == Segment{{0.1, 0.2}, {3, 4}});
}

TEST_CASE("FormatNumber rounds to two decimals without -0 or exponents", "[codec]") {
  CHECK(FormatNumber(4) == "4");
  CHECK(FormatNumber(4.5) == "4.5");
  CHECK(FormatNumber(4.50) == "4.5");
  CHECK(FormatNumber(-0.25) == "-0.25");
  CHECK(FormatNumber(1.005000001) == "1.01");
  CHECK(FormatNumber(2.994) == "2.99");
  CHECK(FormatNumber(2.996) == "3");
  CHECK(FormatNumber(-0.001) == "0");
  CHECK(FormatNumber(-0.0) == "0");
  CHECK(FormatNumber(1e-9) == "0");
  CHECK(FormatNumber(123456789.0) == "123456789");
  CHECK(FormatNumber(1e7 + 0.5) == "10000000.5");
  CHECK(RoundToFormat(3.14159) == Approx(3.14));
}

TEST_CASE("malformed shapes give an error that names the problem and quotes the text", "[codec]") {
  struct Case {
    std::string text;
    bool polygon;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {"shapely.box(0, 0, 4, 4", true, "expected ')' at the end of \"shapely.box(0, 0, 4, 4\""},
      {"shapely.box(0, 0, 4)", true, "expected ',' at column 20 of \"shapely.box(0, 0, 4)\""},
      {"shapely.box(0, , 4, 4)", true, "expected a number at column 16 of \"shapely.box(0, , 4, 4)\""},
      {"shapely.Polygon([(0, 0), (4, 0)])", true,
       "a polygon needs at least 3 distinct points, got 2 at column 17 of \"shapely.Polygon([(0, 0), (4, 0)])\""},
      {"shapely.LineString([(0, 0), (1, 1), (2, 2)])", false,
       "a LineString here has exactly 2 points, got 3 at column 20 of \"shapely.LineString([(0, 0), (1, 1), (2, 2)])\""},
      {"shapely.box(0, 0, 4, 4) extra", true, "unexpected text after the shape at column 25 of \"shapely.box(0, 0, 4, 4) extra\""},
      {"shapely.Circle(0, 0, 4)", true,
       "unknown shape function 'Circle' (expected shapely.box or shapely.Polygon) at column 1 of \"shapely.Circle(0, 0, 4)\""},
      {"shapely.Line([(0, 0), (1, 0)])", false,
       "unknown shape function 'Line' (expected shapely.LineString) at column 1 of \"shapely.Line([(0, 0), (1, 0)])\""},
      {"shapely.LineString([(0, 0), (1, 0)])", true,
       "expected a polygon (shapely.box or shapely.Polygon), got a LineString at column 1 of \"shapely.LineString([(0, 0), (1, 0)])\""},
      {"shapely.box(0, 0, 4, 4)", false,
       "expected a shapely.LineString, got a polygon at column 1 of \"shapely.box(0, 0, 4, 4)\""},
      {"", true, "expected shapely.box, shapely.Polygon or shapely.LineString at the end of \"\""},
  };
  for (const auto& c : cases) {
    INFO(c.text);
    std::string error;
    if (c.polygon) {
      auto r = ParsePolygonShape(c.text);
      REQUIRE_FALSE(r.ok());
      error = r.error();
    } else {
      auto r = ParseLineShape(c.text);
      REQUIRE_FALSE(r.ok());
      error = r.error();
    }
    CHECK(error == c.expected);
  }
}
