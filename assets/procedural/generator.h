#pragma once
// Internal to the procedural generators (assets/procedural/*.cpp): the random stream, the style palettes,
// the mesh builder with the primitives every generator uses, and the table entry a generator provides.
// Sizes in metres, asset frame (z up, origin at the bottom centre, front = -y).
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "assets/asset_mesh.h"
#include "assets/category.h"
#include "assets/procedural.h"
#include "util/hash.h"

namespace villa::procedural {

// util's SplitMix64 stream with the draws the generators use: the same numbers on every machine and
// standard library (no std distributions).
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : stream_(seed) {}
  std::uint64_t Next();
  double Unit();                       // [0, 1)
  double Range(double lo, double hi);  // [lo, hi)
  int Int(int lo, int hi);             // [lo, hi], lo when hi < lo
  bool Chance(double p) { return Unit() < p; }
  template <class T>
  const T& Pick(const std::vector<T>& items) {
    return items[Int(0, static_cast<int>(items.size()) - 1)];
  }

 private:
  SplitMix64 stream_;
};
std::uint64_t HashText(std::string_view text);  // FNV-1a, 64 bit (util/hash.h)
std::uint64_t MixSeed(std::uint64_t a, std::uint64_t b);

// Coordinates are kept on a 0.1 mm grid: records written with 4 decimals are then exact, and the few
// ulps by which sin/cos differ between libm versions vanish.
double Snap(double v);

// Colours and materials of one style. Every list is non-empty.
struct Palette {
  std::vector<MeshMaterial> wood;    // carcasses, tops, frames
  std::vector<MeshMaterial> paint;   // lacquered fronts, painted panels
  std::vector<MeshMaterial> fabric;  // upholstery, cushions, clothes
  std::vector<MeshMaterial> metal;   // legs, handles, rails
  std::vector<MeshMaterial> accent;  // book covers, toys, decor, ceramics
};
const Palette& StylePalette(std::string_view style);
// Materials every style shares.
MeshMaterial Glass();
MeshMaterial MirrorGlass();
MeshMaterial ScreenBlack();
MeshMaterial Porcelain();  // toilets, basins, plates
MeshMaterial Paper();      // page blocks
MeshMaterial Foliage(Rng& rng);
MeshMaterial Soil();
MeshMaterial Appliance(std::string_view style);  // white, steel or black body of an appliance

// Accumulates pieces (each a closed solid, its own vertices) per material, and the record's surfaces and
// cavities. Every coordinate passes through Snap.
class MeshBuilder {
 public:
  int Part(const MeshMaterial& material);  // index of the part with this material (made on first use)

  // Axis-aligned box lo..hi (lo < hi on every axis).
  void Box(int part, Vec3 lo, Vec3 hi);
  // Six quads over eight corners: c[0..3] the bottom ring counter-clockwise seen from above, c[4..7] the
  // top ring above them in the same order. Any convex hexahedron (tilted backs, tapered bodies).
  void Hexahedron(int part, const std::array<Vec3, 8>& c);
  // A box whose middle ring (z = lo.z + (hi.z - lo.z) * waist) is the full lo..hi rectangle and whose top
  // and bottom faces are inset by `inset` m: a cushion or pillow.
  void Cushion(int part, Vec3 lo, Vec3 hi, double inset, double waist = 0.5);
  // Box lo..hi with a pocket open at the top: walls `wall` m thick, floor `floor` m thick (a tub, a drawer,
  // a crate).
  void Tray(int part, Vec3 lo, Vec3 hi, double wall, double floor);
  // Solid of revolution. `profile` holds (r, z) points, counter-clockwise around the solid's cross-section
  // in the (r, z) half-plane (r >= 0): either starting and ending on the axis (r = 0: poles), or a closed
  // ring with r > 0 everywhere (a ring, a roll). Point p of the profile at angle a lands at
  // origin + ex * (r cos a) + ey * (r sin a) + axis * z; (ex, ey, axis) right-handed, ex and ey may be
  // scaled (ellipses). `segments` is a multiple of 4, so the extremes along ex and ey are exact.
  void Lathe(int part, const std::vector<Point>& profile, Vec3 origin, Vec3 ex, Vec3 ey, Vec3 axis, int segments);
  // Vertical lathe about (cx, cy): radii scaled by (sx, sy) along x and y.
  void VerticalLathe(int part, const std::vector<Point>& profile, double cx, double cy, double sx, double sy,
                     int segments);
  // A cylinder of radius r from a to b.
  void Tube(int part, Vec3 a, Vec3 b, double r, int segments = 8);
  // A vertical elliptic cylinder, cross-section radii (rx, ry), from z0 to z1.
  void Cylinder(int part, double cx, double cy, double rx, double ry, double z0, double z1, int segments = 16);
  // An ellipsoid about (cx, cy) with radii (rx, ry), from z0 to z1.
  void Ellipsoid(int part, double cx, double cy, double rx, double ry, double z0, double z1, int segments = 12);
  // The same flattened where it rests: its lowest ring (38 % of the radius) on z0, the rest scaled up to z1
  // (a soft ball, a sitting teddy, a pebble: on its pole it balanced on a point and rolled in a simulator).
  void RestingEllipsoid(int part, double cx, double cy, double rx, double ry, double z0, double z1, int segments = 12);

