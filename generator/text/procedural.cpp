// The procedural backend: the brief steers the partitioner; candidates from successive seeds and
// variants (floor counts the brief allows, with or without rooms beyond the listed ones) are checked
// against the whole brief, and the best valid one is kept.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <set>

#include "generator/text/backends.h"
#include "layout/geometry.h"
#include "layout/validate.h"
#include "util/hash.h"
#ifdef VILLA_HAVE_SCENE_REQUEST
#include "scene/request.h"
#endif

namespace villa {
namespace {

// Staircase rooms (utility rooms of a building with several floors) with a door, an open or the entrance
// on each of the four sides of their box: the builder's stair serves at most three (flights in the middle
// with a passage on both sides; the far side holds the landing), so one of those doors opens onto the
// flights and the room behind it is closed (docs/BUILDING.md "Staircases"). The search prefers layouts
// without them.
int UnservableStairRooms(const Layout& layout) {
  if (layout.LevelCount() < 2) return 0;
  constexpr double kOnSide = 0.05;  // m
  int unservable = 0;
  for (const Room& room : layout.rooms) {
    if (room.category != Category::kUtilityRoom || room.polygon.empty()) continue;
    double x0 = room.polygon[0].x, x1 = x0, y0 = room.polygon[0].y, y1 = y0;
    for (const Point& p : room.polygon) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    bool side[4] = {false, false, false, false};
    for (const auto* list : {&layout.entrances, &layout.doors, &layout.opens})
      for (const Element& e : *list) {
        if (!e.OnLevel(room.level)) continue;
        const Point mid{(e.shape.a.x + e.shape.b.x) / 2.0, (e.shape.a.y + e.shape.b.y) / 2.0};
        if (DistanceToBoundary(mid, room.polygon) > kOnSide) continue;
        if (std::abs(mid.x - x0) < kOnSide) side[0] = true;
        else if (std::abs(mid.x - x1) < kOnSide) side[1] = true;
        else if (std::abs(mid.y - y0) < kOnSide) side[2] = true;
        else if (std::abs(mid.y - y1) < kOnSide) side[3] = true;
      }
    unservable += side[0] && side[1] && side[2] && side[3];
  }
  return unservable;
}

// Floor counts to try, best guess first.
std::vector<int> FloorCandidates(const Brief& brief) {
  if (brief.floors) return {std::clamp(*brief.floors, 1, kMaxFloors)};
  int lo = std::max(1, brief.floors_min.value_or(1));
  int total_min = 0;
  int highest = -1;
  for (const auto& r : brief.rooms) {
    if (r.level >= 0) highest = std::max(highest, r.level);
    if (r.category == Category::kUtilityRoom && r.level == kAnyLevel && r.min == r.max && r.min >= 2)
      return {std::min(r.min, kMaxFloors)};
    if (r.category == Category::kUtilityRoom) continue;
    total_min += r.level == kEachLevel ? r.min : r.min;
  }
  for (const auto& c : brief.connections) highest = std::max(highest, c.level);
  for (const auto& p : brief.panoramic) highest = std::max(highest, p.level);
  lo = std::max(lo, highest + 1);
  // About 4.5 rooms a floor besides the staircase room.
  int guess = std::max(lo, static_cast<int>(std::ceil(total_min / 4.5)));
  lo = std::min(lo, kMaxFloors);
  guess = std::clamp(guess, lo, kMaxFloors);
  std::vector<int> out{guess};
  for (int f = lo; f <= kMaxFloors; ++f)
    if (f != guess) out.push_back(f);
  return out;
}

// A small deterministic generator for the placement shuffles (no std::*_distribution): each number is
// the SplitMix64 hash of the one before.
struct Rng {
  std::uint64_t state;
  std::uint64_t Next() { return state = SplitMix64Hash(state); }
  int Below(int n) { return n <= 1 ? 0 : static_cast<int>(Next() % static_cast<std::uint64_t>(n)); }
};

// Where a room of this category goes when the brief does not say: living spaces low, sleeping rooms and
// balconies high, the rest where there is space.
enum class Preference { kLow, kHigh, kEmptiest };
Preference PreferenceOf(Category c) {
  switch (c) {
    case Category::kLivingRoom:
    case Category::kKitchen:
    case Category::kDiningRoom:
    case Category::kMeetingRoom: return Preference::kLow;
    case Category::kBedroom:
    case Category::kChildrenRoom:
    case Category::kBalcony: return Preference::kHigh;
    default: return Preference::kEmptiest;
  }
}

}  // namespace

// Turns whole-building counts into per-floor ones (a floor-plan of our own choosing, shuffled by `seed`),
// so that with only_required_rooms the building holds exactly the rooms asked for and no floor is left
// for the priors to fill.
void DistributeRooms(PartitionOptions& o, std::uint64_t seed) {
  const int floors = std::max(o.floors, 1);
  const int cap = o.max_rooms_per_floor - (floors > 1 ? 1 : 0);
  std::vector<int> load(static_cast<std::size_t>(floors), 0);
  std::vector<RoomRequirement> fixed, loose;
  for (const auto& r : o.rooms) {
    if (r.level >= 0) {
      fixed.push_back(r);
      if (!(floors > 1 && r.category == Category::kUtilityRoom)) load[static_cast<std::size_t>(r.level)] += r.count;
    } else if (r.count > 0 && !(floors > 1 && r.category == Category::kUtilityRoom)) {
      loose.push_back(r);
    } else {
      fixed.push_back(r);  // "no balcony", staircase rooms: the partitioner's business
    }
  }
  if (loose.empty()) return;
  Rng rng{seed};
  std::map<std::pair<int, int>, int> placed;  // (category, level) -> count
  for (const auto& r : loose) {
    for (int k = 0; k < r.count; ++k) {
      std::vector<int> order;
      for (int l = 0; l < floors; ++l) order.push_back(l);
      const Preference pref = PreferenceOf(r.category);
      if (pref == Preference::kHigh && floors > 1) {
        std::rotate(order.begin(), order.begin() + 1, order.end());  // 1, 2, ..., 0
        if (floors == 3 && rng.Below(2)) std::swap(order[0], order[1]);
      } else if (pref == Preference::kEmptiest) {
        for (int i = floors - 1; i > 0; --i) std::swap(order[static_cast<std::size_t>(i)], order[static_cast<std::size_t>(rng.Below(i + 1))]);
        std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return load[static_cast<std::size_t>(a)] < load[static_cast<std::size_t>(b)]; });
      }
      int level = -1;
      for (int l : order)
        if (load[static_cast<std::size_t>(l)] < cap && !(r.category == Category::kBalcony && floors > 1 && l == 0)) {
          level = l;
          break;
        }
      if (level < 0) level = order.front();  // over capacity: the partitioner reports it
      ++load[static_cast<std::size_t>(level)];
      ++placed[{static_cast<int>(r.category), level}];
    }
  }
  // A floor with a single room beside its staircase looks odd and tempts the priors: move one over from
  // the fullest floor when its category may live there.
  for (int l = 0; l < floors; ++l) {
    while (load[static_cast<std::size_t>(l)] < 2) {
      int from = static_cast<int>(std::max_element(load.begin(), load.end()) - load.begin());
      if (load[static_cast<std::size_t>(from)] <= 2) break;
      bool moved = false;
      for (auto& [key, n] : placed) {
        if (key.second != from || n == 0) continue;
        Category c = static_cast<Category>(key.first);
        if (c == Category::kBalcony && l == 0 && floors > 1) continue;
        if (c == Category::kLivingRoom || c == Category::kKitchen) continue;
        --n;
        ++placed[{key.first, l}];
        --load[static_cast<std::size_t>(from)];
        ++load[static_cast<std::size_t>(l)];
        moved = true;
        break;
      }
      if (!moved) break;
    }
  }
  o.rooms = fixed;
  for (const auto& [key, n] : placed)
    if (n > 0) {
      bool merged = false;
      for (auto& r : o.rooms)
        if (static_cast<int>(r.category) == key.first && r.level == key.second) {
          r.count += n;
          merged = true;
        }
      if (!merged) o.rooms.push_back({static_cast<Category>(key.first), n, key.second});
    }
}

