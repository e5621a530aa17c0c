#include "solver/functional.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "layout/geometry.h"
#include "mesh/geometry2d.h"
#include "solver/box.h"
#include "solver/group_rules.h"
#include "util/text_table.h"

namespace villa::solver {
namespace {

using Json = nlohmann::ordered_json;
constexpr double kInf = std::numeric_limits<double>::infinity();

constexpr double kFloorRoomArea = 14.0;    // m2: rooms whose floor use is measured
constexpr double kFurnitureFootprint = 0.1;  // m2: smaller things are not furniture
constexpr double kFarFromFurniture = 1.5;  // m
constexpr double kFarShare = 0.3;
constexpr double kRaster = 0.05;           // m

double Round3(double v) { return std::round(v * 1e3) / 1e3; }

// One placed object in the plan: its box, frame and what it is.
struct Item {
  const scene::SceneObject* o = nullptr;
  OrientedBox box;  // its footprint and heights (front -V, SCENE.md)
  bool floor = false;      // stands on the floor (free or against a wall)
  bool covering = false;   // a rug: part of the floor
  bool furniture = false;  // floor, not a covering, footprint >= 0.1 m2

  const std::string& category() const { return o->category; }
};

Item MakeItem(const scene::SceneObject& o) {
  Item it;
  it.o = &o;
  const scene::Pose& p = *o.pose;
  it.box.c = {p.x, p.y};
  it.box.yaw = p.yaw;
  it.box.hx = 0.5 * o.size.x;
  it.box.hy = 0.5 * o.size.y;
  it.box.z0 = p.z;
  it.box.z1 = p.z + o.size.z;
  it.floor = o.parent == scene::kParentFloor || o.relation == scene::Relation::kAgainstWall;
  it.covering = it.floor && (o.category == "rug" || o.size.z <= 0.03);
  it.furniture = it.floor && !it.covering && o.size.x * o.size.y >= kFurnitureFootprint;
  return it;
}

// The gap between two footprints (m, > 0 apart, < 0 overlapping): the widest separation along a face normal.
double Gap(const Item& a, const Item& b) { return PlanGap(a.box, b.box); }


bool InFreeFloor(const scene::RoomContext& room, Point p) {
  for (const Ring& r : room.free_floor)
    if (PointInRing(p, r, 0.0)) return true;
  return false;
}

// The staircase's zones: its flights, the hole above, the strip where it arrives (as scene/room_context.cpp
// counts them out of the furnishable floor).
bool IsStaircase(const scene::KeepOut& k) {
  return k.kind == scene::KeepOutKind::kStair || k.kind == scene::KeepOutKind::kStairHole || k.kind == scene::KeepOutKind::kStairArrival;
}

bool Is(const Item& it, std::initializer_list<std::string_view> categories) {
  return std::find(categories.begin(), categories.end(), it.category()) != categories.end();
}

std::string Local(const std::string& id, const std::string& room) {
  return id.rfind(room + "/", 0) == 0 ? id.substr(room.size() + 1) : id;
}

class Checker {
 public:
  explicit Checker(const FunctionalInput& in) : in_(in), room_(*in.context) {
    for (const scene::SceneObject* o : in.objects)
      if (o && o->pose) items_.push_back(MakeItem(*o));
    out_.room = room_.name;
    out_.category = room_.category;
    out_.area = room_.area;
  }

  FunctionalCheck Run() {
    Essentials();
    Tables();
    Seating();
    Desks();
    Beds();
    Kitchen();
    Bathroom();
    if (in_.measure_floor) Floor();
    Wishes();
    Odd();
    return std::move(out_);
  }

