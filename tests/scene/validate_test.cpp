#include <catch2/catch.hpp>

#include <algorithm>
#include <functional>
#include <map>

#include "layout/layout_io.h"
#include "scene/validate.h"

using namespace villa;
using namespace villa::scene;

namespace {

Layout HouseLayout() {
  auto layout = LoadLayout(std::string(VILLA_FIXTURE_DIR) + "/layouts/house_one_floor.json");
  REQUIRE(layout.ok());
  return *layout;
}

SceneObject Make(const std::string& id, const std::string& category, const std::string& parent, Relation relation,
                 unsigned affordances = kConsumer) {
  SceneObject o;
  o.id = "living-room_0/0/" + id;
  o.category = category;
  o.room = "living-room_0/0";
  o.level = 0;
  o.size = {0.5, 0.5, 0.5};
  o.parent = parent;
  o.relation = relation;
  o.affordances = affordances;
  return o;
}

// Every room of the layout, one small living room graph: a bookcase with books inside, a table with a
// lamp on top, a painting, a ceiling lamp.
SceneFile ValidScene(const Layout& layout) {
  SceneFile s;
  s.layout = {"layout.json", std::string(64, '0')};
  for (const Room& r : layout.rooms) s.rooms.push_back({r.name(), std::nullopt, {}, std::nullopt, std::nullopt});
  const unsigned all = kConsumer | kProvider | kInteractor;
  SceneObject bookcase = Make("bookcase-0", "bookcase", "floor", Relation::kAgainstWall, all);
  bookcase.asset = "proc:bookcase";
  bookcase.interaction_zone = InteractionZone{"front", 0.5, {"living-room_0/0/coffee-table-0"}};
  SceneObject books = Make("books-0", "books", "living-room_0/0/bookcase-0", Relation::kInside);
  books.cavity = 1;
  SceneObject table = Make("coffee-table-0", "coffee-table", "floor", Relation::kOnTop, kConsumer | kProvider);
  SceneObject lamp = Make("table-lamp-0", "table-lamp", "living-room_0/0/coffee-table-0", Relation::kOnTop);
  SceneObject painting = Make("painting-0", "painting", "wall", Relation::kOnWall);
  SceneObject light = Make("ceiling-lamp-0", "ceiling-lamp", "ceiling", Relation::kHanging);
  s.objects = {bookcase, books, table, lamp, painting, light};
  s.rooms[0].edges_sem.push_back({"living-room_0/0/coffee-table-0", SemanticRelation::kFrontOf, "living-room_0/0/bookcase-0", {}});
  return s;
}

AssetRecord Bookcase() {
  AssetRecord a;
  a.id = "proc:bookcase";
  a.category = "bookcase";
  a.size = {1.0, 0.35, 1.8};
  a.support_surfaces.push_back({1.8, {{-0.5, -0.17}, {0.5, -0.17}, {0.5, 0.17}, {-0.5, 0.17}}, 0.5, "procedural"});
  a.cavities.push_back({{-0.48, -0.17, 0.02}, {0.48, 0.17, 0.4}, "-y", -1, std::nullopt});
  a.cavities.push_back({{-0.48, -0.17, 0.42}, {0.48, 0.17, 0.8}, "-y", -1, std::nullopt});
  return a;
}

std::vector<std::string> Rules(const std::vector<Finding>& findings) {
  std::vector<std::string> out;
  for (const Finding& f : findings) out.push_back(f.rule);
  return out;
}

bool Has(const std::vector<Finding>& findings, const std::string& subject, const std::string& rule) {
  for (const Finding& f : findings)
    if (f.subject == subject && f.rule == rule) return true;
  return false;
}

}  // namespace

TEST_CASE("a sound scene has no findings, with or without the asset library", "[scene][validate]") {
  Layout layout = HouseLayout();
  SceneFile scene = ValidScene(layout);
  AssetRecord bookcase = Bookcase();
  AssetLookup lookup = [&](std::string_view id) -> const AssetRecord* { return id == bookcase.id ? &bookcase : nullptr; };
  auto findings = ValidateScene(scene, layout, lookup);
  INFO(FormatFindings(findings));
  CHECK(findings.empty());
  CHECK(ValidateScene(scene, layout, nullptr).empty());
}