PartitionOptions PartitionOptionsForBrief(const Brief& brief, int floors, bool only_required) {
  PartitionOptions o;
  o.floors = floors;
  o.shape = brief.shape;
  o.only_required_rooms = only_required;
  // Per-floor counts first; a total then asks only for the rooms not already placed on a floor.
  std::map<int, int> placed;  // category -> rooms on named floors
  auto add = [&](Category c, int count, int level) {
    if (count <= 0 && level == kAnyLevel) return;
    if (level >= floors) return;
    o.rooms.push_back({c, std::max(count, 0), level});
  };
  // Rooms asked on named upper floors count toward an "upstairs" requirement of their kind, as the check
  // counts them ("First: two bedrooms and a second bathroom ... only the upstairs one" is one bathroom).
  std::map<int, int> named_upper;  // category -> rooms asked on named upper floors
  for (const auto& r : brief.rooms)
    if (r.level >= 1 && r.level < floors) named_upper[static_cast<int>(r.category)] += r.min;
    else if (r.level == kEachLevel) named_upper[static_cast<int>(r.category)] += r.min * (floors - 1);
  for (const auto& r : brief.rooms) {
    int count = r.min;  // a range asks for its minimum; the check accepts more
    if (r.level == kUpperLevels) count = std::max(0, count - named_upper[static_cast<int>(r.category)]);
    if (r.level >= 0) {
      add(r.category, count, r.level);
      placed[static_cast<int>(r.category)] += count;
    } else if (r.level == kEachLevel) {
      for (int l = 0; l < floors; ++l) add(r.category, count, l);
      placed[static_cast<int>(r.category)] += count * floors;
    } else if (r.level == kUpperLevels && floors >= 2) {
      // "upstairs" in a three-floor building: the rooms alternate over the upper floors, level 1 first.
      std::vector<int> per_level(static_cast<std::size_t>(floors), 0);
      for (int k = 0; k < count; ++k) ++per_level[static_cast<std::size_t>(1 + k % (floors - 1))];
      for (int l = 1; l < floors; ++l)
        if (per_level[static_cast<std::size_t>(l)] > 0) add(r.category, per_level[static_cast<std::size_t>(l)], l);
      placed[static_cast<int>(r.category)] += count;
    }
  }
  // Rooms a connection or a panoramic window places on a floor ("the second-floor bedroom reaches a
  // balcony") must be there even when the brief counts them only for the whole building.
  std::map<std::pair<int, int>, int> on_level;  // (category, level) -> rooms asked there
  for (const auto& r : o.rooms)
    if (r.level >= 0) on_level[{static_cast<int>(r.category), r.level}] += r.count;
  auto hint = [&](Category c, int level) {
    if (level < 0 || level >= floors || c == Category::kRoom) return;
    if (c == Category::kUtilityRoom && floors > 1) return;
    int& n = on_level[{static_cast<int>(c), level}];
    if (n > 0) return;
    // Only when the whole-building count leaves room for it.
    for (const auto& r : brief.rooms)
      if (r.category == c && r.level == kAnyLevel && r.max >= 0 && placed[static_cast<int>(c)] >= r.max) return;
    n = 1;
    add(c, 1, level);
    placed[static_cast<int>(c)] += 1;
  };
  for (const auto& c : brief.connections) {
    if (c.to.size() != 1) continue;
    hint(c.from, c.level);
    hint(c.to.front(), c.level);
  }
  for (const auto& p : brief.panoramic) hint(p.category, p.level);
  for (const auto& s : brief.sides) hint(s.category, s.level);
  for (const auto& r : brief.rooms) {
    if (r.level != kAnyLevel) continue;
    int rest = r.min - placed[static_cast<int>(r.category)];
    if (r.category == Category::kUtilityRoom) {
      // The partitioner counts staircase rooms in a utility requirement; a multi-story building has one
      // a floor whatever the brief says.
      if (floors > 1) continue;
      rest = r.min;
    }
    if (rest > 0 && floors > 1) {
      // "two rooms for the kids upstairs ... a room for the grandchildren too": the rest go on a floor whose
      // count of the kind the brief does not fix, the least asked of first.
      std::set<int> fixed;
      for (const auto& q : brief.rooms)
        if (q.category == r.category && q.level >= 0 && q.min == q.max) fixed.insert(q.level);
      if (!fixed.empty()) {
        int pick = -1, least = 1 << 20;
        for (int l = 0; l < floors; ++l) {
          if (fixed.count(l) || (l == 0 && r.category == Category::kBalcony)) continue;
          int asked = 0;
          for (const auto& q : o.rooms)
            if (q.level == l) asked += q.count;
          if (asked < least) pick = l, least = asked;
        }
        if (pick >= 0) {
          add(r.category, rest, pick);
          continue;
        }
      }
    }
    if (rest > 0 || (r.max == 0 && placed[static_cast<int>(r.category)] == 0)) add(r.category, rest, kAnyLevel);
  }
  for (const auto& c : brief.connections) {
    if (c.to.empty()) continue;
    std::vector<int> levels;
    if (c.level == kEachLevel)
      for (int l = 0; l < floors; ++l) levels.push_back(l);
    else if (c.level >= 0 && c.level < floors)
      levels.push_back(c.level);
    else if (c.level == kUpperLevels && floors == 2)
      levels.push_back(1);
    else
      levels.push_back(kAnyLevel);
    for (int l : levels) o.connections.push_back({c.from, c.to.front(), c.kind, l});
  }
  for (const auto& p : brief.panoramic) {
    if (p.category == Category::kRoom) {
      o.panoramic_windows = true;
    } else if (std::find(o.panoramic_rooms.begin(), o.panoramic_rooms.end(), p.category) == o.panoramic_rooms.end()) {
      o.panoramic_rooms.push_back(p.category);
    }
  }
  // Many rooms a floor need the larger end of the size range.
  int most = 0;
  std::map<int, int> per_level;
  for (const auto& r : o.rooms)
    if (r.level >= 0) most = std::max(most, per_level[r.level] += r.count);
  if (most >= 5) o.min_side = 14.0;
  o.max_attempts = 120;
  return o;
}