 private:
  std::string Name(const Item& it) const { return Local(it.o->id, room_.name); }
  std::vector<const Item*> All(std::initializer_list<std::string_view> categories) const {
    std::vector<const Item*> out;
    for (const Item& it : items_)
      if (Is(it, categories)) out.push_back(&it);
    return out;
  }
  const Item* Nearest(const Item& from, const std::vector<const Item*>& among) const {
    const Item* best = nullptr;
    double gap = kInf;
    for (const Item* t : among)
      if (const double g = Gap(from, *t); g < gap) gap = g, best = t;
    return best;
  }
  // The notes that speak of a category ("no room for bed (0 of 1)"), each once (a removal the reachability
  // feedback repeated round after round is one note), joined; `seen` carries the notes already said.
  std::string NotesAbout(std::string_view category, std::set<std::string>* seen = nullptr) const {
    std::set<std::string> local;
    if (!seen) seen = &local;
    std::string why;
    for (const std::string& n : in_.notes)
      if (n.find(category) != std::string::npos && seen->insert(n).second) why += (why.empty() ? "" : "; ") + n;
    return why;
  }

  void Essentials() {
    for (const Essential& e : EssentialsOf(room_.category)) {
      int n = 0;
      for (const Item& it : items_)
        n += std::find(e.categories.begin(), e.categories.end(), it.category()) != e.categories.end();
      out_.essentials.emplace_back(e.name);
      if (n >= e.count) continue;
      out_.missing.emplace_back(e.name);
      for (std::string_view c : e.categories) {
        const std::string why = NotesAbout(c, &said_);
        if (!why.empty()) out_.missing_why += (out_.missing_why.empty() ? "" : "; ") + why;
      }
    }
  }

  // Free distance behind a chair's back (m, capped at 2): walls (the free floor's edge), the staircase and
  // furniture (floor objects of 0.1 m2 and more, rugs not) stop it; sampled at five points across the
  // chair's width, from edge to edge.
  double Behind(const Item& chair) const {
    const Point u = chair.box.U(), v = chair.box.V();
    double clear = 2.0;
    for (double s : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
      for (double d = 0.0; d < clear; d += 0.025) {
        const Point p = geo::Add(geo::Add(chair.box.c, geo::Scale(v, chair.box.hy + d + 0.01)), geo::Scale(u, s * chair.box.hx));
        bool blocked = !InFreeFloor(room_, p) || OnStairs(p);
        for (const Item& it : items_) {
          if (blocked) break;
          if (&it == &chair || !it.furniture) continue;
          blocked = it.box.ContainsPlan(p);
        }
        if (blocked) {
          clear = d;
          break;
        }
      }
    }
    return clear;
  }

  bool OnStairs(Point p) const {
    for (const scene::KeepOut& k : room_.keep_outs)
      if (IsStaircase(k) && PointInRing(p, k.polygon, 0.0)) return true;
    return false;
  }

  void Tables() {
    const bool counted = room_.category == Category::kDiningRoom || room_.category == Category::kMeetingRoom;
    const std::vector<const Item*> tables = All({"dining-table", "conference-table"});
    const std::vector<const Item*> chairs = All({"chair", "office-chair", "child-chair"});
    if (tables.empty()) {
      if (counted)
        out_.chairs += static_cast<int>(chairs.size()), out_.chairs_far += static_cast<int>(chairs.size());
      return;
    }
    std::map<const Item*, GroupCheck> groups;
    for (const Item* t : tables) {
      GroupCheck& g = groups[t];
      g.kind = room_.category == Category::kMeetingRoom ? "meeting" : room_.category == Category::kKitchen ? "kitchen-table" : "dining";
      g.anchor = t->o->id;
      g.measures["chairs"] = 0;
      g.measures["chairs_ok"] = 0;
      g.measures["min_behind_m"] = nullptr;
    }
    for (const Item* c : chairs) {
      // A desk's chair belongs to the desk (an office's visitor chairs too).
      const Item* t = Nearest(*c, tables);
      const double gap = Gap(*c, *t);
      if (room_.category == Category::kKitchen || room_.category == Category::kOffice || room_.category == Category::kBedroom ||
          room_.category == Category::kChildrenRoom)
        if (gap > kSeatLost) continue;  // a desk chair, not the table's
      GroupCheck& g = groups[t];
      g.members.push_back(c->o->id);
      if (counted) ++out_.chairs;
      std::string problem;
      if (gap > kSeatLost) {
        problem = FormatFixed(gap, 2) + " m from the nearest table (> " + FormatFixed(kSeatLost, 1) + ")";
        if (counted) ++out_.chairs_far;
      } else {
        const double behind = Behind(*c);
        const auto& m = g.measures["min_behind_m"];
        if (m.is_null() || behind < m.get<double>()) g.measures["min_behind_m"] = Round3(behind);
        problem = TableSeatProblem(c->box, t->box);
        if (problem.empty() && behind < kSeatBehind - 1e-9)
          problem = FormatFixed(behind, 2) + " m free behind it (>= " + FormatFixed(kSeatBehind, 2) + ")";
      }
      g.measures["chairs"] = g.measures["chairs"].get<int>() + 1;
      if (problem.empty()) {
        seated_.insert(c);
        g.measures["chairs_ok"] = g.measures["chairs_ok"].get<int>() + 1;
        if (counted) ++out_.chairs_ok;
      } else {
        g.problems.push_back(Name(*c) + ": " + problem);
      }
    }
    for (const Item* t : tables) {
      GroupCheck& g = groups[t];
      if (g.members.empty() && room_.category != Category::kKitchen) g.problems.push_back("no chair at the table");
      out_.groups.push_back(std::move(g));
    }
  }

