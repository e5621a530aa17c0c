#include "scene/planner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "assets/category.h"
#include "mesh/geometry2d.h"
#include "scene/bathroom_fit.h"
#include "scene/priors.h"
#include "scene/random.h"
#include "scene/request.h"
#include "util/text_table.h"

namespace villa::scene {
namespace {

constexpr double kStandardSill = 0.9;      // m: against a wall under a window stands only what is lower
constexpr double kWallGap = 0.05;           // m left beside each object against a wall
constexpr double kOnWallShare = 0.7;       // share of the free wall (not over windows) hung objects may take
constexpr double kRugShare = 0.5;          // rugs cover at most half the furnishable floor
constexpr double kSurfaceShare = 0.8;      // share of a parent's top small objects may cover
constexpr double kDoubleBedWidth = 1.4;    // m: the narrowest bed planned unless no wider one fits (BedFits)
constexpr double kTinyFootprint = 0.1;     // m2: slippers, a bin: they fit in what the floor share leaves

// The parents a small object goes to when the room's priors do not say (a TV asked for in a bedroom).
std::vector<ParentChoice> DefaultParents(std::string_view category) {
  using R = Relation;
  struct Entry {
    std::string_view category;
    std::vector<ParentChoice> parents;
  };
  static const std::vector<Entry> kTable = {
      {"tv", {{"tv-stand", R::kOnTop}, {"dresser", R::kOnTop}, {"sideboard", R::kOnTop}}},
      {"monitor", {{"desk", R::kOnTop}}},
      {"laptop", {{"desk", R::kOnTop}, {"conference-table", R::kOnTop}, {"dining-table", R::kOnTop}}},
      {"printer", {{"desk", R::kOnTop}, {"filing-cabinet", R::kOnTop}}},
      {"books", {{"bookcase", R::kInside}, {"nightstand", R::kOnTop}, {"desk", R::kOnTop}, {"coffee-table", R::kOnTop}}},
      {"table-lamp", {{"nightstand", R::kOnTop}, {"side-table", R::kOnTop}, {"desk", R::kOnTop}, {"dresser", R::kOnTop}}},
      {"pillow", {{"sofa", R::kOnTop}, {"bed", R::kOnTop}, {"child-bed", R::kOnTop}}},
      {"folded-clothes", {{"wardrobe", R::kInside}, {"dresser", R::kInside}, {"cabinet", R::kInside}}},
      {"hanging-clothes", {{"wardrobe", R::kInside}}},
      {"toy", {{"toy-chest", R::kInside}, {"bookcase", R::kInside}, {"play-table", R::kOnTop}}},
      {"plate", {{"dining-table", R::kOnTop}, {"upper-cabinet", R::kInside}, {"sideboard", R::kInside}}},
      {"glass", {{"dining-table", R::kOnTop}, {"upper-cabinet", R::kInside}, {"sideboard", R::kInside}}},
      {"remote", {{"coffee-table", R::kOnTop}, {"side-table", R::kOnTop}}},
      {"alarm-clock", {{"nightstand", R::kOnTop}}},
      {"sink", {{"counter", R::kOnTop}}},
      {"pan", {{"cooker", R::kOnTop}, {"counter", R::kOnTop}}},
  };
  for (const Entry& e : kTable)
    if (e.category == category) return e.parents;
  // Anything else small: the usual surfaces, in this order.
  return {{"coffee-table", R::kOnTop}, {"side-table", R::kOnTop}, {"sideboard", R::kOnTop}, {"dresser", R::kOnTop},
          {"desk", R::kOnTop},         {"dining-table", R::kOnTop}, {"counter", R::kOnTop}, {"nightstand", R::kOnTop},
          {"bookcase", R::kOnTop},     {"outdoor-table", R::kOnTop}, {"washbasin", R::kOnTop}, {"cabinet", R::kOnTop}};
}

Mount DefaultMount(const CategoryInfo& c) {
  switch (c.placement) {
    case Placement::kFloor: return c.against_wall ? Mount::kWall : Mount::kFloor;
    case Placement::kWall: return Mount::kOnWall;
    case Placement::kCeiling: return Mount::kCeiling;
    case Placement::kSurface: return Mount::kParent;
  }
  return Mount::kFloor;
}

bool IsRug(const CategoryInfo& c) { return c.name == "rug"; }

// A kitchen's run: fridge, counters, cooker and dishwasher, chained next_to one after the other (priors.cpp),
// so together they must fit one straight free stretch of wall (or the chain cannot hold).
bool InKitchenRun(const CategoryInfo& c) {
  return c.name == "counter" || c.name == "fridge" || c.name == "cooker" || c.name == "dishwasher";
}

// Furniture that also works away from the walls (a sofa's back to the room, an island desk) when no wall
// stretch is long enough; storage and appliances do not.
bool MayStandFree(const CategoryInfo& c) {
  return c.name == "sofa" || c.name == "desk" || c.name == "bed" || c.name == "child-bed";
}

double Round2(double v) { return std::round(v * 100.0) / 100.0; }

// A free stretch of wall objects may stand against; `under_window` stretches take only low objects.
struct Stretch {
  double left = 0.0;  // m still free
  bool under_window = false;
};

struct Node {
  const CategoryInfo* info = nullptr;
  const ItemPrior* item = nullptr;  // the prior item it comes from or stands for (may be null)
  Origin origin = Origin::kPrior;
  Mount mount = Mount::kFloor;
  int parent = -1;                  // node index, -1 for floor / wall / ceiling
  Relation relation = Relation::kOnTop;
  Vec3 size;
  std::vector<std::string> hints;
  int wish = -1;
  bool removed = false;
  // What it took from the room's budgets (given back when trimmed).
  double floor_taken = 0.0;  // m2 of the priors' floor share
  double extra_taken = 0.0;  // m2 of the extra share (requests, key furniture)
  double rug_taken = 0.0;
  double onwall_taken = 0.0;
  int stretch = -1;
  double stretch_taken = 0.0;
  double run_taken = 0.0;  // m of the kitchen run (kitchens only)
};

class Planning {
 public:
  Planning(const RoomContext& room, const std::string& text, uint64_t seed, const PlannerOptions& options)
      : room_(room), text_(text), options_(options), priors_(PriorsFor(room.category)),
        rng_(seed ^ (NameHash(room.name) * kSplitMix64Gamma)) {
    const double area = room_.furnishable_area;
    floor_left_ = options_.floor_share * area;
    prompt_extra_ = std::max(0.0, options_.prompt_floor_share - options_.floor_share) * area;
    rug_left_ = kRugShare * area;
    double wall_free = 0.0;
    for (const WallEdge& w : room_.walls) {
      for (const Interval& f : w.free) {
        // Split each free stretch at the windows on it: under a window only low objects stand.
        std::vector<std::pair<double, bool>> cuts = {{f.first, false}};
        for (const WallWindow& win : w.windows) {
          double a = std::max(f.first, win.span.first), b = std::min(f.second, win.span.second);
          if (b > a) cuts.push_back({a, true}), cuts.push_back({b, false});
        }
        std::sort(cuts.begin(), cuts.end());
        for (size_t i = 0; i < cuts.size(); ++i) {
          double end = i + 1 < cuts.size() ? cuts[i + 1].first : f.second;
          if (end - cuts[i].first <= 0.2) continue;
          stretches_.push_back({end - cuts[i].first, cuts[i].second});
          if (!cuts[i].second) wall_free += end - cuts[i].first;
        }
      }
    }
    onwall_left_ = kOnWallShare * wall_free;
    if (room_.category == Category::kKitchen) {
      // A straight run where the smallest one (two counters, a fridge, a cooker) fits along one wall (the
      // critic lays a straight run out again as a whole), else an L round a corner; where not even that
      // fits, the run is not limited: the kitchen keeps its things, the chain is left to the solver.
      double smallest = 0.0;
      for (std::string_view c : {"counter", "counter", "fridge", "cooker"})
        if (const CategoryInfo* info = FindCategory(c)) smallest += info->size_min.x + kWallGap;
      // Walls without their windows first (RunStretches: what a run carries rises above a sill); where
      // even the L does not fit so, with the windows, as before (the critic keeps what it can below them).
      for (bool windows : {false, true}) {
        run_left_ = LongestRun(false, windows);
        if (run_left_ < smallest) run_left_ = LongestRun(true, windows);
        if (run_left_ >= smallest) break;
      }
      run_limited_ = run_left_ >= smallest;
    }
    // Sizes lean small in small rooms and large in large ones.
    double s = priors_.usual_area > 0 ? area / priors_.usual_area : 1.0;
    size_factor_ = std::clamp(0.2 + 0.3 * s, 0.1, 0.65);
    clear_width_ = ClearWidth();
  }