  // A support surface: polygon (CCW) at height z, `clear` m free above it. Returns its index.
  int Surface(double z, const Ring& polygon, double clear);
  // A cavity box; `floor_surface` its bottom's surface index (its z must be lo.z).
  // `rail`: the top of a hanging rail just above the box (0: none).
  void AddCavity(Vec3 lo, Vec3 hi, std::string open, int floor_surface, double rail = 0.0);

  const std::vector<SupportSurface>& surfaces() const { return surfaces_; }
  const std::vector<Cavity>& cavities() const { return cavities_; }
  AssetMesh& mesh() { return mesh_; }

 private:
  TriangleMesh& Mesh(int part) { return mesh_.parts[part].mesh; }
  AssetMesh mesh_;
  std::vector<SupportSurface> surfaces_;
  std::vector<Cavity> cavities_;
};

// The rectangle x0..x1 x y0..y1, counter-clockwise.
Ring Rect(double x0, double y0, double x1, double y1);
// An ellipse (radii rx, ry about cx, cy) as the polygon a vertical lathe of `segments` makes.
Ring Ellipse(double cx, double cy, double rx, double ry, int segments);

// Parameter values of one asset (numbers and words), after parsing and defaults.
struct ParamValues {
  std::map<std::string, double, std::less<>> numbers;
  std::map<std::string, std::string, std::less<>> words;
  double Real(std::string_view key) const;
  int Int(std::string_view key) const;
  const std::string& Word(std::string_view key) const;
  bool Has(std::string_view key) const { return numbers.count(key) || words.count(key); }
};

// What a generator's build function works with.
struct Gen {
  const CategoryInfo& category;
  const ParamValues& params;
  const Palette& palette;
  std::string style;
  double w, d, h;  // the asset's box, m
  Rng rng;         // seeded from the seed, the generator and the category
  MeshBuilder out;

  bool Is(std::string_view category_name) const { return category.name == category_name; }
  // Clear height for a surface with nothing of the asset above it (see docs/ASSETS.md).
  double OpenAbove(double z) const;
  // The top surface x0..x1 x y0..y1 at z with OpenAbove(z) clearance.
  int TopSurface(double z, double x0, double y0, double x1, double y1);
  // A vertical leg at (cx, cy) from z0 to z1, at most `half` m from its axis, shaped by the style: modern a
  // square bar, classic turned, rustic a square post, scandinavian a tapered round leg.
  void Leg(int part, double cx, double cy, double z0, double z1, double half);
};

// One generator: its listing (name, categories, its own parameters besides category, d, h, seed, style,
// w), how automatic parameters are chosen, and how it builds.
struct GeneratorDef {
  std::string name = {};
  std::string description = {};
  std::vector<std::string> categories = {};
  std::vector<ProceduralParam> extra = {};
  // Sets every automatic extra parameter the id left out; `rng` is a stream of its own.
  std::function<void(ParamValues&, const CategoryInfo&, Rng&)> resolve = {};
  std::function<void(Gen&)> build = {};
};

// A count parameter (kInteger), automatic unless `fixed_default` >= 0.
ProceduralParam CountParam(std::string name, std::string meaning, int min, int max, int fixed_default = -1);

// The generators of each file.
std::vector<GeneratorDef> StorageGenerators();  // storage.cpp
std::vector<GeneratorDef> TableGenerators();    // tables.cpp
std::vector<GeneratorDef> SeatingGenerators();  // seating.cpp
std::vector<GeneratorDef> FixtureGenerators();  // fixtures.cpp: appliances, bathroom, lamps, screens
std::vector<GeneratorDef> SmallGenerators();    // small.cpp: books, dishes, clothes, decor

// Sets `key` to f() when the id left it out.
void SetIfMissing(ParamValues& p, const std::string& key, const std::function<double()>& f);

}  // namespace villa::procedural