  void Seating() {
    const std::vector<const Item*> sofas = All({"sofa"});
    if (sofas.empty()) return;
    const bool living = room_.category == Category::kLivingRoom;
    std::vector<const Item*> screens = All({"tv"});
    if (screens.empty()) screens = All({"tv-stand"});
    bool tv_wanted = living;
    for (const FunctionalWish& w : in_.wishes)
      if ((w.category == "tv" || w.category == "tv-stand") && w.count == 0) tv_wanted = false;
    const std::vector<const Item*> tables = All({"coffee-table"});
    for (size_t k = 0; k < sofas.size(); ++k) {
      const Item& sofa = *sofas[k];
      GroupCheck g;
      g.kind = "seating";
      g.anchor = sofa.o->id;
      bool core = true;
      if (k == 0 && (tv_wanted || !screens.empty())) {
        if (screens.empty()) {
          g.problems.push_back("no TV");
          core = false;
        } else {
          const Item& tv = *screens.front();
          g.members.push_back(tv.o->id);
          g.measures["tv_angle_deg"] = Round3(AngleDegrees(sofa.box.Front(), geo::Sub(tv.box.c, sofa.box.c)));
          g.measures["tv_distance_m"] = Round3(geo::Dist(tv.box.c, sofa.box.c));
          g.measures["tv_facing_deg"] = Round3(AngleDegrees(tv.box.Front(), geo::Sub(sofa.box.c, tv.box.c)));
          if (std::string p = TvProblem(sofa.box, tv.box); !p.empty()) g.problems.push_back(p), core = false;
        }
      }
      const Item* table = tables.empty() ? nullptr : Nearest(sofa, tables);
      if (!table) {
        if (k == 0 && living) g.problems.push_back("no coffee table"), core = false;
      } else {
        g.members.push_back(table->o->id);
        g.measures["coffee_gap_m"] = Round3(Gap(sofa, *table));
        g.measures["coffee_offset_m"] = Round3(sofa.box.Local(table->box.c).x);
        if (std::string p = CoffeeTableProblem(table->box, sofa.box); !p.empty()) g.problems.push_back(p), core = false;
      }
      // Armchairs of the group (an edge to its coffee table or sofa, else within kArmchairNear of it; a reading chair
      // elsewhere is a zone of its own) face it within 45 degrees.
      for (const Item* a : All({"armchair"})) {
        const Item& focus = table ? *table : sofa;
        const bool tied = std::any_of(in_.edges.begin(), in_.edges.end(), [&](const scene::SemanticEdge& e) {
          return e.source == a->o->id && (e.target == sofa.o->id || (table && e.target == table->o->id));
        });
        if (in_.edges.empty() ? Gap(*a, focus) > kArmchairNear : !tied) continue;
        g.members.push_back(a->o->id);
        if (std::string p = ArmchairProblem(a->box, focus.box.c); !p.empty()) g.problems.push_back(Name(*a) + ": " + p);
      }
      if (k == 0 && living) {
        ++out_.seating;
        out_.seating_ok += core;
      }
      out_.groups.push_back(std::move(g));
    }
  }

