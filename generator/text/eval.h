#pragma once
// Many requests through PlanLayout and the paper's macro table over them (FSR, RR, VCR, brief adherence):
// the library behind `villa eval`. Requests run in parallel on a thread pool; results keep the prompts'
// order, and prompt i is planned with seed options.plan.seed + i, so a run is reproducible whatever the
// job count (for the procedural backend; a served model samples as it does).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "generator/text/plan.h"
#include "layout/metrics.h"
#include "util/result.h"

namespace villa {

struct EvalPrompt {
  int line = 0;      // in the prompts file, from 1
  std::string id;    // the record's "id" (text or JSON), may be empty
  std::string text;  // the request
};

// The prompts of a JSONL file, a record a line with a "text" string and an optional "id"; at most
// `limit` of them (0: all). An error names the file and line of a record without "text", or the file
// when it holds none.
Result<std::vector<EvalPrompt>> ReadEvalPrompts(const std::filesystem::path& path, int limit = 0);

struct EvalOptions {
  PlanOptions plan;  // the backend and its settings; prompt i uses seed plan.seed + i
  // Prompts planned at once (> 0), or <= 0: 8 for a served model (it answers many at once), the number
  // of cores for the procedural backend (CPU-bound). Never more than there are prompts.
  int jobs = 0;
  // Called after each prompt is planned (from worker threads), e.g. to advance a progress bar.
  std::function<void()> on_planned;

  // False with the bad field named (PlanOptions::IsValid's reason).
  bool IsValid(std::string* message) const;
};

struct EvalSummary {
  PlanBackend backend = PlanBackend::kProcedural;
  std::vector<EvalPrompt> prompts;
  std::vector<PlanSummary> results;  // one per prompt, in order
  MetricsSummary overall;            // FSR, RR, VCR pooled over all results
  double adherence = 0.0;            // mean over prompts of requirements met / requirements
  long requirements_met = 0;
  long requirements = 0;
  int failed = 0;                    // outcome kFailed (no answer at all)
  double seconds = 0.0;              // planning time summed over prompts
  int jobs = 0;                      // prompts planned at once
};

// Plans every prompt (options must be valid).
EvalSummary EvaluatePrompts(const std::vector<EvalPrompt>& prompts, const EvalOptions& options);

// `villa eval --json`: a row per prompt (outcome, FSR, RR, VCR, brief met/total, adherence, rounds,
// attempts, seconds, unmet requirements, unparsed words, error) and the overall figures.
nlohmann::ordered_json EvalReportJson(const EvalSummary& summary);
// `villa eval`: the per-prompt table, the macro table and a closing line.
std::string EvalReportText(const EvalSummary& summary);

}  // namespace villa
