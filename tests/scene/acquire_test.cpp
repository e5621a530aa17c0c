// Asset acquisition (scene/acquire.h): the rules that choose an asset for every planned object.
#include <catch2/catch.hpp>

#include <map>
#include <string>
#include <vector>

#include "assets/procedural.h"
#include "scene/acquire.h"

namespace villa::scene {
namespace {

// A library record of a box: `top` gives it a top surface (clear above it), `cavities` that many shelf
// compartments across its width, each `cavity_h` m high.
AssetRecord Record(const std::string& key, const std::string& category, Vec3 size, Placement placement = Placement::kFloor,
                   bool top = false, int cavities = 0, double cavity_h = 0.3) {
  AssetRecord a;
  a.id = "sh3d:Test#" + key;
  a.name = key;
  a.category = category;
  a.source.kind = "sh3d";
  a.license = "CC0-1.0";
  a.size = size;
  a.placement = placement;
  a.affordances = kConsumer;
  const double hx = size.x / 2, hy = size.y / 2;
  if (top) a.support_surfaces.push_back({size.z, {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}}, 1.0, "mesh"});
  for (int k = 0; k < cavities; ++k) {
    const double z0 = 0.05 + k * (cavity_h + 0.02);
    a.support_surfaces.push_back({z0, {{-hx + 0.02, -hy}, {hx - 0.02, -hy}, {hx - 0.02, hy}, {-hx + 0.02, hy}}, cavity_h, "mesh"});
    a.cavities.push_back({{-hx + 0.02, -hy, z0}, {hx - 0.02, hy, z0 + cavity_h}, "-y", static_cast<int>(a.support_surfaces.size()) - 1, std::nullopt});
  }
  if (!a.support_surfaces.empty()) a.affordances |= kProvider;
  return a;
}

SceneObject Object(const std::string& name, const std::string& category, Vec3 size, const std::string& parent = "floor",
                   Relation relation = Relation::kOnTop) {
  SceneObject o;
  o.id = "living-room_0/0/" + name;
  o.category = category;
  o.room = "living-room_0/0";
  o.size = size;
  o.parent = parent == "floor" || parent == "wall" || parent == "ceiling" ? parent : "living-room_0/0/" + parent;
  o.relation = relation;
  o.affordances = kConsumer;
  return o;
}

RoomContext Living() {
  RoomContext room;
  room.name = "living-room_0/0";
  room.category = Category::kLivingRoom;
  return room;
}

// A living room's graph: a sofa, a coffee table with a bowl on it, a bookcase with books inside, four
// chairs round a table, a TV on a stand, a bathtub (which the test library lacks), a painting.
std::vector<SceneObject> Graph() {
  std::vector<SceneObject> g = {
      Object("sofa-0", "sofa", {2.1, 0.9, 0.85}),
      Object("coffee-table-0", "coffee-table", {1.1, 0.6, 0.42}),
      Object("bowl-0", "bowl", {0.2, 0.2, 0.08}, "coffee-table-0"),
      Object("bookcase-0", "bookcase", {0.9, 0.35, 1.8}, "floor", Relation::kAgainstWall),
      Object("books-0", "books", {0.3, 0.22, 0.26}, "bookcase-0", Relation::kInside),
      Object("books-1", "books", {0.3, 0.22, 0.26}, "bookcase-0", Relation::kInside),
      Object("dining-table-0", "dining-table", {1.6, 0.9, 0.75}),
      Object("chair-0", "chair", {0.48, 0.55, 0.9}),
      Object("chair-1", "chair", {0.5, 0.56, 0.92}),
      Object("chair-2", "chair", {0.47, 0.52, 0.88}),
      Object("tv-stand-0", "tv-stand", {1.5, 0.45, 0.5}, "floor", Relation::kAgainstWall),
      Object("tv-0", "tv", {1.2, 0.1, 0.7}, "tv-stand-0"),
      Object("bathtub-0", "bathtub", {1.7, 0.8, 0.6}),
      Object("painting-0", "painting", {0.9, 0.04, 0.6}, "wall", Relation::kOnWall),
  };
  g[1].affordances |= kProvider;
  g[3].affordances |= kProvider;
  g[6].affordances |= kProvider;
  g[10].affordances |= kProvider;
  return g;
}

// A library shaped to test each rule: a sofa of exactly the wanted size; a coffee table WITHOUT a surface
// (cannot carry the bowl) and one with; a bookcase with compartments (rule 1 takes the generator anyway);
// a TV wider than any stand's top; chairs; a painting; no bathtub.
std::vector<AssetRecord> TestRecords() {
  return {
      Record("sofa", "sofa", {2.1, 0.9, 0.85}, Placement::kFloor, true),
      Record("bareTable", "coffee-table", {1.1, 0.6, 0.42}),
      Record("coffeeTable", "coffee-table", {1.2, 0.65, 0.45}, Placement::kFloor, true),
      Record("bookcase", "bookcase", {0.9, 0.35, 1.8}, Placement::kFloor, true, 4),
      Record("chair", "chair", {0.48, 0.55, 0.9}),
      Record("wideTv", "tv", {1.5, 0.1, 0.8}, Placement::kSurface),
      Record("painting", "painting", {0.9, 0.04, 0.6}, Placement::kWall),
  };
}

const AcquiredAsset& ChoiceOf(const RoomAssets& assets, const std::string& name) {
  for (const AcquiredAsset& c : assets.choices)
    if (c.object == "living-room_0/0/" + name) return c;
  FAIL("no choice for " << name);
  return assets.choices.front();
}

}  // namespace