  // The width of the room where it is narrowest for what stands in it: twice the radius of the largest disc
  // on the free floor that keeps out of the doors' sweeps and strips and the open passages (a 2.5 m wide bedroom
  // walked through from door to door is about 2.3 m wide; an L of 2 m strips is 2 m wide). Sampled on a
  // 0.1 m grid.
  double ClearWidth() const {
    std::vector<const Ring*> out;
    for (const KeepOut& k : room_.keep_outs)
      if (k.kind == KeepOutKind::kDoorSweep || k.kind == KeepOutKind::kDoorStrip || k.kind == KeepOutKind::kOpenPassage)
        out.push_back(&k.polygon);
    double best = 0.0;
    for (const Ring& ring : room_.free_floor) {
      double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
      for (const Point& p : ring) x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
      for (double x = x0 + 0.05; x < x1; x += 0.1)
        for (double y = y0 + 0.05; y < y1; y += 0.1) {
          const Point p{x, y};
          if (!PointInRing(p, ring, 0.0)) continue;
          double r = DistanceToBoundary(p, ring);
          for (const Ring* k : out) {
            if (r <= best) break;
            r = PointInRing(p, *k, 0.0) ? 0.0 : std::min(r, DistanceToBoundary(p, *k));
          }
          best = std::max(best, r);
        }
    }
    return 2.0 * best;
  }

  // The longest run of wall a kitchen's chain may stand along: one free interval of a wall, or with
  // `corner` an L of two intervals meeting in a corner, less the corner a counter's depth takes; with
  // `windows` the stretches under windows count (the low members stand there), else they end the intervals.
  // 0 when the room has no free wall.
  double LongestRun(bool corner, bool windows) const {
    constexpr double kCornerTaken = 0.65;  // m: a counter's depth, the corner's share of the second wall
    double best = 0.0;
    std::vector<std::vector<Interval>> free;
    for (const WallEdge& w : room_.walls) free.push_back(windows ? w.free : RunStretches(w));
    for (const std::vector<Interval>& f : free)
      for (const Interval& i : f) best = std::max(best, i.second - i.first);
    for (size_t a = 0; a < room_.walls.size(); ++a) {
      const WallEdge& wa = room_.walls[a];
      if (!corner || free[a].empty() || free[a].back().second < wa.length() - 0.01) continue;
      for (size_t b = 0; b < room_.walls.size(); ++b) {
        const WallEdge& wb = room_.walls[b];
        if (a == b || free[b].empty() || free[b].front().first > 0.01 || Distance(wa.inner.b, wb.inner.a) > 0.05) continue;
        const double l = (free[a].back().second - free[a].back().first) + (free[b].front().second - free[b].front().first) - kCornerTaken;
        best = std::max(best, l);
      }
    }
    return best;
  }

  // Where a kitchen's run may stand along wall w: its free stretches less its windows. Under a window only
  // what is lower than the sill may stand, and a run is not: the fridge is tall, and the kettle on a
  // counter, the pan on the cooker and the sink rise above a counter-height sill.
  static std::vector<Interval> RunStretches(const WallEdge& w) {
    std::vector<Interval> out;
    for (const Interval& f : w.free) {
      std::vector<Interval> pieces{f};
      for (const WallWindow& win : w.windows) {
        std::vector<Interval> cut;
        for (const Interval& p : pieces) {
          if (win.span.second <= p.first || win.span.first >= p.second) {
            cut.push_back(p);
            continue;
          }
          if (win.span.first > p.first) cut.push_back({p.first, win.span.first});
          if (win.span.second < p.second) cut.push_back({win.span.second, p.second});
        }
        pieces = std::move(cut);
      }
      for (const Interval& p : pieces)
        if (p.second - p.first > 0.01) out.push_back(p);
    }
    return out;
  }

  RoomPlan Run() {
    RoomRequest request = ParseRoomRequest(text_, room_.category, room_.ordinal);
    for (const std::string& other : request.other_rooms) notes_.push_back("the request gives " + other + " another room");
    for (const Wish& w : request.wishes)
      if (w.count == 0) excluded_.insert(std::string(w.category->name));
      else named_.insert(std::string(w.category->name));
    // "Both children's rooms: 1 bed and 1 desk each": the bed asked for is the room's child's bed (Wishes),
    // not one more beside it.
    if (room_.category == Category::kChildrenRoom && named_.count("bed")) named_.insert("child-bed");
    Targets();
    Wishes(request);
    for (bool small : {false, true}) {
      Mandatory(small);
      Draw(small);
    }
    Settings();
    Grow();
    CompleteGroups();
    Settings();  // the place settings follow the seats CompleteGroups added
    Trim();
    if (room_.category == Category::kBedroom) BedFits();  // a narrower bed leaves floor: nothing is added for it
    if (room_.category == Category::kBathroom && BathroomFixtures()) {
      Grow();  // what the fixtures left: towel racks, bottles on the basin instead of the cabinet's things
      Trim();
    }
    return Finish(request);
  }

 private:
  // ---- counts aimed at
  void Targets() {
    if (IsRichRoomType(room_.category) && room_.area >= options_.rich_min_area) {
      lo_ = options_.rich_min_objects;
      hi_ = options_.rich_max_objects;
    } else {
      double s = priors_.usual_area > 0 ? std::clamp(room_.furnishable_area / priors_.usual_area, 0.3, 1.0) : 1.0;
      int base = IsRichRoomType(room_.category) ? (options_.rich_min_objects + options_.rich_max_objects) / 2 : priors_.no_target;
      lo_ = std::max(1, static_cast<int>(std::lround(0.8 * base * s)));
      hi_ = std::max(lo_, static_cast<int>(std::lround(1.2 * base * s)));
    }
    target_ = rng_.Int(lo_, hi_);
  }

