// The solver on the asset library's procedural assets (assets/procedural.h): real meshes of many pieces,
// support surfaces and cavities exactly as the generators export them (a bookcase's compartments, a
// wardrobe's shelves, a nightstand's drawer), in an L-shaped room with a door and a window.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <numbers>
#include <string>

#include "assets/procedural.h"
#include "fixtures.h"
#include "solver/solve.h"

namespace villa::solver {
namespace {

using namespace fixtures;

struct Room {
  RoomProblem problem = LShape();
  std::map<std::string, int> counts;

  std::string Add(const std::string& asset_id, const std::string& parent = "floor", Relation relation = Relation::kOnTop) {
    auto made = MakeProceduralAsset(asset_id);
    INFO(asset_id << ": " << (made.ok() ? "" : made.error()));
    REQUIRE(made.ok());
    ProblemObject o;
    o.category = made->record.category;
    o.id = "r/" + o.category + "-" + std::to_string(counts[o.category]++);
    o.asset = made->record;
    o.mesh = std::make_shared<AssetMesh>(made->mesh);
    o.parent = parent;
    o.relation = relation;
    if (parent != "floor" && parent != "wall" && parent != "ceiling") o.priority = Priority::kDecorative;
    problem.objects.push_back(o);
    return o.id;
  }
  void Edge(const std::string& a, SemanticRelation r, const std::string& b) { problem.edges.push_back(DefaultEdge(a, r, b)); }
};

// The summary and the solver's log, for a failure's message.
std::string Story(const SolveSummary& s) {
  std::string out = s.BriefReport();
  for (const std::string& line : s.log) out += line + "\n";
  return out;
}

TEST_CASE("A room of procedural assets (real surfaces and cavities) is furnished with nothing colliding, floating or out", "[solver]") {
  Room room;
  room.problem.walls[0].openings.push_back({0.3, 1.2, room.problem.floor_z, room.problem.floor_z + 2.1});
  room.problem.keep_outs.push_back({{{0.3, 0}, {1.2, 0}, {1.2, 0.9}, {0.3, 0.9}}, room.problem.floor_z,
                                    room.problem.floor_z + 2.1, KeepOutKind::kDoorSweep, "door"});
  const std::string sofa = room.Add("proc:sofa");
  room.problem.objects.back().relation = Relation::kAgainstWall;
  const std::string table = room.Add("proc:table?category=coffee-table&w=1.0&d=0.55&h=0.42");
  room.problem.objects.back().zone.reset();
  room.problem.objects[room.problem.Find(sofa)].zone = InteractionZone{"front", 0.45, {table}};
  room.Edge(table, SemanticRelation::kFrontOf, sofa);
  room.Edge(table, SemanticRelation::kNextTo, sofa);
  const std::string stand = room.Add("proc:tv-stand");
  room.problem.objects.back().relation = Relation::kAgainstWall;
  room.Edge(sofa, SemanticRelation::kFaceTo, stand);
  const std::string shelf = room.Add("proc:bookcase");
  room.problem.objects.back().relation = Relation::kAgainstWall;
  for (int k = 0; k < 4; ++k) room.Add("proc:books?count=5&w=0.2", shelf, Relation::kInside);
  const std::string armchair = room.Add("proc:armchair");
  room.Edge(armchair, SemanticRelation::kFaceTo, table);
  room.Edge(armchair, SemanticRelation::kNear, table);
  room.Add("proc:bowl", table);
  room.Add("proc:cup", table);
  room.Add("proc:vase", stand);
  room.Add("proc:plant");
  room.Add("proc:rug");
  room.Add("proc:frame?category=painting", "wall", Relation::kOnWall);
  const std::string wardrobe = room.Add("proc:wardrobe");
  room.problem.objects.back().relation = Relation::kAgainstWall;
  for (int k = 0; k < 3; ++k) room.Add("proc:folded-clothes", wardrobe, Relation::kInside);
  const std::string nightstand = room.Add("proc:nightstand");
  room.problem.objects.back().relation = Relation::kAgainstWall;
  room.Add("proc:lamp?category=table-lamp", nightstand);

  auto solved = SolveRoom(room.problem, {});
  REQUIRE(solved.ok());
  const SolveSummary& s = solved->summary;
  INFO(Story(s));
  CHECK(s.metrics.cr == 0.0);
  CHECK(s.metrics.fr == 0.0);
  CHECK(s.metrics.obr == 0.0);
  CHECK(s.metrics.csr == 1.0);
  CHECK(s.metrics.inside_edges == 7);
  CHECK(s.removed.empty());
  CHECK(s.metrics.objects == static_cast<int>(room.problem.objects.size()));
}

// Issue 28: things as they are in the world. A book that would fit the nightstand's lower shelf only
// shrunk stands where it fits (it stood 42 mm into the drawer above when the shelf was chosen at the
// smallest scale and the book kept its full size); garments hang from the wardrobe's rail by their hooks,
// turned across it (they stood on one garment's hem, hooks 0.4 m below the rail).
TEST_CASE("Books fit the shelf they stand on and clothes hang from the wardrobe's rail", "[solver]") {
  Room room;
  const std::string nightstand = room.Add("proc:nightstand?drawers=1&w=0.5&d=0.4&h=0.56&style=modern&seed=1");
  room.problem.objects.back().relation = Relation::kAgainstWall;
  // The top is taken first (the most room left then is the lower shelf, 0.218 m clear).
  room.Add("proc:box?w=0.44&d=0.34&h=0.2", nightstand);
  const std::string book = room.Add("proc:books?count=4&w=0.2&d=0.2&h=0.26", nightstand);
  room.problem.objects.back().scale_min = 0.8;
  room.problem.objects.back().scale_max = 1.0;
  const std::string wardrobe = room.Add("proc:wardrobe?cols=2&w=1.2&d=0.6&h=2.0&style=modern&seed=1");
  room.problem.objects.back().relation = Relation::kAgainstWall;
  for (int k = 0; k < 2; ++k) room.Add("proc:hanging-clothes?count=3&w=0.45&d=0.2&h=0.9", wardrobe, Relation::kInside);
  room.Add("proc:folded-clothes", wardrobe, Relation::kInside);

  auto solved = SolveRoom(room.problem, {});
  REQUIRE(solved.ok());
  const SolveSummary& s = solved->summary;
  INFO(Story(s));
  REQUIRE(s.removed.empty());
  CHECK(s.metrics.cr == 0.0);  // parent and child pairs included
  CHECK(s.metrics.csr == 1.0);
  const std::vector<ObjectPlacement>& at = solved->placements;
  const std::vector<ProblemObject>& objects = solved->objects;
  auto index = [&](const std::string& id) {
    for (size_t i = 0; i < objects.size(); ++i)
      if (objects[i].id == id) return static_cast<int>(i);
    FAIL("no " << id);
    return -1;
  };

  const ProblemObject& b = objects[index(book)];
  const ObjectPlacement& bp = at[index(book)];
  const ProblemObject& n = objects[index(nightstand)];
  const SupportSurface& surface = n.asset.support_surfaces.at(bp.surface);
  CHECK(b.asset.size.z * bp.pose.scale <= surface.clear_height * at[index(nightstand)].pose.scale + 1e-9);

  const int w = index(wardrobe);
  const Pose& wp = at[w].pose;
  int hanging = 0;
  for (size_t i = 0; i < objects.size(); ++i) {
    const ProblemObject& o = objects[i];
    if (o.category != "hanging-clothes") continue;
    ++hanging;
    const Cavity& c = objects[w].asset.cavities.at(at[i].cavity);
    REQUIRE(c.rail.has_value());
    const Pose& p = at[i].pose;
    // The hook's bar lies on the rail; the garments turn across it, their hooks over its line.
    CHECK(p.z + o.asset.size.z * p.scale == Approx(wp.z + *c.rail * wp.scale + kHookRise * p.scale).margin(1e-6));
    CHECK(std::abs(std::remainder(p.yaw - wp.yaw, std::numbers::pi)) == Approx(std::numbers::pi / 2).margin(1e-6));
    const double across = -std::sin(wp.yaw) * (p.x - wp.x) + std::cos(wp.yaw) * (p.y - wp.y);
    CHECK(across == Approx(0.5 * (c.min.y + c.max.y) * wp.scale).margin(1e-6));
  }
  CHECK(hanging == 2);
}

}  // namespace
}  // namespace villa::solver
