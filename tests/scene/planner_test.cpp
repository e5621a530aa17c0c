#include <catch2/catch.hpp>

#include <fstream>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "assets/category.h"
#include "scene/bathroom_fit.h"
#include "scene/planner.h"
#include "scene/priors.h"
#include "scene/validate.h"
#include "scene_test_support.h"

using namespace villa;
using namespace villa::scene;
using namespace villa::scene::testing;

namespace {

// The layouts the planner is checked on: the fixtures and examples (L-shaped and angled rooms, three
// floors with staircases) and the 50 layouts of the reference dataset's test split (rooms of every size).
std::vector<BuiltLayout> CorpusLayouts() {
  std::vector<BuiltLayout> out;
  for (const char* file : {"tests/fixtures/layouts/house_one_floor.json", "tests/fixtures/layouts/bungalow_angled.json",
                           "tests/fixtures/layouts/house_two_floors.json", "tests/fixtures/layouts/villa_three_floors.json",
                           "examples/l-shaped-house.json", "examples/three-floor-villa.json",
                           "examples/two-floor-house.json", "examples/u-shaped-bungalow.json"})
    out.push_back(LoadBuilt(file));
  std::ifstream in(std::string(VILLA_SOURCE_DIR) + "/datasets/villa-1k/test.jsonl");
  std::string line;
  while (std::getline(in, line)) {
    auto record = nlohmann::json::parse(line);
    auto layout = ParseLayoutText(record["messages"][2]["content"].get<std::string>(), "test.jsonl");
    REQUIRE(layout.ok());
    BuiltLayout b{*layout, {}, {}};
    auto building = BuildBuilding(b.layout, b.options);
    REQUIRE(building.ok());
    b.building = std::move(*building);
    out.push_back(std::move(b));
  }
  REQUIRE(out.size() == 58);
  return out;
}

bool HasStairs(const RoomContext& c) {
  for (const KeepOut& z : c.keep_outs)
    if (z.kind == KeepOutKind::kStair || z.kind == KeepOutKind::kStairHole) return true;
  return false;
}

RoomPlan PlanOf(const RoomContext& c, const std::string& text = "", uint64_t seed = 1) {
  auto plan = PriorsPlanner().Plan({&c, text, seed});
  REQUIRE(plan.ok());
  return std::move(*plan);
}

std::vector<Finding> Check(const BuiltLayout& b, const RoomContext& c, const RoomPlan& plan) {
  SceneFile file = PlanSceneFile({"layout.json", std::string(64, '0')}, b.options, c.name, plan);
  ValidateOptions options;
  options.all_rooms = false;
  return ValidateScene(file, b.layout, nullptr, options);
}

int CountCategory(const RoomPlan& plan, const std::string& category, Origin origin) {
  int n = 0;
  for (const SceneObject& o : plan.objects) n += o.category == category && o.origin == origin;
  return n;
}

int CountCategory(const RoomPlan& plan, const std::string& category) {
  int n = 0;
  for (const SceneObject& o : plan.objects) n += o.category == category;
  return n;
}

const SceneObject* Find(const RoomPlan& plan, const std::string& id) {
  for (const SceneObject& o : plan.objects)
    if (o.id == id) return &o;
  return nullptr;
}

bool HasEdge(const RoomPlan& plan, const std::string& source, SemanticRelation relation, const std::string& target) {
  for (const SemanticEdge& e : plan.edges)
    if (e.source == source && e.relation == relation && e.target == target) return true;
  return false;
}

}  // namespace

