// villa finetune export|check: the fine-tune export and its checker (finetune/).
#include <iostream>
#include <sstream>

#include "cli/command.h"
#include "cli/flags.h"
#include "finetune/check.h"
#include "finetune/export.h"
#include "util/number.h"

namespace villa::cli {
namespace {

std::array<double, kSplitCount> ParseSplit(const std::string& text) {
  std::array<double, kSplitCount> shares{};
  std::stringstream in(text);
  std::string part;
  int i = 0;
  while (std::getline(in, part, ':')) {
    if (i >= kSplitCount) throw UsageError("finetune export: --split: expected TRAIN:VAL:TEST, got \"" + text + "\"");
    const std::optional<double> share = ParseNumber(part);
    if (!share) throw UsageError("finetune export: --split: \"" + part + "\" is not a number (in \"" + text + "\")");
    shares[i] = *share;
    ++i;
  }
  if (i != kSplitCount) throw UsageError("finetune export: --split: expected TRAIN:VAL:TEST, got \"" + text + "\"");
  return shares;
}

struct ExportArgs {
  std::string input;
  std::string out;
  std::string split = "0.9:0.05:0.05";
  ExportOptions options;
};

void Setup(CLI::App& app) {
  auto* finetune = app.add_subcommand("finetune", "Export annotated layouts as LoRA fine-tuning data, and check an export");
  finetune->require_subcommand(1);

  auto args = std::make_shared<ExportArgs>();
  auto* exp = finetune->add_subcommand("export", "Write train/val/test JSONL, trainer configs and a data card into DIR");
  exp->add_option("annotated", args->input, "JSONL from `villa annotate DIR --export FILE`")->required()->check(CLI::ExistingFile);
  exp->add_option("--out,-o", args->out, "Output folder (must be empty unless --force)")->required();
  exp->add_option("--format", args->options.format, "Sample format")
      ->transform(CLI::CheckedTransformer(std::map<std::string, ExportFormat>{{"messages", ExportFormat::kMessages},
                                                                               {"sharegpt", ExportFormat::kShareGpt},
                                                                               {"alpaca", ExportFormat::kAlpaca}}))
      ->default_str("messages");
  exp->add_option("--split", args->split, "Shares of train:val:test, summing to 1")->default_str("0.9:0.05:0.05");
  exp->add_option("--include", args->options.include, "Statuses exported: verified, auto, or all (= both)")
      ->transform(CLI::CheckedTransformer(std::map<std::string, IncludeStatus>{{"verified", IncludeStatus::kVerified},
                                                                                {"auto", IncludeStatus::kAuto},
                                                                                {"all", IncludeStatus::kAll}}))
      ->default_str("all");
  exp->add_option("--descriptions", args->options.descriptions,
                  "one: a sample per layout (coarse or fine, picked from seed and id, as in the paper); both: one per description")
      ->transform(CLI::CheckedTransformer(std::map<std::string, DescriptionChoice>{{"one", DescriptionChoice::kOne},
                                                                                    {"both", DescriptionChoice::kBoth}}))
      ->default_str("one");
  exp->add_option("--seed", args->options.seed, "Seed of the split order and the description pick")->default_str("0")->transform(Seed());
  exp->add_option("--base-model", args->options.base_model, "Base model written into the trainer configs")
      ->default_str(args->options.base_model);
  exp->add_option("--name", args->options.dataset_name, "Dataset name: dataset_info.json entries NAME_train, ...")
      ->default_str(args->options.dataset_name);
  exp->add_flag("--force", args->options.force, "Replace an earlier export in DIR");
  exp->callback([args] {
    args->options.split = ParseSplit(args->split);
    if (std::string invalid = args->options.Invalid(); !invalid.empty()) throw UsageError("finetune export: " + invalid);
    auto summary = ExportDataset(args->input, args->out, args->options);
    if (!summary) {
      std::cerr << "villa finetune export: " << summary.error() << "\n";
      SetExitCode(kExitFailure);
      return;
    }
    std::cout << summary->BriefReport();
    std::cout << "wrote " << args->out << "/:";
    for (const auto& f : summary->files) std::cout << " " << f;
    std::cout << "\n";
    SetExitCode(kExitOk);
  });

  auto dir = std::make_shared<std::string>();
  auto* check = finetune->add_subcommand("check", "Re-read an export: bad lines, invalid answers, leakage, system prompts");
  check->add_option("dir", *dir, "Export folder")->required();
  check->callback([dir] {
    auto report = CheckExport(*dir);
    if (!report) {
      std::cerr << "villa finetune check: " << report.error() << "\n";
      SetExitCode(kExitFailure);
      return;
    }
    std::cout << report->BriefReport();
    SetExitCode(report->ok() ? kExitOk : kExitFailure);
  });
}

Registration registration{60, Setup};

}  // namespace
}  // namespace villa::cli