  // ---- budgets
  // `seats`: the people a table the request sizes is to seat (0: none asked).
  Vec3 SizeOf(const CategoryInfo& c, int seats = 0) {
    double f = std::clamp(size_factor_ + 0.2 * (rng_.Unit() - 0.5), 0.0, 1.0);
    auto pick = [&](double lo, double hi) { return Round2(lo + f * (hi - lo)); };
    // A bed's range runs from a single to a king; it is planned a double or wider (BedFits narrows it).
    const double usual_min_x = c.name == "bed" ? std::max(c.size_min.x, kDoubleBedWidth) : c.size_min.x;
    Vec3 size{pick(usual_min_x, c.size_max.x), pick(c.size_min.y, c.size_max.y), pick(c.size_min.z, c.size_max.z)};
    // Issue 27: a narrow room gets the narrower pieces of the range, so that its essentials keep their
    // clearances: a bed a free long side of 0.6 m, a table a row of chairs with 0.75 m behind them (chair
    // 0.5 m, a 0.1 m gap) along its free side.
    // A table the request sizes for its people: one seat every 0.6 m of a long side, one at each end of a
    // table 1.5 m long or more (SeatCap's template), within the category's range.
    if (seats > 0 && (c.name == "dining-table" || c.name == "conference-table")) {
      const int n = seats;
      double length = n <= 4 ? 0.6 * ((n + 1) / 2) : std::max(1.5, 0.6 * ((n - 1) / 2));
      double across = 1e9;  // the room's shorter direction
      if (!room_.free_floor.empty()) {  // 0.8 m to spare at each end in the room's longer direction
        const Box2 box = BoundingBox(room_.free_floor.front());
        length = std::min(length, std::max(box.max_x - box.min_x, box.max_y - box.min_y) - 1.6);
        across = std::min(box.max_x - box.min_x, box.max_y - box.min_y);
      }
      size.x = std::clamp(Round2(length), c.size_min.x, c.size_max.x);
      // Both long sides seated where the room is wide enough (a chair and 1.3 m on each), and 0.9 m wide
      // for its ends where that allows.
      const double fit = Round2(across - 2.0 * 1.3 - 0.01);
      if (n > 4 && fit >= c.size_min.y) size.y = std::clamp(std::max(size.y, 0.9), c.size_min.y, std::min(c.size_max.y, fit));
    }
    auto cap = [&](double& v, double lo, double limit) { v = std::max(lo, std::min(v, Round2(limit))); };
    if (clear_width_ > 0.0) {
      if (c.name == "bed" || c.name == "child-bed") cap(size.x, usual_min_x, clear_width_ - 0.65);
      if (c.name == "dining-table" || c.name == "conference-table") cap(size.y, c.size_min.y, clear_width_ - 1.4);
    }
    return size;
  }

  // Takes what a root object (on the floor, a wall or the ceiling) needs from the room; false (nothing
  // taken) when it does not fit.
  bool TakeRoom(Node& n, bool prompt) {
    const double footprint = n.size.x * n.size.y;
    switch (n.mount) {
      case Mount::kCeiling: return true;
      case Mount::kOnWall:
        if (n.size.x > onwall_left_) return false;
        onwall_left_ -= n.size.x;
        n.onwall_taken = n.size.x;
        return true;
      case Mount::kFloor:
        if (IsRug(*n.info)) {
          if (footprint > rug_left_) return false;
          rug_left_ -= footprint;
          n.rug_taken = footprint;
          return true;
        }
        return TakeFloor(n, footprint, prompt);
      case Mount::kWall: {
        // Best fit: the fullest stretch that still holds its width; tall objects not under windows.
        bool tall = n.size.z > kStandardSill;
        int best = -1, longest = -1;
        for (int i = 0; i < static_cast<int>(stretches_.size()); ++i) {
          const Stretch& s = stretches_[i];
          if (tall && s.under_window) continue;
          if (longest < 0 || s.left > stretches_[longest].left) longest = i;
          if (s.left < n.size.x + kWallGap) continue;
          if (best < 0 || s.left < stretches_[best].left) best = i;
        }
        // Too wide for every stretch: a narrower one of its kind, down to the category's smallest (a bed to a
        // double's width: narrower only where BedFits finds no double clear of the doors).
        const double narrowest = n.info->name == "bed" ? std::max(n.info->size_min.x, kDoubleBedWidth) : n.info->size_min.x;
        if (best < 0 && longest >= 0 && stretches_[longest].left - kWallGap >= narrowest) {
          n.size.x = Round2(std::floor((stretches_[longest].left - kWallGap) * 100.0) / 100.0);
          best = longest;
        }
        if (best < 0) {
          // No wall for it: a sofa, bed or desk may stand free in the room instead.
          if (!MayStandFree(*n.info)) return false;
          n.mount = Mount::kFloor;
          return TakeFloor(n, footprint, prompt);
        }
        if (!TakeFloor(n, n.size.x * n.size.y, prompt)) return false;
        stretches_[best].left -= n.size.x + kWallGap;
        n.stretch = best;
        n.stretch_taken = n.size.x + kWallGap;
        return true;
      }
      case Mount::kParent: return false;
    }
    return false;
  }

  // Floor for a footprint: the priors' share, and for the request's objects and the room's key furniture
  // the extra share on top. Key furniture takes the extra first, so the priors keep their share for the rest.
  bool TakeFloor(Node& n, double footprint, bool prompt) {
    if (footprint < kTinyFootprint) return true;
    const bool key = n.origin == Origin::kPrior && n.item && n.item->key && CountOf(n.item) < n.item->min;
    double room = floor_left_ + (prompt || key ? prompt_extra_ : 0.0);
    if (footprint > room) return false;
    double from_extra = key ? std::min(footprint, prompt_extra_) : std::max(0.0, footprint - floor_left_);
    floor_left_ -= footprint - from_extra;
    prompt_extra_ -= from_extra;
    n.floor_taken = footprint - from_extra;
    n.extra_taken = from_extra;
    return true;
  }

  void GiveBack(const Node& n) {
    run_left_ += n.run_taken;
    floor_left_ += n.floor_taken;
    prompt_extra_ += n.extra_taken;
    rug_left_ += n.rug_taken;
    onwall_left_ += n.onwall_taken;
    if (n.stretch >= 0) stretches_[n.stretch].left += n.stretch_taken;
  }

  // ---- parents
  int ChildrenOf(int parent, std::string_view category) const {
    int k = 0;
    for (const Node& n : nodes_)
      if (!n.removed && n.parent == parent && n.info->name == category) ++k;
    return k;
  }
  double TopUsed(int parent) const {
    double a = 0.0;
    for (const Node& n : nodes_)
      if (!n.removed && n.parent == parent && n.relation == Relation::kOnTop) a += n.size.x * n.size.y;
    return a;
  }
  // Seats planned around a table: objects whose item needs that table.
  int SeatsOf(int parent) const {
    int k = 0;
    for (const Node& n : nodes_)
      if (!n.removed && n.item && n.item->requires_category == nodes_[parent].info->name) ++k;
    return k;
  }

  bool ParentHolds(int parent, const CategoryInfo& child, const Vec3& size, Relation relation, const ItemPrior* item) const {
    const Node& p = nodes_[parent];
    if (p.removed || !(p.info->affordances & kProvider)) return false;
    if (relation == Relation::kInside ? !p.info->has_cavity : !p.info->has_surface) return false;
    int limit = options_.max_per_receptacle;
    if (item && item->per_parent < limit) limit = item->per_parent;
    if (item && item->per_seat) limit = std::max(1, SeatsOf(parent));
    if (relation == Relation::kInside) limit *= CompartmentsOf(p.info->name);
    if (ChildrenOf(parent, child.name) >= limit) return false;
    if (relation == Relation::kOnTop && TopUsed(parent) + size.x * size.y > kSurfaceShare * p.size.x * p.size.y) return false;
    return true;
  }

  // The parent for a small object: the first choice with room left, the emptier instance first.
  int FindParent(const std::vector<ParentChoice>& choices, const CategoryInfo& child, const Vec3& size,
                 const ItemPrior* item, Relation* relation) const {
    for (const ParentChoice& choice : choices) {
      int best = -1, best_load = 0;
      for (int i = 0; i < static_cast<int>(nodes_.size()); ++i) {
        if (nodes_[i].info->name != choice.category || !ParentHolds(i, child, size, choice.relation, item)) continue;
        int load = ChildrenOf(i, child.name);
        if (best < 0 || load < best_load) best = i, best_load = load;
      }
      if (best >= 0) {
        *relation = choice.relation;
        return best;
      }
    }
    return -1;
  }

  const ItemPrior* ItemFor(std::string_view category, std::string_view parent_category = {}) const {
    const ItemPrior* first = nullptr;
    for (const ItemPrior& item : priors_.items) {
      if (item.category != category) continue;
      if (!first) first = &item;
      if (parent_category.empty()) return first;
      for (const ParentChoice& p : item.parents)
        if (p.category == parent_category) return &item;
    }
    return first;
  }