TEST_CASE("planned graphs pass the validator for every room of the corpus over many seeds", "[scene][planner]") {
  std::vector<BuiltLayout> corpus = CorpusLayouts();
  std::set<Category> types;
  int rooms = 0, rich = 0, l_or_angled = 0;
  for (const BuiltLayout& b : corpus) {
    auto contexts = RoomContexts(b.layout, b.building, b.options);
    REQUIRE(contexts.ok());
    for (const RoomContext& c : *contexts) {
      types.insert(c.category);
      ++rooms;
      l_or_angled += !IsAxisAlignedBox(c.polygon, 1e-9);
      for (uint64_t seed = 1; seed <= 6; ++seed) {
        RoomPlan plan = PlanOf(c, "", seed);
        INFO(c.name << " (" << c.area << " m2) seed " << seed);
        auto findings = Check(b, c, plan);
        INFO(FormatFindings(findings));
        REQUIRE(findings.empty());
        const int n = static_cast<int>(plan.objects.size());
        CHECK(n == plan.summary.objects);
        // The counts: 25-33 planned in the five rich room types of usual size (the paper's 22-30 placed,
        // issue 27), never below the paper's 22; any room within the range aimed at, or below it only when
        // the room has no space (said in a note).
        if (IsRichRoomType(c.category) && c.area >= 12.0 && !HasStairs(c)) {
          ++rich;
          CHECK(n >= 22);
          CHECK(n <= 33);
        }
        CHECK(n <= std::max(plan.summary.target_max, 11));  // small meeting rooms keep their table and chairs
        if (n < plan.summary.target_min) {
          CHECK(plan.summary.outcome != PlanOutcome::kPlanned);
          CHECK_FALSE(plan.record.notes.empty());
        }
        // Staircase rooms keep the stairs clear: floor objects only on the floor outside them.
        CHECK(plan.summary.floor_used <= 0.6 + 1e-9);
      }
    }
  }
  CHECK(types.size() == 10);  // every labelled room type was planned
  CHECK(rooms > 400);
  CHECK(rich > 150);
  CHECK(l_or_angled > 30);
}

TEST_CASE("other room types aim at PRIORS.md's NO targets when of usual size", "[scene][planner]") {
  std::vector<BuiltLayout> corpus = CorpusLayouts();
  std::map<Category, std::pair<double, int>> sums;  // mean count per type over rooms of at least usual size
  for (const BuiltLayout& b : corpus) {
    auto contexts = RoomContexts(b.layout, b.building, b.options);
    REQUIRE(contexts.ok());
    for (const RoomContext& c : *contexts) {
      if (IsRichRoomType(c.category) || c.category == Category::kUtilityRoom) continue;
      if (c.furnishable_area < PriorsFor(c.category).usual_area) continue;
      for (uint64_t seed = 1; seed <= 4; ++seed) {
        RoomPlan plan = PlanOf(c, "", seed);
        sums[c.category].first += plan.objects.size();
        sums[c.category].second += 1;
      }
    }
  }
  for (Category type : {Category::kBathroom, Category::kOffice, Category::kMeetingRoom, Category::kBalcony}) {
    INFO(CategoryName(type));
    REQUIRE(sums[type].second > 0);
    double mean = sums[type].first / sums[type].second;
    int target = PriorsFor(type).no_target;
    CHECK(mean >= 0.8 * target);
    CHECK(mean <= 1.2 * target);
  }
}

TEST_CASE("a small bathroom gets fewer objects, all of which fit", "[scene][planner]") {
  // A 2 x 2 m bathroom beside a living room.
  auto layout = ParseLayoutText(R"json({"rooms": {"living-room_0/0": {"shape": "shapely.box(0, 0, 6, 4)"},
                                              "bathroom_0/0": {"shape": "shapely.box(6, 0, 8, 2)"},
                                              "bedroom_0/0": {"shape": "shapely.box(6, 2, 8, 4)"}},
    "entrance": {"main": {"shape": "shapely.LineString([(1, 0), (2, 0)])", "level": 0}},
    "doors": {"living_bath": {"shape": "shapely.LineString([(6, 0.6), (6, 1.4)])", "level": 0},
              "living_bed": {"shape": "shapely.LineString([(6, 2.6), (6, 3.4)])", "level": 0}},
    "opens": {},
    "windows": {"bath_window": {"shape": "shapely.LineString([(8, 0.6), (8, 1.4)])", "is_panoramic": 0, "level": 0}},
    "interiors": {"w1": {"shape": "shapely.LineString([(6, 0), (6, 4)])", "level": 0},
                  "w2": {"shape": "shapely.LineString([(6, 2), (8, 2)])", "level": 0}}})json",
                                "small.json");
  REQUIRE(layout.ok());
  BuiltLayout b{*layout, {}, {}};
  auto building = BuildBuilding(b.layout, b.options);
  REQUIRE(building.ok());
  b.building = std::move(*building);
  RoomContext bath = ContextOf(b, "bathroom_0/0");
  CHECK(bath.area == Approx(4.0));
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    RoomPlan plan = PlanOf(bath, "", seed);
    INFO("seed " << seed << "\n" << PlanTable(plan, bath.name));
    CHECK(Check(b, bath, plan).empty());
    CHECK(plan.objects.size() <= 10);
    CHECK(plan.objects.size() < static_cast<size_t>(PriorsFor(Category::kBathroom).no_target));
    CHECK(CountCategory(plan, "toilet") == 1);  // the room's key furniture is there
    CHECK(CountCategory(plan, "bathtub") == 0);  // a bath needs 5 m2
    CHECK(plan.summary.floor_used <= 0.6 + 1e-9);
  }
}

