// GenerateLayout: footprint -> upper floors -> staircase -> BSP -> labels -> links -> windows -> Layout,
// validated, retried from a fresh sub-seed on failure. All geometry in whole grid units (steps.h).
#include "partitioner/partitioner.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>

#include "layout/footprint.h"
#include "layout/validate.h"
#include "partitioner/steps.h"

namespace villa {

using partition::Axis;
using partition::BspLimits;
using partition::IBox;
using partition::ILine;
using partition::IPoint;
using partition::IRing;
using partition::ISegment;
using partition::Rng;
using partition::Scale;

std::string_view PartitionOutcomeName(PartitionOutcome outcome) {
  switch (outcome) {
    case PartitionOutcome::kSuccess: return "success";
    case PartitionOutcome::kUnmetRequirements: return "unmet requirements";
    case PartitionOutcome::kFailure: return "failure";
  }
  return "failure";
}

std::string PartitionSummary::BriefReport() const {
  std::ostringstream out;
  out << PartitionOutcomeName(outcome);
  if (outcome == PartitionOutcome::kFailure) {
    out << ": " << message;
    return out.str();
  }
  out << ": " << ShapeClassName(shape) << ", " << floors << (floors == 1 ? " floor, " : " floors, ")
      << layout.rooms.size() << " rooms, " << retries << (retries == 1 ? " retry" : " retries");
  if (!unmet_requirements.empty()) out << ", " << unmet_requirements.size() << " unmet";
  return out.str();
}

namespace {

bool IsMultipleOf(double value, double step) {
  const double q = value / step;
  return std::abs(q - std::round(q)) < 1e-6;
}

}  // namespace

bool PartitionOptions::IsValid(std::string* message) const {
  auto fail = [&](std::string text) {
    if (message) *message = std::move(text);
    return false;
  };
  std::ostringstream g;
  g << grid;
  if (!(grid > 0.0) || grid > 1.0) return fail("grid " + g.str() + ": must be in (0, 1] m");
  if (!IsMultipleOf(grid, 0.01)) return fail("grid " + g.str() + ": must be a multiple of 0.01 m (two decimals)");
  if (!IsMultipleOf(kStairRoomSize, grid)) return fail("grid " + g.str() + ": 4 m (the staircase) is not a multiple of it");
  bool door_fits = false;
  for (int k = 1; k * grid <= 1.2 + 1e-9; ++k) door_fits |= k * grid >= 0.8 - 1e-9;
  if (!door_fits) return fail("grid " + g.str() + ": no door width of 0.8-1.2 m is a multiple of it");
  if (floors < 0 || floors > kMaxFloors) return fail("floors " + std::to_string(floors) + ": must be 0 (sampled) or 1-3");
  double wsum = 0.0;
  for (double w : floor_weights) {
    if (!(w >= 0.0)) return fail("floor_weights: weights must be >= 0");
    wsum += w;
  }
  if (floors == 0 && !(wsum > 0.0)) return fail("floor_weights: all zero");
  wsum = 0.0;
  for (double w : shape_weights) {
    if (!(w >= 0.0)) return fail("shape_weights: weights must be >= 0");
    wsum += w;
  }
  if (!shape && !(wsum > 0.0)) return fail("shape_weights: all zero");
  if (!(min_side >= 8.0) || !(max_side >= min_side) || max_side > 60.0)
    return fail("min_side/max_side " + std::to_string(min_side) + "/" + std::to_string(max_side) +
                ": need 8 <= min_side <= max_side <= 60 m");
  if (min_rooms_per_floor < 2 || max_rooms_per_floor > kMaxRoomsPerFloor || min_rooms_per_floor > max_rooms_per_floor)
    return fail("rooms per floor " + std::to_string(min_rooms_per_floor) + ".." + std::to_string(max_rooms_per_floor) +
                ": need 2 <= min <= max <= 6");
  for (const RoomRequirement& r : rooms) {
    if (r.category == Category::kRoom) return fail("rooms: category \"room\" cannot be required");
    if (r.count < 0) return fail("rooms: count " + std::to_string(r.count) + " of " + std::string(CategoryName(r.category)));
    if (r.level < kAnyLevel || r.level >= kMaxFloors)
      return fail("rooms: level " + std::to_string(r.level) + " of " + std::string(CategoryName(r.category)));
  }
  for (const ConnectionRequirement& c : connections) {
    if (c.a == Category::kRoom || c.b == Category::kRoom) return fail("connections: category \"room\"");
    if (c.level < kAnyLevel || c.level >= kMaxFloors) return fail("connections: level " + std::to_string(c.level));
  }
  if (max_attempts < 1) return fail("max_attempts " + std::to_string(max_attempts) + ": must be >= 1");
  return true;
}

namespace {

// ---------------------------------------------------------------------------------------------------
// Category priors.

bool IsPublic(Category c) {
  return c == Category::kLivingRoom || c == Category::kDiningRoom || c == Category::kKitchen ||
         c == Category::kUtilityRoom;
}
// Rooms nobody walks through to reach another.
bool IsLeaf(Category c) { return c == Category::kBathroom || c == Category::kBalcony; }
bool NeedsWindow(Category c) {
  return c == Category::kKitchen || c == Category::kBathroom || c == Category::kBalcony;
}

// Search order of the labeller: the most constrained categories first.
int LabelOrder(Category c) {
  switch (c) {
    case Category::kLivingRoom: return 0;
    case Category::kKitchen: return 1;
    case Category::kDiningRoom: return 2;
    case Category::kBathroom: return 3;
    case Category::kBalcony: return 4;
    case Category::kBedroom: return 5;
    case Category::kChildrenRoom: return 6;
    case Category::kMeetingRoom: return 7;
    case Category::kOffice: return 8;
    case Category::kUtilityRoom: return 9;
    case Category::kRoom: return 10;
  }
  return 10;
}

// Preferred area of each category, m2 (the labeller's size prior).
double PreferredArea(Category c) {
  switch (c) {
    case Category::kKitchen: return 11.0;
    case Category::kBathroom: return 5.5;
    case Category::kDiningRoom: return 15.0;
    case Category::kBedroom: return 16.0;
    case Category::kChildrenRoom: return 13.0;
    case Category::kOffice: return 11.0;
    case Category::kMeetingRoom: return 18.0;
    case Category::kUtilityRoom: return 8.0;
    case Category::kBalcony: return 7.0;
    case Category::kLivingRoom: return 30.0;
    default: return 15.0;
  }
}

// ---------------------------------------------------------------------------------------------------
// One floor's geometry and relations.

// A lattice run along a room edge that lies on the footprint's exterior: points a + t * step, t in
// [0, steps]; step is the primitive direction of the edge (step_len units long).
struct Run {
  IPoint a;
  IPoint step;
  int64_t steps = 0;
  double step_len = 1.0;
  bool axis() const { return step.x == 0 || step.y == 0; }
  double length() const { return static_cast<double>(steps) * step_len; }
};

struct Floor {
  int level = 0;
  IRing footprint;
  std::vector<IRing> rooms;
  int stair = -1;
  std::vector<Category> categories;
  std::vector<std::vector<std::vector<ISegment>>> shared;  // [i][j]: i's boundary shared with j (i's direction)
  std::vector<std::vector<Run>> exterior;
  std::vector<double> area_m2;
  std::vector<double> exterior_m;
  std::vector<char> narrow;  // some part of the room is under kHabitableWidth wide
  std::vector<std::vector<char>> door_ok, open_ok;
  std::vector<char> window_ok, entrance_ok;
  int entrance_room = -1;
};

struct Sizes {
  Scale scale;
  int64_t door = 0;       // door width, units
  int64_t clear = 0;      // clearance from wall corners, units
  int64_t open_min = 0;   // narrowest open, units
  int64_t open_max = 0;
  int64_t entrance_min = 0, entrance_max = 0;
  double window_min_m = 0.6;
};

Sizes MakeSizes(double grid) {
  Sizes s;
  s.scale.grid = grid;
  s.door = s.scale.UnitsUp(0.9);
  if (s.scale.Metres(s.door) > 1.2 + 1e-9) s.door = s.scale.UnitsUp(0.8);
  s.clear = std::max<int64_t>(1, s.scale.UnitsUp(0.1));
  s.open_min = s.scale.UnitsUp(1.5);
  s.open_max = std::max(s.open_min, s.scale.Units(3.0));
  s.entrance_min = s.scale.UnitsUp(1.0);
  s.entrance_max = std::max(s.entrance_min, s.scale.Units(1.5));
  return s;
}

// A segment as a run of grid steps (its direction over the gcd of its extents).
Run RunOf(const ISegment& seg) {
  const int64_t g = partition::Gcd(seg.b.x - seg.a.x, seg.b.y - seg.a.y);
  const IPoint step{(seg.b.x - seg.a.x) / g, (seg.b.y - seg.a.y) / g};
  return {seg.a, step, g, std::sqrt(static_cast<double>(step.x * step.x + step.y * step.y))};
}

// Steps a run offers for an element of at least `min_m` metres after clearances; 0 if none fits.
int64_t MinSteps(const Run& run, double min_m, const Sizes& s) {
  return static_cast<int64_t>(std::ceil(min_m / (run.step_len * s.scale.grid) - 1e-9));
}
int64_t ClearSteps(const Run& run, const Sizes& s) {
  return std::max<int64_t>(1, static_cast<int64_t>(std::ceil(static_cast<double>(s.clear) / run.step_len - 1e-9)));
}
bool RunFits(const Run& run, double min_m, const Sizes& s) {
  return run.steps >= MinSteps(run, min_m, s) + 2 * ClearSteps(run, s);
}

void AnalyseFloor(Floor& f, const Sizes& s) {
  const std::size_t n = f.rooms.size();
  f.shared.assign(n, std::vector<std::vector<ISegment>>(n));
  f.exterior.assign(n, {});
  f.door_ok.assign(n, std::vector<char>(n, 0));
  f.open_ok.assign(n, std::vector<char>(n, 0));
  f.window_ok.assign(n, 0);
  f.entrance_ok.assign(n, 0);
  f.area_m2.assign(n, 0.0);
  f.exterior_m.assign(n, 0.0);
  f.narrow.assign(n, 0);
  const double g2 = s.scale.grid * s.scale.grid;
  std::vector<IBox> boxes(n);
  for (std::size_t i = 0; i < n; ++i) boxes[i] = partition::BoundingBox(f.rooms[i]);
  for (std::size_t i = 0; i < n; ++i) {
    f.area_m2[i] = static_cast<double>(partition::TwiceArea(f.rooms[i])) * g2 / 2.0;
    f.narrow[i] = partition::NarrowerThan(f.rooms[i], kHabitableWidth / s.scale.grid - 1e-9) ? 1 : 0;
    for (std::size_t j = i + 1; j < n; ++j) {
      const IBox& a = boxes[i];
      const IBox& b = boxes[j];
      if (a.max_x < b.min_x || b.max_x < a.min_x || a.max_y < b.min_y || b.max_y < a.min_y) continue;
      f.shared[i][j] = partition::SharedSegments(f.rooms[i], f.rooms[j]);
      for (const ISegment& seg : f.shared[i][j]) {
        f.shared[j][i].push_back({seg.b, seg.a});
        const Run run = RunOf(seg);
        if (RunFits(run, s.scale.Metres(s.door), s)) f.door_ok[i][j] = f.door_ok[j][i] = 1;
        if (RunFits(run, s.scale.Metres(s.open_min), s)) f.open_ok[i][j] = f.open_ok[j][i] = 1;
      }
    }
  }
  // Exterior runs: each edge minus the parts shared with other rooms of the floor.
  for (std::size_t i = 0; i < n; ++i) {
    const IRing& r = f.rooms[i];
    for (std::size_t e = 0; e < r.size(); ++e) {
      const IPoint p = r[e], q = r[(e + 1) % r.size()];
      const int64_t g = partition::Gcd(q.x - p.x, q.y - p.y);
      const IPoint step{(q.x - p.x) / g, (q.y - p.y) / g};
      const int64_t step2 = step.x * step.x + step.y * step.y;
      std::vector<std::pair<int64_t, int64_t>> covered;
      for (std::size_t j = 0; j < n; ++j) {
        if (j == i) continue;
        for (const ISegment& seg : f.shared[i][j]) {
          if (partition::Cross(p, q, seg.a) != 0 || partition::Cross(p, q, seg.b) != 0) continue;
          int64_t t0 = ((seg.a.x - p.x) * step.x + (seg.a.y - p.y) * step.y) / step2;
          int64_t t1 = ((seg.b.x - p.x) * step.x + (seg.b.y - p.y) * step.y) / step2;
          if (t0 > t1) std::swap(t0, t1);
          t0 = std::max<int64_t>(t0, 0);
          t1 = std::min<int64_t>(t1, g);
          if (t1 > t0) covered.push_back({t0, t1});
        }
      }
      std::sort(covered.begin(), covered.end());
      int64_t t = 0;
      const double step_len = std::sqrt(static_cast<double>(step2));
      auto emit = [&](int64_t from, int64_t to) {
        if (to <= from) return;
        f.exterior[i].push_back({{p.x + step.x * from, p.y + step.y * from}, step, to - from, step_len});
      };
      for (const auto& [c0, c1] : covered) {
        emit(t, c0);
        t = std::max(t, c1);
      }
      emit(t, g);
    }
    for (const Run& run : f.exterior[i]) {
      f.exterior_m[i] += run.length() * s.scale.grid;
      if (RunFits(run, s.window_min_m, s)) f.window_ok[i] = 1;
      if (run.axis() && run.steps >= s.entrance_min + 2 * s.clear) f.entrance_ok[i] = 1;
    }
  }
}

// ---------------------------------------------------------------------------------------------------
// Floor plans: the categories each floor gets.

struct FloorPlanSpec {
  std::vector<Category> must;      // required or essential
  std::vector<Category> optional;  // prior fill, dropped from the end when the BSP gives fewer rooms
  int size() const { return static_cast<int>(must.size() + optional.size()); }
};

int SampleRoomsPerFloor(const PartitionOptions& o, Rng& rng) {
  // 3..6 rooms (staircase included) with an average of about 5.
  static const double kWeights[4] = {0.16, 0.33, 0.34, 0.17};
  int n = 3 + rng.Weighted(kWeights, 4);
  return std::clamp(n, o.min_rooms_per_floor, o.max_rooms_per_floor);
}

// `fixed`: categories whose number the caller's requirements set (a brief's "a meeting room"): the fill
// adds none of them, and stops short of `target` when nothing else is left, unless `must_fill` (rooms the
// BSP already made need a category).
void FillFromPriors(FloorPlanSpec& plan, int level, int floors, int target, Rng& rng,
                    const std::vector<Category>& fixed = {}, bool must_fill = false) {
  auto is_fixed = [&](Category c) { return std::find(fixed.begin(), fixed.end(), c) != fixed.end(); };
  auto count = [&](Category c) {
    return static_cast<int>(std::count(plan.must.begin(), plan.must.end(), c) +
                            std::count(plan.optional.begin(), plan.optional.end(), c));
  };
  // Essentials first (as optional, in priority order), then weighted fill.
  std::vector<Category> essentials;
  if (level == 0) {
    essentials = {Category::kLivingRoom, Category::kKitchen};
    if (floors == 1) {
      essentials.push_back(Category::kBathroom);
      essentials.push_back(Category::kBedroom);
    }
  } else {
    essentials = {Category::kBedroom, Category::kBathroom};
  }
  for (Category c : essentials)
    if (plan.size() < target && count(c) == 0 && !is_fixed(c)) plan.optional.push_back(c);
  struct Option {
    Category c;
    double w;
    int cap;
  };
  std::vector<Option> pool;
  if (level == 0 && floors > 1) {
    pool = {{Category::kDiningRoom, 3.0, 1}, {Category::kBathroom, 2.0, 1}, {Category::kOffice, 1.2, 1},
            {Category::kMeetingRoom, 0.8, 1}, {Category::kBedroom, 0.8, 1},   {Category::kChildrenRoom, 0.2, 1}};
  } else if (level == 0) {
    pool = {{Category::kDiningRoom, 2.5, 1}, {Category::kBedroom, 1.5, 3},     {Category::kChildrenRoom, 1.2, 2},
            {Category::kOffice, 0.8, 1},     {Category::kBathroom, 0.6, 2},    {Category::kMeetingRoom, 0.3, 1},
            {Category::kBalcony, 0.3, 1}};
  } else {
    pool = {{Category::kChildrenRoom, 2.0, 2}, {Category::kBalcony, 1.8, 1},     {Category::kBedroom, 1.6, 3},
            {Category::kOffice, 1.0, 1},       {Category::kBathroom, 0.7, 2},    {Category::kMeetingRoom, 0.5, 1}};
  }
  int guard = 0;
  while (plan.size() < target && guard++ < 100) {
    std::vector<double> w;
    for (const Option& o : pool) w.push_back(count(o.c) < o.cap && !is_fixed(o.c) ? o.w : 0.0);
    if (std::all_of(w.begin(), w.end(), [](double x) { return x == 0.0; })) {
      const Category plain = level == 0 ? Category::kOffice : Category::kBedroom;
      if (!must_fill && is_fixed(plain)) break;
      plan.optional.push_back(plain);
      continue;
    }
    plan.optional.push_back(pool[static_cast<std::size_t>(rng.Weighted(w.data(), static_cast<int>(w.size())))].c);
  }
}

// Where a whole-building requirement goes first: preferred floors in order.
std::vector<int> PreferredLevels(Category c, int floors) {
  std::vector<int> order;
  const bool high = c == Category::kBedroom || c == Category::kChildrenRoom || c == Category::kBalcony;
  if (high) {
    for (int l = floors - 1; l >= 0; --l) order.push_back(l);
  } else {
    for (int l = 0; l < floors; ++l) order.push_back(l);
  }
  return order;
}

// ---------------------------------------------------------------------------------------------------
// Labelling: a depth-first search assigning the plan's categories to rooms under the rules.

struct LabelContext {
  const Floor& floor;
  const std::vector<ConnectionRequirement>& links;  // connection requirements to meet on this floor
  bool ground = false;
  Rng& rng;
};

// The room the search starts reachability from: the entrance room (ground) or the staircase.
int ChooseEntrance(const Floor& f, const std::vector<Category>& cat) {
  static const Category kPreference[] = {Category::kLivingRoom, Category::kDiningRoom, Category::kUtilityRoom,
                                         Category::kKitchen,    Category::kOffice,     Category::kMeetingRoom,
                                         Category::kBedroom,    Category::kChildrenRoom};
  for (Category c : kPreference)
    for (std::size_t i = 0; i < cat.size(); ++i)
      if (cat[i] == c && f.entrance_ok[i]) return static_cast<int>(i);
  return -1;
}

bool Reachable(const Floor& f, const std::vector<Category>& cat, int root) {
  const std::size_t n = cat.size();
  std::vector<char> seen(n, 0);
  std::vector<int> stack{root};
  seen[static_cast<std::size_t>(root)] = 1;
  std::size_t count = 1;
  while (!stack.empty()) {
    const int u = stack.back();
    stack.pop_back();
    if (IsLeaf(cat[static_cast<std::size_t>(u)]) && u != root) continue;
    for (std::size_t v = 0; v < n; ++v) {
      if (seen[v] || !f.door_ok[static_cast<std::size_t>(u)][v]) continue;
      seen[v] = 1;
      ++count;
      stack.push_back(static_cast<int>(v));
    }
  }
  return count == n;
}

bool PairAdjacent(const Floor& f, const std::vector<Category>& cat, Category a, Category b, bool need_open) {
  for (std::size_t i = 0; i < cat.size(); ++i) {
    if (cat[i] != a) continue;
    for (std::size_t j = 0; j < cat.size(); ++j)
      if (i != j && cat[j] == b && (need_open ? f.open_ok[i][j] : f.door_ok[i][j])) return true;
  }
  return false;
}

bool FloorRulesHold(const Floor& f, const std::vector<Category>& cat, bool ground, const std::vector<ConnectionRequirement>& links,
                    int* entrance) {
  const std::size_t n = cat.size();
  bool has_kitchen = false, has_dining = false;
  for (Category c : cat) {
    has_kitchen |= c == Category::kKitchen;
    has_dining |= c == Category::kDiningRoom;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (cat[i] == Category::kKitchen && has_dining) {
      bool ok = false;
      for (std::size_t j = 0; j < n; ++j) ok |= cat[j] == Category::kDiningRoom && f.door_ok[i][j];
      if (!ok) return false;
    }
    if (cat[i] == Category::kLivingRoom && (has_kitchen || has_dining)) {
      bool ok = false;
      for (std::size_t j = 0; j < n; ++j)
        ok |= (cat[j] == Category::kKitchen || cat[j] == Category::kDiningRoom) && f.door_ok[i][j];
      if (!ok) return false;
    }
  }
  for (const ConnectionRequirement& link : links)
    if (!PairAdjacent(f, cat, link.a, link.b, link.kind == LinkKind::kOpen)) return false;
  int root = f.stair;
  if (ground) {
    root = ChooseEntrance(f, cat);
    if (root < 0) return false;
  }
  if (root < 0) root = 0;
  if (!Reachable(f, cat, root)) return false;
  *entrance = ground ? root : -1;
  return true;
}

struct LabelSearch {
  const Floor& f;
  const std::vector<ConnectionRequirement>& links;
  bool ground;
  std::vector<Category> slots;         // categories to place, in search order
  std::vector<std::vector<double>> score;  // [slot][room]
  std::vector<Category> cat;
  std::vector<char> used;
  int budget = 400;
  int entrance = -1;

