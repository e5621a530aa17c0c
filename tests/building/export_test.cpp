#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <map>

#include "building/export.h"
#include "test_support.h"

using namespace villa;
using namespace villa::testing;
namespace fs = std::filesystem;

namespace {

fs::path TempDir(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("villa_building_test_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace

TEST_CASE("the .glb re-imports with a node per level, room and element, and the right bounds") {
  const BuildingMesh& b = ThreeFloorBuilding();
  const Layout& layout = ThreeFloorLayout();
  fs::path dir = TempDir("glb");
  fs::path out = dir / "villa.glb";
  REQUIRE(ExportBuilding(b, out, MeshFormat::kGlb));
  auto scene = ReadSceneInfo(out);
  REQUIRE(scene);
  CHECK(scene->meshes.size() == b.parts.size());
  for (int level = 0; level < 3; ++level) {
    const SceneNodeInfo* node = scene->Find("level_" + std::to_string(level));
    REQUIRE(node);
    CHECK(node->path == "villa/level_" + std::to_string(level));
  }
  for (const Room& r : layout.rooms) {
    const SceneNodeInfo* node = scene->Find(r.name());
    REQUIRE(node);
    CHECK(node->path == "villa/level_" + std::to_string(r.level) + "/" + r.name());
    CHECK(node->meshes.size() == 1);
    // Room metadata written as glTF extras comes back as node metadata.
    CHECK(node->metadata.at("category") == std::string(CategoryName(r.category)));
    CHECK(std::stod(node->metadata.at("area_m2")) == Approx(Area(r.polygon)).margin(0.01));
    CHECK(std::stoi(node->metadata.at("level")) == r.level);
  }
  for (const Element& e : layout.doors) {
    const SceneNodeInfo* node = scene->Find(e.name);
    REQUIRE(node);
    CHECK(node->path == "villa/level_" + std::to_string(e.level) + "/doors_" + std::to_string(e.level) + "/" + e.name);
  }
  for (const Element& e : layout.windows) {
    const SceneNodeInfo* node = scene->Find(e.name);
    REQUIRE(node);
    CHECK(node->path == "villa/level_" + std::to_string(e.level) + "/windows_" + std::to_string(e.level) + "/" + e.name);
  }
  for (const Element& e : layout.interiors) CHECK(scene->Find(e.name));
  CHECK(scene->Find("stair_utility-room_0/0")->path == "villa/level_0/stairs_0/stair_utility-room_0/0");
  CHECK(scene->Find("roof"));
  // glTF frame: +Y up, plan y becomes -Z; height is 3 x 2.8 m plus the roof.
  const Box3& box = scene->bounds;
  CHECK(box.min.y == Approx(0.0).margin(1e-6));
  CHECK(box.max.y == Approx(3 * 2.8 + b.slab_thickness).epsilon(1e-6));
  CHECK(box.min.x == Approx(0.0).margin(1e-6));
  CHECK(box.max.x == Approx(14.0));
  CHECK(box.min.z == Approx(-10.0));
  CHECK(box.max.z == Approx(0.0).margin(1e-6));
  // The roof mesh is the top slab: it spans the top level's footprint (9 x 7 m).
  const SceneMeshInfo& roof = scene->meshes[scene->Find("roof")->meshes[0]];
  CHECK(roof.bounds.max.x - roof.bounds.min.x == Approx(9.0));
  CHECK(roof.bounds.max.z - roof.bounds.min.z == Approx(7.0));
  CHECK(roof.bounds.min.y == Approx(3 * 2.8).epsilon(1e-6));
  // Materials: glass is transparent and blended; a floor takes its category's colour.
  std::map<std::string, SceneMaterialInfo> materials;
  for (const auto& m : scene->materials) materials[m.name] = m;
  REQUIRE(materials.count("glass"));
  CHECK(materials["glass"].alpha < 1.0);
  CHECK(materials["glass"].alpha_mode == "BLEND");
  REQUIRE(materials.count("floor-kitchen"));
  CHECK(materials["floor-kitchen"].color.r == Approx(CategoryColor(Category::kKitchen).r).margin(1e-6));
  CHECK(materials["exterior-wall"].alpha == Approx(1.0));
  fs::remove_all(dir);
}

TEST_CASE("the .glb is a well-formed binary glTF 2.0 container") {
  auto bytes = BuildingToGlb(ThreeFloorBuilding());
  REQUIRE(bytes);
  const std::string& g = *bytes;
  REQUIRE(g.size() > 28);
  auto u32 = [&](size_t at) {
    uint32_t v;
    std::memcpy(&v, g.data() + at, 4);
    return v;
  };
  CHECK(g.compare(0, 4, "glTF") == 0);
  CHECK(u32(4) == 2);
  CHECK(u32(8) == g.size());
  uint32_t json_len = u32(12);
  CHECK(json_len % 4 == 0);
  CHECK(g.compare(16, 4, "JSON") == 0);
  CHECK(g.compare(20 + json_len + 4, 4, std::string("BIN\0", 4)) == 0);
  auto json = nlohmann::json::parse(g.substr(20, json_len));
  CHECK(json["asset"]["version"] == "2.0");
  CHECK_FALSE(json.contains("extensionsUsed"));  // nothing declared that is not used
}

TEST_CASE("OBJ export writes the .obj and its .mtl, named objects for every part") {
  fs::path dir = TempDir("obj");
  fs::path out = dir / "villa.obj";
  REQUIRE(ExportBuilding(ThreeFloorBuilding(), out, MeshFormat::kObj));
  REQUIRE(fs::exists(out));
  REQUIRE(fs::exists(dir / "villa.mtl"));
  std::ifstream in(out);
  std::string text((std::istreambuf_iterator<char>(in)), {});
  CHECK(text.find("mtllib villa.mtl") != std::string::npos);
  CHECK(text.find("kitchen_0/0") != std::string::npos);
  CHECK(text.find("living0_kitchen0") != std::string::npos);
  auto scene = ReadSceneInfo(out);
  REQUIRE(scene);
  int triangles = 0, expected = 0;
  for (const auto& m : scene->meshes) triangles += m.triangles;
  for (const auto& p : ThreeFloorBuilding().parts) expected += static_cast<int>(p.mesh.triangles.size());
  CHECK(triangles == expected);
  CHECK(scene->bounds.max.y == Approx(3 * 2.8 + ThreeFloorBuilding().slab_thickness).epsilon(1e-5));
  fs::remove_all(dir);
}

TEST_CASE("export errors name the file") {
  auto status = ExportBuilding(ThreeFloorBuilding(), "/nonexistent-dir/villa.glb", MeshFormat::kGlb);
  REQUIRE_FALSE(status);
  CHECK_THAT(status.error(), Catch::Contains("/nonexistent-dir/villa.glb"));
  CHECK(ParseMeshFormat("glb") == MeshFormat::kGlb);
  CHECK_FALSE(ParseMeshFormat("fbx"));
}
