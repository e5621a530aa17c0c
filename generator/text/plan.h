#pragma once
// Text to a validated layout: the library entry point behind `villa plan`, `villa eval` and `villa generate`.
//
//   PlanOptions options;                       // procedural backend, offline, seed 1
//   PlanSummary plan = PlanLayout("A two-story L-shaped villa with three bedrooms ...", options);
//   if (plan.valid()) SaveLayout(*plan.layout, "layout.json");
//   std::cerr << plan.BriefReport();
//
// Two backends:
//   kProcedural  steers the partitioner with the parsed brief (floors, footprint class, room counts per
//                floor, connections, panoramic windows), generating and testing seeds until the brief is
//                met or the time budget is spent; the best valid candidate wins.
//   kLlm         asks an OpenAI-compatible /v1/chat/completions server (vLLM, llama.cpp, Ollama, SGLang,
//                hosted APIs) with the fine-tune's system prompt and the layout JSON schema, validates the
//                answer and sends the violations back for a corrected layout, up to `rounds` times.
// A layout that breaks a rule of FORMAT.md is never reported as valid: `valid()` is the validator's word.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "generator/text/brief.h"
#include "generator/text/recount.h"
#include "layout/layout.h"
#include "layout/metrics.h"
#include "layout/validate.h"
#include "llm/client.h"

namespace villa {

enum class PlanBackend { kProcedural, kLlm };
std::string_view PlanBackendName(PlanBackend backend);  // "procedural", "llm"

struct PlanOptions {
  PlanBackend backend = PlanBackend::kProcedural;
  // Seeds the partitioner (procedural) and is sent as "seed" to the model (llm). Same seed, same text:
  // same layout from the procedural backend.
  std::uint64_t seed = 1;
  // Procedural: wall-clock budget in seconds for the generate-and-test search over partitioner seeds
  // (> 0). The search stops early as soon as a candidate meets the whole brief.
  double time_budget_s = 5.0;
  // Procedural: at most this many partitioner calls (> 0); bounds the work on a fast machine.
  int max_attempts = 4000;
  // LLM: corrective rounds after the first answer when it is invalid (>= 0). Each round sends the
  // violations back and asks for a corrected layout. Default 2, as in the issue.
  int rounds = 2;
  // LLM: server, model, transport and sampling settings.
  LlmOptions llm;
  // LLM: send response_format json_schema with the layout schema (finetune/layout_schema.h) for
  // constrained decoding; off for servers without it.
  bool json_schema = true;

  // False with a message naming the bad field and value.
  bool IsValid(std::string* message) const;
};

enum class PlanOutcome {
  kMet,          // a valid layout that meets every requirement of the brief
  kPartial,      // a valid layout; some requirements are unmet (listed in `unmet`), or some words of the
                 // request were not understood (brief.unparsed), so the brief may miss a requirement, or
                 // the independent count of the text's rooms (recount.h) reads more than the layout has
  kInvalid,      // only invalid layouts (or none that parsed) came out of all rounds / attempts
  kFailed,       // no answer at all: transport failure, refused request, bad options
};
std::string_view PlanOutcomeName(PlanOutcome outcome);  // "met", "partial", "invalid", "failed"

// One LLM exchange or one batch of procedural attempts, for the report.
struct PlanRound {
  int round = 0;                 // 0 = first answer, 1.. = corrective rounds
  bool parsed = false;           // the answer parsed as a layout
  bool valid = false;            // and passed ValidateLayout
  int violations = 0;
  int requirements_met = 0;
  std::string error;             // transport, truncation or parse error of this round; empty if none
  double seconds = 0.0;
  int http_attempts = 0;         // requests sent for this round, retries included (llm)
  std::string finish_reason;     // as the server reported it (llm)
};

struct PlanSummary {
  PlanOutcome outcome = PlanOutcome::kFailed;
  PlanBackend backend = PlanBackend::kProcedural;
  Brief brief;
  // The best layout produced: valid if any was, else the last one that parsed. Empty when none parsed.
  std::optional<Layout> layout;
  std::vector<Violation> violations;        // of `layout` (empty when valid)
  BriefCheck check;                         // `layout` against `brief`
  std::vector<RequirementResult> unmet;     // check.unmet(), plus the brief's unsupported shape if any
  // The second reading (recount.h): room kinds of which the layout has fewer than the text may ask for.
  std::vector<RecountDisagreement> recount;
  // Rooms the layout has beyond what the brief asks (kinds it does not name, or more than the most it
  // names): the planner fills the floors' area with rooms; reported, never counted against the brief.
  std::vector<std::pair<Category, int>> added;
  LayoutMetrics metrics;                    // FSR / RR / VCR ingredients of `layout`
  std::optional<std::string> shape_class;   // footprint class of `layout` (partitioner's or classified)
  std::vector<PlanRound> rounds;            // llm: one per exchange; procedural: one summarising the search
  int attempts = 0;                         // procedural: partitioner calls; llm: answers received
  double seconds = 0.0;                     // wall clock of the whole plan
  std::string error;                        // why it failed (kFailed / kInvalid), for a person
  std::string raw_answer;                   // llm: the last answer text as received (for the report)

  bool valid() const { return layout.has_value() && violations.empty() && metrics.format_success; }
  // A few lines for a person: outcome, rooms per floor, unmet requirements, violations, time.
  std::string BriefReport() const;
};

PlanSummary PlanLayout(const std::string& text, const PlanOptions& options);

// The rooms of `summary.layout` beyond what its brief asks, by kind (the staircase's utility rooms aside);
// empty when the brief names no room.
std::vector<std::pair<Category, int>> AddedRooms(const PlanSummary& summary);

// The report written beside the layout (layout.report.json): text, backend, outcome, brief, checks,
// unmet requirements, violations, metrics (FSR, RR, VCR), rounds, attempts, time, shape class.
nlohmann::ordered_json PlanReportJson(const PlanSummary& summary);

}  // namespace villa
