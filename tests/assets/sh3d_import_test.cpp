#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>

#include <nlohmann/json.hpp>

#include "assets/asset_mesh.h"
#include "assets/category.h"
#include "assets/asset_library.h"
#include "assets/java_properties.h"
#include "assets/sh3d_import.h"
#include "sh3f_fixture.h"

namespace villa {
namespace {

using test::FreshDir;
using test::WriteFixtureLibrary;

Sh3dCatalog FixtureCatalogRead() {
  auto properties = ParseJavaProperties(test::FixtureCatalog(), "TestLib.sh3f: PluginFurnitureCatalog.properties");
  REQUIRE(properties.ok());
  return ReadSh3dCatalog(*properties, "TestLib.sh3f", "TestLib.sh3f: PluginFurnitureCatalog.properties");
}

const Sh3dPiece& PieceNamed(const Sh3dCatalog& catalog, const std::string& id) {
  auto it = std::find_if(catalog.pieces.begin(), catalog.pieces.end(), [&](const Sh3dPiece& p) { return p.id == id; });
  REQUIRE(it != catalog.pieces.end());
  return *it;
}

Sh3dPieceImport ImportFixturePiece(const std::string& id, const Sh3dImportOptions& options = {}) {
  auto zip = ZipArchive::FromBytes(test::ZipBytes(test::FixtureEntries(), true), "TestLib.sh3f");
  REQUIRE(zip.ok());
  Sh3dCatalog catalog = FixtureCatalogRead();
  return ImportSh3dPiece(*zip, "TestLib.sh3f", catalog, PieceNamed(catalog, id), options);
}

Vec3 ApplyToAsset(const AssetRecord& r, Vec3 p) {
  const auto& m = r.to_asset;
  return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3], m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
          m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
}

TEST_CASE("The catalog reads names across continued lines, escapes, Latin-1, the licence and bad pieces", "[assets][sh3d]") {
  Sh3dCatalog catalog = FixtureCatalogRead();
  CHECK(catalog.library_id == "Test#Library");
  CHECK(catalog.license == "CC-BY-3.0");
  CHECK(catalog.pieces.size() == 11);
  CHECK(PieceNamed(catalog, "Test#bookcase").name == "Bookcase");
  CHECK(PieceNamed(catalog, "Test#bookcase").tags == std::vector<std::string>{"Shelves", "Bookshelf"});
  CHECK(PieceNamed(catalog, "Test#mug").name == "Caf\xC3\xA9 mug");
  CHECK(PieceNamed(catalog, "Test#mug").creator == "Ren\xC3\xA9");
  CHECK(PieceNamed(catalog, "Test#bookcase").model == "testlib/bookcase/bookcase.obj");
  CHECK(*PieceNamed(catalog, "Test#bookcase").drop_on_top == Approx(80));
  CHECK(PieceNamed(catalog, "Test#door").door_or_window);
  CHECK(PieceNamed(catalog, "Test#stairs").staircase);
  REQUIRE(catalog.problems.size() == 1);
  CHECK(catalog.problems[0] == "TestLib.sh3f: PluginFurnitureCatalog.properties: width#10: missing");
}

TEST_CASE("A catalog size past 100 m (1e308 cm, inf) is a bad piece, never a size of null", "[assets][sh3d][issue33]") {
  const std::string text =
      "id=Lib\nid#1=Lib#huge\nname#1=Huge\nmodel#1=/a.obj\nwidth#1=1e308\ndepth#1=50\nheight#1=50\n"
      "id#2=Lib#inf\nname#2=Inf\nmodel#2=/b.obj\nwidth#2=50\ndepth#2=inf\nheight#2=50\n"
      "id#3=Lib#ok\nname#3=Ok\nmodel#3=/c.obj\nwidth#3=50\ndepth#3=40\nheight#3=9999\n";
  auto properties = ParseJavaProperties(text, "L.sh3f: P.properties");
  REQUIRE(properties.ok());
  const Sh3dCatalog catalog = ReadSh3dCatalog(*properties, "L.sh3f", "L.sh3f: P.properties");
  REQUIRE(catalog.pieces.size() == 1);
  CHECK(catalog.pieces[0].id == "Lib#ok");
  REQUIRE(catalog.problems.size() == 2);
  CHECK(catalog.problems[0] == "L.sh3f: P.properties: width#1: expected a number of cm in (0, 10000], got \"1e308\"");
  CHECK(catalog.problems[1] == "L.sh3f: P.properties: depth#2: expected a number of cm in (0, 10000], got \"inf\"");
}

TEST_CASE("A stretched off-centre cube lands in the asset frame with its declared size", "[assets][sh3d]") {
  Sh3dPieceImport chest = ImportFixturePiece("Test#chest");
  REQUIRE(chest.outcome == Sh3dPieceImport::Outcome::kImported);
  const AssetRecord& r = *chest.record;
  CHECK(r.id == "sh3d:TestLib#chest");
  CHECK(r.category == "toy-chest");
  CHECK(r.placement == Placement::kFloor);
  CHECK(r.license == "CC-BY-3.0");
  CHECK(r.creator == "Jane Doe");
  CHECK(r.Credit() == "Toy chest by Jane Doe (CC-BY-3.0)");
  CHECK(r.room_types == std::vector<std::string>{"bedroom", "children-room"});
  CHECK(r.source.kind == "sh3d");
  CHECK(r.source.library == "TestLib.sh3f");
  CHECK(r.source.entry == "testlib/cube/cube.obj");
  // Declared 80 x 60 x 50 cm; the model is 40 (x) x 50 (y, up) x 60 (z, front): x is stretched twice.
  CHECK(r.size.x == Approx(0.8));
  CHECK(r.size.y == Approx(0.6));
  CHECK(r.size.z == Approx(0.5));
  Box3 box = chest.mesh.Bounds();
  CHECK(box.min.x == Approx(-0.4));
  CHECK(box.max.x == Approx(0.4));
  CHECK(box.min.y == Approx(-0.3));
  CHECK(box.max.y == Approx(0.3));
  CHECK(box.min.z == Approx(0.0).margin(1e-9));
  CHECK(box.max.z == Approx(0.5));
  // The model's front (+z) becomes -y; its top (+y) becomes +z; to_asset says so for any point.
  Vec3 front_top_right = ApplyToAsset(r, {50, 45, 60});
  CHECK(front_top_right.x == Approx(0.4));
  CHECK(front_top_right.y == Approx(-0.3));
  CHECK(front_top_right.z == Approx(0.5));
  Vec3 back_bottom_left = ApplyToAsset(r, {10, -5, 0});
  CHECK(back_bottom_left.x == Approx(-0.4));
  CHECK(back_bottom_left.y == Approx(0.3));
  CHECK(back_bottom_left.z == Approx(0.0).margin(1e-9));
  // A closed box: watertight, every edge two-sided, and its volume positive (faces still face out).
  CHECK(r.mesh.watertight);
  CHECK(r.mesh.manifold_edges == Approx(1.0));
  CHECK(r.mesh.triangles == 12);
  CHECK(chest.mesh.Merged().SignedVolume() == Approx(0.8 * 0.6 * 0.5));
  REQUIRE(chest.mesh.parts.size() == 1);
  CHECK(chest.mesh.parts[0].material.name == "red");
  CHECK(chest.mesh.parts[0].material.r == Approx(1.0));
  // SH3D drops things on its top (no dropOnTopElevation given): one surface covering the lid.
  REQUIRE(r.support_surfaces.size() == 1);
  CHECK(r.support_surfaces[0].from == "drop_on_top");
  CHECK(r.support_surfaces[0].z == Approx(0.5));
  CHECK(Area(r.support_surfaces[0].polygon) == Approx(0.48).epsilon(0.05));
  CHECK(r.support_surfaces[0].clear_height == Approx(2.625 - 0.5));
  CHECK(r.cavities.empty());  // a closed box has no free space inside that a ray could see
  CHECK(r.Has(kProvider));
}

TEST_CASE("A bookcase's shelf levels are its support surfaces and each compartment is a cavity", "[assets][sh3d]") {
  Sh3dPieceImport bookcase = ImportFixturePiece("Test#bookcase");
  REQUIRE(bookcase.outcome == Sh3dPieceImport::Outcome::kImported);
  const AssetRecord& r = *bookcase.record;
  CHECK(r.category == "bookcase");
  CHECK(r.Has(kProvider));
  CHECK(r.Has(kInteractor));
  REQUIRE(r.interaction_zone);
  CHECK(r.interaction_zone->depth == Approx(0.5));
  // Levels: bottom board 3 cm, shelves 40 and 80 cm (80 = dropOnTopElevation), top 120 cm.
  REQUIRE(r.support_surfaces.size() == 4);
  const double z[4] = {0.03, 0.40, 0.80, 1.20};
  const double clear[4] = {0.35, 0.38, 0.37, 2.625 - 1.20};
  for (int i = 0; i < 4; ++i) {
    INFO("surface " << i);
    const SupportSurface& s = r.support_surfaces[i];
    CHECK(s.z == Approx(z[i]).margin(0.002));
    CHECK(s.clear_height == Approx(clear[i]).margin(0.01));
    CHECK(Area(s.polygon) > 0.15 * 0.8 * 0.3);
    CHECK(SignedArea(s.polygon) > 0);  // counter-clockwise
  }
  CHECK(r.support_surfaces[2].from == "drop_on_top");
  CHECK(r.support_surfaces[1].from == "mesh");
  // Inner shelf polygons stay between the side panels (x within +-0.38) and in front of the back.
  Box3 shelf;
  for (const Point& p : r.support_surfaces[1].polygon) shelf.Add(Vec3{p.x, p.y, 0});
  CHECK(shelf.min.x == Approx(-0.38).margin(0.011));
  CHECK(shelf.max.x == Approx(0.38).margin(0.011));
  CHECK(shelf.max.y == Approx(0.13).margin(0.011));
  // Four compartments: the bottom one, two beside the divider, the upper one; all open at the front.
  REQUIRE(r.cavities.size() == 4);
  std::vector<int> per_surface(4, 0);
  for (const Cavity& c : r.cavities) {
    INFO("cavity on surface " << c.floor_surface);
    CHECK(c.open == "-y");
    REQUIRE(c.floor_surface >= 0);
    ++per_surface[c.floor_surface];
    const SupportSurface& below = r.support_surfaces[c.floor_surface];
    CHECK(c.min.z == Approx(below.z).margin(0.01));
    CHECK(c.max.z <= below.z + below.clear_height + 1e-9);
    CHECK(c.min.x >= -0.38 - 1e-6);
    CHECK(c.max.x <= 0.38 + 1e-6);
    CHECK(c.max.y <= 0.13 + 1e-6);
    CHECK(c.max.y - c.min.y > 0.2);
  }
  CHECK(per_surface == std::vector<int>{1, 2, 1, 0});
  // The divider splits the middle compartment at x = 0 (it is 2 cm thick).
  for (const Cavity& c : r.cavities)
    if (c.floor_surface == 1) CHECK((c.max.x <= -0.01 + 1e-6 || c.min.x >= 0.01 - 1e-6));
  // The painted divider has a texture: its colour is the texture's mean (pure blue), not Kd.
  auto painted = std::find_if(bookcase.mesh.parts.begin(), bookcase.mesh.parts.end(),
                              [](const AssetMeshPart& p) { return p.material.name == "painted"; });
  REQUIRE(painted != bookcase.mesh.parts.end());
  CHECK(painted->material.r == Approx(0.0));
  CHECK(painted->material.b == Approx(1.0));
  // Boxes that share an edge make it used four times: not watertight, though every box is closed.
  CHECK_FALSE(r.mesh.watertight);
}

TEST_CASE("Placement follows the category and SH3D's elevation, and small things need a parent", "[assets][sh3d]") {
  Sh3dPieceImport mug = ImportFixturePiece("Test#mug");
  REQUIRE(mug.outcome == Sh3dPieceImport::Outcome::kImported);
  CHECK(mug.record->category == "cup");
  CHECK(mug.record->placement == Placement::kSurface);
  CHECK(mug.record->name == "Caf\xC3\xA9 mug");
  Sh3dPieceImport wall = ImportFixturePiece("Test#wallLight");
  CHECK(wall.record->category == "wall-lamp");
  CHECK(wall.record->placement == Placement::kWall);
  Sh3dPieceImport hanging = ImportFixturePiece("Test#hanging");
  CHECK(hanging.record->category == "ceiling-lamp");
  CHECK(hanging.record->placement == Placement::kCeiling);
  CHECK_FALSE(hanging.record->Has(kProvider));
}

TEST_CASE("modelRotation turns the model before the y-up to z-up map", "[assets][sh3d]") {
  Sh3dPieceImport table = ImportFixturePiece("Test#rotated");
  REQUIRE(table.outcome == Sh3dPieceImport::Outcome::kImported);
  const AssetRecord& r = *table.record;
  CHECK(r.category == "side-table");
  // The model is z up already; rotation then (x, y, z) -> (x, -z, y) leaves it as it is, in metres.
  const double expected[3][4] = {{0.01, 0, 0, -0.2}, {0, 0.01, 0, -0.3}, {0, 0, 0.01, 0}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) CHECK(r.to_asset[i][j] == Approx(expected[i][j]).margin(1e-12));
  CHECK(table.mesh.Merged().SignedVolume() == Approx(0.4 * 0.6 * 0.5));
}

TEST_CASE("Doors, windows and staircases are skipped, and a bad model is reported with its entry and line", "[assets][sh3d]") {
  Sh3dPieceImport door = ImportFixturePiece("Test#door");
  CHECK(door.outcome == Sh3dPieceImport::Outcome::kSkipped);
  CHECK(door.reason == "door or window: the building makes these");
  CHECK(ImportFixturePiece("Test#stairs").reason == "staircase: the building makes these");
  Sh3dPieceImport broken = ImportFixturePiece("Test#broken");
  CHECK(broken.outcome == Sh3dPieceImport::Outcome::kFailed);
  CHECK(broken.reason == "unreadable model: TestLib.sh3f: testlib/broken/broken.obj:5: face index 99 out of range (3 vertices)");
}

TEST_CASE("The complexity filter decimates a model over the triangle budget, or skips it", "[assets][sh3d]") {
  Sh3dImportOptions options;
  options.max_triangles = 1000;
  Sh3dPieceImport rug = ImportFixturePiece("Test#rug", options);
  REQUIRE(rug.outcome == Sh3dPieceImport::Outcome::kImported);
  CHECK(rug.source_triangles == 3200);
  CHECK(rug.decimated);
  CHECK(rug.record->mesh.triangles <= 1000);
  CHECK(rug.record->mesh.triangles > 100);
  CHECK(rug.reason.rfind("decimated: 3,200 triangles > 1,000, now ", 0) == 0);
  Box3 box = rug.mesh.Bounds();  // clustering keeps the outline within a cube's size
  CHECK(box.max.x - box.min.x == Approx(2.0).epsilon(0.1));
  CHECK(box.max.y - box.min.y == Approx(1.4).epsilon(0.1));
  CHECK(rug.record->category == "rug");

  options.decimate = false;
  Sh3dPieceImport skipped = ImportFixturePiece("Test#rug", options);
  CHECK(skipped.outcome == Sh3dPieceImport::Outcome::kSkipped);
  CHECK(skipped.reason == "over the triangle budget: 3,200 triangles > 1,000");
  CHECK(ImportFixturePiece("Test#rug").outcome == Sh3dPieceImport::Outcome::kImported);  // default budget 50,000
}

TEST_CASE("A model over its category's budget is decimated to it, keeps its box, and keeps its source", "[assets][sh3d][issue31]") {
  CHECK(CategoryTriangleBudget("bed") == 8000);
  CHECK(CategoryTriangleBudget("office-chair") == 4000);
  CHECK(CategoryTriangleBudget("vase") == 1500);
  CHECK(CategoryTriangleBudget("no-such-thing") == 4000);
  Sh3dPieceImport vase = ImportFixturePiece("Test#vase");
  REQUIRE(vase.outcome == Sh3dPieceImport::Outcome::kImported);
  REQUIRE(vase.record->category == "vase");
  CHECK(vase.decimated);
  CHECK(vase.reason.rfind("decimated to the vase budget: 3,200 triangles > 1,500, now ", 0) == 0);
  CHECK(vase.mesh.TriangleCount() <= 1500);
  CHECK(vase.mesh.TriangleCount() > 300);
  CHECK(vase.full_mesh.TriangleCount() == 3200);
  CHECK(vase.record->mesh.full_triangles == 3200);
  CHECK(vase.record->mesh.full_file == "meshes/TestLib/vase.full.vmesh");
  // The clustered mesh stands in the source's box (a cluster's mean vertex pulled the sides in before).
  const Box3 a = vase.mesh.Bounds(), b = vase.full_mesh.Bounds();
  CHECK(a.min.x == Approx(b.min.x).margin(1e-9));
  CHECK(a.max.x == Approx(b.max.x).margin(1e-9));
  CHECK(a.min.y == Approx(b.min.y).margin(1e-9));
  CHECK(a.max.z == Approx(b.max.z).margin(1e-9));
  CHECK(a.min.z == Approx(b.min.z).margin(1e-9));
  // The record round-trips its source mesh; off, the source is kept as it is.
  const nlohmann::json json = AssetToJson(*vase.record);
  CHECK(json["mesh"]["full"]["triangles"] == 3200);
  const Result<AssetRecord> back = AssetFromJson(json, "vase");
  REQUIRE(back.ok());
  CHECK(back->mesh.full_file == vase.record->mesh.full_file);
  nlohmann::json bad = json;
  bad["mesh"]["full"]["triangles"] = 10;  // fewer than the decimated mesh: no source of it
  CHECK_FALSE(AssetFromJson(bad, "vase").ok());
  Sh3dImportOptions whole;
  whole.category_budgets = false;
  Sh3dPieceImport kept = ImportFixturePiece("Test#vase", whole);
  CHECK_FALSE(kept.decimated);
  CHECK(kept.record->mesh.triangles == 3200);
  CHECK(kept.record->mesh.full_file.empty());
}

TEST_CASE("Importing a folder writes the library, the report, and does it again identically", "[assets][sh3d]") {
  auto dir = FreshDir("import");
  WriteFixtureLibrary(dir / "from", false);  // stored entries this time
  Sh3dImportOptions options;
  options.threads = 2;
  auto summary = ImportSh3dLibraries(dir / "from", dir / "lib", options);
  REQUIRE(summary.ok());
  CHECK(summary->archives == 1);
  CHECK(summary->models_read == 12);
  CHECK(summary->imported == 8);
  CHECK(summary->skipped == 4);
  CHECK(summary->failed == 2);
  CHECK(summary->skip_reasons == std::map<std::string, int>{{"door or window", 1}, {"staircase", 1},
                                                            {"unreadable catalog entry", 1}, {"unreadable model", 1}});
  CHECK(summary->watertight == 5);  // the one-box models; the rug is an open sheet, the bookcase's boxes share edges
  CHECK(summary->BriefReport().find("skipped, door or window: 1") != std::string::npos);

  auto library = AssetLibrary::Open(dir / "lib");
  REQUIRE(library.ok());
  REQUIRE(library->records().size() == 8);
  CHECK(library->records()[0].id == "sh3d:TestLib#chest");  // catalog order
  for (const AssetRecord& r : library->records()) {
    INFO(r.id);
    CHECK(std::filesystem::exists(dir / "lib" / r.mesh.file));
    auto mesh = library->Mesh(r.id);
    REQUIRE(mesh.ok());
    CHECK((*mesh)->TriangleCount() == r.mesh.triangles);
    // The vase was decimated to its category's budget; its source mesh is kept beside it.
    CHECK(r.mesh.full_file.empty() == (r.id != "sh3d:TestLib#vase"));
    if (!r.mesh.full_file.empty()) {
      auto full = ReadAssetMesh(dir / "lib" / r.mesh.full_file);
      REQUIRE(full.ok());
      CHECK(full->TriangleCount() == r.mesh.full_triangles);
      CHECK(r.mesh.full_triangles == 3200);
      CHECK(r.mesh.triangles <= CategoryTriangleBudget(r.category));
    }
  }
  auto report = nlohmann::json::parse(*ReadFile(dir / "lib" / "import-report.json"));
  CHECK(report["format"] == "villa-import-report/1");
  CHECK(report["summary"]["imported"] == 8);
  CHECK(report["models"].size() == 12);
  bool broken_named = false;
  for (const auto& m : report["models"])
    if (m.value("entry", "") == "testlib/broken/broken.obj")
      broken_named = m["reason"].get<std::string>().find("broken.obj:5: face index 99") != std::string::npos;
  CHECK(broken_named);

  // Idempotent: a second import (one thread this time) writes the same bytes.
  std::string first = *ReadFile(dir / "lib" / "assets.jsonl");
  std::string first_report = *ReadFile(dir / "lib" / "import-report.json");
  options.threads = 1;
  REQUIRE(ImportSh3dLibraries(dir / "from", dir / "lib", options).ok());
  CHECK(*ReadFile(dir / "lib" / "assets.jsonl") == first);
  CHECK(*ReadFile(dir / "lib" / "import-report.json") == first_report);
  // No staging folder is left behind.
  int entries = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) entries += e.path().filename() != "from" && e.path().filename() != "lib";
  CHECK(entries == 0);
  std::filesystem::remove_all(dir);
}

