#include "finetune/export.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numeric>
#include <set>
#include <sstream>
#include <system_error>
#include <unordered_set>

#include "finetune/data_card.h"
#include "finetune/geometry_key.h"
#include "finetune/layout_schema.h"
#include "finetune/sample_format.h"
#include "finetune/system_prompt.h"
#include "finetune/trainer_configs.h"
#include "layout/footprint.h"
#include "layout/layout_io.h"
#include "layout/validate.h"
#include "util/atomic_file.h"
#include "util/hash.h"
#include "util/text_table.h"

namespace villa {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t kMaxProblems = 20;

// Every file name an export may write; with --force the ones not written this time are removed, so an
// old split or config cannot linger beside a new export.
const std::vector<std::string>& KnownOutputFiles() {
  static const std::vector<std::string> files = {"train.jsonl", "val.jsonl", "test.jsonl", "dataset_info.json",
                                                 "llamafactory_lora_sft.yaml", "axolotl.yaml", "sources.jsonl",
                                                 "README.md"};
  return files;
}

std::string Trim(std::string text) {
  auto space = [](unsigned char c) { return std::isspace(c) != 0; };
  while (!text.empty() && space(text.back())) text.pop_back();
  std::size_t start = 0;
  while (start < text.size() && space(text[start])) ++start;
  return text.substr(start);
}

struct Description {
  const char* kind;  // "coarse" or "fine"
  std::string text;
};

// One exported layout: its answer and the descriptions that become its samples.
struct Candidate {
  std::string id;
  std::string status;
  std::string shape;
  bool slanted_outside = false, slanted_inside = false;  // a slanted outside edge / wall between rooms
  int floors = 0;
  std::string geometry;
  std::uint64_t order = 0;  // position key within the shuffled list
  std::string answer;
  std::vector<Description> samples;
  int split = 0;
};

void AddProblem(ExportSummary& summary, std::string message) {
  if (summary.problems.size() < kMaxProblems) summary.problems.push_back(std::move(message));
}

bool StatusIncluded(IncludeStatus include, const std::string& status) {
  switch (include) {
    case IncludeStatus::kVerified: return status == "verified";
    case IncludeStatus::kAuto: return status == "auto";
    case IncludeStatus::kAll: return status == "verified" || status == "auto";
  }
  return false;
}

std::string DescriptionText(const Json& record, const char* kind) {
  auto it = record.find("descriptions");
  if (it == record.end() || !it->is_object()) return {};
  auto d = it->find(kind);
  if (d == it->end() || !d->is_string()) return {};
  return Trim(d->get<std::string>());
}

Status CheckOutputFolder(const fs::path& out_dir, bool force) {
  std::error_code ec;
  if (!fs::exists(out_dir, ec)) return Status::Ok();
  if (!fs::is_directory(out_dir, ec)) return Error{out_dir.string() + ": exists and is not a folder"};
  if (!force && fs::directory_iterator(out_dir, ec) != fs::directory_iterator()) {
    return Error{out_dir.string() + ": folder is not empty (use --force to replace an earlier export)"};
  }
  if (ec) return Error{out_dir.string() + ": " + ec.message()};
  return Status::Ok();
}

int CutoffLength(std::size_t longest_tokens) {
  // 10% headroom over the estimate, rounded up to a multiple of 256.
  double wanted = static_cast<double>(longest_tokens) * 1.1 + 64.0;
  return static_cast<int>(std::ceil(wanted / 256.0)) * 256;
}

}  // namespace

std::string_view ExportFormatName(ExportFormat format) {
  switch (format) {
    case ExportFormat::kMessages: return "messages";
    case ExportFormat::kShareGpt: return "sharegpt";
    case ExportFormat::kAlpaca: return "alpaca";
  }
  return "";
}

std::string ExportOptions::Invalid() const {
  double sum = 0.0;
  for (double share : split) {
    if (!(share >= 0.0) || !std::isfinite(share)) return "--split: shares must be non-negative numbers";
    sum += share;
  }
  if (std::abs(sum - 1.0) > 1e-6) return "--split: the three shares must sum to 1, got " + FormatFixed(sum, 6);
  if (split[0] <= 0.0) return "--split: the train share must be positive";
  if (base_model.empty()) return "--base-model: must not be empty";
  if (dataset_name.empty()) return "--name: must not be empty";
  for (char c : dataset_name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') {
      return "--name: only letters, digits, '_' and '-' (it names dataset_info.json entries), got \"" + dataset_name + "\"";
    }
  }
  return {};
}

