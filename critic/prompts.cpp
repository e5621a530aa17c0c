#include "critic/prompts.h"

#include <cmath>
#include <cstdio>

#include "assets/category.h"
#include "critic/observation.h"

namespace villa::critic {
namespace {

using Json = nlohmann::ordered_json;

std::string Cut(const std::string& text, size_t n = 80) { return text.size() <= n ? text : text.substr(0, n) + "..."; }
std::string Shown(const nlohmann::json& value) { return Cut(value.dump()); }

Json Nullable(const char* type) { return Json{{"type", Json::array({type, "null"})}}; }

std::string Fixed(double v, int digits) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", digits, v);
  return text;
}

// A known object id, as the model wrote it (short or full), completed; "" with `error` set when unknown.
std::string KnownId(const nlohmann::json& value, const std::string& path, const std::string& room, const std::set<std::string>& ids,
                    std::string* error) {
  if (!value.is_string()) {
    *error = path + ": " + Shown(value) + " is not an object id";
    return "";
  }
  const std::string id = FullId(room, value.get<std::string>());
  if (!ids.count(id)) {
    std::string known;
    for (const std::string& i : ids) known += (known.empty() ? "" : ", ") + ShortId(room, i);
    *error = path + ": \"" + Cut(value.get<std::string>()) + "\" is not an object of the room (objects: " + Cut(known, 400) + ")";
    return "";
  }
  return id;
}

const std::vector<std::string>& ActionNames() {
  static const std::vector<std::string> names{"add_entity", "remove_entity", "update_pose", "update_scale"};
  return names;
}
const std::vector<std::string>& PhysicalNames() {
  static const std::vector<std::string> names{"ontop", "inside", "against_wall", "on_wall", "hanging"};
  return names;
}

}  // namespace

Json StrictFormat(const std::string& name, const Json& schema) {
  return Json{{"type", "json_schema"}, {"json_schema", Json{{"name", name}, {"strict", true}, {"schema", schema}}}};
}

std::string VocabularyLine() {
  std::string out;
  for (const CategoryInfo& c : Categories()) out += (out.empty() ? "" : ", ") + std::string(c.name);
  return out;
}

// ---- evaluation

std::string EvaluationSystemPrompt() {
  return "You review furnished rooms of a house for a furnishing program. For one room you get five pictures "
         "(first a view straight down, then views from the room's four corners; the walls nearest the camera are "
         "cut off near the floor so you can look in, and every object carries its id as a small label) and a text "
         "state: the room's walls and openings, every object with its id, category, what it rests on, its position, "
         "turn and size, the relations the room's plan asks for (marked ok or UNMET, with the measured value), the "
         "zones that must stay free in front of objects, and what a physics check found.\n"
         "Coordinates are metres on the floor plan: x grows to the east, y to the north, z upwards. A yaw in "
         "degrees says where an object's front points: 0 south (-y), 90 east (+x), 180 north, -90 west.\n"
         "Judge whether the room works for the people who asked for it: can each thing be used (sit at the table, "
         "open the wardrobe, watch the screen from the sofa, reach the bed from both sides)? Does anything look "
         "wrong for a real home (a chair turned to a wall, a cabinet in front of a door or a window, a lamp in a "
         "walkway, things that belong together far apart)? Take the UNMET relations into account but use your own "
         "eyes too.\n"
         "Give a score from 0 (unusable) to 10 (nothing to improve) and list each problem with the ids of the "
         "objects it concerns. Answer with one JSON object and nothing else.";
}

std::string EvaluationUserText(const std::string& request, const std::string& state) {
  return "Request for the house: " + (request.empty() ? std::string("(none: a usual room of its type)") : request) +
         "\n\nState of the room:\n" + state;
}

Json EvaluationResponseFormat() {
  Json problem{{"type", "object"},
               {"additionalProperties", false},
               {"required", Json::array({"objects", "problem"})},
               {"properties", Json{{"objects", Json{{"type", "array"}, {"items", Json{{"type", "string"}}}}},
                                   {"problem", Json{{"type", "string"}}}}}};
  Json schema{{"type", "object"},
              {"additionalProperties", false},
              {"required", Json::array({"score", "problems"})},
              {"properties", Json{{"score", Json{{"type", "number"}, {"minimum", 0}, {"maximum", 10}}},
                                  {"problems", Json{{"type", "array"}, {"items", problem}}}}}};
  return StrictFormat("room_evaluation", schema);
}