  int CountOf(const ItemPrior* item) const {
    int k = 0;
    for (const Node& n : nodes_)
      if (!n.removed && n.item == item) ++k;
    return k;
  }
  int CountOfCategory(std::string_view category) const {
    int k = 0;
    for (const Node& n : nodes_)
      if (!n.removed && n.info->name == category) ++k;
    return k;
  }
  int Total() const {
    int k = 0;
    for (const Node& n : nodes_) k += !n.removed;
    return k;
  }

  // ---- adding
  // Adds one object; for small ones finds (or, when `make_parent`, plans) a parent; `seats` sizes a table for
  // that many people (SizeOf). The index, or -1.
  int Add(const CategoryInfo& info, const ItemPrior* item, Origin origin, int wish, int parent, Relation relation,
          bool make_parent, int seats = 0) {
    Node n;
    n.info = &info;
    n.item = item;
    n.origin = origin;
    n.wish = wish;
    n.mount = item ? item->mount : DefaultMount(info);
    if (parent >= 0) n.mount = Mount::kParent;
    if (n.mount == Mount::kWall && info.name == "sofa" && room_.category == Category::kLivingRoom && SofaFloats())
      n.mount = Mount::kFloor;
    n.size = SizeOf(info, seats);
    if (item) n.hints.assign(item->hints.begin(), item->hints.end());
    const bool prompt = origin == Origin::kPrompt;
    if (n.mount == Mount::kParent) {
      if (parent >= 0) {
        if (!ParentHolds(parent, info, n.size, relation, item)) return -1;
        n.parent = parent;
        n.relation = relation;
      } else {
        std::vector<ParentChoice> choices = item && !item->parents.empty() ? item->parents : DefaultParents(info.name);
        n.parent = FindParent(choices, info, n.size, item, &n.relation);
        if (n.parent < 0 && make_parent) {
          // Plan the first choice of parent that fits the room, then try again.
          for (const ParentChoice& c : choices) {
            const CategoryInfo* pc = FindCategory(c.category);
            if (!pc || excluded_.count(std::string(c.category))) continue;
            if (Add(*pc, ItemFor(c.category), Origin::kPrior, -1, -1, Relation::kOnTop, false) >= 0) break;
          }
          n.parent = FindParent(choices, info, n.size, item, &n.relation);
        }
        if (n.parent < 0) return -1;
      }
      // Pillows lie side by side at a double bed's head: each at most half the bed's width (at the smallest scale
      // the solver may give the bed) less a hand's breadth, else the second lies mid-bed (issue 27).
      const Node& carrier = nodes_[n.parent];
      if (info.name == "pillow" && carrier.info->name == "bed" && carrier.size.x >= 1.2)
        n.size.x = std::max(info.size_min.x, Round2(std::min(n.size.x, 0.5 * (0.8 * carrier.size.x - 0.15))));
      nodes_.push_back(n);
      return static_cast<int>(nodes_.size()) - 1;
    }
    const bool run = run_limited_ && n.mount == Mount::kWall && InKitchenRun(info);
    if (run && !FitRun(n)) return -1;
    if (!TakeRoom(n, prompt)) return -1;  // may turn a wall object free-standing
    if (run) {
      run_left_ -= n.size.x + kWallGap;
      n.run_taken = n.size.x + kWallGap;
    }
    n.relation = n.mount == Mount::kWall ? Relation::kAgainstWall
                 : n.mount == Mount::kOnWall ? Relation::kOnWall
                 : n.mount == Mount::kCeiling ? Relation::kHanging : Relation::kOnTop;
    nodes_.push_back(n);
    return static_cast<int>(nodes_.size()) - 1;
  }

  // Narrows a member of the kitchen run to what the run has left after the members it still needs (a
  // fridge, a cooker, two counters); false when even its smallest does not fit. The counters of a room
  // share one asset (scene/acquire.cpp: one per category, parent and relation), so they share the first
  // one's width: the first takes an equal share of what the two need.
  bool FitRun(Node& n) {
    double reserve = 0.0;
    for (std::string_view category : {"fridge", "cooker"}) {
      const CategoryInfo* c = FindCategory(category);
      if (c && n.info->name != category && CountOfCategory(category) == 0 && !excluded_.count(std::string(category)))
        reserve += c->size_min.x + kWallGap;
    }
    double room = run_left_ - reserve;
    if (n.info->name == "counter") {
      for (const Node& other : nodes_)
        if (!other.removed && other.info == n.info) {
          if (room < other.size.x + kWallGap - 1e-9) return false;
          n.size.x = other.size.x;
          return true;
        }
      room = 0.5 * room;  // this counter and the second one of the priors' minimum
    } else if (const CategoryInfo* counter = FindCategory("counter"); counter && CountOfCategory("counter") < 2) {
      // Counters come first in the priors; a request's fridge or cooker may come before them.
      room -= (2 - CountOfCategory("counter")) * (counter->size_min.x + kWallGap);
    }
    room -= kWallGap;
    if (room < n.info->size_min.x - 1e-9) return false;
    n.size.x = std::min(n.size.x, std::floor(room * 100.0) / 100.0);
    return true;
  }

  // Whether the priors may add one more of `item` now.
  bool Allowed(const ItemPrior& item) const {
    std::string category(item.category);
    if (excluded_.count(category) || named_.count(category)) return false;
    if (item.condition == Condition::kNoDiningRoomOnLevel &&
        std::count(room_.level_categories.begin(), room_.level_categories.end(), Category::kDiningRoom) > 0)
      return false;
    if (!item.requires_category.empty() && CountOfCategory(item.requires_category) == 0) return false;
    if (item.min_area > room_.furnishable_area) return false;
    if (!item.group.empty())
      for (const ItemPrior& other : priors_.items)
        if (&other != &item && other.group == item.group && CountOf(&other) > 0) return false;
    return true;
  }

  // The count an item is planned at least: its minimum, and one in a room big enough for its zone.
  int MinOf(const ItemPrior& item) const {
    const bool zone = item.from_area > 0.0 && room_.furnishable_area >= item.from_area;
    return std::max(item.min, zone ? 1 : 0);
  }

  int MaxOf(const ItemPrior& item) const {
    int max = item.max;
    if (item.mount == Mount::kCeiling) max = std::clamp(1 + static_cast<int>(room_.furnishable_area / 20.0), 1, item.max);
    return std::min(max, SeatCap(item));
  }

  // Issue 27: the chairs of a table are as many as its sides seat with room to pull them out (the template
  // of solver/place.cpp: one every 0.6 m along a long side, one at each end of a table 1.5 m long and 0.7 m
  // wide, 0.75 m clear behind each chair): across the room's free floor, a long side seats when the floor is
  // wide enough for the table, a chair and 0.75 m behind it on that side; an end likewise along the table.
  // Unlimited for what is not a table's seat.
  int SeatCap(const ItemPrior& item) const {
    const std::string_view table = item.requires_category;
    if (table != "dining-table" && table != "conference-table" && table != "play-table" && table != "outdoor-table")
      return std::numeric_limits<int>::max();
    int node = -1;
    for (int i = 0; i < static_cast<int>(nodes_.size()); ++i)
      if (!nodes_[i].removed && nodes_[i].info->name == table) node = i;
    if (node < 0 || room_.free_floor.empty()) return std::numeric_limits<int>::max();
    const Vec3& t = nodes_[node].size;
    const double L = std::max(t.x, t.y), S = std::min(t.x, t.y);
    const Box2 box = BoundingBox(room_.free_floor.front());
    const double D = std::min(box.max_x - box.min_x, box.max_y - box.min_y), E = std::max(box.max_x - box.min_x, box.max_y - box.min_y);
    const double seat = 0.05 + 0.5 + 0.75;  // gap, chair depth, clear behind
    const int along = std::max(1, static_cast<int>(std::floor(L / 0.6 + 1e-9)));
    const int sides = D >= S + 2.0 * seat ? 2 : D >= S + seat ? 1 : 0;
    const int ends = L >= 1.5 && S >= 0.7 ? (E >= L + 2.0 * seat ? 2 : E >= L + seat ? 1 : 0) : 0;
    return std::max(2, sides * along + ends);
  }