TEST_CASE("the validator catches each broken rule and names the object", "[scene][validate]") {
  Layout layout = HouseLayout();
  AssetRecord bookcase = Bookcase();
  AssetLookup lookup = [&](std::string_view id) -> const AssetRecord* { return id == bookcase.id ? &bookcase : nullptr; };
  const std::string room = "living-room_0/0/";
  struct Case {
    std::string name;
    std::function<void(SceneFile&)> breakit;
    std::string subject;
    std::string rule;
  };
  const std::vector<Case> cases = {
      {"duplicate id", [](SceneFile& s) { s.objects.push_back(s.objects[5]); }, room + "ceiling-lamp-0", "id"},
      {"id of another form", [](SceneFile& s) { s.objects[5].id = "living-room_0/0/lamp-0"; }, room + "lamp-0", "id"},
      {"id with a leading zero", [](SceneFile& s) { s.objects[5].id = "living-room_0/0/ceiling-lamp-00"; }, room + "ceiling-lamp-00", "id"},
      {"room not in layout", [](SceneFile& s) { s.objects[5].room = "garage_0/0"; }, room + "ceiling-lamp-0", "room"},
      {"level not the room's", [](SceneFile& s) { s.objects[5].level = 1; }, room + "ceiling-lamp-0", "room"},
      {"a room missing from rooms", [](SceneFile& s) { s.rooms.pop_back(); }, "office_0/0", "rooms"},
      {"a room not in the layout", [](SceneFile& s) { s.rooms.push_back({"garage_0/0", std::nullopt, {}, std::nullopt, std::nullopt}); },
       "garage_0/0", "rooms"},
      {"floor object not V_con", [](SceneFile& s) { s.objects[2].affordances = kProvider; }, room + "coffee-table-0", "physical-edge"},
      {"inside the floor", [](SceneFile& s) { s.objects[2].relation = Relation::kInside; }, room + "coffee-table-0", "physical-edge"},
      {"hanging from the floor", [](SceneFile& s) { s.objects[5].parent = "floor"; }, room + "ceiling-lamp-0", "physical-edge"},
      {"against a wall as parent", [](SceneFile& s) { s.objects[0].parent = "wall"; }, room + "bookcase-0", "physical-edge"},
      {"missing parent", [](SceneFile& s) { s.objects[3].parent = "living-room_0/0/desk-0"; }, room + "table-lamp-0", "forest"},
      {"parent cycle",
       [](SceneFile& s) {
         s.objects[2].parent = "living-room_0/0/table-lamp-0";
         s.objects[3].affordances |= kProvider;
       },
       room + "coffee-table-0", "forest"},
      {"child on another level", [](SceneFile& s) { s.objects[3].level = 1; }, room + "table-lamp-0", "level"},
      {"parent not V_pro", [](SceneFile& s) { s.objects[2].affordances = kConsumer; }, room + "table-lamp-0", "provider"},
      {"cavity beyond the asset's", [](SceneFile& s) { s.objects[1].cavity = 2; }, room + "books-0", "cavity"},
      {"inside without a cavity once posed on a known asset",
       [](SceneFile& s) {
         s.objects[1].cavity.reset();
         s.objects[1].pose = Pose{0.5, 0.5, 0.2, 0.0};
       },
       room + "books-0", "cavity"},
      {"ontop without a surface once posed on a known asset",
       [](SceneFile& s) {
         s.objects[1].relation = Relation::kOnTop;
         s.objects[1].cavity.reset();
         s.objects[1].pose = Pose{0.5, 0.5, 1.975, 0.0};
       },
       room + "books-0", "surface"},
      {"surface beyond the asset's",
       [](SceneFile& s) {
         s.objects[1].relation = Relation::kOnTop;
         s.objects[1].cavity.reset();
         s.objects[1].surface = 1;
       },
       room + "books-0", "surface"},
      {"cavity on an ontop object", [](SceneFile& s) { s.objects[3].cavity = 0; }, room + "table-lamp-0", "cavity"},
      {"surface on the floor", [](SceneFile& s) { s.objects[2].surface = 0; }, room + "coffee-table-0", "surface"},
      {"posed against_wall without a wall", [](SceneFile& s) { s.objects[0].pose = Pose{}; }, room + "bookcase-0", "wall"},
      {"wall edge beyond the polygon", [](SceneFile& s) { s.objects[4].wall = WallRef{6, 0.0}; }, room + "painting-0", "wall"},
      {"wall on a floor object", [](SceneFile& s) { s.objects[2].wall = WallRef{0, 0.0}; }, room + "coffee-table-0", "wall"},
      {"asset not in the library", [](SceneFile& s) { s.objects[2].asset = "sh3d:none"; }, room + "coffee-table-0", "asset"},
      {"V_pro asset without S or C",
       [](SceneFile& s) { s.objects[0].asset = "proc:bare"; },  // looked up below as an empty record
       room + "bookcase-0", "asset"},
      {"zone on a non-V_int object", [](SceneFile& s) { s.objects[2].interaction_zone = InteractionZone{}; }, room + "coffee-table-0", "zone"},
      {"zone exempting a ghost", [](SceneFile& s) { s.objects[0].interaction_zone->exempt.push_back("x"); }, room + "bookcase-0", "zone"},
      {"edge to a missing object", [](SceneFile& s) { s.rooms[0].edges_sem[0].target = "living-room_0/0/tv-0"; }, "living-room_0/0", "edge"},
      {"edge to an object of another room", [](SceneFile& s) { s.rooms[1].edges_sem.push_back(s.rooms[0].edges_sem[0]); },
       "kitchen_0/0", "edge"},
      {"edge to itself", [](SceneFile& s) { s.rooms[0].edges_sem[0].target = s.rooms[0].edges_sem[0].source; }, "living-room_0/0", "edge"},
      {"unknown hint", [](SceneFile& s) { s.objects[2].hints.push_back("upside_down"); }, room + "coffee-table-0", "hint"},
  };
  AssetRecord bare;
  bare.id = "proc:bare";
  AssetLookup with_bare = [&](std::string_view id) -> const AssetRecord* {
    if (id == bare.id) return &bare;
    return lookup(id);
  };
  for (const Case& c : cases) {
    INFO(c.name);
    SceneFile scene = ValidScene(layout);
    c.breakit(scene);
    auto findings = ValidateScene(scene, layout, with_bare);
    INFO(FormatFindings(findings));
    CHECK(Has(findings, c.subject, c.rule));
  }
}