  bool Search(std::size_t slot) {
    if (--budget < 0) return false;
    if (slot == slots.size()) return FloorRulesHold(f, cat, ground, links, &entrance);
    const Category c = slots[slot];
    std::vector<std::pair<double, int>> order;
    for (std::size_t r = 0; r < cat.size(); ++r) {
      if (used[r]) continue;
      if (NeedsWindow(c) && !f.window_ok[r]) continue;
      order.push_back({score[slot][r], static_cast<int>(r)});
    }
    std::sort(order.begin(), order.end(),
              [](const auto& a, const auto& b) { return a.first != b.first ? a.first > b.first : a.second < b.second; });
    for (const auto& [s, r] : order) {
      // Identical categories in consecutive slots: keep room indices increasing (no symmetric repeats).
      if (slot > 0 && slots[slot - 1] == c) {
        bool later = false;
        for (std::size_t q = 0; q < cat.size(); ++q)
          if (used[q] && cat[q] == c && static_cast<int>(q) > r) later = true;
        if (later) continue;
      }
      used[static_cast<std::size_t>(r)] = 1;
      cat[static_cast<std::size_t>(r)] = c;
      if (Search(slot + 1)) return true;
      used[static_cast<std::size_t>(r)] = 0;
      cat[static_cast<std::size_t>(r)] = Category::kRoom;
    }
    return false;
  }
};

// Exterior share of a room's perimeter (balconies sit at the edge).
double ExteriorShare(const Floor& f, std::size_t r, double grid) {
  double perimeter = 0.0;
  for (std::size_t i = 0; i < f.rooms[r].size(); ++i) {
    const IPoint p = f.rooms[r][i], q = f.rooms[r][(i + 1) % f.rooms[r].size()];
    perimeter += std::sqrt(double(q.x - p.x) * double(q.x - p.x) + double(q.y - p.y) * double(q.y - p.y));
  }
  return perimeter > 0 ? f.exterior_m[r] / (perimeter * grid) : 0.0;
}

// Labels the floor's non-staircase rooms with `plan` (same count). False when no assignment meets the
// rules (the caller retries or relaxes the connection requirements).
bool LabelFloor(Floor& f, const std::vector<Category>& plan, const std::vector<ConnectionRequirement>& links,
                const Sizes& s, Rng& rng) {
  const std::size_t n = f.rooms.size();
  LabelSearch search{f, links, f.level == 0, {}, {}, std::vector<Category>(n, Category::kRoom), std::vector<char>(n, 0)};
  if (f.stair >= 0) {
    search.cat[static_cast<std::size_t>(f.stair)] = Category::kUtilityRoom;
    search.used[static_cast<std::size_t>(f.stair)] = 1;
  }
  search.slots = plan;
  std::stable_sort(search.slots.begin(), search.slots.end(),
                   [](Category a, Category b) { return LabelOrder(a) < LabelOrder(b); });
  // Size prior by rank: the rooms sorted by area are matched to the categories sorted by their usual
  // size (the living room largest, bathrooms smallest); the search tries the closest ranks first.
  std::vector<std::size_t> by_area;
  for (std::size_t r = 0; r < n; ++r)
    if (static_cast<int>(r) != f.stair) by_area.push_back(r);
  std::stable_sort(by_area.begin(), by_area.end(), [&](std::size_t a, std::size_t b) { return f.area_m2[a] > f.area_m2[b]; });
  std::vector<double> room_rank(n, 0.0);
  for (std::size_t k = 0; k < by_area.size(); ++k) room_rank[by_area[k]] = static_cast<double>(k);
  std::vector<std::size_t> by_size(search.slots.size());
  for (std::size_t k = 0; k < by_size.size(); ++k) by_size[k] = k;
  auto size_key = [&](std::size_t k) {
    const Category c = search.slots[k];
    return c == Category::kLivingRoom ? 1e9 : PreferredArea(c);
  };
  std::stable_sort(by_size.begin(), by_size.end(), [&](std::size_t a, std::size_t b) { return size_key(a) > size_key(b); });
  std::vector<double> ideal_rank(search.slots.size(), 0.0);
  for (std::size_t k = 0; k < by_size.size(); ++k) ideal_rank[by_size[k]] = static_cast<double>(k);
  for (std::size_t k = 0; k < search.slots.size(); ++k) {
    const Category c = search.slots[k];
    std::vector<double> row(n);
    for (std::size_t r = 0; r < n; ++r) {
      double score = -std::abs(room_rank[r] - ideal_rank[k]) + rng.Unit() * 0.9;
      // Absolute sizes too: a room far above its category's usual size (a 20 m2 bathroom), or a living
      // room under 18 m2, ranks lower.
      if (c == Category::kLivingRoom) {
        score -= 3.0 * std::max(0.0, 1.0 - f.area_m2[r] / 18.0);
      } else if (r != static_cast<std::size_t>(f.stair)) {
        score -= 2.0 * std::max(0.0, std::log(f.area_m2[r] / (1.7 * PreferredArea(c))));
      }
      if (c == Category::kBalcony) score += 3.0 * ExteriorShare(f, r, s.scale.grid);
      // A room with a part under 1.8 m wide (an arm of an L, a strip beside a slanted wall) serves a
      // bathroom, a balcony or a utility room, not a room people live in.
      if (IsHabitable(c) && f.narrow[r]) score -= 8.0;
      if (c == Category::kLivingRoom && f.level == 0 && f.entrance_ok[r]) score += 0.5;
      row[r] = score;
    }
    search.score.push_back(std::move(row));
  }
  if (!search.Search(0)) return false;
  f.categories = search.cat;
  f.entrance_room = search.entrance;
  return true;
}

// ---------------------------------------------------------------------------------------------------
// Links (doors and opens), windows, entrance.

struct Link {
  int a = -1, b = -1;
  bool open = false;
  ISegment shape;
};

struct FloorElements {
  std::vector<Link> links;
  std::vector<std::pair<int, ISegment>> windows;  // room, segment
  std::vector<char> window_panoramic;
  std::optional<std::pair<int, ISegment>> entrance;
};

bool Linked(const std::vector<Link>& links, int a, int b) {
  for (const Link& l : links)
    if ((l.a == a && l.b == b) || (l.a == b && l.b == a)) return true;
  return false;
}

// A door or open between rooms a and b on one of their shared walls (axis-parallel or slanted: a slanted
// wall's grid steps are longer, so its doors are whole steps of at least the door width).
std::optional<Link> MakeLink(const Floor& f, int a, int b, bool open, const Sizes& s, Rng& rng) {
  const double min_m = s.scale.Metres(open ? s.open_min : s.door);
  std::vector<ISegment> walls;
  for (const ISegment& seg : f.shared[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)])
    if (RunFits(RunOf(seg), min_m, s)) walls.push_back(seg);
  if (walls.empty()) return std::nullopt;
  const ISegment& seg = walls[static_cast<std::size_t>(rng.Int(0, static_cast<int64_t>(walls.size()) - 1))];
  const Run wall = RunOf(seg);
  const int64_t clear = ClearSteps(wall, s);
  int64_t width = MinSteps(wall, min_m, s);
  if (open) {
    const int64_t widest = static_cast<int64_t>(std::floor(s.scale.Metres(s.open_max) / (wall.step_len * s.scale.grid) + 1e-9));
    width = rng.Int(width, std::max(width, std::min(widest, wall.steps - 2 * clear)));
  }
  auto door = partition::PlaceDoor(seg, width, clear, rng);
  if (!door) return std::nullopt;
  return Link{a, b, open, *door};
}

std::vector<char> ReachedByLinks(const Floor& f, const std::vector<Link>& links, int root) {
  const std::size_t n = f.rooms.size();
  std::vector<char> seen(n, 0);
  std::vector<int> stack{root};
  seen[static_cast<std::size_t>(root)] = 1;
  while (!stack.empty()) {
    const int u = stack.back();
    stack.pop_back();
    if (u != root && IsLeaf(f.categories[static_cast<std::size_t>(u)])) continue;
    for (const Link& l : links) {
      int v = l.a == u ? l.b : (l.b == u ? l.a : -1);
      if (v < 0 || seen[static_cast<std::size_t>(v)]) continue;
      seen[static_cast<std::size_t>(v)] = 1;
      stack.push_back(v);
    }
  }
  return seen;
}

bool ConnectFloor(const Floor& f, const std::vector<ConnectionRequirement>& required, const Sizes& s, Rng& rng,
                  FloorElements* out) {
  const std::size_t n = f.rooms.size();
  const auto& cat = f.categories;
  auto add = [&](int a, int b, bool open) {
    if (Linked(out->links, a, b)) return true;
    auto link = MakeLink(f, a, b, open, s, rng);
    if (!link && open) link = MakeLink(f, a, b, false, s, rng);
    if (!link) return false;
    out->links.push_back(*link);
    return true;
  };
  auto both_public = [&](int a, int b) {
    return IsPublic(cat[static_cast<std::size_t>(a)]) && IsPublic(cat[static_cast<std::size_t>(b)]);
  };
  // Required and rule links first.
  for (const ConnectionRequirement& req : required) {
    bool done = false;
    for (std::size_t i = 0; i < n && !done; ++i)
      for (std::size_t j = 0; j < n && !done; ++j) {
        if (i == j || cat[i] != req.a || cat[j] != req.b) continue;
        const bool open = req.kind == LinkKind::kOpen || (req.kind == LinkKind::kAny && both_public(int(i), int(j)) &&
                                                          f.open_ok[i][j] && rng.Chance(0.6));
        if (req.kind == LinkKind::kOpen ? !f.open_ok[i][j] : !f.door_ok[i][j]) continue;
        done = add(static_cast<int>(i), static_cast<int>(j), open && both_public(int(i), int(j)));
      }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (cat[i] != Category::kKitchen) continue;
    // A kitchen joins a dining room of its floor (rule 10), open where the wall allows.
    bool has_dining = false, linked = false;
    int pick = -1;
    for (std::size_t j = 0; j < n; ++j) {
      if (cat[j] != Category::kDiningRoom) continue;
      has_dining = true;
      linked |= Linked(out->links, int(i), int(j));
      if (f.door_ok[i][j] && (pick < 0 || f.open_ok[i][j])) pick = static_cast<int>(j);
    }
    if (!has_dining || linked) continue;
    if (pick < 0 || !add(static_cast<int>(i), pick, true)) return false;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (cat[i] != Category::kLivingRoom) continue;
    std::vector<int> cands;
    bool linked = false;
    for (std::size_t j = 0; j < n; ++j) {
      if (cat[j] != Category::kKitchen && cat[j] != Category::kDiningRoom) continue;
      if (Linked(out->links, int(i), int(j))) linked = true;
      if (f.door_ok[i][j]) cands.push_back(static_cast<int>(j));
    }
    if (linked) continue;
    bool any_kd = false;
    for (Category c : cat) any_kd |= c == Category::kKitchen || c == Category::kDiningRoom;
    if (!any_kd) continue;
    if (cands.empty()) return false;
    const int j = cands[static_cast<std::size_t>(rng.Int(0, static_cast<int64_t>(cands.size()) - 1))];
    if (!add(static_cast<int>(i), j, f.open_ok[i][static_cast<std::size_t>(j)] && rng.Chance(0.6))) return false;
  }
  // Spanning tree from the entrance room (ground) or the staircase: public rooms first as hubs.
  const int root = f.level == 0 ? f.entrance_room : f.stair;
  if (root < 0) return false;
  for (int guard = 0; guard < 64; ++guard) {
    const std::vector<char> reached = ReachedByLinks(f, out->links, root);
    if (std::all_of(reached.begin(), reached.end(), [](char c) { return c != 0; })) return true;
    double best = -1e9;
    int bu = -1, bv = -1;
    for (std::size_t u = 0; u < n; ++u) {
      if (!reached[u] || (static_cast<int>(u) != root && IsLeaf(cat[u]))) continue;
      for (std::size_t v = 0; v < n; ++v) {
        if (reached[v] || !f.door_ok[u][v]) continue;
        double score = rng.Unit();
        // Halls first: living and dining rooms and the staircase hall, then the kitchen.
        if (IsPublic(cat[u])) score += cat[u] == Category::kKitchen ? 1.0 : 2.0;
        if (cat[v] == Category::kBathroom && (cat[u] == Category::kBedroom || cat[u] == Category::kChildrenRoom))
          score += 1.0;
        if (cat[v] == Category::kBalcony && !IsPublic(cat[u])) score += 1.0;
        if (score > best) best = score, bu = static_cast<int>(u), bv = static_cast<int>(v);
      }
    }
    if (bu < 0) return false;
    const bool open = both_public(bu, bv) && f.open_ok[static_cast<std::size_t>(bu)][static_cast<std::size_t>(bv)] &&
                      rng.Chance(0.6);
    if (!add(bu, bv, open)) return false;
  }
  return false;
}

// A window of `min_m`..`max_m` metres on the run (clear of its ends), at a random grid position.
std::optional<ISegment> WindowOnRun(const Run& run, double min_m, double max_m, const Sizes& s, Rng& rng) {
  const int64_t clear = ClearSteps(run, s);
  const int64_t lo = MinSteps(run, min_m, s);
  const int64_t room = run.steps - 2 * clear;
  if (room < lo) return std::nullopt;
  const int64_t hi = std::max(lo, std::min(room, static_cast<int64_t>(std::floor(max_m / (run.step_len * s.scale.grid) + 1e-9))));
  const int64_t w = rng.Int(lo, hi);
  const int64_t off = rng.Int(clear, run.steps - clear - w);
  return ISegment{{run.a.x + run.step.x * off, run.a.y + run.step.y * off},
                  {run.a.x + run.step.x * (off + w), run.a.y + run.step.y * (off + w)}};
}

// `panoramic_room`: a room that gets a panoramic window besides balconies and o.panoramic_rooms (-1: none).
bool PlaceWindows(const Floor& f, const PartitionOptions& o, int panoramic_room, const Sizes& s, Rng& rng,
                  FloorElements* out) {
  const std::size_t n = f.rooms.size();
  // Runs in use (one element a run keeps windows, entrance and corners apart).
  std::vector<std::vector<char>> used(n);
  for (std::size_t i = 0; i < n; ++i) used[i].assign(f.exterior[i].size(), 0);
  auto pick_run = [&](std::size_t room, double min_m, bool axis_only, bool longest) -> int {
    int best = -1;
    double best_score = -1.0;
    for (std::size_t k = 0; k < f.exterior[room].size(); ++k) {
      const Run& run = f.exterior[room][k];
      if (used[room][k] || (axis_only && !run.axis()) || !RunFits(run, min_m, s)) continue;
      const double score = longest ? run.length() : rng.Unit() * (1.0 + run.length());
      if (score > best_score) best_score = score, best = static_cast<int>(k);
    }
    return best;
  };
  if (f.level == 0 && f.entrance_room >= 0) {
    const std::size_t r = static_cast<std::size_t>(f.entrance_room);
    int best = -1;
    for (std::size_t k = 0; k < f.exterior[r].size(); ++k) {
      const Run& run = f.exterior[r][k];
      if (!run.axis() || run.steps < s.entrance_min + 2 * s.clear) continue;
      if (best < 0 || rng.Chance(0.5)) best = static_cast<int>(k);
    }
    if (best < 0) return false;
    const Run& run = f.exterior[r][static_cast<std::size_t>(best)];
    const int64_t w = rng.Int(s.entrance_min, std::min(s.entrance_max, run.steps - 2 * s.clear));
    const int64_t off = rng.Int(s.clear, run.steps - s.clear - w);
    out->entrance = std::make_pair(
        static_cast<int>(r), ISegment{{run.a.x + run.step.x * off, run.a.y + run.step.y * off},
                                      {run.a.x + run.step.x * (off + w), run.a.y + run.step.y * (off + w)}});
    used[r][static_cast<std::size_t>(best)] = 1;
  }
  auto add_window = [&](std::size_t room, double min_m, double max_m, bool panoramic, bool longest) {
    const int k = pick_run(room, std::max(min_m, s.window_min_m), false, longest);
    if (k < 0) return false;
    auto w = WindowOnRun(f.exterior[room][static_cast<std::size_t>(k)], std::max(min_m, s.window_min_m), max_m, s, rng);
    if (!w) return false;
    used[room][static_cast<std::size_t>(k)] = 1;
    out->windows.push_back({static_cast<int>(room), *w});
    out->window_panoramic.push_back(panoramic ? 1 : 0);
    return true;
  };
  for (std::size_t i = 0; i < n; ++i) {
    const Category c = f.categories[i];
    const bool pano_wanted = std::find(o.panoramic_rooms.begin(), o.panoramic_rooms.end(), c) != o.panoramic_rooms.end();
    const bool pano_here = static_cast<int>(i) == panoramic_room;
    if (c == Category::kBalcony || pano_wanted || pano_here) {
      if (!add_window(i, 1.5, 6.0, true, true) && !add_window(i, 0.6, 6.0, true, true)) {
        if (c == Category::kBalcony) return false;
      }
      continue;
    }
    switch (c) {
      case Category::kKitchen:
      case Category::kBathroom:
        if (!add_window(i, 0.8, 1.5, false, false) && !add_window(i, 0.6, 1.5, false, false)) return false;
        break;
      case Category::kLivingRoom:
        add_window(i, 1.2, 2.5, false, true);
        if (rng.Chance(0.6)) add_window(i, 1.0, 2.5, false, false);
        break;
      case Category::kUtilityRoom:
        if (rng.Chance(0.3)) add_window(i, 0.6, 1.0, false, false);
        break;
      default:
        if (rng.Chance(0.92)) add_window(i, 1.0, 2.2, false, true);
        break;
    }
  }
  return true;
}

// ---------------------------------------------------------------------------------------------------
// Assembly of the Layout.

double ToMetres(int64_t units, double grid) {
  return std::round(static_cast<double>(units) * grid * 100.0) / 100.0;
}
Point ToPoint(IPoint p, double grid) { return {ToMetres(p.x, grid), ToMetres(p.y, grid)}; }
Segment ToSegment(const ISegment& s, double grid) { return {ToPoint(s.a, grid), ToPoint(s.b, grid)}; }

struct Building {
  std::vector<Floor> floors;
  std::vector<FloorElements> elements;
};

Layout BuildLayout(const Building& b, double grid) {
  Layout layout;
  std::map<std::string, int> name_uses[5];
  auto unique = [&](ElementKind kind, std::string name) {
    int& uses = name_uses[static_cast<int>(kind)][name];
    ++uses;
    return uses == 1 ? name : name + "_" + std::to_string(uses);
  };
  for (std::size_t l = 0; l < b.floors.size(); ++l) {
    const Floor& f = b.floors[l];
    const std::size_t n = f.rooms.size();
    // Stable order: staircase first, then category order, then position (lowest, then leftmost).
    std::vector<std::size_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = i;
    auto key = [&](std::size_t i) {
      const IBox box = partition::BoundingBox(f.rooms[i]);
      const int rank = static_cast<int>(i) == f.stair ? -1 : static_cast<int>(f.categories[i]);
      return std::make_tuple(rank, box.min_y, box.min_x, box.max_y, box.max_x, i);
    };
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t c) { return key(a) < key(c); });
    std::vector<std::string> token(n);
    std::map<Category, int> index;
    for (std::size_t i : order) {
      const Category c = f.categories[i];
      Room room;
      room.category = c;
      room.level = static_cast<int>(l);
      room.index = index[c]++;
      // Canonical vertex order of the text format (counter-clockwise from the lowest x, then y), so the
      // layout validated here is exactly the one a reader parses back from the written text.
      const IRing& ring = f.rooms[i];
      std::size_t first = 0;
      for (std::size_t k = 1; k < ring.size(); ++k)
        if (ring[k].x < ring[first].x || (ring[k].x == ring[first].x && ring[k].y < ring[first].y)) first = k;
      room.polygon.reserve(ring.size());
      for (std::size_t k = 0; k < ring.size(); ++k) room.polygon.push_back(ToPoint(ring[(first + k) % ring.size()], grid));
      token[i] = std::string(CategoryToken(c)) + std::to_string(l) + (room.index > 0 ? "-" + std::to_string(room.index) : "");
      layout.rooms.push_back(std::move(room));
    }
    const FloorElements& e = b.elements[l];
    const int level = static_cast<int>(l);
    if (e.entrance) {
      layout.entrances.push_back({unique(ElementKind::kEntrance, "main_door"), ElementKind::kEntrance,
                                  ToSegment(e.entrance->second, grid), 0, false});
    }
    for (const Link& link : e.links) {
      const std::size_t a = static_cast<std::size_t>(link.a), c = static_cast<std::size_t>(link.b);
      const ElementKind kind = link.open ? ElementKind::kOpen : ElementKind::kDoor;
      Element el{unique(kind, token[a] + "_" + token[c]), kind, ToSegment(link.shape, grid), level, false};
      (link.open ? layout.opens : layout.doors).push_back(std::move(el));
    }
    for (std::size_t k = 0; k < e.windows.size(); ++k) {
      const std::size_t r = static_cast<std::size_t>(e.windows[k].first);
      const bool pano = e.window_panoramic[k] != 0;
      layout.windows.push_back({unique(ElementKind::kWindow, token[r] + (pano ? "_pano" : "_window")),
                                ElementKind::kWindow, ToSegment(e.windows[k].second, grid), level, pano});
    }
    for (std::size_t oi = 0; oi < n; ++oi) {
      for (std::size_t oj = oi + 1; oj < n; ++oj) {
        const std::size_t i = order[oi], j = order[oj];
        for (const ISegment& seg : f.shared[i][j])
          layout.interiors.push_back({unique(ElementKind::kInterior, "wall_" + token[i] + "_" + token[j]),
                                      ElementKind::kInterior, ToSegment(seg, grid), level, false});
      }
    }
  }
  return layout;
}

