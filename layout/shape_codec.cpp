#include "layout/shape_codec.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "util/excerpt.h"

namespace villa {
namespace {

// A small recursive-descent reader over one shapely string. Positions in messages are 1-based columns.
class ShapeReader {
 public:
  explicit ShapeReader(std::string_view text) : text_(text) {}

  // Reads "shapely.<name>" (the "shapely." prefix is optional) and returns the name.
  Result<std::string> Function() {
    SkipSpace();
    std::size_t start = pos_;
    while (pos_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '.' || text_[pos_] == '_')) ++pos_;
    std::string name(text_.substr(start, pos_ - start));
    if (name.rfind("shapely.", 0) == 0) name = name.substr(8);
    if (name.empty()) return Fail("expected shapely.box, shapely.Polygon or shapely.LineString", start);
    return name;
  }

  Status Expect(char c) {
    SkipSpace();
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return {};
    }
    return Error{Message(std::string("expected '") + c + "'", pos_)};
  }

  bool Accept(char c) {
    SkipSpace();
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }

  Result<double> Number() {
    SkipSpace();
    std::size_t start = pos_;
    if (pos_ < text_.size() && (text_[pos_] == '-' || text_[pos_] == '+')) ++pos_;
    std::size_t digits = 0;
    while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_, ++digits;
    if (pos_ < text_.size() && text_[pos_] == '.') {
      ++pos_;
      while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_, ++digits;
    }
    if (digits > 0 && pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
      std::size_t mark = pos_++;
      if (pos_ < text_.size() && (text_[pos_] == '-' || text_[pos_] == '+')) ++pos_;
      std::size_t exp_digits = 0;
      while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_, ++exp_digits;
      if (exp_digits == 0) pos_ = mark;
    }
    if (digits == 0) return Fail("expected a number", start);
    std::string token(text_.substr(start, pos_ - start));
    char* end = nullptr;
    double value = std::strtod(token.c_str(), &end);
    if (!std::isfinite(value)) return Fail("number out of range", start);
    return value;
  }

  // "(x, y)" or "[x, y]"
  Result<Point> Coordinate() {
    SkipSpace();
    char close = ')';
    if (Accept('[')) close = ']';
    else if (!Accept('(')) return Fail("expected '(' starting a coordinate pair", pos_);
    auto x = Number();
    if (!x) return Error{x.error()};
    if (auto s = Expect(','); !s) return Error{s.error()};
    auto y = Number();
    if (!y) return Error{y.error()};
    if (auto s = Expect(close); !s) return Error{s.error()};
    return Point{*x, *y};
  }

  // "[(x, y), (x, y), ...]" with an optional trailing comma.
  Result<std::vector<Point>> CoordinateList() {
    if (auto s = Expect('['); !s) return Error{s.error()};
    std::vector<Point> points;
    if (Accept(']')) return points;
    while (true) {
      auto p = Coordinate();
      if (!p) return Error{p.error()};
      points.push_back(*p);
      if (Accept(']')) break;
      if (auto s = Expect(','); !s) return Error{std::string(s.error())};
      if (Accept(']')) break;
    }
    return points;
  }

  Status End() {
    SkipSpace();
    if (pos_ != text_.size()) return Error{Message("unexpected text after the shape", pos_)};
    return {};
  }

  std::string Message(const std::string& what, std::size_t at) const {
    std::string where = at >= text_.size() ? " at the end" : " at column " + std::to_string(at + 1);
    return what + where + " of \"" + Excerpt(text_) + "\"";
  }
  Error Fail(const std::string& what, std::size_t at) const { return Error{Message(what, at)}; }
  std::size_t pos() const { return pos_; }

 private:
  void SkipSpace() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  std::string_view text_;
  std::size_t pos_ = 0;
};

bool Near(const Point& a, const Point& b) { return std::abs(a.x - b.x) <= 1e-12 && std::abs(a.y - b.y) <= 1e-12; }

// Drops a repeated closing point and consecutive duplicates, orients counter-clockwise and starts the ring
// at its smallest vertex (least x, then least y), so one geometry has exactly one ring and one text.
Ring NormaliseRing(std::vector<Point> points) {
  Ring ring;
  for (const auto& p : points)
    if (ring.empty() || !Near(ring.back(), p)) ring.push_back(p);
  while (ring.size() > 1 && Near(ring.front(), ring.back())) ring.pop_back();
  if (SignedArea(ring) < 0) std::reverse(ring.begin(), ring.end());
  auto smallest = std::min_element(ring.begin(), ring.end(), [](const Point& a, const Point& b) {
    return a.x < b.x || (a.x == b.x && a.y < b.y);
  });
  std::rotate(ring.begin(), smallest, ring.end());
  return ring;
}

