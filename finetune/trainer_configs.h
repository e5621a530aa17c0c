#pragma once
// The trainer configs written beside an export: LLaMA-Factory (`llamafactory-cli train`) and axolotl
// (`axolotl train`). Defaults are the paper's: LoRA on Qwen3.5-9B, 15 epochs, AdamW, batch 4, lr 1e-4.
// Paths are relative to the export folder: run the trainers from inside it.
#include <string>

#include "finetune/export.h"

namespace villa {

// The paper's hyper-parameters, and our choices where it says nothing (marked).
struct TrainingHyperParameters {
  int epochs = 15;
  double learning_rate = 1e-4;
  int per_device_batch = 4;
  const char* optimizer = "adamw_torch";  // AdamW
  int lora_rank = 16;                     // not in the paper
  int lora_alpha = 32;                    // not in the paper
  double lora_dropout = 0.05;             // not in the paper
  const char* scheduler = "cosine";       // not in the paper
  double warmup_ratio = 0.03;             // not in the paper
};

struct TrainerConfigInput {
  ExportOptions options;  // base_model, dataset_name, format
  std::array<bool, kSplitCount> has_split{};  // which split files were written
  int cutoff_len = 0;     // tokens
  TrainingHyperParameters hyper;
};

std::string LlamaFactoryConfig(const TrainerConfigInput& input);
// Only for the messages format (axolotl's chat_template type reads the messages list with its system turn).
std::string AxolotlConfig(const TrainerConfigInput& input);

// The dataset_info.json name of a split: "<dataset_name>_<split>".
std::string DatasetEntryName(const ExportOptions& options, int split);
// "train.jsonl", ...
std::string SplitFileName(int split);

}  // namespace villa
