#include <catch2/catch.hpp>

#include <cstdlib>
#include <thread>

#include "assets/asset_library.h"
#include "assets/mesh_affordances.h"
#include "assets/mesh_quality.h"
#include "assets/sh3d_import.h"
#include "sh3f_fixture.h"

namespace villa {
namespace {

// Restores an environment variable when the test ends.
class EnvGuard {
 public:
  explicit EnvGuard(const char* name) : name_(name) {
    const char* v = std::getenv(name);
    if (v) old_ = v;
  }
  ~EnvGuard() {
    if (old_) setenv(name_, old_->c_str(), 1);
    else unsetenv(name_);
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

TEST_CASE("The library folder: --library, else VILLA_ASSETS, else XDG_DATA_HOME, else ~/.local/share", "[assets][library]") {
  EnvGuard a("VILLA_ASSETS"), x("XDG_DATA_HOME"), h("HOME");
  setenv("HOME", "/home/someone", 1);
  unsetenv("VILLA_ASSETS");
  unsetenv("XDG_DATA_HOME");
  CHECK(DefaultLibraryDir() == "/home/someone/.local/share/villa/assets");
  setenv("XDG_DATA_HOME", "relative/ignored", 1);
  CHECK(DefaultLibraryDir() == "/home/someone/.local/share/villa/assets");
  setenv("XDG_DATA_HOME", "/data", 1);
  CHECK(DefaultLibraryDir() == "/data/villa/assets");
  setenv("VILLA_ASSETS", "/srv/assets", 1);
  CHECK(DefaultLibraryDir() == "/srv/assets");
}

TEST_CASE("Meshes load on first use, once, shared by every thread that asks", "[assets][library]") {
  auto dir = test::FreshDir("library_cache");
  test::WriteFixtureLibrary(dir / "from");
  REQUIRE(ImportSh3dLibraries(dir / "from", dir / "lib", {}).ok());
  auto library = AssetLibrary::Open(dir / "lib");
  REQUIRE(library.ok());
  const std::string id = "sh3d:TestLib#bookcase";
  std::vector<std::shared_ptr<const AssetMesh>> got(8);
  std::vector<std::thread> threads;
  for (int t = 0; t < 8; ++t)
    threads.emplace_back([&, t] {
      auto mesh = library->Mesh(id);
      if (mesh.ok()) got[t] = *mesh;
    });
  for (auto& t : threads) t.join();
  for (const auto& m : got) {
    REQUIRE(m);
    CHECK(m.get() == got[0].get());  // one load, one mesh
  }
  CHECK(got[0]->TriangleCount() == library->Find(id)->mesh.triangles);
  // The file is read once: removing it now changes nothing for this library.
  std::filesystem::remove(dir / "lib" / library->Find(id)->mesh.file);
  CHECK(library->Mesh(id).ok());

  CHECK(library->Mesh("sh3d:TestLib#nothing").error() == "sh3d:TestLib#nothing: no such asset in " + (dir / "lib").string());
  CHECK(library->Mesh("proc:bookcase?rows=3").error() ==
        "proc:bookcase?rows=3: procedural asset, but no generator is available to build its mesh");
  // A library that knows how to make procedural meshes asks its maker, once per id.
  int made = 0;
  library->SetProceduralMeshMaker([&](std::string_view) -> Result<AssetMesh> {
    ++made;
    return **library->Mesh("sh3d:TestLib#chest");
  });
  CHECK(library->Mesh("proc:box?w=1").ok());
  CHECK(library->Mesh("proc:box?w=1").ok());
  CHECK(made == 1);

  auto missing = AssetLibrary::Open(dir / "nowhere");
  REQUIRE_FALSE(missing.ok());
  CHECK(missing.error() == (dir / "nowhere").string() + ": no asset library here (no assets.jsonl; run `villa assets import`)");
  std::filesystem::remove_all(dir);
}

TEST_CASE("Edge statistics tell a closed box from an open one", "[assets][mesh]") {
  AssetMesh box;
  box.parts.push_back({{"a"}, {}});
  // A unit cube as two parts: five faces in one, the lid in the other (edges weld across parts).
  const Vec3 corners[8] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
  for (const Vec3& c : corners) box.parts[0].mesh.vertices.push_back(c);
  const int quads[6][4] = {{0, 2, 3, 1}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}, {4, 5, 7, 6}};
  for (int q = 0; q < 5; ++q) {
    box.parts[0].mesh.AddTriangle(quads[q][0], quads[q][1], quads[q][2]);
    box.parts[0].mesh.AddTriangle(quads[q][0], quads[q][2], quads[q][3]);
  }
  EdgeStatistics open = MeshEdgeStatistics(box);
  CHECK_FALSE(open.Watertight());
  CHECK(open.boundary == 4);
  CHECK(open.edges == 17);
  AssetMeshPart lid{{"b"}, {}};
  for (const Vec3& c : corners) lid.mesh.vertices.push_back(c);
  lid.mesh.AddTriangle(4, 5, 7);
  lid.mesh.AddTriangle(4, 7, 6);
  box.parts.push_back(lid);
  EdgeStatistics closed = MeshEdgeStatistics(box);
  CHECK(closed.Watertight());
  CHECK(closed.edges == 18);
  CHECK(closed.ManifoldShare() == Approx(1.0));
  box.parts.push_back(lid);  // the lid twice: its edges are used three times
  CHECK(MeshEdgeStatistics(box).non_manifold == 5);
}

TEST_CASE("Decimation meets the budget, keeps materials and the outline", "[assets][mesh]") {
  // A finely tessellated sphere-ish blob: a 60 x 60 grid wrapped on a unit sphere, two materials.
  AssetMesh blob;
  for (int part = 0; part < 2; ++part) {
    AssetMeshPart p{{part ? "red" : "blue", part ? 1.0 : 0.0, 0.0, part ? 0.0 : 1.0, 1.0}, {}};
    const int n = 60;
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        double theta = M_PI * j / n, phi = M_PI * (part + static_cast<double>(i) / n);
        p.mesh.vertices.push_back({std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), 1 + std::cos(theta)});
      }
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        int a = j * (n + 1) + i;
        p.mesh.AddTriangle(a, a + n + 1, a + n + 2);
        p.mesh.AddTriangle(a, a + n + 2, a + 1);
      }
    blob.parts.push_back(std::move(p));
  }
  REQUIRE(blob.TriangleCount() == 14400);
  auto simple = DecimateToBudget(blob, 2000);
  REQUIRE(simple.ok());
  CHECK(simple->TriangleCount() <= 2000);
  CHECK(simple->TriangleCount() > 500);  // the finest grid that fits, not the coarsest
  REQUIRE(simple->parts.size() == 2);
  CHECK(simple->parts[1].material.name == "red");
  Box3 before = blob.Bounds(), after = simple->Bounds();
  CHECK(after.max.z - after.min.z == Approx(before.max.z - before.min.z).epsilon(0.1));
  CHECK(after.max.x - after.min.x == Approx(before.max.x - before.min.x).epsilon(0.1));
  CHECK(DecimateToBudget(blob, 20000)->TriangleCount() == 14400);  // within budget: unchanged
  CHECK_FALSE(DecimateToBudget(blob, 1).ok());
}

