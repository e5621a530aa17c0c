#include "layout/footprint.h"

#include <algorithm>
#include <cmath>

namespace villa {

std::string_view ShapeClassName(ShapeClass shape) {
  switch (shape) {
    case ShapeClass::kRectangle: return "rectangle";
    case ShapeClass::kL: return "L";
    case ShapeClass::kU: return "U";
    case ShapeClass::kT: return "T";
    case ShapeClass::kH: return "H";
    case ShapeClass::kIrregular: return "irregular";
  }
  return "rectangle";
}

std::optional<ShapeClass> ParseShapeClass(std::string_view name) {
  for (ShapeClass s : AllShapeClasses()) {
    const std::string_view n = ShapeClassName(s);
    if (name == n) return s;
    if (n.size() == 1 && name.size() == 1 && (name[0] | 0x20) == (n[0] | 0x20)) return s;
  }
  return std::nullopt;
}

const std::vector<ShapeClass>& AllShapeClasses() {
  static const std::vector<ShapeClass> all{ShapeClass::kRectangle, ShapeClass::kL, ShapeClass::kU,
                                           ShapeClass::kT,         ShapeClass::kH, ShapeClass::kIrregular};
  return all;
}

std::vector<PolygonWithHoles> FootprintOf(const std::vector<Ring>& rings, double tolerance,
                                          const std::vector<bool>& subtract) {
  const ExteriorBoundary boundary = ExteriorBoundaryOf(rings, tolerance, subtract, PinchRule::kKeepRegionsApart);
  if (!boundary.closed) return {};
  std::vector<PolygonWithHoles> out;
  std::vector<Ring> holes;
  for (const BoundaryRing& chain : boundary.rings) {
    Ring ring;
    for (const Segment& piece : chain.pieces) ring.push_back(piece.a);
    ring = WithoutCollinearCorners(ring, tolerance);
    if (ring.size() < 3 || std::abs(chain.signed_area) <= tolerance) continue;
    if (chain.signed_area > 0) {
      out.push_back({std::move(ring), {}});
    } else {
      std::reverse(ring.begin(), ring.end());
      holes.push_back(std::move(ring));
    }
  }
  // Each hole belongs to the smallest outline holding the middle of its first edge.
  for (Ring& hole : holes) {
    const Point probe{(hole[0].x + hole[1].x) / 2, (hole[0].y + hole[1].y) / 2};
    PolygonWithHoles* best = nullptr;
    for (PolygonWithHoles& p : out)
      if (PointInRing(probe, p.outer, tolerance) && (!best || Area(p.outer) < Area(best->outer))) best = &p;
    if (best) best->holes.push_back(std::move(hole));
  }
  return out;
}

std::vector<PolygonWithHoles> LevelFootprint(const Layout& layout, int level, double tolerance) {
  std::vector<Ring> rings;
  for (int r : layout.RoomsOnLevel(level)) rings.push_back(layout.rooms[r].polygon);
  return FootprintOf(rings, tolerance);
}

std::optional<ShapeClass> ClassifyFootprint(const Layout& layout, int level) {
  std::vector<int> rooms = layout.RoomsOnLevel(level);
  if (rooms.empty()) return std::nullopt;
  // A slanted edge on the outside (not shared with another room of the level) makes it irregular.
  for (int r : rooms) {
    const Ring& ring = layout.rooms[r].polygon;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      Point a = ring[i], b = ring[(i + 1) % ring.size()];
      if (std::abs(a.x - b.x) <= kTolerance || std::abs(a.y - b.y) <= kTolerance) continue;
      Point mid{(a.x + b.x) / 2, (a.y + b.y) / 2};
      bool shared = false;
      for (int o : rooms)
        if (o != r && PointOnBoundary(mid, layout.rooms[o].polygon, kTolerance)) shared = true;
      if (!shared) return ShapeClass::kIrregular;
    }
  }
  // Orthogonal: which cells of the compressed grid are empty, and where do the empty parts touch the
  // bounding box?
  std::vector<double> xs, ys;
  for (int r : rooms)
    for (const Point& p : layout.rooms[r].polygon) {
      xs.push_back(p.x);
      ys.push_back(p.y);
    }
  auto unique_sorted = [&](std::vector<double>& v) {
    std::sort(v.begin(), v.end());
    std::vector<double> out;
    for (double x : v)
      if (out.empty() || x - out.back() > kTolerance) out.push_back(x);
    v = out;
  };
  unique_sorted(xs);
  unique_sorted(ys);
  int nx = static_cast<int>(xs.size()) - 1, ny = static_cast<int>(ys.size()) - 1;
  if (nx <= 0 || ny <= 0) return ShapeClass::kIrregular;
  std::vector<int> cell(nx * ny, 0);  // 1 = inside the footprint
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      Point c{(xs[i] + xs[i + 1]) / 2, (ys[j] + ys[j + 1]) / 2};
      for (int r : rooms)
        if (PointInRing(c, layout.rooms[r].polygon, 0)) {
          cell[i * ny + j] = 1;
          break;
        }
    }
  struct Part {
    bool left = false, right = false, bottom = false, top = false;
    int sides() const { return left + right + bottom + top; }
  };
  std::vector<Part> parts;
  std::vector<int> seen(nx * ny, 0);
  for (int start = 0; start < nx * ny; ++start) {
    if (cell[start] || seen[start]) continue;
    Part part;
    std::vector<int> stack{start};
    seen[start] = 1;
    while (!stack.empty()) {
      int c = stack.back();
      stack.pop_back();
      int i = c / ny, j = c % ny;
      if (i == 0) part.left = true;
      if (i == nx - 1) part.right = true;
      if (j == 0) part.bottom = true;
      if (j == ny - 1) part.top = true;
      const int di[4] = {1, -1, 0, 0}, dj[4] = {0, 0, 1, -1};
      for (int d = 0; d < 4; ++d) {
        int a = i + di[d], b = j + dj[d];
        if (a < 0 || b < 0 || a >= nx || b >= ny) continue;
        int n = a * ny + b;
        if (!cell[n] && !seen[n]) {
          seen[n] = 1;
          stack.push_back(n);
        }
      }
    }
    parts.push_back(part);
  }
  auto corner = [](const Part& p) { return p.sides() == 2 && !(p.left && p.right) && !(p.top && p.bottom); };
  auto notch = [](const Part& p) { return p.sides() == 1; };
  if (parts.empty()) return ShapeClass::kRectangle;
  if (parts.size() == 1) {
    if (corner(parts[0])) return ShapeClass::kL;
    if (notch(parts[0])) return ShapeClass::kU;
    return ShapeClass::kIrregular;
  }
  if (parts.size() == 2) {
    const Part& a = parts[0];
    const Part& b = parts[1];
    if (corner(a) && corner(b) &&
        ((a.left && b.left) || (a.right && b.right) || (a.top && b.top) || (a.bottom && b.bottom)))
      return ShapeClass::kT;
    if (notch(a) && notch(b) && ((a.left && b.right) || (a.right && b.left) || (a.top && b.bottom) || (a.bottom && b.top)))
      return ShapeClass::kH;
  }
  return ShapeClass::kIrregular;
}

}  // namespace villa
