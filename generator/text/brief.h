#pragma once
// The brief: what a free-text request asks of a villa, as requirements a layout can be checked against.
//
//   Brief brief = ParseBrief("I want to build a three-story, irregularly shaped villa ...");
//   BriefCheck check = CheckBrief(brief, layout);   // which requirements the layout meets
//
// Parsing is a hand-written tokeniser and phrase patterns (no regular expressions). It understands:
//   floors        "three-story", "3-storey", "2 floors", "two levels", "single-storey", "bungalow"
//   footprint     rectangular / square, L-, U-, T-, H-shaped, hexagonal / six-sided, octagonal, trapezoidal,
//                 star- / cross-shaped, bay window / bay-fronted, angled wing, irregular / slanted / angled;
//                 shapes the partitioner cannot make (round, pentagonal, triangular, ...) are kept as
//                 unsupported_shape
//   rooms         category and count, per floor when the text says so; synonyms (master bedroom, kids'
//                 room, study, lounge, WC, open-plan kitchen, terrace, staircase room, ...); numbers in
//                 words and digits; "no balcony" / "without an office" as a count of zero
//   connections   kitchen open to the dining room, living room reaching the kitchen, en-suite bathroom,
//                 bedroom / children's room reaching a balcony, "the entrance opens into the living room"
//   windows       panoramic (floor-to-ceiling) windows in a room or on a floor
//   furniture     "a TV in the meeting room", "place a double bed in the children's room", "bookshelves
//                 full of books": kept for the furnishing stage, not checked against a layout (object words:
//                 its own list, and assets/category.h's vocabulary when villa_assets is built)
// Words it cannot attach to any of these are returned in `unparsed` with their place in the text; they
// are never dropped silently.
//
// Floor naming convention (docs/GENERATOR.md): levels count from 0 = ground floor.
//   "ground floor", "downstairs", "main floor", "lower floor"  -> level 0
//   ordinals are American, as in the paper's example request ("the kitchen on the first floor" is on the
//   ground floor, "the second-floor bedroom" on level 1) and in the annotator's drafts ("second floor" =
//   middle floor of three): "first floor" = level 0, "second floor" = 1, "third floor" = 2;
//   UNLESS the text names both a "ground floor" and a "first floor" as different places: then they are
//   British (first floor = level 1, second = level 2).
//   "level N" / "floor N": the N-th floor (1-based), or level N when the text also says "level 0".
//   "top floor", "uppermost floor"                            -> the highest level (floors - 1)
//   "upstairs", "upper floor(s)"                              -> level 1 in a two-floor building, the
//                                                                upper levels together (kUpperLevels)
//                                                                in a three-floor one
//   "middle floor"                                            -> level 1
//   "the upper two floors" (", three on each")                -> the highest two levels (three on each)
//   "on each floor", "on every level", "on both floors"       -> every level (kEachLevel)
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "layout/layout.h"
#include "partitioner/partitioner.h"

namespace villa {

// Where a requirement applies: a level (0 = ground floor), kAnyLevel (partitioner.h: anywhere in the
// building) or one of these.
inline constexpr int kUpperLevels = -2;  // on the levels above the ground floor, counted together
inline constexpr int kEachLevel = -3;    // on every level separately

// A place in the request text (byte offsets), so a report can quote it.
struct TextSpan {
  std::size_t begin = 0;
  std::size_t end = 0;  // one past the last byte
  std::string text;     // the request's bytes in [begin, end)
};

// Rooms of one category: between `min` and `max` of them (max < 0: no upper bound) on `level`.
struct BriefRooms {
  Category category = Category::kRoom;
  int level = kAnyLevel;
  int min = 1;
  int max = -1;
  TextSpan source;
};

// How two rooms must connect (partitioner.h LinkKind): kAny "directly access", "leads to", "reaches";
// kOpen "openly connected", "open to", "open-plan"; kDoor "en-suite", "its own bathroom", "reached through".
std::string_view LinkKindName(LinkKind kind);  // "any", "open", "door"

// A room of category `from` (on `level`) connects to a room of one of the categories `to` on the same
// level (doors and opens join rooms of one level). `every`: each room of `from` there must have such a
// link ("each bedroom has its own bathroom").
struct BriefConnection {
  Category from = Category::kRoom;
  std::vector<Category> to;
  int level = kAnyLevel;
  LinkKind kind = LinkKind::kAny;
  bool every = false;
  TextSpan source;
};

// A panoramic window in a room of `category` (kRoom: in any room) on `level`.
struct BriefPanoramic {
  Category category = Category::kRoom;
  int level = kAnyLevel;
  TextSpan source;
};

// The entrance leads into a room of `category`.
struct BriefEntrance {
  Category category = Category::kRoom;
  TextSpan source;
};

// A room of `category` on `level` lies in the outer third of its floor towards `side` ("north" = +y,
// "south" = -y, "east" = +x, "west" = -x), as the annotator's fine descriptions say it.
struct BriefSide {
  Category category = Category::kRoom;
  int level = kAnyLevel;
  std::string side;
  TextSpan source;
};

// A furniture request for the furnishing stage: `count` x `item` ("double bed") in a room of `category`
// (kRoom when the text names no room) on `level`.
struct BriefFurniture {
  std::string item;
  int count = 1;
  Category category = Category::kRoom;
  int level = kAnyLevel;
  TextSpan source;
};

struct Brief {
  std::string text;                          // the request as given
  std::optional<int> floors;                 // number of floors (1..), when the text says or implies it
  std::optional<TextSpan> floors_source;
  std::optional<int> floors_min;             // "multi-story", "upstairs": at least this many floors
  std::optional<ShapeClass> shape;           // footprint class asked for
  std::optional<TextSpan> shape_source;
  std::optional<TextSpan> unsupported_shape; // a footprint the partitioner cannot make ("star-shaped")
  std::vector<BriefRooms> rooms;
  std::vector<BriefConnection> connections;
  std::vector<BriefPanoramic> panoramic;
  std::vector<BriefEntrance> entrance;
  std::vector<BriefSide> sides;
  std::vector<BriefFurniture> furniture;
  std::vector<TextSpan> unparsed;            // words not understood, in text order
  std::vector<std::string> conflicts;        // requirements that contradict each other or the format
  bool british_ordinals = false;             // "first floor" read as level 1 (the text names a ground floor)

  // Number of checkable requirements (floors, shape, rooms, connections, panoramic, entrance, sides);
  // the denominator of brief adherence.
  int RequirementCount() const;
};

Brief ParseBrief(std::string_view text);

nlohmann::ordered_json BriefToJson(const Brief& brief);
// "3 floors, irregular footprint, 1 kitchen (level 0), ..., kitchen-open-dining-room (level 0)".
std::string BriefOneLine(const Brief& brief);

// One requirement checked against a layout.
struct RequirementResult {
  std::string requirement;  // "2 bathroom", "kitchen on level 0", "kitchen open to dining-room on level 0"
  bool met = false;
  std::string detail;       // what the layout has instead: "found 1 bathroom"
  std::string source;       // the words of the request it came from
};

struct BriefCheck {
  std::vector<RequirementResult> results;  // one per requirement, in Brief order
  int met() const;
  int total() const { return static_cast<int>(results.size()); }
  // Share of requirements met; 1 when the brief asks nothing checkable.
  double adherence() const;
  std::vector<RequirementResult> unmet() const;
};

BriefCheck CheckBrief(const Brief& brief, const Layout& layout);

nlohmann::ordered_json BriefCheckToJson(const BriefCheck& check);

}  // namespace villa
