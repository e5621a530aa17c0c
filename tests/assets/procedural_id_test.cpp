// Procedural asset ids (canonical form, errors, the id helper), the generator table against the category
// vocabulary, frames (front = -y), and what the furnishing stage relies on: compartments sized for the
// small things that go inside them.
#include <algorithm>
#include <catch2/catch.hpp>
#include <set>

#include "assets/asset.h"
#include "assets/asset_library.h"
#include "assets/category.h"
#include "assets/embedder.h"
#include "assets/procedural.h"
#include "ray_cast.h"

namespace villa {
namespace {

using test::FirstHit;
using test::Ray;

ProceduralAsset Make(const std::string& id) {
  auto asset = MakeProceduralAsset(id);
  INFO(id);
  if (!asset.ok()) FAIL(asset.error());
  return std::move(asset).value();
}

std::string Error(const std::string& id) {
  auto asset = MakeProceduralAsset(id);
  INFO(id);
  REQUIRE_FALSE(asset.ok());
  return asset.error();
}

TEST_CASE("Every category names a generator that makes it, and only those", "[assets][procedural]") {
  for (const CategoryInfo& c : Categories()) {
    INFO(c.name);
    REQUIRE_FALSE(c.generator.empty());
    const ProceduralGenerator* g = FindProceduralGenerator(c.generator);
    REQUIRE(g);
    CHECK(std::count(g->categories.begin(), g->categories.end(), std::string(c.name)) == 1);
  }
  for (const ProceduralGenerator& g : ProceduralGenerators())
    for (const std::string& name : g.categories) {
      INFO(g.name << " makes " << name);
      const CategoryInfo* c = FindCategory(name);
      REQUIRE(c);
      CHECK(c->generator == g.name);
    }
  CHECK(FindProceduralGenerator("spaceship") == nullptr);
}

TEST_CASE("The generator listing: parameters sorted, defaults inside their ranges", "[assets][procedural]") {
  std::set<std::string> names;
  for (const ProceduralGenerator& g : ProceduralGenerators()) {
    INFO(g.name);
    CHECK(names.insert(g.name).second);
    CHECK_FALSE(g.description.empty());
    std::vector<std::string> keys;
    for (const ProceduralParam& p : g.params) {
      keys.push_back(p.name);
      CHECK_FALSE(p.meaning.empty());
      if (p.kind == ProceduralParam::Kind::kChoice) {
        CHECK(std::count(p.choices.begin(), p.choices.end(), p.default_choice) == 1);
      } else {
        CHECK(p.min <= p.default_value);
        CHECK(p.default_value <= p.max);
      }
    }
    CHECK(std::is_sorted(keys.begin(), keys.end()));
    for (const char* key : {"d", "h", "seed", "style", "w"}) CHECK(std::count(keys.begin(), keys.end(), key) == 1);
    CHECK(std::count(keys.begin(), keys.end(), "category") == (g.categories.size() > 1 ? 1 : 0));
  }
  CHECK(ProceduralStyles() == std::vector<std::string>{"modern", "classic", "rustic", "scandinavian"});
}

TEST_CASE("An id is canonical: every key written, sorted, numbers without trailing zeros", "[assets][procedural]") {
  const std::string canonical = "proc:bookcase?cols=2&d=0.34&h=1.65&rows=5&seed=3&style=modern&w=0.9";
  const ProceduralAsset a = Make("proc:bookcase?w=0.90&rows=5&seed=3");
  CHECK(a.record.id == canonical);
  const ProceduralAsset b = Make("proc:bookcase?seed=3&rows=5&w=0.9&style=modern&cols=2");
  CHECK(b.record.id == canonical);
  CHECK(AssetToJson(a.record).dump() == AssetToJson(b.record).dump());
  // Left out: sizes from the middle of the category's range, automatic counts from the size.
  CHECK(Make("proc:table?category=coffee-table&round=0").record.id ==
        "proc:table?category=coffee-table&d=0.625&h=0.415&round=0&seed=0&style=modern&w=1.05");
  CHECK(Make("proc:plate").record.id == "proc:plate?d=0.24&h=0.023&seed=0&style=modern&w=0.24");
  CHECK(Make("proc:bookcase?seed=4294967295").record.id.find("seed=4294967295") != std::string::npos);
}

TEST_CASE("Id errors name the id, the bad key or value and what is allowed", "[assets][procedural]") {
  CHECK(Error("bookcase") == "bookcase: a procedural asset id starts with \"proc:\"");
  CHECK(Error("proc:spaceship?w=1")
            .rfind("proc:spaceship?w=1: unknown generator \"spaceship\" (generators: armchair, ", 0) == 0);
  CHECK(Error("proc:bookcase?rows=12") == "proc:bookcase?rows=12: rows = 12 is out of range [1, 8]");
  CHECK(Error("proc:bookcase?rows=2.5") == "proc:bookcase?rows=2.5: rows = 2.5 must be a whole number");
  CHECK(Error("proc:bookcase?w=0.9125") == "proc:bookcase?w=0.9125: w = 0.9125 has more than 3 decimals");
  CHECK(Error("proc:bookcase?w=-1") == "proc:bookcase?w=-1: w = -1 is not a number (digits, at most 3 decimals)");
  CHECK(Error("proc:bookcase?w=") == "proc:bookcase?w=: w =  is not a number (digits, at most 3 decimals)");
  CHECK(Error("proc:bookcase?w=3") == "proc:bookcase?w=3: w = 3 is out of range [0.6, 1.2]");
  CHECK(Error("proc:bookcase?style=baroque") ==
        "proc:bookcase?style=baroque: style = \"baroque\" is not one of modern, classic, rustic, scandinavian");
  CHECK(Error("proc:bookcase?colour=red") ==
        "proc:bookcase?colour=red: unknown key \"colour\" for generator bookcase (keys: cols, d, h, rows, seed, style, "
        "w)");
  CHECK(Error("proc:bookcase?w=1&w=1") == "proc:bookcase?w=1&w=1: key \"w\" given twice");
  CHECK(Error("proc:bookcase?rows") == "proc:bookcase?rows: \"rows\" is not key=value");
  CHECK(Error("proc:bookcase?rows=2&") == "proc:bookcase?rows=2&: \"\" is not key=value");
  CHECK(Error("proc:bookcase?") == "proc:bookcase?: \"\" is not key=value");
  CHECK(Error("proc:table?category=sofa") ==
        "proc:table?category=sofa: category = \"sofa\" is not one of dining-table, coffee-table, side-table, "
        "conference-table, play-table, outdoor-table");
  // Inside the generator's range, outside the category's own.
  CHECK(Error("proc:table?category=coffee-table&w=2.4") ==
        "proc:table?category=coffee-table&w=2.4: w = 2.4 is out of range [0.8, 1.3] for category coffee-table");
  // Long ids are cut in messages.
  const std::string long_id = "proc:bookcase?style=" + std::string(200, 'x');
  CHECK(Error(long_id).size() < 250);
}

TEST_CASE("ProceduralAssetId clamps the size into the category's range and writes the canonical id",
          "[assets][procedural]") {
  auto id = ProceduralAssetId("bookcase", {5.0, 0.1, 1.5004}, "modern", 3);
  REQUIRE(id.ok());
  CHECK(*id == "proc:bookcase?cols=2&d=0.28&h=1.5&rows=4&seed=3&style=modern&w=1.2");
  const ProceduralAsset a = Make(*id);
  CHECK(a.record.id == *id);
  CHECK(a.record.size.x == 1.2);
  CHECK(a.record.size.y == 0.28);
  CHECK(a.record.size.z == 1.5);

  auto sideboard = ProceduralAssetId("sideboard", {1.6, 0.45, 0.8}, "scandinavian", 7);
  REQUIRE(sideboard.ok());
  CHECK(sideboard->find("proc:cabinet?category=sideboard&") == 0);
  CHECK(Make(*sideboard).record.category == "sideboard");

  // Every category has an id, and its asset is that category at the clamped size.
  for (const CategoryInfo& c : Categories()) {
    auto cid = ProceduralAssetId(c.name, {0, 0, 0}, "rustic", 11);
    INFO(c.name);
    REQUIRE(cid.ok());
    const ProceduralAsset asset = Make(*cid);
    CHECK(asset.record.category == c.name);
    CHECK(asset.record.size == c.size_min);
  }

  auto unknown = ProceduralAssetId("spaceship", {1, 1, 1}, "modern", 0);
  REQUIRE_FALSE(unknown.ok());
  CHECK(unknown.error() == "unknown category \"spaceship\"");
  auto nan = ProceduralAssetId("sofa", {std::nan(""), 1, 1}, "modern", 0);
  REQUIRE_FALSE(nan.ok());
  CHECK(nan.error() == "size of a sofa must be finite numbers (m)");
  auto style = ProceduralAssetId("sofa", {2, 1, 1}, "baroque", 0);
  REQUIRE_FALSE(style.ok());
  CHECK(style.error() == "style \"baroque\" is not one of modern, classic, rustic, scandinavian");
}

std::set<std::string> MaterialNames(const ProceduralAsset& a) {
  std::set<std::string> out;
  for (const AssetMeshPart& p : a.mesh.parts) out.insert(p.material.name);
  return out;
}

TEST_CASE("Seeds and styles vary an asset, and one id always gives the same one", "[assets][procedural]") {
  const ProceduralAsset one = Make("proc:books?seed=1"), two = Make("proc:books?seed=2");
  CHECK(one.mesh.Merged().vertices != two.mesh.Merged().vertices);
  CHECK(Make("proc:books?seed=1").mesh.Merged().vertices == one.mesh.Merged().vertices);
  std::set<std::set<std::string>> palettes;
  for (const std::string& style : ProceduralStyles())
    palettes.insert(MaterialNames(Make("proc:bookcase?seed=1&style=" + style)));
  CHECK(palettes.size() == ProceduralStyles().size());
  // Book colours vary within one row.
  CHECK(MaterialNames(Make("proc:books?count=8&w=0.3")).size() >= 3);
}

// Height of the first geometry below (x, y) seen from above the asset.
double TopAt(const ProceduralAsset& a, double x, double y) {
  const double start = a.record.size.z + 1.0;
  auto hit = FirstHit(a.mesh.Merged(), Ray{{x, y, start}, {0, 0, -1}});
  REQUIRE(hit);
  return start - *hit;
}

TEST_CASE("Front is -y: seats open to -y, backs and headboards stand at +y", "[assets][procedural]") {
  for (const char* id : {"proc:chair?category=chair", "proc:sofa", "proc:armchair", "proc:office-chair"}) {
    INFO(id);
    const ProceduralAsset a = Make(id);
    REQUIRE_FALSE(a.record.support_surfaces.empty());
    const double seat = a.record.support_surfaces[0].z;
    CHECK(TopAt(a, 0.0, -a.record.size.y / 2 + 0.03) == Approx(seat).margin(0.001));  // seat front: nothing above
    CHECK(TopAt(a, 0.0, a.record.size.y / 2 - 0.01) > seat + 0.2);                    // back
  }
  const ProceduralAsset bed = Make("proc:bed?style=modern");
  const double mattress = bed.record.support_surfaces[0].z;
  CHECK(TopAt(bed, 0.0, bed.record.size.y / 2 - 0.01) == Approx(bed.record.size.z));  // headboard at +y
  CHECK(TopAt(bed, 0.0, -bed.record.size.y / 2 + 0.1) <= mattress + 1e-9);            // foot at -y
  // A bookcase's compartments open to -y; its back panel closes them at +y.
  const ProceduralAsset shelf = Make("proc:bookcase");
  for (const Cavity& c : shelf.record.cavities) {
    CHECK(c.open == "-y");
    CHECK(c.min.y == Approx(-shelf.record.size.y / 2));
    const Vec3 mid = (c.min + c.max) * 0.5;
    auto back = FirstHit(shelf.mesh.Merged(), Ray{{mid.x, shelf.record.size.y, mid.z}, {0, -1, 0}});
    REQUIRE(back);
    CHECK(shelf.record.size.y - *back == Approx(shelf.record.size.y / 2));  // hits the outer back face
  }
}

TEST_CASE("Structural generators: compartments as asked, within the triangle budgets", "[assets][procedural]") {
  const ProceduralAsset big = Make("proc:bookcase?rows=8&cols=4&w=1.2&h=2.1");
  CHECK(big.record.cavities.size() == 32);
  CHECK(big.record.support_surfaces.size() == 33);  // a floor per compartment and the top
  CHECK(big.record.mesh.triangles < 500);
  const ProceduralAsset books = Make("proc:books?count=12&w=0.5");
  CHECK(books.record.mesh.triangles / 12 < 50);
  const ProceduralAsset one_book = Make("proc:books?count=1&w=0.12");
  CHECK(one_book.record.mesh.triangles < 50);

  const ProceduralAsset dresser = Make("proc:dresser?rows=4&cols=2");
  CHECK(dresser.record.cavities.size() == 8);
  for (const Cavity& c : dresser.record.cavities) CHECK(c.open == "closed");
  for (int doors : {0, 1}) {
    const ProceduralAsset counter = Make("proc:counter?cols=2&doors=" + std::to_string(doors));
    REQUIRE(counter.record.cavities.size() == 4);
    for (const Cavity& c : counter.record.cavities) CHECK(c.open == (doors ? "closed" : "-y"));
    CHECK(counter.record.support_surfaces.front().z == Approx(counter.record.size.z));  // the worktop
  }
  const ProceduralAsset glass = Make("proc:glass-cabinet");
  for (const Cavity& c : glass.record.cavities) CHECK(c.open == "closed");
  const ProceduralAsset night = Make("proc:nightstand?drawers=1");
  REQUIRE(night.record.cavities.size() == 2);
  CHECK(night.record.cavities[0].open == "-y");      // lower: open shelf
  CHECK(night.record.cavities[1].open == "closed");  // upper: drawer
  // Hung things and small things are placed as the vocabulary says.
  CHECK(Make("proc:wall-cabinet").record.placement == Placement::kWall);
  CHECK(Make("proc:lamp?category=ceiling-lamp").record.placement == Placement::kCeiling);
  CHECK(Make("proc:plate").record.placement == Placement::kSurface);
}

// Does `item` fit inside `cavity`, turned by `quarter_turns` x 90 degrees about z?
bool Fits(const AssetRecord& item, const Cavity& cavity, int quarter_turns) {
  const double w = quarter_turns % 2 ? item.size.y : item.size.x, d = quarter_turns % 2 ? item.size.x : item.size.y;
  return w <= cavity.max.x - cavity.min.x && d <= cavity.max.y - cavity.min.y &&
         item.size.z <= cavity.max.z - cavity.min.z;
}

bool AnyFits(const ProceduralAsset& parent, const ProceduralAsset& item, int quarter_turns) {
  return std::any_of(parent.record.cavities.begin(), parent.record.cavities.end(),
                     [&](const Cavity& c) { return Fits(item.record, c, quarter_turns); });
}

TEST_CASE("Small things fit the compartments made for them", "[assets][procedural]") {
  for (const std::string& style : ProceduralStyles()) {
    INFO(style);
    const std::string s = "?style=" + style, amp = "&style=" + style;
    // Clothes hang from the rail with their shoulders across it (turned 90 degrees), at the smallest wardrobe too.
    for (const std::string& wardrobe : {"proc:wardrobe" + s, "proc:wardrobe" + s + "&w=0.9&d=0.55&h=1.8"}) {
      INFO(wardrobe);
      CHECK(AnyFits(Make(wardrobe), Make("proc:hanging-clothes" + s), 1));
      CHECK(AnyFits(Make(wardrobe), Make("proc:hanging-clothes" + s + "&h=1.1&w=0.5"), 1));
      CHECK(AnyFits(Make(wardrobe), Make("proc:folded-clothes" + s), 0));
    }
    CHECK(AnyFits(Make("proc:bookcase" + s), Make("proc:books" + s), 0));
    CHECK(AnyFits(Make("proc:wall-cabinet" + s), Make("proc:plate" + s), 0));
    CHECK(AnyFits(Make("proc:wall-cabinet" + s), Make("proc:cup?category=glass" + amp), 0));
    CHECK(AnyFits(Make("proc:glass-cabinet" + s), Make("proc:bowl" + s), 0));
    CHECK(AnyFits(Make("proc:cabinet?category=sideboard" + amp), Make("proc:plate" + s), 0));
    CHECK(AnyFits(Make("proc:chest" + s), Make("proc:toy" + s), 0));
    CHECK(AnyFits(Make("proc:cabinet" + s), Make("proc:folded-clothes" + s), 0));
  }
}

TEST_CASE("Adapters: the library builds proc: meshes, retrieval ranks procedural offers", "[assets][procedural]") {
  auto mesh = MakeProceduralMesh("proc:bookcase?rows=3");
  REQUIRE(mesh.ok());
  CHECK(mesh->TriangleCount() == Make("proc:bookcase?rows=3").record.mesh.triangles);
  auto bad = MakeProceduralMesh("proc:bookcase?rows=12");
  REQUIRE_FALSE(bad.ok());
  CHECK(bad.error() == "proc:bookcase?rows=12: rows = 12 is out of range [1, 8]");

  AssetLibrary library = AssetLibrary::FromRecords({});
  library.SetProceduralMeshMaker(MakeProceduralMesh);
  auto shared = library.Mesh("proc:plate?seed=2");
  REQUIRE(shared.ok());
  CHECK((*shared)->TriangleCount() == Make("proc:plate?seed=2").record.mesh.triangles);

  CHECK(ProceduralStyleIn("a Rustic oak table") == "rustic");
  CHECK(ProceduralStyleIn("nordic-style sofa") == "scandinavian");
  CHECK(ProceduralStyleIn("an antique, ornate mirror") == "classic");
  CHECK(ProceduralStyleIn("countryside") == "modern");  // whole words only
  CHECK(ProceduralStyleIn("a table", "rustic") == "rustic");

  RetrievalQuery query;
  query.category = "bookcase";
  query.text = "tall scandinavian shelves";
  query.size = Vec3{0.9, 0.3, 1.8};
  const std::vector<AssetRecord> offer = ProceduralOffer(query);
  REQUIRE(offer.size() == 1);
  CHECK(offer[0].category == "bookcase");
  CHECK(offer[0].size == Vec3{0.9, 0.3, 1.8});
  CHECK(offer[0].id.find("style=scandinavian") != std::string::npos);
  CHECK(ProceduralOffer(query)[0].id == offer[0].id);
  query.text = "tall shelves";
  CHECK(ProceduralOffer(query)[0].id != offer[0].id);  // another query, another seed
  RetrievalQuery by_text;
  by_text.text = "a low coffee table";
  REQUIRE(ProceduralOffer(by_text).size() == 1);
  CHECK(ProceduralOffer(by_text)[0].category == "coffee-table");
  CHECK(ProceduralOffer(RetrievalQuery{}).empty());
  RetrievalQuery unknown;
  unknown.category = "spaceship";
  CHECK(ProceduralOffer(unknown).empty());

  // With no library at all, the offer is what retrieval ranks first, cavity and all.
  auto retriever = AssetRetriever::Build({}, std::make_shared<LexicalEmbedder>());
  REQUIRE(retriever.ok());
  retriever->SetOffer(ProceduralOffer);
  RetrievalQuery books;
  books.category = "bookcase";
  books.needs_cavity = true;
  auto ranked = retriever->Rank(books);
  REQUIRE(ranked.ok());
  REQUIRE_FALSE(ranked->ranked.empty());
  CHECK(ranked->ranked[0].asset->id.rfind("proc:bookcase?", 0) == 0);
  CHECK_FALSE(ranked->ranked[0].asset->cavities.empty());
}

}  // namespace
}  // namespace villa