// The people the request seats at a table of a room kind ("a dining table for six", "Dining table with 4
// chairs", "a meeting room that seats ten"), read by the furnishing's own request reader; 0 when it says
// nothing.
int SeatsAsked(const Brief& brief, Category room) {
#ifdef VILLA_HAVE_SCENE_REQUEST
  const scene::RoomRequest request = scene::ParseRoomRequest(brief.text, room);
  int seats = 0;
  for (const scene::Wish& w : request.wishes) {
    if (w.category->name == "dining-table" || w.category->name == "conference-table") seats = std::max(seats, w.seats);
    if (w.category->name == "chair") seats = std::max(seats, w.count);
  }
  return seats;
#else
  (void)brief;
  (void)room;
  return 0;
#endif
}

// Rooms of `room`'s kind in `layout` too small for a table seating `seats` with 0.75 m behind every chair
// (the furnishing's rule, issue 27): a table 0.9 m deep and 0.6 m a place along, chairs on both long
// sides (0.05 m gap, 0.5 m chair, 0.75 m clear each), 0.2 m of wall; ends left free.
// A kitchen's table stands clear of a run of counters along one wall (0.6 m deep, 0.4 m more to work at
// them).
int RoomsTooSmallToSeat(const Layout& layout, Category room, int seats) {
  if (seats < 3) return 0;
  const double counters = room == Category::kKitchen ? 1.0 : 0.0;
  const double length = 0.6 * std::ceil(seats / 2.0), need_across = 0.9 + 2.0 * 1.3 + 0.2 + counters, need_along = length + 0.6;
  int short_of = 0;
  for (const Room& r : layout.rooms) {
    if (r.category != room || r.polygon.empty()) continue;
    const Box2 b = BoundingBox(r.polygon);
    const double w = b.max_x - b.min_x, h = b.max_y - b.min_y;
    // The table's long side along the room's (as the furnishing lays it out: scene/planner.cpp SeatCap).
    const bool fits = std::min(w, h) >= need_across && std::max(w, h) >= need_along;
    short_of += !fits;
  }
  return short_of;
}