TEST_CASE("With no library every object gets a procedural asset of its category, at its size", "[scene][acquire]") {
  AssetLibrary empty = AssetLibrary::FromRecords({});
  auto acquirer = AssetAcquirer::Make(empty, {}, 3, "");
  REQUIRE(acquirer.ok());
  std::vector<SceneObject> objects = Graph();
  auto assets = (*acquirer)->Acquire(Living(), objects);
  REQUIRE(assets.ok());
  CHECK(assets->summary.library == 0);
  CHECK(assets->summary.procedural == static_cast<int>(objects.size()));
  for (size_t i = 0; i < objects.size(); ++i) {
    INFO(objects[i].id);
    CHECK(assets->choices[i].rule == AcquireRule::kProcedural);
    const AssetRecord* r = (*acquirer)->Find(objects[i].asset);
    REQUIRE(r);
    CHECK(r->category == objects[i].category);
    CHECK(objects[i].size == r->size);
  }
  // The books fit a compartment of the bookcase chosen for them (the parent is chosen first).
  const AssetRecord* bookcase = (*acquirer)->Find(objects[3].asset);
  const AssetRecord* books = (*acquirer)->Find(objects[4].asset);
  bool fits = false;
  for (const Cavity& c : bookcase->cavities)
    fits = fits || (books->size.x < c.max.x - c.min.x && books->size.y < c.max.y - c.min.y && books->size.z < c.max.z - c.min.z);
  CHECK(fits);
  // The seed (and only the seed) changes the look: the same seed gives the same ids.
  std::vector<SceneObject> again = Graph();
  REQUIRE(AssetAcquirer::Make(empty, {}, 3, "").value()->Acquire(Living(), again).ok());
  std::vector<SceneObject> other = Graph();
  REQUIRE(AssetAcquirer::Make(empty, {}, 4, "").value()->Acquire(Living(), other).ok());
  int same = 0;
  for (size_t i = 0; i < objects.size(); ++i) {
    CHECK(again[i].asset == objects[i].asset);
    same += other[i].asset == objects[i].asset;
  }
  CHECK(same < static_cast<int>(objects.size()));
  // A style named in the request is the procedural style.
  CHECK(AssetAcquirer::Make(empty, {}, 3, "a rustic farmhouse living room").value()->style() == "rustic");
}