  void Desks() {
    const std::vector<const Item*> chairs = All({"office-chair", "chair", "child-chair"});
    for (const Item* desk : All({"desk"})) {
      GroupCheck g;
      g.kind = "desk";
      g.anchor = desk->o->id;
      const Item* best = nullptr;
      double best_gap = kInf;
      for (const Item* c : chairs) {
        // One chair serves one desk or table: a seat already taken does not count again.
        if (seated_.count(c) || !DeskSeatProblem(c->box, desk->box).empty()) continue;
        if (const double gap = Gap(*desk, *c); gap < best_gap) best_gap = gap, best = c;
      }
      ++out_.desks;
      if (best) {
        seated_.insert(best);
        g.members.push_back(best->o->id);
        g.measures["chair_gap_m"] = Round3(best_gap);
        ++out_.desks_ok;
      } else {
        g.problems.push_back("no chair at its front facing it");
      }
      out_.groups.push_back(std::move(g));
    }
  }

  void Beds() {
    const std::vector<const Item*> beds = All({"bed", "child-bed"});
    if (beds.empty()) return;
    std::map<const Item*, GroupCheck> groups;
    for (const Item* b : beds) {
      GroupCheck& g = groups[b];
      g.kind = "bed";
      g.anchor = b->o->id;
    }
    for (const Item* n : All({"nightstand"})) {
      const Item* bed = Nearest(*n, beds);
      GroupCheck& g = groups[bed];
      g.members.push_back(n->o->id);
      ++out_.nightstands;
      const std::string problem = BedsideProblem(n->box, bed->box);
      if (problem.empty()) ++out_.nightstands_ok;
      else g.problems.push_back(Name(*n) + ": " + problem);
    }
    for (const Item& p : items_) {
      if (p.category() != "pillow") continue;
      auto bed = std::find_if(beds.begin(), beds.end(), [&](const Item* b) { return b->o->id == p.o->parent; });
      if (bed == beds.end()) continue;
      GroupCheck& g = groups[*bed];
      g.members.push_back(p.o->id);
      ++out_.pillows;
      const AssetRecord* asset = in_.assets ? in_.assets((*bed)->o->asset) : nullptr;
      const double scale = asset && asset->size.y > 0.0 ? (*bed)->o->size.y / asset->size.y : 1.0;
      if (const std::string problem = PillowProblem(p.box.c, MattressBox((*bed)->box, asset, scale)); problem.empty()) ++out_.pillows_ok;
      else g.problems.push_back(Name(p) + ": " + problem);
    }
    for (const Item* b : beds) out_.groups.push_back(std::move(groups[b]));
  }