void PlanProcedural(const Brief& brief, const PlanOptions& options, PlanSummary& summary) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const auto deadline = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options.time_budget_s));
  const std::vector<int> floors = FloorCandidates(brief);
  // Briefs that list their rooms one by one are met more often with exactly those rooms.
  int exact_categories = 0;
  for (const auto& r : brief.rooms)
    if (r.min == r.max && r.category != Category::kUtilityRoom) ++exact_categories;
  // ... and so are briefs that say what every floor holds ("The top floor has a bedroom and a WC").
  std::set<int> listed_levels;
  for (const auto& r : brief.rooms)
    if (r.level >= 0) listed_levels.insert(r.level);
  const int stated_floors = brief.floors.value_or(brief.floors_min.value_or(0));
  bool every_floor_listed = stated_floors > 0;
  for (int l = 0; l < stated_floors; ++l) every_floor_listed &= listed_levels.count(l) > 0;
  const bool prefer_only_required = exact_categories >= 4 || every_floor_listed;

  // Tables the request sizes for its people want rooms that can seat them.
  // ("Kitchen table for four": a kitchen where the brief asks for no dining room.)
  const bool dining_room = std::any_of(brief.rooms.begin(), brief.rooms.end(), [](const BriefRooms& r) {
    return r.category == Category::kDiningRoom && r.min > 0;
  });
  const int dining_seats = SeatsAsked(brief, Category::kDiningRoom), meeting_seats = SeatsAsked(brief, Category::kMeetingRoom),
            kitchen_seats = dining_room ? 0 : SeatsAsked(brief, Category::kKitchen);
  auto unseated = [&](const Layout& layout) {
    return RoomsTooSmallToSeat(layout, Category::kDiningRoom, dining_seats) + RoomsTooSmallToSeat(layout, Category::kMeetingRoom, meeting_seats) +
           RoomsTooSmallToSeat(layout, Category::kKitchen, kitchen_seats);
  };
  int best_met = -1;
  int best_unseated = 0;
  int best_extras = 0;
  int best_stairs = 0;  // UnservableStairRooms of the best layout
  std::optional<Layout> best;
  std::optional<ShapeClass> best_shape;
  std::string last_failure;
  int attempts = 0;
  int valid_candidates = 0;
  int since_goal = -1;  // attempts since the first candidate meeting the whole brief
  // A brief that cannot be met (more rooms than six a floor, a store room in a building with stairs) would
  // search to the time budget: short of the goal, the search stops once a round of every variant (each
  // floor count, only the required rooms or not, counts placed here or by the partitioner) and one more
  // have gone by without a better candidate. On the voices corpus the best was found by the 7th attempt at
  // the latest. (A brief met looks for a tidier layout a while longer, above.)
  int last_improve = -1;
  const int stall = 4 * static_cast<int>(floors.size()) + 4;
  const int goal = brief.RequirementCount();
  // Rooms the priors added on floors whose contents the brief lists: met, but untidy.
  std::map<int, int> listed_per_level;
  for (const auto& r : brief.rooms)
    if (r.level >= 0 && r.category != Category::kUtilityRoom) listed_per_level[r.level] += r.min;
  auto extras_of = [&](const Layout& layout) {
    if (!every_floor_listed) return 0;
    int extras = 0;
    for (const auto& [level, n] : listed_per_level) {
      int rooms = 0;
      for (int i : layout.RoomsOnLevel(level)) rooms += layout.rooms[static_cast<std::size_t>(i)].category != Category::kUtilityRoom;
      extras += std::max(0, rooms - n);
    }
    return extras;
  };
  for (int a = 0; a < options.max_attempts; ++a) {
    if (a > 0 && Clock::now() >= deadline) break;
    if (since_goal >= 0 && ++since_goal > 12) break;  // a tidier layout is not worth a long search (issue 32: under 50 ms)
    if (best && best_met < goal && a - last_improve > stall) break;
    const int f = floors[static_cast<std::size_t>(a) % floors.size()];
    const bool only_required = ((a / static_cast<int>(floors.size())) % 2 == 0) == prefer_only_required;
    PartitionOptions po = PartitionOptionsForBrief(brief, f, only_required);
    // Every other round of variants places the whole-building counts ourselves.
    if ((a / (2 * static_cast<int>(floors.size()))) % 2 == 0) DistributeRooms(po, SplitMix64Hash(options.seed ^ (0xD15Full + a)));
    const std::uint64_t seed = SplitMix64Hash(options.seed * kFnv1a64Prime + static_cast<std::uint64_t>(a));
    PartitionSummary ps = GenerateLayout(po, seed);
    ++attempts;
    if (!ps.ok()) {
      last_failure = ps.message;
      continue;
    }
    ++valid_candidates;
    BriefCheck check = CheckBrief(brief, ps.layout);
    const int met = check.met();
    const int extras = extras_of(ps.layout);
    const int stairs = UnservableStairRooms(ps.layout);
    const int short_of = unseated(ps.layout);
    if (met > best_met ||
        (met == best_met && (stairs < best_stairs ||
                             (stairs == best_stairs && (short_of < best_unseated || (short_of == best_unseated && extras < best_extras)))))) {
      best_met = met;
      best_unseated = short_of;
      best_extras = extras;
      best_stairs = stairs;
      last_improve = a;
      best = std::move(ps.layout);
      best_shape = ps.shape;
    }
    if (best_met == goal && since_goal < 0) since_goal = 0;
    if (best_met == goal && best_extras == 0 && best_stairs == 0 && best_unseated == 0) break;
  }
  PlanRound round;
  round.round = 0;
  round.parsed = best.has_value();
  round.valid = best.has_value();
  round.requirements_met = std::max(best_met, 0);
  round.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  summary.rounds.push_back(round);
  summary.attempts = attempts;
  if (best) {
    summary.layout = std::move(best);
    summary.shape_class = std::string(ShapeClassName(*best_shape));
  } else {
    summary.error = "the partitioner made no valid layout in " + std::to_string(attempts) + " attempts" +
                    (last_failure.empty() ? "" : ": " + last_failure);
  }
}

}  // namespace villa