TEST_CASE("floor objects stay within the floor share and small objects within their receptacles", "[scene][planner]") {
  BuiltLayout b = LoadBuilt("examples/three-floor-villa.json");
  auto contexts = RoomContexts(b.layout, b.building, b.options);
  REQUIRE(contexts.ok());
  for (const RoomContext& c : *contexts) {
    for (uint64_t seed = 1; seed <= 5; ++seed) {
      RoomPlan plan = PlanOf(c, "", seed);
      INFO(c.name << " seed " << seed);
      double priors_floor = 0.0;
      std::map<std::pair<std::string, std::string>, int> per_parent;  // (parent, category) -> count
      std::map<std::string, int> seats;                                // table id -> chairs facing it
      for (const SceneObject& o : plan.objects) {
        bool floor = o.parent == "floor" && (o.relation == Relation::kOnTop || o.relation == Relation::kAgainstWall);
        if (floor && o.category != "rug" && o.size.x * o.size.y >= 0.1 && o.origin == Origin::kPrior)
          priors_floor += o.size.x * o.size.y;
        if (!IsRootParent(o.parent)) ++per_parent[{o.parent, o.category}];
      }
      for (const SemanticEdge& e : plan.edges)
        if (e.relation == SemanticRelation::kFaceTo) ++seats[e.target];
      // The priors' share, plus the key furniture's allowance up to the request share.
      CHECK(priors_floor <= 0.6 * c.furnishable_area + 1e-6);
      for (const auto& [key, count] : per_parent) {
        const SceneObject* parent = Find(plan, key.first);
        REQUIRE(parent);
        bool inside = false;
        for (const SceneObject& o : plan.objects)
          if (o.parent == key.first && o.category == key.second) inside = o.relation == Relation::kInside;
        int limit = inside ? 3 * CompartmentsOf(parent->category) : 3;
        if (key.second == "plate" || key.second == "glass" || key.second == "laptop" || key.second == "cup")
          limit = std::max(limit, seats[key.first]);  // place settings: one per seat
        INFO(key.first << " holds " << count << " " << key.second);
        CHECK(count <= limit);
      }
    }
  }
}

TEST_CASE("planning is deterministic for a seed and varies with it", "[scene][planner]") {
  BuiltLayout b = LoadBuilt("examples/l-shaped-house.json");
  RoomContext c = ContextOf(b, "living-room_0/0");
  RoomPlan a = PlanOf(c, "two armchairs", 7), again = PlanOf(c, "two armchairs", 7);
  FileRef ref{"layout.json", std::string(64, '0')};
  CHECK(SceneToText(PlanSceneFile(ref, b.options, c.name, a)) == SceneToText(PlanSceneFile(ref, b.options, c.name, again)));
  std::set<std::string> texts;
  for (uint64_t seed = 1; seed <= 8; ++seed) texts.insert(SceneToText(PlanSceneFile(ref, b.options, c.name, PlanOf(c, "", seed))));
  CHECK(texts.size() >= 4);
}

