#include <catch2/catch.hpp>

#include "mesh/ray_caster.h"
#include "mesh/solids.h"

using namespace villa;

namespace {

// A closed box [x0, x1] x [0, 1] x [z0, z1] (a prism over its footprint).
TriangleMesh Box(double x0, double x1, double z0, double z1) {
  return ExtrudePlan({{x0, 0.0}, {x1, 0.0}, {x1, 1.0}, {x0, 1.0}}, {}, z0, z1);
}

}  // namespace

TEST_CASE("RayCaster: the nearest hit, its mesh, and the outward normal of the triangle hit") {
  RayCaster rays;
  REQUIRE(rays.ok());
  const int empty = rays.Add(TriangleMesh{});
  const int near_box = rays.Add(Box(0.0, 1.0, 0.0, 1.0));
  const int far_box = rays.Add(Box(3.0, 4.0, 0.0, 2.0));
  rays.Commit();
  CHECK(empty == -1);  // nothing to hit takes no id
  CHECK(near_box == 0);
  CHECK(far_box == 1);

  // Along +x at mid height: the near box's face at x = 0, facing the ray (-x).
  auto hit = rays.Cast({-1.0, 0.5, 0.5}, {1, 0, 0}, 100.0);
  REQUIRE(hit);
  CHECK(hit->mesh == near_box);
  CHECK(hit->t == Approx(1.0).margin(1e-6));
  CHECK(hit->normal.x == Approx(-1.0).margin(1e-9));
  // Starting past the near box: the far one.
  hit = rays.Cast({-1.0, 0.5, 0.5}, {1, 0, 0}, 100.0, 2.5);
  REQUIRE(hit);
  CHECK(hit->mesh == far_box);
  CHECK(hit->t == Approx(4.0).margin(1e-6));
  // Above the near box, only the taller far box is in the way; t_max short of it: no hit.
  CHECK(rays.Cast({-1.0, 0.5, 1.5}, {1, 0, 0}, 100.0)->mesh == far_box);
  CHECK_FALSE(rays.Cast({-1.0, 0.5, 1.5}, {1, 0, 0}, 3.9));
  // Straight down onto the far box's top: normal +z.
  hit = rays.Cast({3.5, 0.5, 5.0}, {0, 0, -1}, 100.0);
  REQUIRE(hit);
  CHECK(hit->t == Approx(3.0).margin(1e-6));
  CHECK(hit->normal.z == Approx(1.0).margin(1e-9));
}

TEST_CASE("RayCaster: crossings along a segment, one per face passed") {
  const RayCaster rays(Box(0.0, 1.0, 0.0, 1.0));
  const std::vector<double> crossings = rays.Crossings({-1.0, 0.5, 0.5}, {1, 0, 0}, 10.0);
  REQUIRE(crossings.size() == 2);
  CHECK(crossings[0] == Approx(1.0).margin(1e-6));
  CHECK(crossings[1] == Approx(2.0).margin(1e-6));
  CHECK(rays.Crossings({-1.0, 0.5, 0.5}, {1, 0, 0}, 0.5).empty());
}
