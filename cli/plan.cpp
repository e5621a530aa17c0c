// villa plan "TEXT" -o layout.json [--backend procedural|llm] ...: text to a validated layout, with a
// report (layout.report.json) and a floor-plan picture (layout.png) beside it.
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <memory>
#include <string>

#include "cli/backend_flags.h"
#include "cli/command.h"
#include "util/utf8.h"
#include "cli/flags.h"
#include "generator/text/plan.h"
#include "layout/layout_io.h"
#include "render/plan_render.h"
#include "util/atomic_file.h"

namespace villa::cli {
namespace {

struct PlanCommand {
  std::string text;
  std::string out;
  std::string backend = "procedural";
  std::string api_key_env;
  bool force = false;
  bool no_png = false;
  bool quiet = false;
  PlanOptions options;
};

// The paths written beside -o: "layout.json" -> "layout.report.json", "layout.png".
std::filesystem::path Beside(const std::filesystem::path& out, const std::string& suffix) {
  std::filesystem::path p = out;
  return p.replace_extension().string() + suffix;
}

}  // namespace

void ApplyBackendFlags(const std::string& backend, const std::string& api_key_env, PlanOptions& options) {
  if (backend == "procedural") {
    options.backend = PlanBackend::kProcedural;
  } else if (backend == "llm") {
    options.backend = PlanBackend::kLlm;
    if (options.llm.url.empty()) throw UsageError("--backend llm needs --llm URL (an OpenAI-compatible server)");
    if (options.llm.model.empty()) throw UsageError("--backend llm needs --model NAME");
  } else {
    throw UsageError("--backend " + backend + ": expected procedural or llm");
  }
  if (!api_key_env.empty()) {
    const char* key = std::getenv(api_key_env.c_str());
    if (!key || !*key) throw UsageError("--api-key-env " + api_key_env + ": that environment variable is not set");
    options.llm.api_key = key;
  }
  std::string message;
  if (!options.IsValid(&message)) throw UsageError(message);
}

void AddBackendFlags(CLI::App* sub, std::string& backend, std::string& api_key_env, PlanOptions& o) {
  sub->add_option("--backend", backend, "procedural (default: offline, steers the partitioner) or llm")
      ->check(CLI::IsMember({"procedural", "llm"}));
  sub->add_option("--llm", o.llm.url,
                  "OpenAI-compatible server for --backend llm: http://host:port, .../v1 or the full "
                  ".../v1/chat/completions (vLLM, llama.cpp, Ollama, SGLang, hosted APIs); implies --backend llm");
  sub->add_option("--model", o.llm.model, "model name sent in requests (e.g. the LoRA adapter's served name)");
  sub->add_option("--api-key-env", api_key_env,
                  "name of the environment variable holding the API key (sent as a Bearer token, never printed)");
  sub->add_option("--seed", o.seed, "seed of the partitioner (procedural) and of the model's sampling (llm)")->transform(Seed());
  sub->add_option("--rounds", o.rounds, "llm: corrective rounds after an invalid answer")
      ->capture_default_str()
      ->transform(WholeIn(0, 100));
  sub->add_option("--timeout", o.llm.timeout_s, "llm: seconds to wait for one answer")
      ->capture_default_str()
      ->check(NumberIn(0.0, 86400.0, /*above_min=*/true));
  sub->add_option("--retries", o.llm.max_retries, "llm: retries on 429, 5xx and connection errors")
      ->capture_default_str()
      ->transform(WholeIn(0, 100));
  sub->add_option("--temperature", o.llm.temperature, "llm: sampling temperature")->capture_default_str()->check(NumberIn(0.0, 2.0));
  sub->add_option("--max-tokens", o.llm.max_tokens, "llm: answer budget in tokens")
      ->capture_default_str()
      ->transform(WholeIn(1, 10000000));
  sub->add_flag("--no-schema", [&o](std::int64_t) { o.json_schema = false; },
                "llm: do not send response_format json_schema (servers without constrained decoding)");
  sub->add_flag("--no-template-kwargs", [&o](std::int64_t) { o.llm.disable_thinking = false; },
                "llm: do not send chat_template_kwargs (hosted APIs that reject unknown fields)");
  sub->add_option("--budget", o.time_budget_s, "procedural: seconds to search for a layout meeting the brief")
      ->capture_default_str()
      ->check(NumberIn(0.0, 86400.0, /*above_min=*/true));
}

namespace {

void Run(PlanCommand& command) {
  PlanOptions& options = command.options;
  if (!options.llm.url.empty() && command.backend == "procedural") command.backend = "llm";
  ApplyBackendFlags(command.backend, command.api_key_env, options);
  std::string text = command.text;
  if (text == "-") text.assign(std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>());
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) throw UsageError("plan: the request text is empty");
  if (std::string p = RequestTextProblem(text); !p.empty()) throw UsageError("plan: the request: " + p);