TEST_CASE("A failed import leaves the old library, and a re-import keeps what it did not make", "[assets][sh3d]") {
  auto dir = FreshDir("import_keep");
  WriteFixtureLibrary(dir / "from");
  REQUIRE(ImportSh3dLibraries(dir / "from", dir / "lib", {}).ok());
  std::string before = *ReadFile(dir / "lib" / "assets.jsonl");

  // A damaged archive: the import fails naming it, and the library is untouched.
  std::string bytes = test::ZipBytes(test::FixtureEntries(), true);
  auto damaged = bytes;
  damaged.resize(damaged.size() / 2);
  std::filesystem::create_directories(dir / "bad");
  REQUIRE(WriteFileAtomic(dir / "bad" / "Damaged.sh3f", damaged).ok());
  auto failed = ImportSh3dLibraries(dir / "bad", dir / "lib", {});
  REQUIRE_FALSE(failed.ok());
  CHECK(failed.error() == (dir / "bad" / "Damaged.sh3f").string() + ": not a readable zip archive: no end-of-central-directory record");
  CHECK(*ReadFile(dir / "lib" / "assets.jsonl") == before);

  // A record of another kind with its mesh, and a file of the user's: both survive a re-import.
  auto library = AssetLibrary::Open(dir / "lib");
  REQUIRE(library.ok());
  std::vector<AssetRecord> records = library->records();
  AssetRecord mine = records[0];
  mine.id = "gltf:my-chair";
  mine.source.kind = "gltf";
  mine.mesh.file = "meshes/mine/chair.vmesh";
  records.push_back(mine);
  REQUIRE(WriteAssetRecords((dir / "lib" / "assets.jsonl").string(), records).ok());
  std::filesystem::create_directories(dir / "lib" / "meshes" / "mine");
  std::filesystem::copy_file(dir / "lib" / records[0].mesh.file, dir / "lib" / mine.mesh.file);
  REQUIRE(WriteFileAtomic(dir / "lib" / "NOTES.txt", "my notes\n").ok());
  auto again = ImportSh3dLibraries(dir / "from", dir / "lib", {});
  REQUIRE(again.ok());
  CHECK(again->carried_over == 1);
  auto reopened = AssetLibrary::Open(dir / "lib");
  REQUIRE(reopened.ok());
  REQUIRE(reopened->Find("gltf:my-chair"));
  CHECK(reopened->Mesh("gltf:my-chair").ok());
  CHECK(*ReadFile(dir / "lib" / "NOTES.txt") == "my notes\n");

  // A folder that is not a library is never replaced.
  std::filesystem::create_directories(dir / "home");
  REQUIRE(WriteFileAtomic(dir / "home" / "thesis.tex", "...").ok());
  auto refused = ImportSh3dLibraries(dir / "from", dir / "home", {});
  REQUIRE_FALSE(refused.ok());
  CHECK(refused.error().find("home: holds files but no assets.jsonl, so it is not an asset library") != std::string::npos);
  CHECK(std::filesystem::exists(dir / "home" / "thesis.tex"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("The Debian bookcase: five shelf levels and glass doors in front of its compartments", "[assets][sh3d]") {
  // sweethome3d-furniture is a declared dependency (scripts/install-deps.sh).
  auto archive_path = DefaultSh3dFurnitureDir() / "BlendSwap-CC-0.sh3f";
  REQUIRE(std::filesystem::exists(archive_path));
  auto zip = ZipArchive::Open(archive_path);
  REQUIRE(zip.ok());
  auto properties = ParseJavaProperties(*zip->Read("PluginFurnitureCatalog.properties"), "catalog");
  REQUIRE(properties.ok());
  Sh3dCatalog catalog = ReadSh3dCatalog(*properties, "BlendSwap-CC-0.sh3f", "catalog");
  CHECK(catalog.license == "CC0-1.0");
  Sh3dPieceImport bookcase = ImportSh3dPiece(*zip, "BlendSwap-CC-0.sh3f", catalog, PieceNamed(catalog, "Blend Swap CC-0#bookcase"), {});
  REQUIRE(bookcase.outcome == Sh3dPieceImport::Outcome::kImported);
  const AssetRecord& r = *bookcase.record;
  CHECK(r.id == "sh3d:BlendSwap-CC-0#bookcase");
  CHECK(r.creator == "Michtek");
  CHECK(r.size.z == Approx(1.472));
  std::vector<double> levels;
  for (const SupportSurface& s : r.support_surfaces)
    if (levels.empty() || s.z - levels.back() > 0.05) levels.push_back(s.z);
  CHECK(levels.size() == 5);
  REQUIRE(r.cavities.size() == 4);
  for (const Cavity& c : r.cavities) CHECK(c.open == "closed");  // its glass doors
}

}  // namespace
}  // namespace villa
