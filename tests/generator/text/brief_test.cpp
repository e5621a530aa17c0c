// The brief parser: the paper's example request, synonyms, numbers, floors, connections, furniture, and
// what it reports as not understood.
#include <algorithm>

#include <catch2/catch.hpp>

#include "generator/text/brief.h"
#include "generator/text/plan.h"
#include "layout/layout_io.h"

namespace villa {
namespace {

const BriefRooms* FindRooms(const Brief& brief, Category category, int level) {
  for (const auto& r : brief.rooms)
    if (r.category == category && r.level == level) return &r;
  return nullptr;
}

bool HasConnection(const Brief& brief, Category from, Category to, LinkKind kind, int level) {
  for (const auto& c : brief.connections) {
    bool forward = c.from == from && std::find(c.to.begin(), c.to.end(), to) != c.to.end();
    bool backward = c.from == to && std::find(c.to.begin(), c.to.end(), from) != c.to.end();
    if ((forward || backward) && c.kind == kind && c.level == level) return true;
  }
  return false;
}

int Exact(const Brief& brief, Category category, int level = kAnyLevel) {
  const BriefRooms* r = FindRooms(brief, category, level);
  if (!r) return -100;
  if (r->min != r->max) return -(r->min) - 1000;
  return r->min;
}

constexpr const char* kPaperRequest =
    "I want to build a three-story, irregularly shaped villa. The house needs a living room, a kitchen, a dining "
    "room, a master bedroom, a children's room, a meeting room, an office, two bathrooms, three utility rooms, and "
    "two balconies. For the layout, I hope the kitchen on the first floor can be openly connected to the dining "
    "room, and the living room can directly access the kitchen. Both the second-floor bedroom and the third-floor "
    "children's room should directly connect to balconies with panoramic windows. In addition, please include a TV "
    "in the meeting room and place a double bed in the children's room.";

}  // namespace

TEST_CASE("the paper's example request is parsed whole") {
  Brief brief = ParseBrief(kPaperRequest);
  INFO(BriefToJson(brief).dump(2));
  REQUIRE(brief.floors == 3);
  REQUIRE(brief.shape == ShapeClass::kIrregular);
  CHECK(!brief.unsupported_shape);
  CHECK(Exact(brief, Category::kLivingRoom) == 1);
  CHECK(Exact(brief, Category::kKitchen) == 1);
  CHECK(Exact(brief, Category::kDiningRoom) == 1);
  CHECK(Exact(brief, Category::kBedroom) == 1);
  CHECK(Exact(brief, Category::kChildrenRoom) == 1);
  CHECK(Exact(brief, Category::kMeetingRoom) == 1);
  CHECK(Exact(brief, Category::kOffice) == 1);
  CHECK(Exact(brief, Category::kBathroom) == 2);
  CHECK(Exact(brief, Category::kUtilityRoom) == 3);
  CHECK(Exact(brief, Category::kBalcony) == 2);
  CHECK(brief.rooms.size() == 10);
  // "the kitchen on the first floor" = ground floor (the paper's convention), open to the dining room.
  CHECK(HasConnection(brief, Category::kKitchen, Category::kDiningRoom, LinkKind::kOpen, 0));
  CHECK(HasConnection(brief, Category::kLivingRoom, Category::kKitchen, LinkKind::kAny, kAnyLevel));
  // "second-floor bedroom" = level 1, "third-floor children's room" = level 2, each reaching a balcony.
  CHECK(HasConnection(brief, Category::kBedroom, Category::kBalcony, LinkKind::kAny, 1));
  CHECK(HasConnection(brief, Category::kChildrenRoom, Category::kBalcony, LinkKind::kAny, 2));
  CHECK(brief.connections.size() == 4);
  // The balconies carry the panoramic windows, one on each of those floors.
  REQUIRE(brief.panoramic.size() == 2);
  for (const auto& p : brief.panoramic) CHECK(p.category == Category::kBalcony);
  CHECK(((brief.panoramic[0].level == 1 && brief.panoramic[1].level == 2) ||
         (brief.panoramic[0].level == 2 && brief.panoramic[1].level == 1)));
  REQUIRE(brief.furniture.size() == 2);
  CHECK(brief.furniture[0].item == "TV");
  CHECK(brief.furniture[0].category == Category::kMeetingRoom);
  CHECK(brief.furniture[1].item == "double bed");
  CHECK(brief.furniture[1].category == Category::kChildrenRoom);
  CHECK(brief.unparsed.empty());
  CHECK(brief.conflicts.empty());
  CHECK(!brief.british_ordinals);
}

TEST_CASE("floor counts in words, digits and compounds") {
  CHECK(ParseBrief("a three-story villa").floors == 3);
  CHECK(ParseBrief("a 3-storey villa").floors == 3);
  CHECK(ParseBrief("a house on 2 floors").floors == 2);
  CHECK(ParseBrief("two levels, please").floors == 2);
  CHECK(ParseBrief("a single-storey home").floors == 1);
  CHECK(ParseBrief("a cosy bungalow").floors == 1);
  CHECK(ParseBrief("Floors: 3. Shape: L-shaped.").floors == 3);
  Brief multi = ParseBrief("a multi-storey house");
  CHECK(!multi.floors);
  CHECK(multi.floors_min == 2);
  // Named floors imply at least that many.
  CHECK(ParseBrief("a kitchen downstairs and a bedroom on the third floor").floors_min == 3);
  Brief five = ParseBrief("a five-story villa");
  CHECK(five.floors == 5);
  REQUIRE(five.conflicts.size() == 1);
  CHECK(five.conflicts[0] == "5 floors asked: a villa has at most 3 (FORMAT.md rule 6)");
}

TEST_CASE("synonyms, numbers and en-suite / open-plan words") {
  Brief brief = ParseBrief(
      "A 2-storey U-shaped home: lounge, open-plan kitchen, WC, study, master bedroom with en-suite, kids' room "
      "and 2 terraces.");
  INFO(BriefToJson(brief).dump(2));
  CHECK(brief.floors == 2);
  CHECK(brief.shape == ShapeClass::kU);
  CHECK(Exact(brief, Category::kLivingRoom) == 1);
  CHECK(Exact(brief, Category::kKitchen) == 1);
  CHECK(Exact(brief, Category::kBathroom) == 2);  // the WC and the en-suite
  CHECK(Exact(brief, Category::kOffice) == 1);
  CHECK(Exact(brief, Category::kBedroom) == 1);
  CHECK(Exact(brief, Category::kChildrenRoom) == 1);
  CHECK(Exact(brief, Category::kBalcony) == 2);
  CHECK(HasConnection(brief, Category::kBedroom, Category::kBathroom, LinkKind::kDoor, kAnyLevel));
  CHECK(HasConnection(brief, Category::kKitchen, Category::kLivingRoom, LinkKind::kOpen, kAnyLevel));
  CHECK(brief.unparsed.empty());
}

TEST_CASE("rooms per floor: leading scopes, trailing phrases, upstairs, each floor") {
  SECTION("ground floor and upstairs") {
    Brief brief = ParseBrief("On the ground floor there is a living room and a kitchen; upstairs are two bedrooms "
                             "and a bathroom.");
    CHECK(Exact(brief, Category::kLivingRoom, 0) == 1);
    CHECK(Exact(brief, Category::kKitchen, 0) == 1);
    // "upstairs" and the ground floor with no count of floors and no other floor named: two floors, as
    // people mean it (issue 32's unseen requests), the upstairs rooms on level 1.
    CHECK(brief.floors == 2);
    CHECK(Exact(brief, Category::kBedroom, 1) == 2);
    CHECK(Exact(brief, Category::kBathroom, 1) == 1);
    // Another floor named: "upstairs" stays the upper floors together.
    Brief top = ParseBrief("Kitchen on the ground floor, bedrooms upstairs and an office on the top floor.");
    CHECK(!top.floors);
  }
  SECTION("upstairs in a two-floor house is level 1") {
    Brief brief = ParseBrief("A two-story house: a kitchen and a lounge downstairs, three bedrooms upstairs.");
    CHECK(Exact(brief, Category::kKitchen, 0) == 1);
    CHECK(Exact(brief, Category::kLivingRoom, 0) == 1);
    CHECK(Exact(brief, Category::kBedroom, 1) == 3);
  }
  SECTION("a trailing phrase places the room before it, not the whole list") {
    Brief brief = ParseBrief("A two-story house with a living room, a kitchen, two bedrooms, a bathroom on each "
                             "floor and a balcony.");
    CHECK(Exact(brief, Category::kBathroom, kEachLevel) == 1);
    CHECK(Exact(brief, Category::kBedroom) == 2);
    CHECK(Exact(brief, Category::kLivingRoom) == 1);
    CHECK(Exact(brief, Category::kBalcony) == 1);
  }
  SECTION("'and' joins rooms under one trailing phrase") {
    Brief brief = ParseBrief("I need a kitchen and a dining room on the ground floor and an office on the top floor "
                             "of a three-story villa.");
    CHECK(Exact(brief, Category::kKitchen, 0) == 1);
    CHECK(Exact(brief, Category::kDiningRoom, 0) == 1);
    CHECK(Exact(brief, Category::kOffice, 2) == 1);
  }
  SECTION("American ordinals by default, British when the text names a ground floor and a first floor") {
    Brief american = ParseBrief("First floor: kitchen and living room. Second floor: two bedrooms.");
    CHECK(!american.british_ordinals);
    CHECK(Exact(american, Category::kKitchen, 0) == 1);
    CHECK(Exact(american, Category::kBedroom, 1) == 2);
    Brief british = ParseBrief("Ground floor: kitchen and living room. First floor: two bedrooms.");
    CHECK(british.british_ordinals);
    CHECK(Exact(british, Category::kKitchen, 0) == 1);
    CHECK(Exact(british, Category::kBedroom, 1) == 2);
    // The annotator's convention: ground, second (= middle), third (= top) floor.
    Brief drafts = ParseBrief("Ground floor: a kitchen. Second floor: a study. Third floor: a bedroom.");
    CHECK(!drafts.british_ordinals);
    CHECK(Exact(drafts, Category::kOffice, 1) == 1);
    CHECK(Exact(drafts, Category::kBedroom, 2) == 1);
  }
  SECTION("a trailing floor phrase after a comma list's 'and' places only the last room") {
    Brief brief = ParseBrief("A two-storey house with a living room, a kitchen, a dining room and two bedrooms upstairs.");
    CHECK(Exact(brief, Category::kDiningRoom) == 1);  // on no floor in particular
    CHECK(Exact(brief, Category::kBedroom, 1) == 2);
    // "..., all upstairs": the whole list.
    Brief all = ParseBrief("Two kids' rooms, a main bedroom and a bathroom, all upstairs. Downstairs: kitchen.");
    CHECK(Exact(all, Category::kChildrenRoom, 1) == 2);
    CHECK(Exact(all, Category::kBedroom, 1) == 1);
    CHECK(Exact(all, Category::kBathroom, 1) == 1);
    Brief pair = ParseBrief("A two-storey house: a kitchen and a dining room on the ground floor, two bedrooms upstairs.");
    CHECK(Exact(pair, Category::kKitchen, 0) == 1);
    CHECK(Exact(pair, Category::kDiningRoom, 0) == 1);
  }
  SECTION("top floor and level numbers") {
    Brief brief = ParseBrief("A three-storey villa with a meeting room on the top floor and a study on level 2.");
    CHECK(Exact(brief, Category::kMeetingRoom, 2) == 1);
    CHECK(Exact(brief, Category::kOffice, 1) == 1);
  }
}

TEST_CASE("issue 32: one room for each of others, sums across floors, negations that run on, spec headings") {
  SECTION("each with, a bathroom each, every bedroom has, for each of, both en-suite, each storey") {
    CHECK(Exact(ParseBrief("Four bedrooms upstairs, each with an en-suite bathroom."), Category::kBathroom) == 4);
    CHECK(Exact(ParseBrief("A house with two bedrooms with a bathroom each."), Category::kBathroom) == 2);
    CHECK(Exact(ParseBrief("Three bedrooms; every bedroom has a balcony."), Category::kBalcony) == 3);
    CHECK(Exact(ParseBrief("Three bedrooms upstairs and a balcony for each of the three upstairs bedrooms."),
                Category::kBalcony) == 3);
    CHECK(Exact(ParseBrief("A bungalow with 2 bedrooms, both en-suite, plus a guest WC."), Category::kBathroom) == 3);
    CHECK(Exact(ParseBrief("Three storeys, each with its own bathroom."), Category::kBathroom) == 3);
    CHECK(Exact(ParseBrief("A bungalow with a kitchen and 3 bedrooms, 2 of them en-suite."), Category::kBathroom) == 2);
  }
  SECTION("every bedroom with its own bathroom (the children's rooms too); both upper floors get one each") {
    Brief every = ParseBrief("Two kids' rooms and one main bedroom, every bedroom with its own bathroom.");
    CHECK(Exact(every, Category::kBathroom) == 3);
    Brief both = ParseBrief("Three floors. Both upper floors get a balcony.");
    CHECK(Exact(both, Category::kBalcony, 1) == 1);
    CHECK(Exact(both, Category::kBalcony, 2) == 1);
  }
  SECTION("estate-agent shorthand: 3 bed 2.5 bath, br, ba, a four-bed house that lists its bedrooms") {
    Brief agent = ParseBrief("A 3 bed 2.5 bath two-story with a kitchen.");
    CHECK(Exact(agent, Category::kBedroom) == 3);
    CHECK(Exact(agent, Category::kBathroom) == 3);  // the half bath is a room
    Brief abbreviated = ParseBrief("Two floors. Upstairs: 2 br, 2 ba. Ground: kitchen, living rm.");
    CHECK(Exact(abbreviated, Category::kBedroom, 1) == 2);
    CHECK(Exact(abbreviated, Category::kBathroom, 1) == 2);
    CHECK(Exact(abbreviated, Category::kLivingRoom, 0) == 1);
    Brief four = ParseBrief("Four-bed detached house: four bedrooms, a bathroom and a kitchen.");
    CHECK(Exact(four, Category::kBedroom) == 4);
    CHECK(four.unparsed.empty());
    CHECK(Exact(ParseBrief("A Victorian-style terrace with two bedrooms."), Category::kBalcony) == -100);  // the house
    // A bedroom in brackets after a suite is the suite.
    CHECK(Exact(ParseBrief("Living room, kitchen, primary suite (bedroom + bath), and one guest bedroom."), Category::kBedroom) == 2);
  }
  SECTION("rooms with no floor and rooms on a floor add up") {
    Brief brief = ParseBrief("A two-storey house with a WC under the stairs and a family bathroom upstairs.");
    CHECK(Exact(brief, Category::kBathroom) == 2);
  }
  SECTION("a negation runs on over or, nor and 'and the'; after the noun") {
    Brief brief = ParseBrief("Two bedrooms and a kitchen. We won't need a study or a dining room. Skip the balcony "
                             "and the office. Living room not needed.");
    CHECK(Exact(brief, Category::kOffice) == 0);
    CHECK(Exact(brief, Category::kDiningRoom) == 0);
    CHECK(Exact(brief, Category::kBalcony) == 0);
    CHECK(Exact(brief, Category::kLivingRoom) == 0);
    CHECK(Exact(brief, Category::kBedroom) == 2);
  }
  SECTION("spec headings and shorthand") {
    Brief brief = ParseBrief("Floors: 2. Footprint: L. Ground: kitchen, lounge. Upper: bedrooms x3, bathrooms (2).");
    REQUIRE(brief.shape.has_value());
    CHECK(*brief.shape == ShapeClass::kL);
    CHECK(Exact(brief, Category::kBedroom, 1) == 3);
    CHECK(Exact(brief, Category::kBathroom, 1) == 2);
    // A text that names its ground floor counts numbered floors up from it.
    Brief numbered = ParseBrief("Floors: 3. Ground: kitchen. Floor 1: two bedrooms. Floor 2: an office.");
    CHECK(Exact(numbered, Category::kBedroom, 1) == 2);
    CHECK(Exact(numbered, Category::kOffice, 2) == 1);
    Brief each = ParseBrief("Three floors with a bathroom on each one. Ground floor: a kitchen.");
    CHECK(Exact(each, Category::kBathroom, kEachLevel) == 1);
  }
  SECTION("British words") {
    CHECK(Exact(ParseBrief("A bungalow with two reception rooms, a kitchen and a box room."), Category::kLivingRoom) == 2);
    CHECK(Exact(ParseBrief("A bungalow with two reception rooms, a kitchen and a box room."), Category::kBedroom) == 1);
    CHECK(Exact(ParseBrief("A bungalow with a kitchen, a bedroom and a cloakroom WC."), Category::kBathroom) == 1);
  }
}

TEST_CASE("a definite list refers to rooms, an indefinite one counts them") {
  Brief definite = ParseBrief("The ground floor holds the kitchen, dining room and living room.");
  for (Category c : {Category::kKitchen, Category::kDiningRoom, Category::kLivingRoom}) {
    const BriefRooms* r = FindRooms(definite, c, 0);
    REQUIRE(r);
    CHECK(r->min == 1);
    CHECK(r->max == -1);
  }
  Brief indefinite = ParseBrief("The ground floor holds a kitchen, dining room and living room.");
  for (Category c : {Category::kKitchen, Category::kDiningRoom, Category::kLivingRoom}) CHECK(Exact(indefinite, c, 0) == 1);
}

TEST_CASE("estate-agent shorthand: 4 bed 3 bath") {
  Brief brief = ParseBrief("2 story home, 4 bed 3 bath, with a study and a double bed in the study.");
  CHECK(brief.floors == 2);
  CHECK(Exact(brief, Category::kBedroom) == 4);
  CHECK(Exact(brief, Category::kBathroom) == 3);
  CHECK(Exact(brief, Category::kOffice) == 1);
  REQUIRE(brief.furniture.size() == 1);
  CHECK(brief.furniture[0].item == "double bed");
  CHECK(brief.furniture[0].category == Category::kOffice);
  CHECK(brief.unparsed.empty());
}

TEST_CASE("negations, ranges and counts after the noun") {
  Brief brief = ParseBrief("A two-storey house with no balcony, without an office, at least two bathrooms, a "
                           "couple of bedrooms and three or more children's rooms. Kitchens: 1.");
  INFO(BriefToJson(brief).dump(2));
  CHECK(Exact(brief, Category::kBalcony) == 0);
  CHECK(Exact(brief, Category::kOffice) == 0);
  const BriefRooms* bathrooms = FindRooms(brief, Category::kBathroom, kAnyLevel);
  REQUIRE(bathrooms);
  CHECK(bathrooms->min == 2);
  CHECK(bathrooms->max == -1);
  CHECK(Exact(brief, Category::kBedroom) == 2);
  const BriefRooms* children = FindRooms(brief, Category::kChildrenRoom, kAnyLevel);
  REQUIRE(children);
  CHECK(children->min == 3);
  CHECK(children->max == -1);
  CHECK(Exact(brief, Category::kKitchen) == 1);
}

TEST_CASE("a part of a count named after it is not more rooms") {
  // Kids' rooms out of the bedrooms are taken from them; a guest bedroom out of the bedrooms is one of them.
  const Brief kids = ParseBrief("I need 4 bedrooms in total (2 of them are kids' rooms), three bathrooms and a kitchen.");
  CHECK(Exact(kids, Category::kBedroom) == 2);
  CHECK(Exact(kids, Category::kChildrenRoom) == 2);
  CHECK(Exact(kids, Category::kBathroom) == 3);
  const Brief guest = ParseBrief("Two bedrooms, one of them a guest bedroom, plus a bathroom and a kitchen.");
  CHECK(Exact(guest, Category::kBedroom) == 2);
  // Without "of them" a guest bedroom is one more.
  CHECK(Exact(ParseBrief("Two bedrooms and a guest bedroom, plus a bathroom."), Category::kBedroom) == 3);
}

TEST_CASE("footprints the partitioner cannot make are reported") {
  for (const char* text : {"a round villa with a kitchen", "a pentagonal house", "a triangular home with two floors"}) {
    Brief brief = ParseBrief(text);
    INFO(text);
    CHECK(brief.unsupported_shape.has_value());
    CHECK(!brief.shape.has_value());
  }
  CHECK(ParseBrief("an L-shaped house").shape == ShapeClass::kL);
  CHECK(ParseBrief("an H shape floor plan").shape == ShapeClass::kH);
  CHECK(ParseBrief("a T-shaped villa").shape == ShapeClass::kT);
  CHECK(ParseBrief("a square house").shape == ShapeClass::kRectangle);
  CHECK(ParseBrief("a villa with slanted walls").shape == ShapeClass::kIrregular);
  // The polygonal classes.
  CHECK(ParseBrief("a hexagonal home with two floors").shape == ShapeClass::kHexagon);
  CHECK(ParseBrief("a six-sided pavilion").shape == ShapeClass::kHexagon);
  CHECK(ParseBrief("an octagonal single-storey house").shape == ShapeClass::kOctagon);
  CHECK(ParseBrief("a star-shaped house").shape == ShapeClass::kCross);
  CHECK(ParseBrief("a cross-shaped villa round a central hall").shape == ShapeClass::kCross);
  CHECK(ParseBrief("a trapezoidal plot-hugging house").shape == ShapeClass::kTrapezoid);
  CHECK(ParseBrief("a house with a bay window in the living room").shape == ShapeClass::kBay);
  CHECK(ParseBrief("a villa with an angled wing for the bedrooms").shape == ShapeClass::kAngledWing);
  CHECK(ParseBrief("a pavilion with no right angles, two bedrooms and a kitchen").shape == ShapeClass::kOctagon);
  // A star or cross that is not the outline is no footprint.
  CHECK(!ParseBrief("a villa with a star on the door").shape);
  // A round table is furniture, not the footprint; 200 square metres is not a shape.
  Brief table = ParseBrief("a house with a round table in the dining room, 200 square metres");
  CHECK(!table.unsupported_shape);
  CHECK(!table.shape);
  REQUIRE(table.furniture.size() == 1);
  CHECK(table.furniture[0].item == "round table");
  CHECK(table.furniture[0].category == Category::kDiningRoom);
}

TEST_CASE("what is not understood is reported with its place in the text") {
  const std::string text = "A two-story villa with a kitchen, a swimming pool, a garage and 200 square meters.";
  Brief brief = ParseBrief(text);
  REQUIRE(brief.unparsed.size() == 3);
  CHECK(brief.unparsed[0].text == "swimming pool");
  CHECK(brief.unparsed[1].text == "garage");
  CHECK(brief.unparsed[2].text == "200 square meters");
  for (const auto& u : brief.unparsed) CHECK(text.substr(u.begin, u.end - u.begin) == u.text);
  CHECK(Exact(brief, Category::kKitchen) == 1);
  Json json = BriefToJson(brief);
  CHECK(json["unparsed"].size() == 3);
  CHECK(json["unparsed"][1]["text"] == "garage");
}

TEST_CASE("connections, the entrance, sides and furniture") {
  Brief brief = ParseBrief(
      "The entrance opens into the lounge. The lounge leads to the kitchen, which is open to the dining area. Each "
      "bedroom has its own bathroom. The kitchen is on the north side. Please put two desks in the study and a "
      "large flat-screen TV in the living room.");
  INFO(BriefToJson(brief).dump(2));
  REQUIRE(brief.entrance.size() == 1);
  CHECK(brief.entrance[0].category == Category::kLivingRoom);
  CHECK(HasConnection(brief, Category::kLivingRoom, Category::kKitchen, LinkKind::kAny, kAnyLevel));
  CHECK(HasConnection(brief, Category::kKitchen, Category::kDiningRoom, LinkKind::kOpen, kAnyLevel));
  bool every = false;
  for (const auto& c : brief.connections)
    if (c.from == Category::kBedroom && c.kind == LinkKind::kDoor) every = c.every;
  CHECK(every);
  REQUIRE(brief.sides.size() == 1);
  CHECK(brief.sides[0].category == Category::kKitchen);
  CHECK(brief.sides[0].side == "north");
  REQUIRE(brief.furniture.size() == 2);
  CHECK(brief.furniture[0].item == "desks");
  CHECK(brief.furniture[0].count == 2);
  CHECK(brief.furniture[0].category == Category::kOffice);
  CHECK(brief.furniture[1].item == "large flat-screen TV");
  CHECK(brief.furniture[1].category == Category::kLivingRoom);
  CHECK(brief.unparsed.empty());
}

TEST_CASE("contradictions with the format are reported as conflicts") {
  Brief brief = ParseBrief("A three-story villa with two utility rooms, and seven bedrooms on the ground floor.");
  INFO(BriefToJson(brief).dump(2));
  bool staircase = false, crowded = false;
  for (const auto& c : brief.conflicts) {
    staircase |= c.find("utility (staircase) room a floor") != std::string::npos;
    crowded |= c.find("7 rooms asked on level 0") != std::string::npos;
  }
  CHECK(staircase);
  CHECK(crowded);
}

TEST_CASE("a layout is checked against every requirement of a brief") {
  Result<Layout> layout = LoadLayout(std::string(VILLA_FIXTURE_DIR) + "/layouts/house_two_floors.json");
  REQUIRE(layout.ok());
  SECTION("a brief the fixture meets") {
    Brief brief = ParseBrief(
        "A two-story rectangular house with two living rooms, a kitchen open to the dining room, two bathrooms and a "
        "bedroom. The children's room reaches a balcony with panoramic windows. The entrance leads into the "
        "living room.");
    BriefCheck check = CheckBrief(brief, *layout);
    INFO(BriefCheckToJson(check).dump(2));
    CHECK(check.total() == brief.RequirementCount());
    CHECK(check.total() >= 10);
    CHECK(check.met() == check.total());
    CHECK(check.adherence() == 1.0);
  }
  SECTION("a brief it does not meet, with what it has instead") {
    Brief brief = ParseBrief("A three-story L-shaped house with a kitchen open to the living room and an office.");
    BriefCheck check = CheckBrief(brief, *layout);
    INFO(BriefCheckToJson(check).dump(2));
    std::vector<RequirementResult> unmet = check.unmet();
    REQUIRE(unmet.size() == 4);
    CHECK(unmet[0].requirement == "3 floors");
    CHECK(unmet[0].detail == "has 2");
    CHECK(unmet[1].requirement == "L footprint");
    CHECK(unmet[1].detail == "footprint is rectangle");
    CHECK(unmet[2].requirement == "1 office");
    CHECK(unmet[2].detail == "found 0");
    CHECK(unmet[3].requirement == "kitchen open to living-room");
    CHECK(check.met() == 1);  // the kitchen
  }
}

namespace villa {

TEST_CASE("any text parses: random word soup keeps every span inside the text") {
  const std::vector<std::string> words = {
      "a", "the", "two", "3", "3rd", "first", "floor", "floors", "-", "story", "storey", "level", "0", "on", "each",
      "upstairs", "top", "ground", "kitchen", "open", "to", "dining", "room", "living", "bedroom", "bed", "4",
      "bath", "en", "suite", "with", "its", "own", "bathroom", "balcony", "balconies", "panoramic", "windows",
      "TV", "in", "children's", "kids'", "’s", "no", "without", "at", "least", "or", "more", ",", ".", ";", ":",
      "\n", "L", "shaped", "round", "star", "entrance", "leads", "into", "north", "side", "which", "is", "and",
      "x", "Bedrooms", "for", "six", "table", "m²", "é", "\"", "(", ")", "/", "&", "directly", "access", "it",
      "has", "also", "every", "couple", "of", "1.5", "999999999", "upstairs:", "Floors", "zero"};
  std::uint64_t state = 12345;
  auto next = [&state] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<std::size_t>(state >> 33);
  };
  for (int n = 0; n < 3000; ++n) {
    std::string text;
    const std::size_t length = next() % 40;
    for (std::size_t k = 0; k < length; ++k) {
      text += words[next() % words.size()];
      if (next() % 3) text += ' ';
    }
    Brief brief = ParseBrief(text);
    INFO(text);
    for (const auto& u : brief.unparsed) {
      REQUIRE(u.begin <= u.end);
      REQUIRE(u.end <= text.size());
      CHECK(text.substr(u.begin, u.end - u.begin) == u.text);
    }
    for (const auto& r : brief.rooms) {
      CHECK(r.min >= 0);
      CHECK((r.max < 0 || r.max >= r.min));
      CHECK(r.source.end <= text.size());
    }
    CHECK_NOTHROW(BriefToJson(brief).dump());
    CHECK(brief.RequirementCount() >= 0);
  }
}

// Issue 17 defect 7: four requests the parser used to misread while reporting them met.

TEST_CASE("'each reached from a bedroom' links the balconies to the bedrooms already counted") {
  Brief brief = ParseBrief(
      "A two-story villa with two bedrooms upstairs, and two balconies upstairs, each reached from a bedroom.");
  INFO(BriefToJson(brief).dump(2));
  CHECK(Exact(brief, Category::kBedroom, 1) == 2);
  CHECK(Exact(brief, Category::kBalcony, 1) == 2);
  CHECK(!FindRooms(brief, Category::kBedroom, kAnyLevel));
  REQUIRE(HasConnection(brief, Category::kBalcony, Category::kBedroom, LinkKind::kAny, 1));
  for (const auto& c : brief.connections)
    if (c.from == Category::kBalcony) CHECK(c.every);
  CHECK(brief.unparsed.empty());
}

TEST_CASE("chained 'opens onto' gives both openings") {
  Brief brief = ParseBrief(
      "A two-story villa where the kitchen opens onto the dining room and the dining room opens onto the living "
      "room.");
  INFO(BriefToJson(brief).dump(2));
  CHECK(HasConnection(brief, Category::kKitchen, Category::kDiningRoom, LinkKind::kOpen, kAnyLevel));
  CHECK(HasConnection(brief, Category::kDiningRoom, Category::kLivingRoom, LinkKind::kOpen, kAnyLevel));
  CHECK(brief.connections.size() == 2);
  CHECK(brief.unparsed.empty());
}

TEST_CASE("'six bedrooms on the upper two floors, three on each' gives three on each upper floor") {
  Brief brief = ParseBrief("A three-story villa with six bedrooms on the upper two floors, three on each.");
  INFO(BriefToJson(brief).dump(2));
  REQUIRE(brief.floors == 3);
  CHECK(Exact(brief, Category::kBedroom, 1) == 3);
  CHECK(Exact(brief, Category::kBedroom, 2) == 3);
  CHECK(!FindRooms(brief, Category::kBedroom, 0));
  CHECK(!FindRooms(brief, Category::kBedroom, kAnyLevel));
  CHECK(!FindRooms(brief, Category::kBedroom, kUpperLevels));
  CHECK(brief.conflicts.empty());
  CHECK(brief.unparsed.empty());
}

TEST_CASE("'three on each' that does not add up to the total is a conflict") {
  Brief brief = ParseBrief("A three-story villa with five bedrooms on the upper two floors, three on each.");
  INFO(BriefToJson(brief).dump(2));
  CHECK(Exact(brief, Category::kBedroom, 1) == 3);
  CHECK(Exact(brief, Category::kBedroom, 2) == 3);
  CHECK(brief.conflicts.size() == 1);
}

TEST_CASE("'both bathrooms on the ground floor' asks for two there") {
  Brief brief = ParseBrief("A two-story villa with both bathrooms on the ground floor.");
  INFO(BriefToJson(brief).dump(2));
  CHECK(Exact(brief, Category::kBathroom, 0) == 2);
  CHECK(brief.unparsed.empty());
  // "both" after the bathrooms were counted refers to them, it adds none.
  Brief again = ParseBrief("Two bathrooms and a kitchen. Both bathrooms are on the ground floor.");
  INFO(BriefToJson(again).dump(2));
  CHECK(Exact(again, Category::kBathroom) == 2);
  const BriefRooms* ground = FindRooms(again, Category::kBathroom, 0);
  REQUIRE(ground);
  CHECK(ground->min == 1);  // a reference: at least one of the two there
}

TEST_CASE("a request with words not understood is partial, never met, and the report quotes them") {
  PlanOptions options;
  options.time_budget_s = 2.0;
  PlanSummary plan = PlanLayout("A two-story villa with a kitchen and a flurbish upstairs.", options);
  INFO(plan.BriefReport());
  REQUIRE(plan.valid());
  CHECK(plan.check.met() == plan.check.total());  // every requirement it did read is met...
  REQUIRE(plan.brief.unparsed.size() == 1);
  CHECK(plan.brief.unparsed[0].text == "flurbish");
  CHECK(plan.outcome == PlanOutcome::kPartial);  // ...but not the word it could not place
  CHECK(plan.BriefReport().find("not understood: \"flurbish\"") != std::string::npos);
  CHECK(plan.BriefReport().rfind("partial", 0) == 0);
}

TEST_CASE("make run's request is met, its furniture wishes go to the furnish stage") {
  const std::string request =
      "I want a three-story L-shaped villa with a living room, an open-plan kitchen and a dining room on the ground "
      "floor, two bedrooms and a bathroom upstairs, and a children's room with a balcony with panoramic windows on "
      "the top floor. Put a TV in the living room and bookshelves full of books in the children's room.";
  PlanOptions options;
  options.seed = 7;
  PlanSummary plan = PlanLayout(request, options);
  INFO(plan.BriefReport());
  CHECK(plan.brief.unparsed.empty());
  REQUIRE(plan.brief.furniture.size() == 2);
  CHECK(plan.brief.furniture[0].item == "TV");
  CHECK(plan.brief.furniture[0].category == Category::kLivingRoom);
  CHECK(plan.brief.furniture[1].item == "bookshelves full of books");
  CHECK(plan.brief.furniture[1].category == Category::kChildrenRoom);
  CHECK(plan.outcome == PlanOutcome::kMet);
  CHECK(plan.BriefReport().find("furnishing wish") != std::string::npos);
  CHECK(plan.BriefReport().find("not understood") == std::string::npos);
}

}  // namespace villa

