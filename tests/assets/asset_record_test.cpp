#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "assets/asset.h"
#include "assets/asset_mesh.h"
#include "assets/category.h"
#include "util/atomic_file.h"

namespace villa {
namespace {

// The record of SCENE.md's example, completed.
const char* kCouch = R"({"id": "sh3d:BlendSwap-CC-0#couch", "name": "Couch", "category": "sofa",
  "source": {"kind": "sh3d", "package": "sweethome3d-furniture 1.8-1", "library": "BlendSwap-CC-0.sh3f",
             "entry": "blendswap-cc-0/couch/couch.obj", "sh3d_category": "Living room", "tags": ["Blend Swap"]},
  "license": "CC0-1.0", "creator": "Someone", "room_types": ["living-room"],
  "size": [2.074, 0.876, 0.856], "to_asset": [[0.01, 0, 0, 0], [0, 0, -0.01, 0], [0, 0.01, 0, 0]],
  "front_yaw_offset": 0, "placement": "floor", "affordances": ["V_con", "V_pro", "V_int"],
  "support_surfaces": [{"z": 0.42, "polygon": [[-0.85, -0.35], [0.85, -0.35], [0.85, 0.1], [-0.85, 0.1]],
                        "clear_height": 0.44, "from": "drop_on_top"}],
  "cavities": [{"min": [-0.8, -0.3, 0.1], "max": [0.8, 0.3, 0.4], "open": "-y", "floor_surface": 0}],
  "interaction_zone": {"side": "front", "depth": 0.45},
  "mesh": {"file": "meshes/couch.vmesh", "triangles": 22682, "watertight": false, "manifold_edges": 0.97}})";

TEST_CASE("An asset record reads every SCENE.md field and writes them back unchanged", "[assets]") {
  auto parsed = AssetFromJson(nlohmann::json::parse(kCouch), "lib.jsonl:1");
  REQUIRE(parsed.ok());
  const AssetRecord& a = *parsed;
  CHECK(a.size.x == Approx(2.074));
  CHECK(a.to_asset[1][2] == Approx(-0.01));
  CHECK(a.affordances == (kConsumer | kProvider | kInteractor));
  REQUIRE(a.support_surfaces.size() == 1);
  CHECK(Area(a.support_surfaces[0].polygon) == Approx(1.7 * 0.45));
  REQUIRE(a.cavities.size() == 1);
  CHECK(a.cavities[0].floor_surface == 0);
  REQUIRE(a.interaction_zone);
  CHECK(a.interaction_zone->depth == Approx(0.45));
  CHECK(a.Credit().empty());  // CC0 needs no credit

  auto again = AssetFromJson(nlohmann::json::parse(AssetToJson(a).dump()), "again");
  REQUIRE(again.ok());
  CHECK(AssetToJson(*again).dump() == AssetToJson(a).dump());
  CHECK(AssetToJson(a) == nlohmann::ordered_json::parse(AssetToJson(*again).dump()));
}

TEST_CASE("Asset record errors name the place, the JSON path and the bad value", "[assets]") {
  auto with = [](const std::string& key, nlohmann::json value) {
    auto j = nlohmann::json::parse(kCouch);
    j[key] = value;
    auto r = AssetFromJson(j, "lib.jsonl:7");
    REQUIRE_FALSE(r.ok());
    return r.error();
  };
  CHECK(with("size", {1, 0, 1}) == "lib.jsonl:7: size: every side must be > 0 m, got [1,0,1]");
  CHECK(with("placement", "roof") == "lib.jsonl:7: placement: expected floor, wall, ceiling or surface, got \"roof\"");
  CHECK(with("front_yaw_offset", 45) == "lib.jsonl:7: front_yaw_offset: must be a multiple of 90, got 45");
  CHECK(with("colour", "red") == "lib.jsonl:7: colour: unknown key");
  CHECK(with("affordances", {"V_con", "V_con"}).find("affordances: expected distinct") != std::string::npos);
  auto j = nlohmann::json::parse(kCouch);
  j["support_surfaces"][0]["polygon"] = {{0, 0}, {0, 1}, {1, 1}};  // clockwise
  CHECK(AssetFromJson(j, "f").error() ==
        "f: support_surfaces[0].polygon: polygon must be counter-clockwise with positive area");
  j = nlohmann::json::parse(kCouch);
  j["cavities"][0]["floor_surface"] = 3;
  CHECK(AssetFromJson(j, "f").error() == "f: cavities[0].floor_surface: names no support surface: 3");
  j = nlohmann::json::parse(kCouch);
  j["cavities"][0]["rail"] = 0.3;  // inside the box, not above it
  CHECK(AssetFromJson(j, "f").error() ==
        "f: cavities[0].rail: must lie just above the cavity's top (0.400000 to 0.1 m more), got 0.300000");
}