bool IsAxisAlignedRectangle(const Ring& ring) {
  if (ring.size() != 4) return false;
  for (std::size_t i = 0; i < 4; ++i) {
    const Point& p = ring[i];
    const Point& q = ring[(i + 1) % 4];
    bool horizontal = p.y == q.y && p.x != q.x;
    bool vertical = p.x == q.x && p.y != q.y;
    if (!horizontal && !vertical) return false;
    const Point& r = ring[(i + 2) % 4];
    bool next_horizontal = q.y == r.y;
    if (horizontal == next_horizontal) return false;
  }
  return SignedArea(ring) > 0;
}

std::string FormatPoint(const Point& p) { return "(" + FormatNumber(p.x) + ", " + FormatNumber(p.y) + ")"; }

}  // namespace

double RoundToFormat(double value) {
  double r = std::round(value * 100.0) / 100.0;
  return r == 0.0 ? 0.0 : r;  // no negative zero
}

std::string FormatNumber(double value) {
  double r = RoundToFormat(value);
  char buffer[64];
  if (r == std::floor(r) && std::abs(r) < 1e15) {
    std::snprintf(buffer, sizeof buffer, "%.0f", r);
  } else {
    std::snprintf(buffer, sizeof buffer, "%.2f", r);
    std::string s(buffer);
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s == "-0" ? "0" : s;
  }
  std::string s(buffer);
  return s == "-0" ? "0" : s;
}

Result<Ring> ParsePolygonShape(std::string_view text) {
  ShapeReader reader(text);
  auto name = reader.Function();
  if (!name) return Error{name.error()};
  if (*name == "box") {
    if (auto s = reader.Expect('('); !s) return Error{s.error()};
    double v[4];
    for (int i = 0; i < 4; ++i) {
      if (i > 0) {
        if (auto s = reader.Expect(','); !s) return Error{s.error()};
      }
      auto n = reader.Number();
      if (!n) return Error{n.error()};
      v[i] = *n;
    }
    if (auto s = reader.Expect(')'); !s) return Error{s.error()};
    if (auto s = reader.End(); !s) return Error{s.error()};
    double x0 = std::min(v[0], v[2]), x1 = std::max(v[0], v[2]);
    double y0 = std::min(v[1], v[3]), y1 = std::max(v[1], v[3]);
    return Ring{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  }
  if (*name == "Polygon") {
    if (auto s = reader.Expect('('); !s) return Error{s.error()};
    std::size_t list_at = reader.pos();
    auto points = reader.CoordinateList();
    if (!points) return Error{points.error()};
    if (auto s = reader.Expect(')'); !s) return Error{s.error()};
    if (auto s = reader.End(); !s) return Error{s.error()};
    Ring ring = NormaliseRing(std::move(*points));
    if (ring.size() < 3)
      return reader.Fail("a polygon needs at least 3 distinct points, got " + std::to_string(ring.size()), list_at);
    return ring;
  }
  if (*name == "LineString") return reader.Fail("expected a polygon (shapely.box or shapely.Polygon), got a LineString", 0);
  return reader.Fail("unknown shape function '" + Excerpt(*name) + "' (expected shapely.box or shapely.Polygon)", 0);
}

Result<Segment> ParseLineShape(std::string_view text) {
  ShapeReader reader(text);
  auto name = reader.Function();
  if (!name) return Error{name.error()};
  if (*name != "LineString") {
    if (*name == "box" || *name == "Polygon") return reader.Fail("expected a shapely.LineString, got a polygon", 0);
    return reader.Fail("unknown shape function '" + Excerpt(*name) + "' (expected shapely.LineString)", 0);
  }
  if (auto s = reader.Expect('('); !s) return Error{s.error()};
  std::size_t list_at = reader.pos();
  auto points = reader.CoordinateList();
  if (!points) return Error{points.error()};
  if (auto s = reader.Expect(')'); !s) return Error{s.error()};
  if (auto s = reader.End(); !s) return Error{s.error()};
  if (points->size() != 2)
    return reader.Fail("a LineString here has exactly 2 points, got " + std::to_string(points->size()), list_at);
  return Segment{(*points)[0], (*points)[1]};
}

std::string FormatPolygonShape(const Ring& input) {
  Ring ring;
  ring.reserve(input.size());
  for (const auto& p : input) ring.push_back({RoundToFormat(p.x), RoundToFormat(p.y)});
  ring = NormaliseRing(std::move(ring));
  if (IsAxisAlignedRectangle(ring)) {
    double x0 = ring[0].x, x1 = ring[0].x, y0 = ring[0].y, y1 = ring[0].y;
    for (const auto& p : ring) {
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
    return "shapely.box(" + FormatNumber(x0) + ", " + FormatNumber(y0) + ", " + FormatNumber(x1) + ", " + FormatNumber(y1) + ")";
  }
  std::string out = "shapely.Polygon([";
  for (std::size_t i = 0; i < ring.size(); ++i) {
    if (i) out += ", ";
    out += FormatPoint(ring[i]);
  }
  return out + "])";
}

std::string FormatLineShape(const Segment& s) {
  return "shapely.LineString([" + FormatPoint(s.a) + ", " + FormatPoint(s.b) + "])";
}

}  // namespace villa