TEST_CASE("a number keeps its sign: -3 bedrooms and -2 floors are no counts, reported, never met", "[issue33]") {
  PlanOptions options;
  options.time_budget_s = 2.0;
  PlanSummary plan = PlanLayout("A villa with -3 bedrooms and -2 floors.", options);
  INFO(plan.BriefReport());
  CHECK(plan.outcome != PlanOutcome::kMet);
  REQUIRE(plan.brief.conflicts.size() >= 2);
  CHECK(plan.brief.conflicts[plan.brief.conflicts.size() - 2] == "\"-3\": a number below zero is no count of rooms or floors; not read as 3");
  CHECK(plan.BriefReport().find("conflict: \"-2\": a number below zero") != std::string::npos);
  // A hyphen between words is no sign: a 3-bedroom villa still has three.
  const Brief hyphen = ParseBrief("A 3-bedroom villa.");
  CHECK(hyphen.conflicts.empty());
}

}  // namespace villa

namespace villa {

TEST_CASE("a laundry, pantry or mudroom is a utility room on one floor, and no false met where the stairs take it") {
  const Brief one = ParseBrief("Single floor: kitchen, lounge, a laundry room, two bedrooms and a bathroom");
  CHECK(Exact(one, Category::kUtilityRoom) == 1);
  CHECK(one.unparsed.empty());
  CHECK(Exact(ParseBrief("a bungalow with a kitchen, a pantry, a living room and a bedroom"), Category::kUtilityRoom) == 1);
  // Two floors: the utility room on each floor holds the stairs, so a laundry there stays unmet and says why.
  const Brief two = ParseBrief("two storey; kitchen, dining room, living room, 3 bedrooms, 2 bathrooms, laundry");
  CHECK(FindRooms(two, Category::kUtilityRoom, kAnyLevel) == nullptr);
  REQUIRE(two.unparsed.size() == 1);
  CHECK(two.unparsed[0].text == "laundry");
  CHECK(std::any_of(two.conflicts.begin(), two.conflicts.end(),
                    [](const std::string& c) { return c.find("the utility room holds the stairs") != std::string::npos; }));
  // The staircase room asked by name is still that room.
  CHECK(Exact(ParseBrief("two floors with a staircase room on each floor, a kitchen and two bedrooms"), Category::kUtilityRoom, kEachLevel) == 1);
}

TEST_CASE("shorthand, repeated digits, dozens and misspelt room words are read as people mean them", "[issue32]") {
  {
    const Brief b = ParseBrief("1 floor. 2br 1ba, kitchen, lounge");
    INFO(BriefToJson(b).dump(1));
    CHECK(Exact(b, Category::kBedroom) == 2);
    CHECK(Exact(b, Category::kBathroom) == 1);
    CHECK(b.unparsed.empty());
  }
  {
    const Brief b = ParseBrief("Two (2) bedrooms, two (2) bathrooms and one (1) kitchen on a single floor.");
    INFO(BriefToJson(b).dump(1));
    CHECK(Exact(b, Category::kBedroom) == 2);
    CHECK(Exact(b, Category::kBathroom) == 2);
    CHECK(b.unparsed.empty());
  }
  {
    const Brief b = ParseBrief("Three storeys. Half a dozen bedrooms in total, three bathrooms and a kitchen.");
    INFO(BriefToJson(b).dump(1));
    CHECK(Exact(b, Category::kBedroom) == 6);
  }
  {
    // One edit from exactly one room's name; a word of its own ("double" beside "doubles") is no misspelling.
    const Brief b = ParseBrief("just 2 bedroms, a bathrom, a balcny and two double bedrooms");
    INFO(BriefToJson(b).dump(1));
    CHECK(Exact(b, Category::kBedroom) == 4);
    CHECK(Exact(b, Category::kBathroom) == 1);
    CHECK(Exact(b, Category::kBalcony) == 1);
  }
}

TEST_CASE("spec sheets with dashes, yes and no, and brackets that are part of a count", "[issue32]") {
  {
    const Brief b = ParseBrief("Storeys: 1 | Bedrooms - 2 | Bathrooms - 1 | Kitchen: yes | Study: no | Dining - 0");
    INFO(BriefToJson(b).dump(1));
    CHECK(Exact(b, Category::kBedroom) == 2);
    CHECK(Exact(b, Category::kBathroom) == 1);
    CHECK(Exact(b, Category::kKitchen) == 1);
    CHECK(Exact(b, Category::kOffice) == 0);
    CHECK(Exact(b, Category::kDiningRoom) == 0);
  }
  {
    const Brief b = ParseBrief("2 fl | 3 bed (1 master) | 2 bath | kitchen");
    INFO(BriefToJson(b).dump(1));
    CHECK(b.floors == 2);
    CHECK(Exact(b, Category::kBedroom) == 3);
  }
  {
    const Brief b = ParseBrief("Second floor: three bedrooms and two bathrooms, one of which is an en-suite.");
    INFO(BriefToJson(b).dump(1));
    int bathrooms = 0;
    for (const auto& r : b.rooms)
      if (r.category == Category::kBathroom) bathrooms += r.min;
    CHECK(bathrooms == 2);
  }
}

TEST_CASE("floors by headings and glosses: ground/first headings, 'top:', '1st floor (ground level)', 'each of the two upper floors'",
          "[issue32]") {
  {
    const Brief b = ParseBrief("a villa over ground and first floor. ground: kitchen and a lounge. first: 3 bedrooms and a bathroom");
    INFO(BriefToJson(b).dump(1));
    CHECK(b.british_ordinals);
    CHECK(Exact(b, Category::kKitchen, 0) == 1);
    CHECK(Exact(b, Category::kBedroom, 1) == 3);
  }
  {
    const Brief b = ParseBrief("3 levels. ground: kitchen, living. lvl 1: 3 bed, 2 bath. top: office + balcony");
    INFO(BriefToJson(b).dump(1));
    CHECK(b.floors == 3);
    CHECK(Exact(b, Category::kBedroom, 1) == 3);
    CHECK(Exact(b, Category::kOffice, 2) == 1);
    CHECK(Exact(b, Category::kBalcony, 2) == 1);
  }
  {
    const Brief b = ParseBrief("3 floors. 1st floor (ground level): kitchen & living room. 2nd floor: 2 bedrooms + 1 bath. 3rd floor: an office.");
    INFO(BriefToJson(b).dump(1));
    CHECK_FALSE(b.british_ordinals);
    CHECK(Exact(b, Category::kKitchen, 0) == 1);
    CHECK(Exact(b, Category::kBedroom, 1) == 2);
    CHECK(Exact(b, Category::kOffice, 2) == 1);
    CHECK(b.conflicts.empty());
  }
  {
    const Brief b = ParseBrief("Three-storey villa with a balcony on each of the two upper floors and a kitchen.");
    INFO(BriefToJson(b).dump(1));
    int balconies = 0;
    for (const auto& r : b.rooms)
      if (r.category == Category::kBalcony) balconies += r.level == kEachLevel || r.level == kUpperLevels ? 2 * r.min : r.min;
    CHECK(balconies == 2);
  }
}

TEST_CASE("a room for each of the people counted before it: 'three kids: a children's room for each kid'", "[issue32]") {
  const Brief b = ParseBrief("A two-story house for a family with three kids: a children's room for each kid, plus one master bedroom.");
  INFO(BriefToJson(b).dump(1));
  CHECK(Exact(b, Category::kChildrenRoom) == 3);
  CHECK(Exact(b, Category::kBedroom) == 1);
  CHECK(b.unparsed.empty());
  const Brief sons = ParseBrief("two sons, a bedroom for each son, a kitchen");
  CHECK(Exact(sons, Category::kBedroom) == 2);
}

TEST_CASE("a room to be used as another kind is one room of that kind: 'a small box room I can use as a study'", "[issue32]") {
  const Brief b = ParseBrief("Two bedrooms, a lounge with space for the telly, and a small box room I can use as a study.");
  INFO(BriefToJson(b).dump(1));
  CHECK(Exact(b, Category::kBedroom) == 2);
  CHECK(Exact(b, Category::kOffice) == 1);
  CHECK(b.unparsed.empty());
  CHECK(Exact(ParseBrief("a spare room to use as an office and a kitchen"), Category::kOffice) == 1);
  CHECK(FindRooms(ParseBrief("a spare room to use as an office and a kitchen"), Category::kBedroom, kAnyLevel) == nullptr);
}

TEST_CASE("'up' and 'down' right after a room are the floors of a two-storey note", "[issue32]") {
  const Brief b = ParseBrief("2 storeys: 3 bedrooms up, a bathroom up, kitchen and lounge down, a wc down");
  INFO(BriefToJson(b).dump(1));
  CHECK(Exact(b, Category::kBedroom, 1) == 3);
  CHECK(Exact(b, Category::kBathroom, 1) == 1);
  CHECK(Exact(b, Category::kBathroom, 0) == 1);
  CHECK(Exact(b, Category::kLivingRoom, 0) == 1);
  // Not a floor where a word follows: "set up a desk", "a room up the stairs".
  CHECK(Exact(ParseBrief("a bedroom up the stairs and a kitchen"), Category::kBedroom) == 1);
}

TEST_CASE("a count split over the floors in brackets after it: 'Bathrooms: 2 (one downstairs, one upstairs)'", "[issue32]") {
  const Brief b = ParseBrief("Storeys - 2 | Bedrooms - 3 (all upstairs) | Bathrooms - 2 (1 downstairs, 1 upstairs) | Kitchen - 1 (downstairs)");
  INFO(BriefToJson(b).dump(1));
  CHECK(b.floors == 2);
  CHECK(Exact(b, Category::kBedroom, 1) == 3);
  CHECK(Exact(b, Category::kBathroom, 0) == 1);
  CHECK(Exact(b, Category::kBathroom, 1) == 1);
  CHECK(Exact(b, Category::kKitchen, 0) == 1);
  CHECK(b.unparsed.empty());
  const Brief after = ParseBrief("2 storey house, 3 bedrooms up, 2 bathrooms (one up, one down)");
  CHECK(Exact(after, Category::kBathroom, 0) == 1);
  CHECK(Exact(after, Category::kBathroom, 1) == 1);
  const Brief ordinals = ParseBrief("A two-storey house with 2 living rooms, the first downstairs, the second upstairs.");
  CHECK(Exact(ordinals, Category::kLivingRoom, 0) == 1);
  CHECK(Exact(ordinals, Category::kLivingRoom, 1) == 1);
  // Brackets that are no floors are left as they are.
  CHECK(Exact(ParseBrief("3 bedrooms (2 of them en-suite) and a kitchen"), Category::kBedroom) == 3);
}

TEST_CASE("floors named by their ordinals alone after 'on the': 'two bedrooms on the first, an office on the second'", "[issue32]") {
  const Brief b = ParseBrief("A three-storey house: living room and kitchen on the ground floor, two bedrooms on the first, an office on the second.");
  INFO(BriefToJson(b).dump(1));
  CHECK(b.british_ordinals);
  CHECK(Exact(b, Category::kBedroom, 1) == 2);
  CHECK(Exact(b, Category::kOffice, 2) == 1);
  // Not where a word follows the ordinal, or the text names no floors.
  CHECK(Exact(ParseBrief("a kitchen on the first try and two bedrooms"), Category::kBedroom) == 2);
}

TEST_CASE("'the master bedroom' after guest bedrooms only is one more bedroom, after plain bedrooms one of them", "[issue32]") {
  const Brief b = ParseBrief("Two-storey house. Downstairs: lounge, kitchen, a guest bedroom. Upstairs: the master bedroom and another bedroom.");
  INFO(BriefToJson(b).dump(1));
  CHECK(Exact(b, Category::kBedroom, 0) == 1);
  CHECK(Exact(b, Category::kBedroom, 1) == 2);
  const Brief plain = ParseBrief("Three bedrooms upstairs; the master bedroom has a walk-in wardrobe.");
  CHECK(Exact(plain, Category::kBedroom, 1) == 3);
}

TEST_CASE("'our three kids each want their own room' is three children's rooms", "[issue32]") {
  const Brief b = ParseBrief("Two floors. Our three kids each want their own room, plus a bedroom for us and a kitchen.");
  INFO(BriefToJson(b).dump(1));
  CHECK(Exact(b, Category::kChildrenRoom) == 3);
  CHECK(Exact(b, Category::kBedroom) == 1);
  CHECK(Exact(ParseBrief("the two boys each get their own bedroom"), Category::kChildrenRoom) == 2);
}

TEST_CASE("'one bathroom for every two bedrooms' is a ratio, in the brief and in the recount", "[issue32]") {
  const Brief b = ParseBrief("Two-storey, four bedrooms, one bathroom for every two bedrooms, a kitchen and a living room.");
  INFO(BriefToJson(b).dump(1));
  CHECK(Exact(b, Category::kBedroom) == 4);
  CHECK(Exact(b, Category::kBathroom) == 2);
  CHECK(Exact(ParseBrief("three bedrooms and a bathroom for every two bedrooms"), Category::kBathroom) == 2);
  CHECK(Exact(ParseBrief("three bedrooms and a balcony for every bedroom"), Category::kBalcony) == 3);
  PlanOptions options;
  options.seed = 3;
  const PlanSummary plan = PlanLayout("Two-storey, four bedrooms, one bathroom for every two bedrooms, a kitchen and a living room.", options);
  CHECK(plan.outcome == PlanOutcome::kMet);
}

// The third unseen set (issue 32): listing shorthand, second thoughts, asides in brackets, heading lines.
TEST_CASE("listing shorthand is written out: '3bd/2ba', 'kit, din, fam rm', '2 balc', 'GF: ... 1F: ...'", "[issue32]") {
  const Brief b = ParseBrief("2 flrs, 3bd/2ba, kit, din, fam rm, 2 balc, meeting rm. Dining tbl for 8.");
  INFO(BriefToJson(b).dump(1));
  CHECK(Exact(b, Category::kBedroom) == 3);
  CHECK(Exact(b, Category::kBathroom) == 2);
  CHECK(Exact(b, Category::kKitchen) == 1);
  CHECK(Exact(b, Category::kDiningRoom) == 1);  // the table is furniture, not a second dining room
  CHECK(Exact(b, Category::kLivingRoom) == 1);
  CHECK(Exact(b, Category::kBalcony) == 2);
  CHECK(Exact(b, Category::kMeetingRoom) == 1);
  const Brief f = ParseBrief("Octagon plan, 2 flrs. GF: kitchen, lounge, WC. 1F: 3 bed, 1 bath, balcony.");
  INFO(BriefToJson(f).dump(1));
  CHECK(Exact(f, Category::kKitchen, 0) == 1);
  CHECK(Exact(f, Category::kBedroom, 1) == 3);
  CHECK(Exact(f, Category::kBalcony, 1) == 1);
  const Brief e = ParseBrief("Storeys: 2\nLevel 0 (ground) \xE2\x80\x93 kitchen, lounge \xC3\x97" "2\nLevel 1 \xE2\x80\x93 bedroom \xC3\x97" "2, bathroom");
  INFO(BriefToJson(e).dump(1));
  CHECK(Exact(e, Category::kLivingRoom, 0) == 2);
  CHECK(Exact(e, Category::kBedroom, 1) == 2);
  CHECK(e.unparsed.empty());
}

TEST_CASE("second thoughts replace what they correct: 'actually, make that three', 'scratch the meeting room'", "[issue32]") {
  CHECK(Exact(ParseBrief("Kitchen, lounge, two bedrooms, one bathroom. Actually, make that three bedrooms."), Category::kBedroom) == 3);
  const Brief it = ParseBrief("I'd like four bedrooms... actually make it three, plus a nursery. Two bathrooms.");
  INFO(BriefToJson(it).dump(1));
  CHECK(Exact(it, Category::kBedroom) == 3);
  CHECK(Exact(it, Category::kChildrenRoom) == 1);
  CHECK(it.unparsed.empty());
  const Brief scratch = ParseBrief("Three storeys. Second floor: office and meeting room. No, scratch the meeting room, just the office.");
  INFO(BriefToJson(scratch).dump(1));
  for (const BriefRooms& r : scratch.rooms)
    if (r.category == Category::kMeetingRoom) {
      CHECK(r.max == 0);
    }
  CHECK(scratch.conflicts.empty());
}

TEST_CASE("rooms in brackets after a count are parts of it, unless the brackets add one", "[issue32]") {
  CHECK(Exact(ParseBrief("a kitchen and two bedrooms (ours plus a guest room)"), Category::kBedroom) == 2);
  CHECK(Exact(ParseBrief("Bedrooms: 5 (incl. master)\nBathrooms: 2"), Category::kBedroom) == 5);
  const Brief kids = ParseBrief("Upstairs the four bedrooms (well, strictly three bedrooms and a nursery for the baby) and a bathroom.");
  INFO(BriefToJson(kids).dump(1));
  CHECK(Exact(kids, Category::kBedroom, 1) == 3);
  CHECK(Exact(kids, Category::kChildrenRoom, 1) == 1);
  CHECK(Exact(ParseBrief("two bedrooms (plus a guest room)"), Category::kBedroom) != 2);
  // "used as": one room of the kind it is used as.
  CHECK(Exact(ParseBrief("a kitchen, a living room, and a second living room we'd use as a den"), Category::kLivingRoom) == 2);
  const Brief studio = ParseBrief("Rooms: studio (used as office), bedroom, shower room");
  CHECK(Exact(studio, Category::kOffice) == 1);
}

TEST_CASE("floors: heading lines scope the lines under them, asides in brackets keep a trailing floor phrase", "[issue32]") {
  const Brief spec = ParseBrief("Floors: 2\nGround floor:\n- Living room (sofa, TV)\n- Kitchen\n- WC\nFirst floor:\n- Bedroom x3\n- Bathroom x2");
  INFO(BriefToJson(spec).dump(1));
  CHECK(Exact(spec, Category::kBathroom, 0) == 1);
  CHECK(Exact(spec, Category::kBedroom, 1) == 3);
  CHECK(Exact(spec, Category::kBathroom, 1) == 2);
  const Brief aside = ParseBrief(
      "just one bedroom and one bath (with a bathtub, not a shower!) upstairs, and a kitchen, livng room and a study downstairs. two floors.");
  INFO(BriefToJson(aside).dump(1));
  CHECK(Exact(aside, Category::kBedroom, 1) == 1);
  CHECK(Exact(aside, Category::kBathroom, 1) == 1);
  CHECK(Exact(aside, Category::kKitchen, 0) == 1);
  CHECK(Exact(aside, Category::kLivingRoom, 0) == 1);
  CHECK(Exact(aside, Category::kOffice, 0) == 1);
  // "Upstairs for living:" says what a floor is for; "both kids get their own children's room" is two.
  const Brief live = ParseBrief("Two floors. Upstairs for living: two bedrooms, a kitchen and a lounge. Both kids get their own children's room.");
  INFO(BriefToJson(live).dump(1));
  CHECK(Exact(live, Category::kLivingRoom, 1) == 1);
  CHECK(Exact(live, Category::kChildrenRoom) == 2);
}

TEST_CASE("a total first and its floors after: the floors' rooms are part of it, 'more' adds", "[issue32]") {
  const Brief b = ParseBrief("Floors: 3\nBedrooms x4, Bathrooms x3, Kitchen x1\nTop floor: 2 bedrooms + 1 bathroom only");
  INFO(BriefToJson(b).dump(1));
  CHECK(Exact(b, Category::kBedroom, 2) == 2);
  CHECK(Exact(b, Category::kBedroom) == 4);  // in all, the two on the top floor among them
  CHECK(Exact(b, Category::kBathroom) == 3);
  const Brief more = ParseBrief("Two floors. Four bedrooms and a kitchen. Upstairs two more bedrooms.");
  INFO(BriefToJson(more).dump(1));
  CHECK(Exact(more, Category::kBedroom) == 6);
  CHECK(Exact(more, Category::kBedroom, 1) == 2);
  // "the two upper floors each have two bedrooms": two on each.
  const Brief each = ParseBrief("Three floors. The ground floor has the kitchen and living room; the two upper floors each have two bedrooms.");
  INFO(BriefToJson(each).dump(1));
  CHECK(Exact(each, Category::kBedroom, 1) == 2);
  CHECK(Exact(each, Category::kBedroom, 2) == 2);
  CHECK(each.unparsed.empty());
  int beds = 0;
  for (const BriefRooms& r : ParseBrief("Upper: master bed, 2 children's rooms, bathroom").rooms)
    if (r.category == Category::kBedroom) beds += r.min;
  CHECK(beds == 1);
}

TEST_CASE("the fourth unseen set: forms, headings, second thoughts, fixtures set against each other", "[issue32]") {
  // "bedroom count = 4": a count after "count ="; "Floors ... 1": a form's dot leaders.
  const Brief form = ParseBrief("Requirements:\n- storeys = 2\n- bedroom count = 4\n- bathroom count = 2\n- kitchen = 1");
  INFO(BriefToJson(form).dump(1));
  CHECK(Exact(form, Category::kBedroom) == 4);
  CHECK(Exact(form, Category::kBathroom) == 2);
  CHECK(ParseBrief("Spec:\nFloors ... 1\nShape ... octagon\nRooms ... bedroom, bathroom, kitchen").floors == 1);
  // A "Middle:" heading between "Ground:" and "Top:"; not "In the middle:" of one floor's wings.
  const Brief middle = ParseBrief("Three-storey house. Ground: kitchen, dining. Middle: living room, office. Top: three bedrooms.");
  INFO(BriefToJson(middle).dump(1));
  CHECK(Exact(middle, Category::kLivingRoom, 1) == 1);
  CHECK(ParseBrief("A single-storey H-shaped home. In the middle: a big kitchen and living room.").floors == 1);
  // A second thought on the floors: the later count holds.
  CHECK(ParseBrief("An L-shaped house on three floors - wait, two floors is plenty. Kitchen and lounge.").floors == 2);
  // "well, ... actually": the restatement replaces the kitchen-diner.
  const Brief well = ParseBrief("On the ground floor, a kitchen-diner - well, a kitchen and a separate dining room actually - and a WC.");
  INFO(BriefToJson(well).dump(1));
  int kitchens = 0;
  for (const BriefRooms& r : well.rooms) kitchens += r.category == Category::kKitchen ? r.min : 0;
  CHECK(kitchens == 1);
  // The "no" after a dash is the next room's; "doubles as home and office" is what the building is.
  const Brief dash = ParseBrief("Two storeys, three bedrooms, kitchen, living room - no dining room, we eat in the kitchen.");
  CHECK(Exact(dash, Category::kLivingRoom) == 1);
  const Brief home = ParseBrief("A building that doubles as home and office, three levels. Ground: a meeting room, an office and a bathroom.");
  CHECK(Exact(home, Category::kOffice, 0) == 1);
  CHECK(Exact(home, Category::kOffice) == -100);  // no second office anywhere
  // Fixtures set against each other are no rooms.
  const Brief bath = ParseBrief("Bungalow: kitchen, living rm, 2 bedrms, bathrm, study. Bath not shower.");
  INFO(BriefToJson(bath).dump(1));
  CHECK(Exact(bath, Category::kBathroom) == 1);
  CHECK(Exact(ParseBrief("two bathrooms, one with a bath and one with a shower"), Category::kBathroom) == 2);
  CHECK(Exact(ParseBrief("4 bed, 2 bath, shower room"), Category::kBathroom) == 3);
}

TEST_CASE("the fifth unseen set: notes that furnish a room named before, storage, negated floors, corrections", "[issue32]") {
  // "Lvg rm: big sectional + TV. Study: desk.": the rooms of the list, furnished, not two more.
  const Brief notes = ParseBrief("2-flr villa pls. GF: lvg rm, kit, din rm, WC, terrace. 1F: 3 bdrm, 2 bath, study. "
                                 "Lvg rm: big sectional + TV. Study: desk.");
  INFO(BriefToJson(notes).dump(1));
  CHECK(Exact(notes, Category::kLivingRoom, 0) == 1);
  CHECK(Exact(notes, Category::kLivingRoom) == -100);  // no second one, anywhere
  CHECK(Exact(notes, Category::kOffice, 1) == 1);
  CHECK(Exact(notes, Category::kOffice) == -100);
  const Brief kids = ParseBrief("Single lvl. Lounge, kit, 2 bdrm, kids rm, 1 bath. Kit needs fridge & dishwasher. Kids rm: desk.");
  INFO(BriefToJson(kids).dump(1));
  CHECK(Exact(kids, Category::kChildrenRoom) == 1);
  CHECK(Exact(kids, Category::kKitchen) == 1);
  // Without a room of its kind before, a heading still names a room.
  CHECK(Exact(ParseBrief("Kitchen, bedroom. Study: desk."), Category::kOffice) == 1);
  // "2x kids rm", "mtg rm", "store" in a list.
  const Brief terse = ParseBrief("3 floors. GF: kit, din, lvg, WC, store. 1F: 2 bdrm, bath, 2x kids rm. 2F: home office, mtg rm, terrace. "
                                 "Mtg rm w/ 6 chairs.");
  INFO(BriefToJson(terse).dump(1));
  CHECK(Exact(terse, Category::kChildrenRoom, 1) == 2);
  CHECK(Exact(terse, Category::kMeetingRoom, 2) == 1);
  CHECK(Exact(terse, Category::kMeetingRoom) == -100);
  // The store is understood: a separate one cannot be made where the utility room holds the stairs.
  CHECK(Exact(terse, Category::kUtilityRoom, 0) == -100);
  CHECK(std::any_of(terse.conflicts.begin(), terse.conflicts.end(), [](const std::string& c) { return c.find("\"store\"") == 0; }));
  CHECK(Exact(ParseBrief("Bungalow: kitchen, lounge, bedroom, bathroom, store."), Category::kUtilityRoom) == 1);
  CHECK(Exact(ParseBrief("A kitchen with plenty of storage and a bedroom."), Category::kUtilityRoom) == -100);
  // "the other shower only": what the other bathroom holds.
  CHECK(Exact(ParseBrief("Bungalow: kit, 3 bdrm, 2 bthrm. Bathtub in 1 of the bthrms, the other shower only."), Category::kBathroom) == 2);
  // "no first floor at all": no heading, and no British numbering.
  const Brief bungalow = ParseBrief("Just a ground floor for us, it's a bungalow - no first floor at all. Lounge, kitchen, two bedrooms and a shower room.");
  INFO(BriefToJson(bungalow).dump(1));
  CHECK(bungalow.floors == 1);
  CHECK(Exact(bungalow, Category::kBedroom, 0) == 2);
  // Corrections: "two kids' rooms - no, three"; "make that six" after a table is the table's.
  const Brief three = ParseBrief("Two-storey. Ground floor: living room, kitchen, WC. First floor: our bedroom, two kids' rooms - no, three, "
                                 "we're optimists - and a bathroom. Dining table for four... make that six.");
  INFO(BriefToJson(three).dump(1));
  CHECK(Exact(three, Category::kChildrenRoom, 1) == 3);
  CHECK(Exact(three, Category::kBathroom, 1) == 1);
  // "turn the office into a meeting room": one room, not both.
  const Brief turned = ParseBrief("One storey. Lounge, kitchen, two bedrooms, a bathroom, an office - hmm, no, turn the office into a meeting room.");
  INFO(BriefToJson(turned).dump(1));
  CHECK(Exact(turned, Category::kOffice) == 0);
  CHECK(Exact(turned, Category::kMeetingRoom) == 1);
  // "No matter" is no master bedroom taken back.
  const Brief matter = ParseBrief("Two storeys: downstairs a living room and a kitchen, upstairs two bedrooms. No matter, we can wait.");
  CHECK(Exact(matter, Category::kBedroom, 1) == 2);
  CHECK(Exact(matter, Category::kBedroom) == -100);
  // Showers and baths of a bathroom named beside them are fixtures; "one bed ... each" furniture.
  CHECK(Exact(ParseBrief("First floor: main bedroom with en-suite and a bathroom. I'd like a walk-in shower in the en-suite."),
              Category::kBathroom, 0) == 2);  // (American: the first floor is the ground)
  CHECK(Exact(ParseBrief("Two bathrooms. The downstairs bathroom gets a shower."), Category::kBathroom) == 2);
  CHECK(Exact(ParseBrief("A house with a kitchen, two bedrooms and a bath."), Category::kBathroom) == 1);
  const Brief beds = ParseBrief("Level 2 has 2 kids' rooms, one bedroom and two bathrooms. Both kids' rooms with one bed and 1 desk each.");
  INFO(BriefToJson(beds).dump(1));
  CHECK(Exact(beds, Category::kBedroom) == -100);
}

TEST_CASE("the sixth unseen set: furnishing counts after a heading, rooms for the kids, moves, totals said again", "[issue32]") {
  // "lvg rm: 2 armchairs", "per bedroom: 1 bed", "dining room: 1 table, 4 chairs": the furniture's counts,
  // not more rooms.
  const Brief notes = ParseBrief("one floor, six rooms: 2 bedrooms, 1 bathroom, 1 kitchen, 1 living room, 1 dining room. "
                                 "per bedroom: 1 bed. dining room: 1 table, 4 chairs. lvg rm: 2 armchairs.");
  INFO(BriefToJson(notes).dump(1));
  CHECK(Exact(notes, Category::kBedroom) == 2);
  CHECK(Exact(notes, Category::kDiningRoom) == 1);
  CHECK(Exact(notes, Category::kLivingRoom) == 1);
  CHECK(notes.conflicts.empty());
  CHECK(notes.unparsed.empty());  // "six rooms" is the sum of the list
  // Rooms for the children, written as rooms for people.
  const Brief kids = ParseBrief("Two storeys. Downstairs: kitchen, living room. Upstairs: our bedroom, two rooms for the kids "
                                "and a bathroom. A room for the grandchildren too.");
  INFO(BriefToJson(kids).dump(1));
  CHECK(Exact(kids, Category::kChildrenRoom, 1) == 2);
  CHECK(Exact(kids, Category::kChildrenRoom) == 3);  // the grandchildren's besides the two
  // Notes: "w/ ensuite", "2nd lvg rm", "piano in GF lvg rm" (the one listed), "2 plants on balc".
  const Brief terse = ParseBrief("3 flrs. GF: kit, din rm, lvg rm, guest WC. 1F: master bdrm w/ ensuite, 2x kids rm, family bath. "
                                 "2F: study, 2nd lvg rm, balc. piano in GF lvg rm. 2 plants on balc.");
  INFO(BriefToJson(terse).dump(1));
  CHECK(Exact(terse, Category::kLivingRoom, 0) == 1);
  CHECK(Exact(terse, Category::kLivingRoom, 2) == 1);
  CHECK(Exact(terse, Category::kBalcony, 2) == 1);
  CHECK(Exact(terse, Category::kBathroom, 1) == 2);
  CHECK(terse.unparsed.empty());
  // A room moved to another floor is that room, not one more there.
  const Brief moved = ParseBrief("Three floors. Ground floor: kitchen, living room and an office. Middle floor: two bedrooms and a "
                                 "bathroom. Top floor: a meeting room. No wait - the meeting room goes on the ground floor instead "
                                 "of the office, and the office moves up to the top floor, together with a balcony.");
  INFO(BriefToJson(moved).dump(1));
  CHECK(Exact(moved, Category::kMeetingRoom, 0) == 1);
  CHECK(Exact(moved, Category::kMeetingRoom, 2) == -100);
  CHECK(Exact(moved, Category::kOffice, 2) == 1);
  CHECK(Exact(moved, Category::kOffice, 0) == -100);
  // A floor count taken back after "no,".
  CHECK(ParseBrief("Let's do three floors. Hmm, no, two floors is plenty. Kitchen and a bedroom.").floors == 2);
  // Totals said again after the floors: "That's 2 balconies total", "(4)", "10 rooms".
  const Brief totals = ParseBrief("3 floors, 10 rooms. Ground: kitchen + living room + 1 bathroom (3). 1st floor: 2 bedrooms + 1 "
                                  "bathroom + 1 balcony (4). 2nd floor: 1 meeting room + 1 office + 1 balcony (3). That's 2 "
                                  "balconies total.");
  INFO(BriefToJson(totals).dump(1));
  CHECK(Exact(totals, Category::kBalcony) == -100);  // no requirement beside the two per floor
  CHECK(Exact(totals, Category::kBalcony, 2) == 1);
  CHECK(totals.unparsed.empty());
  // The main bathroom besides a WC and an en-suite.
  const Brief bath = ParseBrief("Two storeys. On the ground floor: kitchen, lounge and a loo. First floor: master bedroom with "
                                "en-suite, a guest bedroom, the main bathroom.");
  INFO(BriefToJson(bath).dump(1));
  CHECK(Exact(bath, Category::kBathroom, 1) == 2);
  // "living" as a verb; a misspelt piece; a bathroom's shower; "shower" in a list is a room.
  CHECK(Exact(ParseBrief("Four bedrooms and a living room. Nobody is living out of a suitcase."), Category::kLivingRoom) == 1);
  const Brief typo = ParseBrief("2 storeys, 3 bdrm, kit, lvg rm. kit needs dishwaser.");
  INFO(BriefToJson(typo).dump(1));
  CHECK(typo.unparsed.empty());
  CHECK(Exact(typo, Category::kKitchen) == 1);
  const Brief shower = ParseBrief("Two floors, two bathrooms. The downstairs bathroom gets a shower instead. On second thought, a kitchen.");
  INFO(BriefToJson(shower).dump(1));
  CHECK(shower.unparsed.empty());
  CHECK(Exact(shower, Category::kBathroom) == 2);
  CHECK(Exact(ParseBrief("A bungalow: bedroom, kitchen, shower."), Category::kBathroom) == 1);
}

TEST_CASE("the seventh unseen set: the requester's bedroom, list totals after a dash, rooms said again, floors taken back", "[issue32]") {
  // "our bedroom, a guest bedroom", "her bedroom, a spare bedroom": two.
  CHECK(Exact(ParseBrief("Two floors. Downstairs: kitchen, living room. Upstairs: our bedroom, a guest bedroom, one bathroom."),
              Category::kBedroom, 1) == 2);
  CHECK(Exact(ParseBrief("A bungalow: a sitting room, a kitchen, her bedroom, a spare bedroom and a shower room."), Category::kBedroom) == 2);
  // After bedrooms counted, "our bedroom" is one of them.
  CHECK(Exact(ParseBrief("Three bedrooms and a kitchen. Our bedroom should be quiet."), Category::kBedroom) == 3);
  // "ea", a count after a dash that is the list's, "each of the 3", "per bathroom" after a piece.
  const Brief notes = ParseBrief("3 levels, 12 rooms. Level 0 (ground): kitchen, living room, dining room, bathroom - 4. Level 1: 3 "
                                 "bedrooms + 1 bathroom - 4. Level 2: office, meeting room, bathroom, balcony - 4. Each of the 3 "
                                 "bedrooms: 1 bed. 1 mirror per bathroom. Mirror in ea bath.");
  INFO(BriefToJson(notes).dump(1));
  CHECK(Exact(notes, Category::kBathroom, 0) == 1);
  CHECK(Exact(notes, Category::kBalcony, 2) == 1);
  CHECK(Exact(notes, Category::kBathroom) == -100);
  CHECK(notes.unparsed.empty());
  // "the family bathroom" of the list, named again; "The en-suite" of the master bedroom, not every bedroom's.
  const Brief family = ParseBrief("Ground floor: lounge, kitchen, a downstairs loo. First floor: master bedroom with en-suite, two "
                                  "further bedrooms and a family bathroom. Fitted wardrobe in every bedroom. The en-suite only needs a "
                                  "shower, but the family bathroom must have a proper bath.");
  INFO(BriefToJson(family).dump(1));
  CHECK(Exact(family, Category::kBathroom, 1) == 2);
  CHECK(Exact(family, Category::kBathroom) == -100);
  CHECK(family.connections.size() == 1);
  CHECK(family.unparsed.empty());
  // "the heart of it" is no footprint; "so two beds" after bunk beds are pieces; "master suite - bedroom".
  CHECK_FALSE(ParseBrief("A living room, a kitchen. The living room is the heart of it.").unsupported_shape.has_value());
  CHECK(ParseBrief("A heart-shaped house with a kitchen.").unsupported_shape.has_value());
  CHECK(Exact(ParseBrief("Two bedrooms and a kids' room. Bunk beds in the kids' room, so two beds."), Category::kBedroom) == 2);
  CHECK(Exact(ParseBrief("Second floor: master suite - bedroom plus its own bathroom - and a home office."), Category::kBedroom, 1) == 1);
  // Second thoughts: a floor count, a balcony each taken back, a plural said before its numbers.
  CHECK(ParseBrief("Three floors - actually two is plenty. Ground floor: kitchen. Upstairs: 3 bedrooms.").floors == 2);
  const Brief balcony = ParseBrief("Two floors. Upstairs: two bedrooms, each with a balcony - hmm, actually just one shared balcony.");
  INFO(BriefToJson(balcony).dump(1));
  CHECK(Exact(balcony, Category::kBalcony, 1) == 1);
  CHECK(Exact(ParseBrief("A house with bedrooms for the two founders. 3 floors. Ground floor: kitchen. Top floor: 2 bedrooms."),
              Category::kBedroom) == -100);
  // Office space rented elsewhere is no room of the house.
  CHECK(Exact(ParseBrief("We're tired of renting office space, so we want a home with an office, a kitchen and a bedroom."),
              Category::kOffice) == 1);
}

}  // namespace villa
