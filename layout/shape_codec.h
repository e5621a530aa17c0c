#pragma once
// The shapely-string codec: the geometry strings inside the layout JSON.
//   shapely.box(min_x, min_y, max_x, max_y)
//   shapely.Polygon([(x1, y1), (x2, y2), ...])
//   shapely.LineString([(x1, y1), (x2, y2)])
// Parsing accepts integers or decimals, signs, any spacing, and a repeated closing point; it returns
// polygons counter-clockwise without the closing point, starting at the smallest vertex (least x, then y). Writing is canonical: at most 2 decimals, no
// exponent, counter-clockwise, axis-aligned rectangles as shapely.box, everything else as Polygon.
// Errors name the problem and quote the text with a caret line; callers prefix the element path.
#include <string>
#include <string_view>

#include "layout/layout.h"
#include "util/result.h"

namespace villa {

Result<Ring> ParsePolygonShape(std::string_view text);
Result<Segment> ParseLineShape(std::string_view text);

// "4", "4.5", "-0.25": rounded to 2 decimals, trailing zeros dropped, never "-0".
std::string FormatNumber(double value);
std::string FormatPolygonShape(const Ring& ring);
std::string FormatLineShape(const Segment& segment);

// Rounds to the 2-decimal grid the text format carries (what a write-then-read does to a value).
double RoundToFormat(double value);

}  // namespace villa
