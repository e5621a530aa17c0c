#include <catch2/catch.hpp>

#include <atomic>
#include <fstream>

#include "assets/embedder.h"
#include "assets/retrieval.h"
#include "sh3f_fixture.h"

namespace villa {
namespace {

AssetRecord Rec(std::string id, std::string name, std::string category, Vec3 size, std::vector<std::string> tags = {},
                std::vector<std::string> rooms = {}, Placement placement = Placement::kFloor, int surfaces = 0, int cavities = 0) {
  AssetRecord r;
  r.id = "sh3d:Test#" + id;
  r.name = std::move(name);
  r.category = std::move(category);
  r.size = size;
  r.source.kind = "sh3d";
  r.source.tags = std::move(tags);
  r.room_types = std::move(rooms);
  r.placement = placement;
  for (int i = 0; i < surfaces; ++i)
    r.support_surfaces.push_back({0.3 * (i + 1), {{-0.1, -0.1}, {0.1, -0.1}, {0.1, 0.1}, {-0.1, 0.1}}, 0.25, "mesh"});
  for (int i = 0; i < cavities; ++i) r.cavities.push_back({{-0.1, -0.1, 0.3 * (i + 1)}, {0.1, 0.1, 0.3 * (i + 1) + 0.2}, "-y", i, std::nullopt});
  return r;
}

// A small library shaped like the Debian one: SH3D names, our categories, tags, real sizes.
std::vector<AssetRecord> Library() {
  using P = Placement;
  return {
      Rec("sofa3", "Sofa 3 seats", "sofa", {2.1, 0.9, 0.85}, {"Sofa"}, {"living-room"}, P::kFloor, 3),
      Rec("cornerSofa", "Corner sofa", "sofa", {2.5, 1.9, 0.8}, {"Sofa", "Corner"}, {"living-room"}, P::kFloor, 2),
      Rec("armchair", "Armchair", "armchair", {0.8, 0.85, 0.9}, {"Seat"}, {"living-room"}),
      Rec("oakChair", "Oak chair", "chair", {0.49, 0.61, 1.18}, {"Seat"}, {"living-room"}),
      Rec("barStool", "Bar stool", "stool", {0.4, 0.4, 0.75}, {}, {"kitchen", "dining-room"}),
      Rec("table", "Table", "dining-table", {1.6, 0.9, 0.75}, {}, {"living-room"}, P::kFloor, 1),
      Rec("coffeeTable", "Coffee table", "coffee-table", {1.1, 0.6, 0.42}, {}, {"living-room"}, P::kFloor, 1),
      Rec("bedsideTable", "Bedside table", "nightstand", {0.48, 0.4, 0.5}, {"Nightstand"}, {"bedroom"}, P::kFloor, 1, 1),
      Rec("bookcase", "Bookcase", "bookcase", {0.9, 0.35, 2.0}, {"Shelves", "Bookshelf"}, {"living-room"}, P::kFloor, 5, 4),
      Rec("shelves", "Shelves", "bookcase", {0.8, 0.39, 0.8}, {}, {"living-room"}, P::kFloor, 1),
      Rec("wardrobe", "Wardrobe", "wardrobe", {2.0, 0.66, 2.36}, {"Cupboard"}, {"bedroom"}, P::kFloor, 3, 2),
      Rec("bed", "Bed", "bed", {1.6, 2.1, 0.9}, {}, {"bedroom"}, P::kFloor, 1),
      Rec("childBed", "Child bed", "child-bed", {0.9, 1.9, 0.8}, {}, {"bedroom", "children-room"}, P::kFloor, 1),
      Rec("refrigerator", "Refrigerator", "fridge", {0.9, 0.8, 1.8}, {"Appliance"}, {"kitchen"}),
      Rec("cooker", "Cooker", "cooker", {0.6, 0.6, 0.9}, {"Appliance", "Oven"}, {"kitchen"}, P::kFloor, 1),
      Rec("toilets", "Toilets unit", "toilet", {0.4, 0.7, 0.8}, {}, {"bathroom"}),
      Rec("washbasin", "Washbasin", "washbasin", {0.6, 0.45, 0.9}, {}, {"bathroom"}, P::kFloor, 1),
      Rec("deskLamp", "Desk lamp", "table-lamp", {0.25, 0.25, 0.45}, {}, {}, P::kSurface),
      Rec("hangingLight", "Hanging light", "ceiling-lamp", {0.45, 0.45, 0.8}, {"Pendant", "Ceiling"}, {}, P::kCeiling),
      Rec("lamp", "Lamp", "floor-lamp", {0.4, 0.4, 1.7}, {}, {}),
      Rec("tv", "TV", "tv", {1.0, 0.2, 0.6}, {"Electronics"}, {"living-room"}, P::kSurface),
      Rec("tvCabinet", "Television cabinet", "tv-stand", {1.4, 0.45, 0.5}, {}, {"living-room"}, P::kFloor, 2, 1),
      Rec("yucca", "Yucca", "plant", {0.6, 0.6, 1.5}, {"Plant"}, {"living-room"}),
      Rec("mug", "Coffee mug", "cup", {0.09, 0.12, 0.11}, {}, {"kitchen"}, P::kSurface),
      Rec("rug", "Oriental rug", "rug", {2.0, 1.4, 0.01}, {}, {"living-room"}),
      Rec("desk", "Desk", "desk", {1.4, 0.7, 0.75}, {}, {"office"}, P::kFloor, 1),
      Rec("officeChair", "Office chair", "office-chair", {0.6, 0.6, 1.0}, {"Seat"}, {"office"}),
      Rec("frame", "Frame Chambord", "painting", {0.8, 0.04, 0.6}, {}, {}, P::kWall),
      Rec("radiator", "Radiator", "radiator", {0.8, 0.1, 0.6}, {"Heating"}, {}, P::kWall),
      Rec("mirror", "Mirror", "mirror", {0.6, 0.03, 0.9}, {}, {"bathroom"}, P::kWall),
  };
}

AssetRetriever Retriever() {
  auto r = AssetRetriever::Build(Library(), std::make_shared<LexicalEmbedder>());
  REQUIRE(r.ok());
  return std::move(*r);
}

TEST_CASE("Retrieval ranks the expected asset first on a labelled set of queries", "[assets][retrieval]") {
  struct Labelled {
    RetrievalQuery query;
    std::string expected;
  };
  auto text = [](std::string t) {
    RetrievalQuery q;
    q.text = std::move(t);
    return q;
  };
  auto sized = [&](std::string t, Vec3 size) {
    RetrievalQuery q = text(std::move(t));
    q.size = size;
    return q;
  };
  RetrievalQuery books = text("bookshelves full of books");
  books.needs_cavity = true;
  RetrievalQuery reading = text("reading lamp");
  reading.placement = Placement::kSurface;
  RetrievalQuery office = text("chair");
  office.category = "office-chair";
  office.room_type = "office";
  const std::vector<Labelled> labelled = {
      {text("couch"), "sofa3"},
      {text("an L-shaped corner sofa"), "cornerSofa"},
      {books, "bookcase"},
      {sized("low shelves", {0.8, 0.4, 0.8}), "shelves"},
      {text("bedside table"), "bedsideTable"},
      {text("nightstand"), "bedsideTable"},
      {text("double bed"), "bed"},
      {text("kids bed"), "childBed"},
      {text("refrigerator"), "refrigerator"},
      {text("stove"), "cooker"},
      {text("wc"), "toilets"},
      {text("bathroom sink"), "washbasin"},
      {reading, "deskLamp"},
      {text("chandelier"), "hangingLight"},
      {text("standing lamp"), "lamp"},
      {text("television"), "tv"},
      {text("tv cabinet"), "tvCabinet"},
      {text("potted plant"), "yucca"},
      {text("mug"), "mug"},
      {text("carpet"), "rug"},
      {office, "officeChair"},
      {text("picture"), "frame"},
      {text("radiator"), "radiator"},
      {text("armoire"), "wardrobe"},
  };
  AssetRetriever retriever = Retriever();
  int first = 0;
  for (const Labelled& l : labelled) {
    INFO("query: " << l.query.Text());
    auto result = retriever.Rank(l.query);
    REQUIRE(result.ok());
    REQUIRE_FALSE(result->ranked.empty());
    CHECK(result->ranked[0].asset->id == "sh3d:Test#" + l.expected);
    first += result->ranked[0].asset->id == "sh3d:Test#" + l.expected;
    CHECK_FALSE(result->category_missing);
  }
  CHECK(first == static_cast<int>(labelled.size()));
}

TEST_CASE("Retrieval filters by need and placement, scores size, and is deterministic", "[assets][retrieval]") {
  AssetRetriever retriever = Retriever();
  RetrievalQuery q;
  q.text = "bookcase";
  q.needs_surface = true;
  RetrievalOptions options;
  options.k = 100;
  auto all = retriever.Rank(q, options);
  REQUIRE(all.ok());
  for (const RankedAsset& r : all->ranked) CHECK_FALSE(r.asset->support_surfaces.empty());
  q.needs_cavity = true;
  q.placement = Placement::kFloor;
  auto cavities = retriever.Rank(q, options);
  for (const RankedAsset& r : cavities->ranked) {
    CHECK_FALSE(r.asset->cavities.empty());
    CHECK(r.asset->placement == Placement::kFloor);
  }
  CHECK(cavities->ranked.size() == 4);  // the nightstand, the bookcase, the wardrobe, the tv-stand
  // Scores fall down the list; the same query ranks the same way every time.
  for (std::size_t i = 1; i < all->ranked.size(); ++i) CHECK(all->ranked[i - 1].score >= all->ranked[i].score);
  auto again = retriever.Rank(q, options);
  REQUIRE(again->ranked.size() == cavities->ranked.size());
  for (std::size_t i = 0; i < again->ranked.size(); ++i) CHECK(again->ranked[i].asset == cavities->ranked[i].asset);

  // Size fit: 1 at the wanted size, 0.61 one tolerance factor off on one axis, 1 inside a category's range.
  CHECK(SizeFit({1, 1, 1}, Vec3{1, 1, 1}, "", 1.25) == Approx(1.0));
  CHECK(SizeFit({1.25, 1, 1}, Vec3{1, 1, 1}, "", 1.25) == Approx(std::exp(-0.5)));
  CHECK(SizeFit({2.0, 0.9, 0.85}, std::nullopt, "sofa", 1.25) == Approx(1.0));
  CHECK(SizeFit({2.5, 1.9, 0.8}, std::nullopt, "sofa", 1.25) < 0.2);
  CHECK(SizeFit({9, 9, 9}, std::nullopt, "no-such-category", 1.25) == Approx(1.0));
  RetrievalOptions bad;
  bad.k = 0;
  CHECK(retriever.Rank(q, bad).error() == "retrieval options: k must be >= 1, got 0");
}

TEST_CASE("A category the library lacks names its procedural generator", "[assets][retrieval]") {
  AssetRetriever retriever = Retriever();
  RetrievalQuery q;
  q.text = "a stack of books";
  auto books = retriever.Rank(q);
  REQUIRE(books.ok());
  CHECK(books->category == "books");
  CHECK(books->category_missing);
  CHECK(books->fallback_generator == "books");
  q.text = "bathtub";
  auto bath = retriever.Rank(q);
  CHECK(bath->category_missing);
  CHECK(bath->fallback_generator == "bathtub");  // every category now has a generator (assets/procedural)
  q.text = "sofa";
  q.placement = Placement::kWall;  // no sofa hangs on a wall
  CHECK(retriever.Rank(q)->category_missing);
}

TEST_CASE("Offered assets compete in the same ranking and fill a category the library lacks", "[assets][retrieval]") {
  AssetRetriever retriever = Retriever();
  int offers = 0;
  // A test double of the procedural generators: one asset of the query's category, at the query's size.
  retriever.SetOffer([&](const RetrievalQuery& q) {
    ++offers;
    std::vector<AssetRecord> out;
    if (q.category.empty()) return out;
    AssetRecord r = Rec("unused", "Procedural " + q.category, q.category, q.size.value_or(Vec3{0.3, 0.2, 0.25}));
    r.id = "proc:" + q.category + "?seed=1";
    r.source.kind = "procedural";
    out.push_back(r);
    return out;
  });
  RetrievalQuery q;
  q.text = "a stack of books";
  auto books = retriever.Rank(q);
  REQUIRE(books.ok());
  REQUIRE_FALSE(books->ranked.empty());
  CHECK(books->ranked[0].asset->id == "proc:books?seed=1");
  CHECK(books->ranked[0].asset == &books->offered->at(0));  // the result keeps the offered record alive
  CHECK(books->category_missing);                            // the library itself has none
  CHECK(books->fallback_generator == "books");
  // Where the library has the category, its asset still competes and may win on its name.
  q.text = "bedside table";
  auto nightstand = retriever.Rank(q);
  CHECK(nightstand->ranked[0].asset->id == "sh3d:Test#bedsideTable");
  CHECK(nightstand->ranked[1].asset->id == "proc:nightstand?seed=1");
  CHECK_FALSE(nightstand->category_missing);
  CHECK(offers == 2);
}

TEST_CASE("The lexical embedding is deterministic and meets synonyms through the vocabulary", "[assets][retrieval]") {
  LexicalEmbedder e;
  CHECK(e.Name() == "lexical-v1/1024");
  auto cosine = [&](const std::string& a, const std::string& b) {
    Embedding x = e.EmbedOne(a), y = e.EmbedOne(b);
    double dot = 0;
    for (std::size_t i = 0; i < x.size(); ++i) dot += x[i] * y[i];
    return dot;
  };
  CHECK(e.EmbedOne("Corner sofa") == e.EmbedOne("Corner sofa"));
  CHECK(cosine("couch", "Sofa. sofa.") > cosine("couch", "Bed. bed.") + 0.35);
  CHECK(cosine("bookshelves", "bookshelf") > cosine("bookshelves", "wardrobe") + 0.3);
  CHECK(cosine("x", "x") == Approx(1.0));
  Embedding empty = e.EmbedOne("");
  CHECK(std::all_of(empty.begin(), empty.end(), [](float v) { return v == 0.0f; }));
}

// Counts the texts it is asked for: the cache must keep them from coming back.
class CountingEmbedder : public Embedder {
 public:
  std::string Name() const override { return "counting/" + inner_.Name(); }
  Result<std::vector<Embedding>> Embed(const std::vector<std::string>& texts) const override {
    asked_ += static_cast<int>(texts.size());
    return inner_.Embed(texts);
  }
  int asked() const { return asked_; }

