#pragma once
// What the critic asks a multimodal model, in our own words, and how its answers are read. Every answer
// is one JSON object under a strict JSON schema (sent as response_format json_schema); the readers here
// check what the schema cannot (ids that exist, numbers in range, a category of the vocabulary) and return
// the fault in words the model can act on, which the conversation sends back (llm/json_chat.h).
//
//   evaluation  the room's pictures and text state -> {"score": 0-10, "problems": [{"objects", "problem"}]}
//   actions     the same plus the evaluation -> {"actions": [{"action", "id", "x", "y", "yaw", "scale",
//               "wall", "category", "parent", "relation", "reason"}]}, every field present, null where unused
//   graph       a room, the request and the priors' draft graph -> the revised graph (critic/graph_planner.h)
// Coordinates in answers: metres in the plan (x east, y north), yaw in degrees (0 faces -y, 90 faces +x).
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene.h"
#include "util/result.h"

namespace villa::critic {

// ---- evaluation

std::string EvaluationSystemPrompt();
// The user message's text: the request, then the room's text state.
std::string EvaluationUserText(const std::string& request, const std::string& state);
nlohmann::ordered_json EvaluationResponseFormat();

struct Evaluation {
  double score = 0.0;  // [0, 10]
  struct Problem {
    std::vector<std::string> objects;  // full ids
    std::string problem;
  };
  std::vector<Problem> problems;
};
// Reads an evaluation; `room` completes short ids, `ids` are the room's objects (full ids). The error
// names the JSON path and the value.
Result<Evaluation> ReadEvaluation(const nlohmann::json& answer, const std::string& room, const std::set<std::string>& ids);

// ---- actions

std::string ActionsSystemPrompt();
std::string ActionsUserText(const std::string& request, const std::string& state, const Evaluation& evaluation,
                            const std::string& room);
nlohmann::ordered_json ActionsResponseFormat();

// One action as the model wrote it (ids completed with the room's prefix, angles still in degrees).
struct ProposedAction {
  std::string action;  // "add_entity", "remove_entity", "update_pose", "update_scale"
  std::string id;      // full id (add_entity: "" until the loop names the new object)
  std::optional<double> x, y, yaw_deg, scale;
  std::optional<int> wall;
  std::string category, parent, relation;  // add_entity
  std::string reason;
};
// Reads the actions (at most `max_actions` are kept; the rest are ignored). `walls` is the number of the
// room's walls.
Result<std::vector<ProposedAction>> ReadActions(const nlohmann::json& answer, const std::string& room,
                                                const std::set<std::string>& ids, int walls, int max_actions);

// ---- graph

std::string GraphSystemPrompt();
nlohmann::ordered_json GraphResponseFormat();

// A response_format for a schema: {"type": "json_schema", "json_schema": {name, strict: true, schema}}.
nlohmann::ordered_json StrictFormat(const std::string& name, const nlohmann::ordered_json& schema);

// The vocabulary's category names, comma separated (what add_entity and the graph may use).
std::string VocabularyLine();

}  // namespace villa::critic
