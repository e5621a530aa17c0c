#include "critic/graph_planner.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "assets/category.h"
#include "critic/observation.h"
#include "critic/prompts.h"
#include "layout/geometry.h"
#include "scene/validate.h"

namespace villa::critic {
namespace {

using Json = nlohmann::ordered_json;

std::string Cut(const std::string& text, size_t n = 80) { return text.size() <= n ? text : text.substr(0, n) + "..."; }

std::string Fixed(double v, int digits) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", digits, v);
  return text;
}

// "sofa-0": the category and a number, the form the ids' last part takes.
bool LocalIdOf(const std::string& id, const std::string& category) {
  if (id.size() <= category.size() + 1 || id.compare(0, category.size(), category) != 0 || id[category.size()] != '-') return false;
  for (size_t i = category.size() + 1; i < id.size(); ++i)
    if (!std::isdigit(static_cast<unsigned char>(id[i]))) return false;
  return true;
}

bool RelationFitsParent(scene::Relation relation, const std::string& parent) {
  switch (relation) {
    case scene::Relation::kOnWall: return parent == scene::kParentWall;
    case scene::Relation::kHanging: return parent == scene::kParentCeiling;
    case scene::Relation::kAgainstWall: return parent == scene::kParentFloor;
    case scene::Relation::kOnTop: return parent != scene::kParentWall && parent != scene::kParentCeiling;
    case scene::Relation::kInside: return !scene::IsRootParent(parent);
  }
  return false;
}

std::string DraftJson(const scene::RoomPlan& draft, const std::string& room) {
  Json objects = Json::array(), edges = Json::array();
  for (const scene::SceneObject& o : draft.objects)
    objects.push_back({{"id", ShortId(room, o.id)},
                       {"category", o.category},
                       {"parent", ShortId(room, o.parent)},
                       {"relation", std::string(scene::RelationName(o.relation))}});
  for (const scene::SemanticEdge& e : draft.edges)
    edges.push_back({{"source", ShortId(room, e.source)},
                     {"relation", std::string(scene::SemanticRelationName(e.relation))},
                     {"target", ShortId(room, e.target)}});
  return Json{{"objects", objects}, {"edges", edges}}.dump();
}

}  // namespace

std::string GraphPlannerOptions::Check() const {
  std::string message;
  if (!llm.IsValid(&message)) return "graph planner: " + message;
  if (!chat.IsValid(&message)) return "graph planner: " + message;
  return "";
}

std::string GraphUserText(const scene::RoomContext& room, const std::string& request, const scene::RoomPlan& draft) {
  Box2 box = BoundingBox(room.polygon);
  int doors = 0, windows = 0;
  for (const scene::ContextOpening& o : room.openings) (o.kind == ElementKind::kWindow ? windows : doors)++;
  std::string out = "Room: " + std::string(CategoryDisplayName(room.category)) + " " + room.name + ", level " +
                    std::to_string(room.level) + ", " + Fixed(room.area, 1) + " m2 (" + Fixed(room.furnishable_area, 1) +
                    " m2 free to furnish), about " + Fixed(box.max_x - box.min_x, 1) + " x " + Fixed(box.max_y - box.min_y, 1) +
                    " m, " + std::to_string(doors) + " door(s) or openings, " + std::to_string(windows) + " window(s).\n";
  out += "Request for the house: " + (request.empty() ? std::string("(none: a usual room of its type)") : request) + "\n";
  out += "Draft graph: " + DraftJson(draft, room.name);
  return out;
}

