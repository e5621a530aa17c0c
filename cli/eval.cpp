// villa eval PROMPTS.jsonl [--backend ...] [--jobs J] [--json]: runs many requests through `plan` and
// prints the paper's macro table: FSR, RR, VCR and brief adherence, per prompt and overall
// (generator/text/eval.h runs and aggregates them).
// villa eval --scenes INPUT... : plans, builds and furnishes every request (or layout) three times and
// prints the paper's micro table per room type and the macro table (generator/scene_eval.h);
// villa eval --scenes --glb FILE.glb [--scene scene.json] [--layout layout.json]: the micro table of
// furnished .glb files made by villa or another method (solver/glb_metrics.h).
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/backend_flags.h"
#include "cli/command.h"
#include "cli/flags.h"
#include "generator/text/eval.h"
#include "layout/layout_io.h"
#include "util/progress.h"
#ifdef VILLA_HAVE_FURNISH
#include "cli/critic_flag.h"
#include "cli/furnish_flags.h"
#include "generator/scene_eval.h"
#endif

namespace villa::cli {


namespace {

struct EvalCommand {
  std::vector<std::string> inputs;
  std::string backend = "procedural";
  std::string api_key_env;
  int jobs = 0;
  int limit = 0;
  bool json = false;
  bool markdown = false;
  bool scenes = false;
  int scenes_per_layout = 3;
  std::vector<std::string> glbs, scene_files, layout_files;
  std::string keep;
  PlanOptions options;
#ifdef VILLA_HAVE_FURNISH
  solver::FurnishOptions furnish;  // --library, --procedural, --no-reach, --radius (cli/furnish_flags.h)
#endif
};

void Print(const std::string& text) { std::cout << text; }

#ifdef VILLA_HAVE_FURNISH
// --scenes --glb: every file measured, each a scene of its own layout, then one table over them.
void RunGlb(const EvalCommand& command) {
  const size_t n = command.glbs.size();
  if ((!command.scene_files.empty() && command.scene_files.size() != n) ||
      (!command.layout_files.empty() && command.layout_files.size() != n))
    throw UsageError("eval: give one --scene and one --layout per --glb, in the same order, or none");
  if (!command.inputs.empty()) throw UsageError("eval: --glb takes no request files");
  std::vector<RoomScore> rooms;
  nlohmann::ordered_json files = nlohmann::ordered_json::array();
  std::vector<std::string> notes;
  for (size_t i = 0; i < n; ++i) {
    solver::GlbMetricsOptions o;
    if (!command.scene_files.empty()) o.scene = command.scene_files[i];
    if (!command.layout_files.empty()) o.layout = command.layout_files[i];
    o.library = command.furnish.library;
    for (const std::string& path : {o.scene.string(), o.layout.string(), command.glbs[i]})
      if (!path.empty() && !std::filesystem::exists(path)) throw UsageError(path + ": no such file");
    auto measured = solver::MeasureFurnishedGlb(command.glbs[i], o);
    if (!measured.ok()) {
      std::cerr << "villa eval: " << measured.error() << "\n";
      SetExitCode(kExitFailure);
      return;
    }
    std::vector<RoomScore> one = RoomScoresOf(*measured, static_cast<int>(i), 0);
    rooms.insert(rooms.end(), one.begin(), one.end());
    nlohmann::ordered_json per_room = nlohmann::ordered_json::array();
    for (const solver::GlbRoomMetrics& r : measured->rooms) {
      const solver::ExactMetrics& m = r.metrics;
      nlohmann::ordered_json pairs = nlohmann::ordered_json::array();
      for (const solver::CollisionPair& p : m.pairs) pairs.push_back({p.a, p.b});
      per_room.push_back({{"room", r.room}, {"category", std::string(CategoryName(r.category))}, {"NO", m.objects},
                          {"CR", m.cr}, {"FR", m.fr}, {"OBR", m.obr},
                          {"CSR", m.inside_edges ? nlohmann::ordered_json(m.csr) : nlohmann::ordered_json(nullptr)},
                          {"collisions", pairs}, {"records_resolved", r.records_resolved},
                          {"records_from_mesh", r.records_from_mesh}});
    }
    files.push_back({{"glb", command.glbs[i]}, {"frame", measured->frame}, {"objects", measured->objects},
                     {"rooms", per_room}, {"notes", measured->notes}, {"seconds", measured->seconds}});
    for (const std::string& note : measured->notes) notes.push_back(command.glbs[i] + ": " + note);
  }
  const MicroTable table = MicroTableOf(rooms);
  if (command.json) {
    nlohmann::ordered_json out{{"format", "villa-glb-eval/1"}, {"files", files}, {"micro", MicroTableJson(table)}};
    Print(out.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n");
  } else if (command.markdown) {
    Print(MicroTableMarkdown(table));
  } else {
    for (const auto& f : files)
      std::cout << f["glb"].get<std::string>() << ": " << f["objects"] << " objects, frame " << f["frame"].get<std::string>() << "\n";
    for (const std::string& note : notes) std::cout << "note: " << note << "\n";
    Print(MicroTableText(table));
  }
  SetExitCode(kExitOk);
}

void RunScenes(EvalCommand& command) {
  if (!command.glbs.empty()) {
    if (!command.keep.empty()) throw UsageError("eval: --keep keeps the scenes --scenes furnishes; --glb furnishes none");
    return RunGlb(command);
  }
  if (!command.scene_files.empty() || !command.layout_files.empty())
    throw UsageError("eval: --scene and --layout go with --glb");
  if (command.inputs.empty()) throw UsageError("eval: --scenes needs request files (JSONL) or layouts, or --glb FILE");
  std::vector<std::filesystem::path> inputs(command.inputs.begin(), command.inputs.end());
  for (const auto& p : inputs)
    if (!std::filesystem::exists(p)) throw UsageError(p.string() + ": no such file");
  auto requests = ReadSceneRequests(inputs, command.limit);
  if (!requests) throw UsageError(requests.error());
  SceneEvalOptions options;
  options.plan = command.options;
  options.scenes_per_layout = command.scenes_per_layout;
  options.furnish = command.furnish;
  options.furnish.jobs = command.jobs;
  if (std::string problem = options.Check(); !problem.empty()) throw UsageError("eval: " + problem);
  if (!command.keep.empty()) {
    // Kept scenes never replace anything: a new or empty folder.
    std::error_code ec;
    if (std::filesystem::exists(command.keep, ec) &&
        (!std::filesystem::is_directory(command.keep, ec) || !std::filesystem::is_empty(command.keep, ec)))
      throw UsageError("eval: --keep " + command.keep + ": not a new or empty folder (nothing in it is replaced)");
    options.keep = command.keep;
  }
  std::unique_ptr<ProgressBar> bar;
  options.on_start = [&](size_t scenes) { bar = std::make_unique<ProgressBar>("scenes", scenes); };
  options.on_scene_done = [&] { bar->Advance(); };
  auto summary = EvaluateScenes(*requests, options);
  if (bar) bar->Finish();
  if (!summary) {
    const std::string& message = summary.error();
    if (message.rfind("usage: ", 0) == 0) throw UsageError("eval: " + message.substr(7));
    std::cerr << "villa eval: " << message << "\n";
    SetExitCode(kExitFailure);
    return;
  }
  if (command.json)
    Print(SceneEvalJson(*summary).dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n");
  else if (command.markdown)
    Print(SceneEvalMarkdown(*summary));
  else
    Print(SceneEvalText(*summary));
  SetExitCode(kExitOk);
}
#endif

void Run(EvalCommand& command) {
  if (!command.options.llm.url.empty() && command.backend == "procedural") command.backend = "llm";
  ApplyBackendFlags(command.backend, command.api_key_env, command.options);
  if (command.json && command.markdown) throw UsageError("eval: --json and --markdown exclude each other");
  if (command.scenes) {
#ifdef VILLA_HAVE_FURNISH
    return RunScenes(command);
#else
    throw UsageError("eval: --scenes needs the solver component (this villa was built without it)");
#endif
  }
  if (!command.glbs.empty()) throw UsageError("eval: --glb goes with --scenes");
  if (!command.keep.empty()) throw UsageError("eval: --keep goes with --scenes");
  if (command.markdown) throw UsageError("eval: --markdown goes with --scenes");
  if (command.inputs.size() != 1) throw UsageError("eval: give one JSONL file of requests");
  EvalOptions options;
  options.plan = command.options;
  const std::string& prompts_file = command.inputs.front();
  if (!std::filesystem::exists(prompts_file)) throw UsageError(prompts_file + ": no such file");
  Result<std::vector<EvalPrompt>> prompts = ReadEvalPrompts(prompts_file, command.limit);
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
      "in parallel (--jobs).\n"
      "--scenes: the paper's micro table. Every request is planned, built and furnished --scenes-per-layout\n"
      "times (seeds S+i, S+i+1, ...; a record may give a \"layout\" file to furnish instead, and a .json input\n"
      "or a layout record is furnished as it is), then per room type (the paper's nine: living room, bedroom,\n"
      "bathroom, kitchen, dining room, children's room, office, meeting room, utility room) CR, FR, OBR, CSR,\n"
      "NO, RCH and ACC averaged over each layout's scenes and then over layouts, the macro table and the\n"
      "time per room and per villa against the paper's (docs/METRICS.md). --glb FILE scores furnished .glb\n"
      "files instead (ours or another method's in villa's glTF contract), with their scene.json (--scene)\n"
      "and layout (--layout) when there are any.\n"
      "Exit status: 0 evaluated, 1 a file that cannot be read or scored, 2 usage (missing file, a line\n"
      "without \"text\").");
  sub->add_option("inputs", command->inputs, "JSONL of requests (and, with --scenes, layout files)");
  AddBackendFlags(sub, command->backend, command->api_key_env, command->options);
  sub->add_option("-j,--jobs", command->jobs,
                  "prompts planned at once (default: 8 for llm, the number of cores for procedural); with --scenes, "
                  "rooms furnished at once")
      ->transform(WholeIn(0, 1024));
  sub->add_option("--limit", command->limit, "only the first N prompts")->transform(WholeIn(0, 1000000000));
  sub->add_flag("--json", command->json, "print a machine-readable report instead of the tables");
  sub->add_flag("--markdown", command->markdown, "with --scenes: print Markdown tables");
  sub->add_flag("--scenes", command->scenes, "furnish the layouts and print the micro table per room type");
  sub->add_option("--scenes-per-layout", command->scenes_per_layout, "scenes (furnishing seeds) per layout")
      ->capture_default_str()
      ->transform(WholeIn(1, 100));
  sub->add_option("--glb", command->glbs, "with --scenes: score this furnished .glb (repeatable)");
  sub->add_option("--scene", command->scene_files, "with --glb: its scene.json (repeatable, one per --glb)");
  sub->add_option("--layout", command->layout_files, "with --glb: its layout (repeatable, one per --glb)");
  sub->add_option("--keep", command->keep,
                  "with --scenes: keep each scene's layout.json, scene.json, furnished.glb, report.json and CREDITS in "
                  "DIR/<NNN-request>/<seed>/ (a new or empty folder)");
#ifdef VILLA_HAVE_FURNISH
  AddFurnishFlags(sub, command->furnish, {.seed = false, .jobs = false, .reach = true, .scope = "with --scenes: "});
  AddCriticChoice(sub, command->furnish, "with --scenes: ");
#endif
  sub->callback([command] { Run(*command); });
}};

}  // namespace
}  // namespace villa::cli
