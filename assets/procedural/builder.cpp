// The procedural generators' shared parts: random stream, palettes, mesh primitives, surfaces and cavities.
#include <cassert>
#include <cmath>
#include <numbers>

#include "assets/procedural/generator.h"
#include "util/hash.h"

namespace villa::procedural {

std::uint64_t Rng::Next() { return stream_.Next(); }

double Rng::Unit() { return stream_.Unit(); }

double Rng::Range(double lo, double hi) { return lo + (hi - lo) * Unit(); }

int Rng::Int(int lo, int hi) { return static_cast<int>(stream_.Int(lo, hi)); }

std::uint64_t HashText(std::string_view text) { return Fnv1a64(text); }

std::uint64_t MixSeed(std::uint64_t a, std::uint64_t b) {
  Rng rng(a * kSplitMix64Gamma ^ (b + 0x632BE59BD9B4E019ull));
  return rng.Next();
}

double Snap(double v) {
  double r = std::round(v * 1e4) / 1e4;
  return r == 0.0 ? 0.0 : r;
}

// ---------------------------------------------------------------------------------------------- palettes

namespace {

MeshMaterial M(const char* name, double r, double g, double b, double alpha = 1.0) { return {name, r, g, b, alpha}; }

std::map<std::string, Palette, std::less<>> MakePalettes() {
  std::map<std::string, Palette, std::less<>> p;
  p["modern"] = {{M("white-oak", 0.78, 0.66, 0.5), M("walnut", 0.42, 0.29, 0.2), M("black-ash", 0.16, 0.15, 0.15)},
                 {M("white-lacquer", 0.93, 0.93, 0.92), M("graphite-lacquer", 0.27, 0.28, 0.3),
                  M("sage-lacquer", 0.62, 0.68, 0.6)},
                 {M("grey-fabric", 0.55, 0.56, 0.58), M("charcoal-fabric", 0.25, 0.26, 0.28),
                  M("teal-fabric", 0.2, 0.45, 0.48), M("sand-fabric", 0.76, 0.7, 0.6)},
                 {M("chrome", 0.8, 0.81, 0.83), M("black-steel", 0.12, 0.12, 0.13)},
                 {M("red", 0.75, 0.2, 0.18), M("blue", 0.2, 0.35, 0.65), M("yellow", 0.93, 0.75, 0.2),
                  M("black", 0.1, 0.1, 0.1), M("white", 0.95, 0.95, 0.95), M("teal", 0.1, 0.5, 0.5)}};
  p["classic"] = {{M("mahogany", 0.4, 0.17, 0.1), M("dark-walnut", 0.3, 0.2, 0.13), M("cherry", 0.55, 0.27, 0.16)},
                  {M("ivory-paint", 0.92, 0.89, 0.8), M("bottle-green-paint", 0.16, 0.3, 0.22),
                   M("oxblood-paint", 0.42, 0.12, 0.12)},
                  {M("burgundy-velvet", 0.45, 0.1, 0.15), M("cream-damask", 0.88, 0.83, 0.7),
                   M("forest-velvet", 0.15, 0.32, 0.2), M("gold-brocade", 0.72, 0.58, 0.3)},
                  {M("brass", 0.78, 0.62, 0.3), M("antique-bronze", 0.45, 0.35, 0.22)},
                  {M("oxblood", 0.45, 0.1, 0.1), M("navy", 0.12, 0.16, 0.35), M("forest", 0.13, 0.3, 0.18),
                   M("gold", 0.8, 0.65, 0.3), M("cream", 0.9, 0.86, 0.74), M("tan", 0.65, 0.48, 0.3)}};
  p["rustic"] = {
      {M("pine", 0.75, 0.57, 0.36), M("weathered-oak", 0.55, 0.46, 0.36), M("reclaimed-wood", 0.45, 0.33, 0.22)},
      {M("chalk-white", 0.88, 0.86, 0.8), M("barn-red", 0.55, 0.2, 0.15), M("duck-egg", 0.6, 0.72, 0.7)},
      {M("linen", 0.8, 0.75, 0.65), M("brown-leather", 0.42, 0.26, 0.15), M("plaid-red", 0.6, 0.22, 0.18),
       M("oatmeal", 0.7, 0.64, 0.54)},
      {M("wrought-iron", 0.18, 0.17, 0.16), M("copper", 0.72, 0.45, 0.3)},
      {M("rust", 0.6, 0.3, 0.15), M("olive", 0.42, 0.42, 0.2), M("mustard", 0.78, 0.6, 0.2), M("brick", 0.6, 0.3, 0.24),
       M("cream", 0.88, 0.84, 0.72), M("moss", 0.35, 0.42, 0.25)}};
  p["scandinavian"] = {
      {M("birch", 0.86, 0.77, 0.62), M("ash", 0.8, 0.72, 0.58), M("light-oak", 0.82, 0.7, 0.52)},
      {M("white-matte", 0.95, 0.95, 0.94), M("pale-grey", 0.82, 0.83, 0.83), M("dusty-blue", 0.6, 0.68, 0.76)},
      {M("light-grey-wool", 0.75, 0.76, 0.77), M("mustard-wool", 0.82, 0.65, 0.25), M("sage-wool", 0.64, 0.7, 0.6),
       M("off-white-boucle", 0.9, 0.88, 0.84)},
      {M("matte-black", 0.13, 0.13, 0.13), M("matte-white-metal", 0.9, 0.9, 0.9)},
      {M("dusty-pink", 0.85, 0.65, 0.62), M("mint", 0.65, 0.8, 0.72), M("slate", 0.4, 0.45, 0.5),
       M("ochre", 0.8, 0.6, 0.3), M("snow", 0.96, 0.96, 0.95), M("terracotta", 0.75, 0.45, 0.33)}};
  return p;
}

}  // namespace

const Palette& StylePalette(std::string_view style) {
  static const auto palettes = MakePalettes();
  auto it = palettes.find(style);
  assert(it != palettes.end() && "style checked when the id was parsed");
  return it->second;
}

MeshMaterial Glass() { return M("glass", 0.75, 0.85, 0.88, 0.3); }
MeshMaterial MirrorGlass() { return M("mirror", 0.85, 0.88, 0.9); }
MeshMaterial ScreenBlack() { return M("screen", 0.04, 0.05, 0.06); }
MeshMaterial Porcelain() { return M("porcelain", 0.96, 0.96, 0.95); }
MeshMaterial Paper() { return M("paper", 0.95, 0.93, 0.86); }
MeshMaterial Soil() { return M("soil", 0.3, 0.22, 0.15); }
MeshMaterial Foliage(Rng& rng) {
  static const std::vector<MeshMaterial> greens = {M("leaf-green", 0.25, 0.5, 0.2), M("dark-leaf", 0.13, 0.35, 0.15),
                                                   M("olive-leaf", 0.4, 0.5, 0.22)};
  return rng.Pick(greens);
}
MeshMaterial Appliance(std::string_view style) {
  if (style == "modern") return M("stainless-steel", 0.72, 0.73, 0.74);
  if (style == "classic") return M("cream-enamel", 0.9, 0.87, 0.78);
  if (style == "rustic") return M("black-enamel", 0.14, 0.14, 0.15);
  return M("white-enamel", 0.95, 0.95, 0.95);
}

// ---------------------------------------------------------------------------------------------- primitives

namespace {

Vec3 SnapV(Vec3 p) { return {Snap(p.x), Snap(p.y), Snap(p.z)}; }

// (cos, sin) of step j of `segments` around a circle; quarter turns exact, so extremes are exactly r.
std::pair<double, double> CircleStep(int j, int segments) {
  if (j % (segments / 4) == 0) {
    int quarter = j / (segments / 4);
    return {quarter == 0 ? 1.0 : quarter == 2 ? -1.0 : 0.0, quarter == 1 ? 1.0 : quarter == 3 ? -1.0 : 0.0};
  }
  double a = 2.0 * std::numbers::pi * j / segments;
  return {std::cos(a), std::sin(a)};
}

int Vertex(TriangleMesh& m, Vec3 p) {
  m.vertices.push_back(SnapV(p));
  return static_cast<int>(m.vertices.size()) - 1;
}

// Quad a-b-c-d, counter-clockwise seen from outside.
void Quad(TriangleMesh& m, int a, int b, int c, int d) {
  m.AddTriangle(a, b, c);
  m.AddTriangle(a, c, d);
}

// Rings of four corners each (counter-clockwise from above), bottom to top, joined by side quads and
// closed by a bottom and a top cap.
void Stack(TriangleMesh& m, const std::vector<std::array<Vec3, 4>>& rings) {
  std::vector<std::array<int, 4>> idx;
  for (const auto& ring : rings) {
    std::array<int, 4> r;
    for (int i = 0; i < 4; ++i) r[i] = Vertex(m, ring[i]);
    idx.push_back(r);
  }
  Quad(m, idx.front()[0], idx.front()[3], idx.front()[2], idx.front()[1]);
  for (size_t k = 0; k + 1 < idx.size(); ++k)
    for (int i = 0; i < 4; ++i) {
      int j = (i + 1) % 4;
      Quad(m, idx[k][i], idx[k][j], idx[k + 1][j], idx[k + 1][i]);
    }
  Quad(m, idx.back()[0], idx.back()[1], idx.back()[2], idx.back()[3]);
}

std::array<Vec3, 4> RectRing(double x0, double y0, double x1, double y1, double z) {
  return {Vec3{x0, y0, z}, Vec3{x1, y0, z}, Vec3{x1, y1, z}, Vec3{x0, y1, z}};
}

}  // namespace

int MeshBuilder::Part(const MeshMaterial& material) {
  for (size_t i = 0; i < mesh_.parts.size(); ++i)
    if (mesh_.parts[i].material == material) return static_cast<int>(i);
  mesh_.parts.push_back({material, {}});
  return static_cast<int>(mesh_.parts.size()) - 1;
}

void MeshBuilder::Box(int part, Vec3 lo, Vec3 hi) {
  assert(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z && "a box needs lo < hi on every axis");
  Stack(Mesh(part), {RectRing(lo.x, lo.y, hi.x, hi.y, lo.z), RectRing(lo.x, lo.y, hi.x, hi.y, hi.z)});
}

void MeshBuilder::Hexahedron(int part, const std::array<Vec3, 8>& c) {
  Stack(Mesh(part), {{c[0], c[1], c[2], c[3]}, {c[4], c[5], c[6], c[7]}});
}

void MeshBuilder::Cushion(int part, Vec3 lo, Vec3 hi, double inset, double waist) {
  double zm = lo.z + (hi.z - lo.z) * waist;
  Stack(Mesh(part),
        {RectRing(lo.x + inset, lo.y + inset, hi.x - inset, hi.y - inset, lo.z), RectRing(lo.x, lo.y, hi.x, hi.y, zm),
         RectRing(lo.x + inset, lo.y + inset, hi.x - inset, hi.y - inset, hi.z)});
}

void MeshBuilder::Tray(int part, Vec3 lo, Vec3 hi, double wall, double floor) {
  // Five boxes, not one hollow piece: every piece of a procedural mesh is convex, so a physics engine's
  // hull of each is the mesh itself (a hollow tray's hull would fill its pocket; issue 28).
  Box(part, {lo.x + wall, lo.y + wall, lo.z}, {hi.x - wall, hi.y - wall, lo.z + floor});
  Box(part, {lo.x, lo.y, lo.z}, {hi.x, lo.y + wall, hi.z});
  Box(part, {lo.x, hi.y - wall, lo.z}, {hi.x, hi.y, hi.z});
  Box(part, {lo.x, lo.y + wall, lo.z}, {lo.x + wall, hi.y - wall, hi.z});
  Box(part, {hi.x - wall, lo.y + wall, lo.z}, {hi.x, hi.y - wall, hi.z});
}

void MeshBuilder::Lathe(int part, const std::vector<Point>& profile, Vec3 origin, Vec3 ex, Vec3 ey, Vec3 axis,
                        int segments) {
  assert(segments >= 4 && segments % 4 == 0 && profile.size() >= 3);
  TriangleMesh& m = Mesh(part);
  const bool poles = profile.front().x == 0.0 && profile.back().x == 0.0;
  const int n = static_cast<int>(profile.size());
  // ring[i][j]: the vertex of profile point i at angle j (one shared vertex for a point on the axis).
  std::vector<std::vector<int>> ring(n);
  for (int i = 0; i < n; ++i) {
    const Point q = profile[i];
    if (q.x == 0.0) {
      ring[i].assign(segments, Vertex(m, origin + axis * q.y));
      continue;
    }
    for (int j = 0; j < segments; ++j) {
      auto [c, s] = CircleStep(j, segments);
      ring[i].push_back(Vertex(m, origin + ex * (q.x * c) + ey * (q.x * s) + axis * q.y));
    }
  }
  const int last = poles ? n - 1 : n;
  for (int i = 0; i < last; ++i) {
    const int k = (i + 1) % n;
    for (int j = 0; j < segments; ++j) {
      const int jn = (j + 1) % segments;
      int a = ring[i][j], b = ring[i][jn], c = ring[k][jn], d = ring[k][j];
      if (a != b) m.AddTriangle(a, b, c);
      if (c != d) m.AddTriangle(a, c, d);
    }
  }
}

void MeshBuilder::VerticalLathe(int part, const std::vector<Point>& profile, double cx, double cy, double sx, double sy,
                                int segments) {
  Lathe(part, profile, {cx, cy, 0.0}, {sx, 0, 0}, {0, sy, 0}, {0, 0, 1}, segments);
}

void MeshBuilder::Tube(int part, Vec3 a, Vec3 b, double r, int segments) {
  Vec3 axis = b - a;
  const double length = Norm(axis);
  axis = axis * (1.0 / length);
  // ex: a unit vector across the axis, along a coordinate axis when the tube is axis-aligned (exact extremes).
  Vec3 helper = std::abs(axis.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
  Vec3 ex = Normalized(Cross(helper, axis));
  Vec3 ey = Cross(axis, ex);
  Lathe(part, {{0, 0}, {r, 0}, {r, length}, {0, length}}, a, ex, ey, axis, segments);
}

void MeshBuilder::Cylinder(int part, double cx, double cy, double rx, double ry, double z0, double z1, int segments) {
  VerticalLathe(part, {{0, z0}, {1, z0}, {1, z1}, {0, z1}}, cx, cy, rx, ry, segments);
}

void MeshBuilder::Ellipsoid(int part, double cx, double cy, double rx, double ry, double z0, double z1, int segments) {
  constexpr int kRings = 8;  // even: the equator (r = 1 exactly) is one of them
  std::vector<Point> profile;
  for (int i = 0; i <= kRings; ++i) {
    const double a = std::numbers::pi * i / kRings;
    const double r = i == 0 || i == kRings ? 0.0 : i == kRings / 2 ? 1.0 : std::sin(a);
    const double z = i == 0 ? z0 : i == kRings ? z1 : z0 + (z1 - z0) * (1.0 - std::cos(a)) / 2;
    profile.push_back({r, z});
  }
  VerticalLathe(part, profile, cx, cy, rx, ry, segments);
}

void MeshBuilder::RestingEllipsoid(int part, double cx, double cy, double rx, double ry, double z0, double z1, int segments) {
  constexpr int kRings = 8;
  const double cut = (1.0 - std::cos(std::numbers::pi / kRings)) / 2.0;  // the lowest ring's height, 0..1
  std::vector<Point> profile{{0.0, z0}};
  for (int i = 1; i <= kRings; ++i) {
    const double a = std::numbers::pi * i / kRings;
    const double r = i == kRings ? 0.0 : i == kRings / 2 ? 1.0 : std::sin(a);
    profile.push_back({r, z0 + (z1 - z0) * ((1.0 - std::cos(a)) / 2.0 - cut) / (1.0 - cut)});
  }
  VerticalLathe(part, profile, cx, cy, rx, ry, segments);
}

int MeshBuilder::Surface(double z, const Ring& polygon, double clear) {
  SupportSurface s;
  s.z = Snap(z);
  for (Point p : polygon) s.polygon.push_back({Snap(p.x), Snap(p.y)});
  // Snapped as its top is, so a cavity's floor clearance equals the snapped cavity height exactly.
  s.clear_height = Snap(Snap(z + clear) - s.z);
  s.from = "procedural";
  surfaces_.push_back(std::move(s));
  return static_cast<int>(surfaces_.size()) - 1;
}

void MeshBuilder::AddCavity(Vec3 lo, Vec3 hi, std::string open, int floor_surface, double rail) {
  assert(floor_surface < 0 || std::abs(surfaces_[floor_surface].z - Snap(lo.z)) < 1e-9);
  cavities_.push_back({SnapV(lo), SnapV(hi), std::move(open), floor_surface, std::nullopt});
  if (rail > 0.0) cavities_.back().rail = Snap(rail);
}

Ring Rect(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

Ring Ellipse(double cx, double cy, double rx, double ry, int segments) {
  Ring out;
  for (int j = 0; j < segments; ++j) {
    auto [c, s] = CircleStep(j, segments);
    out.push_back({Snap(cx + rx * c), Snap(cy + ry * s)});
  }
  return out;
}

// ---------------------------------------------------------------------------------------------- params

double ParamValues::Real(std::string_view key) const {
  auto it = numbers.find(key);
  assert(it != numbers.end() && "every parameter is set before a generator runs");
  return it->second;
}

int ParamValues::Int(std::string_view key) const { return static_cast<int>(std::lround(Real(key))); }

const std::string& ParamValues::Word(std::string_view key) const {
  auto it = words.find(key);
  assert(it != words.end() && "every parameter is set before a generator runs");
  return it->second;
}

void SetIfMissing(ParamValues& p, const std::string& key, const std::function<double()>& f) {
  if (!p.numbers.count(key)) p.numbers[key] = f();
}

ProceduralParam CountParam(std::string name, std::string meaning, int min, int max, int fixed_default) {
  ProceduralParam p;
  p.name = std::move(name);
  p.kind = ProceduralParam::Kind::kInteger;
  p.meaning = std::move(meaning);
  p.min = min;
  p.max = max;
  p.automatic = fixed_default < 0;
  p.default_value = fixed_default < 0 ? min : fixed_default;
  return p;
}

// Clear height above a surface with nothing of the asset over it. On the floor: up to the ceiling of a
// storey (2.625 m clear, SCENE.md), at least 0.1 m. Hung or standing on another object the asset does not
// know its height above the floor: 0.3 m, what small things on a shelf or a counter need. The solver
// still checks the room's real geometry.
double Gen::OpenAbove(double z) const {
  constexpr double kStoreyClear = 2.625;
  if (category.placement == Placement::kFloor) return std::max(0.1, kStoreyClear - z);
  return 0.3;
}

int Gen::TopSurface(double z, double x0, double y0, double x1, double y1) {
  return out.Surface(z, Rect(x0, y0, x1, y1), OpenAbove(z));
}

void Gen::Leg(int part, double cx, double cy, double z0, double z1, double half) {
  const double l = z1 - z0;
  if (style == "modern" || style == "rustic") {
    const double a = style == "modern" ? half * 0.7 : half;
    out.Box(part, {cx - a, cy - a, z0}, {cx + a, cy + a, z1});
  } else if (style == "classic") {
    out.VerticalLathe(part,
                      {{0, z0},
                       {0.6, z0},
                       {0.6, z0 + 0.08 * l},
                       {1.0, z0 + 0.18 * l},
                       {0.7, z0 + 0.32 * l},
                       {0.55, z0 + 0.7 * l},
                       {0.85, z0 + 0.86 * l},
                       {0.85, z1},
                       {0, z1}},
                      cx, cy, half, half, 12);
  } else {
    out.VerticalLathe(part, {{0, z0}, {0.6, z0}, {1.0, z1}, {0, z1}}, cx, cy, half, half, 12);
  }
}

}  // namespace villa::procedural
