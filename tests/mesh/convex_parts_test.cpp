// mesh/convex_parts.h: a building's solids cut into convex prisms, whose union is the solid (volume) and
// which leave its openings open (a doorway's centre in no part).
#include <algorithm>

#include <catch2/catch.hpp>

#include "mesh/convex_parts.h"
#include "mesh/mesh.h"
#include "mesh/solids.h"

using namespace villa;

namespace {

// Inside (or on) every face plane of a convex part.
bool InsideConvex(const TriangleMesh& part, Vec3 p) {
  for (const auto& t : part.triangles) {
    const Vec3 n = Cross(part.vertices[t[1]] - part.vertices[t[0]], part.vertices[t[2]] - part.vertices[t[0]]);
    if (Dot(p - part.vertices[t[0]], n) > 1e-12) return false;
  }
  return true;
}

// Every vertex of the part on or behind each of its faces: convex.
bool Convex(const TriangleMesh& part) {
  for (const Vec3& v : part.vertices)
    if (!InsideConvex(part, v)) return false;
  return true;
}

int PartsHolding(const std::vector<TriangleMesh>& parts, Vec3 p) {
  int n = 0;
  for (const TriangleMesh& part : parts) n += InsideConvex(part, p);
  return n;
}

double Volume(const std::vector<TriangleMesh>& parts) {
  double v = 0.0;
  for (const TriangleMesh& part : parts) v += part.SignedVolume();
  return v;
}

}  // namespace

TEST_CASE("A mitred wall with a door and a window is cut into six convex prisms that leave both open") {
  WallFrame frame{{0, 0}, {1, 0}, {0, 1}, 0.2};
  // Mitred ends: the face at q = -0.1 runs 0.2 m further each way than the one at q = +0.1.
  const Ring plan{{-0.1, -0.1}, {4.1, -0.1}, {3.9, 0.1}, {0.1, 0.1}};
  const TriangleMesh wall = WallSolid(plan, frame, 0.0, 2.8, {{1.0, 2.0, 0.0, 2.1}, {2.5, 3.5, 0.9, 2.1}});
  const auto parts = ConvexPrismParts(wall);
  REQUIRE(parts);
  // Below the window's sill: the wall either side of the door; up to the heads: three piers; above: one.
  CHECK(parts->size() == 6);
  CHECK(Volume(*parts) == Approx(wall.SignedVolume()).epsilon(1e-9));
  for (const TriangleMesh& part : *parts) CHECK(Convex(part));
  CHECK(PartsHolding(*parts, {1.5, 0.0, 1.0}) == 0);  // the doorway
  CHECK(PartsHolding(*parts, {3.0, 0.0, 1.5}) == 0);  // the window
  CHECK(PartsHolding(*parts, {1.5, 0.0, 2.5}) == 1);  // over the door
  CHECK(PartsHolding(*parts, {3.0, 0.0, 0.5}) == 1);  // under the window
  CHECK(PartsHolding(*parts, {4.05, -0.09, 1.0}) == 1);  // in the mitred end
  CHECK(PartsHolding(*parts, {4.05, 0.09, 1.0}) == 0);   // past it
}

TEST_CASE("An L-shaped slab with a stair hole is cut into convex prisms that leave the hole and the notch open") {
  const Ring outer{{0, 0}, {8, 0}, {8, 4}, {4, 4}, {4, 8}, {0, 8}};
  const Ring hole{{1, 1}, {1, 3}, {3, 3}, {3, 1}};
  const TriangleMesh slab = ExtrudePlan(outer, {hole}, 2.8, 3.0);
  const auto parts = ConvexPrismParts(slab);
  REQUIRE(parts);
  CHECK(Volume(*parts) == Approx(0.2 * (48.0 - 4.0)).epsilon(1e-9));
  for (const TriangleMesh& part : *parts) CHECK(Convex(part));
  CHECK(PartsHolding(*parts, {2, 2, 2.9}) == 0);  // the stair hole
  CHECK(PartsHolding(*parts, {6, 6, 2.9}) == 0);  // outside the L
  CHECK(PartsHolding(*parts, {6, 2, 2.9}) == 1);
  CHECK(parts->size() <= 8);
}

TEST_CASE("Flights of steps side by side are cut across their width into convex prisms of their profiles") {
  // Two flights, 1 m wide each, side by side along y, rising along x in opposite directions.
  TriangleMesh flights = ExtrudeProfile({{0, 0}, {1.2, 0}, {1.2, 0.8}, {0.9, 0.8}, {0.9, 0.6}, {0.6, 0.6}, {0.6, 0.4}, {0.3, 0.4}, {0.3, 0.2}, {0, 0.2}},
                                        {0, 0}, {1, 0}, {0, -1}, -1.0, 0.0);
  const TriangleMesh other = ExtrudeProfile({{0, 0}, {1.2, 0}, {1.2, 0.2}, {0.9, 0.2}, {0.9, 0.4}, {0.6, 0.4}, {0.6, 0.6}, {0.3, 0.6}, {0.3, 0.8}, {0, 0.8}},
                                            {0, 0}, {1, 0}, {0, -1}, -2.0, -1.0);
  const double volume = flights.SignedVolume() + other.SignedVolume();
  flights.Append(other);
  const auto parts = ConvexPrismParts(flights);
  REQUIRE(parts);
  CHECK(Volume(*parts) == Approx(volume).epsilon(1e-9));
  for (const TriangleMesh& part : *parts) CHECK(Convex(part));
  CHECK(PartsHolding(*parts, {1.05, 0.5, 0.7}) == 1);  // the first flight's top step
  CHECK(PartsHolding(*parts, {0.15, 0.5, 0.7}) == 0);  // over its bottom step
  CHECK(PartsHolding(*parts, {0.15, 1.5, 0.7}) == 1);  // the second flight's top step
  CHECK(PartsHolding(*parts, {1.05, 1.5, 0.7}) == 0);
}

