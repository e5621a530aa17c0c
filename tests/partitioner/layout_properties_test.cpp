// Properties of whole layouts over a few thousand seeds: valid, every class, floors nested, staircases
// stacked and off centre, coordinates on the grid, names and levels; requirements honoured or reported.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <set>

#include "layout/geometry.h"
#include "layout/layout_io.h"
#include "layout/topology.h"
#include "layout/validate.h"
#include "layout/footprint.h"
#include "partitioner/dataset.h"
#include "partitioner/geometry.h"
#include "partitioner/partitioner.h"

using namespace villa;

namespace {

bool OnGrid(double v, double grid) { return std::abs(v / grid - std::round(v / grid)) < 1e-9; }

double LevelArea(const Layout& layout, int level) {
  double a = 0.0;
  for (int r : layout.RoomsOnLevel(level)) a += Area(layout.rooms[static_cast<std::size_t>(r)].polygon);
  return a;
}

// The room's narrowest part in metres (the partitioner's MinWidth on the 0.5 m grid).
double NarrowestPart(const Ring& ring) {
  partition::IRing units;
  for (const Point& p : ring) units.push_back({std::llround(p.x / 0.5), std::llround(p.y / 0.5)});
  return partition::MinWidth(units) * 0.5;
}

int CountCategory(const Layout& layout, Category c, int level = kAnyLevel) {
  int n = 0;
  for (const Room& r : layout.rooms) n += r.category == c && (level == kAnyLevel || r.level == level);
  return n;
}

}  // namespace

TEST_CASE("Thousands of seeded layouts are valid and cover every footprint class", "[partitioner][properties]") {
  PartitionOptions options;
  std::map<std::string, int> shapes;
  std::map<int, int> floors;
  int angled = 0, angled_interior = 0, rooms_total = 0, floors_total = 0, retries = 0, habitable = 0, narrow = 0;
  const uint64_t kCount = 2400;
  for (uint64_t seed = 0; seed < kCount; ++seed) {
    const PartitionSummary s = GenerateLayout(options, seed);
    INFO("seed " << seed << ": " << s.BriefReport());
    REQUIRE(s.outcome == PartitionOutcome::kSuccess);
    const Layout& layout = s.layout;
    // Valid (GenerateLayout validated; check again independently).
    const ValidationReport report = ValidateLayout(layout);
    REQUIRE(report.valid());
    ++shapes[std::string(ShapeClassName(s.shape))];
    ++floors[s.floors];
    angled += s.angled_edges;
    angled_interior += HasSlantedWallBetweenRooms(layout);
    retries += s.retries;
    // The record's class is the one the classifier reads from the geometry.
    REQUIRE(ClassifyFootprint(layout, 0) == s.shape);
    for (const Room& r : layout.rooms) {
      if (!IsHabitable(r.category)) continue;
      ++habitable;
      narrow += NarrowestPart(r.polygon) < kHabitableWidth - 1e-9;
    }
    REQUIRE(layout.LevelCount() == s.floors);
    floors_total += s.floors;
    rooms_total += static_cast<int>(layout.rooms.size());

    // Coordinates on the 0.5 m grid; every element has its level.
    for (const Room& r : layout.rooms)
      for (const Point& p : r.polygon) REQUIRE((OnGrid(p.x, 0.5) && OnGrid(p.y, 0.5)));
    for (ElementKind kind : kAllElementKinds)
      for (const Element& e : layout.elements(kind)) {
        REQUIRE(e.level != kAllLevels);
        REQUIRE((OnGrid(e.shape.a.x, 0.5) && OnGrid(e.shape.a.y, 0.5) && OnGrid(e.shape.b.x, 0.5) && OnGrid(e.shape.b.y, 0.5)));
        REQUIRE(e.level < s.floors);
      }
    REQUIRE(layout.entrances.size() == 1);

    // Rooms a floor 3..6; upper floors inside and no larger than the floor below.
    for (int l = 0; l < s.floors; ++l) {
      const auto on = layout.RoomsOnLevel(l);
      REQUIRE(on.size() >= 3);
      REQUIRE(on.size() <= 6);
      if (l > 0) {
        REQUIRE(LevelArea(layout, l) <= LevelArea(layout, l - 1) + 1e-9);
        for (int u : on)
          for (const Point& p : layout.rooms[static_cast<std::size_t>(u)].polygon) {
            bool inside = false;
            for (int d : layout.RoomsOnLevel(l - 1))
              inside |= PointInRing(p, layout.rooms[static_cast<std::size_t>(d)].polygon, 1e-9);
            REQUIRE(inside);
          }
      }
    }
    // Staircase rooms: identical 4 x 4 utility rooms on every floor, off the footprint's centroid.
    if (s.floors > 1) {
      std::vector<Ring> stairs;
      for (const Room& r : layout.rooms)
        if (r.category == Category::kUtilityRoom) stairs.push_back(r.polygon);
      REQUIRE(static_cast<int>(stairs.size()) == s.floors);
      for (const Ring& r : stairs) {
        REQUIRE(SameRing(r, stairs[0], 1e-9));
        REQUIRE(Area(r) == Approx(16.0));
      }
      for (int l = 0; l < s.floors; ++l) {
        double cx = 0, cy = 0, a = 0;
        for (int r : layout.RoomsOnLevel(l)) {
          const Ring& ring = layout.rooms[static_cast<std::size_t>(r)].polygon;
          const Point c = Centroid(ring);
          const double ar = Area(ring);
          cx += c.x * ar, cy += c.y * ar, a += ar;
        }
        const Point sc = Centroid(stairs[0]);
        REQUIRE((std::abs(sc.x - cx / a) > 1e-6 || std::abs(sc.y - cy / a) > 1e-6));
      }
    }
    // Every room reachable from the entrance (rule 8, checked through the shared topology).
    const auto reached = ReachableRooms(layout, RoomConnections(layout), EntranceRooms(layout));
    for (bool r : reached) REQUIRE(r);
  }
  // Every class at least 3 % of the layouts; a slanted outside edge in at least 40 %, a slanted wall between
  // rooms in at least 25 % (the polygons issue's mix).
  for (ShapeClass shape : AllShapeClasses()) CHECK(shapes[std::string(ShapeClassName(shape))] * 100 >= 3 * static_cast<int>(kCount));
  CHECK(angled * 100 >= 40 * static_cast<int>(kCount));
  CHECK(angled_interior * 100 >= 25 * static_cast<int>(kCount));
  INFO("habitable rooms with a part under 1.8 m: " << narrow << " of " << habitable);
  CHECK(narrow * 100 <= 2 * habitable);
  CHECK(floors.size() == 3);
  const double mean_rooms = static_cast<double>(rooms_total) / floors_total;
  CHECK(mean_rooms > 4.5);
  CHECK(mean_rooms < 5.5);
  CHECK(retries < static_cast<int>(kCount));  // well under one retry a layout
}

