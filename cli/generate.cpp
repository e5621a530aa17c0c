// villa generate "TEXT" -o OUTDIR: the whole pipeline (generator/generate.h). Plan a layout from the text,
// build it and furnish every room: OUTDIR/layout.json, plan.png (floor plans with the furniture),
// scene.json, furnished.glb, CREDITS, preview.png, report.json.
#include <filesystem>
#include <iostream>
#include <iterator>
#include <memory>
#include <string>

#include "cli/backend_flags.h"
#include "cli/command.h"
#include "cli/flags.h"
#include "cli/critic_flag.h"
#include "cli/furnish_flags.h"
#include "generator/generate.h"
#include "util/progress.h"

namespace villa::cli {
namespace {

struct GenerateCommand {
  std::string text;
  std::string out;
  std::string backend = "procedural";
  std::string api_key_env;
  bool force = false;
  bool quiet = false;
  bool no_furnish = false;
  PlanOptions options;
  BuildOptions build;
  solver::FurnishOptions furnish;
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
  options.furnish = !command.no_furnish;
  options.furnishing = command.furnish;
  std::string problem;
  if (!options.IsValid(&problem)) throw UsageError("generate: " + problem);
  if (Status usable = CheckGenerateOutput(options); !usable) throw UsageError("generate: " + usable.error());
  std::unique_ptr<ProgressBar> progress;
  if (!command.quiet) {
    // The bar counts rooms as they are furnished; it draws only on a terminal.
    options.furnishing.on_start = [&](size_t rooms) { progress = std::make_unique<ProgressBar>("furnish", rooms); };
    options.furnishing.on_room_done = [&](const std::string&) { progress->Advance(); };
  }

  Result<GenerateSummary> summary = GenerateVilla(command.text, options);
  if (progress) progress->Finish();
  if (!summary) {
    if (summary.error().rfind("usage: ", 0) == 0) throw UsageError("generate: " + summary.error().substr(7));
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
  solver::FurnishOptions& f = command->furnish;
  CLI::App* sub = app.add_subcommand(
      "generate",
      "Text to a furnished 3D villa: plan a layout from the request (like `villa plan`), build it (like\n"
      "`villa build`) and furnish every room (like `villa furnish --text`: the request's furniture wishes go to\n"
      "the rooms they name, \"a TV in the meeting room\"). Writes into OUTDIR:\n"
      "  layout.json    the layout\n"
      "  plan.png       the floor plans with every object's footprint\n"
      "  scene.json     every room's graph and the objects' poses\n"
      "  furnished.glb  the building and every object (glTF 2.0)\n"
      "  CREDITS        the Creative Commons Attribution models placed\n"
      "  rooms/*.png    a picture of each room: a top view and a cut-away view\n"
      "  preview.png    the furnished villa from outside and a cut-away of each level\n"
      "  report.json    brief, checks, FSR/RR/VCR, CR/FR/OBR/CSR/NO (RCH/ACC when reachability is measured),\n"
      "                 every room's furnishing, timings\n"
      "--no-furnish stops after the building: layout.json, plan.png, building.glb, preview.png, report.json.\n"
      "Rooms are furnished in parallel (--jobs); the files are the same whatever the job count.\n"
      "Exit status: 0 a valid layout built and furnished, 1 the plan, the build or the furnishing failed (what\n"
      "could be written is written, report.json says why), 2 usage.");
  sub->add_option("text", command->text, "the request, in English (\"-\" reads it from stdin)")->required();
  sub->add_option("-o,--out", command->out, "output folder (created if missing)")->required()->check(PathName());
  AddBackendFlags(sub, command->backend, command->api_key_env, command->options);
  AddFurnishFlags(sub, f);
  AddCriticChoice(sub, f);
  sub->add_flag("--no-furnish", command->no_furnish, "plan and build only (building.glb, no furniture)");
  sub->add_flag("--force", command->force, "overwrite existing output files in OUTDIR");
  sub->add_flag("-q,--quiet", command->quiet, "print nothing on success");
  sub->callback([command] { Run(*command); });
}};

}  // namespace
}  // namespace villa::cli
