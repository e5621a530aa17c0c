// villa scenes LAYOUTS.jsonl --out DIR [--shard i/n|auto] [--seed S] [--library DIR | --procedural]
//              [--critic offline|none] [--no-reach] [--no-physics] [--pictures] [--jobs N] [--force]
// Every layout of a dataset furnished into DIR/scenes/<id>/ with one index line a villa in
// DIR/scenes.jsonl, sharded and resumable (shards/scenes.h does the work; this file parses flags and
// prints). Registered by shards/CMakeLists.txt.
#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

#include "cli/command.h"
#include "cli/flags.h"
#include "cli/furnish_flags.h"
#include "shards/scenes.h"

namespace villa::cli {
namespace {

struct ScenesCommand {
  std::string input;
  std::string out;
  std::string shard = "0/1";
  bool pictures = false;
  bool quiet = false;
  shards::ScenesOptions options;
};

std::string Clock(double seconds) {
  const long s = static_cast<long>(seconds + 0.5);
  char text[32];
  std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  return text;
}

void Run(ScenesCommand& command) {
  shards::ScenesOptions& o = command.options;
  Result<Shard> shard = ParseShard(command.shard);
  if (!shard) throw UsageError("scenes: " + shard.error());
  o.shard = *shard;
  o.input = command.input;
  o.out = command.out;
  o.furnish.pictures = command.pictures;
  const auto start = std::chrono::steady_clock::now();
  int furnished_now = 0;  // on_villa is called for the villas this run furnishes (not those kept from before)
  if (!command.quiet)
    // One line a villa (a cluster task's log is a file, not a terminal): count, rate, ETA.
    o.on_villa = [&](const shards::Json& entry, int done, int failed, int total) {
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const int finished = done + failed;
      const double per_villa = elapsed / ++furnished_now;  // this run's rate: a resumed run's kept villas cost nothing
      std::printf("scenes %s: %d/%d (%d failed) %s %s in %.1f s; %.1f villas/h, ETA %s\n", shard->Text().c_str(), finished, total, failed,
                  entry["id"].get<std::string>().c_str(), entry.value("status", "").c_str(), entry.value("seconds", 0.0),
                  3600.0 / per_villa, Clock(per_villa * (total - finished)).c_str());
      std::fflush(stdout);
    };
  auto summary = shards::RunScenesShard(o);
  if (!summary) {
    const std::string& message = summary.error();
    if (message.rfind("usage: ", 0) == 0) throw UsageError("scenes: " + message.substr(7));
    std::cerr << "villa scenes: " << message << "\n";
    SetExitCode(kExitFailure);
    return;
  }
  if (!command.quiet)
    std::cout << "scenes " << shard->Text() << ": " << summary->total << " villas, " << summary->done << " furnished now, "
              << summary->skipped << " kept from before, " << summary->failed << " failed; " << summary->seconds << " s; wrote "
              << command.out << "/scenes.jsonl\n";
  SetExitCode(summary->failed ? kExitFailure : kExitOk);
}

Registration registration{78, [](CLI::App& app) {
  auto command = std::make_shared<ScenesCommand>();
  shards::ScenesOptions& o = command->options;
  CLI::App* sub = app.add_subcommand(
      "scenes",
      "Furnish every layout of a dataset, as `villa furnish` furnishes one: layouts.jsonl from `villa synth`,\n"
      "an annotator export (rejected layouts left out) or a fine-tune export's train/val/test file.\n"
      "Writes into DIR:\n"
      "  scenes/<id>/   layout.json, scene.json, furnished.glb, report.json, CREDITS, entry.json (and\n"
      "                 plan.png, rooms/*.png with --pictures), each villa's folder moved into place whole\n"
      "  scenes.jsonl   one line a villa: id, index, layout SHA-256, seed, status, metrics (CR, FR, OBR,\n"
      "                 CSR, RCH, ACC, physics), every file with its SHA-256, seconds\n"
      "  manifest.json  the recipe (input and its SHA-256, seed, options, library, tool version, shard)\n"
      "  progress.json  done, failed, left, rate and ETA (`villa dataset status DIR`)\n"
      "--shard i/n (or auto in a Slurm array task or a Kubernetes indexed job) furnishes the i-th of n\n"
      "contiguous parts; `villa dataset merge` joins the shards into what one run would write. A rerun\n"
      "keeps every villa whose files still match their SHA-256 and redoes the rest (a killed run resumes).\n"
      "Each villa's seed comes from --seed and its id, so a villa is the same whatever shard furnishes it.\n"
      "Exit status: 0 every villa furnished, 1 some failed (their entries say why) or a write failed,\n"
      "2 usage (bad flags, a folder holding another recipe's shard, the shard running elsewhere).");
  sub->add_option("layouts", command->input, "the layouts (.jsonl)")->required();
  sub->add_option("--out", command->out, "the shard's folder (created if missing)")->required()->check(PathName());
  sub->add_option("--shard", command->shard, "furnish only shard i of n, e.g. 3/8 (default 0/1); auto: from SLURM_ARRAY_TASK_ID or JOB_COMPLETION_INDEX");
  sub->add_option("--seed", o.seed, "the dataset's furnishing seed (each villa's is mixed from it and its id)")->capture_default_str()->transform(Seed());
  sub->add_option("--critic", o.critic, "offline (default) or none")->check(CLI::IsMember({"offline", "none"}));
  AddFurnishFlags(sub, o.furnish, {.seed = false, .jobs = true, .reach = true, .scope = ""});
  sub->add_flag("--pictures", command->pictures, "also draw plan.png and rooms/*.png for every villa (slower)");
  sub->add_flag("--allow-invalid", o.furnish.allow_invalid, "furnish layouts that break the geometric rules 1-5 (else failed)");
  sub->add_flag("--force", o.force, "start over in a folder that holds another recipe's shard");
  sub->add_flag("-q,--quiet", command->quiet, "print only the problems");
  sub->callback([command] { Run(*command); });
}};

}  // namespace
}  // namespace villa::cli
