// villa generate "TEXT" -o OUTDIR: the whole pipeline (generator/generate.h). Plan a layout from the text,
// then build it: OUTDIR/layout.json, building.glb, plan.png (floor plans), preview.png (3D cut-aways),
// report.json.
#include <filesystem>
#include <iostream>
#include <iterator>
#include <memory>
#include <string>

#include "cli/backend_flags.h"
#include "cli/command.h"
#include "generator/generate.h"

namespace villa::cli {
namespace {

struct GenerateCommand {
  std::string text;
  std::string out;
  std::string backend = "procedural";
  std::string api_key_env;
  bool force = false;
  bool quiet = false;
  PlanOptions options;
  BuildOptions build;
};

void Run(GenerateCommand& command) {
  if (command.text == "-") command.text.assign(std::istreambuf_iterator<char>(std::cin), {});
  if (command.text.find_first_not_of(" \t\r\n") == std::string::npos) throw UsageError("generate: the request text is empty");
  ApplyBackendFlags(command.backend, command.api_key_env, command.options);
  GenerateOptions options;
  options.plan = command.options;
  options.build = command.build;
  options.out = command.out;
  options.force = command.force;
  std::string problem;
  if (!options.IsValid(&problem)) throw UsageError("generate: " + problem);
  if (Status usable = CheckGenerateOutput(options); !usable) throw UsageError("generate: " + usable.error());

  Result<GenerateSummary> summary = GenerateVilla(command.text, options);
  if (!summary) {
    std::cerr << "villa generate: " << summary.error() << "\n";
    SetExitCode(kExitFailure);
    return;
  }
  const bool ok = summary->ok();
  if (!command.quiet || !ok) {
    std::ostream& out = ok ? std::cout : std::cerr;
    out << summary->BriefReport();
    for (const std::string& p : summary->problems) std::cerr << "villa generate: " << p << "\n";
    for (const std::string& f : summary->files) out << (options.out / f).string() << "\n";
  }
  SetExitCode(ok ? kExitOk : kExitFailure);
}

Registration registration{65, [](CLI::App& app) {
  auto command = std::make_shared<GenerateCommand>();
  CLI::App* sub = app.add_subcommand(
      "generate",
      "Text to a 3D villa: plan a layout from the request (like `villa plan`), then build it (like\n"
      "`villa build`). Writes into OUTDIR: layout.json, plan.png (floor plans), building.glb (glTF 2.0),\n"
      "preview.png (the building and a cut-away of each level) and report.json (brief, checks, metrics,\n"
      "VCR on the built geometry, timings). Exit status: 0 a valid layout built, 1 the plan or the build\n"
      "failed (what could be written is written, report.json says why), 2 usage.");
  sub->add_option("text", command->text, "the request, in English (\"-\" reads it from stdin)")->required();
  sub->add_option("-o,--out", command->out, "output folder (created if missing)")->required();
  AddBackendFlags(sub, command->backend, command->api_key_env, command->options);
  sub->add_flag("--force", command->force, "overwrite existing output files in OUTDIR");
  sub->add_flag("-q,--quiet", command->quiet, "print nothing on success");
  sub->callback([command] { Run(*command); });
}};

}  // namespace
}  // namespace villa::cli