  bool AddPrior(const ItemPrior& item) {
    const CategoryInfo* info = FindCategory(item.category);
    if (!info || !Allowed(item) || CountOf(&item) >= MaxOf(item)) return false;
    return Add(*info, &item, Origin::kPrior, -1, -1, Relation::kOnTop, false) >= 0;
  }

  // Whether a living room's sofa stands free (its back to the room, facing the TV on its wall): the TV
  // stand is 2-3 m in front of the sofa (priors.cpp), so with both against opposite walls these must be
  // 3.4-4.4 m apart (sofa and stand depths and their wall gaps included) and hold free stretches facing each
  // other, room for the sofa on one and the stand across from it on the other (doors, passages and stair
  // keep-outs take wall; a sofa stands under a window, the stand does not: the TV on it rises above the
  // sill). Where no two walls do and the room is
  // longer than that one way, the sofa floats, as a designer would.
  bool SofaFloats() const {
    constexpr double kAcrossMin = 3.4, kAcrossMax = 4.4;  // m wall to wall
    constexpr double kSofa = 2.1, kStand = 1.4;           // m of free wall each needs (the narrowest assets, about)
    if (room_.free_floor.empty()) return false;
    const Box2 box = BoundingBox(room_.free_floor.front());
    if (std::max(box.max_x - box.min_x, box.max_y - box.min_y) <= kAcrossMax) return false;
    for (const WallEdge& a : room_.walls) {
      const Point da = geo::Unit(geo::Sub(a.inner.b, a.inner.a));
      for (const WallEdge& b : room_.walls) {
        const Point db = geo::Unit(geo::Sub(b.inner.b, b.inner.a));
        if (&a == &b || geo::Dot(da, db) > -0.99) continue;
        const double across = geo::Dot(geo::Sub(b.inner.a, a.inner.a), geo::Left(da));
        if (across < kAcrossMin || across > kAcrossMax) continue;
        for (const Interval& fa : a.free) {
          if (fa.second - fa.first < kSofa) continue;
          for (const Interval& fb : RunStretches(b)) {
            if (fb.second - fb.first < kStand) continue;
            // b's stretch seen along a (b runs the other way).
            const double b0 = geo::Dot(geo::Sub(geo::Add(b.inner.a, geo::Scale(db, fb.second)), a.inner.a), da);
            const double b1 = geo::Dot(geo::Sub(geo::Add(b.inner.a, geo::Scale(db, fb.first)), a.inner.a), da);
            if (std::min(fa.second, b1) - std::max(fa.first, b0) >= kStand) return false;
          }
        }
      }
    }
    return true;
  }

  // ---- the steps
  void Wishes(const RoomRequest& request) {
    std::vector<std::vector<int>> made(request.wishes.size());
    // Containers first, so "bookshelves full of books" has its bookcases before its books.
    // (A table sized for its people before its chairs, which it caps.)
    std::vector<int> order;
    for (int pass = 0; pass < 3; ++pass)
      for (int w = 0; w < static_cast<int>(request.wishes.size()); ++w) {
        const Wish& wish = request.wishes[w];
        if (pass == 0 ? wish.seats > 0 : wish.seats == 0 && (wish.container >= 0) == (pass == 2)) order.push_back(w);
      }
    for (int w : order) {
      const Wish& wish = request.wishes[w];
      if (wish.count == 0) continue;
      // A bed asked for in a children's room is the room's child's bed (its sizes, its pillow, the room's
      // essential), not an adult's bed beside it.
      const CategoryInfo* child_bed = room_.category == Category::kChildrenRoom && wish.category->name == "bed" ? FindCategory("child-bed") : nullptr;
      const CategoryInfo& info = child_bed ? *child_bed : *wish.category;
      if (wish.count < 0) {
        notes_.push_back("the request asks for " + std::to_string(wish.count) + " x " + std::string(info.name) +
                         ": a count below zero is no count; none added for it");
        continue;
      }
      std::vector<int> parents;
      if (wish.container >= 0) parents = made[wish.container];
      const ItemPrior* item =
          ItemFor(info.name, wish.container >= 0 ? request.wishes[wish.container].category->name : std::string_view{});
      int want = wish.count;
      if (wish.fill && !parents.empty()) {
        const CategoryInfo& pc = *request.wishes[wish.container].category;
        int per = wish.relation == Relation::kInside ? std::min(6, options_.max_per_receptacle * CompartmentsOf(pc.name))
                                                     : options_.max_per_receptacle;
        want = per * static_cast<int>(parents.size());
      }
      // Chairs for a table: as many as its sides seat with room to pull them out.
      if (item && !item->requires_category.empty() && want > SeatCap(*item)) {
        notes_.push_back("the request asks for " + std::to_string(want) + " x " + std::string(info.name) + "; the " +
                         std::string(item->requires_category) + " seats " + std::to_string(SeatCap(*item)) +
                         " with 0.75 m behind each in this room");
        dropped_ += want - SeatCap(*item);
        want = SeatCap(*item);
      }
      int added = 0;
      for (int k = 0; k < want; ++k) {
        int parent = -1;
        Relation relation = wish.relation;
        if (!parents.empty()) {
          // Spread over the containers: the one holding fewest of this category that still has room.
          for (int p : parents)
            if (ParentHolds(p, info, info.size_min, relation, item) &&
                (parent < 0 || ChildrenOf(p, info.name) < ChildrenOf(parent, info.name)))
              parent = p;
          if (parent < 0) break;
        }
        int node = Add(info, item, Origin::kPrompt, w, parent, relation, true, wish.seats);
        if (node < 0) break;
        for (const std::string& h : wish.hints)
          if (std::find(nodes_[node].hints.begin(), nodes_[node].hints.end(), h) == nodes_[node].hints.end())
            nodes_[node].hints.push_back(h);
        made[w].push_back(node);
        ++added;
      }
      if (added < want && !wish.fill) {
        notes_.push_back("the request asks for " + std::to_string(want) + " x " + std::string(info.name) + "; " +
                         std::to_string(added) + " fit");
        dropped_ += want - added;
      }
    }
  }

  // Issue 27: a group's members come with its hub whatever the count aimed at: the chair of a desk drawn
  // last, the table's minimum of chairs (Draw and Grow stop at the target; Mandatory ran before the hub was
  // drawn).
  void CompleteGroups() {
    for (const ItemPrior& item : priors_.items)
      if (!item.requires_category.empty() && item.mount != Mount::kParent) FillTo(item, MinWanted(item));
  }

  // An item's minimum: the priors', capped at the seats its table gives (noted once when that is fewer).
  int MinWanted(const ItemPrior& item) {
    const int min = MinOf(item), seats = SeatCap(item);
    if (seats < min && capped_.insert(&item).second)
      notes_.push_back("seats for " + std::to_string(seats) + " " + std::string(item.category) + "(s) around the " +
                       std::string(item.requires_category) + " with 0.75 m behind each (the priors ask " + std::to_string(min) + ")");
    return std::min(min, seats);
  }

  // Adds `item` until there are `want`; a note when the room takes no more.
  void FillTo(const ItemPrior& item, int want) {
    while (CountOf(&item) < want && Allowed(item))
      if (!AddPrior(item)) {
        notes_.push_back("no room for " + std::string(item.category) + " (" + std::to_string(CountOf(&item)) + " of " +
                         std::to_string(want) + ")");
        dropped_ += want - CountOf(&item);
        break;
      }
  }

  // Place settings follow the seats: one per chair around their table, within the item's range.
  int SettingsWanted(const ItemPrior& item) const {
    int seats = 0;
    for (int i = 0; i < static_cast<int>(nodes_.size()); ++i)
      if (!nodes_[i].removed && !item.parents.empty() && nodes_[i].info->name == item.parents[0].category) seats += SeatsOf(i);
    return std::clamp(seats, item.min, item.max);
  }