TEST_CASE("the request's objects appear with their counts, containers, places and relations", "[scene][planner]") {
  BuiltLayout b = LoadBuilt("examples/l-shaped-house.json");
  RoomContext living = ContextOf(b, "living-room_0/0");
  const std::string room = living.name + "/";
  for (uint64_t seed : {1, 2, 3}) {
    INFO("seed " << seed);
    RoomPlan plan = PlanOf(living, "Two armchairs facing the sofa, a TV, bookshelves full of books and a desk by the window. No rug.", seed);
    INFO(PlanTable(plan, living.name));
    CHECK(Check(b, living, plan).empty());
    CHECK(CountCategory(plan, "armchair") == 2);
    CHECK(CountCategory(plan, "armchair", Origin::kPrompt) == 2);
    CHECK(CountCategory(plan, "tv", Origin::kPrompt) == 1);
    CHECK(CountCategory(plan, "tv") == 1);
    CHECK(CountCategory(plan, "rug") == 0);
    CHECK(CountCategory(plan, "desk", Origin::kPrompt) == 1);
    // The TV stands on a TV stand, planned for it.
    const SceneObject* tv = Find(plan, room + "tv-0");
    REQUIRE(tv);
    CHECK(tv->parent == room + "tv-stand-0");
    CHECK(tv->relation == Relation::kOnTop);
    // "bookshelves" (plural, no number): two bookcases, each with books inside.
    CHECK(CountCategory(plan, "bookcase", Origin::kPrompt) == 2);
    for (const char* bookcase : {"bookcase-0", "bookcase-1"}) {
      int books = 0;
      for (const SceneObject& o : plan.objects)
        books += o.category == "books" && o.parent == room + bookcase && o.relation == Relation::kInside;
      CHECK(books >= 3);
    }
    const SceneObject* desk = Find(plan, room + "desk-0");
    REQUIRE(desk);
    CHECK(std::count(desk->hints.begin(), desk->hints.end(), std::string(kHintNearWindow)) == 1);
    CHECK(HasEdge(plan, room + "armchair-0", SemanticRelation::kFaceTo, room + "sofa-0"));
    CHECK(plan.objects.size() <= 33);
  }
}

TEST_CASE("objects the request gives another room stay out", "[scene][planner]") {
  BuiltLayout b = LoadBuilt("examples/three-floor-villa.json");
  const std::string text = "A TV in the meeting room and a piano-free living room with three armchairs. The kitchen has an island.";
  RoomContext meeting = ContextOf(b, "meeting-room_1/0");
  RoomPlan m = PlanOf(meeting, text);
  CHECK(CountCategory(m, "tv", Origin::kPrompt) == 1);
  CHECK(CountCategory(m, "armchair", Origin::kPrompt) == 0);  // a big meeting room's own lounge chairs may stand
  CHECK(CountCategory(m, "island") == 0);
  CHECK(Check(b, meeting, m).empty());
  RoomContext living = ContextOf(b, "living-room_0/0");
  RoomPlan l = PlanOf(living, text);
  CHECK(CountCategory(l, "armchair", Origin::kPrompt) == 3);
  CHECK(CountCategory(l, "tv", Origin::kPrompt) == 0);  // the living room's TV comes from its priors
  CHECK(CountCategory(l, "island") == 0);
  bool noted = false;
  for (const std::string& n : l.record.notes) noted = noted || n.find("tv (meeting-room)") != std::string::npos;
  CHECK(noted);
  RoomContext kitchen = ContextOf(b, "kitchen_0/0");
  CHECK(CountCategory(PlanOf(kitchen, text), "island", Origin::kPrompt) == 1);
}

TEST_CASE("a request too big for the room keeps what fits and says what did not", "[scene][planner]") {
  BuiltLayout b = LoadBuilt("tests/fixtures/layouts/house_one_floor.json");
  RoomContext c = ContextOf(b, "bathroom_0/0");
  RoomPlan plan = PlanOf(c, "20 wardrobes");
  CHECK(CountCategory(plan, "wardrobe") < 20);
  CHECK(CountCategory(plan, "wardrobe") >= 1);
  CHECK(plan.summary.outcome == PlanOutcome::kPartial);
  CHECK(plan.summary.dropped == 20 - CountCategory(plan, "wardrobe"));
  REQUIRE_FALSE(plan.record.notes.empty());
  CHECK(plan.record.notes[0].find("20 x wardrobe") != std::string::npos);
  CHECK(Check(b, c, plan).empty());
}

