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
    case ShapeClass::kHexagon: return "hexagon";
    case ShapeClass::kOctagon: return "octagon";
    case ShapeClass::kTrapezoid: return "trapezoid";
    case ShapeClass::kCross: return "cross";
    case ShapeClass::kBay: return "bay";
    case ShapeClass::kAngledWing: return "angled-wing";
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
  static const std::vector<ShapeClass> all{
      ShapeClass::kRectangle, ShapeClass::kL,       ShapeClass::kU,         ShapeClass::kT,
      ShapeClass::kH,         ShapeClass::kIrregular, ShapeClass::kHexagon, ShapeClass::kOctagon,
      ShapeClass::kTrapezoid, ShapeClass::kCross,   ShapeClass::kBay,       ShapeClass::kAngledWing};
  return all;
}

bool ShapeClassIsAngled(ShapeClass shape) {
  switch (shape) {
    case ShapeClass::kIrregular:
    case ShapeClass::kHexagon:
    case ShapeClass::kOctagon:
    case ShapeClass::kTrapezoid:
    case ShapeClass::kBay:
    case ShapeClass::kAngledWing: return true;
    default: return false;
  }
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

namespace {

bool Slanted(Point a, Point b) { return std::abs(a.x - b.x) > kTolerance && std::abs(a.y - b.y) > kTolerance; }
bool Horizontal(Point a, Point b) { return std::abs(a.y - b.y) <= kTolerance; }
bool Vertical(Point a, Point b) { return std::abs(a.x - b.x) <= kTolerance; }
// > 0 for a left turn a -> b -> c (a convex corner of a counter-clockwise ring).
double Turn(Point a, Point b, Point c) { return (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x); }
// The inside angle at b of a counter-clockwise ring, degrees in (0, 360).
double InsideAngle(Point a, Point b, Point c) {
  const double ux = a.x - b.x, uy = a.y - b.y, vx = c.x - b.x, vy = c.y - b.y;
  double deg = std::atan2(vx * uy - vy * ux, vx * ux + vy * uy) * 180.0 / M_PI;
  return deg <= 0.0 ? deg + 360.0 : deg;
}
bool Parallel(Point a, Point b, Point c, Point d) {
  const double cross = (b.x - a.x) * (d.y - c.y) - (b.y - a.y) * (d.x - c.x);
  return std::abs(cross) <= kTolerance * (Distance(a, b) + Distance(c, d));
}
bool Square(Point a, Point b, Point c, Point d) {
  const double dot = (b.x - a.x) * (d.x - c.x) + (b.y - a.y) * (d.y - c.y);
  return std::abs(dot) <= kTolerance * (Distance(a, b) + Distance(c, d));
}
int SlantedEdges(const Ring& ring) {
  int n = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) n += Slanted(ring[i], ring[(i + 1) % ring.size()]);
  return n;
}
bool ConvexWithAngles(const Ring& ring, double lo, double hi) {
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const double a = InsideAngle(ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n]);
    if (a < lo || a > hi) return false;
  }
  return true;
}

// Edge i of the ring is a 45-degree chamfer of a convex corner between a horizontal and a vertical side.
bool IsChamfer(const Ring& r, std::size_t i) {
  const std::size_t n = r.size();
  const Point p0 = r[(i + n - 1) % n], p1 = r[i], p2 = r[(i + 1) % n], p3 = r[(i + 2) % n];
  if (!Slanted(p1, p2) || std::abs(std::abs(p2.x - p1.x) - std::abs(p2.y - p1.y)) > kTolerance) return false;
  const bool hv = Horizontal(p0, p1) && Vertical(p2, p3), vh = Vertical(p0, p1) && Horizontal(p2, p3);
  return (hv || vh) && Turn(p0, p1, p2) > 0 && Turn(p1, p2, p3) > 0;
}

// The ring with every 45-degree corner chamfer replaced by the corner it cuts.
Ring WithoutChamfers(Ring r) {
  for (bool changed = true; changed && r.size() > 4;) {
    changed = false;
    for (std::size_t i = 0; i < r.size(); ++i) {
      if (!IsChamfer(r, i)) continue;
      const std::size_t n = r.size(), j = (i + 1) % n;
      const Point p0 = r[(i + n - 1) % n], p1 = r[i], p2 = r[j];
      const Point corner = Horizontal(p0, p1) ? Point{p2.x, p1.y} : Point{p1.x, p2.y};
      r[i] = corner;
      r.erase(r.begin() + static_cast<long>(j));
      changed = true;
      break;
    }
  }
  return WithoutCollinearCorners(r, kTolerance);
}