TEST_CASE("The same seed gives the same layout, another seed another", "[partitioner][determinism]") {
  PartitionOptions options;
  options.floors = 2;
  const PartitionSummary a = GenerateLayout(options, 42), b = GenerateLayout(options, 42), c = GenerateLayout(options, 43);
  REQUIRE(a.ok());
  CHECK(a.layout.rooms.size() == b.layout.rooms.size());
  for (std::size_t i = 0; i < a.layout.rooms.size(); ++i) CHECK(a.layout.rooms[i].polygon == b.layout.rooms[i].polygon);
  bool differs = a.layout.rooms.size() != c.layout.rooms.size();
  for (std::size_t i = 0; !differs && i < a.layout.rooms.size(); ++i)
    differs = a.layout.rooms[i].polygon != c.layout.rooms[i].polygon;
  CHECK(differs);
}

TEST_CASE("A coarser or finer grid keeps every coordinate on it", "[partitioner][grid]") {
  for (double grid : {0.25, 1.0}) {
    PartitionOptions options;
    options.grid = grid;
    for (uint64_t seed = 0; seed < 60; ++seed) {
      const PartitionSummary s = GenerateLayout(options, seed);
      INFO("grid " << grid << " seed " << seed << ": " << s.BriefReport());
      REQUIRE(s.outcome == PartitionOutcome::kSuccess);
      for (const Room& r : s.layout.rooms)
        for (const Point& p : r.polygon) REQUIRE((OnGrid(p.x, grid) && OnGrid(p.y, grid)));
      for (const Element& d : s.layout.doors) REQUIRE((OnGrid(d.shape.a.x, grid) && OnGrid(d.shape.b.y, grid)));
    }
  }
}