  void Kitchen() {
    if (room_.category != Category::kKitchen) return;
    GroupCheck g;
    g.kind = "kitchen";
    const std::vector<const Item*> counters = All({"counter"});
    if (!counters.empty()) g.anchor = counters.front()->o->id;
    for (size_t k = 1; k < counters.size(); ++k) g.members.push_back(counters[k]->o->id);
    const std::vector<const Item*> cookers = All({"cooker"}), fridges = All({"fridge"});
    const std::vector<const Item*> sinks = All({"sink"});
    const Item* sink = sinks.empty() ? nullptr : sinks.back();
    auto touches_counter = [&](const Item& it) {
      return std::any_of(counters.begin(), counters.end(), [&](const Item* c) { return Gap(it, *c) <= kRunGap; });
    };
    for (const Item* c : cookers) {
      g.members.push_back(c->o->id);
      if (!touches_counter(*c)) g.problems.push_back(Name(*c) + ": not in a run of counters");
    }
    for (const Item* f : fridges) {
      g.members.push_back(f->o->id);
      if (!touches_counter(*f)) g.problems.push_back(Name(*f) + ": not at the end of a run of counters");
    }
    if (sink) g.members.push_back(sink->o->id);
    // The work triangle: sink, cooker and fridge centres.
    if (sink && !cookers.empty() && !fridges.empty()) {
      const Point s = sink->box.c, c = cookers.front()->box.c, f = fridges.front()->box.c;
      const double perimeter = geo::Dist(s, c) + geo::Dist(c, f) + geo::Dist(f, s);
      g.measures["work_triangle_m"] = Round3(perimeter);
      if (perimeter < kTriangleMin - 1e-9 || perimeter > kTriangleMax + 1e-9)
        g.problems.push_back("work triangle " + FormatFixed(perimeter, 2) + " m (" + FormatFixed(kTriangleMin, 0) + "-" +
                             FormatFixed(kTriangleMax, 0) + ")");
    }
    out_.groups.push_back(std::move(g));
  }

  void Bathroom() {
    if (room_.category != Category::kBathroom) return;
    GroupCheck g;
    g.kind = "bathroom";
    const std::vector<const Item*> basins = All({"washbasin"});
    if (!basins.empty()) {
      const Item& basin = *basins.front();
      g.anchor = basin.o->id;
      const Item* mirror = nullptr;
      for (const Item* m : All({"mirror"})) {
        const Point l = basin.box.Local(m->box.c);
        if (std::abs(l.x) <= kMirrorOffset && l.y > 0.0 && m->box.z0 > basin.box.z1 - 0.05) mirror = m;
      }
      if (mirror) g.members.push_back(mirror->o->id);
      else g.problems.push_back("no mirror above the basin");
    }
    for (const Item* t : All({"toilet", "bathtub", "shower"})) g.members.push_back(t->o->id);
    out_.groups.push_back(std::move(g));
  }

  // The floor raster: the largest disc free of furniture and the share of the floor far from it.
  void Floor() {
    if (room_.area < kFloorRoomArea - 1e-9 || room_.free_floor.empty()) return;
    out_.floor_measured = true;
    out_.bare_limit = std::max(1.5, 0.25 * std::sqrt(room_.area));
    std::vector<const OrientedBox*> furniture, occupied;
    for (const Item& it : items_) {
      if (!it.floor || it.covering) continue;
      occupied.push_back(&it.box);
      if (it.furniture) furniture.push_back(&it.box);
    }
    std::vector<const Ring*> stairs;
    for (const scene::KeepOut& k : room_.keep_outs)
      if (IsStaircase(k)) stairs.push_back(&k.polygon);
    double x0 = kInf, y0 = kInf, x1 = -kInf, y1 = -kInf;
    for (const Ring& r : room_.free_floor) {
      const Box2 b = BoundingBox(r);
      x0 = std::min(x0, b.min_x), y0 = std::min(y0, b.min_y), x1 = std::max(x1, b.max_x), y1 = std::max(y1, b.max_y);
    }
    int free = 0, far = 0;
    for (double x = x0 + 0.5 * kRaster; x < x1; x += kRaster) {
      for (double y = y0 + 0.5 * kRaster; y < y1; y += kRaster) {
        const Point p{x, y};
        if (!InFreeFloor(room_, p)) continue;
        bool taken = false;
        for (const OrientedBox* b : occupied) taken = taken || b->ContainsPlan(p);
        for (const Ring* s : stairs) taken = taken || PointInRing(p, *s, 0.0);
        if (taken) continue;
        double to_furniture = kInf;
        for (const Ring* s : stairs) to_furniture = std::min(to_furniture, DistanceToBoundary(p, *s));
        for (const OrientedBox* b : furniture) to_furniture = std::min(to_furniture, DistanceToBox(*b, p));
        double to_wall = kInf;
        for (const Ring& r : room_.free_floor) to_wall = std::min(to_wall, DistanceToBoundary(p, r));
        ++free;
        far += to_furniture > kFarFromFurniture;
        const double radius = std::min(to_furniture, to_wall);
        if (radius > out_.bare_radius) out_.bare_radius = radius, out_.bare_centre = p;
      }
    }
    out_.far_share = free ? double(far) / free : 0.0;
    out_.floor_ok = out_.bare_radius <= out_.bare_limit + 1e-9 && out_.far_share <= kFarShare + 1e-9;
  }

