// The bridge between the scene model and the solver (solver/scene_problem.h): a room's context, planned
// objects and the building become a RoomProblem; the solution becomes posed scene objects again.
#include <catch2/catch.hpp>

#include "layout/geometry.h"
#include "mesh/geometry2d.h"

#include <map>
#include <numbers>

#include "assets/procedural.h"
#include "building/building.h"
#include "layout/layout_io.h"
#include "scene/room_context.h"
#include "solver/scene_problem.h"

using namespace villa;

namespace {

struct House {
  Layout layout;
  BuildingMesh building;
  scene::RoomContext living;
};

House LoadHouse() {
  auto layout = LoadLayout(std::string(VILLA_FIXTURE_DIR) + "/layouts/house_one_floor.json");
  REQUIRE(layout.ok());
  House h{*layout, {}, {}};
  auto building = BuildBuilding(h.layout, {});
  REQUIRE(building.ok());
  h.building = std::move(*building);
  auto context = scene::RoomContextOf(h.layout, h.building, {}, "living-room_0/0");
  REQUIRE(context.ok());
  h.living = std::move(*context);
  return h;
}

scene::SceneObject Planned(const std::string& name, const std::string& asset, const std::string& parent = "floor",
                           scene::Relation relation = scene::Relation::kOnTop) {
  scene::SceneObject o;
  o.id = "living-room_0/0/" + name;
  o.category = name.substr(0, name.rfind('-'));
  o.room = "living-room_0/0";
  o.asset = asset;
  o.parent = scene::IsRootParent(parent) ? parent : "living-room_0/0/" + parent;
  o.relation = relation;
  o.affordances = kConsumer;
  return o;
}

// Procedural records and meshes by id; "bad:" ids get a mesh twice the record's size.
solver::AssetResolver Resolver() {
  return [](const std::string& id) -> Result<std::pair<AssetRecord, std::shared_ptr<const AssetMesh>>> {
    const bool bad = id.rfind("bad:", 0) == 0;
    auto made = MakeProceduralAsset(bad ? id.substr(4) : id);
    if (!made.ok()) return Error{made.error()};
    if (bad)
      for (AssetMeshPart& p : made->mesh.parts)
        for (Vec3& v : p.mesh.vertices) v = v * 2.0;
    return std::make_pair(made->record, std::make_shared<const AssetMesh>(std::move(made->mesh)));
  };
}

}  // namespace

TEST_CASE("A room's context, objects and building become the solver's problem", "[solver][scene_problem]") {
  House h = LoadHouse();
  std::vector<scene::SceneObject> objects = {
      Planned("sofa-0", "proc:sofa", "floor", scene::Relation::kAgainstWall),
      Planned("coffee-table-0", "proc:table?category=coffee-table"),
      Planned("bowl-0", "proc:bowl", "coffee-table-0"),
      Planned("plant-0", "proc:plant"),                              // no cavity: the books cannot go in
      Planned("books-0", "proc:books", "plant-0", scene::Relation::kInside),
      Planned("vase-0", "proc:vase", "books-0"),                     // its parent is left out, so it is
      Planned("armchair-0", "bad:proc:armchair"),                    // its mesh leaves its box
      Planned("painting-0", "proc:frame?category=painting", "wall", scene::Relation::kOnWall),
  };
  objects[0].origin = scene::Origin::kPrompt;
  objects[0].interaction_zone = scene::InteractionZone{"front", 0.45, {objects[1].id, objects[6].id}};
  std::vector<scene::SemanticEdge> edges = {
      {objects[1].id, scene::SemanticRelation::kFrontOf, objects[0].id, {std::nullopt, 0.45, 0.6, std::nullopt}},
      {objects[0].id, scene::SemanticRelation::kFaceTo, objects[1].id, {20.0, std::nullopt, std::nullopt, std::nullopt}},
      {objects[6].id, scene::SemanticRelation::kNear, objects[1].id, {}},
  };
  auto mapped = solver::RoomProblemOf(h.living, h.building, objects, edges, Resolver());
  REQUIRE(mapped.ok());
  const solver::RoomProblem& p = mapped->problem;
  REQUIRE(p.Check().ok());

  // The room: its free floor, walls with the window as an opening from sill to head, keep-outs one to one.
  CHECK(p.free_floor == h.living.free_floor.front());
  CHECK(p.floor_z == Approx(h.living.floor_z));
  CHECK(p.walls.size() == h.living.walls.size());
  bool window = false;
  for (const solver::WallEdge& w : p.walls)
    for (const solver::WallOpening& o : w.openings)
      window = window || (o.z0 == Approx(p.floor_z + 0.9) && o.z1 == Approx(p.floor_z + 2.1));
  CHECK(window);
  // The context's keep-outs one to one, and the way through the room between its doors (issue 27): every
  // corridor 0.7 m wide, on the free floor.
  size_t circulation = 0;
  for (const solver::KeepOut& k : p.keep_outs) {
    if (k.kind != solver::KeepOutKind::kCirculation) continue;
    ++circulation;
    REQUIRE(k.polygon.size() == 4);
    CHECK(geo::Dist(k.polygon[0], k.polygon[3]) == Approx(0.7));
    CHECK(PointInRing(geo::Lerp(geo::Lerp(k.polygon[0], k.polygon[3], 0.5), geo::Lerp(k.polygon[1], k.polygon[2], 0.5), 0.5),
                      p.free_floor, 0.0));
  }
  CHECK(p.keep_outs.size() - circulation == h.living.keep_outs.size());
  int doors = 0;
  for (const scene::ContextOpening& o : h.living.openings) doors += o.kind != ElementKind::kWindow;
  CHECK((doors >= 2) == (circulation > 0));
  // Building parts: walls, door leaves, panes and their frames of level 0 near the room, nothing else.
  CHECK(p.building.size() >= 4);
  for (const solver::BuildingPart& b : p.building) {
    INFO(b.name);
    CHECK((b.name.rfind("exterior-wall", 0) == 0 || b.name.rfind("interior-wall", 0) == 0 || b.name.rfind("door", 0) == 0 ||
           b.name.rfind("glass", 0) == 0 || b.name.rfind("window-frame", 0) == 0));
  }

  // Objects: the books (a plant has no cavity), the vase on them and the armchair (mesh outside its box) are
  // left out, each with why; the rest keep their relations; the sofa from the request is named.
  std::vector<std::string> ids;
  for (const solver::ProblemObject& o : p.objects) ids.push_back(o.id);
  CHECK(ids == std::vector<std::string>{objects[0].id, objects[1].id, objects[2].id, objects[3].id, objects[7].id});
  REQUIRE(mapped->dropped.size() == 3);
  CHECK(mapped->dropped[0].find("armchair-0: asset bad:proc:armchair: mesh reaches") != std::string::npos);
  CHECK(mapped->dropped[1].find("books-0: its parent's asset") != std::string::npos);
  CHECK(mapped->dropped[2].find("vase-0: its parent living-room_0/0/books-0 is left out") != std::string::npos);
  const solver::ProblemObject& sofa = p.objects[0];
  CHECK(sofa.relation == solver::Relation::kAgainstWall);
  // Named by the request, and the living room's essential piece (issue 27): essential ranks higher.
  CHECK(sofa.priority == solver::Priority::kEssential);
  CHECK(solver::IsProtected(sofa.priority));
  CHECK(p.objects[2].priority == solver::Priority::kDecorative);  // a small prior object on furniture
  CHECK(p.objects[3].priority == solver::Priority::kPrior);
  CHECK(sofa.scale_min == Approx(solver::kSceneScaleMin));
  REQUIRE(sofa.zone);
  CHECK(sofa.zone->exempt == std::vector<std::string>{objects[1].id});  // the armchair is gone
  // Edges: front_of with a gap range also gives a gap edge; face_to keeps its angle; the armchair's is gone.
  REQUIRE(p.edges.size() == 3);
  CHECK(p.edges[0].relation == solver::SemanticRelation::kFrontOf);
  CHECK(p.edges[1].relation == solver::SemanticRelation::kNear);
  CHECK(p.edges[1].min_gap == Approx(0.45));
  CHECK(p.edges[1].max_gap == Approx(0.6));
  CHECK(p.edges[2].max_angle == Approx(20.0 * std::numbers::pi / 180.0));
}