TEST_CASE("The paper's brief (three stories, 14 rooms, four links) is met exactly", "[partitioner][requirements]") {
  PartitionOptions o;
  o.floors = 3;
  o.shape = ShapeClass::kIrregular;
  o.only_required_rooms = true;
  o.panoramic_windows = true;
  o.rooms = {{Category::kLivingRoom, 1, kAnyLevel}, {Category::kKitchen, 1, 0},       {Category::kDiningRoom, 1, kAnyLevel},
             {Category::kBedroom, 1, 1},            {Category::kChildrenRoom, 1, 2},  {Category::kMeetingRoom, 1, kAnyLevel},
             {Category::kOffice, 1, kAnyLevel},     {Category::kBathroom, 2, kAnyLevel}, {Category::kUtilityRoom, 3, kAnyLevel},
             {Category::kBalcony, 2, kAnyLevel}};
  o.connections = {ConnectionRequirement::KitchenOpenToDining(0), ConnectionRequirement::LivingToKitchen(),
                   ConnectionRequirement::BalconyFrom(Category::kBedroom, 1),
                   ConnectionRequirement::BalconyFrom(Category::kChildrenRoom, 2)};
  for (uint64_t seed = 0; seed < 25; ++seed) {
    const PartitionSummary s = GenerateLayout(o, seed);
    INFO("seed " << seed << ": " << s.BriefReport());
    REQUIRE(s.outcome == PartitionOutcome::kSuccess);
    CHECK(s.unmet_requirements.empty());
    CHECK(s.shape == ShapeClass::kIrregular);
    CHECK(s.layout.rooms.size() == 14);
    CHECK(CountCategory(s.layout, Category::kBathroom) == 2);
    CHECK(CountCategory(s.layout, Category::kBalcony) == 2);
    CHECK(CountCategory(s.layout, Category::kBedroom, 1) == 1);
    CHECK(CountCategory(s.layout, Category::kChildrenRoom, 2) == 1);
    CHECK(CountCategory(s.layout, Category::kKitchen, 0) == 1);
    // The kitchen opens to the dining room; the bedroom (level 1) has a door to a balcony.
    const auto links = RoomConnections(s.layout);
    bool kitchen_open = false, bedroom_balcony = false, children_balcony = false;
    for (const Connection& c : links) {
      const Room& a = s.layout.rooms[static_cast<std::size_t>(c.room_a)];
      const Room& b = s.layout.rooms[static_cast<std::size_t>(c.room_b)];
      auto is = [&](Category x, Category y) {
        return (a.category == x && b.category == y) || (a.category == y && b.category == x);
      };
      kitchen_open |= is(Category::kKitchen, Category::kDiningRoom) && c.via == Via::kOpen;
      bedroom_balcony |= is(Category::kBedroom, Category::kBalcony) && c.via == Via::kDoor && a.level == 1;
      children_balcony |= is(Category::kChildrenRoom, Category::kBalcony) && c.via == Via::kDoor && a.level == 2;
    }
    CHECK(kitchen_open);
    CHECK(bedroom_balcony);
    CHECK(children_balcony);
    bool panoramic = false;
    for (const Element& w : s.layout.windows) panoramic |= w.panoramic;
    CHECK(panoramic);
  }
}

TEST_CASE("An en-suite bathroom is reached through its bedroom's door", "[partitioner][requirements]") {
  PartitionOptions o;
  o.floors = 2;
  o.connections = {ConnectionRequirement::EnSuite(Category::kBedroom, 1)};
  for (uint64_t seed = 0; seed < 20; ++seed) {
    const PartitionSummary s = GenerateLayout(o, seed);
    INFO("seed " << seed << ": " << s.BriefReport());
    REQUIRE(s.outcome == PartitionOutcome::kSuccess);
    bool found = false;
    for (const Connection& c : RoomConnections(s.layout)) {
      const Room& a = s.layout.rooms[static_cast<std::size_t>(c.room_a)];
      const Room& b = s.layout.rooms[static_cast<std::size_t>(c.room_b)];
      found |= c.via == Via::kDoor && a.level == 1 &&
               ((a.category == Category::kBedroom && b.category == Category::kBathroom) ||
                (b.category == Category::kBedroom && a.category == Category::kBathroom));
    }
    CHECK(found);
  }
}

TEST_CASE("Requirements that cannot be met are reported, not crashed on", "[partitioner][requirements]") {
  PartitionOptions o;
  o.floors = 1;
  o.rooms = {{Category::kBedroom, 8, 0}};
  const PartitionSummary s = GenerateLayout(o, 3);
  REQUIRE(s.outcome == PartitionOutcome::kUnmetRequirements);
  REQUIRE(s.unmet_requirements.size() == 1);
  CHECK(s.unmet_requirements[0].find("8 bedroom on level 0") != std::string::npos);
  CHECK(ValidateLayout(s.layout).valid());

  PartitionOptions far;
  far.floors = 2;
  far.rooms = {{Category::kOffice, 1, 2}};
  far.connections = {ConnectionRequirement::BalconyFrom(Category::kBedroom, 2)};
  const PartitionSummary t = GenerateLayout(far, 3);
  REQUIRE(t.outcome == PartitionOutcome::kUnmetRequirements);
  CHECK(t.unmet_requirements.size() == 2);
  for (const std::string& u : t.unmet_requirements) CHECK(u.find("the building has 2 floors") != std::string::npos);
}