Result<Evaluation> ReadEvaluation(const nlohmann::json& answer, const std::string& room, const std::set<std::string>& ids) {
  Evaluation e;
  if (!answer.contains("score") || !answer["score"].is_number()) return Error{"score: missing or not a number"};
  e.score = answer["score"].get<double>();
  if (!(e.score >= 0.0 && e.score <= 10.0)) return Error{"score: " + Shown(answer["score"]) + " is not in [0, 10]"};
  if (!answer.contains("problems") || !answer["problems"].is_array()) return Error{"problems: missing or not a list"};
  for (size_t i = 0; i < answer["problems"].size(); ++i) {
    const nlohmann::json& p = answer["problems"][i];
    const std::string path = "problems[" + std::to_string(i) + "]";
    if (!p.is_object() || !p.contains("problem") || !p["problem"].is_string())
      return Error{path + ": needs \"objects\" (ids) and \"problem\" (words)"};
    Evaluation::Problem problem;
    problem.problem = p["problem"].get<std::string>();
    if (p.contains("objects")) {
      if (!p["objects"].is_array()) return Error{path + ".objects: " + Shown(p["objects"]) + " is not a list of ids"};
      for (size_t k = 0; k < p["objects"].size(); ++k) {
        std::string error;
        const std::string id = KnownId(p["objects"][k], path + ".objects[" + std::to_string(k) + "]", room, ids, &error);
        if (!error.empty()) return Error{error};
        problem.objects.push_back(id);
      }
    }
    e.problems.push_back(std::move(problem));
  }
  return e;
}

// ---- actions

std::string ActionsSystemPrompt() {
  return "You rearrange one furnished room to fix the problems a review found. You get the same pictures and text "
         "state as the reviewer (metres on the floor plan, x east, y north; yaw in degrees, 0 faces south (-y), 90 "
         "faces east (+x)) and the review itself. Answer with a list of actions:\n"
         "- update_pose: move object \"id\" so its footprint centre is at x, y and turn it to yaw (null keeps the "
         "present value). An object that stands with its back to a wall stays on a wall: give \"wall\" (an index "
         "of the state's wall list) to move it to another one. What stands on or inside an object moves with it.\n"
         "- update_scale: resize object \"id\" to \"scale\" times its modelled size (0.8 to 1).\n"
         "- remove_entity: take object \"id\" (and what stands on or in it) out of the room.\n"
         "- add_entity: bring in a new object of \"category\" (one of the vocabulary below) resting on \"parent\" "
         "(floor, wall, ceiling, or the id of the object it stands on or in) with \"relation\" (ontop, inside, "
         "against_wall, on_wall or hanging); x, y and yaw may be null to let the program find a free place; \"id\" "
         "is ignored (write \"new\").\n"
         "A physics program carries the actions out in order. It refuses a move that would make things collide, "
         "float or leave the room, or shifts the object to the nearest free place, and it tells you next round "
         "what it did. Change only what fixes a problem, prefer moving to removing, and remove only what cannot be "
         "placed well anywhere. Fill every field of every action and use null for the fields an action does not "
         "need. Answer with one JSON object and nothing else; an empty list means the room is fine.\n"
         "Vocabulary: " +
         VocabularyLine();
}

std::string ActionsUserText(const std::string& request, const std::string& state, const Evaluation& evaluation,
                            const std::string& room) {
  std::string review = "score " + Fixed(evaluation.score, 1) + "/10";
  for (const Evaluation::Problem& p : evaluation.problems) {
    review += "\n- ";
    for (size_t i = 0; i < p.objects.size(); ++i) review += (i ? ", " : "") + ShortId(room, p.objects[i]);
    review += (p.objects.empty() ? "" : ": ") + p.problem;
  }
  return EvaluationUserText(request, state) + "\nReview:\n" + review;
}