Result<scene::RoomPlan> ReadGraph(const nlohmann::json& answer, const scene::RoomContext& room, const scene::RoomPlan& draft,
                                  const Layout* layout) {
  if (!answer.contains("objects") || !answer["objects"].is_array()) return Error{"objects: missing or not a list"};
  if (!answer.contains("edges") || !answer["edges"].is_array()) return Error{"edges: missing or not a list"};
  std::map<std::string, const scene::SceneObject*> drafted;
  for (const scene::SceneObject& o : draft.objects) drafted[o.id] = &o;
  scene::RoomPlan plan;
  plan.record = draft.record;
  plan.record.planner = "mllm";
  plan.summary = draft.summary;
  std::set<std::string> ids;
  // Objects: ids, categories and physical edges first, parents checked once every id is known.
  for (size_t i = 0; i < answer["objects"].size(); ++i) {
    const nlohmann::json& a = answer["objects"][i];
    const std::string path = "objects[" + std::to_string(i) + "]";
    auto text = [&](const char* key) -> Result<std::string> {
      if (!a.is_object() || !a.contains(key) || !a[key].is_string()) return Error{path + "." + key + ": missing or not a string"};
      return a[key].get<std::string>();
    };
    auto id = text("id"), category = text("category"), parent = text("parent"), relation = text("relation");
    for (auto* r : {&id, &category, &parent, &relation})
      if (!r->ok()) return Error{r->error()};
    const CategoryInfo* info = FindCategory(*category);
    if (!info) return Error{path + ".category: \"" + Cut(*category) + "\" is not a category of the vocabulary"};
    const std::string local = ShortId(room.name, *id);
    if (!LocalIdOf(local, *category))
      return Error{path + ".id: \"" + Cut(*id) + "\" must be the category and a number (" + *category + "-0)"};
    const std::string full = FullId(room.name, local);
    if (!ids.insert(full).second) return Error{path + ".id: \"" + local + "\" appears twice"};
    auto rel = scene::ParseRelation(*relation);
    if (!rel) return Error{path + ".relation: \"" + Cut(*relation) + "\": expected ontop, inside, against_wall, on_wall or hanging"};
    const std::string parent_id = scene::IsRootParent(*parent) ? *parent : FullId(room.name, *parent);
    if (!RelationFitsParent(*rel, parent_id))
      return Error{path + ": relation " + *relation + " does not go with parent \"" + Cut(*parent) +
                   "\" (against_wall: floor, on_wall: wall, hanging: ceiling, inside: an object)"};
    scene::SceneObject o;
    auto kept = drafted.find(full);
    if (kept != drafted.end() && kept->second->category == *category) {
      o = *kept->second;
      if (o.parent != parent_id || o.relation != *rel) o.surface.reset(), o.cavity.reset();
    } else {
      o.id = full;
      o.category = *category;
      o.room = room.name;
      o.level = room.level;
      o.size = (info->size_min + info->size_max) * 0.5;
      o.affordances = info->affordances;
      o.origin = scene::Origin::kCritic;
      if (info->zone && (o.affordances & kInteractor)) o.interaction_zone = scene::InteractionZone{info->zone->side, info->zone->depth, {}};
    }
    o.parent = parent_id;
    o.relation = *rel;
    plan.objects.push_back(std::move(o));
  }
  for (size_t i = 0; i < plan.objects.size(); ++i) {
    const scene::SceneObject& o = plan.objects[i];
    if (!scene::IsRootParent(o.parent) && !ids.count(o.parent))
      return Error{"objects[" + std::to_string(i) + "].parent: \"" + ShortId(room.name, o.parent) + "\" is not an object of the graph"};
  }
  for (scene::SceneObject& o : plan.objects)
    if (o.interaction_zone) std::erase_if(o.interaction_zone->exempt, [&](const std::string& e) { return !ids.count(e); });
  // Edges: known ids, known relations; a drafted edge keeps its parameters.
  std::map<std::tuple<std::string, int, std::string>, scene::EdgeParams> draft_params;
  for (const scene::SemanticEdge& e : draft.edges) draft_params[{e.source, static_cast<int>(e.relation), e.target}] = e.params;
  std::set<std::tuple<std::string, int, std::string>> seen;
  for (size_t i = 0; i < answer["edges"].size(); ++i) {
    const nlohmann::json& a = answer["edges"][i];
    const std::string path = "edges[" + std::to_string(i) + "]";
    if (!a.is_object() || !a.contains("source") || !a["source"].is_string() || !a.contains("target") || !a["target"].is_string() ||
        !a.contains("relation") || !a["relation"].is_string())
      return Error{path + ": needs \"source\", \"relation\" and \"target\" strings"};
    auto relation = scene::ParseSemanticRelation(a["relation"].get<std::string>());
    if (!relation) return Error{path + ".relation: \"" + Cut(a["relation"].get<std::string>()) + "\" is not a relation"};
    const std::string s = FullId(room.name, a["source"].get<std::string>()), t = FullId(room.name, a["target"].get<std::string>());
    for (const auto& [end, name] : {std::pair{&s, "source"}, std::pair{&t, "target"}})
      if (!ids.count(*end)) return Error{path + "." + name + ": \"" + Cut(ShortId(room.name, *end)) + "\" is not an object of the graph"};
    if (s == t) return Error{path + ": an edge joins two different objects"};
    const auto key = std::make_tuple(s, static_cast<int>(*relation), t);
    if (!seen.insert(key).second) continue;
    auto params = draft_params.find(key);
    plan.edges.push_back({s, *relation, t, params == draft_params.end() ? scene::EdgeParams{} : params->second});
  }
  if (answer.contains("notes") && answer["notes"].is_string() && !answer["notes"].get<std::string>().empty())
    plan.record.notes.push_back("model: " + Cut(answer["notes"].get<std::string>(), 300));
  plan.summary.objects = static_cast<int>(plan.objects.size());
  plan.summary.from_prompt = 0;
  for (const scene::SceneObject& o : plan.objects) plan.summary.from_prompt += o.origin == scene::Origin::kPrompt;
  // The gate: the structural validator of the scene (a plan lists only its room).
  if (layout) {
    scene::ValidateOptions vo;
    vo.all_rooms = false;
    const auto findings = scene::ValidateScene(scene::PlanSceneFile({}, {}, room.name, plan), *layout, {}, vo);
    if (!findings.empty()) return Error{"the graph breaks the scene rules:\n" + scene::FormatFindings(findings)};
  }
  return plan;
}