  void Settings() {
    for (const ItemPrior& item : priors_.items)
      if (item.per_seat)
        while (CountOf(&item) < SettingsWanted(item))
          if (!AddPrior(item)) break;
  }

  // The priors' minimum counts: anchors, or (small) what stands on them.
  void Mandatory(bool small) {
    for (const ItemPrior& item : priors_.items) {
      if ((item.mount == Mount::kParent) != small) continue;
      FillTo(item, item.per_seat ? SettingsWanted(item) : MinWanted(item));
    }
  }

  // Every item drawn between its min and max, up to the target: anchors, or (small) what stands on them.
  void Draw(bool small) {
    for (const ItemPrior& item : priors_.items) {
      if ((item.mount == Mount::kParent) != small || item.per_seat) continue;
      int cap = rng_.Int(std::min(MinOf(item), MaxOf(item)), MaxOf(item));
      while (CountOf(&item) < cap && Total() < target_)
        if (!AddPrior(item)) break;
    }
  }

  // Up to the target: one more of a random item that can take one, small objects twice as likely.
  // Then, in the rich room types of usual size, the furniture dressed (issue 27): small things only, on and in what the
  // room already holds, up to the top of the range (the reachability feedback and the agent leave out some
  // pieces with what stands on them; a room planned at the range's foot ends below the paper's counts).
  void Grow() {
    std::set<const ItemPrior*> full;
    const bool dress = options_.dress && IsRichRoomType(room_.category) && room_.area >= options_.rich_min_area;
    while (Total() < target_ || (dress && Total() < hi_)) {
      const bool small_only = Total() >= target_;
      std::vector<const ItemPrior*> open;
      std::vector<double> weights;
      for (const ItemPrior& item : priors_.items) {
        if (small_only && item.mount != Mount::kParent) continue;
        if (full.count(&item) || item.per_seat || CountOf(&item) >= MaxOf(item) || !Allowed(item)) continue;
        open.push_back(&item);
        weights.push_back(item.mount == Mount::kParent ? 2.0 : 1.0);
      }
      if (open.empty()) break;
      double total = 0.0;
      for (double w : weights) total += w;
      double x = rng_.Unit() * total;
      size_t pick = 0;
      while (pick + 1 < open.size() && x >= weights[pick]) x -= weights[pick++];
      if (!AddPrior(*open[pick])) full.insert(open[pick]);
    }
  }

  // Above the target: take back prior objects nothing stands on. First small things above their item's
  // minimum, then anchors above theirs, then small things down from their minimum; the item furthest above
  // its minimum first. Objects the request named stay.
  void Trim() {
    for (int pass = 0; pass < 3 && Total() > hi_; ++pass) {
      const bool small = pass != 1;
      while (Total() > hi_) {
        int victim = -1, surplus = -1000;
        for (int i = static_cast<int>(nodes_.size()) - 1; i >= 0; --i) {
          const Node& n = nodes_[i];
          if (n.removed || n.origin == Origin::kPrompt || !n.item || (n.mount == Mount::kParent) != small || HasChildren(i) ||
              HasMembers(i))
            continue;
          int over = CountOf(n.item) - MinOf(*n.item);
          if (pass < 2 && over <= 0) continue;
          if (over > surplus) victim = i, surplus = over;
        }
        if (victim < 0) break;
        GiveBack(nodes_[victim]);
        nodes_[victim].removed = true;
      }
    }
  }

  // Whether node i is the last of its category and the group's hub of other nodes (the desk of a chair, the
  // table of its chairs): trimmed, it would leave them without their group.
  bool HasMembers(int i) const {
    if (CountOfCategory(nodes_[i].info->name) > 1) return false;
    for (const Node& n : nodes_)
      if (!n.removed && n.item && n.item->requires_category == nodes_[i].info->name) return true;
    return false;
  }

  bool HasChildren(int i) const {
    for (const Node& n : nodes_)
      if (!n.removed && n.parent == i) return true;
    return false;
  }

  // ---- bathrooms
  // The live floor-standing node of a category, -1 when none.
  int RootOf(std::string_view category) const {
    for (int i = 0; i < static_cast<int>(nodes_.size()); ++i)
      if (!nodes_[i].removed && nodes_[i].parent < 0 && nodes_[i].info->name == category) return i;
    return -1;
  }

  void RemoveWithChildren(int i) {
    for (int j = 0; j < static_cast<int>(nodes_.size()); ++j)
      if (!nodes_[j].removed && nodes_[j].parent == i) RemoveWithChildren(j);
    GiveBack(nodes_[i]);
    nodes_[i].removed = true;
  }

  // The mirror over the basin narrower than the basin by the 10 cm wall decor keeps from a wall's end on
  // each side (solver/place.cpp), down to the category's smallest: centred over a basin that stands in a
  // corner (as small bathrooms put it), a wider mirror could not hang.
  // The mirror's width over a basin `basin_width` wide: narrower by the 10 cm wall decor keeps from a wall's
  // end on each side (the basin may stand in a corner), not below the category's smallest.
  double MirrorWidth(int mirror, double basin_width) const {
    constexpr double kDecorEnd = 0.1;  // m wall decor keeps from a wall's end
    const Node& m = nodes_[mirror];
    return std::max(m.info->size_min.x, std::min(m.size.x, basin_width - 2.0 * kDecorEnd));
  }
  void FitMirror(int mirror, int basin) {
    if (mirror < 0 || basin < 0) return;
    Node& m = nodes_[mirror];
    const double width = MirrorWidth(mirror, nodes_[basin].size.x);
    onwall_left_ += m.size.x - width;
    m.onwall_taken -= m.size.x - width;
    m.size.x = width;
  }

  // Issue 27 (a bedroom keeps its bed): whether the planned bed stands with its head to a wall on open floor,
  // clear of the doors' sweeps and the stairs (the bathroom's search, scene/bathroom_fit.h, with the bed as
  // its one fixture); where it does not, the widest of 1.4, 1.2 and 0.9 m at the shortest length that does
  // (a single bed in a walk-through room), one pillow on a single. True when the bed changed.
  bool BedFits() {
    const int bed = RootOf("bed");
    if (bed < 0) return false;
    Node& n = nodes_[bed];
    auto fits = [&](double width, double length) {
      return FitBathFixtures(room_, {BathFixture{"bed", width, length, n.size.z, 0.0}}).fits;
    };
    if (fits(n.size.x, n.size.y)) return false;
    const double length = n.info->size_min.y;
    for (double width : {kDoubleBedWidth, 1.2, n.info->size_min.x}) {
      if (width >= n.size.x || width < n.info->size_min.x || !fits(width, length)) continue;
      GiveBack(n);
      const double before = n.size.x;
      n.size.x = width;
      n.size.y = length;
      TakeRoom(n, n.origin == Origin::kPrompt);
      if (width < 1.2) {  // one pillow on a single bed
        int pillows = 0;
        for (int j = 0; j < static_cast<int>(nodes_.size()); ++j)
          if (!nodes_[j].removed && nodes_[j].parent == bed && nodes_[j].info->name == "pillow" && ++pillows > 1) RemoveWithChildren(j);
      }
      notes_.push_back("a bed " + FormatFixed(width, 2) + " m wide instead of " + FormatFixed(before, 2) +
                       " m: no wider one stands with its head to a wall clear of the doors");
      return true;
    }
    return false;
  }

