#pragma once
// The procedural spatial partitioner (paper, appendix "Dataset Construction Details"): from one seed, a
// valid multi-story layout (FORMAT.md rules 1-10): footprint -> upper floors -> staircase -> BSP rooms ->
// labels -> doors, opens, walls, windows, entrance. Every layout it returns has passed ValidateLayout.
//
// Two callers: `villa synth` (datasets: no requirements, everything sampled from priors) and the
// generator's procedural backend (a parsed text brief: floors, footprint class, rooms, connections).
// A requirement that cannot be met is reported in the Summary (an outcome, not a crash).
//
// Units are metres. All coordinates of a returned layout are multiples of `grid` (exact integers in grid
// units inside the partitioner: no rounding, so rooms tile with no sliver gaps).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "layout/footprint.h"
#include "layout/layout.h"

namespace villa {

inline constexpr int kAnyLevel = -1;  // a requirement for the whole building, not one floor

// "n rooms of this category" on one floor, or in the whole building (level = kAnyLevel; the partitioner
// then chooses the floors by its priors: living rooms and kitchens low, bedrooms and balconies high).
struct RoomRequirement {
  Category category = Category::kBedroom;
  int count = 1;
  int level = kAnyLevel;
};

// A direct link between a room of category `a` and one of category `b` (on `level`, or on any floor).
enum class LinkKind {
  kAny,   // a door or an open
  kDoor,  // a door (e.g. an en-suite bathroom, a bedroom reaching a balcony)
  kOpen,  // an open connection (e.g. a kitchen open to the dining room)
};
struct ConnectionRequirement {
  Category a = Category::kKitchen;
  Category b = Category::kDiningRoom;
  LinkKind kind = LinkKind::kAny;
  int level = kAnyLevel;

  // The connections a text brief names:
  static ConnectionRequirement KitchenOpenToDining(int level = kAnyLevel) {
    return {Category::kKitchen, Category::kDiningRoom, LinkKind::kOpen, level};
  }
  static ConnectionRequirement LivingToKitchen(int level = kAnyLevel) {
    return {Category::kLivingRoom, Category::kKitchen, LinkKind::kAny, level};
  }
  // A bedroom (or children's room) with its own bathroom behind a door.
  static ConnectionRequirement EnSuite(Category bedroom = Category::kBedroom, int level = kAnyLevel) {
    return {bedroom, Category::kBathroom, LinkKind::kDoor, level};
  }
  // A bedroom or children's room opening onto a balcony through a door.
  static ConnectionRequirement BalconyFrom(Category room = Category::kBedroom, int level = kAnyLevel) {
    return {room, Category::kBalcony, LinkKind::kDoor, level};
  }
};

struct PartitionOptions {
  // Grid of every coordinate, m. 4 m / grid must be a whole number (the staircase room), the grid a
  // multiple of 0.01 m (two decimals in the text), at most 1 m (door widths 0.8-1.2 m on the grid).
  double grid = 0.5;

  // Floors, 1..3. 0: sampled from the seed with `floor_weights` (single : two : three stories).
  int floors = 0;
  double floor_weights[3] = {2.0, 4.0, 4.0};

  // Footprint class; unset: sampled from the seed with `shape_weights` (in ShapeClass order).
  std::optional<ShapeClass> shape;
  // The default mix: about half the footprints have a slanted outside edge (irregular, hexagon, octagon,
  // trapezoid, bay, angled wing; a fifth of the others get 45-degree corners too).
  double shape_weights[kShapeClassCount] = {0.07, 0.10, 0.07, 0.07, 0.05, 0.14, 0.08, 0.10, 0.06, 0.06, 0.10, 0.10};

  // Limits of the ground floor's bounding rectangle, m. Within them the size follows the ground floor's
  // room count (about 20-32 m2 a room, aspect 1-1.6; U, T and H footprints at least 13 m a side).
  double min_side = 9.0;
  double max_side = 24.0;

  // Rooms a floor (the staircase room included), 3..6 (FORMAT.md rule 6 caps at 6). Sampled per floor
  // with an average of about 5 unless `rooms` fixes the count (see `only_required_rooms`).
  int min_rooms_per_floor = 3;
  int max_rooms_per_floor = 6;

  // Required rooms. A multi-story building always has its staircase utility room on every floor; a
  // requirement for utility rooms counts those. The floor's other rooms are chosen by the priors, unless
  // `only_required_rooms`: then the building has exactly the required rooms (plus staircase rooms).
  std::vector<RoomRequirement> rooms;
  bool only_required_rooms = false;

  // Required direct links (kitchen open to dining, living to kitchen, en-suite, balcony from a bedroom).
  std::vector<ConnectionRequirement> connections;

  // At least one panoramic window. Balconies always have one (rule 9); without a balcony the living room
  // (the lowest one with a long enough exterior wall), else the top floor's largest room with one, gets it.
  bool panoramic_windows = false;
  // Every room of these categories gets a panoramic window on its longest exterior wall.
  std::vector<Category> panoramic_rooms;

  // Attempts (each from its own sub-seed) before giving up; the Summary counts the retries.
  int max_attempts = 400;
  // Run ValidateLayout on the result (always on for datasets; a caller that validates itself may skip).
  bool validate = true;

  // False with a message naming the field and the bad value (e.g. "grid 0.3: 4 m is not a multiple").
  bool IsValid(std::string* message) const;
};

enum class PartitionOutcome {
  kSuccess,         // a valid layout meeting every requirement
  kUnmetRequirements,  // a valid layout; some requirements could not be met (listed in unmet_requirements)
  kFailure,         // no valid layout within max_attempts (or invalid options); layout is empty
};
std::string_view PartitionOutcomeName(PartitionOutcome outcome);

struct PartitionSummary {
  PartitionOutcome outcome = PartitionOutcome::kFailure;
  Layout layout;                 // valid unless outcome == kFailure
  ShapeClass shape = ShapeClass::kRectangle;
  int floors = 0;
  int retries = 0;               // attempts that were discarded before this layout (0 = first try)
  bool angled_edges = false;     // the ground footprint has an edge that is neither horizontal nor vertical
  // One line per requirement that is not met, for a person: "2 bathroom on level 1: made 1", with why
  // when no layout of the plan could meet it: "8 bedroom on level 0: made 6 (room for 6 on that floor)".
  std::vector<std::string> unmet_requirements;
  // Why attempts failed, most frequent first ("validation: rule 2: 3", "no place for the staircase: 1").
  std::vector<std::string> retry_reasons;
  std::string message;           // kFailure: why

  bool ok() const { return outcome != PartitionOutcome::kFailure; }
  // One line: "success: L, 2 floors, 9 rooms, 1 retry".
  std::string BriefReport() const;
};

// The layout of one seed. Deterministic: the same options and seed give the same layout on every
// platform (own PRNG helpers, no std::*_distribution, integer geometry).
PartitionSummary GenerateLayout(const PartitionOptions& options, uint64_t seed);

// The seed of layout `index` of a dataset made with `dataset_seed` (a mix of both only: threads and
// shards do not change it).
uint64_t DatasetLayoutSeed(uint64_t dataset_seed, uint64_t index);

// Floors of each of `count` layouts for a single : two : three story ratio: exact counts (largest
// remainder of count * weight / total), interleaved by index (a fixed sequence: layout i's floors depend
// only on i, count and the weights).
std::vector<int> DatasetFloorPlan(uint64_t count, const double weights[3]);

}  // namespace villa
