#pragma once
// The fine-tune export: annotated layouts (`villa annotate DIR --export FILE.jsonl`) -> training data that
// LoRA trainers read as is (LLaMA-Factory, axolotl, TRL, unsloth, OpenAI fine-tuning), with the trainers'
// configs and a data card.
//
// One sample = (system prompt, a description of a layout, the layout as compact canonical JSON). The
// system prompt is SystemPrompt() (finetune/system_prompt.md), the same bytes the generator sends.
// Every answer is re-validated (ValidateLayout, all ten rules) and must round-trip through the text
// format and match LayoutJsonSchema(); rejected, pending and invalid records are left out and counted.
// Splits are decided per geometry (GeometryKey), so all descriptions of one layout share a split, and a
// geometry seen twice is kept once. Same input and options give byte-identical files.
#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "util/result.h"

namespace villa {

enum class ExportFormat {
  kMessages,  // {"messages":[{"role":"system",...},{"role":"user",...},{"role":"assistant",...}]}
  kShareGpt,  // {"conversations":[{"from":"human",...},{"from":"gpt",...}],"system":...}
  kAlpaca,    // {"instruction":...,"input":"","output":...,"system":...}
};
std::string_view ExportFormatName(ExportFormat format);  // "messages", "sharegpt", "alpaca"

// Which annotation statuses become samples. Rejected and pending records never do.
enum class IncludeStatus {
  kVerified,  // only layouts a person verified
  kAuto,      // only auto-annotated layouts
  kAll,       // verified and auto
};

// How many samples a layout gives. The paper annotates each layout with either a coarse or a fine
// description: kOne picks one of the two, deterministically from the seed and the record id (the other
// when the picked one is empty); kBoth makes a sample of each non-empty description.
enum class DescriptionChoice { kOne, kBoth };

inline constexpr int kSplitCount = 3;
inline constexpr std::array<const char*, kSplitCount> kSplitNames = {"train", "val", "test"};

struct ExportOptions {
  ExportFormat format = ExportFormat::kMessages;
  // Shares of train, val, test; non-negative, summing to 1 (within 1e-6). Counts are exact: val and test
  // get round(share * layouts), train the rest.
  std::array<double, kSplitCount> split = {0.9, 0.05, 0.05};
  IncludeStatus include = IncludeStatus::kAll;
  DescriptionChoice descriptions = DescriptionChoice::kOne;
  std::uint64_t seed = 0;  // reorders splits and picks descriptions; same seed, same files
  std::string base_model = "Qwen/Qwen3.5-9B";  // written into the trainer configs
  std::string dataset_name = "villa";          // prefix of the dataset_info.json entries: villa_train, ...
  bool force = false;                          // write into a non-empty output folder

  // Empty when valid, else what is wrong, naming the option.
  std::string Invalid() const;
};

// Length statistics of one text field over the exported samples.
struct LengthStats {
  std::size_t count = 0;
  std::size_t min = 0, max = 0, median = 0;
  double mean = 0.0;
};
LengthStats ComputeLengthStats(std::vector<std::size_t> values);

// A rough token count for Qwen-style BPE on this kind of text (digits are single tokens, JSON punctuation
// mostly single tokens, words about 4 letters a token). It errs on the high side, so a cutoff length
// derived from it does not truncate answers.
std::size_t ApproxTokens(std::string_view text);

struct ExportSummary {
  // Input records.
  std::size_t records = 0;
  std::size_t bad_lines = 0;           // lines that are not JSON or not a record
  std::size_t rejected = 0;            // status "rejected"
  std::map<std::string, std::size_t> rejected_reasons;  // its "reason" -> records
  std::size_t pending = 0;             // status "pending"
  std::size_t excluded_status = 0;     // verified/auto left out by --include
  std::size_t unknown_status = 0;      // a status outside the four
  std::size_t unreadable_layout = 0;   // the layout does not parse
  std::size_t invalid_layout = 0;      // parses but breaks a rule of FORMAT.md
  std::size_t answer_mismatch = 0;     // valid, but its answer does not round-trip or match the schema
  std::size_t no_description = 0;      // neither description is present
  std::size_t duplicate_geometry = 0;  // same geometry as an earlier record: kept once
  std::map<int, std::size_t> invalid_by_rule;  // first broken rule -> layouts
  std::vector<std::string> problems;           // first messages, "file:line: ..." (at most 20)

  // Exported.
  std::size_t layouts = 0;  // distinct geometries exported
  std::array<std::size_t, kSplitCount> layouts_per_split{};
  std::array<std::size_t, kSplitCount> samples_per_split{};
  std::size_t samples = 0;
  std::map<int, std::size_t> layouts_by_floors;          // floors -> layouts
  std::map<std::string, std::size_t> layouts_by_shape;   // footprint class -> layouts
  std::size_t slanted_outside = 0;  // layouts whose ground outline has a slanted edge
  std::size_t slanted_inside = 0;   // layouts with a slanted wall, door or open between two rooms
  std::map<std::string, std::size_t> layouts_by_status;  // verified / auto -> layouts
  std::size_t coarse_samples = 0;
  std::size_t fine_samples = 0;
  LengthStats prompt_chars, prompt_tokens, answer_chars, answer_tokens, sample_tokens;
  std::size_t system_prompt_chars = 0, system_prompt_tokens = 0;
  int cutoff_len = 0;  // written into the configs: the longest sample, with headroom
  std::vector<std::string> files;  // written, relative to the output folder

  std::string BriefReport() const;
};

// Reads `annotated` (JSONL), writes DIR/{train,val,test}.jsonl, dataset_info.json,
// llamafactory_lora_sft.yaml, axolotl.yaml (messages format only), sources.jsonl and README.md, each
// atomically. Fails (nothing written) on unreadable input, invalid options, or a non-empty `out_dir`
// without options.force; with force, previous export files of any format are replaced or removed.
Result<ExportSummary> ExportDataset(const std::filesystem::path& annotated, const std::filesystem::path& out_dir,
                                    const ExportOptions& options);

}  // namespace villa