TEST_CASE("staircase rooms plan nothing on the stairs' floor", "[scene][planner]") {
  BuiltLayout b = LoadBuilt("tests/fixtures/layouts/villa_three_floors.json");
  for (const char* name : {"utility-room_0/0", "utility-room_1/0", "utility-room_2/0"}) {
    RoomContext c = ContextOf(b, name);
    RoomPlan plan = PlanOf(c);
    INFO(name << "\n" << PlanTable(plan, c.name));
    for (const SceneObject& o : plan.objects) CHECK(o.parent != "floor");
    CHECK(plan.summary.outcome != PlanOutcome::kPlanned);
    CHECK(Check(b, c, plan).empty());
  }
}

TEST_CASE("every prior names known categories, parents that provide, and sane counts", "[scene][planner]") {
  for (const RoomPriors& room : AllRoomPriors()) {
    INFO(CategoryName(room.room));
    CHECK(room.no_target > 0);
    CHECK(room.usual_area > 0);
    for (const ItemPrior& item : room.items) {
      INFO(item.category);
      const CategoryInfo* info = FindCategory(item.category);
      REQUIRE(info);
      CHECK(item.min <= item.max);
      CHECK(item.max > 0);
      for (const ParentChoice& p : item.parents) {
        const CategoryInfo* parent = FindCategory(p.category);
        REQUIRE(parent);
        CHECK((parent->affordances & kProvider) != 0);
        CHECK((p.relation == Relation::kInside ? parent->has_cavity : parent->has_surface));
      }
      CHECK((item.mount == Mount::kParent) == !item.parents.empty());
      for (const EdgeRule& e : item.edges) CHECK(FindCategory(e.target) != nullptr);
      for (std::string_view e : item.exempt) CHECK(FindCategory(e) != nullptr);
      if (!item.requires_category.empty()) CHECK(FindCategory(item.requires_category) != nullptr);
      for (std::string_view h : item.hints) CHECK(IsKnownHint(h));
    }
  }
  CHECK(AllRoomPriors().size() == 10);
  CHECK(PriorsFor(Category::kRoom).items.empty());
}

TEST_CASE("planner options are checked", "[scene][planner]") {
  PlannerOptions o;
  CHECK(o.Check().empty());
  o.floor_share = 0;
  CHECK(o.Check().find("floor_share") != std::string::npos);
  o = {};
  o.prompt_floor_share = 0.2;
  CHECK(o.Check().find("prompt_floor_share") != std::string::npos);
  o = {};
  o.max_per_receptacle = 0;
  CHECK(o.Check().find("max_per_receptacle") != std::string::npos);
  o = {};
  o.rich_max_objects = 10;
  CHECK_FALSE(o.Check().empty());
  auto bad = PriorsPlanner(o).Plan({nullptr, "", 0});
  REQUIRE_FALSE(bad.ok());
  BuiltLayout b = LoadBuilt("examples/l-shaped-house.json");
  RoomContext c = ContextOf(b, "kitchen_0/0");
  auto refused = PriorsPlanner(o).Plan({&c, "", 0});
  REQUIRE_FALSE(refused.ok());
  CHECK(refused.error().find("planner options") != std::string::npos);
}

TEST_CASE("an unlabelled room with no request is planned empty and says why", "[scene][planner]") {
  BuiltLayout b = LoadBuilt("examples/l-shaped-house.json");
  RoomContext c = ContextOf(b, "bedroom_0/0");
  c.category = Category::kRoom;
  RoomPlan plan = PlanOf(c);
  CHECK(plan.objects.empty());
  CHECK(plan.summary.outcome == PlanOutcome::kEmpty);
  REQUIRE(plan.record.notes.size() == 1);
  CHECK(plan.record.notes[0].find("no priors") != std::string::npos);
  // With a request it plans what the request names.
  RoomPlan asked = PlanOf(c, "a sofa and a lamp");
  CHECK(CountCategory(asked, "sofa") == 1);
  CHECK(CountCategory(asked, "table-lamp") == 1);
}