// ---------------------------------------------------------------------------------------------------
// One attempt.

struct Plan {
  int floors = 1;
  ShapeClass shape = ShapeClass::kRectangle;
  std::vector<FloorPlanSpec> specs;  // per floor, non-staircase rooms
  std::vector<std::vector<ConnectionRequirement>> links;  // per floor
  std::vector<Category> fixed;  // categories whose number the requirements set (the prior fill adds none)
  // Why a requirement cannot be met by any layout of this plan (empty when it can), by index into
  // options.rooms / options.connections: over a floor's capacity, no such floor, no such room.
  std::vector<std::string> room_hints, link_hints;
  int impossible() const {
    int n = 0;
    for (const auto& h : room_hints) n += !h.empty();
    for (const auto& h : link_hints) n += !h.empty();
    return n;
  }
};

Plan MakePlan(const PartitionOptions& o, Rng& rng) {
  Plan plan;
  plan.floors = o.floors > 0 ? o.floors : 1 + rng.Weighted(o.floor_weights, 3);
  plan.shape = o.shape ? *o.shape : AllShapeClasses()[static_cast<std::size_t>(rng.Weighted(o.shape_weights, kShapeClassCount))];
  const int F = plan.floors;
  const bool multi = F > 1;
  plan.specs.assign(static_cast<std::size_t>(F), {});
  plan.links.assign(static_cast<std::size_t>(F), {});
  plan.room_hints.assign(o.rooms.size(), "");
  for (const RoomRequirement& r : o.rooms)
    if (r.category != Category::kUtilityRoom) plan.fixed.push_back(r.category);
  plan.link_hints.assign(o.connections.size(), "");
  const int cap = o.max_rooms_per_floor - (multi ? 1 : 0);
  auto spec_of = [&](int l) -> FloorPlanSpec& { return plan.specs[static_cast<std::size_t>(l)]; };
  auto has = [&](int l, Category c) {
    const auto& m = spec_of(l).must;
    return c == Category::kUtilityRoom ? (multi || std::count(m.begin(), m.end(), c) > 0)
                                       : std::count(m.begin(), m.end(), c) > 0;
  };
  auto place = [&](Category c, int level) {
    if (level < 0 || level >= F || spec_of(level).size() >= cap) return false;
    spec_of(level).must.push_back(c);
    return true;
  };
  // 1. Requirements for one floor.
  for (std::size_t i = 0; i < o.rooms.size(); ++i) {
    const RoomRequirement& r = o.rooms[i];
    if (r.level == kAnyLevel) continue;
    if (r.level >= F) {
      plan.room_hints[i] = "the building has " + std::to_string(F) + (F == 1 ? " floor" : " floors");
      continue;
    }
    const int stairs = multi && r.category == Category::kUtilityRoom ? 1 : 0;  // the staircase room is there
    int made = stairs;
    for (int k = stairs; k < r.count; ++k) made += place(r.category, r.level) ? 1 : 0;
    if (made < r.count) plan.room_hints[i] = "room for " + std::to_string(made) + " on that floor";
    if (r.count < stairs) plan.room_hints[i] = "every floor of a multi-story building has its staircase room";
  }
  // 2. What whole-building requirements still ask for.
  std::map<Category, int> remaining;
  std::map<Category, std::size_t> remaining_index;
  for (std::size_t i = 0; i < o.rooms.size(); ++i) {
    const RoomRequirement& r = o.rooms[i];
    if (r.level != kAnyLevel) continue;
    int count = r.count;
    if (multi && r.category == Category::kUtilityRoom) {
      if (count < F) plan.room_hints[i] = "a " + std::to_string(F) + "-story building has a staircase room on every floor";
      count -= F;
    }
    remaining[r.category] += std::max(0, count);
    remaining_index[r.category] = i;
  }
  auto pull = [&](Category c, int level) {
    // A room for a connection: taken from the whole-building requirements, or added when the building
    // is not limited to the required rooms.
    if (remaining[c] > 0) {
      if (!place(c, level)) return false;
      --remaining[c];
      return true;
    }
    return !o.only_required_rooms && place(c, level);
  };
  // 3. Connection requirements choose their floor and pull their two rooms there.
  for (std::size_t i = 0; i < o.connections.size(); ++i) {
    const ConnectionRequirement& c = o.connections[i];
    std::vector<int> levels;
    if (c.level != kAnyLevel) {
      if (c.level >= F) {
        plan.link_hints[i] = "the building has " + std::to_string(F) + (F == 1 ? " floor" : " floors");
        continue;
      }
      levels.push_back(c.level);
    } else {
      levels = PreferredLevels(c.a == Category::kLivingRoom || c.a == Category::kKitchen ? c.a : c.b, F);
      // Floors already holding an end first.
      std::stable_sort(levels.begin(), levels.end(),
                       [&](int x, int y) { return (has(x, c.a) + has(x, c.b)) > (has(y, c.a) + has(y, c.b)); });
    }
    bool placed = false;
    for (int l : levels) {
      if (placed) break;
      const bool need_a = !has(l, c.a), need_b = !has(l, c.b) && !(c.a == c.b && !need_a);
      const int free = cap - spec_of(l).size();
      if (need_a + need_b > free) continue;
      auto available = [&](Category cat) { return remaining[cat] > 0 || !o.only_required_rooms; };
      if ((need_a && !available(c.a)) || (need_b && !available(c.b))) continue;
      if (need_a) pull(c.a, l);
      if (need_b) pull(c.b, l);
      plan.links[static_cast<std::size_t>(l)].push_back(c);
      placed = true;
    }
    if (!placed) {
      const bool missing = o.only_required_rooms && (remaining[c.a] == 0 || remaining[c.b] == 0);
      plan.link_hints[i] = missing ? "the required rooms leave none free for it" : "no floor has room for both";
    }
  }
  // 4. The rest of the whole-building rooms, by each category's preferred floors.
  for (auto& [category, count] : remaining) {
    const Category c = category;
    for (; count > 0; --count) {
      bool ok = false;
      std::vector<int> levels;
      for (int l = 0; l < F; ++l) levels.push_back(l);
      if (c == Category::kBathroom) {
        // Spread bathrooms: the floor with the fewest first.
        std::stable_sort(levels.begin(), levels.end(), [&](int a, int b) {
          auto cnt = [&](int l) { return std::count(spec_of(l).must.begin(), spec_of(l).must.end(), c); };
          return cnt(a) < cnt(b);
        });
      } else {
        levels = PreferredLevels(c, F);
      }
      for (int l : levels)
        if (!ok) ok = place(c, l);
      if (!ok) {
        plan.room_hints[remaining_index[c]] = "more than the floors hold (at most " + std::to_string(o.max_rooms_per_floor) +
                                              " rooms a floor)";
        break;
      }
    }
  }
  // 5. Prior fill up to the floor's room count.
  for (int l = 0; l < F; ++l) {
    const int target = o.only_required_rooms ? std::max(spec_of(l).size(), 1)
                                             : std::max(spec_of(l).size(), SampleRoomsPerFloor(o, rng) - (multi ? 1 : 0));
    FillFromPriors(spec_of(l), l, F, std::min(target, cap), rng, plan.fixed);
  }
  return plan;
}

