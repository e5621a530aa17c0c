#include "generator/text/eval.h"

#include <algorithm>
#include <atomic>
#include <sstream>
#include <thread>

#include "layout/layout_io.h"
#include "util/text_table.h"

namespace villa {
namespace {

std::string Percent(std::optional<double> r) { return r ? FormatFixed(100.0 * *r, 1) + "%" : "-"; }
Json RatioJson(std::optional<double> r) { return r ? Json(*r) : Json(nullptr); }

}  // namespace

Result<std::vector<EvalPrompt>> ReadEvalPrompts(const std::filesystem::path& path, int limit) {
  std::vector<EvalPrompt> prompts;
  std::string problem;
  Status status = ReadJsonl(path, [&](const Json& record, int line) {
    std::string where = path.string() + ":" + std::to_string(line);
    if (!record.is_object() || !record.contains("text") || !record["text"].is_string()) {
      problem = where + ": expected an object with a \"text\" string";
      return false;
    }
    EvalPrompt p;
    p.line = line;
    p.text = record["text"].get<std::string>();
    if (record.contains("id")) p.id = record["id"].is_string() ? record["id"].get<std::string>() : record["id"].dump();
    prompts.push_back(std::move(p));
    return limit <= 0 || static_cast<int>(prompts.size()) < limit;
  });
  if (!problem.empty()) return Error{problem};
  if (!status) return Error{status.error()};
  if (prompts.empty()) return Error{path.string() + ": no prompts"};
  return prompts;
}

bool EvalOptions::IsValid(std::string* message) const { return plan.IsValid(message); }

EvalSummary EvaluatePrompts(const std::vector<EvalPrompt>& prompts, const EvalOptions& options) {
  EvalSummary summary;
  summary.backend = options.plan.backend;
  summary.prompts = prompts;
  int jobs = options.jobs > 0 ? options.jobs
                              : options.plan.backend == PlanBackend::kLlm ? 8
                                                                          : std::max(1u, std::thread::hardware_concurrency());
  jobs = std::max(1, std::min<int>(jobs, static_cast<int>(prompts.size())));
  summary.jobs = jobs;
  summary.results.resize(prompts.size());
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i = next++; i < prompts.size(); i = next++) {
      PlanOptions o = options.plan;
      o.seed = options.plan.seed + i;  // distinct layouts for distinct prompts, reproducible per line
      summary.results[i] = PlanLayout(prompts[i].text, o);
      if (options.on_planned) options.on_planned();
    }
  };
  std::vector<std::thread> threads;
  for (int t = 0; t < jobs; ++t) threads.emplace_back(worker);
  for (auto& t : threads) t.join();

  double adherence_sum = 0.0;
  for (const auto& r : summary.results) {
    summary.overall.Add(r.metrics);
    adherence_sum += r.check.adherence();
    summary.requirements_met += r.check.met();
    summary.requirements += r.check.total();
    summary.failed += r.outcome == PlanOutcome::kFailed;
    summary.seconds += r.seconds;
  }
  summary.adherence = summary.results.empty() ? 0.0 : adherence_sum / summary.results.size();
  return summary;
}

nlohmann::ordered_json EvalReportJson(const EvalSummary& summary) {
  const std::vector<EvalPrompt>& prompts = summary.prompts;
  const std::vector<PlanSummary>& results = summary.results;
  Json rows = Json::array();
  for (std::size_t i = 0; i < results.size(); ++i) {
    const PlanSummary& r = results[i];
    MetricsSummary one;
    one.Add(r.metrics);
    Json row{{"line", prompts[i].line}, {"id", prompts[i].id}, {"outcome", std::string(PlanOutcomeName(r.outcome))},
             {"fsr", RatioJson(one.fsr())}, {"rr", RatioJson(one.rr())}, {"rr_entrance", RatioJson(one.rr_entrance())},
             {"vcr", RatioJson(one.vcr())}, {"brief_met", r.check.met()}, {"brief_total", r.check.total()},
             {"adherence", r.check.adherence()}, {"rounds", r.rounds.size()}, {"attempts", r.attempts},
             {"seconds", r.seconds}};
    Json unmet = Json::array();
    for (const auto& u : r.unmet) unmet.push_back(u.requirement);
    row["unmet"] = unmet;
    Json unparsed = Json::array();
    for (const auto& u : r.brief.unparsed) unparsed.push_back(u.text);
    row["unparsed"] = unparsed;
    if (!r.error.empty()) row["error"] = r.error;
    rows.push_back(row);
  }
  Json out{{"prompts", rows},
           {"overall", Json{{"count", results.size()}, {"backend", std::string(PlanBackendName(summary.backend))},
                            {"fsr", RatioJson(summary.overall.fsr())}, {"rr", RatioJson(summary.overall.rr())},
                            {"rr_entrance", RatioJson(summary.overall.rr_entrance())},
                            {"vcr", RatioJson(summary.overall.vcr())}, {"brief_adherence", summary.adherence},
                            {"requirements_met", summary.requirements_met}, {"requirements", summary.requirements},
                            {"failed", summary.failed}, {"seconds", summary.seconds}}}};
  return out;
}

std::string EvalReportText(const EvalSummary& summary) {
  const std::vector<EvalPrompt>& prompts = summary.prompts;
  const std::vector<PlanSummary>& results = summary.results;
  std::ostringstream text;
  TextTable table({"#", "prompt", "outcome", "FSR", "RR", "VCR", "brief", "rounds", "s"});
  for (std::size_t i = 0; i < results.size(); ++i) {
    const PlanSummary& r = results[i];
    MetricsSummary one;
    one.Add(r.metrics);
    std::string label = prompts[i].id.empty() ? prompts[i].text : prompts[i].id;
    if (label.size() > 40) label = label.substr(0, 37) + "...";
    table.AddRow({std::to_string(i + 1), label, std::string(PlanOutcomeName(r.outcome)), Percent(one.fsr()),
                  Percent(one.rr()), Percent(one.vcr()),
                  std::to_string(r.check.met()) + "/" + std::to_string(r.check.total()),
                  std::to_string(r.rounds.size()), FormatFixed(r.seconds, 2)});
  }
  text << table.Render() << "\n";
  TextTable macro({"backend", "prompts", "FSR", "RR", "RR (entrance)", "VCR", "brief adherence"});
  const MetricsSummary& overall = summary.overall;
  macro.AddRow({std::string(PlanBackendName(summary.backend)), std::to_string(results.size()), Percent(overall.fsr()),
                Percent(overall.rr()), Percent(overall.rr_entrance()), Percent(overall.vcr()), Percent(summary.adherence)});
  text << macro.Render();
  text << summary.requirements_met << "/" << summary.requirements << " requirements met; " << summary.failed
       << " failed requests; " << FormatFixed(summary.seconds, 1) << " s of planning\n";
  return text.str();
}

}  // namespace villa
