// villa eval PROMPTS.jsonl [--backend ...] [--jobs J] [--json]: runs many requests through `plan` and
// prints the paper's macro table: FSR, RR, VCR and brief adherence, per prompt and overall
// (generator/text/eval.h runs and aggregates them).
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/backend_flags.h"
#include "cli/command.h"
#include "generator/text/eval.h"
#include "layout/layout_io.h"
#include "util/progress.h"

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

void Run(EvalCommand& command) {
  EvalOptions options;
  options.plan = command.options;
  if (!options.plan.llm.url.empty() && command.backend == "procedural") command.backend = "llm";
  ApplyBackendFlags(command.backend, command.api_key_env, options.plan);
  if (!std::filesystem::exists(command.prompts)) throw UsageError(command.prompts + ": no such file");
  Result<std::vector<EvalPrompt>> prompts = ReadEvalPrompts(command.prompts, command.limit);
  if (!prompts) throw UsageError(prompts.error());

  options.jobs = command.jobs;
  std::string problem;
  if (!options.IsValid(&problem)) throw UsageError("eval: " + problem);
  ProgressBar bar("eval", prompts->size());
  options.on_planned = [&bar] { bar.Advance(); };
  const EvalSummary summary = EvaluatePrompts(*prompts, options);
  bar.Finish();
  if (command.json)
    std::cout << EvalReportJson(summary).dump(2, ' ', false, Json::error_handler_t::replace) << "\n";
  else
    std::cout << EvalReportText(summary);
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