struct AttemptResult {
  bool ok = false;
  std::string reason;
  Building building;
  bool relaxed_links = false;
};

// BSP draws a floor gets, and the worst penalty of its rooms (ShapePenalty plus the narrow-part penalty) that
// ends the draws (1.5: every room within about 2.6:1 and filling 66 % of its box in its own frame) and that
// is still accepted (about 3.2:1).
constexpr int kBspDraws = 3;
constexpr double kShapeGood = 1.5;
constexpr double kShapeAcceptable = 6.0;
// The footprint: the largest floor's usual room sizes times kNeedLo..kNeedLo + kNeedSpan (before the
// minimum sides); a floor gets extra rooms while its area exceeds kSpacious times its rooms' usual sizes;
// rooms over kOversized m2 are split once more while the floor has room for another.
constexpr double kNeedLo = 0.8;
constexpr double kNeedSpan = 0.2;
constexpr double kSpacious = 2.0;
constexpr double kOversized = 40.0;

// A floor whose labelled rooms are sized against their type: a living room under 14 m2, or another room
// over 3x its category's usual size (a 17 m2 bathroom, a 48 m2 bedroom).
bool SizedAgainstType(const Floor& f) {
  for (std::size_t i = 0; i < f.rooms.size(); ++i) {
    if (static_cast<int>(i) == f.stair) continue;
    const Category c = f.categories[i];
    if (c == Category::kLivingRoom ? f.area_m2[i] < 14.0 : f.area_m2[i] > 3.0 * PreferredArea(c)) return true;
  }
  return false;
}

