// The A-PSSG revised by a model (critic/graph_planner.h) against the local scripted server: a revision
// that drops and adds objects is taken, kept objects keep the draft's attributes; a revision the
// structural validator refuses is sent back with its findings; with none usable the draft stays, saying why.
#include <catch2/catch.hpp>

#include "assets/category.h"
#include "critic/graph_planner.h"
#include "critic/observation.h"
#include "llm/scripted_server.h"
#include "room_fixture.h"

namespace villa {
namespace {

using testing::Completion;
using testing::Json;
using testing::ScriptedServer;

const std::string kRoom = "living-room_0/0";

// The draft as the model would return it, less `drop` and its edges, plus `add` (id, category, parent,
// relation) and `edges` (source, relation, target).
Json Revision(const scene::RoomPlan& draft, const std::string& drop, const std::vector<std::array<std::string, 4>>& add,
              const std::vector<std::array<std::string, 3>>& edges) {
  Json objects = Json::array(), list = Json::array();
  for (const scene::SceneObject& o : draft.objects) {
    const std::string id = critic::ShortId(kRoom, o.id);
    if (id == drop || critic::ShortId(kRoom, o.parent) == drop) continue;
    objects.push_back({{"id", id}, {"category", o.category}, {"parent", critic::ShortId(kRoom, o.parent)},
                       {"relation", std::string(scene::RelationName(o.relation))}});
  }
  for (const auto& a : add) objects.push_back({{"id", a[0]}, {"category", a[1]}, {"parent", a[2]}, {"relation", a[3]}});
  for (const scene::SemanticEdge& e : draft.edges) {
    const std::string s = critic::ShortId(kRoom, e.source), t = critic::ShortId(kRoom, e.target);
    if (s == drop || t == drop) continue;
    list.push_back({{"source", s}, {"relation", std::string(scene::SemanticRelationName(e.relation))}, {"target", t}});
  }
  for (const auto& e : edges) list.push_back({{"source", e[0]}, {"relation", e[1]}, {"target", e[2]}});
  return {{"objects", objects}, {"edges", list}, {"notes", "a plant instead of the floor lamp"}};
}

critic::GraphPlannerOptions Model(const ScriptedServer& server) {
  critic::GraphPlannerOptions o;
  o.llm = testing::ScriptedOptions(server, "villa-planner");
  return o;
}

}  // namespace

TEST_CASE("A model's revision of the priors' graph is taken when the structural validator accepts it", "[critic][graph]") {
  auto room = testing::MakeCriticRoom(kRoom);
  const scene::PlanRequest request{room->context, "a living room with a big plant", 3, &room->layout};
  auto draft = scene::PriorsPlanner().Plan(request);
  REQUIRE(draft.ok());
  bool has_lamp = false;
  for (const scene::SceneObject& o : draft->objects) has_lamp = has_lamp || o.id == kRoom + "/floor-lamp-0";
  REQUIRE(has_lamp);
  const Json revised = Revision(*draft, "floor-lamp-0", {{"plant-7", "plant", "floor", "ontop"}}, {{"plant-7", "next_to", "sofa-0"}});
  ScriptedServer server({Completion(revised.dump())});
  const critic::MllmGraphPlanner planner({}, Model(server));
  auto plan = planner.Plan(request);
  REQUIRE(plan.ok());
  CHECK(plan->record.planner == "mllm");
  CHECK(plan->objects.size() == draft->objects.size());  // one out, one in
  const scene::SceneObject* plant = nullptr;
  for (const scene::SceneObject& o : plan->objects) {
    CHECK(o.id != kRoom + "/floor-lamp-0");
    if (o.id == kRoom + "/plant-7") plant = &o;
  }
  REQUIRE(plant);
  CHECK(plant->origin == scene::Origin::kCritic);
  CHECK(plant->size.z == Approx(0.5 * (FindCategory("plant")->size_min.z + FindCategory("plant")->size_max.z)));
  bool edge = false;
  for (const scene::SemanticEdge& e : plan->edges) edge = edge || (e.source == plant->id && e.relation == scene::SemanticRelation::kNextTo);
  CHECK(edge);
  // Kept objects keep the draft's attributes (the coffee table's edge parameters, the sofa's zone).
  for (const scene::SemanticEdge& e : plan->edges)
    if (e.source == kRoom + "/coffee-table-0" && e.relation == scene::SemanticRelation::kFrontOf) CHECK(e.params.min_gap == 0.45);
  const auto bodies = server.bodies();
  REQUIRE(bodies.size() == 1);
  CHECK(bodies[0]["response_format"]["json_schema"]["name"] == "room_graph");
  const std::string user = bodies[0]["messages"][1]["content"].get<std::string>();
  CHECK(user.find("with a big plant") != std::string::npos);
  CHECK(user.find("\"floor-lamp-0\"") != std::string::npos);
  CHECK(planner.requests() == 1);
}

TEST_CASE("A revision the validator refuses goes back with its findings, with none usable the draft stays", "[critic][graph]") {
  auto room = testing::MakeCriticRoom(kRoom);
  const scene::PlanRequest request{room->context, "", 3, &room->layout};
  auto draft = scene::PriorsPlanner().Plan(request);
  REQUIRE(draft.ok());
  // A remote control put on the floor lamp: the lamp offers no surface (the validator's provider rule).
  const Json refused = Revision(*draft, "", {{"remote-5", "remote", "floor-lamp-0", "ontop"}}, {});
  const Json good = Revision(*draft, "", {}, {});
  ScriptedServer server({Completion(refused.dump()), Completion(good.dump())});
  const critic::MllmGraphPlanner planner({}, Model(server));
  auto plan = planner.Plan(request);
  REQUIRE(plan.ok());
  CHECK(plan->record.planner == "mllm");
  const auto bodies = server.bodies();
  REQUIRE(bodies.size() == 2);
  const std::string feedback = bodies[1]["messages"].back()["content"].get<std::string>();
  CHECK(feedback.find("breaks the scene rules") != std::string::npos);
  CHECK(feedback.find("remote-5") != std::string::npos);

  // Unknown categories and ids, every turn: the draft, with a note.
  Json bad = good;
  bad["objects"].push_back({{"id", "spaceship-0"}, {"category", "spaceship"}, {"parent", "floor"}, {"relation", "ontop"}});
  ScriptedServer stubborn({Completion(bad.dump()), Completion(bad.dump()), Completion(bad.dump())});
  const critic::MllmGraphPlanner stubborn_planner({}, Model(stubborn));
  auto kept = stubborn_planner.Plan(request);
  REQUIRE(kept.ok());
  CHECK(kept->record.planner == "priors");
  CHECK(kept->objects == draft->objects);
  REQUIRE_FALSE(kept->record.notes.empty());
  CHECK(kept->record.notes.back().find("the model's graph was not used") != std::string::npos);
  CHECK(kept->record.notes.back().find("\"spaceship\" is not a category of the vocabulary") != std::string::npos);
}

}  // namespace villa
