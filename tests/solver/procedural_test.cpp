// The solver on the asset library's procedural assets (assets/procedural.h): real meshes of many pieces,
// support surfaces and cavities exactly as the generators export them (a bookcase's compartments, a
// wardrobe's shelves, a nightstand's drawer), in an L-shaped room with a door and a window.
#include <catch2/catch.hpp>

#include <map>
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
  std::string log;
  for (const std::string& line : s.log) log += line + "\n";
  INFO(s.BriefReport() << log);
  CHECK(s.metrics.cr == 0.0);
  CHECK(s.metrics.fr == 0.0);
  CHECK(s.metrics.obr == 0.0);
  CHECK(s.metrics.csr == 1.0);
  CHECK(s.metrics.inside_edges == 7);
  CHECK(s.removed.empty());
  CHECK(s.metrics.objects == static_cast<int>(room.problem.objects.size()));
}

}  // namespace
}  // namespace villa::solver
