// The brief parser: the paper's example request, synonyms, numbers, floors, connections, furniture, and
// what it reports as not understood.
#include <algorithm>

#include <catch2/catch.hpp>

#include "generator/text/brief.h"

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

std::string Unparsed(const Brief& brief) {
  std::string out;
  for (const auto& u : brief.unparsed) out += (out.empty() ? "" : "|") + u.text;
  return out;
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
}  // namespace villa