// `strict`: floors with rooms sized against their type are retried (the first attempts; later ones take
// any valid layout, so a tight brief still gets one).
AttemptResult Attempt(const PartitionOptions& o, const Plan& plan, const Sizes& s, Rng& rng, bool strict) {
  AttemptResult result;
  const int F = plan.floors;
  const Scale& scale = s.scale;
  // Footprint: the usual sizes of the planned rooms (PreferredArea, plus the staircase) of the floor that
  // needs most (an upper floor's need counts 15 % more: its cuts take some of the ground floor), times
  // kNeedLo.., in a rectangle of aspect 1-1.6 whose cuts (notches, angled bites) take roughly `kept` of it.
  static const double kKept[kShapeClassCount] = {1.0, 0.78, 0.8, 0.72, 0.7, 0.85, 0.78, 0.86, 0.8, 0.68, 0.95, 0.72};
  const double kept = kKept[static_cast<int>(plan.shape)];
  double need = 0.0;
  for (int l = 0; l < F; ++l) {
    const FloorPlanSpec& spec = plan.specs[static_cast<std::size_t>(l)];
    double sum = F > 1 ? kStairRoomSize * kStairRoomSize : 0.0;
    for (Category c : spec.must) sum += PreferredArea(c);
    for (Category c : spec.optional) sum += PreferredArea(c);
    need = std::max(need, l == 0 ? sum : sum * 1.15);
  }
  const double area = need * (kNeedLo + rng.Unit() * kNeedSpan) / kept;
  const double aspect = 1.0 + rng.Unit() * 0.6;
  double long_side = std::sqrt(area * aspect), short_side = std::sqrt(area / aspect);
  const bool winged = plan.shape == ShapeClass::kU || plan.shape == ShapeClass::kT || plan.shape == ShapeClass::kH ||
                      plan.shape == ShapeClass::kCross || plan.shape == ShapeClass::kAngledWing;
  const double floor_side = std::max(o.min_side, winged ? 11.0 : 0.0);
  long_side = std::clamp(long_side, floor_side, std::max(floor_side, o.max_side));
  short_side = std::clamp(short_side, floor_side, std::max(floor_side, o.max_side));
  int64_t W = scale.Units(long_side), H = scale.Units(short_side);
  if (rng.Chance(0.5)) std::swap(W, H);
  IRing ground = partition::FootprintShape(plan.shape, W, H, scale, rng);
  if (ground.empty()) {
    result.reason = "footprint cuts did not fit";
    return result;
  }
  // Three in ten orthogonal footprints get 45-degree corners.
  if (!ShapeClassIsAngled(plan.shape) && rng.Chance(0.3)) ground = partition::ChamferCorners(std::move(ground), scale, rng);
  std::optional<IBox> stair;
  const int64_t stair_units = scale.Units(kStairRoomSize);
  if (F > 1) {
    stair = partition::PlaceStaircase(ground, stair_units, scale, rng);
    if (!stair) {
      result.reason = "no place for the staircase";
      return result;
    }
  }
  const double g2 = scale.grid * scale.grid;
  BspLimits limits;
  limits.min_area2 = static_cast<int64_t>(std::ceil(2.0 * 6.0 / g2));
  limits.min_side = scale.UnitsUp(2.5);
  limits.min_width = 1.2 / scale.grid;

  std::vector<IRing> footprints{ground};
  for (int l = 1; l < F; ++l) {
    const int rooms = plan.specs[static_cast<std::size_t>(l)].size() + 1;
    const int64_t min_area2 = static_cast<int64_t>(2.0 * (16.0 + 14.0 * (rooms - 1)) / g2);
    footprints.push_back(partition::UpperFootprint(footprints.back(), stair, min_area2, scale, rng));
  }
  // A spacious floor gets more rooms from the priors (one at a time while its area exceeds kSpacious
  // times the usual sizes of its rooms, at most the cap), unless the building is limited to the required
  // rooms.
  std::vector<FloorPlanSpec> specs = plan.specs;
  if (!o.only_required_rooms) {
    const int cap = o.max_rooms_per_floor - (stair ? 1 : 0);
    for (int l = 0; l < F; ++l) {
      FloorPlanSpec& spec = specs[static_cast<std::size_t>(l)];
      const double area = static_cast<double>(partition::TwiceArea(footprints[static_cast<std::size_t>(l)])) * g2 / 2.0 -
                          (stair ? 16.0 : 0.0);
      while (spec.size() < cap) {
        double usual = 0.0;
        for (Category c : spec.must) usual += PreferredArea(c);
        for (Category c : spec.optional) usual += PreferredArea(c);
        if (area < kSpacious * usual) break;
        const int before = spec.size();
        FillFromPriors(spec, l, F, spec.size() + 1, rng, plan.fixed);
        if (spec.size() == before) break;
      }
    }
  }
  Building& b = result.building;
  for (int l = 0; l < F; ++l) {
    Floor f;
    f.level = l;
    f.footprint = footprints[static_cast<std::size_t>(l)];
    std::vector<IRing> pieces{f.footprint};
    if (stair) {
      pieces.clear();
      if (!partition::SubtractInside(f.footprint, partition::BoxRing(*stair), &pieces)) {
        result.reason = "staircase cut off the grid";
        return result;
      }
    }
    for (const IRing& p : pieces)
      if (!partition::PieceUsable(p, limits)) {
        result.reason = "floor (beside the staircase) too narrow for rooms";
        return result;
      }
    const FloorPlanSpec& spec = specs[static_cast<std::size_t>(l)];
    // Room sizes the plan asks for: every category at about its usual size, except the largest (the
    // living room, else the biggest by prior), which takes what is left.
    std::vector<Category> planned = spec.must;
    for (Category c : spec.optional) planned.push_back(c);
    std::vector<int64_t> wanted;
    {
      int64_t floor_area2 = 0;
      for (const IRing& p : pieces) floor_area2 += partition::TwiceArea(p);
      std::size_t largest = 0;
      for (std::size_t k = 1; k < planned.size(); ++k) {
        auto size = [](Category c) { return c == Category::kLivingRoom ? 1e9 : PreferredArea(c); };
        if (size(planned[k]) > size(planned[largest])) largest = k;
      }
      // Every room at its usual size scaled to the floor (0.8-1.35x: a spacious floor's surplus goes to the
      // largest room, or into an extra room when that grows oversized), +-15 %; the rest of the area goes
      // to the largest room. On a tight floor all shrink to leave the largest a quarter.
      const double area = static_cast<double>(floor_area2) * g2 / 2.0;
      double usual = 0.0;
      for (Category c : planned) usual += PreferredArea(c);
      const double grow = std::clamp(area / std::max(1.0, usual), 0.8, 1.35);
      double sum = 0.0;
      std::vector<double> metres;
      for (std::size_t k = 0; k < planned.size(); ++k) {
        if (k == largest) continue;
        // Bathrooms do not grow with the floor.
        const double g = planned[k] == Category::kBathroom ? std::min(grow, 1.0) : grow;
        metres.push_back(PreferredArea(planned[k]) * g * (0.85 + 0.3 * rng.Unit()));
        sum += metres.back();
      }
      const double budget = 0.75 * area;
      const double shrink = sum > budget ? budget / sum : 1.0;
      for (double m : metres) wanted.push_back(static_cast<int64_t>(2.0 * m * shrink / g2));
    }
    // Rooms over kOversized m2 are split once more while the floor has room for another (not when the
    // building is limited to the required rooms).
    BspLimits floor_limits = limits;
    // Splits that leave a part under 1.8 m wide (a room with a 1.2 m arm is a corridor, not a bedroom)
    // score worse; the labels then give such a room to a bathroom or a balcony.
    floor_limits.comfortable_width = kHabitableWidth / scale.grid;
    if (!o.only_required_rooms) {
      floor_limits.max_area2 = static_cast<int64_t>(2.0 * kOversized / g2);
      floor_limits.max_pieces = o.max_rooms_per_floor - (stair ? 1 : 0);
    }
    // Interior walls may follow the outline's slanted sides.
    const std::vector<ILine> follow = partition::SlantedLines(f.footprint);
    // A few BSP draws of the floor; the one whose worst room is best proportioned wins, and the first
    // whose rooms are all within kShapeGood is taken at once. A floor
    // with a room still beyond about 3.2:1 is retried.
    auto enough = [&](const std::vector<IRing>& r) {
      return static_cast<int>(r.size()) >= static_cast<int>(spec.must.size()) &&
             static_cast<int>(r.size()) + (stair ? 1 : 0) >= std::min(o.min_rooms_per_floor, spec.size() + (stair ? 1 : 0));
    };
    std::vector<IRing> rooms;
    double worst_best = 1e18;
    for (int draw = 0; draw < kBspDraws && worst_best > kShapeGood; ++draw) {
      std::vector<IRing> candidate = partition::SplitRoomBsp(pieces, spec.size(), floor_limits, rng, wanted, follow);
      if (!enough(candidate)) continue;
      double worst = 0.0;
      for (const IRing& r : candidate) worst = std::max(worst, partition::PartsPenalty({r}, floor_limits));
      if (worst < worst_best) worst_best = worst, rooms = std::move(candidate);
    }
    if (rooms.empty()) {
      result.reason = "BSP gave too few rooms";
      return result;
    }
    if (worst_best > kShapeAcceptable) {
      result.reason = "rooms too elongated";
      return result;
    }
    FloorPlanSpec grown = spec;
    if (static_cast<int>(rooms.size()) > grown.size())
      FillFromPriors(grown, l, F, static_cast<int>(rooms.size()), rng, plan.fixed, true);  // rooms split for size need a category
    std::vector<Category> categories = grown.must;
    for (Category c : grown.optional)
      if (static_cast<int>(categories.size()) < static_cast<int>(rooms.size())) categories.push_back(c);
    f.rooms = std::move(rooms);
    if (stair) {
      f.stair = static_cast<int>(f.rooms.size());
      f.rooms.push_back(partition::BoxRing(*stair));
    }
    AnalyseFloor(f, s);
    const auto& links = plan.links[static_cast<std::size_t>(l)];
    if (!LabelFloor(f, categories, links, s, rng)) {
      bool labelled = !links.empty() && LabelFloor(f, categories, {}, s, rng);
      if (labelled) {
        result.relaxed_links = true;
      } else if (!o.only_required_rooms) {
        // Second chance with the prior fill's most demanding room (a bathroom or balcony needs a window
        // and ends a path; a dining room must sit by the kitchen) swapped for a plain one.
        for (std::size_t k = categories.size(); k-- > spec.must.size() && !labelled;) {
          const Category c = categories[k];
          if (!IsLeaf(c) && c != Category::kDiningRoom) continue;
          categories[k] = l == 0 ? Category::kOffice : Category::kBedroom;
          labelled = LabelFloor(f, categories, links, s, rng);
          if (!labelled) categories[k] = c;
        }
      }
      if (!labelled) {
        result.reason = "no labelling meets the rules";
        return result;
      }
    }
    if (strict && SizedAgainstType(f)) {
      result.reason = "rooms sized against their type";
      return result;
    }
    FloorElements e;
    if (!ConnectFloor(f, result.relaxed_links ? std::vector<ConnectionRequirement>{} : links, s, rng, &e)) {
      result.reason = "rooms not all reachable";
      return result;
    }
    b.floors.push_back(std::move(f));
    b.elements.push_back(std::move(e));
  }
  // A requested panoramic window without a balcony (balconies always have one): the living room's (the
  // lowest with an exterior wall long enough), else the largest such room of the top floor's.
  std::pair<int, int> panoramic{-1, -1};  // level, room
  if (o.panoramic_windows) {
    bool balcony = false;
    for (const Floor& f : b.floors)
      for (Category c : f.categories) balcony |= c == Category::kBalcony;
    for (const Floor& f : b.floors)
      for (std::size_t i = 0; i < f.rooms.size() && !balcony && panoramic.first < 0; ++i)
        if (f.categories[i] == Category::kLivingRoom && f.window_ok[i]) panoramic = {f.level, static_cast<int>(i)};
    if (!balcony && panoramic.first < 0) {
      const Floor& top = b.floors.back();
      for (std::size_t i = 0; i < top.rooms.size(); ++i)
        if (top.window_ok[i] && top.categories[i] != Category::kBathroom &&
            (panoramic.second < 0 || top.area_m2[i] > top.area_m2[static_cast<std::size_t>(panoramic.second)]))
          panoramic = {top.level, static_cast<int>(i)};
    }
  }
  for (int l = 0; l < F; ++l) {
    const int pano_room = panoramic.first == l ? panoramic.second : -1;
    if (!PlaceWindows(b.floors[static_cast<std::size_t>(l)], o, pano_room, s, rng, &b.elements[static_cast<std::size_t>(l)])) {
      result.reason = "no exterior wall for a required window or the entrance";
      return result;
    }
  }
  result.ok = true;
  return result;
}