TEST_CASE("A cavity's hanging rail round-trips, and only hanging things ask for one", "[assets]") {
  auto j = nlohmann::json::parse(kCouch);
  j["cavities"][0]["rail"] = 0.424;
  auto a = AssetFromJson(j, "f");
  REQUIRE(a.ok());
  REQUIRE(a->cavities[0].rail.has_value());
  CHECK(*a->cavities[0].rail == 0.424);
  CHECK(AssetToJson(*a)["cavities"][0]["rail"] == 0.424);
  CHECK(!AssetToJson(*AssetFromJson(nlohmann::json::parse(kCouch), "f")).at("cavities")[0].contains("rail"));
  CHECK(CavitySuits(a->cavities[0], "hanging-clothes"));
  CHECK(CavityClearHeight(a->cavities[0], "hanging-clothes") == Approx(0.424 + kHookRise - 0.1));
  CHECK(CavityClearHeight(a->cavities[0], "folded-clothes") == Approx(0.3));
  a->cavities[0].rail.reset();
  CHECK(!CavitySuits(a->cavities[0], "hanging-clothes"));
  CHECK(CavitySuits(a->cavities[0], "books"));
}

TEST_CASE("A library file with a repeated id names both lines", "[assets]") {
  auto dir = std::filesystem::temp_directory_path() / "villa_asset_record_test";
  std::filesystem::create_directories(dir);
  auto a = *AssetFromJson(nlohmann::json::parse(kCouch), "x");
  auto b = a;
  b.id = "proc:box?w=1";
  b.license = "CC-BY-3.0";
  CHECK(b.Credit() == "Couch by Someone (CC-BY-3.0)");
  REQUIRE(WriteAssetRecords((dir / "ok.jsonl").string(), {a, b}).ok());
  auto back = ReadAssetRecords((dir / "ok.jsonl").string());
  REQUIRE(back.ok());
  REQUIRE(back->size() == 2);
  CHECK(back->at(1).id == "proc:box?w=1");
  REQUIRE(WriteAssetRecords((dir / "dup.jsonl").string(), {a, b, a}).ok());
  auto dup = ReadAssetRecords((dir / "dup.jsonl").string());
  REQUIRE_FALSE(dup.ok());
  CHECK(dup.error() == (dir / "dup.jsonl").string() + ":3: id \"sh3d:BlendSwap-CC-0#couch\" already used on line 1");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace villa


namespace villa {
namespace {

TEST_CASE("A .vmesh file round-trips parts, materials and float geometry, and damage is named", "[assets]") {
  AssetMesh mesh;
  AssetMeshPart wood;
  wood.material = {"wood", 0.5, 0.3, 0.1, 1.0};
  wood.mesh.vertices = {{-0.5, -0.25, 0}, {0.5, -0.25, 0}, {0, 0.25, 0.75}};
  wood.mesh.triangles = {{0, 1, 2}};
  AssetMeshPart glass = wood;
  glass.material = {"glass", 0.9, 0.95, 1.0, 0.35};
  mesh.parts = {wood, glass};
  auto path = std::filesystem::temp_directory_path() / "villa_asset_mesh_test.vmesh";
  REQUIRE(WriteAssetMesh(path, mesh).ok());
  auto back = ReadAssetMesh(path);
  REQUIRE(back.ok());
  REQUIRE(back->parts.size() == 2);
  CHECK(back->parts[1].material.name == "glass");
  CHECK(back->parts[1].material.alpha == Approx(0.35));
  CHECK(back->parts[0].mesh.vertices[2].z == Approx(0.75));
  CHECK(back->parts[0].mesh.triangles == wood.mesh.triangles);
  CHECK(back->TriangleCount() == 2);
  CHECK(back->Bounds().max.z == Approx(0.75));

  std::string bytes = *ReadFile(path);
  std::string cut = bytes.substr(0, bytes.size() - 2);
  REQUIRE(WriteFileAtomic(path, cut).ok());
  auto damaged = ReadAssetMesh(path);
  REQUIRE_FALSE(damaged.ok());
  CHECK(damaged.error().find("1 triangles declared, 10 bytes left (truncated)") != std::string::npos);
  // Issue 33: a short file declaring 2^26 - 1 vertices is refused before anything is allocated; a vertex at
  // 3e38 m is no furniture.
  std::string huge = bytes.substr(0, 8 + 4 + 4 + 4 + 16);  // header, one part, "wood", colour
  for (int k = 0; k < 4; ++k) huge.push_back(static_cast<char>(((1u << 26) - 1) >> (8 * k)));
  REQUIRE(WriteFileAtomic(path, huge).ok());
  auto declared = ReadAssetMesh(path);
  REQUIRE_FALSE(declared.ok());
  CHECK(declared.error().find("67108863 vertices declared, 0 bytes left (truncated)") != std::string::npos);
  AssetMesh far = mesh;
  far.parts[0].mesh.vertices[1].x = 3e38;
  REQUIRE(WriteAssetMesh(path, far).ok());
  auto beyond = ReadAssetMesh(path);
  REQUIRE_FALSE(beyond.ok());
  CHECK(beyond.error().find("a vertex beyond 1000 m") != std::string::npos);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace villa


namespace villa {
namespace {

TEST_CASE("The category vocabulary resolves request words and keeps its sizes and zones consistent", "[assets]") {
  CHECK(CategoryForWord("couch")->name == "sofa");
  CHECK(CategoryForWord("Bookshelves")->name == "bookcase");
  CHECK(CategoryForWord("TV")->name == "tv");
  CHECK(CategoryForWord("bedside tables")->name == "nightstand");
  CHECK(CategoryForWord("coffee_table")->name == "coffee-table");
  CHECK(CategoryForWord("spaceship") == nullptr);
  std::set<std::string_view> names;
  for (const CategoryInfo& c : Categories()) {
    INFO(c.name);
    CHECK(names.insert(c.name).second);
    CHECK(c.size_min.x > 0);
    CHECK(c.size_min.x <= c.size_max.x);
    CHECK(c.size_min.y <= c.size_max.y);
    CHECK(c.size_min.z <= c.size_max.z);
    CHECK(((c.affordances & kProvider) != 0) == (c.has_surface || c.has_cavity));
    CHECK(((c.affordances & kInteractor) != 0) == c.zone.has_value());
  }
}

}  // namespace
}  // namespace villa

TEST_CASE("an assets.jsonl that is a folder, a FIFO or a device is no library: the error names it", "[assets][issue33]") {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("villa_assets_folder_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "assets.jsonl");
  auto folder = villa::ReadAssetRecords((dir / "assets.jsonl").string());
  REQUIRE_FALSE(folder.ok());
  CHECK(folder.error() == (dir / "assets.jsonl").string() + ": a folder, not a regular file");
  auto device = villa::ReadAssetRecords("/dev/zero");
  REQUIRE_FALSE(device.ok());
  CHECK(device.error() == "/dev/zero: a character device, not a regular file");
  std::filesystem::remove_all(dir);
}