TEST_CASE("A solved arrangement becomes posed scene objects, and removed ones leave zones and edges", "[solver][scene_problem]") {
  House h = LoadHouse();
  std::vector<scene::SceneObject> objects = {Planned("sofa-0", "proc:sofa", "floor", scene::Relation::kAgainstWall),
                                             Planned("coffee-table-0", "proc:table?category=coffee-table"),
                                             Planned("bowl-0", "proc:bowl", "coffee-table-0"),
                                             Planned("painting-0", "proc:frame?category=painting", "wall", scene::Relation::kOnWall)};
  objects[0].interaction_zone = scene::InteractionZone{"front", 0.45, {objects[1].id}};
  objects[0].hints = {"far_from_door"};
  auto mapped = solver::RoomProblemOf(h.living, h.building, objects, {}, Resolver());
  REQUIRE(mapped.ok());
  solver::RoomSolution solution;
  // The coffee table was removed (and the bowl with it); the sofa and the painting are posed.
  solution.objects = {mapped->problem.objects[0], mapped->problem.objects[3]};
  solver::ObjectPlacement sofa;
  sofa.pose = {2.0, 1.0, h.living.floor_z, std::numbers::pi / 2, 0.9};
  sofa.wall = 1;
  sofa.placed = true;
  solver::ObjectPlacement painting;
  painting.pose = {3.0, 4.5, h.living.floor_z + 1.4, std::numbers::pi, 1.0};
  painting.wall = 2;
  painting.placed = true;
  solution.placements = {sofa, painting};
  auto posed = solver::SolvedSceneObjects(mapped->problem, solution, objects);
  REQUIRE(posed.size() == 2);
  const scene::SceneObject& s = posed[0];
  REQUIRE(s.pose);
  CHECK(s.pose->x == 2.0);
  CHECK(s.pose->yaw == Approx(std::numbers::pi / 2));
  CHECK(s.scale == std::array<double, 3>{0.9, 0.9, 0.9});
  CHECK(s.size.x == Approx(mapped->problem.objects[0].asset.size.x * 0.9));
  REQUIRE(s.wall);
  CHECK(s.wall->edge == mapped->problem.walls[1].edge);
  CHECK(s.hints == objects[0].hints);                // what the solver does not keep comes from the plan
  CHECK(s.interaction_zone->exempt.empty());         // the removed coffee table is no longer exempt
  CHECK(posed[1].wall->edge == mapped->problem.walls[2].edge);
  CHECK_FALSE(posed[1].surface);
}