MllmGraphPlanner::MllmGraphPlanner(scene::PlannerOptions priors, GraphPlannerOptions options)
    : priors_(priors), options_(std::move(options)) {}

Result<scene::RoomPlan> MllmGraphPlanner::Plan(const scene::PlanRequest& request) const {
  auto draft = priors_.Plan(request);
  if (!draft.ok() || draft->objects.empty()) return draft;  // nothing fits: nothing to revise
  scene::RoomPlan revised;
  const JsonCheck check = [&](const nlohmann::json& j) {
    auto plan = ReadGraph(j, *request.room, *draft, request.layout);
    if (!plan.ok()) return plan.error();
    revised = std::move(*plan);
    return std::string();
  };
  LlmOptions llm = options_.llm;
  if (!llm.seed) llm.seed = request.seed;
  const JsonChatResult asked = AskJson(llm,
                                       {{"system", GraphSystemPrompt(), {}},
                                        {"user", GraphUserText(*request.room, request.text, *draft), {}}},
                                       options_.json_schema ? GraphResponseFormat() : nullptr, check, options_.chat);
  requests_ += asked.requests;
  cache_hits_ += asked.cache_hits;
  tokens_ += asked.prompt_tokens + asked.completion_tokens;
  const std::string cost = std::to_string(asked.turns.size()) + " turn(s), " + std::to_string(asked.requests) + " request(s), " +
                           std::to_string(asked.prompt_tokens + asked.completion_tokens) + " tokens";
  if (!asked.accepted) {
    draft->record.notes.push_back("the model's graph was not used (" + cost + "): " + Cut(asked.error, 300));
    return draft;
  }
  revised.record.notes.push_back("graph revised by the model (" + cost + ")");
  return revised;
}

}  // namespace villa::critic