LengthStats ComputeLengthStats(std::vector<std::size_t> values) {
  LengthStats stats;
  if (values.empty()) return stats;
  std::sort(values.begin(), values.end());
  stats.count = values.size();
  stats.min = values.front();
  stats.max = values.back();
  stats.median = values[(values.size() - 1) / 2];
  double total = 0.0;
  for (auto v : values) total += static_cast<double>(v);
  stats.mean = total / static_cast<double>(values.size());
  return stats;
}

std::size_t ApproxTokens(std::string_view text) {
  std::size_t tokens = 0;
  std::size_t letters = 0;
  auto flush = [&] {
    tokens += (letters + 3) / 4;
    letters = 0;
  };
  for (unsigned char c : text) {
    if (std::isalpha(c) || c >= 0x80) {
      ++letters;
    } else {
      flush();
      if (std::isdigit(c)) ++tokens;                    // Qwen tokenizes digits one by one
      else if (!std::isspace(c)) ++tokens;              // punctuation: about one token each
      else if (c == '\n') ++tokens;                     // line breaks do not merge into words
    }
  }
  flush();
  return tokens;
}

std::string ExportSummary::BriefReport() const {
  std::ostringstream out;
  out << "read " << records << " records";
  if (bad_lines) out << " (+" << bad_lines << " bad lines)";
  out << "; exported " << layouts << " layouts as " << samples << " samples\n";
  TextTable splits({"split", "layouts", "samples"});
  for (int s = 0; s < kSplitCount; ++s) {
    splits.AddRow({kSplitNames[s], std::to_string(layouts_per_split[s]), std::to_string(samples_per_split[s])});
  }
  out << splits.Render();
  TextTable left({"left out", "records"});
  left.AddRow({"rejected", std::to_string(rejected)});
  left.AddRow({"pending", std::to_string(pending)});
  if (excluded_status) left.AddRow({"status not included", std::to_string(excluded_status)});
  if (unknown_status) left.AddRow({"unknown status", std::to_string(unknown_status)});
  left.AddRow({"layout does not parse", std::to_string(unreadable_layout)});
  left.AddRow({"layout invalid", std::to_string(invalid_layout)});
  for (const auto& [rule, count] : invalid_by_rule) left.AddRow({"  first broken rule " + std::to_string(rule), std::to_string(count)});
  if (answer_mismatch) left.AddRow({"answer not canonical/schema", std::to_string(answer_mismatch)});
  left.AddRow({"no description", std::to_string(no_description)});
  left.AddRow({"duplicate geometry", std::to_string(duplicate_geometry)});
  if (bad_lines) left.AddRow({"bad lines", std::to_string(bad_lines)});
  out << left.Render();
  for (const auto& p : problems) out << "  " << p << "\n";
  return out.str();
}

