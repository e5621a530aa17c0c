// The functional checks of a furnished room (solver/functional.h, issue 27), each rule on a hand-placed
// room that holds it and on one that breaks it: essentials, chairs at a side of their table with 0.75 m
// behind them, the seating group (TV angle and distance, coffee table before the sofa), a desk's chair,
// nightstands and pillows at the bed's head, the floor used, wishes, children's pieces and closed cells.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "solver/functional.h"

namespace villa::solver {
namespace {

constexpr double kPi = std::numbers::pi;

// A w x d room with its whole polygon as free floor.
scene::RoomContext Room(Category category, double w, double d) {
  scene::RoomContext c;
  c.name = "r";
  c.category = category;
  c.polygon = {{0, 0}, {w, 0}, {w, d}, {0, d}};
  c.area = w * d;
  c.free_floor = {c.polygon};
  c.free_area = c.furnishable_area = c.area;
  c.clear_height = 2.7;
  return c;
}

// A piece standing on the floor, its front (local -y) turned by yaw (0: front towards -y).
scene::SceneObject Put(const std::string& name, double x, double y, double yaw_deg, double w, double d, double h,
                       const std::string& parent = "floor") {
  scene::SceneObject o;
  o.id = "r/" + name;
  o.category = name.substr(0, name.rfind('-'));
  o.room = "r";
  o.parent = parent;
  o.relation = scene::Relation::kOnTop;
  o.pose = scene::Pose{x, y, 0.0, yaw_deg * kPi / 180.0};
  o.size = {w, d, h};
  return o;
}

struct Case {
  scene::RoomContext room;
  std::vector<scene::SceneObject> objects;
  std::vector<FunctionalWish> wishes;
  std::vector<std::string> notes;
  FunctionalCheck Check() const {
    FunctionalInput in;
    in.context = &room;
    for (const scene::SceneObject& o : objects) in.objects.push_back(&o);
    in.wishes = wishes;
    in.notes = notes;
    return CheckRoomFunction(in);
  }
  scene::SceneObject& operator[](const std::string& name) {
    for (scene::SceneObject& o : objects)
      if (o.id == "r/" + name) return o;
    FAIL("no object " << name);
    return objects.front();
  }
};

const GroupCheck* Group(const FunctionalCheck& c, const std::string& kind) {
  for (const GroupCheck& g : c.groups)
    if (g.kind == kind) return &g;
  return nullptr;
}

// A dining room 5 x 4.4 with a 1.6 x 0.9 table in the middle and a chair at each long side, facing it.
Case Dining() {
  Case c{Room(Category::kDiningRoom, 5.0, 4.4), {}, {}, {}};
  c.objects.push_back(Put("dining-table-0", 2.5, 2.2, 0, 1.6, 0.9, 0.75));
  // Chairs 0.45 x 0.5, 0.05 m from the table's long sides; front -y turned towards the table.
  c.objects.push_back(Put("chair-0", 2.1, 2.2 - 0.45 - 0.05 - 0.25, 180, 0.45, 0.5, 0.85));  // south side, faces +y
  c.objects.push_back(Put("chair-1", 2.9, 2.2 - 0.45 - 0.05 - 0.25, 180, 0.45, 0.5, 0.85));
  c.objects.push_back(Put("chair-2", 2.1, 2.2 + 0.45 + 0.05 + 0.25, 0, 0.45, 0.5, 0.85));   // north side, faces -y
  c.objects.push_back(Put("chair-3", 2.9, 2.2 + 0.45 + 0.05 + 0.25, 0, 0.45, 0.5, 0.85));
  return c;
}

TEST_CASE("Chairs at the long sides of their table, facing it with room behind them, pass", "[solver][functional]") {
  const FunctionalCheck c = Dining().Check();
  INFO(FunctionalJson(c).dump());
  CHECK(c.essentials_ok());
  CHECK(c.chairs == 4);
  CHECK(c.chairs_ok == 4);
  CHECK(c.chairs_far == 0);
  const GroupCheck* g = Group(c, "dining");
  REQUIRE(g);
  CHECK(g->ok());
  CHECK(g->members.size() == 4);
  CHECK(g->measures["min_behind_m"].get<double>() == Approx(2.2 - 0.45 - 0.05 - 0.5).margin(1e-3));
}

TEST_CASE("A chair along a wall, beyond its table's end, turned away or with no room behind it fails", "[solver][functional]") {
  SECTION("against the wall 2.15 m beyond the table's end: far from it") {
    Case d = Dining();
    d.room = Room(Category::kDiningRoom, 6.0, 4.4);
    d["chair-3"].pose = scene::Pose{5.7, 2.2, 0.0, kPi / 2};
    const FunctionalCheck c = d.Check();
    INFO(FunctionalJson(c).dump());
    CHECK(c.chairs_ok == 3);
    CHECK(c.chairs_far == 1);
    CHECK_FALSE(Group(c, "dining")->ok());
  }
  SECTION("at the table's corner") {
    Case d = Dining();
    d["chair-3"].pose->x = 2.5 + 0.8 + 0.2;
    const FunctionalCheck c = d.Check();
    INFO(FunctionalJson(c).dump());
    CHECK(c.chairs_ok == 3);
    REQUIRE(Group(c, "dining")->problems.size() == 1);
    CHECK(Group(c, "dining")->problems[0].find("chair-3") == 0);
  }
  SECTION("its back to the table") {
    Case d = Dining();
    d["chair-0"].pose->yaw = 0.0;
    CHECK(d.Check().chairs_ok == 3);
  }
  SECTION("0.5 m between their backs and the walls") {
    Case d = Dining();
    d.room = Room(Category::kDiningRoom, 5.0, 3.0);
    for (auto& o : d.objects) o.pose->y -= 0.7;  // the table at y 1.5: the chairs' backs 0.5 m from the walls
    const FunctionalCheck c = d.Check();
    INFO(FunctionalJson(c).dump());
    CHECK(c.chairs_ok == 0);
    CHECK(Group(c, "dining")->measures["min_behind_m"].get<double>() == Approx(0.5).margin(1e-3));
    bool said = false;
    for (const std::string& p : Group(c, "dining")->problems) said = said || p.find("free behind it (>= 0.75)") != std::string::npos;
    CHECK(said);
  }
}

TEST_CASE("A room type's essentials: a bedroom without its bed, a dining room without chairs", "[solver][functional]") {
  Case bedroom{Room(Category::kBedroom, 4, 4), {Put("wardrobe-0", 1, 3.7, 0, 1.2, 0.6, 2.0)}, {}, {"removed r/bed-0: no free slot"}};
  FunctionalCheck c = bedroom.Check();
  CHECK(c.essentials == std::vector<std::string>{"bed"});
  CHECK(c.missing == std::vector<std::string>{"bed"});
  CHECK(c.missing_why.find("removed r/bed-0") != std::string::npos);
  CHECK_FALSE(c.ok());
  bedroom.objects.push_back(Put("bed-0", 2, 1.1, 180, 1.6, 2.0, 0.5));
  CHECK(bedroom.Check().essentials_ok());

  // A removal the reachability feedback repeated round after round is said once.
  bedroom.objects.pop_back();
  bedroom.notes = {"removed r/bed-0: in the way", "removed r/rug-0: makes room for r/bed-0", "removed r/bed-0: in the way",
                   "removed r/rug-0: makes room for r/bed-0"};
  CHECK(bedroom.Check().missing_why == "removed r/bed-0: in the way; removed r/rug-0: makes room for r/bed-0");

  Case dining = Dining();
  dining.objects.resize(2);  // the table and one chair: two needed
  CHECK(dining.Check().missing == std::vector<std::string>{"dining chairs"});
  CHECK(EssentialsOf(Category::kBalcony).empty());
}

// A living room 6 x 5: sofa against the south wall facing north, coffee table 0.45 m before it, TV stand
// with its TV 3.45 m from the sofa, facing it.
Case Living() {
  Case c{Room(Category::kLivingRoom, 6.0, 5.0), {}, {}, {}};
  c.objects.push_back(Put("sofa-0", 3.0, 0.5, 180, 2.1, 0.9, 0.85));  // front +y
  c.objects.push_back(Put("coffee-table-0", 3.0, 0.95 + 0.45 + 0.3, 0, 1.1, 0.6, 0.42));
  c.objects.push_back(Put("tv-stand-0", 3.0, 3.9, 0, 1.6, 0.45, 0.5));
  c.objects.push_back(Put("tv-0", 3.0, 3.95, 0, 1.2, 0.08, 0.7, "r/tv-stand-0"));
  c.objects.back().pose->z = 0.5;
  return c;
}

TEST_CASE("A seating group: the sofa faces the TV at a viewing distance with the coffee table before it", "[solver][functional]") {
  {
    const FunctionalCheck c = Living().Check();
    INFO(FunctionalJson(c).dump());
    CHECK(c.seating == 1);
    CHECK(c.seating_ok == 1);
    CHECK(Group(c, "seating")->measures["tv_distance_m"].get<double>() == Approx(3.45).margin(1e-3));
  }
  SECTION("the sofa turned 90 degrees from the TV") {
    Case l = Living();
    l["sofa-0"].pose = scene::Pose{0.5, 2.5, 0.0, kPi / 2};  // against the west wall, front +x
    l["coffee-table-0"].pose = scene::Pose{1.7, 2.5, 0.0, kPi / 2};
    const FunctionalCheck c = l.Check();
    INFO(FunctionalJson(c).dump());
    CHECK(c.seating_ok == 0);
  }
  SECTION("the screen turned to the side: the sofa faces it, it shows the sofa its end") {
    Case l = Living();
    l["tv-stand-0"].pose->yaw = kPi / 2;
    l["tv-0"].pose->yaw = kPi / 2;
    const FunctionalCheck c = l.Check();
    CHECK(c.seating_ok == 0);
    CHECK(Group(c, "seating")->problems == std::vector<std::string>{"the TV is turned 90 degrees from the sofa (<= 45)"});
    l["tv-stand-0"].pose->yaw = l["tv-0"].pose->yaw = 40.0 * kPi / 180.0;  // turned 40 degrees: still seen
    CHECK(l.Check().seating_ok == 1);
  }
  SECTION("the coffee table 2 m away, behind the sofa's front") {
    Case l = Living();
    l["coffee-table-0"].pose = scene::Pose{5.3, 0.5, 0.0, 0.0};
    CHECK(l.Check().seating_ok == 0);
  }
  SECTION("no TV in a living room") {
    Case l = Living();
    l.objects.resize(2);
    const FunctionalCheck c = l.Check();
    CHECK(c.seating_ok == 0);
    CHECK(Group(c, "seating")->problems == std::vector<std::string>{"no TV"});
  }
}

TEST_CASE("A desk has its chair at its front facing it, one against the wall beside it does not count", "[solver][functional]") {
  Case office{Room(Category::kOffice, 3.5, 3.0), {}, {}, {}};
  office.objects.push_back(Put("desk-0", 1.75, 2.65, 0, 1.4, 0.7, 0.75));          // against the north wall, front -y
  office.objects.push_back(Put("office-chair-0", 1.75, 2.65 - 0.35 - 0.3, 180, 0.6, 0.6, 1.0));  // pulled in, facing +y
  FunctionalCheck c = office.Check();
  INFO(FunctionalJson(c).dump());
  CHECK(c.desks == 1);
  CHECK(c.desks_ok == 1);
  CHECK(c.essentials_ok());
  office["office-chair-0"].pose = scene::Pose{3.2, 0.5, 0.0, -kPi / 2};
  c = office.Check();
  CHECK(c.desks_ok == 0);
  CHECK(Group(c, "desk")->problems == std::vector<std::string>{"no chair at its front facing it"});
}

// A bedroom 3.6 x 3.6: bed head against the north wall (front, the foot, towards -y), nightstands at the head.
Case Bedroom() {
  constexpr double W = 3.6;
  Case c{Room(Category::kBedroom, W, W), {}, {}, {}};
  c.objects.push_back(Put("bed-0", W / 2, W - 1.0, 0, 1.6, 2.0, 0.5));
  c.objects.push_back(Put("nightstand-0", W / 2 - 0.8 - 0.05 - 0.225, W - 0.2, 0, 0.45, 0.4, 0.55));
  c.objects.push_back(Put("nightstand-1", W / 2 + 0.8 + 0.05 + 0.225, W - 0.2, 0, 0.45, 0.4, 0.55));
  for (int k = 0; k < 2; ++k) {
    c.objects.push_back(Put("pillow-" + std::to_string(k), W / 2 + (k ? 0.35 : -0.35), W - 0.3, 0, 0.55, 0.35, 0.15, "r/bed-0"));
    c.objects.back().pose->z = 0.5;
  }
  return c;
}

TEST_CASE("Nightstands and pillows at the bed's head pass, at its foot or mid-bed they fail", "[solver][functional]") {
  {
    const FunctionalCheck c = Bedroom().Check();
    INFO(FunctionalJson(c).dump());
    CHECK(c.nightstands == 2);
    CHECK(c.nightstands_ok == 2);
    CHECK(c.pillows == 2);
    CHECK(c.pillows_ok == 2);
  }
  Case b = Bedroom();
  b["nightstand-1"].pose->y = 1.6 - 0.2;  // beside the foot
  b["pillow-1"].pose->y = 2.6;             // mid-bed
  const FunctionalCheck c = b.Check();
  INFO(FunctionalJson(c).dump());
  CHECK(c.nightstands_ok == 1);
  CHECK(c.pillows_ok == 1);
  CHECK(Group(c, "bed")->problems.size() == 2);
}

TEST_CASE("The floor of a big room: everything in one corner leaves a bare disc, spread, it does not", "[solver][functional]") {
  Case living = Living();
  living.room = Room(Category::kLivingRoom, 8.0, 7.0);
  // The group squeezed into the south-west 6 x 5 corner leaves the north-east bare.
  FunctionalCheck c = living.Check();
  INFO(FunctionalJson(c).dump());
  REQUIRE(c.floor_measured);
  CHECK(c.bare_limit == Approx(std::max(1.5, 0.25 * std::sqrt(56.0))));
  CHECK(c.bare_radius > c.bare_limit);
  CHECK_FALSE(c.floor_ok);
  // Furniture along the other walls and a reading corner use the rest of the floor.
  living.objects.push_back(Put("bookcase-0", 7.8, 3.5, 90, 1.2, 0.35, 1.9));
  living.objects.push_back(Put("sideboard-0", 4.0, 6.8, 0, 1.6, 0.45, 0.8));
  living.objects.push_back(Put("armchair-0", 6.5, 5.5, 135, 0.8, 0.8, 0.9));
  living.objects.push_back(Put("side-table-0", 6.9, 6.3, 0, 0.5, 0.5, 0.55));
  living.objects.push_back(Put("plant-0", 7.6, 0.4, 0, 0.45, 0.45, 1.2));
  living.objects.push_back(Put("armchair-1", 5.2, 2.6, -90, 0.8, 0.8, 0.9));
  living.objects.push_back(Put("plant-1", 0.4, 6.6, 0, 0.45, 0.45, 1.2));
  living.objects.push_back(Put("cabinet-0", 1.8, 6.75, 0, 1.0, 0.45, 0.9));
  c = living.Check();
  INFO(FunctionalJson(c).dump());
  CHECK(c.bare_radius <= c.bare_limit);
  CHECK(c.far_share <= 0.30);
  CHECK(c.floor_ok);
  // Rugs are floor, not furniture: a rug over the bare half changes nothing.
  Case bare = Living();
  bare.room = Room(Category::kLivingRoom, 8.0, 7.0);
  Case rugged = bare;
  rugged.objects.push_back(Put("rug-0", 5.5, 4.5, 0, 3.0, 2.0, 0.01));
  const FunctionalCheck without = bare.Check(), with = rugged.Check();
  CHECK(with.bare_radius == without.bare_radius);
  CHECK(with.far_share == without.far_share);
  CHECK_FALSE(with.floor_ok);
  // A small room is not measured.
  CHECK_FALSE(Bedroom().Check().floor_measured);
}

TEST_CASE("A wish missing from its room is reported with the planner's or solver's account", "[solver][functional]") {
  Case l = Living();
  l.wishes = {{"tv", 1, false}, {"bookcase", 2, false}};
  l.objects.push_back(Put("bookcase-0", 5.7, 2.5, 90, 1.0, 0.35, 1.9));
  l.notes = {"removed r/bookcase-1: no free slot even at its smallest scale"};
  const FunctionalCheck c = l.Check();
  REQUIRE(c.wishes.size() == 2);
  CHECK(c.wishes[0].ok);
  CHECK(c.wishes[0].present == 1);
  CHECK_FALSE(c.wishes[1].ok);
  CHECK(c.wishes[1].present == 1);
  CHECK(c.wishes[1].why.find("removed r/bookcase-1") != std::string::npos);
  CHECK_FALSE(c.wishes_ok());
}

TEST_CASE("Children's pieces outside a children's room and small things in closed cells are odd", "[solver][functional]") {
  Case meeting{Room(Category::kMeetingRoom, 5.0, 4.4), {}, {}, {}};
  meeting.objects = Dining().objects;
  meeting.objects[0].category = "conference-table";
  meeting.objects[1].category = "child-chair";
  FunctionalCheck c = meeting.Check();
  REQUIRE(c.odd.size() == 1);
  CHECK(c.odd[0] == "chair-0: a children's piece in a meeting-room");
  meeting.room.category = Category::kChildrenRoom;
  CHECK(meeting.Check().odd.empty());

  // A kettle on the bottom of a counter's closed cell.
  Case kitchen{Room(Category::kKitchen, 4.0, 3.0), {}, {}, {}};
  kitchen.objects.push_back(Put("counter-0", 1.0, 2.7, 0, 1.2, 0.6, 0.9));
  kitchen.objects[0].asset = "test:counter";
  kitchen.objects.push_back(Put("kettle-0", 1.0, 2.7, 0, 0.2, 0.15, 0.25, "r/counter-0"));
  kitchen.objects[1].surface = 0;
  kitchen.objects[1].pose->z = 0.1;
  AssetRecord counter;
  counter.id = "test:counter";
  counter.size = {1.2, 0.6, 0.9};
  SupportSurface shelf;  // the cell's floor, 8 cm up, behind a door
  shelf.z = 0.08;
  shelf.polygon = {{-0.55, -0.25}, {0.55, -0.25}, {0.55, 0.25}, {-0.55, 0.25}};
  shelf.clear_height = 0.7;
  counter.support_surfaces = {shelf};
  Cavity cell;
  cell.min = {-0.55, -0.25, 0.08};
  cell.max = {0.55, 0.25, 0.78};
  cell.open = "closed";
  cell.floor_surface = 0;
  counter.cavities = {cell};
  FunctionalInput in;
  in.context = &kitchen.room;
  for (const auto& o : kitchen.objects) in.objects.push_back(&o);
  in.assets = [&](std::string_view id) -> const AssetRecord* { return id == counter.id ? &counter : nullptr; };
  REQUIRE(counter.ClosedCellFloor(0));
  c = CheckRoomFunction(in);
  REQUIRE(c.odd.size() == 1);
  CHECK(c.odd[0] == "kettle-0: stands 'ontop' inside a closed cell of counter-0");
  counter.cavities[0].open = "-y";  // an open shelf: fine
  CHECK_FALSE(counter.ClosedCellFloor(0));
  CHECK(CheckRoomFunction(in).odd.empty());
}

TEST_CASE("Tallies add rooms up and print the summary line", "[solver][functional]") {
  FunctionalTally t;
  t.Add(Dining().Check());
  t.Add(Bedroom().Check());
  CHECK(t.rooms == 2);
  CHECK(t.rooms_essential == 2);
  CHECK(t.chairs == 4);
  CHECK(t.chairs_ok == 4);
  CHECK(t.nightstands_ok == 2);
  CHECK(t.Line().find("essentials 2/2 rooms, table chairs 4/4 (0 far)") == 0);
  const auto j = t.ToJson();
  CHECK(j["table_chairs"] == nlohmann::ordered_json{4, 4});
}

}  // namespace
}  // namespace villa::solver