  const std::filesystem::path out = command.out;
  if (out.extension() != ".json") throw UsageError("-o " + command.out + ": the layout file must end in .json");
  const std::filesystem::path report_path = Beside(out, ".report.json");
  const std::filesystem::path png_path = Beside(out, ".png");
  const std::filesystem::path invalid_path = Beside(out, ".invalid.json");
  if (!command.force)
    for (const auto& p : {out, report_path, png_path, invalid_path})
      if (std::filesystem::exists(p)) throw UsageError(p.string() + " exists: pass --force to overwrite it");
  if (!out.parent_path().empty() && !std::filesystem::is_directory(out.parent_path()))
    throw UsageError("-o " + command.out + ": folder " + out.parent_path().string() + " does not exist");

  PlanSummary plan = PlanLayout(text, options);

  Json report = PlanReportJson(plan);
  if (options.backend == PlanBackend::kLlm)
    report["llm"] = Json{{"url", ChatCompletionsUrl(options.llm.url)}, {"model", options.llm.model},
                         {"temperature", options.llm.temperature}, {"seed", options.seed}, {"rounds", options.rounds}};
  else
    report["procedural"] = Json{{"seed", options.seed}, {"budget_s", options.time_budget_s}};
  bool ok = true;
  auto fail = [&](const std::string& message) {
    std::cerr << "villa plan: " << message << "\n";
    ok = false;
  };
  if (plan.layout) {
    const std::filesystem::path layout_path = plan.valid() ? out : invalid_path;
    if (Status s = SaveLayout(*plan.layout, layout_path); !s) fail(s.error());
    else report["layout_file"] = layout_path.filename().string();
    if (!command.no_png) {
      PlanRenderOptions render;
      render.source_name = layout_path.filename().string();
      if (Status s = RenderPlan(*plan.layout, png_path, render); !s) fail(s.error());
      else report["picture_file"] = png_path.filename().string();
    }
  }
  if (Status s = WriteFileAtomic(report_path, report.dump(2, ' ', false, Json::error_handler_t::replace) + "\n"); !s) fail(s.error());

  if (!command.quiet) std::cerr << plan.BriefReport();
  if (plan.valid() && ok) {
    if (!command.quiet) std::cerr << "wrote " << out.string() << ", " << report_path.string()
                                  << (command.no_png ? "" : ", " + png_path.string()) << "\n";
    SetExitCode(kExitOk);
  } else {
    if (!plan.valid())
      std::cerr << "villa plan: no valid layout"
                << (plan.layout ? " (the last one is in " + invalid_path.string() + ")" : std::string()) << "; see "
                << report_path.string() << "\n";
    SetExitCode(kExitFailure);
  }
}

Registration registration{50, [](CLI::App& app) {
  auto command = std::make_shared<PlanCommand>();
  CLI::App* sub = app.add_subcommand(
      "plan",
      "Text to a validated layout. Parses the request into a brief (floors, footprint, rooms per floor,\n"
      "connections, panoramic windows, furniture), then makes a layout with the procedural backend (offline,\n"
      "default) or a served LLM (--llm URL --model NAME), checks it against the layout rules and the brief,\n"
      "and writes OUT (the layout JSON), OUT's .report.json (brief, unmet requirements, violations, FSR, RR,\n"
      "VCR, rounds, time) and OUT's .png (the floor plans).\n"
      "Exit status: 0 a valid layout was written, 1 no valid layout came out, 2 usage.");
  sub->add_option("text", command->text, "the request, in English (\"-\" reads it from stdin)")->required();
  sub->add_option("-o,--out", command->out, "layout file to write (.json)")->required()->check(PathName());
  AddBackendFlags(sub, command->backend, command->api_key_env, command->options);
  sub->add_flag("--force", command->force, "overwrite existing output files");
  sub->add_flag("--no-png", command->no_png, "do not draw the floor-plan picture");
  sub->add_flag("-q,--quiet", command->quiet, "print nothing but errors");
  sub->callback([command] { Run(*command); });
}};

}  // namespace
}  // namespace villa::cli