Result<ExportSummary> ExportDataset(const fs::path& annotated, const fs::path& out_dir, const ExportOptions& options) {
  if (std::string invalid = options.Invalid(); !invalid.empty()) return Error{invalid};
  if (auto s = CheckOutputFolder(out_dir, options.force); !s) return Error{s.error()};

  ExportSummary summary;
  std::vector<Candidate> candidates;
  std::unordered_set<std::string> seen_geometry;
  const std::string source = annotated.string();
  const std::string system_prompt(SystemPrompt());

  auto on_record = [&](const Json& record, int line) -> bool {
    ++summary.records;
    const std::string where = source + ":" + std::to_string(line);
    if (!record.is_object() || !record.contains("id") || !(record["id"].is_string() || record["id"].is_number_integer())) {
      ++summary.bad_lines;
      AddProblem(summary, where + ": not an annotation record (needs \"id\", \"status\", \"descriptions\", \"layout\")");
      return true;
    }
    const std::string id = record["id"].is_string() ? record["id"].get<std::string>() : record["id"].dump();
    const std::string status = record.contains("status") && record["status"].is_string() ? record["status"].get<std::string>() : "";
    if (status == "rejected") {
      ++summary.rejected;
      auto reason = record.find("reason");
      ++summary.rejected_reasons[reason != record.end() && reason->is_string() && !reason->get<std::string>().empty()
                                     ? reason->get<std::string>()
                                     : "(no reason given)"];
      return true;
    }
    if (status == "pending") {
      ++summary.pending;
      return true;
    }
    if (status != "verified" && status != "auto") {
      ++summary.unknown_status;
      AddProblem(summary, where + ": " + id + ": status: expected verified, auto, rejected or pending, got \"" + status + "\"");
      return true;
    }
    if (!StatusIncluded(options.include, status)) {
      ++summary.excluded_status;
      return true;
    }

    auto layout = LayoutFromRecord(record, where);
    if (!layout) {
      ++summary.unreadable_layout;
      AddProblem(summary, layout.error());
      return true;
    }
    ValidationReport report = ValidateLayout(*layout);
    if (!report.valid()) {
      ++summary.invalid_layout;
      const Violation& first = report.violations.front();
      ++summary.invalid_by_rule[first.rule];
      AddProblem(summary, where + ": " + id + ": rule " + std::to_string(first.rule) + ": " + first.message);
      return true;
    }
    std::string answer = LayoutToString(*layout, -1);
    auto reread = ParseLayoutText(answer, where);
    Status schema = Status::Ok();
    if (reread) schema = MatchLayoutJsonSchema(Json::parse(answer));
    if (!reread || LayoutToString(*reread, -1) != answer || !schema) {
      ++summary.answer_mismatch;
      AddProblem(summary, where + ": " + id + ": answer " +
                              (!reread ? "does not parse back: " + reread.error()
                               : !schema ? "does not match the layout JSON Schema: " + schema.error()
                                         : std::string("does not round-trip to the same text")));
      return true;
    }

    std::vector<Description> texts;
    std::string coarse = DescriptionText(record, "coarse"), fine = DescriptionText(record, "fine");
    if (options.descriptions == DescriptionChoice::kBoth) {
      if (!coarse.empty()) texts.push_back({"coarse", coarse});
      if (!fine.empty()) texts.push_back({"fine", fine});
    } else {
      bool pick_fine = (SplitMix64Hash(StableHash(id) ^ SplitMix64Hash(options.seed)) & 1) != 0;
      if (pick_fine && fine.empty()) pick_fine = false;
      if (!pick_fine && coarse.empty()) pick_fine = true;
      const std::string& text = pick_fine ? fine : coarse;
      if (!text.empty()) texts.push_back({pick_fine ? "fine" : "coarse", text});
    }
    if (texts.empty()) {
      ++summary.no_description;
      AddProblem(summary, where + ": " + id + ": no coarse or fine description");
      return true;
    }

    std::string geometry = GeometryKey(*layout);
    if (!seen_geometry.insert(geometry).second) {
      ++summary.duplicate_geometry;
      return true;
    }

    Candidate c;
    c.id = id;
    c.status = status;
    if (record.contains("shape") && record["shape"].is_string()) {
      c.shape = record["shape"].get<std::string>();
    } else {
      std::optional<ShapeClass> shape = ClassifyFootprint(*layout);
      c.shape = shape ? std::string(ShapeClassName(*shape)) : "none";
    }
    c.floors = layout->LevelCount();
    c.slanted_outside = HasSlantedOutsideEdge(*layout, 0);
    c.slanted_inside = HasSlantedWallBetweenRooms(*layout);
    c.order = SplitMix64Hash(StableHash(geometry) ^ SplitMix64Hash(options.seed));
    c.geometry = std::move(geometry);
    c.answer = std::move(answer);
    c.samples = std::move(texts);
    candidates.push_back(std::move(c));
    return true;
  };
  auto on_bad_line = [&](const std::string& message) {
    ++summary.bad_lines;
    AddProblem(summary, message);
  };
  if (auto s = ReadJsonl(annotated, on_record, on_bad_line); !s) return Error{s.error()};
  if (candidates.empty()) {
    return Error{source + ": nothing to export (" + std::to_string(summary.records) + " records read)\n" + summary.BriefReport()};
  }

  // Deterministic shuffle by geometry, then exact quotas: the first `test` layouts go to test, the next
  // `val` to val, the rest to train. A geometry is one candidate, so it lives in exactly one split.
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    return a.order != b.order ? a.order < b.order : a.geometry < b.geometry;
  });
  const std::size_t n = candidates.size();
  std::size_t n_val = static_cast<std::size_t>(std::llround(options.split[1] * static_cast<double>(n)));
  std::size_t n_test = static_cast<std::size_t>(std::llround(options.split[2] * static_cast<double>(n)));
  while (n_val + n_test >= n && (n_val + n_test) > 0) {
    // Keep at least one training layout.
    if (n_test >= n_val && n_test > 0) --n_test;
    else if (n_val > 0) --n_val;
    else break;
  }
  for (std::size_t i = 0; i < n; ++i) candidates[i].split = i < n_test ? 2 : i < n_test + n_val ? 1 : 0;

  // Lines per split, in shuffled order (trainers that do not shuffle still see mixed floors and shapes).
  std::array<std::string, kSplitCount> content;
  std::string sources;
  std::array<std::size_t, kSplitCount> line_numbers{};
  std::vector<std::size_t> prompt_chars, prompt_tokens, answer_chars, answer_tokens, sample_tokens;
  const std::size_t system_tokens = ApproxTokens(system_prompt);
  constexpr std::size_t kTemplateTokens = 16;  // role markers of a chat template around three turns
  for (int split = 0; split < kSplitCount; ++split) {
    for (const Candidate& c : candidates) {
      if (c.split != split) continue;
      ++summary.layouts_per_split[split];
      ++summary.layouts;
      ++summary.layouts_by_floors[c.floors];
      ++summary.layouts_by_shape[c.shape];
      summary.slanted_outside += c.slanted_outside;
      summary.slanted_inside += c.slanted_inside;
      ++summary.layouts_by_status[c.status];
      const std::size_t answer_tok = ApproxTokens(c.answer);
      for (const Description& d : c.samples) {
        SampleTexts texts{system_prompt, d.text, c.answer};
        content[split] += SampleLine(options.format, texts).dump() + "\n";
        ++line_numbers[split];
        ++summary.samples_per_split[split];
        ++summary.samples;
        (std::string(d.kind) == "coarse" ? summary.coarse_samples : summary.fine_samples)++;
        sources += Json{{"split", kSplitNames[split]}, {"line", line_numbers[split]}, {"id", c.id},
                        {"description", d.kind}, {"status", c.status}}.dump() + "\n";
        const std::size_t prompt_tok = ApproxTokens(d.text);
        prompt_chars.push_back(d.text.size());
        prompt_tokens.push_back(prompt_tok);
        answer_chars.push_back(c.answer.size());
        answer_tokens.push_back(answer_tok);
        sample_tokens.push_back(system_tokens + prompt_tok + answer_tok + kTemplateTokens);
      }
    }
  }
  summary.prompt_chars = ComputeLengthStats(prompt_chars);
  summary.prompt_tokens = ComputeLengthStats(prompt_tokens);
  summary.answer_chars = ComputeLengthStats(answer_chars);
  summary.answer_tokens = ComputeLengthStats(answer_tokens);
  summary.sample_tokens = ComputeLengthStats(sample_tokens);
  summary.system_prompt_chars = system_prompt.size();
  summary.system_prompt_tokens = system_tokens;
  summary.cutoff_len = CutoffLength(summary.sample_tokens.max);

  TrainerConfigInput config;
  config.options = options;
  config.cutoff_len = summary.cutoff_len;
  for (int s = 0; s < kSplitCount; ++s) config.has_split[s] = summary.samples_per_split[s] > 0;

  // Everything is rendered before the first write, so a failure cannot leave half an export.
  std::vector<std::pair<std::string, std::string>> files;
  Json info = Json::object();
  for (int s = 0; s < kSplitCount; ++s) {
    if (!config.has_split[s]) continue;
    files.push_back({SplitFileName(s), std::move(content[s])});
    info[DatasetEntryName(options, s)] = DatasetInfoEntry(options.format, SplitFileName(s));
  }
  files.push_back({"sources.jsonl", std::move(sources)});
  files.push_back({"dataset_info.json", info.dump(2) + "\n"});
  files.push_back({"llamafactory_lora_sft.yaml", LlamaFactoryConfig(config)});
  if (options.format == ExportFormat::kMessages) files.push_back({"axolotl.yaml", AxolotlConfig(config)});
  for (const auto& [name, text] : files) summary.files.push_back(name);
  summary.files.push_back("README.md");
  files.push_back({"README.md", DataCard(summary, config)});

  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec) return Error{out_dir.string() + ": cannot create the folder: " + ec.message()};
  for (const auto& [name, text] : files) {
    if (auto s = WriteFileAtomic(out_dir / name, text); !s) return Error{s.error()};
  }
  for (const auto& known : KnownOutputFiles()) {
    if (std::find(summary.files.begin(), summary.files.end(), known) != summary.files.end()) continue;
    fs::remove(out_dir / known, ec);  // a stale file of an earlier export (only with --force)
  }
  return summary;
}

}  // namespace villa