TEST_CASE("With a library: storage with contents is procedural, the rest ranked, needs filter, missing categories fall back",
          "[scene][acquire]") {
  AssetLibrary library = AssetLibrary::FromRecords(TestRecords());
  library.SetProceduralMeshMaker(MakeProceduralMesh);
  auto acquirer = AssetAcquirer::Make(library, {}, 0, "");
  REQUIRE(acquirer.ok());
  std::vector<SceneObject> objects = Graph();
  auto made = (*acquirer)->Acquire(Living(), objects);
  REQUIRE(made.ok());
  const RoomAssets& assets = *made;

  // The library's sofa fits exactly and wins the ranking.
  CHECK(ChoiceOf(assets, "sofa-0").rule == AcquireRule::kLibrary);
  CHECK(ChoiceOf(assets, "sofa-0").asset == "sh3d:Test#sofa");
  // The coffee table carries a bowl: the one without a surface is never chosen.
  CHECK(ChoiceOf(assets, "coffee-table-0").asset != "sh3d:Test#bareTable");
  CHECK(!(*acquirer)->Find(ChoiceOf(assets, "coffee-table-0").asset)->support_surfaces.empty());
  // Rule 1: the bookcase holds books, so its generator makes it although the library has one.
  CHECK(ChoiceOf(assets, "bookcase-0").rule == AcquireRule::kStructural);
  CHECK(ChoiceOf(assets, "bookcase-0").asset.rfind("proc:bookcase?", 0) == 0);
  // The TV stand carries a TV: structural too; the library's TV is wider than its top, so it is not used.
  CHECK(ChoiceOf(assets, "tv-stand-0").rule == AcquireRule::kStructural);
  CHECK(ChoiceOf(assets, "tv-0").asset != "sh3d:Test#wideTv");
  // No bathtub in the library: the generator's.
  CHECK(ChoiceOf(assets, "bathtub-0").rule == AcquireRule::kFallback);
  CHECK(ChoiceOf(assets, "bathtub-0").asset.rfind("proc:bathtub?", 0) == 0);
  CHECK_FALSE(ChoiceOf(assets, "bathtub-0").note.empty());
  // Chairs of one parent share one asset (one mesh, instanced), whatever their planned sizes.
  CHECK(ChoiceOf(assets, "chair-1").asset == ChoiceOf(assets, "chair-0").asset);
  CHECK(ChoiceOf(assets, "chair-2").asset == ChoiceOf(assets, "chair-0").asset);
  CHECK(ChoiceOf(assets, "books-1").asset == ChoiceOf(assets, "books-0").asset);
  // Every object's size is its asset's; V_pro is kept only where the asset has a surface or a cavity.
  for (const SceneObject& o : objects) {
    INFO(o.id);
    const AssetRecord* r = (*acquirer)->Find(o.asset);
    REQUIRE(r);
    CHECK(o.size == r->size);
    if (o.affordances & kProvider) CHECK(!(r->support_surfaces.empty() && r->cavities.empty()));
  }
  CHECK(assets.summary.library + assets.summary.procedural == static_cast<int>(objects.size()));
  CHECK(assets.summary.fallbacks >= 1);

  // Rule 1 switched off: the library's bookcase (it has compartments) competes.
  AcquireOptions ranked_storage;
  ranked_storage.structural_procedural = false;
  std::vector<SceneObject> again = Graph();
  auto ranked = AssetAcquirer::Make(library, ranked_storage, 0, "").value()->Acquire(Living(), again);
  REQUIRE(ranked.ok());
  CHECK(ChoiceOf(*ranked, "bookcase-0").rule != AcquireRule::kStructural);
}

TEST_CASE("Acquisition options are checked", "[scene][acquire]") {
  AcquireOptions o;
  CHECK(o.Check().empty());
  o.style = "baroque";
  CHECK(o.Check().find("baroque") != std::string::npos);
  o.style = "";
  o.candidates = 0;
  CHECK_FALSE(o.Check().empty());
  AssetLibrary empty = AssetLibrary::FromRecords({});
  CHECK_FALSE(AssetAcquirer::Make(empty, o, 0, "").ok());
}

}  // namespace villa::scene

namespace villa::scene {

TEST_CASE("Low furniture against a wall is made to pass under the room's window sills", "[scene][acquire]") {
  AssetLibrary empty = AssetLibrary::FromRecords({});
  auto acquirer = AssetAcquirer::Make(empty, {}, 0, "");
  REQUIRE(acquirer.ok());
  RoomContext kitchen;
  kitchen.name = "kitchen_0/0";
  kitchen.category = Category::kKitchen;
  WallEdge wall;
  wall.windows.push_back({"kitchen0_window", {1.0, 2.0}, 0.9, 2.1, false});
  kitchen.walls.push_back(wall);
  std::vector<SceneObject> objects = {Object("counter-0", "counter", {1.2, 0.6, 0.92}, "floor", Relation::kAgainstWall),
                                      Object("fridge-0", "fridge", {0.7, 0.65, 1.8}, "floor", Relation::kAgainstWall),
                                      Object("sideboard-0", "sideboard", {1.4, 0.45, 0.9})};
  for (SceneObject& o : objects) o.room = kitchen.name;
  REQUIRE((*acquirer)->Acquire(kitchen, objects).ok());
  CHECK(objects[0].size.z == Approx(0.88));  // the sill (0.9) less 2 cm
  CHECK(objects[1].size.z == Approx(1.8));   // a fridge is meant to be tall
  CHECK(objects[2].size.z == Approx(0.9));   // free-standing: it does not go under a window
  // Without a window nothing changes.
  kitchen.walls.clear();
  std::vector<SceneObject> again = {Object("counter-0", "counter", {1.2, 0.6, 0.92}, "floor", Relation::kAgainstWall)};
  REQUIRE((*acquirer)->Acquire(kitchen, again).ok());
  CHECK(again[0].size.z == Approx(0.92));
}

}  // namespace villa::scene