TEST_CASE("Invalid options are refused with the field and value named", "[partitioner][options]") {
  std::string message;
  PartitionOptions o;
  CHECK(o.IsValid(&message));
  o.grid = 0.3;
  CHECK_FALSE(o.IsValid(&message));
  CHECK(message.find("grid 0.3") != std::string::npos);
  o = PartitionOptions{};
  o.floors = 4;
  CHECK_FALSE(o.IsValid(&message));
  CHECK(message.find("floors 4") != std::string::npos);
  const PartitionSummary s = GenerateLayout(o, 1);
  CHECK(s.outcome == PartitionOutcome::kFailure);
  CHECK(s.message.find("floors 4") != std::string::npos);
  CHECK(s.layout.rooms.empty());
}

TEST_CASE("Shape class names round-trip", "[partitioner][options]") {
  for (ShapeClass s : AllShapeClasses()) CHECK(ParseShapeClass(ShapeClassName(s)) == s);
  CHECK(ShapeClassName(ShapeClass::kIrregular) == "irregular");
  CHECK(ParseShapeClass("l") == ShapeClass::kL);
  CHECK_FALSE(ParseShapeClass("star"));
}

TEST_CASE("Dataset floor plans are exact and interleaved", "[partitioner][dataset]") {
  const double w[3] = {2, 4, 4};
  const auto plan = DatasetFloorPlan(1000, w);
  std::map<int, int> n;
  for (int f : plan) ++n[f];
  CHECK(n[1] == 200);
  CHECK(n[2] == 400);
  CHECK(n[3] == 400);
  // Interleaved: every window of 10 has the 2:4:4 mix within one.
  for (std::size_t start = 0; start + 10 <= plan.size(); start += 10) {
    std::map<int, int> m;
    for (std::size_t i = start; i < start + 10; ++i) ++m[plan[i]];
    CHECK(std::abs(m[1] - 2) <= 1);
    CHECK(std::abs(m[2] - 4) <= 1);
  }
  const auto odd = DatasetFloorPlan(7, w);
  std::map<int, int> k;
  for (int f : odd) ++k[f];
  CHECK(k[1] + k[2] + k[3] == 7);
  CHECK(k[1] == 1);  // 1.4 / 2.8 / 2.8 by largest remainder: 1, 3, 3
  CHECK(k[2] == 3);
  CHECK(DatasetLayoutSeed(5, 1) != DatasetLayoutSeed(5, 2));
  CHECK(DatasetLayoutSeed(5, 1) != DatasetLayoutSeed(6, 1));
}

TEST_CASE("A panoramic window without a balcony goes to the living room", "[partitioner][requirements]") {
  PartitionOptions o;
  o.floors = 2;
  o.only_required_rooms = true;
  o.panoramic_windows = true;
  o.rooms = {{Category::kLivingRoom, 1, 0}, {Category::kKitchen, 1, 0}, {Category::kBedroom, 2, 1}, {Category::kBathroom, 1, 1}};
  for (uint64_t seed = 0; seed < 15; ++seed) {
    const PartitionSummary s = GenerateLayout(o, seed);
    INFO("seed " << seed << ": " << s.BriefReport());
    REQUIRE(s.outcome == PartitionOutcome::kSuccess);
    CHECK(CountCategory(s.layout, Category::kBalcony) == 0);
    int panoramic = 0;
    for (const Element& w : s.layout.windows) {
      if (!w.panoramic) continue;
      ++panoramic;
      CHECK(w.name.rfind("living0", 0) == 0);
    }
    CHECK(panoramic == 1);
  }
}

TEST_CASE("The layout validated is exactly the one read back from the written text", "[partitioner][round-trip]") {
  PartitionOptions options;
  for (uint64_t seed = 0; seed < 300; ++seed) {
    const PartitionSummary s = GenerateLayout(options, seed);
    REQUIRE(s.ok());
    const Result<Layout> back = ParseLayoutText(LayoutToString(s.layout, -1), "round trip");
    REQUIRE(back.ok());
    REQUIRE(back->rooms.size() == s.layout.rooms.size());
    for (std::size_t i = 0; i < s.layout.rooms.size(); ++i) {
      INFO("seed " << seed << " " << s.layout.rooms[i].name());
      CHECK(back->rooms[i].name() == s.layout.rooms[i].name());
      CHECK(back->rooms[i].polygon == s.layout.rooms[i].polygon);  // same vertices, same order
    }
    for (ElementKind kind : kAllElementKinds) {
      REQUIRE(back->elements(kind).size() == s.layout.elements(kind).size());
      for (std::size_t i = 0; i < s.layout.elements(kind).size(); ++i) {
        CHECK(back->elements(kind)[i].name == s.layout.elements(kind)[i].name);
        CHECK(back->elements(kind)[i].shape == s.layout.elements(kind)[i].shape);
        CHECK(back->elements(kind)[i].level == s.layout.elements(kind)[i].level);
      }
    }
  }
}