  // A small bathroom's fixture set, chosen so that every fixture stands against a wall with its use zone
  // (toilet 0.6 m, basin 0.7 m, bath, shower and cabinet in front) on open floor (scene/bathroom_fit.h):
  // as planned; else the fixtures at their smallest (a smaller basin and toilet, a short bath); else a
  // shower instead of the bath; else no separate cabinet; else no bath or shower. What the request named
  // stays. True when the plan changed (the caller fills the room up again).
  bool BathroomFixtures() {
    const int toilet = RootOf("toilet"), basin = RootOf("washbasin"), cabinet = RootOf("cabinet"), bin = RootOf("bin");
    int bathing = RootOf("bathtub");
    if (bathing < 0) bathing = RootOf("shower");
    const int mirror = RootOf("mirror");
    auto named = [&](int i) { return i >= 0 && nodes_[i].origin == Origin::kPrompt; };
    struct Choice {
      bool smallest = false, shower = false, no_cabinet = false, no_bathing = false;
    };
    std::vector<Choice> choices = {{}, {true}};
    const bool tub = bathing >= 0 && nodes_[bathing].info->name == "bathtub" && !named(bathing);
    if (tub) choices.push_back({true, true});
    if (cabinet >= 0 && !named(cabinet)) choices.push_back({true, tub, true});
    if (bathing >= 0 && !named(bathing)) choices.push_back({true, tub, cabinet >= 0 && !named(cabinet), true});
    const CategoryInfo* shower = FindCategory("shower");
    auto size_of = [&](int i, const Choice& c) {
      const CategoryInfo& info = i == bathing && c.shower ? *shower : *nodes_[i].info;
      if (i == bathing && c.shower) return Vec3{info.size_min.x, info.size_min.y, info.size_max.z};
      if (!c.smallest || i == bin) return nodes_[i].size;
      return Vec3{info.size_min.x, info.size_min.y, nodes_[i].size.z};
    };
    auto fixtures_of = [&](const Choice& c) {
      std::vector<BathFixture> out;
      auto add = [&](int i) {
        if (i < 0) return;
        const CategoryInfo& info = i == bathing && c.shower ? *shower : *nodes_[i].info;
        const Vec3 size = size_of(i, c);
        BathFixture f{std::string(info.name), size.x, size.y, size.z, info.zone ? info.zone->depth : 0.0};
        if (i == basin && mirror >= 0) f.mirror = MirrorWidth(mirror, size.x);  // as FitMirror will make it
        out.push_back(f);
      };
      add(toilet);
      add(basin);
      if (!c.no_bathing) add(bathing);
      if (!c.no_cabinet) add(cabinet);
      if (bin >= 0 && toilet >= 0) {
        add(bin);
        out.back().companion_of = 0;
      }
      return out;
    };
    size_t pick = choices.size() - 1;
    bool fits = false;
    for (size_t k = 0; k < choices.size() && !fits; ++k)
      if ((fits = FitBathFixtures(room_, fixtures_of(choices[k])).fits)) pick = k;
    if (pick == 0) {
      FitMirror(mirror, basin);
      return false;
    }
    const Choice& c = choices[pick];
    std::vector<std::string> what;
    if (c.no_bathing) {
      what.push_back("no " + std::string(c.shower ? "bath or shower" : nodes_[bathing].info->name));
      RemoveWithChildren(bathing);
      excluded_.insert("bathtub");
      excluded_.insert("shower");
    } else if (c.shower) {
      what.push_back("a shower instead of the bath");
      nodes_[bathing].size = size_of(bathing, c);
      nodes_[bathing].info = shower;
      nodes_[bathing].item = ItemFor("shower");
      excluded_.insert("bathtub");
    }
    if (c.no_cabinet) {
      what.push_back("no separate cabinet");
      RemoveWithChildren(cabinet);
      excluded_.insert("cabinet");
    }
    if (c.smallest) {
      what.push_back("the fixtures at their smallest");
      for (int i : {toilet, basin, cabinet, c.shower ? -1 : bathing})
        if (i >= 0 && !nodes_[i].removed) nodes_[i].size = size_of(i, c);
    }
    FitMirror(mirror, basin);
    std::string words;
    for (const std::string& w : what) words += (words.empty() ? "" : ", ") + w;
    notes_.push_back("a small bathroom: " + words + (fits ? " (so that every fixture's use zone stays open floor)"
                                                          : " (even so the use zones do not all fit)"));
    return true;
  }

  // ---- output
  RoomPlan Finish(const RoomRequest& request) {
    RoomPlan plan;
    // Output order: what stands on the floor, a wall or the ceiling first, then what stands on or in it;
    // within each, a category's objects together, categories in the order they were first planned.
    std::vector<int> order;
    for (int i = 0; i < static_cast<int>(nodes_.size()); ++i)
      if (!nodes_[i].removed) order.push_back(i);
    std::map<std::string_view, int> first_seen;
    for (int i : order) first_seen.emplace(nodes_[i].info->name, i);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
      bool sa = nodes_[a].mount == Mount::kParent, sb = nodes_[b].mount == Mount::kParent;
      if (sa != sb) return !sa;
      int ca = first_seen[nodes_[a].info->name], cb = first_seen[nodes_[b].info->name];
      if (ca != cb) return ca < cb;
      return nodes_[a].parent < nodes_[b].parent;  // a category's small objects grouped by parent
    });
    std::vector<std::string> ids(nodes_.size());
    std::map<std::string, int> next;
    std::map<std::string, std::vector<int>> by_category;  // live node indices in output order
    for (int i : order) {
      std::string category(nodes_[i].info->name);
      ids[i] = room_.name + "/" + category + "-" + std::to_string(next[category]++);
      by_category[category].push_back(i);
    }
    auto instance = [&](int i) {
      const auto& list = by_category[std::string(nodes_[i].info->name)];
      return static_cast<int>(std::find(list.begin(), list.end(), i) - list.begin());
    };
    std::set<std::tuple<std::string, int, std::string>> seen_edges;
    auto add_edge = [&](const std::string& source, SemanticRelation relation, const std::string& target, const EdgeParams& params) {
      if (source == target || !seen_edges.insert({source, static_cast<int>(relation), target}).second) return;
      plan.edges.push_back({source, relation, target, params});
    };
    for (int i : order) {
      const Node& n = nodes_[i];
      SceneObject o;
      o.id = ids[i];
      o.category = std::string(n.info->name);
      o.room = room_.name;
      o.level = room_.level;
      o.size = n.size;
      o.affordances = n.info->affordances;
      o.parent = n.parent >= 0 ? ids[n.parent]
                 : n.mount == Mount::kOnWall ? std::string(kParentWall)
                 : n.mount == Mount::kCeiling ? std::string(kParentCeiling) : std::string(kParentFloor);
      o.relation = n.relation;
      o.origin = n.origin;
      o.hints = n.hints;
      if (n.info->zone && (o.affordances & kInteractor)) {
        InteractionZone zone{n.info->zone->side, n.info->zone->depth, {}};
        // A table's chair keeps the floor behind it free to be pulled out and sat on (issue 27: 0.75 m); its
        // front is under the table.
        if (n.item && (n.item->requires_category == "dining-table" || n.item->requires_category == "conference-table"))
          zone = InteractionZone{"back", 0.75, {}};
        // A desk's chair is pulled in under the desk: it is reached, and pulled out, from behind.
        if (n.item && n.item->requires_category == "desk" &&
            std::any_of(n.item->edges.begin(), n.item->edges.end(), [](const auto& e) {
              return e.relation == SemanticRelation::kFrontOf && e.params.max_gap && *e.params.max_gap <= 0.5;
            }))
          zone = InteractionZone{"back", 0.6, {}};
        if (n.item)
          for (std::string_view c : n.item->exempt)
            for (int j : by_category[std::string(c)]) zone.exempt.push_back(ids[j]);
        o.interaction_zone = zone;
      }
      plan.objects.push_back(o);
      if (!n.item) continue;
      const int k = instance(i);
      for (const EdgeRule& rule : n.item->edges) {
        const std::vector<int>* targets = &by_category[std::string(rule.target)];
        if (targets->empty()) continue;
        int t = -1;
        SemanticRelation relation = rule.relation;
        switch (rule.pick) {
          case Pick::kFirst: t = targets->front(); break;
          case Pick::kSame: t = (*targets)[std::min<size_t>(k, targets->size() - 1)]; break;
          case Pick::kPrevious: t = k > 0 && rule.target == n.info->name ? (*targets)[k - 1] : -1; break;
          case Pick::kLast: t = targets->back(); break;
          case Pick::kAlternate:
            t = targets->front();
            if (relation == SemanticRelation::kLeftOf && k % 2 == 1) relation = SemanticRelation::kRightOf;
            break;
        }
        // What hangs on a wall "behind" and "centred" on something hangs above it: over a sofa (or bed) that
        // stands free in the room there is no wall to hang it on, so the painting is the room's wall art
        // without those edges (the solver hangs it at eye level where it fits).
        if (t >= 0 && n.mount == Mount::kOnWall && nodes_[t].mount == Mount::kFloor && nodes_[t].item &&
            nodes_[t].item->mount == Mount::kWall &&
            (relation == SemanticRelation::kBehind || relation == SemanticRelation::kCentered))
          continue;
        if (t >= 0) add_edge(ids[i], relation, ids[t], rule.params);
      }
    }
    // Edges the request states between the objects it names (their first instances).
    for (const WishEdge& e : request.edges) {
      int s = -1, t = -1;
      for (int i = 0; i < static_cast<int>(nodes_.size()); ++i) {
        if (nodes_[i].removed) continue;
        if (s < 0 && nodes_[i].wish == e.source) s = i;
        if (t < 0 && nodes_[i].wish == e.target) t = i;
      }
      if (s >= 0 && t >= 0) add_edge(ids[s], e.relation, ids[t], {});
    }

