// villa furnish LAYOUT -o DIR [--room NAME]... [--text "..."] [--seed N] [--jobs N] [--library DIR]: every
// room of a layout planned, given assets and solved; the scene file, the furnished .glb, a report and
// pictures written into DIR (solver/furnish.h does the work; this file parses flags and prints).
#include <iostream>
#include <memory>
#include <string>

#include "cli/command.h"
#include "cli/flags.h"
#include "solver/furnish.h"
#include "util/progress.h"

namespace villa::cli {
namespace {

struct FurnishCommand {
  std::string layout;
  std::string output;
  bool quiet = false;
  solver::FurnishOptions options;
};

void Run(FurnishCommand& command) {
  if (std::string problem = command.options.Check(); !problem.empty()) throw UsageError("furnish: " + problem);
  std::unique_ptr<ProgressBar> progress;
  if (!command.quiet) {
    // The bar counts rooms; it draws only on a terminal.
    command.options.on_start = [&](size_t rooms) { progress = std::make_unique<ProgressBar>("furnish", rooms); };
    command.options.on_room_done = [&](const std::string&) { progress->Advance(); };
  }
  auto summary = solver::FurnishLayoutFile(command.layout, command.output, command.options);
  if (progress) progress->Finish();
  if (!summary.ok()) {
    const std::string& message = summary.error();
    if (message.rfind("usage: ", 0) == 0) throw UsageError("furnish: " + message.substr(7));
    std::cerr << "villa furnish: " << message << "\n";
    SetExitCode(kExitFailure);
    return;
  }
  if (!command.quiet) {
    std::cout << summary->BriefReport() << "wrote";
    for (const std::string& f : summary->written) std::cout << " " << f;
    std::cout << " in " << command.output << "\n";
  }
  SetExitCode(kExitOk);
}

Registration registration{75, [](CLI::App& app) {
  auto command = std::make_shared<FurnishCommand>();
  solver::FurnishOptions& o = command->options;
  CLI::App* sub = app.add_subcommand(
      "furnish",
      "Furnish every room of a layout (paper Sec. 3.2-3.4). The layout is validated (rules 1-5) and built;\n"
      "each room gets its A-PSSG from the room priors and the request (--text), an asset for every object\n"
      "(storage holding things from its procedural generator, the rest ranked from the asset library with\n"
      "procedural offers; procedural only when no library is installed), and poses from the solver (a\n"
      "constructive start, Ceres per layer, the exact FCL check and a rule agent applying add/remove/\n"
      "update_pose/update_scale). Rooms are solved in parallel; the result is the same whatever --jobs.\n"
      "Writes into DIR (atomically; never over an earlier run's files without --force, never anything else):\n"
      "  scene.json     every room's graph, the placed objects' poses, each room's solve record and metrics\n"
      "                 (shared/design/SCENE.md), checked by the scene validator before it is written\n"
      "  furnished.glb  the building as `villa build` writes it plus one node per object under its room,\n"
      "                 one shared mesh per asset, extras (id, category, asset, parent, relation, licence)\n"
      "  report.json    per room: objects and their assets, energy trace, actions, outcome and reason, CR,\n"
      "                 FR, OBR, CSR, NO, RCH, ACC, seconds; totals and per room type; reachability: every\n"
      "                 room and zone reachable or not, its path and length, what blocks it, the feedback\n"
      "  CREDITS        the Creative Commons Attribution models placed, with their creators\n"
      "  plan.png       the floor plans with every object's footprint and the walks from the entrance\n"
      "Reachability (docs/REACH.md): a person (a 0.2 m disc) from the entrance to every room and interaction\n"
      "zone, across floors by the stairs; furniture in the way is moved or removed by the room's solver.\n"
      "A room that cannot be completed keeps its best state and says why (outcome budget or infeasible).\n"
      "Exit status: 0 furnished (whatever the rooms' outcomes), 1 unreadable or unbuildable layout, bad\n"
      "library or write failure, 2 usage (unknown --room, existing outputs without --force, bad values).");
  sub->add_option("layout", command->layout, "layout file (.json)")->required();
  sub->add_option("-o,--output", command->output, "folder to write into (created if missing)")->required();
  sub->add_option("--room", o.rooms, "furnish only this room (repeatable), as the layout names it: living-room_0/0");
  sub->add_option("--text", o.text,
                  "the request: \"a cosy living room with two armchairs and bookshelves full of books; a desk by the "
                  "window in the office\" (objects are bound to the rooms the text names)");
  sub->add_option("--seed", o.seed, "seed of every random choice (plans, procedural assets, solver)")
      ->capture_default_str()
      ->transform(Seed());
  sub->add_option("--jobs", o.jobs, "rooms furnished at once (0: one per hardware thread)")
      ->capture_default_str()
      ->transform(WholeIn(0, 256));
  sub->add_option("--library", o.library,
                  "asset library folder (default: $VILLA_ASSETS, else ~/.local/share/villa/assets when installed, else "
                  "procedural assets only)");
  sub->add_flag("--procedural", o.procedural_only, "procedural assets only, whatever library is installed");
  sub->add_flag("--force", o.force, "overwrite the files of an earlier run in DIR");
  sub->add_flag("--allow-invalid", o.allow_invalid, "furnish even when the layout breaks the geometric rules 1-5");
  sub->add_flag("--no-reach", [&o](std::int64_t) { o.check_reach = false; },
                "skip reachability (a person walking from the entrance to every room and interaction zone, and the "
                "feedback that clears what furniture blocks); RCH and ACC are then not measured");
  sub->add_option("--radius", o.reach.reach.radius, "the person's radius for reachability, m")
      ->capture_default_str()
      ->check(NumberIn(0.0, 2.0, /*above_min=*/true));
  sub->add_flag("-q,--quiet", command->quiet, "print nothing on success");
  sub->callback([command] { Run(*command); });
}};

}  // namespace
}  // namespace villa::cli