TEST_CASE("a living room's sofa stands free where no two facing walls hold it and the TV stand 3.4-4.4 m apart",
          "[scene][planner]") {
  // Both rooms are 7.2 x 3.5 m inside; the bounding box alone would put the sofa against a long wall. In the
  // first the wall across from the south wall is taken by a 3.1 m opening to the kitchen and a door, so no
  // stretch across holds the TV stand: the sofa stands free, and a painting has no wall above it. In the
  // second that wall has one 1 m door: sofa and stand go on the two long walls, the painting above the sofa.
  for (const char* which : {"open", "door"}) {
    BuiltLayout b = LoadBuilt(std::string("tests/fixtures/layouts/living_long_") + which + ".json");
    RoomContext c = ContextOf(b, "living-room_0/0");
    RoomPlan plan = PlanOf(c);
    INFO(which << "\n" << PlanTable(plan, c.name));
    const bool floats = std::string(which) == "open";
    const SceneObject* sofa = nullptr;
    for (const SceneObject& o : plan.objects)
      if (o.category == "sofa") sofa = &o;
    REQUIRE(sofa);
    CHECK(sofa->relation == (floats ? Relation::kOnTop : Relation::kAgainstWall));
    int over_sofa = 0;
    for (const SemanticEdge& e : plan.edges)
      over_sofa += e.target == sofa->id && e.source.find("/painting-") != std::string::npos &&
                   (e.relation == SemanticRelation::kBehind || e.relation == SemanticRelation::kCentered);
    CHECK(over_sofa == (floats ? 0 : 2));
    CHECK(Check(b, c, plan).empty());
  }
}

TEST_CASE("A bedroom with no place for a double clear of its doors gets a single bed, a roomy one keeps its double",
          "[scene][planner][issue27]") {
  // bedroom_2/0 of bedroom_walkthrough.json: 6.5 m long, 1.5-2.5 m deep, a door at one end and one in its long
  // wall: no bed 1.4 m wide stands with its head to a wall clear of both doors' sweeps (the premise, checked).
  const BuiltLayout walk = LoadBuilt("tests/fixtures/layouts/bedroom_walkthrough.json");
  const RoomContext c = ContextOf(walk, "bedroom_2/0");
  const CategoryInfo* bed = FindCategory("bed");
  REQUIRE(bed);
  CHECK_FALSE(FitBathFixtures(c, {BathFixture{"bed", 1.4, bed->size_min.y, 0.7, 0.0}}).fits);
  CHECK(FitBathFixtures(c, {BathFixture{"bed", 0.9, bed->size_min.y, 0.7, 0.0}}).fits);
  const BuiltLayout wide = LoadBuilt("tests/fixtures/layouts/house_one_floor.json");
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    INFO("seed " << seed);
    const RoomPlan plan = PlanOf(c, "", seed);
    int beds = 0, pillows = 0;
    for (const auto& o : plan.objects) {
      if (o.category == "bed") {
        ++beds;
        CHECK(o.size.x < 1.4);
        CHECK(o.size.x >= bed->size_min.x);
        CHECK(o.size.y == Approx(bed->size_min.y));
        CHECK(FitBathFixtures(c, {BathFixture{"bed", o.size.x, o.size.y, o.size.z, 0.0}}).fits);
        for (const auto& p : plan.objects) pillows += p.category == "pillow" && p.parent == o.id;
      }
    }
    CHECK(beds == 1);
    CHECK(pillows <= 1);  // one pillow on a single
    bool noted = false;
    for (const std::string& n : plan.record.notes) noted = noted || n.find("no wider one stands with its head to a wall clear of the doors") != std::string::npos;
    CHECK(noted);
    for (const auto& o : PlanOf(ContextOf(wide, "bedroom_0/0"), "", seed).objects)
      if (o.category == "bed") CHECK(o.size.x >= 1.4);
  }
}

TEST_CASE("A narrow room gets the narrow end of the bed's sizes: a free long side of 0.6 m where the room is 2 m wide",
          "[scene][planner]") {
  // bedroom_0/0 of bedroom_narrow_strips.json is an L of 2 m wide strips (1.7 m of free floor across); the
  // wide bedroom of house_one_floor.json is 5 x 4 m.
  const BuiltLayout narrow = LoadBuilt("tests/fixtures/layouts/bedroom_narrow_strips.json");
  const BuiltLayout wide = LoadBuilt("tests/fixtures/layouts/house_one_floor.json");
  const CategoryInfo* bed = FindCategory("bed");
  REQUIRE(bed);
  for (uint64_t seed = 1; seed <= 4; ++seed) {
    double narrow_width = 0.0, wide_width = 0.0;
    for (const auto& o : PlanOf(ContextOf(narrow, "bedroom_0/0"), "", seed).objects)
      if (o.category == "bed") narrow_width = o.size.x;
    for (const auto& o : PlanOf(ContextOf(wide, "bedroom_0/0"), "", seed).objects)
      if (o.category == "bed") wide_width = o.size.x;
    INFO("seed " << seed);
    CHECK(narrow_width == Approx(1.4));  // 1.7 - 0.65 is below a double's width: a double's (BedFits goes narrower)
    CHECK(wide_width > 1.4 + 0.05);
  }
}



