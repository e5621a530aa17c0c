// villa dataset merge OUT SHARD... | verify DIR | status DIR...: the shards of a `villa synth` or
// `villa scenes` job joined, checked and watched (shards/dataset_tools.h does the work). Registered by
// shards/CMakeLists.txt.
#include <ctime>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/command.h"
#include "shards/dataset_tools.h"

namespace villa::cli {
namespace {

struct DatasetCommand {
  std::string out;
  std::vector<std::string> shards;
  std::string dir;
  std::vector<std::string> dirs;
};

Registration registration{79, [](CLI::App& app) {
  auto command = std::make_shared<DatasetCommand>();
  CLI::App* sub = app.add_subcommand(
      "dataset",
      "Shards of a `villa synth` or `villa scenes` job: merge them, verify a dataset, watch a running job.\n"
      "Exit status: 0 done, 1 refused or a check failed (the message names the folder, file and value), 2 usage.");
  sub->require_subcommand(1);
  CLI::App* merge = sub->add_subcommand(
      "merge",
      "Join the shard folders of one job into OUT (a new folder): synth's layouts.jsonl and manifest.json\n"
      "byte-identical to the one-machine run; scenes' villa folders (hard links where possible) and one index.\n"
      "Refuses a shard of another recipe or tool version, a shard twice, a missing, unfinished or torn one.");
  merge->add_option("out", command->out, "the merged dataset's folder (must not exist or be empty)")->required();
  merge->add_option("shards", command->shards, "the shard folders, in any order")->required();
  merge->callback([command] {
    std::vector<std::filesystem::path> dirs(command->shards.begin(), command->shards.end());
    auto summary = shards::MergeShards(command->out, dirs);
    if (!summary) {
      std::cerr << "villa dataset merge: " << summary.error() << "\n";
      SetExitCode(kExitFailure);
      return;
    }
    std::cout << "merged " << summary->shards << " " << summary->kind << " shard(s): " << summary->records
              << (summary->kind == "synth" ? " layouts" : " villas") << (summary->failed ? " (" + std::to_string(summary->failed) + " failed)" : "")
              << " in " << command->out << "\n";
    SetExitCode(kExitOk);
  });
  CLI::App* verify = sub->add_subcommand(
      "verify", "Re-hash every file of a synth or scenes folder (a shard or a merged dataset) against its manifest and index.");
  verify->add_option("dir", command->dir, "the dataset's folder")->required();
  verify->callback([command] {
    auto summary = shards::VerifyDataset(command->dir);
    if (!summary) {
      std::cerr << "villa dataset verify: " << summary.error() << "\n";
      SetExitCode(kExitFailure);
      return;
    }
    std::cout << command->dir << ": " << summary->kind << " dataset verified: " << summary->records
              << (summary->kind == "synth" ? " layouts" : " villas (" + std::to_string(summary->failed) + " failed), " +
                                                            std::to_string(summary->files) + " files hashed")
              << "\n";
    SetExitCode(kExitOk);
  });
  CLI::App* status = sub->add_subcommand(
      "status", "Villas (layouts) done, failed and left per shard and over all, with the rate and ETA of running ones.");
  status->add_option("dirs", command->dirs, "shard folders, or folders holding them")->required();
  status->callback([command] {
    std::vector<std::filesystem::path> dirs(command->dirs.begin(), command->dirs.end());
    auto text = shards::DatasetStatus(dirs, static_cast<int64_t>(std::time(nullptr)));
    if (!text) {
      std::cerr << "villa dataset status: " << text.error() << "\n";
      SetExitCode(kExitFailure);
      return;
    }
    std::cout << *text;
    SetExitCode(kExitOk);
  });
}};

}  // namespace
}  // namespace villa::cli
