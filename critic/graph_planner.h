#pragma once
// The A-PSSG from a model (paper Sec. 3.2: the MLLM builds the scene graph from the prompt): the built-in
// priors planner drafts the room's graph, a model behind an OpenAI-compatible endpoint revises it for the
// request (keeps, adds, drops objects and edges), and the structural validator (scene/validate.h) is the
// gate: a revision it refuses goes back to the model with the findings, a bounded number of times, and
// when none passes the draft is kept with a note saying why. Answers are cached like the critic's.
//
//   furnish.graph_planner = std::make_shared<MllmGraphPlanner>(PlannerOptions{}, GraphPlannerOptions{...});
#include <atomic>
#include <string>

#include "llm/client.h"
#include "llm/json_chat.h"
#include "scene/planner.h"
#include "util/result.h"

namespace villa::critic {

struct GraphPlannerOptions {
  LlmOptions llm;           // server, model, key, sampling
  JsonChatOptions chat;     // corrective turns, answer cache
  bool json_schema = true;  // send response_format json_schema (strict)
  std::string Check() const;
};

class MllmGraphPlanner : public scene::GraphPlanner {
 public:
  MllmGraphPlanner(scene::PlannerOptions priors, GraphPlannerOptions options);
  std::string_view name() const override { return "mllm"; }
  // The priors' draft revised by the model; the draft itself (planner "priors", a note why) when the
  // model gives no graph the validator accepts or cannot be reached.
  Result<scene::RoomPlan> Plan(const scene::PlanRequest& request) const override;

  // Requests sent, answers from the cache and tokens so far (rooms are planned in parallel).
  int requests() const { return requests_; }
  int cache_hits() const { return cache_hits_; }
  int tokens() const { return tokens_; }

 private:
  scene::PriorsPlanner priors_;
  GraphPlannerOptions options_;
  mutable std::atomic<int> requests_{0}, cache_hits_{0}, tokens_{0};
};

// The user message of the graph request: the room (type, size, doors, windows), the request, the draft.
std::string GraphUserText(const scene::RoomContext& room, const std::string& request, const scene::RoomPlan& draft);

// A model's graph read against the draft: kept objects keep the draft's size, affordances, zone and hints;
// new ones take their category's (assets/category.h), origin "critic". Errors name the JSON path and the
// value; the structural validator's findings come as one error too when `layout` is given.
Result<scene::RoomPlan> ReadGraph(const nlohmann::json& answer, const scene::RoomContext& room, const scene::RoomPlan& draft,
                                  const Layout* layout);

}  // namespace villa::critic