Json ActionsResponseFormat() {
  Json relation{{"type", Json::array({"string", "null"})}, {"enum", Json::array({"ontop", "inside", "against_wall", "on_wall", "hanging", nullptr})}};
  Json action{{"type", "object"},
              {"additionalProperties", false},
              {"required", Json::array({"action", "id", "x", "y", "yaw", "scale", "wall", "category", "parent", "relation", "reason"})},
              {"properties", Json{{"action", Json{{"type", "string"}, {"enum", ActionNames()}}},
                                  {"id", Json{{"type", "string"}}},
                                  {"x", Nullable("number")},
                                  {"y", Nullable("number")},
                                  {"yaw", Nullable("number")},
                                  {"scale", Nullable("number")},
                                  {"wall", Nullable("integer")},
                                  {"category", Nullable("string")},
                                  {"parent", Nullable("string")},
                                  {"relation", relation},
                                  {"reason", Json{{"type", "string"}}}}}};
  Json schema{{"type", "object"},
              {"additionalProperties", false},
              {"required", Json::array({"actions"})},
              {"properties", Json{{"actions", Json{{"type", "array"}, {"items", action}}}}}};
  return StrictFormat("room_actions", schema);
}

Result<std::vector<ProposedAction>> ReadActions(const nlohmann::json& answer, const std::string& room,
                                                const std::set<std::string>& ids, int walls, int max_actions) {
  if (!answer.contains("actions") || !answer["actions"].is_array()) return Error{"actions: missing or not a list"};
  std::vector<ProposedAction> out;
  for (size_t i = 0; i < answer["actions"].size() && static_cast<int>(out.size()) < max_actions; ++i) {
    const nlohmann::json& a = answer["actions"][i];
    const std::string path = "actions[" + std::to_string(i) + "]";
    if (!a.is_object()) return Error{path + ": " + Shown(a) + " is not an object"};
    ProposedAction p;
    if (!a.contains("action") || !a["action"].is_string() ||
        std::find(ActionNames().begin(), ActionNames().end(), a["action"].get<std::string>()) == ActionNames().end())
      return Error{path + ".action: " + (a.contains("action") ? Shown(a["action"]) : "missing") +
                   "; expected add_entity, remove_entity, update_pose or update_scale"};
    p.action = a["action"].get<std::string>();
    auto number = [&](const char* key, std::optional<double>* into) -> std::string {
      if (!a.contains(key) || a[key].is_null()) return "";
      if (!a[key].is_number() || !std::isfinite(a[key].get<double>())) return path + "." + key + ": " + Shown(a[key]) + " is not a number";
      *into = a[key].get<double>();
      return "";
    };
    for (auto [key, into] : {std::pair{"x", &p.x}, std::pair{"y", &p.y}, std::pair{"yaw", &p.yaw_deg}, std::pair{"scale", &p.scale}})
      if (std::string e = number(key, into); !e.empty()) return Error{e};
    if (a.contains("wall") && !a["wall"].is_null()) {
      if (!a["wall"].is_number_integer() || a["wall"].get<int>() < 0 || a["wall"].get<int>() >= walls)
        return Error{path + ".wall: " + Shown(a["wall"]) + " is not a wall index (0 to " + std::to_string(walls - 1) + ")"};
      p.wall = a["wall"].get<int>();
    }
    if (a.contains("reason") && a["reason"].is_string()) p.reason = a["reason"].get<std::string>();
    if (p.action != "add_entity") {
      std::string error;
      p.id = KnownId(a.contains("id") ? a["id"] : nlohmann::json(), path + ".id", room, ids, &error);
      if (!error.empty()) return Error{error};
    }
    if (p.action == "update_pose" && (!p.x || !p.y) && !p.yaw_deg && !p.wall)
      return Error{path + ": update_pose needs x and y, a yaw, or a wall"};
    if (p.action == "update_pose" && (p.x.has_value() != p.y.has_value())) return Error{path + ": give both x and y, or neither"};
    if (p.action == "update_scale") {
      if (!p.scale) return Error{path + ".scale: update_scale needs a scale"};
      if (*p.scale < 0.8 - 1e-9 || *p.scale > 1.0 + 1e-9) return Error{path + ".scale: " + Fixed(*p.scale, 3) + " is not in [0.8, 1]"};
    }
    if (p.action == "add_entity") {
      if (!a.contains("category") || !a["category"].is_string() || !FindCategory(a["category"].get<std::string>()))
        return Error{path + ".category: " + (a.contains("category") ? Shown(a["category"]) : "missing") +
                     " is not a category of the vocabulary"};
      p.category = a["category"].get<std::string>();
      if (!a.contains("relation") || !a["relation"].is_string() ||
          std::find(PhysicalNames().begin(), PhysicalNames().end(), a["relation"].get<std::string>()) == PhysicalNames().end())
        return Error{path + ".relation: " + (a.contains("relation") ? Shown(a["relation"]) : "missing") +
                     "; expected ontop, inside, against_wall, on_wall or hanging"};
      p.relation = a["relation"].get<std::string>();
      if (!a.contains("parent") || !a["parent"].is_string()) return Error{path + ".parent: missing (floor, wall, ceiling or an object id)"};
      const std::string parent = a["parent"].get<std::string>();
      if (scene::IsRootParent(parent)) {
        p.parent = parent;
      } else {
        std::string error;
        p.parent = KnownId(a["parent"], path + ".parent", room, ids, &error);
        if (!error.empty()) return Error{error};
      }
    }
    out.push_back(std::move(p));
  }
  return out;
}