// The ring with one bay (an axis side, three sides out of it with the outer two slanted, the same line
// on) taken off; nullopt without one.
std::optional<Ring> WithoutBay(const Ring& r) {
  const std::size_t n = r.size();
  if (n < 7) return std::nullopt;
  for (std::size_t i = 0; i < n; ++i) {
    const Point p0 = r[i], p1 = r[(i + 1) % n], p2 = r[(i + 2) % n], p3 = r[(i + 3) % n], p4 = r[(i + 4) % n],
                p5 = r[(i + 5) % n];
    if (Slanted(p0, p1) || !Slanted(p1, p2) || Slanted(p2, p3) || !Slanted(p3, p4) || Slanted(p4, p5)) continue;
    if (!Parallel(p0, p1, p2, p3) || std::abs(Turn(p0, p1, p4)) > kTolerance * Distance(p0, p1) * 4 ||
        std::abs(Turn(p0, p1, p5)) > kTolerance * Distance(p0, p1) * 4)
      continue;  // the bay's outer side parallel to its base, and the base line going on past it
    if (Turn(p0, p1, p2) >= 0 || Turn(p1, p2, p3) <= 0 || Turn(p2, p3, p4) <= 0 || Turn(p3, p4, p5) >= 0) continue;
    Ring out;
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t off = (k + n - i) % n;  // 1..4 are the bay's corners p1..p4
      if (off >= 1 && off <= 4) continue;
      out.push_back(r[k]);
    }
    return WithoutCollinearCorners(out, kTolerance);
  }
  return std::nullopt;
}

// Three consecutive slanted edges, the first and last parallel and the middle square to them, every other
// edge axis-parallel: a wing turned off a rectangular body.
bool IsAngledWing(const Ring& r) {
  const std::size_t n = r.size();
  if (SlantedEdges(r) != 3 || n < 6) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const Point p0 = r[i], p1 = r[(i + 1) % n], p2 = r[(i + 2) % n], p3 = r[(i + 3) % n];
    if (Slanted(p0, p1) && Slanted(p1, p2) && Slanted(p2, p3) && Parallel(p0, p1, p2, p3) && Square(p0, p1, p1, p2))
      return true;
  }
  return false;
}

// The orthogonal classes, from which cells of the compressed grid of `outline` are empty and where the
// empty parts touch the bounding box.
ShapeClass ClassifyOrthogonal(const Ring& outline) {
  std::vector<double> xs, ys;
  for (const Point& p : outline) {
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
    for (int j = 0; j < ny; ++j)
      cell[i * ny + j] = PointInRing({(xs[i] + xs[i + 1]) / 2, (ys[j] + ys[j + 1]) / 2}, outline, 0) ? 1 : 0;
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
  if (parts.size() == 4) {
    int corners = 0, mask = 0;
    for (const Part& p : parts) {
      if (!corner(p)) break;
      ++corners;
      mask |= 1 << ((p.right ? 1 : 0) + (p.top ? 2 : 0));
    }
    if (corners == 4 && mask == 15) return ShapeClass::kCross;
  }
  return ShapeClass::kIrregular;
}

// The single outline of `level` without holes; nullopt for none, several, or a courtyard.
std::optional<Ring> SingleOutline(const Layout& layout, int level) {
  const std::vector<PolygonWithHoles> outline = LevelFootprint(layout, level);
  if (outline.size() != 1 || !outline[0].holes.empty()) return std::nullopt;
  return outline[0].outer;
}

}  // namespace

std::optional<ShapeClass> ClassifyFootprint(const Layout& layout, int level) {
  if (layout.RoomsOnLevel(level).empty()) return std::nullopt;
  const std::optional<Ring> outline = SingleOutline(layout, level);
  if (!outline) return ShapeClass::kIrregular;
  const Ring& r = *outline;
  if (SlantedEdges(r) == 0) return ClassifyOrthogonal(r);
  if (r.size() == 6 && ConvexWithAngles(r, 105.0, 145.0)) return ShapeClass::kHexagon;
  if (r.size() == 8 && ConvexWithAngles(r, 120.0, 150.0)) return ShapeClass::kOctagon;
  if (r.size() == 4 && (Parallel(r[0], r[1], r[3], r[2]) || Parallel(r[1], r[2], r[0], r[3])))
    return ShapeClass::kTrapezoid;
  if (IsAngledWing(r)) return ShapeClass::kAngledWing;
  if (std::optional<Ring> rest = WithoutBay(r)) {
    const Ring plain = WithoutChamfers(*rest);
    if (SlantedEdges(plain) == 0) return ShapeClass::kBay;
  }
  const Ring plain = WithoutChamfers(r);
  if (SlantedEdges(plain) == 0) return ClassifyOrthogonal(plain);
  return ShapeClass::kIrregular;
}

bool HasSlantedWallBetweenRooms(const Layout& layout) {
  for (const auto* list : {&layout.interiors, &layout.doors, &layout.opens})
    for (const Element& e : *list)
      if (Slanted(e.shape.a, e.shape.b)) return true;
  return false;
}

bool HasSlantedOutsideEdge(const Layout& layout, int level) {
  for (const PolygonWithHoles& p : LevelFootprint(layout, level))
    if (SlantedEdges(p.outer) > 0) return true;
  return false;
}

bool FootprintChamfered(const Layout& layout, int level) {
  const std::optional<Ring> outline = SingleOutline(layout, level);
  if (!outline) return false;
  for (std::size_t i = 0; i < outline->size(); ++i)
    if (IsChamfer(*outline, i)) return true;
  return false;
}

}  // namespace villa