// Requirements the finished layout does not meet.
std::vector<std::string> UnmetRequirements(const PartitionOptions& o, const Plan& plan, const Building& b) {
  std::vector<std::string> unmet;
  const int F = static_cast<int>(b.floors.size());
  auto count = [&](Category c, int level) {
    int n = 0;
    for (const Floor& f : b.floors)
      if (level == kAnyLevel || f.level == level)
        n += static_cast<int>(std::count(f.categories.begin(), f.categories.end(), c));
    return n;
  };
  auto hinted = [](std::string text, const std::string& hint) { return hint.empty() ? text : text + " (" + hint + ")"; };
  for (std::size_t i = 0; i < o.rooms.size(); ++i) {
    const RoomRequirement& r = o.rooms[i];
    const int made = count(r.category, r.level);
    if (made != r.count) {
      std::string where = r.level == kAnyLevel ? "" : " on level " + std::to_string(r.level);
      unmet.push_back(hinted(std::to_string(r.count) + " " + std::string(CategoryName(r.category)) + where + ": made " +
                                 std::to_string(made),
                             plan.room_hints[i]));
    }
  }
  for (std::size_t i = 0; i < o.connections.size(); ++i) {
    const ConnectionRequirement& c = o.connections[i];
    bool met = false;
    for (int l = 0; l < F && !met; ++l) {
      if (c.level != kAnyLevel && c.level != l) continue;
      const Floor& f = b.floors[static_cast<std::size_t>(l)];
      for (const Link& link : b.elements[static_cast<std::size_t>(l)].links) {
        const Category ca = f.categories[static_cast<std::size_t>(link.a)];
        const Category cb = f.categories[static_cast<std::size_t>(link.b)];
        const bool pair = (ca == c.a && cb == c.b) || (ca == c.b && cb == c.a);
        const bool kind = c.kind == LinkKind::kAny || (c.kind == LinkKind::kOpen) == link.open;
        met |= pair && kind;
      }
    }
    if (!met) {
      static const char* kKind[] = {"a door or open", "a door", "an open connection"};
      std::string where = c.level == kAnyLevel ? "" : " on level " + std::to_string(c.level);
      unmet.push_back(hinted(std::string(CategoryName(c.a)) + " to " + std::string(CategoryName(c.b)) + " through " +
                                 kKind[static_cast<int>(c.kind)] + where + ": not made",
                             plan.link_hints[i]));
    }
  }
  if (o.panoramic_windows) {
    bool any = false;
    for (const FloorElements& e : b.elements)
      for (char p : e.window_panoramic) any |= p != 0;
    if (!any) unmet.push_back("a panoramic window: no exterior wall long enough");
  }
  for (Category c : o.panoramic_rooms) {
    for (const Floor& f : b.floors) {
      const FloorElements& e = b.elements[static_cast<std::size_t>(f.level)];
      for (std::size_t i = 0; i < f.categories.size(); ++i) {
        if (f.categories[i] != c) continue;
        bool has = false;
        for (std::size_t k = 0; k < e.windows.size(); ++k)
          has |= e.windows[k].first == static_cast<int>(i) && e.window_panoramic[k];
        if (!has)
          unmet.push_back("panoramic window in " + std::string(CategoryName(c)) + " on level " + std::to_string(f.level) +
                          ": no exterior wall long enough");
      }
    }
  }
  return unmet;
}

}  // namespace