 private:
  LexicalEmbedder inner_;
  mutable std::atomic<int> asked_{0};
};

TEST_CASE("Embeddings are cached on disk by text: a second run asks for none, a damaged entry is redone", "[assets][retrieval]") {
  auto dir = test::FreshDir("embedding_cache");
  auto counting = std::make_shared<CountingEmbedder>();
  std::vector<std::string> texts = {"Sofa 3 seats. sofa.", "Bed. bed.", "Oak chair. chair. Seat."};
  {
    CachedEmbedder cache(counting, dir);
    auto first = cache.Embed(texts);
    REQUIRE(first.ok());
    CHECK(counting->asked() == 3);
    CHECK(cache.misses() == 3);
    auto same = cache.Embed({texts[1], texts[1]});  // from memory
    CHECK(counting->asked() == 3);
    CHECK((*same)[0] == (*first)[1]);
  }
  CachedEmbedder fresh(counting, dir);  // a new process, in effect: only the disk remains
  auto second = fresh.Embed(texts);
  REQUIRE(second.ok());
  CHECK(counting->asked() == 3);
  CHECK(fresh.hits() == 3);
  CHECK((*second)[2] == LexicalEmbedder().EmbedOne(texts[2]));
  // Damage one file: it is treated as missing and asked for again.
  int files = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
    if (e.path().extension() == ".vemb") {
      if (files++ == 0) std::ofstream(e.path(), std::ios::binary | std::ios::trunc) << "garbage";
    }
  CHECK(files == 3);
  CachedEmbedder third(counting, dir);
  REQUIRE(third.Embed(texts).ok());
  CHECK(counting->asked() == 4);
  // Retrieval through the cache ranks as without it.
  auto cached = AssetRetriever::Build(Library(), std::make_shared<CachedEmbedder>(counting, dir));
  REQUIRE(cached.ok());
  RetrievalQuery q;
  q.text = "couch";
  CHECK(cached->Rank(q)->ranked[0].asset->id == "sh3d:Test#sofa3");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace villa