// ---- graph

std::string GraphSystemPrompt() {
  return "You plan what goes into one room of a house, as a scene graph for a furnishing program. You get the room "
         "(its type, floor size, doors and windows), the request for the house, and a draft graph made from "
         "common room layouts. Revise the draft so the room fits the request: keep what suits it, add what the "
         "request asks for in this room and the draft lacks, drop what contradicts it, and keep the room usable "
         "(do not fill a small room). Return the whole graph.\n"
         "Objects: \"id\" is the category followed by a number (sofa-0, chair-1); keep the draft's ids for the "
         "objects you keep. \"category\" must be one of the vocabulary below. Every object rests on exactly one "
         "\"parent\" with a \"relation\": on the floor (parent floor, relation ontop), with its back to a wall "
         "(parent floor, relation against_wall), hung on a wall (parent wall, relation on_wall), hung from the "
         "ceiling (parent ceiling, relation hanging), on top of another object (parent its id, relation ontop) or "
         "inside one (parent its id, relation inside; the parent must have shelves or compartments).\n"
         "Edges say how objects relate: face_to (the source looks at the target), front_of, behind, left_of, "
         "right_of (the source on that side of the target, seen from the target), next_to (0 to 0.5 m apart), near "
         "(0.5 to 1.5 m), far (more than 1.5 m), align (turned alike), centered (on the target's middle line).\n"
         "Answer with one JSON object and nothing else.\nVocabulary: " +
         VocabularyLine();
}

Json GraphResponseFormat() {
  Json object{{"type", "object"},
              {"additionalProperties", false},
              {"required", Json::array({"id", "category", "parent", "relation"})},
              {"properties", Json{{"id", Json{{"type", "string"}}},
                                  {"category", Json{{"type", "string"}}},
                                  {"parent", Json{{"type", "string"}}},
                                  {"relation", Json{{"type", "string"}, {"enum", PhysicalNames()}}}}}};
  Json relations = Json::array();
  for (int r = 0; r < scene::kSemanticRelationCount; ++r)
    relations.push_back(std::string(scene::SemanticRelationName(static_cast<scene::SemanticRelation>(r))));
  Json edge{{"type", "object"},
            {"additionalProperties", false},
            {"required", Json::array({"source", "relation", "target"})},
            {"properties", Json{{"source", Json{{"type", "string"}}},
                                {"relation", Json{{"type", "string"}, {"enum", relations}}},
                                {"target", Json{{"type", "string"}}}}}};
  Json schema{{"type", "object"},
              {"additionalProperties", false},
              {"required", Json::array({"objects", "edges", "notes"})},
              {"properties", Json{{"objects", Json{{"type", "array"}, {"items", object}}},
                                  {"edges", Json{{"type", "array"}, {"items", edge}}},
                                  {"notes", Json{{"type", "string"}}}}}};
  return StrictFormat("room_graph", schema);
}

}  // namespace villa::critic
