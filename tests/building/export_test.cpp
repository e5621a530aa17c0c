#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <set>

#include "building/export.h"
#include "building/glb_writer.h"
#include "building/materials.h"
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
  // Every part's triangles, no more, no fewer (a slab's edges are a second primitive of its mesh).
  size_t triangles = 0, expected = 0;
  for (const SceneMeshInfo& m : scene->meshes) triangles += m.triangles;
  for (const MeshPart& p : b.parts) expected += p.mesh.triangles.size();
  CHECK(triangles == expected);
  for (int level = 0; level < 3; ++level) {
    const SceneNodeInfo* node = scene->Find("level_" + std::to_string(level));
    REQUIRE(node);
    CHECK(node->path == "villa/level_" + std::to_string(level));
  }
  for (const Room& r : layout.rooms) {
    const SceneNodeInfo* node = scene->Find(r.name());
    REQUIRE(node);
    CHECK(node->path == "villa/level_" + std::to_string(r.level) + "/" + r.name());
    CHECK(node->meshes.size() == 3);  // the top in the room's colour, edges in the facade's, the bottom the ceiling's
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
  // Materials: glass is transparent and blended; a floor is what its room type is laid with (the kitchen's
  // tile), not the plan's zone colour.
  std::map<std::string, SceneMaterialInfo> materials;
  for (const auto& m : scene->materials) materials[m.name] = m;
  REQUIRE(materials.count("glass"));
  CHECK(materials["glass"].alpha < 1.0);
  CHECK(materials["glass"].alpha_mode == "BLEND");
  MeshPart kitchen_floor;
  kitchen_floor.category = Category::kKitchen;
  const PartMaterial tile = MaterialOf(kitchen_floor);
  CHECK(tile.name == "floor-porcelain");
  REQUIRE(materials.count(tile.name));
  CHECK(materials[tile.name].color.r == Approx(gltf::SrgbToLinear(tile.color.r)).margin(1e-6));
  CHECK(std::abs(tile.color.r - CategoryColor(Category::kKitchen).r) > 0.05);
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

namespace {

nlohmann::json GlbJson(const std::string& g) {
  uint32_t json_len;
  std::memcpy(&json_len, g.data() + 12, 4);
  return nlohmann::json::parse(g.substr(20, json_len));
}

}  // namespace

TEST_CASE("issue 18: base colours are the palette's values made linear, as glTF defines them") {
  CHECK(gltf::SrgbToLinear(0.0) == 0.0);
  CHECK(gltf::SrgbToLinear(1.0) == Approx(1.0));
  CHECK(gltf::SrgbToLinear(0.5) == Approx(0.214041).margin(1e-6));
  CHECK(gltf::SrgbToLinear(0.04) == Approx(0.04 / 12.92));
  for (double c : {0.0, 0.02, 0.1, 0.37, 0.5, 0.8, 1.0}) CHECK(gltf::LinearToSrgb(gltf::SrgbToLinear(c)) == Approx(c).margin(1e-12));

  const BuildingMesh& b = ThreeFloorBuilding();
  auto bytes = BuildingToGlb(b);
  REQUIRE(bytes);
  auto json = GlbJson(*bytes);
  std::map<std::string, nlohmann::json> by_name;
  for (const auto& m : json["materials"]) by_name[m["name"]] = m;
  // Every part's material: the factor is the linear value of the sRGB colour in the shared table.
  for (const MeshPart& part : b.parts) {
    const PartMaterial m = MaterialOf(part);
    INFO(m.name);
    REQUIRE(by_name.count(m.name));
    const auto& f = by_name[m.name]["pbrMetallicRoughness"]["baseColorFactor"];
    CHECK(f[0].get<double>() == Approx(gltf::SrgbToLinear(m.color.r)).margin(1e-6));
    CHECK(f[1].get<double>() == Approx(gltf::SrgbToLinear(m.color.g)).margin(1e-6));
    CHECK(f[2].get<double>() == Approx(gltf::SrgbToLinear(m.color.b)).margin(1e-6));
    CHECK(f[3].get<double>() == Approx(m.alpha));
  }
  // The roof's brown (111, 73, 61 in the preview) is written dark, not the pale sRGB value.
  const auto& roof = by_name["roof"]["pbrMetallicRoughness"]["baseColorFactor"];
  CHECK(roof[0].get<double>() < 0.3);
}

TEST_CASE("issue 18: no slab edge carries a room colour, no ceiling the colour of the room above, every named node carries its exact name in extras") {
  const BuildingMesh& b = ThreeFloorBuilding();
  auto bytes = BuildingToGlb(b);
  REQUIRE(bytes);
  auto json = GlbJson(*bytes);
  // Every node with a name has it, byte for byte, in extras.name ("kitchen_0/0", "name:2").
  int named = 0;
  for (const auto& node : json["nodes"]) {
    if (!node.contains("name")) continue;
    ++named;
    INFO(node["name"]);
    REQUIRE(node.contains("extras"));
    CHECK(node["extras"]["name"] == node["name"]);
  }
  CHECK(named == static_cast<int>(json["nodes"].size()));
  CHECK(named > static_cast<int>(b.parts.size()));  // parts, groups, levels and the root

  // Re-read through assimp: every steep triangle of a floor or terrace slab is in the exterior wall's
  // material; the room colour stays on the top, and the underside is the ceiling below (issue 31: it took
  // the colour of the room above).
  fs::path dir = TempDir("edges");
  REQUIRE(ExportBuilding(b, dir / "villa.glb", MeshFormat::kGlb));
  auto scene = ReadSceneInfo(dir / "villa.glb");
  REQUIRE(scene);
  int steep = 0, below = 0;
  for (const MeshPart& part : b.parts) {
    if (part.kind != PartKind::kFloor) continue;
    const SceneNodeInfo* node = scene->Find(part.name);
    REQUIRE(node);
    for (int m : node->meshes) {
      const SceneMeshInfo& mesh = scene->meshes[m];
      const std::string& material = scene->materials[mesh.material].name;
      for (const auto& t : mesh.mesh.triangles) {
        // In the file's +Y-up frame "steep" means a small y component of the normal.
        const Vec3 n = Cross(mesh.mesh.vertices[t[1]] - mesh.mesh.vertices[t[0]], mesh.mesh.vertices[t[2]] - mesh.mesh.vertices[t[0]]);
        const bool is_steep = std::abs(n.y) < 0.5 * Norm(n);
        steep += is_steep;
        below += !is_steep && n.y < 0.0;
        INFO(part.name << " " << material);
        CHECK(material == (is_steep ? std::string("exterior-wall") : n.y < 0.0 ? std::string("ceiling") : MaterialOf(part).name));
      }
    }
  }
  CHECK(steep > 0);
  CHECK(below > 0);
  fs::remove_all(dir);
}

namespace {

// The building's .glb with one object in its first room: an asset of `mesh` in each of `materials`.
std::string GlbWithObject(const BuildingMesh& b, const TriangleMesh& mesh, const std::vector<PartMaterial>& materials,
                          const std::string& name) {
  ExportFurniture furniture;
  ExportAssetMesh asset;
  asset.name = "test:asset";
  for (const PartMaterial& m : materials) asset.parts.push_back({&mesh, m});
  furniture.meshes.push_back(asset);
  ExportObject object;
  object.name = name;
  object.room = b.rooms.front().name;
  object.mesh = 0;
  furniture.objects.push_back(object);
  auto bytes = BuildingToGlb(b, &furniture);
  REQUIRE(bytes);
  return *bytes;
}

}  // namespace

TEST_CASE("issue 31: materials by what they are made of: one name each, bare metals metallic, the ceiling its own") {
  const BuildingMesh& b = ThreeFloorBuilding();
  TriangleMesh cube;
  for (int k = 0; k < 8; ++k) cube.vertices.push_back({k & 1 ? 0.1 : -0.1, k & 2 ? 0.1 : -0.1, k & 4 ? 0.2 : 0.0});
  for (const auto& f : std::vector<std::array<int, 3>>{{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                                                      {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}})
    cube.AddTriangle(f[0], f[1], f[2]);
  const std::string bytes =
      GlbWithObject(b, cube,
                    {PartMaterial{"glass", {0.75, 0.85, 0.88}, 0.3, 0.05}, PartMaterial{"chrome", {0.8, 0.81, 0.83}, 1.0, 0.5},
                     PartMaterial{"matte-white-metal", {0.9, 0.9, 0.9}, 1.0, 0.9}, PartMaterial{"gold-brocade", {0.72, 0.58, 0.3}, 1.0, 0.9},
                     PartMaterial{"white-enamel", {0.95, 0.95, 0.95}, 1.0, 0.5}, PartMaterial{"mirror", {0.85, 0.88, 0.9}, 1.0, 0.9}},
                    "kitchen_0/0/thing-0");
  auto json = GlbJson(bytes);
  std::map<std::string, nlohmann::json> by_name;
  for (const auto& m : json["materials"]) {
    INFO(m["name"]);
    CHECK(by_name.emplace(m["name"].get<std::string>(), m).second);  // no name twice
  }
  // The window's glass and the asset's (another colour and opacity) are two materials with two names.
  REQUIRE(by_name.count("glass"));
  REQUIRE(by_name.count("glass-2"));
  auto metallic = [&](const std::string& name) { return by_name.at(name)["pbrMetallicRoughness"]["metallicFactor"].get<double>(); };
  CHECK(metallic("chrome") > 0.5);
  CHECK(metallic("matte-white-metal") > 0.5);
  CHECK(metallic("mirror") > 0.5);
  CHECK(metallic("gold-brocade") == 0.0);  // a fabric
  CHECK(metallic("white-enamel") == 0.0);  // a painted finish
  for (const auto& [name, m] : by_name)
    if (name.rfind("floor-", 0) == 0) CHECK(metallic(name) == 0.0);
  // The ceiling is one material, unlike every floor's.
  REQUIRE(by_name.count("ceiling"));
  const auto ceiling = by_name["ceiling"]["pbrMetallicRoughness"]["baseColorFactor"];
  for (const auto& [name, m] : by_name)
    if (name.rfind("floor-", 0) == 0) CHECK(m["pbrMetallicRoughness"]["baseColorFactor"] != ceiling);
}

namespace {

TEST_CASE("issue 31: floors by what they are laid with and walls painted in the villa's style") {
  // Tile where water is, stone in halls and outside, carpet for children (and a classic villa's bedrooms),
  // wood elsewhere.
  CHECK(FinishOf(Category::kKitchen, "modern") == FloorFinish::kTile);
  CHECK(FinishOf(Category::kBathroom, "rustic") == FloorFinish::kTile);
  CHECK(FinishOf(Category::kUtilityRoom, "modern") == FloorFinish::kStone);
  CHECK(FinishOf(Category::kBalcony, "classic") == FloorFinish::kStone);
  CHECK(FinishOf(Category::kChildrenRoom, "scandinavian") == FloorFinish::kCarpet);
  CHECK(FinishOf(Category::kBedroom, "classic") == FloorFinish::kCarpet);
  CHECK(FinishOf(Category::kBedroom, "modern") == FloorFinish::kWood);
  CHECK(FinishOf(Category::kLivingRoom, "rustic") == FloorFinish::kWood);

  // The same building in each style: its own floors and paint, every floor material named once.
  std::map<std::string, std::string> living_floor;
  std::set<std::string> names;
  for (const char* style : {"modern", "classic", "rustic", "scandinavian"}) {
    BuildingMesh b = ThreeFloorBuilding();
    b.style = style;
    auto bytes = BuildingToGlb(b);
    REQUIRE(bytes);
    const auto json = GlbJson(*bytes);
    std::map<std::string, nlohmann::json> by_name;
    for (const auto& m : json["materials"]) by_name[m["name"]] = m;
    for (const MeshPart& part : b.parts) {
      if (part.kind != PartKind::kFloor) continue;
      const PartMaterial m = MaterialOf(part, style);
      INFO(style << " " << part.name << " " << m.name);
      REQUIRE(by_name.count(m.name));
      CHECK(by_name[m.name]["pbrMetallicRoughness"]["baseColorFactor"][0].get<double>() == Approx(gltf::SrgbToLinear(m.color.r)).margin(1e-6));
      if (part.category == Category::kLivingRoom) living_floor[style] = m.name;
      names.insert(m.name);
    }
  }
  CHECK(living_floor["modern"] == "floor-oak-grey");
  CHECK(living_floor["classic"] == "floor-walnut");
  CHECK(living_floor["rustic"] == "floor-pine");
  CHECK(living_floor["scandinavian"] == "floor-oak-white");
  // A style nobody knows reads as modern; the walls' paint follows the style.
  MeshPart wall;
  wall.kind = PartKind::kInteriorWall;
  CHECK(MaterialOf(wall, "baroque-ish").color.r == MaterialOf(wall, "modern").color.r);
  CHECK(MaterialOf(wall, "rustic").color.b < MaterialOf(wall, "scandinavian").color.b);
}

}  // namespace

TEST_CASE("issue 31: every mesh carries vertex normals: furniture curves shade smooth, walls and boxes keep their edges") {
  const BuildingMesh& b = ThreeFloorBuilding();
  // A 16-sided cylinder (a lamp shade, a bowl's wall): 16 x 22.5-degree edges round its side, 90 at its rims.
  TriangleMesh cylinder;
  constexpr int kSides = 16;
  auto at = [](int k, double z) {
    const double a = 2.0 * std::numbers::pi * (k % kSides) / kSides;
    return Vec3{0.2 * std::cos(a), 0.2 * std::sin(a), z};
  };
  const int bottom = cylinder.AddVertex({0, 0, 0}), top = cylinder.AddVertex({0, 0, 0.3});
  for (int k = 0; k < kSides; ++k) {
    const int b0 = cylinder.AddVertex(at(k, 0.0)), b1 = cylinder.AddVertex(at(k + 1, 0.0));
    const int t0 = cylinder.AddVertex(at(k, 0.3)), t1 = cylinder.AddVertex(at(k + 1, 0.3));
    cylinder.AddTriangle(b0, b1, t1);
    cylinder.AddTriangle(b0, t1, t0);
    cylinder.AddTriangle(bottom, b1, b0);
    cylinder.AddTriangle(top, t0, t1);
  }
  const std::string bytes = GlbWithObject(b, cylinder, {PartMaterial{"linen", {0.9, 0.88, 0.8}, 1.0, 0.9}}, "living-room_0/0/floor-lamp-0");
  auto scene = ReadSceneInfoFromMemory(bytes, "glb");
  REQUIRE(scene);
  int shade_meshes = 0;
  for (const SceneMeshInfo& m : scene->meshes) {
    INFO(m.name);
    REQUIRE(m.normals.size() == m.mesh.vertices.size());
    for (const Vec3& n : m.normals) CHECK(Norm(n) == Approx(1.0).margin(1e-5));
    if (m.bounds.max.y - m.bounds.min.y == Approx(0.3).margin(1e-6) && m.bounds.max.x == Approx(0.2).margin(1e-6)) {
      ++shade_meshes;
      // Round: one vertex per rim point on the side (32), the caps' rims again and their centres (34); a
      // faceted side would need four per side face (64).
      CHECK(m.mesh.vertices.size() == 32 + 34);
      continue;
    }
    // The building is boxes and prisms: every corner takes its own face's normal.
    for (const auto& t : m.mesh.triangles) {
      const Vec3 face = Cross(m.mesh.vertices[t[1]] - m.mesh.vertices[t[0]], m.mesh.vertices[t[2]] - m.mesh.vertices[t[0]]);
      if (Norm(face) < 1e-6) continue;  // a sliver of collinear corners (a stair's): no area to shade, no direction
      for (int v : t) CHECK(Dot(m.normals[v], Normalized(face)) > 0.999);
    }
  }
  CHECK(shade_meshes == 1);
}

TEST_CASE("issue 31: a sheet of an asset (no closed solid) is drawn from both sides, a closed solid culls its back faces") {
  const BuildingMesh& b = ThreeFloorBuilding();
  TriangleMesh sheet;  // a picture's face: two triangles, open
  for (const Vec3& v : {Vec3{0, 0, 0}, Vec3{0.5, 0, 0}, Vec3{0.5, 0, 0.4}, Vec3{0, 0, 0.4}}) sheet.vertices.push_back(v);
  sheet.AddTriangle(0, 1, 2);
  sheet.AddTriangle(0, 2, 3);
  TriangleMesh cube;
  for (int k = 0; k < 8; ++k) cube.vertices.push_back({k & 1 ? 0.1 : -0.1, k & 2 ? 0.1 : -0.1, k & 4 ? 0.2 : 0.0});
  for (const auto& f : std::vector<std::array<int, 3>>{{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                                                      {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}})
    cube.AddTriangle(f[0], f[1], f[2]);
  auto double_sided = [&](const TriangleMesh& mesh) {
    const auto json = GlbJson(GlbWithObject(b, mesh, {PartMaterial{"canvas", {0.9, 0.88, 0.8}, 1.0, 0.9}}, "living-room_0/0/painting-0"));
    for (const auto& m : json["materials"])
      if (m["name"] == "canvas") return m.value("doubleSided", false);
    FAIL("no canvas material");
    return false;
  };
  CHECK(double_sided(sheet));
  CHECK_FALSE(double_sided(cube));
}

TEST_CASE("issue 31: a stair's treads are the villa's wood, its risers and soffit the stair's grey") {
  const BuildingMesh& b = ThreeFloorBuilding();
  auto bytes = BuildingToGlb(b);
  REQUIRE(bytes);
  auto scene = ReadSceneInfoFromMemory(*bytes, "glb");
  REQUIRE(scene);
  int tread = -1, stair = -1;
  for (size_t k = 0; k < scene->materials.size(); ++k) {
    if (scene->materials[k].name == "stair-tread") tread = static_cast<int>(k);
    if (scene->materials[k].name == "stair") stair = static_cast<int>(k);
  }
  REQUIRE(tread >= 0);
  REQUIRE(stair >= 0);
  CHECK(StairTreadMaterial(b.style).color.r == MaterialOf(MeshPart{.kind = PartKind::kFloor, .category = Category::kLivingRoom}, b.style).color.r);
  int tread_meshes = 0;
  for (const SceneMeshInfo& m : scene->meshes) {
    if (m.material != tread) continue;
    ++tread_meshes;
    // glTF is +Y up: every tread faces up.
    for (const auto& t : m.mesh.triangles) {
      const Vec3 n = Cross(m.mesh.vertices[t[1]] - m.mesh.vertices[t[0]], m.mesh.vertices[t[2]] - m.mesh.vertices[t[0]]);
      if (Norm(n) > 1e-6) CHECK(n.y > 0.9 * Norm(n));
    }
  }
  int stairs = 0;
  for (const MeshPart& p : b.parts) stairs += p.kind == PartKind::kStair;
  CHECK(stairs > 0);
  CHECK(tread_meshes == stairs);
}