    PlanSummary& sum = plan.summary;
    sum.objects = static_cast<int>(plan.objects.size());
    for (const SceneObject& o : plan.objects) sum.from_prompt += o.origin == Origin::kPrompt;
    sum.target_min = lo_;
    sum.target_max = hi_;
    sum.dropped = dropped_;
    double floor_used = 0.0;
    for (const Node& n : nodes_)
      if (!n.removed) floor_used += n.floor_taken + n.extra_taken;
    sum.floor_used = room_.furnishable_area > 0 ? floor_used / room_.furnishable_area : 0.0;
    if (sum.objects == 0) {
      sum.outcome = PlanOutcome::kEmpty;
      notes_.push_back(priors_.items.empty() && text_.empty() ? "no priors for this room type and no request"
                                                              : "nothing fits this room");
    } else if (dropped_ > 0 || sum.objects < lo_) {
      sum.outcome = PlanOutcome::kPartial;
      if (sum.objects < lo_)
        notes_.push_back(std::to_string(sum.objects) + " objects, below the " + std::to_string(lo_) +
                         " aimed at: the room has no space for more");
    }
    plan.record.notes = notes_;
    return plan;
  }

  const RoomContext& room_;
  const std::string& text_;
  const PlannerOptions& options_;
  const RoomPriors& priors_;
  SplitMix64 rng_;
  std::vector<Node> nodes_;
  std::vector<Stretch> stretches_;
  double floor_left_ = 0.0, prompt_extra_ = 0.0, rug_left_ = 0.0, onwall_left_ = 0.0;
  double run_left_ = 0.0;     // m of the kitchen run's wall still free (kitchens only)
  bool run_limited_ = false;  // the kitchen run must fit run_left_
  double size_factor_ = 0.5;
  double clear_width_ = 0.0;  // m, ClearWidth()
  int lo_ = 0, hi_ = 0, target_ = 0;
  int dropped_ = 0;
  std::set<std::string> excluded_, named_;
  std::set<const ItemPrior*> capped_;  // items whose seats MinWanted noted
  std::vector<std::string> notes_;
};

}  // namespace

std::string PlannerOptions::Check() const {
  auto fmt = [](double v) {
    std::string s = std::to_string(v);
    return s.substr(0, s.find_last_not_of('0') + 1);
  };
  if (!(floor_share > 0.0 && floor_share <= 1.0)) return "floor_share = " + fmt(floor_share) + ": must be in (0, 1]";
  if (!(prompt_floor_share >= floor_share && prompt_floor_share <= 1.0))
    return "prompt_floor_share = " + fmt(prompt_floor_share) + ": must be in [floor_share, 1]";
  if (max_per_receptacle < 1 || max_per_receptacle > 10)
    return "max_per_receptacle = " + std::to_string(max_per_receptacle) + ": must be in [1, 10]";
  if (rich_min_objects < 1 || rich_max_objects < rich_min_objects)
    return "rich_min_objects / rich_max_objects = " + std::to_string(rich_min_objects) + " / " +
           std::to_string(rich_max_objects) + ": need 1 <= min <= max";
  if (!(rich_min_area >= 0.0)) return "rich_min_area = " + fmt(rich_min_area) + ": must be >= 0";
  return "";
}

std::string_view PlanOutcomeName(PlanOutcome outcome) {
  switch (outcome) {
    case PlanOutcome::kPlanned: return "planned";
    case PlanOutcome::kPartial: return "partial";
    case PlanOutcome::kEmpty: return "empty";
  }
  return "planned";
}

Result<RoomPlan> PriorsPlanner::Plan(const PlanRequest& request) const {
  if (!request.room) return Error{"plan: no room given"};
  if (std::string problem = options_.Check(); !problem.empty()) return Error{"planner options: " + problem};
  auto start = std::chrono::steady_clock::now();
  RoomPlan plan = Planning(*request.room, request.text, request.seed, options_).Run();
  plan.record.planner = std::string(name());
  plan.record.seed = request.seed;
  plan.record.text = request.text;
  plan.summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return plan;
}

}  // namespace villa::scene

namespace villa::scene {

SceneFile PlanSceneFile(const FileRef& layout, const BuildOptions& build, const std::string& room, const RoomPlan& plan) {
  SceneFile scene;
  scene.layout = layout;
  scene.build = {build.slab_thickness, build.exterior_wall_thickness, build.interior_wall_thickness};
  RoomEntry entry;
  entry.name = room;
  entry.plan = plan.record;
  entry.edges_sem = plan.edges;
  scene.rooms.push_back(entry);
  scene.objects = plan.objects;
  return scene;
}

std::string PlanTable(const RoomPlan& plan, const std::string& room) {
  const std::string prefix = room + "/";
  auto local = [&](const std::string& id) { return id.rfind(prefix, 0) == 0 ? id.substr(prefix.size()) : id; };
  const bool assets = std::any_of(plan.objects.begin(), plan.objects.end(), [](const SceneObject& o) { return !o.asset.empty(); });
  std::vector<std::string> header{"id", "category", "parent / relation", "affordances", "zone", "origin"};
  if (assets) header.push_back("asset");
  TextTable table(header);
  for (const SceneObject& o : plan.objects) {
    std::string affordances;
    for (const std::string& a : AffordanceNames(o.affordances)) affordances += (affordances.empty() ? "" : " ") + a;
    std::string zone = "none";
    if (o.interaction_zone) {
      zone = o.interaction_zone->side + " " + FormatFixed(o.interaction_zone->depth, 2);
      if (!o.interaction_zone->exempt.empty()) zone += " (" + std::to_string(o.interaction_zone->exempt.size()) + " exempt)";
    }
    std::string origin(OriginName(o.origin));
    for (const std::string& h : o.hints) origin += ", " + h;
    std::vector<std::string> row{local(o.id), o.category, local(o.parent) + " / " + std::string(RelationName(o.relation)),
                                 affordances, zone, origin};
    if (assets) row.push_back(o.asset);
    table.AddRow(row);
  }
  std::string out = table.Render();
  if (!plan.edges.empty()) {
    out += "semantic edges:\n";
    for (const SemanticEdge& e : plan.edges)
      out += "  " + local(e.source) + " " + std::string(SemanticRelationName(e.relation)) + " " + local(e.target) + "\n";
  }
  for (const std::string& note : plan.record.notes) out += "note: " + note + "\n";
  return out;
}

}  // namespace villa::scene