PartitionSummary GenerateLayout(const PartitionOptions& options, uint64_t seed) {
  PartitionSummary summary;
  std::string message;
  if (!options.IsValid(&message)) {
    summary.outcome = PartitionOutcome::kFailure;
    summary.message = "invalid options: " + message;
    return summary;
  }
  const Sizes sizes = MakeSizes(options.grid);
  // Floors and footprint class come from the seed once: retries keep them, so the dataset's mix of
  // classes follows the weights and not how often each class needs a retry.
  PartitionOptions fixed = options;
  {
    Rng pick(partition::MixSeed(seed, 0xF100D5C1A55ull));
    if (fixed.floors == 0) fixed.floors = 1 + pick.Weighted(fixed.floor_weights, 3);
    if (!fixed.shape)
      fixed.shape = AllShapeClasses()[static_cast<std::size_t>(pick.Weighted(fixed.shape_weights, kShapeClassCount))];
  }
  std::map<std::string, int> reasons;
  std::optional<PartitionSummary> best;
  for (int attempt = 0; attempt < options.max_attempts; ++attempt) {
    Rng rng(partition::MixSeed(seed, static_cast<uint64_t>(attempt)));
    const Plan plan = MakePlan(fixed, rng);
    AttemptResult a = Attempt(fixed, plan, sizes, rng, attempt < std::max(1, options.max_attempts / 8));
    if (!a.ok) {
      ++reasons[a.reason];
      continue;
    }
    Layout layout = BuildLayout(a.building, options.grid);
    // The class is what the one classifier reads from the outline: an irregular cut that happens to be a
    // 45-degree chamfer reads as the corner it cuts, so an irregular outline is read back (the other classes
    // are theirs by construction, chamfers included; the layout test reads every class back).
    if (plan.shape == ShapeClass::kIrregular && ClassifyFootprint(layout, 0) != plan.shape) {
      ++reasons["footprint reads as another class"];
      continue;
    }
    if (options.validate) {
      const ValidationReport report = ValidateLayout(layout);
      if (!report.valid()) {
        ++reasons["validation: rule " + std::to_string(report.violations.front().rule)];
        continue;
      }
    }
    std::vector<std::string> unmet = UnmetRequirements(fixed, plan, a.building);
    PartitionSummary candidate;
    candidate.layout = std::move(layout);
    candidate.shape = plan.shape;
    candidate.floors = plan.floors;
    candidate.retries = attempt;
    candidate.angled_edges = partition::HasAngledEdge(a.building.floors[0].footprint);
    candidate.unmet_requirements = std::move(unmet);
    candidate.outcome =
        candidate.unmet_requirements.empty() ? PartitionOutcome::kSuccess : PartitionOutcome::kUnmetRequirements;
    const bool better = !best || candidate.unmet_requirements.size() < best->unmet_requirements.size();
    if (better) best = std::move(candidate);
    // Requirements that no plan can meet do not improve with more attempts.
    if (static_cast<int>(best->unmet_requirements.size()) <= plan.impossible()) break;
    if (attempt >= options.max_attempts / 4) break;  // good enough: keep the best valid layout so far
  }
  std::vector<std::pair<int, std::string>> sorted;
  for (const auto& [reason, n] : reasons) sorted.push_back({-n, reason});
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::string> reason_lines;
  for (const auto& [n, reason] : sorted) reason_lines.push_back(reason + ": " + std::to_string(-n));
  if (!best) {
    summary.outcome = PartitionOutcome::kFailure;
    summary.retries = options.max_attempts;
    summary.message = "no valid layout in " + std::to_string(options.max_attempts) + " attempts" +
                      (reason_lines.empty() ? "" : " (most often: " + reason_lines.front() + ")");
    summary.retry_reasons = std::move(reason_lines);
    return summary;
  }
  best->retry_reasons = std::move(reason_lines);
  return std::move(*best);
}

