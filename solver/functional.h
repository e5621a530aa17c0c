#pragma once
// Does a furnished room work as a room? The checks an interior designer makes and CR/FR/OBR cannot see
// (issue 27): the room type's essential pieces are there, every functional group stands as a group
// (chairs at a side of their table with room behind them to pull out, a sofa facing its TV with the coffee
// table before it, nightstands at the head of the bed, a chair at every desk), the floor is used rather
// than furnished in one corner, what the request asked for is there, and small things stand on tops and
// open shelves, not inside closed cells.
//
// Everything is measured from the placed objects alone (poses, sizes, categories, parents), as a stranger's
// tool would measure it, with the thresholds of issue 27 (docs/METRICS.md "Functional checks"): the group
// rules of solver/group_rules.h (the ones the solver keeps members to), a dining or meeting chair's 0.75 m
// clear behind it (a strip as wide as the chair, free of walls and floor furniture), and the floor use of
// rooms of 14 m2 or more: the largest disc on the free floor touching no furniture (rugs and things under
// 0.1 m2 of footprint are not furniture; staircases count as occupied) has a radius of at most max(1.5 m,
// 0.25 sqrt(area)), and at most 30 % of the unoccupied free floor lies farther than 1.5 m from furniture
// (a 5 cm raster).
// Units: metres, radians inside; degrees only in messages and JSON.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "assets/asset.h"
#include "layout/layout.h"
#include "scene/room_context.h"
#include "scene/scene.h"

namespace villa::solver {

// A wish of the request for this room ("a TV", "two armchairs", "bookshelves full of books").
struct FunctionalWish {
  std::string category;
  int count = 1;        // at least this many wanted
  bool fill = false;    // "full of": any number counts
};

// One functional group of the room and how it stands.
struct GroupCheck {
  std::string kind;                   // "dining", "meeting", "seating", "bed", "desk", "kitchen", "bathroom"
  std::string anchor;                 // the hub's id (table, sofa, bed, desk, ...); "" when it is missing
  std::vector<std::string> members;   // ids of the group's other objects
  std::vector<std::string> problems;  // what is wrong, one line each ("chair-3: 0.42 m behind it (>= 0.75)")
  nlohmann::ordered_json measures = nlohmann::ordered_json::object();  // the group's numbers
  bool ok() const { return problems.empty(); }
};

struct FunctionalCheck {
  std::string room;
  Category category = Category::kRoom;
  double area = 0.0;  // m2 of the room polygon

  std::vector<std::string> essentials;  // the categories the room type needs (a sofa, a bed, ...)
  std::vector<std::string> missing;     // those not in the room
  std::string missing_why;              // the planner's or solver's account, when something is missing

  std::vector<GroupCheck> groups;
  // Tallies over the room's objects, for the shares.
  int chairs = 0, chairs_ok = 0, chairs_far = 0;  // chairs of dining and meeting rooms
  int seating = 0, seating_ok = 0;                // living rooms' main seating group
  int desks = 0, desks_ok = 0;
  int nightstands = 0, nightstands_ok = 0;
  int pillows = 0, pillows_ok = 0;                // pillows on beds

  bool floor_measured = false;   // rooms of >= 14 m2
  double bare_radius = 0.0;      // m: the largest furniture-free disc on the free floor
  Point bare_centre;
  double bare_limit = 0.0;       // m: max(1.5, 0.25 sqrt(area))
  double far_share = 0.0;        // share of the unoccupied free floor > 1.5 m from furniture
  bool floor_ok = true;

  struct Wish {
    std::string category;
    int asked = 0;
    int present = 0;
    bool ok = true;
    std::string why;  // when not ok: what the planner or solver said
  };
  std::vector<Wish> wishes;

  std::vector<std::string> odd;  // semantic slips: "kettle-0 stands inside counter-1's closed cell"

  bool essentials_ok() const { return missing.empty(); }
  bool wishes_ok() const;
  bool groups_ok() const;
  // Everything holds.
  bool ok() const { return essentials_ok() && wishes_ok() && groups_ok() && floor_ok && odd.empty(); }
};

// The essential categories of a room type, each a list of alternatives ("bed" | "child-bed"), with the
// number needed: a bedroom's bed, a bathroom's toilet and basin, a kitchen's cooker, fridge, sink and
// counter, a dining room's table and two chairs, a living room's sofa, an office's desk and chair, a
// meeting room's table and two chairs. Empty for balconies, utility rooms and unlabelled rooms.
struct Essential {
  std::vector<std::string_view> categories;
  int count = 1;
  std::string_view name;  // how reports call it ("bed", "dining chairs")
};
const std::vector<Essential>& EssentialsOf(Category room);

struct FunctionalInput {
  const scene::RoomContext* context = nullptr;       // required
  std::vector<const scene::SceneObject*> objects;    // the room's placed objects (with poses)
  // Asset records by id, for the support semantics (closed cells, children's pieces); may be empty.
  std::function<const AssetRecord*(std::string_view id)> assets;
  std::vector<FunctionalWish> wishes;
  std::vector<std::string> notes;                    // the planner's and solver's account (for `why`)
  // The room's semantic edges, when known: an armchair is the seating group's when it has an edge to its
  // coffee table or sofa (a reading chair elsewhere is a zone of its own); without them, when within 1.5 m.
  std::vector<scene::SemanticEdge> edges;
  bool measure_floor = true;  // false: the floor's bare disc and far share are not measured (the critic's
                              // per-move guard needs the groups only)
};

FunctionalCheck CheckRoomFunction(const FunctionalInput& input);

// The room's check as report.json writes it.
nlohmann::ordered_json FunctionalJson(const FunctionalCheck& check);

// Sums over rooms (a villa, a room type, a benchmark): the shares.
struct FunctionalTally {
  int rooms = 0;
  int with_essentials = 0, rooms_essential = 0;  // rooms whose type has essentials / with all of them present
  int chairs = 0, chairs_ok = 0, chairs_far = 0;
  int seating = 0, seating_ok = 0;
  int desks = 0, desks_ok = 0;
  int nightstands = 0, nightstands_ok = 0;
  int pillows = 0, pillows_ok = 0;
  int floor_rooms = 0, floor_ok = 0;           // rooms of >= 14 m2
  int wishes = 0, wishes_ok = 0;
  int odd = 0;
  int groups = 0, groups_ok = 0;
  void Add(const FunctionalCheck& check);
  void Add(const FunctionalTally& other);
  nlohmann::ordered_json ToJson() const;  // {"rooms", "essentials": [ok, n], ...}
  // "essentials 49/49 rooms, chairs 97/97 at their table, ..." for summaries.
  std::string Line() const;
  // Table columns (ok/n, "-" with none): essentials, table chairs (with the far ones), seating, desks,
  // nightstands, pillows, floor, wishes, odd; Header() names them.
  std::vector<std::string> Cells() const;
  static const std::vector<std::string>& Header();
};

// What fails in a room, one line ("missing bed (removed ...); [dining] chair-3: ...; floor: bare disc ...");
// empty when everything holds.
std::string FailingLine(const FunctionalCheck& check);

}  // namespace villa::solver
