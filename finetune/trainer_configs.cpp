#include "finetune/trainer_configs.h"

#include <cctype>
#include <sstream>

#include "util/text_table.h"

namespace villa {
namespace {

// YAML scalars we write are either plain words/paths/numbers or double-quoted when they could be read as
// something else (a model id with a colon, spaces).
std::string YamlString(const std::string& text) {
  bool plain = !text.empty();
  for (char c : text) {
    bool ok = std::isalnum(static_cast<unsigned char>(c)) || c == '/' || c == '.' || c == '_' || c == '-';
    plain = plain && ok;
  }
  if (plain) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string Scientific(double value) {
  // 1.0e-4 style, as LLaMA-Factory's examples write learning rates (PyYAML reads "1e-4" as a string).
  std::ostringstream out;
  out.setf(std::ios::scientific);
  out.precision(1);
  out << value;
  std::string text = out.str();  // "1.0e-04"
  auto e = text.find('e');
  std::string mantissa = text.substr(0, e), exponent = text.substr(e + 1);
  char sign = exponent[0];
  std::string digits = exponent.substr(1);
  while (digits.size() > 1 && digits[0] == '0') digits.erase(0, 1);
  return mantissa + "e" + (sign == '-' ? "-" : "+") + digits;
}

}  // namespace

std::string DatasetEntryName(const ExportOptions& options, int split) {
  return options.dataset_name + "_" + kSplitNames[split];
}

std::string SplitFileName(int split) { return std::string(kSplitNames[split]) + ".jsonl"; }

std::string LlamaFactoryConfig(const TrainerConfigInput& in) {
  const auto& h = in.hyper;
  std::ostringstream y;
  y << "# LoRA SFT of the villa layout generator with LLaMA-Factory. Run from this folder:\n"
    << "#   llamafactory-cli train llamafactory_lora_sft.yaml\n"
    << "# Hyper-parameters of the Text2Villa paper: 15 epochs, AdamW, batch size 4, learning rate 1e-4.\n"
    << "# The LoRA rank, alpha, dropout, scheduler and warm-up are our choices (the paper does not give them).\n\n"
    << "### model\n"
    << "model_name_or_path: " << YamlString(in.options.base_model) << "\n"
    << "trust_remote_code: true\n\n"
    << "### method\n"
    << "stage: sft\n"
    << "do_train: true\n"
    << "finetuning_type: lora\n"
    << "lora_target: all\n"
    << "lora_rank: " << h.lora_rank << "\n"
    << "lora_alpha: " << h.lora_alpha << "\n"
    << "lora_dropout: " << FormatFixed(h.lora_dropout, 2) << "\n\n"
    << "### dataset\n"
    << "dataset_dir: .\n"
    << "dataset: " << DatasetEntryName(in.options, 0) << "\n";
  if (in.has_split[1]) y << "eval_dataset: " << DatasetEntryName(in.options, 1) << "\n";
  y << "# qwen3_5_nothink: no empty <think></think> block is put before the JSON answers.\n"
    << "template: qwen3_5_nothink\n"
    << "# The longest sample measured in this export, in approximate tokens, with headroom.\n"
    << "cutoff_len: " << in.cutoff_len << "\n"
    << "overwrite_cache: true\n"
    << "preprocessing_num_workers: 4\n\n"
    << "### output\n"
    << "output_dir: saves/" << in.options.dataset_name << "-lora\n"
    << "logging_steps: 10\n"
    << "save_strategy: epoch\n"
    << "plot_loss: true\n"
    << "overwrite_output_dir: true\n"
    << "report_to: none\n\n"
    << "### train\n"
    << "per_device_train_batch_size: " << h.per_device_batch << "\n"
    << "gradient_accumulation_steps: 1\n"
    << "learning_rate: " << Scientific(h.learning_rate) << "\n"
    << "num_train_epochs: " << h.epochs << ".0\n"
    << "optim: " << h.optimizer << "\n"
    << "lr_scheduler_type: " << h.scheduler << "\n"
    << "warmup_ratio: " << FormatFixed(h.warmup_ratio, 2) << "\n"
    << "bf16: true\n";
  if (in.has_split[1]) {
    y << "\n### eval\n"
      << "per_device_eval_batch_size: " << h.per_device_batch << "\n"
      << "eval_strategy: epoch\n";
  }
  return y.str();
}

std::string AxolotlConfig(const TrainerConfigInput& in) {
  const auto& h = in.hyper;
  auto dataset = [](std::ostringstream& y, const std::string& file, bool test) {
    y << "  - path: " << file << "\n"
      << "    ds_type: json\n";
    if (test) y << "    split: train\n";
    y << "    type: chat_template\n"
      << "    field_messages: messages\n"
      << "    message_property_mappings:\n"
      << "      role: role\n"
      << "      content: content\n"
      << "    roles_to_train: [\"assistant\"]\n";
  };
  std::ostringstream y;
  y << "# LoRA SFT of the villa layout generator with axolotl. Run from this folder:\n"
    << "#   axolotl train axolotl.yaml\n"
    << "# Hyper-parameters of the Text2Villa paper: 15 epochs, AdamW, batch size 4, learning rate 1e-4.\n"
    << "# The LoRA rank, alpha, dropout, scheduler and warm-up are our choices (the paper does not give them).\n\n"
    << "base_model: " << YamlString(in.options.base_model) << "\n"
    << "trust_remote_code: true\n"
    << "chat_template: tokenizer_default\n\n"
    << "datasets:\n";
  dataset(y, SplitFileName(0), false);
  if (in.has_split[1]) {
    y << "test_datasets:\n";
    dataset(y, SplitFileName(1), true);
  }
  y << "val_set_size: 0\n"
    << "dataset_prepared_path: last_run_prepared\n"
    << "output_dir: outputs/" << in.options.dataset_name << "-lora\n\n"
    << "# The longest sample measured in this export, in approximate tokens, with headroom.\n"
    << "sequence_len: " << in.cutoff_len << "\n"
    << "sample_packing: false\n"
    << "train_on_inputs: false\n\n"
    << "adapter: lora\n"
    << "lora_r: " << h.lora_rank << "\n"
    << "lora_alpha: " << h.lora_alpha << "\n"
    << "lora_dropout: " << FormatFixed(h.lora_dropout, 2) << "\n"
    << "lora_target_linear: true\n\n"
    << "micro_batch_size: " << h.per_device_batch << "\n"
    << "gradient_accumulation_steps: 1\n"
    << "num_epochs: " << h.epochs << "\n"
    << "optimizer: " << h.optimizer << "\n"
    << "lr_scheduler: " << h.scheduler << "\n"
    << "learning_rate: " << Scientific(h.learning_rate) << "\n"
    << "warmup_ratio: " << FormatFixed(h.warmup_ratio, 2) << "\n"
    << "bf16: auto\n"
    << "gradient_checkpointing: true\n"
    << "logging_steps: 10\n"
    << "saves_per_epoch: 1\n";
  if (in.has_split[1]) y << "evals_per_epoch: 1\n";
  return y.str();
}

}  // namespace villa