  void Wishes() {
    for (const FunctionalWish& w : in_.wishes) {
      if (w.count <= 0) continue;
      FunctionalCheck::Wish c;
      c.category = w.category;
      c.asked = w.fill ? 1 : w.count;
      // (A bed asked for in a children's room is planned as the room's child's bed: scene/planner.cpp.)
      const bool child_bed = w.category == "bed" && in_.context->category == Category::kChildrenRoom;
      for (const Item& it : items_) c.present += it.category() == w.category || (child_bed && it.category() == "child-bed");
      c.ok = c.present >= c.asked;
      if (!c.ok) {
        c.why = NotesAbout(w.category);
        if (c.why.empty()) c.why = "not planned or removed without a note";
      }
      out_.wishes.push_back(std::move(c));
    }
  }

  // Small things on the floor of a closed cell (behind a door or drawer front), children's pieces outside
  // children's rooms.
  void Odd() {
    const bool children = room_.category == Category::kChildrenRoom;
    for (const Item& it : items_) {
      const scene::SceneObject& o = *it.o;
      if (!children && (o.category == "child-bed" || o.category == "child-chair" || o.category == "play-table" || o.category == "toy-chest"))
        out_.odd.push_back(Name(it) + ": a children's piece in a " + std::string(CategoryName(room_.category)));
      if (!in_.assets) continue;
      const AssetRecord* own = in_.assets(o.asset);
      if (own && !children && !own->room_types.empty() &&
          std::all_of(own->room_types.begin(), own->room_types.end(), [](const std::string& t) { return t == "children-room"; }) &&
          o.category != "toy")
        out_.odd.push_back(Name(it) + ": " + own->name + " is made for children's rooms");
      if (o.relation != scene::Relation::kOnTop || scene::IsRootParent(o.parent) || !o.surface) continue;
      const scene::SceneObject* parent = nullptr;
      for (const Item& p : items_)
        if (p.o->id == o.parent) parent = p.o;
      const AssetRecord* record = parent ? in_.assets(parent->asset) : nullptr;
      if (!record) continue;
      if (record->ClosedCellFloor(*o.surface))
        out_.odd.push_back(Name(it) + ": stands 'ontop' inside a closed cell of " + Local(parent->id, room_.name));
    }
  }

