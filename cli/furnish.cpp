// villa furnish LAYOUT -o DIR [--room NAME]... [--text "..."] [--seed N] [--jobs N] [--library DIR]
//                     [--critic offline|mllm|none --mllm URL --model NAME --api-key-env VAR --rounds N]:
// every room of a layout planned, given assets, solved and reviewed by the critic; the scene file, the
// furnished .glb, a report and pictures written into DIR (solver/furnish.h and critic/critic.h do the
// work; this file parses flags and prints). Registered by critic/CMakeLists.txt.
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>

#include "cli/command.h"
#include "cli/flags.h"
#include "cli/furnish_flags.h"
#include "cli/embedding_flags.h"
#include "critic/critic.h"
#include "critic/graph_planner.h"
#include "solver/furnish.h"
#include "util/progress.h"
#include "util/staged_output.h"

namespace villa::cli {
namespace {

struct FurnishCommand {
  std::string layout;
  std::string output;
  bool quiet = false;
  solver::FurnishOptions options;
  std::string critic = "offline";
  std::string graph = "priors";
  std::string api_key_env;
  std::string cache_dir;
  bool no_cache = false;
  bool no_critic_log = false;
  critic::CriticOptions critic_options;
  EmbeddingFlags embeddings;
};

// The critic of the run from its flags (a usage error for a bad combination).
void ApplyCriticFlags(FurnishCommand& command) {
  critic::CriticOptions& c = command.critic_options;
  auto kind = critic::ParseCriticKind(command.critic);
  if (!kind) throw UsageError("furnish: --critic " + command.critic + ": expected offline, mllm or none");
  c.kind = *kind;
  const bool graph_model = command.graph == "mllm";
  if (command.graph != "priors" && !graph_model) throw UsageError("furnish: --graph " + command.graph + ": expected priors or mllm");
  const std::string who = c.kind == critic::CriticKind::kMllm ? "--critic mllm" : "--graph mllm";
  if (c.kind == critic::CriticKind::kMllm || graph_model) {
    if (c.llm.url.empty()) throw UsageError("furnish: " + who + " needs --mllm URL (an OpenAI-compatible endpoint; vision for the critic)");
    if (c.llm.model.empty()) throw UsageError("furnish: " + who + " needs --model NAME");
  } else if (!c.llm.url.empty()) {
    throw UsageError("furnish: --mllm is for --critic mllm or --graph mllm");
  }
  if (!command.api_key_env.empty()) {
    const char* key = std::getenv(command.api_key_env.c_str());
    if (!key || !*key) throw UsageError("furnish: --api-key-env " + command.api_key_env + ": that environment variable is not set");
    c.llm.api_key = key;
  }
  c.chat.cache_dir = command.no_cache ? std::filesystem::path()
                     : command.cache_dir.empty() ? DefaultLlmCacheDir()
                                                 : std::filesystem::path(command.cache_dir);
  c.views.labels = true;
  // Written into the run's staging folder and moved into DIR/critic with the other outputs (all or nothing).
  if (!command.no_critic_log)
    c.log_dir = std::filesystem::path(command.output) / StagedOutput::kStagingName / solver::kCriticLogFolder;
  if (std::string problem = c.Check(); !problem.empty()) throw UsageError("furnish: " + problem);
  command.options.critic = critic::MakeRoomCritic(c);
  if (graph_model) {
    critic::GraphPlannerOptions g{c.llm, c.chat, c.json_schema};
    if (std::string problem = g.Check(); !problem.empty()) throw UsageError("furnish: " + problem);
    command.options.graph_planner = std::make_shared<critic::MllmGraphPlanner>(command.options.planner, g);
  }
}

void Run(FurnishCommand& command) {
  ApplyCriticFlags(command);
  // The embeddings' key: the critic's --api-key-env unless the endpoints differ in need (one key flag).
  command.embeddings.api_key_env = command.api_key_env;
  command.options.acquire.embedder = EmbedderFrom(command.embeddings, "furnish");
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
      "update_pose/update_scale). Then a critic reviews each room and acts through the same four actions\n"
      "(--critic): offline (the default) measures every relation of the room's graph and moves objects\n"
      "until they hold; mllm asks a multimodal model (any OpenAI-compatible vision endpoint) with five\n"
      "pictures and the room's state, for a score and for actions; none keeps the solver's result.\n"
      "Rooms are solved in parallel; the result is the same whatever --jobs.\n"
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
      "  rooms/ROOM.png each room from above and from its south-west corner\n"
      "  critic/ROOM/   every critic round: state, pictures (mllm), requests, answers, actions, energies\n"
      "Reachability (docs/REACH.md): a person (a 0.2 m disc) from the entrance to every room and interaction\n"
      "zone, across floors by the stairs; furniture in the way is moved or removed by the room's solver.\n"
      "A room that cannot be completed keeps its best state and says why (outcome budget or infeasible).\n"
      "Exit status: 0 furnished (whatever the rooms' outcomes), 1 unreadable or unbuildable layout, bad\n"
      "library or write failure, 2 usage (unknown --room, existing outputs without --force, bad values).");
  sub->add_option("layout", command->layout, "layout file (.json)")->required();
  sub->add_option("-o,--output", command->output, "folder to write into (created if missing)")->required()->check(PathName());
  sub->add_option("--room", o.rooms, "furnish only this room (repeatable), as the layout names it: living-room_0/0");
  sub->add_option("--text", o.text,
                  "the request: \"a cosy living room with two armchairs and bookshelves full of books; a desk by the "
                  "window in the office\" (objects are bound to the rooms the text names)");
  AddFurnishFlags(sub, o, {.seed = true, .jobs = true, .reach = true, .scope = ""});
  sub->add_flag("--force", o.force, "overwrite the files of an earlier run in DIR");
  sub->add_flag("--allow-invalid", o.allow_invalid, "furnish even when the layout breaks the geometric rules 1-5");
  critic::CriticOptions& c = command->critic_options;
  sub->add_option("--critic", command->critic, "offline (default: geometric, no server), mllm (a multimodal model) or none")
      ->check(CLI::IsMember({"offline", "mllm", "none"}));
  sub->add_option("--graph", command->graph,
                  "priors (default: the built-in room priors and the request) or mllm (the model revises the priors' "
                  "graph for the request; the structural validator is the gate)")
      ->check(CLI::IsMember({"priors", "mllm"}));
  sub->add_option("--mllm", c.llm.url,
                  "the model's OpenAI-compatible server for --critic mllm: http://host:port, .../v1 or .../v1/chat/completions");
  sub->add_option("--model", c.llm.model, "model name sent in the critic's requests");
  sub->add_option("--api-key-env", command->api_key_env,
                  "name of the environment variable holding the API key (sent as a Bearer token, never written anywhere)");
  sub->add_option("--rounds", c.rounds, "critic rounds per room")->capture_default_str()->transform(WholeIn(0, 100));
  sub->add_option("--timeout", c.llm.timeout_s, "mllm: seconds to wait for one answer")
      ->capture_default_str()
      ->check(NumberIn(0.0, 3600.0, /*above_min=*/true));
  sub->add_option("--retries", c.llm.max_retries, "mllm: retries on 429, 5xx and connection errors")->capture_default_str()->transform(WholeIn(0, 20));
  sub->add_option("--reasks", c.chat.max_reasks, "mllm: questions asked again after a malformed or cut-off answer")
      ->capture_default_str()
      ->transform(WholeIn(0, 20));
  sub->add_option("--llm-cache", command->cache_dir, "folder of cached answers (default: " + DefaultLlmCacheDir().string() + ")");
  sub->add_flag("--no-cache", command->no_cache, "mllm: neither read nor write cached answers");
  sub->add_flag("--no-schema", [&c](std::int64_t) { c.json_schema = false; },
                "mllm: do not send response_format json_schema (servers without structured output)");
  sub->add_option("--embeddings", command->embeddings.url,
                  "rank library assets by the embeddings of this OpenAI-compatible server (with --embeddings-model) "
                  "instead of the offline lexical ones; cached on disk by text");
  sub->add_option("--embeddings-model", command->embeddings.model, "the embedding model's name");
  sub->add_flag("--critic-pictures", c.log_pictures, "offline: log the pictures of every round too (slower)");
  sub->add_flag("--no-critic-log", command->no_critic_log, "do not write DIR/critic/");
  sub->add_flag("-q,--quiet", command->quiet, "print nothing on success");
  sub->callback([command] { Run(*command); });
}};

}  // namespace
}  // namespace villa::cli
