// villa eval PROMPTS.jsonl [--backend ...] [--jobs J] [--json]: runs many requests through `plan` and
// prints the paper's macro table: FSR, RR, VCR and brief adherence, per prompt and overall.
#include <atomic>
#include <filesystem>
#include <iostream>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "cli/backend_flags.h"
#include "cli/command.h"
#include "generator/text/plan.h"
#include "layout/layout_io.h"
#include "util/progress.h"
#include "util/text_table.h"

namespace villa::cli {


namespace {

struct EvalCommand {
  std::string prompts;
  std::string backend = "procedural";
  std::string api_key_env;
  int jobs = 0;
  int limit = 0;
  bool json = false;
  PlanOptions options;
};

struct Prompt {
  int line = 0;
  std::string id;
  std::string text;
};

std::string Percent(std::optional<double> r) { return r ? FormatFixed(100.0 * *r, 1) + "%" : "-"; }
Json RatioJson(std::optional<double> r) { return r ? Json(*r) : Json(nullptr); }

void Run(EvalCommand& command) {
  PlanOptions& options = command.options;
  if (!options.llm.url.empty() && command.backend == "procedural") command.backend = "llm";
  ApplyBackendFlags(command.backend, command.api_key_env, options);
  if (!std::filesystem::exists(command.prompts)) throw UsageError(command.prompts + ": no such file");

  std::vector<Prompt> prompts;
  Status status = ReadJsonl(command.prompts, [&](const Json& record, int line) {
    std::string where = command.prompts + ":" + std::to_string(line);
    if (!record.is_object() || !record.contains("text") || !record["text"].is_string())
      throw UsageError(where + ": expected an object with a \"text\" string");
    Prompt p;
    p.line = line;
    p.text = record["text"].get<std::string>();
    if (record.contains("id")) p.id = record["id"].is_string() ? record["id"].get<std::string>() : record["id"].dump();
    prompts.push_back(std::move(p));
    return command.limit <= 0 || static_cast<int>(prompts.size()) < command.limit;
  });
  if (!status) throw UsageError(status.error());
  if (prompts.empty()) throw UsageError(command.prompts + ": no prompts");

  // Served models answer many requests at once; the procedural backend is CPU-bound.
  int jobs = command.jobs > 0 ? command.jobs
                              : options.backend == PlanBackend::kLlm ? 8
                                                                     : std::max(1u, std::thread::hardware_concurrency());
  jobs = std::min<int>(jobs, static_cast<int>(prompts.size()));
  std::vector<PlanSummary> results(prompts.size());
  std::atomic<std::size_t> next{0};
  ProgressBar bar("eval", prompts.size());
  auto worker = [&] {
    for (std::size_t i = next++; i < prompts.size(); i = next++) {
      PlanOptions o = options;
      o.seed = options.seed + i;  // distinct layouts for distinct prompts, reproducible per line
      results[i] = PlanLayout(prompts[i].text, o);
      bar.Advance();
    }
  };
  std::vector<std::thread> threads;
  for (int t = 0; t < jobs; ++t) threads.emplace_back(worker);
  for (auto& t : threads) t.join();
  bar.Finish();

  MetricsSummary overall;
  double adherence_sum = 0.0;
  long met = 0, total = 0;
  int failed = 0;
  double seconds = 0.0;
  for (const auto& r : results) {
    overall.Add(r.metrics);
    adherence_sum += r.check.adherence();
    met += r.check.met();
    total += r.check.total();
    failed += r.outcome == PlanOutcome::kFailed;
    seconds += r.seconds;
  }
  const double adherence = adherence_sum / results.size();

  if (command.json) {
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
             {"overall", Json{{"count", results.size()}, {"backend", std::string(PlanBackendName(options.backend))},
                              {"fsr", RatioJson(overall.fsr())}, {"rr", RatioJson(overall.rr())},
                              {"rr_entrance", RatioJson(overall.rr_entrance())}, {"vcr", RatioJson(overall.vcr())},
                              {"brief_adherence", adherence}, {"requirements_met", met},
                              {"requirements", total}, {"failed", failed}, {"seconds", seconds}}}};
    std::cout << out.dump(2, ' ', false, Json::error_handler_t::replace) << "\n";
  } else {
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
    std::cout << table.Render() << "\n";
    TextTable macro({"backend", "prompts", "FSR", "RR", "RR (entrance)", "VCR", "brief adherence"});
    macro.AddRow({std::string(PlanBackendName(options.backend)), std::to_string(results.size()), Percent(overall.fsr()),
                  Percent(overall.rr()), Percent(overall.rr_entrance()), Percent(overall.vcr()), Percent(adherence)});
    std::cout << macro.Render();
    std::cout << met << "/" << total << " requirements met; " << failed << " failed requests; "
              << FormatFixed(seconds, 1) << " s of planning\n";
  }
  SetExitCode(kExitOk);
}

Registration registration{55, [](CLI::App& app) {
  auto command = std::make_shared<EvalCommand>();
  CLI::App* sub = app.add_subcommand(
      "eval",
      "Run many requests through plan and print the paper's macro table: FSR, RR (per floor, and from the\n"
      "entrance), VCR and brief adherence (share of requirements met), per prompt and overall.\n"
      "PROMPTS is JSONL with a \"text\" field a line (and an optional \"id\"). Requests to a served model run\n"
      "in parallel (--jobs). Exit status: 0 evaluated, 2 usage (missing file, a line without \"text\").");
  sub->add_option("prompts", command->prompts, "JSONL file of requests")->required();
  AddBackendFlags(sub, command->backend, command->api_key_env, command->options);
  sub->add_option("-j,--jobs", command->jobs,
                  "prompts planned at once (default: 8 for llm, the number of cores for procedural)");
  sub->add_option("--limit", command->limit, "only the first N prompts");
  sub->add_flag("--json", command->json, "print a machine-readable report instead of the tables");
  sub->callback([command] { Run(*command); });
}};

}  // namespace
}  // namespace villa::cli