  const FunctionalInput& in_;
  const scene::RoomContext& room_;
  std::vector<Item> items_;
  std::set<const Item*> seated_;  // chairs already counted at a table or a desk
  std::set<std::string> said_;    // notes already in out_.missing_why
  FunctionalCheck out_;
};

}  // namespace

const std::vector<Essential>& EssentialsOf(Category room) {
  static const std::vector<Essential> none;
  static const std::map<Category, std::vector<Essential>> table = {
      {Category::kLivingRoom, {{{"sofa"}, 1, "sofa"}}},
      {Category::kBedroom, {{{"bed", "child-bed"}, 1, "bed"}}},
      {Category::kChildrenRoom, {{{"child-bed", "bed"}, 1, "bed"}}},
      {Category::kBathroom, {{{"toilet"}, 1, "toilet"}, {{"washbasin"}, 1, "basin"}}},
      {Category::kKitchen, {{{"cooker"}, 1, "cooker"}, {{"fridge"}, 1, "fridge"}, {{"sink"}, 1, "sink"}, {{"counter"}, 1, "counter"}}},
      {Category::kDiningRoom, {{{"dining-table"}, 1, "dining table"}, {{"chair"}, 2, "dining chairs"}}},
      {Category::kOffice, {{{"desk"}, 1, "desk"}, {{"office-chair", "chair"}, 1, "desk chair"}}},
      {Category::kMeetingRoom, {{{"conference-table", "dining-table"}, 1, "meeting table"}, {{"chair", "office-chair"}, 2, "meeting chairs"}}},
  };
  auto it = table.find(room);
  return it == table.end() ? none : it->second;
}

bool FunctionalCheck::wishes_ok() const {
  return std::all_of(wishes.begin(), wishes.end(), [](const Wish& w) { return w.ok; });
}
bool FunctionalCheck::groups_ok() const {
  return std::all_of(groups.begin(), groups.end(), [](const GroupCheck& g) { return g.ok(); });
}

FunctionalCheck CheckRoomFunction(const FunctionalInput& input) {
  if (!input.context) return {};
  return Checker(input).Run();
}

Json FunctionalJson(const FunctionalCheck& c) {
  Json j;
  j["ok"] = c.ok();
  j["essentials"] = {{"needed", c.essentials}, {"missing", c.missing}};
  if (!c.missing_why.empty()) j["essentials"]["why"] = c.missing_why;
  Json groups = Json::array();
  for (const GroupCheck& g : c.groups) {
    Json gj{{"kind", g.kind}, {"anchor", g.anchor.empty() ? Json(nullptr) : Json(g.anchor)}, {"members", g.members}, {"ok", g.ok()}};
    if (!g.problems.empty()) gj["problems"] = g.problems;
    if (!g.measures.empty()) gj["measures"] = g.measures;
    groups.push_back(std::move(gj));
  }
  j["groups"] = std::move(groups);
  if (c.floor_measured)
    j["floor"] = {{"ok", c.floor_ok},
                  {"bare_radius_m", Round3(c.bare_radius)},
                  {"bare_limit_m", Round3(c.bare_limit)},
                  {"bare_centre", {Round3(c.bare_centre.x), Round3(c.bare_centre.y)}},
                  {"far_share", Round3(c.far_share)}};
  else
    j["floor"] = nullptr;
  Json wishes = Json::array();
  for (const FunctionalCheck::Wish& w : c.wishes) {
    Json wj{{"category", w.category}, {"asked", w.asked}, {"present", w.present}, {"ok", w.ok}};
    if (!w.why.empty()) wj["why"] = w.why;
    wishes.push_back(std::move(wj));
  }
  j["wishes"] = std::move(wishes);
  j["odd"] = c.odd;
  return j;
}

void FunctionalTally::Add(const FunctionalCheck& c) {
  ++rooms;
  if (!c.essentials.empty()) rooms_essential += c.essentials_ok();
  chairs += c.chairs, chairs_ok += c.chairs_ok, chairs_far += c.chairs_far;
  seating += c.seating, seating_ok += c.seating_ok;
  desks += c.desks, desks_ok += c.desks_ok;
  nightstands += c.nightstands, nightstands_ok += c.nightstands_ok;
  pillows += c.pillows, pillows_ok += c.pillows_ok;
  if (c.floor_measured) ++floor_rooms, floor_ok += c.floor_ok;
  for (const FunctionalCheck::Wish& w : c.wishes) ++wishes, wishes_ok += w.ok;
  odd += static_cast<int>(c.odd.size());
  for (const GroupCheck& g : c.groups) ++groups, groups_ok += g.ok();
  with_essentials += !c.essentials.empty();
}

void FunctionalTally::Add(const FunctionalTally& o) {
  rooms += o.rooms, rooms_essential += o.rooms_essential, with_essentials += o.with_essentials;
  chairs += o.chairs, chairs_ok += o.chairs_ok, chairs_far += o.chairs_far;
  seating += o.seating, seating_ok += o.seating_ok;
  desks += o.desks, desks_ok += o.desks_ok;
  nightstands += o.nightstands, nightstands_ok += o.nightstands_ok;
  pillows += o.pillows, pillows_ok += o.pillows_ok;
  floor_rooms += o.floor_rooms, floor_ok += o.floor_ok;
  wishes += o.wishes, wishes_ok += o.wishes_ok;
  odd += o.odd;
  groups += o.groups, groups_ok += o.groups_ok;
}

Json FunctionalTally::ToJson() const {
  auto pair = [](int ok, int n) { return nlohmann::ordered_json{ok, n}; };
  return {{"rooms", rooms},
          {"essentials", pair(rooms_essential, with_essentials)},
          {"table_chairs", pair(chairs_ok, chairs)},
          {"chairs_far", chairs_far},
          {"seating", pair(seating_ok, seating)},
          {"desks", pair(desks_ok, desks)},
          {"nightstands", pair(nightstands_ok, nightstands)},
          {"pillows", pair(pillows_ok, pillows)},
          {"floor", pair(floor_ok, floor_rooms)},
          {"wishes", pair(wishes_ok, wishes)},
          {"groups", pair(groups_ok, groups)},
          {"odd", odd}};
}

std::string FunctionalTally::Line() const {
  auto frac = [](int ok, int n) { return std::to_string(ok) + "/" + std::to_string(n); };
  return "essentials " + frac(rooms_essential, with_essentials) + " rooms, table chairs " + frac(chairs_ok, chairs) +
         " (" + std::to_string(chairs_far) + " far), seating " + frac(seating_ok, seating) + ", desks " + frac(desks_ok, desks) +
         ", nightstands " + frac(nightstands_ok, nightstands) + ", pillows " + frac(pillows_ok, pillows) + ", floor " +
         frac(floor_ok, floor_rooms) + " rooms, wishes " + frac(wishes_ok, wishes) + ", odd " + std::to_string(odd);
}

std::vector<std::string> FunctionalTally::Cells() const {
  auto frac = [](int ok, int n) { return n ? std::to_string(ok) + "/" + std::to_string(n) : std::string("-"); };
  return {frac(rooms_essential, with_essentials),
          frac(chairs_ok, chairs) + (chairs_far ? " (" + std::to_string(chairs_far) + " far)" : ""),
          frac(seating_ok, seating),
          frac(desks_ok, desks),
          frac(nightstands_ok, nightstands),
          frac(pillows_ok, pillows),
          frac(floor_ok, floor_rooms),
          frac(wishes_ok, wishes),
          std::to_string(odd)};
}

const std::vector<std::string>& FunctionalTally::Header() {
  static const std::vector<std::string> header{"essentials", "table chairs", "seating", "desks", "nightstands",
                                               "pillows",    "floor",        "wishes",  "odd"};
  return header;
}

std::string FailingLine(const FunctionalCheck& c) {
  std::string line;
  const auto add = [&](const std::string& part) { line += (line.empty() ? "" : "; ") + part; };
  if (!c.missing.empty()) {
    std::string m = "missing";
    for (const std::string& e : c.missing) m += " " + e;
    add(c.missing_why.empty() ? m : m + " (" + c.missing_why + ")");
  }
  for (const GroupCheck& g : c.groups)
    for (const std::string& p : g.problems) add("[" + g.kind + "] " + p);
  if (c.floor_measured && !c.floor_ok)
    add("floor: bare disc r " + FormatFixed(c.bare_radius, 2) + " m (<= " + FormatFixed(c.bare_limit, 2) + ") at (" + FormatFixed(c.bare_centre.x, 1) +
        ", " + FormatFixed(c.bare_centre.y, 1) + "), " + FormatFixed(100.0 * c.far_share, 0) + " % of the free floor > 1.5 m from furniture");
  for (const FunctionalCheck::Wish& w : c.wishes)
    if (!w.ok) add("wish " + w.category + " " + std::to_string(w.present) + "/" + std::to_string(w.asked) + " (" + w.why + ")");
  for (const std::string& o : c.odd) add("odd: " + o);
  return line;
}

}  // namespace villa::solver
