#include "finetune/data_card.h"

#include <numeric>
#include <sstream>

#include "finetune/system_prompt.h"
#include "util/text_table.h"
#include "util/version.h"

namespace villa {
namespace {

std::string Percent(std::size_t part, std::size_t whole) { return FormatPercent(static_cast<double>(part), static_cast<double>(whole)); }

std::string LengthRow(const std::string& what, const LengthStats& s) {
  return "| " + what + " | " + std::to_string(s.min) + " | " + std::to_string(s.median) + " | " + FormatFixed(s.mean, 1) +
         " | " + std::to_string(s.max) + " |\n";
}

// "Floors (1 : 2 : 3 storeys): 200 : 400 : 400, ratio 2 : 4 : 4."
std::string FloorsSentence(const std::map<int, std::size_t>& by_floors) {
  // The ratio in tenths of the total when that is exact (the paper's "2:4:4" for 200/400/400), else in
  // lowest terms.
  std::size_t g = 0, total = 0;
  int top = 0;
  for (const auto& [floors, count] : by_floors) g = std::gcd(g, count), total += count, top = std::max(top, floors);
  bool tenths = total > 0;
  for (const auto& [floors, count] : by_floors) tenths = tenths && (count * 10) % total == 0;
  std::string label, counts, ratio;
  for (int f = 1; f <= top; ++f) {
    auto it = by_floors.find(f);
    std::size_t count = it == by_floors.end() ? 0 : it->second;
    const char* sep = f > 1 ? " : " : "";
    label += sep + std::to_string(f);
    counts += sep + std::to_string(count);
    ratio += sep + std::to_string(tenths ? count * 10 / total : g ? count / g : 0);
  }
  return "Floors (" + label + (top == 1 ? " storey" : " storeys") + "): " + counts + (ratio == counts ? "" : ", ratio " + ratio) + ".";
}

}  // namespace

std::string DataCard(const ExportSummary& s, const TrainerConfigInput& config) {
  const ExportOptions& o = config.options;
  const auto& h = config.hyper;
  const std::string adapter = o.dataset_name + "-layout";
  const std::size_t auto_layouts = s.layouts_by_status.count("auto") ? s.layouts_by_status.at("auto") : 0;
  const std::size_t verified_layouts = s.layouts_by_status.count("verified") ? s.layouts_by_status.at("verified") : 0;
  std::ostringstream md;

  md << "# " << o.dataset_name << ": text-to-layout fine-tuning data\n\n"
     << "Pairs of (a description of a building, its layout as JSON) that teach an LLM to write the layouts of\n"
     << "villa's FORMAT.md: rooms as shapely polygons, doors, opens, windows, interior walls and the entrance as\n"
     << "shapely LineStrings, one to three floors. Written by `villa finetune export` (villa " << kVersion << ") in the\n"
     << "`" << ExportFormatName(o.format) << "` format; check it with `villa finetune check .`.\n\n";

  md << "## Annotation\n\n";
  if (auto_layouts == s.layouts) {
    md << "**No person verified this dataset.** All " << s.layouts << " layouts were labelled and described\n"
       << "automatically (`villa annotate --auto`: drafted room categories and descriptions, status `auto`).\n"
       << "Every answer passes the validator (all ten rules of FORMAT.md), but the descriptions were never read\n"
       << "by a person.\n\n";
  } else if (auto_layouts > 0) {
    md << "**" << auto_layouts << " of " << s.layouts << " layouts were annotated automatically** (`villa annotate --auto`):\n"
       << "no person verified those; " << verified_layouts << " were verified by a person in `villa annotate`.\n\n";
  } else {
    md << "All " << s.layouts << " layouts were verified by a person in `villa annotate` (status `verified`).\n\n";
  }

  md << "## Splits\n\n"
     << "Decided per layout geometry (rooms and 1D elements, names and labels ignored) by a stable hash with\n"
     << "seed " << o.seed << ", with exact quotas for the shares "
     << FormatFixed(o.split[0], 2) << " : " << FormatFixed(o.split[1], 2) << " : " << FormatFixed(o.split[2], 2)
     << ". All descriptions of a layout are in one split, and a geometry that occurs twice is kept once, so no\n"
     << "answer of the val or test split was seen in training.\n\n"
     << "| split | file | layouts | samples |\n| --- | --- | ---: | ---: |\n";
  for (int i = 0; i < kSplitCount; ++i) {
    md << "| " << kSplitNames[i] << " | " << (config.has_split[i] ? std::string("`").append(SplitFileName(i)).append("`") : "(none)") << " | "
       << s.layouts_per_split[i] << " | " << s.samples_per_split[i] << " |\n";
  }
  md << "| total | | " << s.layouts << " | " << s.samples << " |\n\n";

  md << "Left out of " << s.records << " input records: " << s.rejected << " rejected, " << s.pending << " pending, "
     << s.excluded_status << " with a status not included (`--include " << (o.include == IncludeStatus::kVerified ? "verified" : o.include == IncludeStatus::kAuto ? "auto" : "all")
     << "`), " << s.unreadable_layout << " unreadable and " << s.invalid_layout << " invalid layouts, "
     << s.answer_mismatch << " answers off the canonical text, " << s.no_description << " without a description, "
     << s.duplicate_geometry << " duplicate geometries";
  if (s.bad_lines) md << ", " << s.bad_lines << " bad lines";
  md << ".";
  if (!s.rejected_reasons.empty()) {
    md << " Reasons for rejection:";
    for (const auto& [reason, count] : s.rejected_reasons) md << "\n- " << reason << " (" << count << ")";
  }
  md << "\n\n";

  md << "## Composition\n\n"
     << FloorsSentence(s.layouts_by_floors) << "\n\n"
     << "| footprint (ground floor) | layouts | share |\n| --- | ---: | ---: |\n";
  for (const auto& [shape, count] : s.layouts_by_shape) md << "| " << shape << " | " << count << " | " << Percent(count, s.layouts) << " |\n";
  md << "\nA slanted outside edge (neither horizontal nor vertical) in " << s.slanted_outside << " layouts ("
     << Percent(s.slanted_outside, s.layouts) << "), a slanted wall, door or open between two rooms in " << s.slanted_inside
     << " (" << Percent(s.slanted_inside, s.layouts) << ").\n";
  md << "\nDescriptions: " << s.coarse_samples << " coarse (" << Percent(s.coarse_samples, s.samples) << ") and "
     << s.fine_samples << " fine (" << Percent(s.fine_samples, s.samples) << "). ";
  if (o.descriptions == DescriptionChoice::kOne) {
    md << "As in the paper, each layout is described once, by its coarse or its fine description, picked\n"
       << "from the seed and the layout id (`--descriptions one`).\n\n";
  } else {
    md << "Each layout gives a sample per description (`--descriptions both`).\n\n";
  }

  md << "## Lengths\n\n"
     << "Prompts are the user turn (the description), answers the assistant turn (compact JSON). Tokens are\n"
     << "estimated (digits and punctuation one token each, words about four letters a token), on the high side.\n\n"
     << "| field | min | median | mean | max |\n| --- | ---: | ---: | ---: | ---: |\n"
     << LengthRow("prompt, characters", s.prompt_chars) << LengthRow("prompt, ~tokens", s.prompt_tokens)
     << LengthRow("answer, characters", s.answer_chars) << LengthRow("answer, ~tokens", s.answer_tokens)
     << LengthRow("whole sample, ~tokens", s.sample_tokens) << "\n"
     << "The system prompt (the same in every sample) has " << s.system_prompt_chars << " characters, about "
     << s.system_prompt_tokens << " tokens. The configs set the cutoff to " << s.cutoff_len << " tokens.\n\n";

  md << "## Format\n\n";
  switch (o.format) {
    case ExportFormat::kMessages:
      md << "A sample a line: `{\"messages\": [{\"role\": \"system\", ...}, {\"role\": \"user\", ...}, {\"role\": \"assistant\", ...}]}`,\n"
         << "read as is by TRL, axolotl (`type: chat_template`), unsloth, OpenAI fine-tuning and LLaMA-Factory.\n";
      break;
    case ExportFormat::kShareGpt:
      md << "A sample a line: `{\"conversations\": [{\"from\": \"human\", ...}, {\"from\": \"gpt\", ...}], \"system\": ...}`.\n";
      break;
    case ExportFormat::kAlpaca:
      md << "A sample a line: `{\"instruction\": ..., \"input\": \"\", \"output\": ..., \"system\": ...}`.\n";
      break;
  }
  md << "The system prompt is villa's `finetune/system_prompt.md`, compiled into `villa`; `villa plan --backend llm`\n"
     << "sends exactly the same text, so train and inference prompts cannot drift apart. `dataset_info.json`\n"
     << "registers the splits for LLaMA-Factory as `" << DatasetEntryName(o, 0) << "`, `" << DatasetEntryName(o, 1)
     << "`, `" << DatasetEntryName(o, 2) << "` (those present). `sources.jsonl` maps every line back to its layout id.\n\n";

  md << "## Training\n\n"
     << "Defaults are the paper's: LoRA on `" << o.base_model << "`, " << h.epochs << " epochs, AdamW (`" << h.optimizer
     << "`), batch size " << h.per_device_batch << ", learning rate " << FormatFixed(h.learning_rate * 1e4, 0) << "e-4. "
     << "Our own choices where the paper says nothing: LoRA rank " << h.lora_rank << ", alpha " << h.lora_alpha
     << ", dropout " << FormatFixed(h.lora_dropout, 2) << ", " << h.scheduler << " schedule with " << FormatFixed(h.warmup_ratio * 100, 0)
     << "% warm-up. Another base model: re-export with `--base-model NAME`, or edit the configs.\n\n"
     << "LLaMA-Factory (template `qwen3_5_nothink`, so no empty think block lands in front of the JSON):\n\n"
     << "```sh\n# from this folder\nllamafactory-cli train llamafactory_lora_sft.yaml   # adapter in saves/" << o.dataset_name << "-lora\n```\n\n";
  if (o.format == ExportFormat::kMessages) {
    md << "axolotl (`type: chat_template`, loss on the assistant turn only):\n\n"
       << "```sh\n# from this folder\naxolotl train axolotl.yaml   # adapter in outputs/" << o.dataset_name << "-lora\n```\n\n"
       << "TRL (the messages turned into prompt/completion, so the loss covers the answer only):\n\n"
       << "```python\nfrom datasets import load_dataset\nfrom peft import LoraConfig\nfrom trl import SFTConfig, SFTTrainer\n\n"
       << "files = {\"train\": \"train.jsonl\"" << (config.has_split[1] ? ", \"validation\": \"val.jsonl\"" : "") << "}\n"
       << "data = load_dataset(\"json\", data_files=files)\n"
       << "data = data.map(lambda r: {\"prompt\": r[\"messages\"][:2], \"completion\": r[\"messages\"][2:]}, remove_columns=[\"messages\"])\n"
       << "trainer = SFTTrainer(\n"
       << "    model=\"" << o.base_model << "\",\n"
       << "    train_dataset=data[\"train\"],\n";
    if (config.has_split[1]) md << "    eval_dataset=data[\"validation\"],\n";
    md << "    args=SFTConfig(output_dir=\"outputs/" << o.dataset_name << "-lora\", num_train_epochs=" << h.epochs
       << ", learning_rate=1e-4,\n"
       << "                   per_device_train_batch_size=" << h.per_device_batch << ", optim=\"" << h.optimizer
       << "\", max_length=" << s.cutoff_len << ", bf16=True),\n"
       << "    peft_config=LoraConfig(r=" << h.lora_rank << ", lora_alpha=" << h.lora_alpha << ", lora_dropout="
       << FormatFixed(h.lora_dropout, 2) << ", target_modules=\"all-linear\", task_type=\"CAUSAL_LM\"),\n"
       << ")\ntrainer.train()\ntrainer.save_model()\n```\n\n";
  } else {
    md << "axolotl and TRL read the `messages` format: export again with `--format messages` for them.\n\n";
  }

  md << "## Serving and use\n\n"
     << "vLLM serves the base model with the adapter under a name of its own (the path is LLaMA-Factory's\n"
     << "output folder; axolotl and TRL write to `outputs/" << o.dataset_name << "-lora`):\n\n"
     << "```sh\nvllm serve " << o.base_model << " --enable-lora --lora-modules " << adapter << "=saves/" << o.dataset_name
     << "-lora \\\n    --max-lora-rank " << h.lora_rank << " --max-model-len 16384\n```\n\n"
     << "(16,384 tokens leave room for the prompt, about " << s.system_prompt_tokens + s.prompt_tokens.max
     << " tokens here, plus the answer budget `villa plan` asks for by default, 8,192 tokens.)\n\n"
     << "Requests name the adapter as the model and send the same system prompt (thinking off):\n\n"
     << "```json\n{\"model\": \"" << adapter << "\",\n \"messages\": [{\"role\": \"system\", \"content\": \"<finetune/system_prompt.md>\"},\n"
     << "              {\"role\": \"user\", \"content\": \"A two-storey L-shaped house with an open kitchen ...\"}],\n"
     << " \"chat_template_kwargs\": {\"enable_thinking\": false}, \"temperature\": 0.2}\n```\n\n"
     << "villa does all of this itself, with the JSON Schema of the layout as `response_format` and validation of\n"
     << "every answer:\n\n"
     << "```sh\nvilla plan \"A two-storey L-shaped house with an open kitchen\" -o house.json \\\n"
     << "    --backend llm --llm http://localhost:8000/v1 --model " << adapter << "\n```\n";
  return md.str();
}

}  // namespace villa
