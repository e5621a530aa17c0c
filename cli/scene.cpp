// villa scene plan LAYOUT --room NAME [--text "..."] [--seed N] [--library DIR | --procedural] -o graph.json:
// one room's A-PSSG (objects with affordances, physical and semantic edges, interaction zones, the chosen
// assets; no poses yet) from the built-in room priors and the request text.
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "building/building.h"
#include "cli/command.h"
#include "cli/flags.h"
#include "cli/embedding_flags.h"
#include "layout/layout_io.h"
#include "layout/validate.h"
#include "scene/acquire.h"
#include "scene/file_digest.h"
#include "scene/planner.h"
#include "scene/room_context.h"
#include "scene/validate.h"
#include "util/text_table.h"

namespace villa::cli {
namespace {

struct PlanCommand {
  std::string layout;
  std::string room;
  std::string text;
  uint64_t seed = 0;
  std::string output;
  bool force = false;
  bool quiet = false;
  bool allow_invalid = false;
  std::string library;
  bool procedural = false;
  scene::PlannerOptions options;
  EmbeddingFlags embeddings;
};

void Fail(const std::string& message) {
  std::cerr << "villa scene plan: " << message << "\n";
  SetExitCode(kExitFailure);
}

// The layout as the scene file names it: relative to the output's folder when it can be, else absolute.
std::string LayoutReference(const std::string& layout, const std::string& output) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path from = fs::absolute(fs::path(output), ec).parent_path();
  fs::path relative = fs::relative(fs::absolute(layout, ec), from, ec);
  if (ec || relative.empty()) return fs::absolute(layout, ec).string();
  return relative.generic_string();
}

void Run(PlanCommand& command) {
  namespace fs = std::filesystem;
  if (!fs::exists(command.layout)) throw UsageError("scene plan: " + command.layout + ": no such file");
  if (fs::exists(command.output) && !command.force)
    throw UsageError("scene plan: " + command.output + " exists; pass --force to overwrite it");
  if (std::string problem = command.options.Check(); !problem.empty()) throw UsageError("scene plan: " + problem);

  auto layout = LoadLayout(command.layout);
  if (!layout) return Fail(layout.error());
  if (layout->FindRoom(command.room) < 0) {
    std::string names;
    for (const Room& r : layout->rooms) names += (names.empty() ? "" : ", ") + r.name();
    throw UsageError("scene plan: --room " + command.room + ": no such room in " + command.layout + " (rooms: " + names + ")");
  }
  ValidateOptions vo;
  vo.check_architecture = false;
  ValidationReport report = ValidateLayout(*layout, vo);
  if (!report.geometric_ok()) {
    for (const Violation& v : report.violations)
      if (v.rule <= 5) std::cerr << "villa scene plan: " << command.layout << ": rule " << v.rule << ": " << v.message << "\n";
    if (!command.allow_invalid)
      return Fail(command.layout + ": breaks the geometric rules 1-5; not planned (--allow-invalid plans it anyway)");
  }
  BuildOptions build;
  auto building = BuildBuilding(*layout, build);
  if (!building) return Fail(command.layout + ": " + building.error());
  auto context = scene::RoomContextOf(*layout, *building, build, command.room);
  if (!context) return Fail(command.layout + ": " + context.error());

  scene::PriorsPlanner planner(command.options);
  auto plan = planner.Plan({&*context, command.text, command.seed});
  if (!plan) return Fail(plan.error());

  auto library = scene::OpenFurnishingLibrary(command.library, command.procedural);
  if (!library) return Fail(library.error());
  scene::AcquireOptions acquire;
  acquire.embedder = EmbedderFrom(command.embeddings, "scene plan");
  auto acquirer = scene::AssetAcquirer::Make(*library->library, acquire, command.seed, command.text);
  if (!acquirer) return Fail(acquirer.error());
  auto assets = (*acquirer)->Acquire(*context, plan->objects);
  if (!assets) return Fail(assets.error());

  auto digest = scene::FileSha256(command.layout);
  if (!digest) return Fail(digest.error());
  scene::SceneFile file =
      scene::PlanSceneFile({LayoutReference(command.layout, command.output), *digest}, build, context->name, *plan);
  file.library = library->file;
  scene::ValidateOptions plan_rules;
  plan_rules.all_rooms = false;
  const scene::AssetLookup lookup = [&](std::string_view id) { return (*acquirer)->Find(id); };
  auto findings = scene::ValidateScene(file, *layout, lookup, plan_rules);
  if (!findings.empty())
    return Fail("the planned graph breaks the scene rules (a bug; nothing written):\n" + scene::FormatFindings(findings));
  if (Status s = scene::WriteScene(file, command.output); !s) return Fail(s.error());

  if (!command.quiet) {
    const scene::PlanSummary& sum = plan->summary;
    std::cout << context->name << " (" << CategoryName(context->category) << ", " << FormatFixed(context->area, 1)
              << " m2, free floor " << FormatFixed(context->free_area, 1) << " m2, furnishable "
              << FormatFixed(context->furnishable_area, 1) << " m2): " << sum.objects << " objects (aimed at "
              << sum.target_min << "-" << sum.target_max << "), " << sum.from_prompt << " from the request, "
              << plan->edges.size() << " semantic edges, floor objects cover " << FormatPercent(sum.floor_used, 1.0)
              << "; " << scene::PlanOutcomeName(sum.outcome) << "\n"
              << "assets: " << assets->summary.distinct_assets << " distinct, " << assets->summary.library
              << " from the library, " << assets->summary.procedural << " procedural ("
              << assets->summary.fallbacks << " fallbacks), style " << (*acquirer)->style()
              << (library->note.empty() ? "" : "; " + library->note) << "\n"
              << scene::PlanTable(*plan, context->name) << "wrote " << command.output << "\n";
  }
  SetExitCode(kExitOk);
}

Registration registration{70, [](CLI::App& app) {
  CLI::App* scene = app.add_subcommand("scene", "Scene graphs of rooms (the furnishing stage)");
  scene->require_subcommand(1);
  auto command = std::make_shared<PlanCommand>();
  CLI::App* plan = scene->add_subcommand(
      "plan",
      "Plan one room's A-PSSG: the objects the request names (with counts, containers, places and relations)\n"
      "plus the room type's priors, each with its affordances (V_con, V_pro, V_int), one physical edge\n"
      "(parent + relation) and its interaction zone, and the semantic edges between them; then an asset for\n"
      "every object: storage holding things from its procedural generator (exact shelves and compartments),\n"
      "everything else ranked from the asset library and procedural offers together, a category the library\n"
      "lacks from its generator (no library installed: procedural assets only). Written as a scene file\n"
      "(shared/design/SCENE.md) holding that room; no poses yet (`villa furnish` places them).\n"
      "Deterministic for a seed. Exit status: 0 planned, 1 unreadable or unbuildable layout or library,\n"
      "2 usage (including a --room the layout does not have).");
  plan->add_option("layout", command->layout, "layout file (.json)")->required();
  plan->add_option("--room", command->room, "the room to plan, as the layout names it (living-room_0/0)")->required();
  plan->add_option("--text", command->text,
                   "the request: \"two armchairs, bookshelves full of books and a desk by the window\"; objects the text "
                   "gives other rooms (\"a TV in the meeting room\") are left to them");
  plan->add_option("--seed", command->seed, "seed of the priors' draws")->capture_default_str()->transform(Seed());
  plan->add_option("-o,--output", command->output, "the graph file to write (.json)")->required()->check(PathName());
  plan->add_flag("--force", command->force, "overwrite an existing output file");
  plan->add_flag("--allow-invalid", command->allow_invalid, "plan even when the layout breaks the geometric rules");
  plan->add_option("--library", command->library,
                   "asset library folder (default: $VILLA_ASSETS, else ~/.local/share/villa/assets when installed, "
                   "else procedural assets only)");
  plan->add_flag("--procedural", command->procedural, "procedural assets only, whatever library is installed");
  plan->add_option("--embeddings", command->embeddings.url,
                   "rank library assets by the embeddings of this OpenAI-compatible server instead of the offline "
                   "lexical ones (cached on disk by text)");
  plan->add_option("--model", command->embeddings.model, "the embedding model's name (with --embeddings)");
  plan->add_option("--api-key-env", command->embeddings.api_key_env, "environment variable holding the API key (never printed)");
  plan->add_flag("-q,--quiet", command->quiet, "print nothing on success");
  plan->add_option("--floor-share", command->options.floor_share,
                   "share of the furnishable floor the priors' floor objects may cover")
      ->capture_default_str()
      ->check(NumberIn(0.0, 1.0, /*above_min=*/true));
  plan->callback([command] { Run(*command); });
}};

}  // namespace
}  // namespace villa::cli
