// Every procedural generator, at its defaults and at random parameters: the record round-trips, its size is
// the mesh's box, surfaces lie on the mesh with their clear height free, cavities are empty and open ones
// reachable from their open side, every piece is a closed solid, and the id rebuilds the same bytes.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <sstream>

#include "assets/asset.h"
#include "assets/category.h"
#include "assets/procedural.h"
#include "ray_cast.h"

namespace villa {
namespace {

using test::FirstHit;
using test::Ray;

// ------------------------------------------------------------------ helpers

Point Centroid(const Ring& ring) {
  Point c{0, 0};
  for (Point p : ring) c = {c.x + p.x / ring.size(), c.y + p.y / ring.size()};
  return c;
}

// The centroid, and every vertex and edge midpoint moved 15 % of the way to the centroid (inside a convex
// polygon, clear of its edges).
std::vector<Point> SamplePoints(const Ring& ring) {
  const Point c = Centroid(ring);
  std::vector<Point> out{c};
  auto in = [&](Point p) { return Point{p.x + 0.15 * (c.x - p.x), p.y + 0.15 * (c.y - p.y)}; };
  for (size_t i = 0; i < ring.size(); ++i) {
    const Point a = ring[i], b = ring[(i + 1) % ring.size()];
    out.push_back(in(a));
    out.push_back(in({(a.x + b.x) / 2, (a.y + b.y) / 2}));
  }
  return out;
}

std::string Format(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3f", v);
  return buffer;
}

// The key=value pairs of an id.
std::map<std::string, std::string> IdValues(const std::string& id) {
  std::map<std::string, std::string> out;
  std::stringstream query(id.substr(id.find('?') + 1));
  for (std::string pair; std::getline(query, pair, '&');)
    out[pair.substr(0, pair.find('='))] = pair.substr(pair.find('=') + 1);
  return out;
}

constexpr double kTol = 0.001;  // m: surfaces lie on the mesh within this
constexpr double kEps = 0.001;  // m: cavity boxes shrunk by this before rays test them

// Everything the contract promises of one procedural asset.
void CheckAsset(const ProceduralAsset& asset) {
  const AssetRecord& r = asset.record;
  INFO(r.id);
  const TriangleMesh merged = asset.mesh.Merged();

  // The record round-trips through its JSON, and the id alone rebuilds the same bytes.
  const std::string json = AssetToJson(r).dump();
  auto read = AssetFromJson(nlohmann::json::parse(json), "test");
  REQUIRE(read.ok());
  CHECK(AssetToJson(*read).dump() == json);
  auto again = MakeProceduralAsset(r.id);
  REQUIRE(again.ok());
  CHECK(AssetToJson(again->record).dump() == json);
  REQUIRE(again->mesh.parts.size() == asset.mesh.parts.size());
  for (size_t i = 0; i < asset.mesh.parts.size(); ++i) {
    CHECK(again->mesh.parts[i].material == asset.mesh.parts[i].material);
    CHECK(again->mesh.parts[i].mesh.vertices == asset.mesh.parts[i].mesh.vertices);
    CHECK(again->mesh.parts[i].mesh.triangles == asset.mesh.parts[i].mesh.triangles);
  }

  // Size: the mesh's exact box, the requested one, origin at the bottom centre.
  const Box3 box = merged.Bounds();
  auto values = IdValues(r.id);
  const Vec3 want{std::stod(values["w"]), std::stod(values["d"]), std::stod(values["h"])};
  CHECK(r.size.x == Approx(want.x).margin(1e-9));
  CHECK(r.size.y == Approx(want.y).margin(1e-9));
  CHECK(r.size.z == Approx(want.z).margin(1e-9));
  CHECK(box.max.x - box.min.x == Approx(r.size.x).margin(1e-9));
  CHECK(box.max.y - box.min.y == Approx(r.size.y).margin(1e-9));
  CHECK(box.max.z - box.min.z == Approx(r.size.z).margin(1e-9));
  CHECK(box.min.x == Approx(-box.max.x).margin(1e-9));
  CHECK(box.min.y == Approx(-box.max.y).margin(1e-9));
  CHECK(box.min.z == Approx(0.0).margin(1e-12));
  CHECK(r.mesh.triangles == asset.mesh.TriangleCount());
  CHECK(r.mesh.file.empty());
  CHECK(r.source.kind == "procedural");

  // Every piece is a closed, outward solid.
  CHECK(r.mesh.watertight);
  for (const AssetMeshPart& part : asset.mesh.parts)
    for (const TriangleMesh& piece : MeshPieces(part.mesh)) {
      const SolidCheck check = CheckSolid(piece);
      INFO("part " << part.material.name << ", piece of " << piece.triangles.size() << " triangles");
      CHECK(check.closed);
      CHECK(check.volume > 0.0);
    }

  // Affordances the category promises.
  const CategoryInfo* category = FindCategory(r.category);
  REQUIRE(category);
  if (category->has_surface) CHECK(!r.support_surfaces.empty());
  if (category->has_cavity) CHECK(!r.cavities.empty());
  if (r.Has(kProvider)) CHECK(!(r.support_surfaces.empty() && r.cavities.empty()));

  // Surfaces lie on the mesh (a ray down from just above meets it at z) with their clear height free.
  for (size_t i = 0; i < r.support_surfaces.size(); ++i) {
    const SupportSurface& s = r.support_surfaces[i];
    INFO("surface " << i << " at z = " << s.z);
    CHECK(s.from == "procedural");
    CHECK(s.clear_height > 0.0);
    for (Point p : SamplePoints(s.polygon)) {
      INFO("at (" << p.x << ", " << p.y << ")");
      auto down = FirstHit(merged, {{p.x, p.y, s.z + 0.01}, {0, 0, -1}});
      REQUIRE(down);
      CHECK(std::abs(*down - 0.01) <= kTol);
      auto up = FirstHit(merged, {{p.x, p.y, s.z + kTol}, {0, 0, 1}});
      if (up) CHECK(*up >= s.clear_height - 2 * kTol);
    }
  }

  // Cavities: inside the box, empty, their floor surface their bottom; open ones reachable from -y and
  // closed ones not.
  for (size_t i = 0; i < r.cavities.size(); ++i) {
    const Cavity& c = r.cavities[i];
    INFO("cavity " << i);
    CHECK(c.min.x >= box.min.x);
    CHECK(c.max.x <= box.max.x);
    CHECK(c.min.y >= box.min.y);
    CHECK(c.max.y <= box.max.y);
    CHECK(c.min.z >= box.min.z);
    CHECK(c.max.z <= box.max.z);
    REQUIRE(c.floor_surface >= 0);
    REQUIRE(c.floor_surface < static_cast<int>(r.support_surfaces.size()));
    const SupportSurface& floor = r.support_surfaces[c.floor_surface];
    CHECK(floor.z == c.min.z);
    CHECK(floor.clear_height == Approx(c.max.z - c.min.z).margin(1e-9));
    Box3 fb;
    for (Point p : floor.polygon) fb.Add(Vec3{p.x, p.y, 0});
    CHECK(fb.min.x == c.min.x);
    CHECK(fb.max.x == c.max.x);
    CHECK(fb.min.y == c.min.y);
    CHECK(fb.max.y == c.max.y);
    const Vec3 lo{c.min.x + kEps, c.min.y + kEps, c.min.z + kEps}, hi{c.max.x - kEps, c.max.y - kEps, c.max.z - kEps};
    constexpr int kGrid = 4;
    auto at = [](double a, double b, int k) { return a + (b - a) * (k + 0.5) / kGrid; };
    for (int u = 0; u < kGrid; ++u)
      for (int v = 0; v < kGrid; ++v) {
        const Ray rays[3] = {{{lo.x, at(lo.y, hi.y, u), at(lo.z, hi.z, v)}, {1, 0, 0}},
                             {{at(lo.x, hi.x, u), lo.y, at(lo.z, hi.z, v)}, {0, 1, 0}},
                             {{at(lo.x, hi.x, u), at(lo.y, hi.y, v), lo.z}, {0, 0, 1}}};
        const double lengths[3] = {hi.x - lo.x, hi.y - lo.y, hi.z - lo.z};
        for (int a = 0; a < 3; ++a) {
          auto hit = FirstHit(merged, rays[a]);
          if (hit) CHECK(*hit > lengths[a]);
        }
        // From in front of the asset towards +y through the cavity's front face.
        const Ray in{{at(lo.x, hi.x, u), box.min.y - 0.05, at(lo.z, hi.z, v)}, {0, 1, 0}};
        auto hit = FirstHit(merged, in);
        const double front = c.min.y - in.origin.y;
        if (c.open == "-y") {
          if (hit) CHECK(*hit >= front + kEps);
        } else {
          CHECK(c.open == "closed");
          REQUIRE(hit);
          CHECK(*hit <= front + kEps);
        }
      }
  }
}

// A random value of a parameter, written as an id writes it.
std::string RandomValue(const ProceduralParam& p, std::mt19937_64& rng) {
  const double u = static_cast<double>(rng() >> 11) * 0x1.0p-53;
  switch (p.kind) {
    case ProceduralParam::Kind::kChoice:
      return p.choices[rng() % p.choices.size()];
    case ProceduralParam::Kind::kInteger: {
      const double span = std::min(p.max - p.min, 1e6);
      return std::to_string(static_cast<long long>(p.min + std::floor(u * (span + 1))));
    }
    case ProceduralParam::Kind::kReal:
      return Format(std::min(p.max, std::round((p.min + u * (p.max - p.min)) * 1000) / 1000));
  }
  return "";
}

TEST_CASE("Every procedural generator at its defaults meets the asset contract", "[assets][procedural]") {
  for (const ProceduralGenerator& g : ProceduralGenerators()) {
    for (const std::string& category : g.categories) {
      const std::string id = "proc:" + g.name + (g.categories.size() > 1 ? "?category=" + category : "");
      auto asset = MakeProceduralAsset(id);
      INFO(id);
      REQUIRE(asset.ok());
      CHECK(asset->record.category == category);
      CheckAsset(*asset);
    }
  }
}

TEST_CASE("Every procedural generator at random parameters meets the asset contract", "[assets][procedural]") {
  std::mt19937_64 rng(20261122);
  for (const ProceduralGenerator& g : ProceduralGenerators()) {
    for (int trial = 0; trial < 12; ++trial) {
      // The category first: sizes are drawn from its own usual range.
      const std::string category = g.categories[rng() % g.categories.size()];
      const CategoryInfo* info = FindCategory(category);
      REQUIRE(info);
      std::string id = "proc:" + g.name;
      char sep = '?';
      for (ProceduralParam p : g.params) {
        if (p.automatic && rng() % 2 == 0) continue;  // left to the generator half the time
        std::string value = p.name == "category" ? category : RandomValue(p, rng);
        if (p.name == "w" || p.name == "d" || p.name == "h") {
          double Vec3::*axis = p.name == "w" ? &Vec3::x : p.name == "d" ? &Vec3::y : &Vec3::z;
          p.min = info->size_min.*axis;
          p.max = info->size_max.*axis;
          value = RandomValue(p, rng);
        }
        id += sep + p.name + "=" + value;
        sep = '&';
      }
      INFO(id);
      auto asset = MakeProceduralAsset(id);
      if (!asset.ok())
        FAIL_CHECK(asset.error());
      else
        CheckAsset(*asset);
    }
  }
}

}  // namespace
}  // namespace villa