TEST_CASE("a plan may list some rooms and leave surfaces and cavities to the asset choice", "[scene][validate]") {
  Layout layout = HouseLayout();
  SceneFile scene = ValidScene(layout);
  scene.rooms.resize(1);
  scene.objects[0].asset = "";
  scene.objects[1].cavity.reset();
  ValidateOptions plan;
  plan.all_rooms = false;
  auto findings = ValidateScene(scene, layout, nullptr, plan);
  INFO(FormatFindings(findings));
  CHECK(findings.empty());
  // The same as a full scene misses rooms.
  std::vector<std::string> rules = Rules(ValidateScene(scene, layout, nullptr));
  CHECK(std::count(rules.begin(), rules.end(), std::string("rooms")) == static_cast<long>(layout.rooms.size() - 1));
}

TEST_CASE("a plan with assets chosen leaves surfaces and cavities to the solver until it poses the objects", "[scene][validate]") {
  Layout layout = HouseLayout();
  SceneFile scene = ValidScene(layout);
  scene.objects[1].cavity.reset();  // the bookcase's asset is known, the books not yet placed
  const AssetRecord bookcase = Bookcase();
  AssetLookup lookup = [&](std::string_view id) -> const AssetRecord* { return id == bookcase.id ? &bookcase : nullptr; };
  CHECK(!Has(ValidateScene(scene, layout, lookup), "living-room_0/0/books-0", "cavity"));
  scene.objects[1].pose = Pose{0.5, 0.5, 0.2, 0.0};
  CHECK(Has(ValidateScene(scene, layout, lookup), "living-room_0/0/books-0", "cavity"));
}