TEST_CASE("a count below zero adds nothing and says so, ten thousand armchairs are noted, not planned", "[scene][planner][issue33]") {
  const BuiltLayout b = LoadBuilt("examples/three-floor-villa.json");
  auto contexts = RoomContexts(b.layout, b.building, b.options);
  REQUIRE(contexts.ok());
  const RoomContext* living = nullptr;
  for (const RoomContext& c : *contexts)
    if (c.category == Category::kLivingRoom && !living) living = &c;
  REQUIRE(living);
  auto notes = [](const RoomPlan& p) {
    std::string all;
    for (const std::string& n : p.record.notes) all += n + "\n";
    return all;
  };
  const RoomPlan negative = PlanOf(*living, "-3 armchairs");
  INFO(notes(negative));
  CHECK(notes(negative).find("the request asks for -3 x armchair: a count below zero is no count; none added for it") != std::string::npos);
  CHECK(CountCategory(negative, "armchair", Origin::kPrompt) == 0);
  const RoomPlan many = PlanOf(*living, "10000 armchairs");
  INFO(notes(many));
  const int planned = CountCategory(many, "armchair", Origin::kPrompt);
  CHECK(planned >= 2);
  CHECK(notes(many).find("the request asks for 10000 x armchair; " + std::to_string(planned) + " fit") != std::string::npos);
}

TEST_CASE("a dining room asked to seat eight gets a table that seats eight and eight chairs, a meeting room for twelve its twelve", "[scene][planner]") {
  BuiltLayout b = LoadBuilt("examples/three-floor-villa.json");
  RoomContext dining = ContextOf(b, "dining-room_0/0");  // 4 x 6 m
  const std::string text = "A dining room that can seat eight people, and a meeting room for twelve.";
  for (uint64_t seed : {1, 2, 3}) {
    INFO("seed " << seed);
    RoomPlan plan = PlanOf(dining, text, seed);
    INFO(PlanTable(plan, dining.name));
    CHECK(Check(b, dining, plan).empty());
    const SceneObject* table = Find(plan, dining.name + "/dining-table-0");
    REQUIRE(table);
    // One seat every 0.6 m of a long side and one at each end: 1.8 m long, 0.9 m wide or more.
    CHECK(table->size.x >= 1.8 - 1e-9);
    CHECK(table->size.y >= 0.9 - 1e-9);
    CHECK(CountCategory(plan, "dining-table") == 1);
    CHECK(CountCategory(plan, "chair", Origin::kPrompt) == 8);
    CHECK(CountCategory(plan, "chair") == 8);
  }
  RoomContext meeting = ContextOf(b, "meeting-room_1/0");  // 11 x 4 m
  RoomPlan m = PlanOf(meeting, text);
  INFO(PlanTable(m, meeting.name));
  const SceneObject* table = Find(m, meeting.name + "/conference-table-0");
  REQUIRE(table);
  CHECK(table->size.x >= 3.0 - 1e-9);
  CHECK(CountCategory(m, "chair", Origin::kPrompt) == 12);
  // More than the room seats: as many as it does, and says so.
  const BuiltLayout house = LoadBuilt("examples/l-shaped-house.json");
  RoomContext l = ContextOf(house, "dining-room_0/0");  // 4 x 7 m
  RoomPlan p = PlanOf(l, "a dining room for 20 people");
  const int chairs = CountCategory(p, "chair", Origin::kPrompt);
  CHECK(chairs >= 6);
  CHECK(chairs < 20);
  bool noted = false;
  for (const std::string& n : p.record.notes)
    noted = noted || n.find("the request asks for 20 x chair; the dining-table seats " + std::to_string(chairs)) == 0;
  CHECK(noted);
}