uint64_t DatasetLayoutSeed(uint64_t dataset_seed, uint64_t index) {
  return partition::MixSeed(dataset_seed ^ 0x5A17A5EEDull, index);
}

std::vector<int> DatasetFloorPlan(uint64_t count, const double weights[3]) {
  // Exact totals by largest remainder (ties: fewer floors first), then an interleaving: position i goes
  // to the class furthest behind its share target * (i + 1) / count, compared in exact integers so every
  // platform gives the same sequence.
  const double total = weights[0] + weights[1] + weights[2];
  if (!(total > 0.0)) return std::vector<int>(count, 1);
  std::array<uint64_t, 3> target{0, 0, 0};
  std::array<double, 3> rem{};
  uint64_t assigned = 0;
  for (int f = 0; f < 3; ++f) {
    const double exact = static_cast<double>(count) * weights[f] / total;
    target[f] = static_cast<uint64_t>(std::floor(exact));
    rem[f] = exact - static_cast<double>(target[f]);
    assigned += target[f];
  }
  while (assigned > count) {  // rounding of huge counts: take back from the largest class
    int f = static_cast<int>(std::max_element(target.begin(), target.end()) - target.begin());
    --target[f];
    --assigned;
  }
  while (assigned < count) {
    int best = 0;
    for (int f = 1; f < 3; ++f)
      if (rem[f] > rem[best]) best = f;
    ++target[best];
    rem[best] = -1.0;
    ++assigned;
  }
  std::vector<int> plan;
  plan.reserve(count);
  std::array<uint64_t, 3> made{0, 0, 0};
  for (uint64_t i = 0; i < count; ++i) {
    int best = -1;
    __int128 best_deficit = 0;
    for (int f = 0; f < 3; ++f) {
      if (made[f] >= target[f]) continue;
      // deficit * count = target * (i + 1) - made * count
      const __int128 deficit = static_cast<__int128>(target[f]) * static_cast<__int128>(i + 1) -
                               static_cast<__int128>(made[f]) * static_cast<__int128>(count);
      if (best < 0 || deficit > best_deficit) best = f, best_deficit = deficit;
    }
    ++made[static_cast<std::size_t>(best)];
    plan.push_back(best + 1);
  }
  return plan;
}

}  // namespace villa