TEST_CASE("An imported tray (an open shell over a separate glass sheet, its rim out of level) is one solid cut with slack") {
  // The shell: bottom, outer sides, a rim sloping 0.2 mm inwards, inner sides down to the glass; the glass
  // a quad of its own vertices (as Sweet Home 3D's Scopia coffee table has it).
  TriangleMesh mesh;
  const double ox[4] = {-0.3, 0.3, 0.3, -0.3}, oy[4] = {-0.2, -0.2, 0.2, 0.2};
  const double ix[4] = {-0.27, 0.27, 0.27, -0.27}, iy[4] = {-0.17, -0.17, 0.17, 0.17};
  for (double z : {0.0, 0.05})
    for (int i = 0; i < 4; ++i) mesh.vertices.push_back({ox[i], oy[i], z});
  for (double z : {0.0498, 0.045, 0.045})
    for (int i = 0; i < 4; ++i) mesh.vertices.push_back({ix[i], iy[i], z});
  auto quad = [&](int a, int b, int c, int d) {
    mesh.AddTriangle(a, b, c);
    mesh.AddTriangle(a, c, d);
  };
  quad(0, 3, 2, 1);  // bottom
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    quad(i, j, 4 + j, 4 + i);       // outer side
    quad(4 + i, 4 + j, 8 + j, 8 + i);  // rim
    quad(8 + i, 8 + j, 12 + j, 12 + i);  // inner side
  }
  quad(16, 17, 18, 19);  // the glass, its own corners
  REQUIRE(SplitPieces(mesh).size() == 2);
  const std::vector<TriangleMesh> solids = SolidPiecesOf(mesh);
  REQUIRE(solids.size() == 1);
  CHECK(CheckSolid(solids[0]).closed);
  CHECK_FALSE(ConvexPrismParts(solids[0]));  // the rim is 0.2 mm out of level: no exact stack
  const auto parts = ConvexPrismParts(solids[0], kModelTolerance);
  REQUIRE(parts);
  CHECK(PartsHolding(*parts, {0.0, 0.0, 0.047}) == 0);   // over the glass, in the tray
  CHECK(PartsHolding(*parts, {0.0, 0.0, 0.02}) == 1);    // under it
  CHECK(PartsHolding(*parts, {0.0, -0.185, 0.048}) == 1);  // in the rim
  CHECK(Volume(*parts) == Approx(solids[0].SignedVolume()).epsilon(0.02));
}

TEST_CASE("Solids as a file with vertex normals writes them: each box is one closed solid, stacked boxes stay two") {
  // A bookcase's side and a shelf on it (touching along a face and at its edges) and a book apart.
  TriangleMesh boxes = ExtrudePlan({{0, 0}, {0.02, 0}, {0.02, 0.3}, {0, 0.3}}, {}, 0.0, 1.0);
  boxes.Append(ExtrudePlan({{0.02, 0}, {0.8, 0}, {0.8, 0.3}, {0.02, 0.3}}, {}, 0.0, 0.02));
  boxes.Append(ExtrudePlan({{0.1, 0.05}, {0.13, 0.05}, {0.13, 0.25}, {0.1, 0.25}}, {}, 0.02, 0.25));
  // As the .glb holds them: corners repeated for each face at a crease, one weld over the whole primitive.
  const ShadedMesh shaded = ShadeSmooth(boxes, 40.0);
  TriangleMesh file;
  file.vertices = shaded.vertices;
  file.triangles = shaded.triangles;
  REQUIRE(SplitPieces(file).size() > 3);  // by index, loose faces
  const std::vector<TriangleMesh> solids = SolidPiecesOf(file);
  REQUIRE(solids.size() == 3);
  std::vector<double> volumes;
  for (const TriangleMesh& solid : solids) {
    CHECK(CheckSolid(solid).closed);
    volumes.push_back(solid.SignedVolume());
  }
  std::sort(volumes.begin(), volumes.end());
  CHECK(volumes[0] == Approx(0.03 * 0.2 * 0.23));
  CHECK(volumes[1] == Approx(0.78 * 0.3 * 0.02));
  CHECK(volumes[2] == Approx(0.02 * 0.3 * 1.0));
  // The same boxes as written (closed by index) give the same three.
  CHECK(SolidPiecesOf(boxes).size() == 3);
}

TEST_CASE("A solid with slanted faces is no stack of prisms") {
  TriangleMesh tetra;
  tetra.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  tetra.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  REQUIRE(tetra.SignedVolume() > 0);
  CHECK_FALSE(ConvexPrismParts(tetra));
}