TEST_CASE("Affordance options are checked", "[assets][mesh]") {
  AffordanceOptions o;
  CHECK(o.Check().empty());
  o.min_share = 0;
  CHECK(o.Check() == "min_share must be in (0, 1]");
  Sh3dImportOptions import;
  import.max_triangles = 0;
  CHECK(import.Check() == "max_triangles must be > 0, got 0");
}

TEST_CASE("Decimation keeps solid pieces apart and keeps a thin piece it would erase", "[assets][mesh][issue31]") {
  // A 1 m cube of 60 x 60 quads a face (a table's top) and, 2 cm below it and apart from it, a thin
  // rod 1 cm across and 1 m long of 400 segments (a tube frame): separate pieces of one material.
  AssetMeshPart part{{"steel", 0.7, 0.7, 0.7, 1.0}, {}};
  TriangleMesh& m = part.mesh;
  const int n = 60;
  for (int face = 0; face < 6; ++face) {
    const int axis = face / 2, side = face % 2;
    const int base = static_cast<int>(m.vertices.size());
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        double c[3];
        c[axis] = side;
        c[(axis + 1) % 3] = static_cast<double>(i) / n;
        c[(axis + 2) % 3] = static_cast<double>(j) / n;
        m.vertices.push_back({c[0] - 0.5, c[1] - 0.5, c[2] + 0.2});
      }
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int a = base + j * (n + 1) + i;
        if (side) {
          m.AddTriangle(a, a + n + 2, a + n + 1);
          m.AddTriangle(a, a + 1, a + n + 2);
        } else {
          m.AddTriangle(a, a + n + 1, a + n + 2);
          m.AddTriangle(a, a + n + 2, a + 1);
        }
      }
  }
  const int rod_first = static_cast<int>(m.vertices.size());
  const int segments = 400;
  for (int s = 0; s <= segments; ++s)
    for (int k = 0; k < 3; ++k) {
      const double a = 2.0 * M_PI * k / 3.0;
      m.vertices.push_back({-0.5 + static_cast<double>(s) / segments, 0.005 * std::cos(a), 0.005 * std::sin(a) + 0.1});
    }
  for (int s = 0; s < segments; ++s)
    for (int k = 0; k < 3; ++k) {
      const int a = rod_first + 3 * s + k, b = rod_first + 3 * s + (k + 1) % 3;
      m.AddTriangle(a, b, b + 3);
      m.AddTriangle(a, b + 3, a + 3);
    }
  AssetMesh mesh;
  mesh.parts.push_back(part);
  const int rod = 6 * segments, cube = 6 * 2 * n * n;
  REQUIRE(mesh.TriangleCount() == cube + rod);
  const std::vector<std::vector<std::uint32_t>> pieces = SolidPieceIds(mesh);
  CHECK(pieces[0][0] != pieces[0][rod_first]);
  auto simple = DecimateToBudget(mesh, 4000, /*best_effort=*/true);
  REQUIRE(simple.ok());
  CHECK(simple->TriangleCount() <= 4000);
  const Box3 box = simple->Bounds();
  CHECK(box.min.z == Approx(0.1 - 0.005 * std::sqrt(0.75)).margin(1e-6));  // the rod is still there, at its height
  int low = 0;  // triangles of the rod (below the cube)
  for (const auto& t : simple->parts[0].mesh.triangles)
    low += simple->parts[0].mesh.vertices[t[0]].z < 0.15 && simple->parts[0].mesh.vertices[t[1]].z < 0.15;
  CHECK(low == rod);
  // Shared cubes (the paper's filter alone, no pieces) erase the rod.
  const AssetMesh shared = ClusterVertices(mesh, 0.05);
  int left = 0;
  for (const auto& t : shared.parts[0].mesh.triangles) left += shared.parts[0].mesh.vertices[t[0]].z < 0.15;
  CHECK(left < rod / 10);
}

}  // namespace
}  // namespace villa
