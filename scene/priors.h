#pragma once
// The built-in room priors of shared/design/PRIORS.md as data: for each room type, what a furnished room of
// that type holds when the request is brief. Anchors stand on the floor, against a wall, on a wall or hang
// from the ceiling; small objects stand on or lie inside a parent (books inside a bookcase, a TV on its
// stand). Each item carries its count range, its semantic edges to other items (sofa face_to tv-stand),
// placement hints (bed far from the door) and the categories allowed in its interaction zone.
//
// Where we go beyond PRIORS.md (items added so usual rooms reach the paper's 22-30 objects, place settings
// exempt from the 3-per-receptacle rule, ceiling lamps by area) docs/SCENE.md says so and why.
#include <string_view>
#include <vector>

#include "layout/layout.h"
#include "scene/scene.h"

namespace villa::scene {

// How an item is held (the physical edge it gets).
enum class Mount {
  kFloor,    // free-standing: ontop the floor
  kWall,     // against_wall, on the floor
  kOnWall,   // hung on a wall
  kCeiling,  // hanging from the ceiling
  kParent,   // ontop or inside one of `parents`
};

struct ParentChoice {
  std::string_view category;
  Relation relation = Relation::kOnTop;  // kOnTop or kInside
};

// Which instance of the target category an edge of instance i points at.
enum class Pick {
  kFirst,      // the first one (the sofa)
  kSame,       // the i-th, or the last when there are fewer (upper cabinet i above counter i)
  kPrevious,   // instance i-1 of the item's own category (contiguous counters); none for i = 0
  kAlternate,  // the first, with left_of for even i and right_of for odd i (nightstands beside the bed)
  kLast,       // the last one (the cooker at the end of the run of counters)
};

struct EdgeRule {
  SemanticRelation relation = SemanticRelation::kNear;
  std::string_view target;  // category
  EdgeParams params;
  Pick pick = Pick::kFirst;
};

enum class Condition {
  kAlways,
  kNoDiningRoomOnLevel,  // the kitchen table: only when the floor has no dining room
};

struct ItemPrior {
  std::string_view category;             // assets/category.h vocabulary
  int min = 0;
  int max = 0;
  Mount mount = Mount::kFloor;
  std::vector<ParentChoice> parents;     // kParent: in order of preference
  std::vector<EdgeRule> edges;
  std::vector<std::string_view> hints;   // kHint* of scene.h
  std::vector<std::string_view> exempt;  // categories allowed in its interaction zone
  std::string_view requires_category;    // planned only beside an object of this category ("" = always)
  int per_parent = 3;                    // at most this many on / in one parent (ProcTHOR's 3)
  bool per_seat = false;                 // one per chair of the parent (place settings), ignoring per_parent
  std::string_view group;                // at most one item of a group is planned (bath or shower)
  Condition condition = Condition::kAlways;
  double min_area = 0.0;                 // m2 of furnishable floor the room needs for this item
  // Issue 27: planned at least once in a room with this much furnishable floor (m2; 0: only as drawn): the
  // further zones of big rooms (a reading corner, a bench at the bed's foot, an island).
  double from_area = 0.0;
  // The room's defining furniture (the bed of a bedroom, the toilet of a bathroom): its first `min` may
  // cover floor beyond the priors' share, up to the share a request may use (PlannerOptions).
  bool key = false;
};

struct RoomPriors {
  Category room = Category::kRoom;
  int no_target = 0;         // the paper's NO for this room type (PRIORS.md)
  double usual_area = 0.0;   // m2 of furnishable floor of a usual room of this type
  std::vector<ItemPrior> items;  // in planning order: anchors first, then what stands on them
};

// The priors of a room type; an empty RoomPriors (no items) for kRoom.
const RoomPriors& PriorsFor(Category category);
// Every labelled room type's priors, in LabelledCategories() order.
const std::vector<RoomPriors>& AllRoomPriors();

// The five room types the paper furnishes with 22-30 objects when of usual size (>= 12 m2).
bool IsRichRoomType(Category category);

// How many compartments (cavities) a usual asset of this storage category offers, for the at-most-3-of-a-
// type-per-receptacle rule applied per compartment (a bookcase of 5 shelves holds more than 3 rows of
// books). 1 for categories not listed.
int CompartmentsOf(std::string_view category);

}  // namespace villa::scene
