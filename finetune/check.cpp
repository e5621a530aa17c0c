#include "finetune/check.h"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "finetune/export.h"
#include "finetune/geometry_key.h"
#include "finetune/layout_schema.h"
#include "finetune/sample_format.h"
#include "finetune/system_prompt.h"
#include "layout/layout_io.h"
#include "layout/validate.h"
#include "util/atomic_file.h"
#include "util/json_read.h"
#include "util/text_table.h"

namespace villa {
namespace {

namespace fs = std::filesystem;
constexpr std::size_t kMaxMessages = 30;

void Note(CheckReport& report, std::string message) {
  if (report.messages.size() < kMaxMessages) report.messages.push_back(std::move(message));
}

// The split a file belongs to: "train", "val" or "test" from its dataset_info entry name or file name;
// any other file is a split of its own, named after the file.
std::string SplitOf(const std::string& entry_name, const std::string& file_name) {
  for (const char* split : kSplitNames) {
    const std::string suffix = std::string("_") + split;
    if (entry_name.size() >= suffix.size() && entry_name.compare(entry_name.size() - suffix.size(), suffix.size(), suffix) == 0) {
      return split;
    }
    if (file_name == std::string(split) + ".jsonl") return split;
  }
  return file_name;
}

struct SplitFile {
  std::string split;
  std::string file_name;
  std::optional<Json> entry;  // its dataset_info.json entry
};

}  // namespace

std::string CheckReport::BriefReport() const {
  std::ostringstream out;
  TextTable table({"check", "count"});
  table.AddRow({"files", std::to_string(files)});
  table.AddRow({"samples", std::to_string(samples)});
  table.AddRow({"bad lines", std::to_string(bad_lines)});
  table.AddRow({"invalid answers", std::to_string(invalid_answers)});
  table.AddRow({"system prompt mismatches", std::to_string(prompt_mismatches)});
  table.AddRow({"layouts leaked across splits", std::to_string(leaked_layouts)});
  table.AddRow({"dataset_info.json problems", std::to_string(dataset_info_problems)});
  out << table.Render();
  for (const auto& m : messages) out << "  " << m << "\n";
  out << (ok() ? "ok\n" : samples == 0 ? "FAILED: no samples found\n" : "FAILED\n");
  return out.str();
}

Result<CheckReport> CheckExport(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return Error{dir.string() + ": not a folder"};
  CheckReport report;

  // Which files, from dataset_info.json (what the trainer will read); without it, every *.jsonl.
  std::vector<SplitFile> files;
  const fs::path info_path = dir / "dataset_info.json";
  auto info_text = ReadFile(info_path);
  std::optional<Json> info;
  if (!info_text) {
    ++report.dataset_info_problems;
    Note(report, info_text.error());
  } else {
    if (Result<Json> parsed = ParseJson<Json>(*info_text, info_path.string()); parsed.ok()) {
      info = std::move(*parsed);
    } else {
      ++report.dataset_info_problems;
      Note(report, parsed.error());
    }
  }
  if (info && info->is_object()) {
    for (const auto& [name, entry] : info->items()) {
      if (!entry.is_object() || !entry.contains("file_name") || !entry["file_name"].is_string()) {
        ++report.dataset_info_problems;
        Note(report, info_path.string() + ": [\"" + name + "\"].file_name: missing");
        continue;
      }
      const std::string file = entry["file_name"];
      files.push_back({SplitOf(name, file), file, entry});
    }
  } else {
    if (info) {
      ++report.dataset_info_problems;
      Note(report, info_path.string() + ": expected an object of dataset entries");
    }
    for (const auto& item : fs::directory_iterator(dir, ec)) {
      const std::string name = item.path().filename().string();
      if (item.path().extension() == ".jsonl" && name != "sources.jsonl") files.push_back({SplitOf("", name), name, std::nullopt});
    }
    std::sort(files.begin(), files.end(), [](const SplitFile& a, const SplitFile& b) { return a.file_name < b.file_name; });
  }

  const std::string_view prompt = SystemPrompt();
  std::map<std::string, std::set<std::string>> splits_of_geometry;
  std::map<std::string, std::string> first_seen;  // geometry -> "file:line" of its first sample
  std::optional<ExportFormat> export_format;
  for (const SplitFile& f : files) {
    ++report.files;
    const fs::path path = dir / f.file_name;
    std::optional<ExportFormat> file_format;
    auto on_record = [&](const Json& line, int number) {
      const std::string where = path.string() + ":" + std::to_string(number);
      ExportFormat format;
      auto texts = ParseSampleLine(line, &format);
      if (!texts) {
        ++report.bad_lines;
        Note(report, where + ": " + texts.error());
        return true;
      }
      if (export_format && *export_format != format) {
        ++report.bad_lines;
        Note(report, where + ": a " + std::string(ExportFormatName(format)) + " sample among " +
                         std::string(ExportFormatName(*export_format)) + " samples");
        return true;
      }
      export_format = format;
      file_format = format;
      ++report.samples;
      if (texts->user.empty()) {
        ++report.bad_lines;
        Note(report, where + ": empty prompt (user turn)");
      }
      if (texts->system != prompt) {
        ++report.prompt_mismatches;
        Note(report, where + ": system prompt differs from the one compiled into villa (" +
                         std::to_string(texts->system.size()) + " vs " + std::to_string(prompt.size()) + " characters)");
      }
      auto layout = ParseLayoutText(texts->assistant, where + ": answer");
      if (!layout) {
        ++report.invalid_answers;
        Note(report, layout.error());
        return true;
      }
      ValidationReport validation = ValidateLayout(*layout);
      Status schema = MatchLayoutJsonSchema(Json::parse(texts->assistant));
      if (!validation.valid()) {
        ++report.invalid_answers;
        const Violation& v = validation.violations.front();
        Note(report, where + ": answer breaks rule " + std::to_string(v.rule) + ": " + v.message);
      } else if (LayoutToString(*layout, -1) != texts->assistant) {
        ++report.invalid_answers;
        Note(report, where + ": answer is not the canonical compact text of its layout");
      } else if (!schema) {
        ++report.invalid_answers;
        Note(report, where + ": answer does not match the layout JSON Schema: " + schema.error());
      }
      std::string geometry = GeometryKey(*layout);
      auto& splits = splits_of_geometry[geometry];
      if (splits.insert(f.split).second && splits.size() == 2) {
        ++report.leaked_layouts;
        Note(report, where + ": the layout of " + first_seen[geometry] + " is also in split \"" + f.split + "\"");
      }
      first_seen.emplace(geometry, where);
      return true;
    };
    auto on_bad_line = [&](const std::string& message) {
      ++report.bad_lines;
      Note(report, message);
    };
    if (auto s = ReadJsonl(path, on_record, on_bad_line); !s) {
      ++report.bad_lines;
      Note(report, s.error());
      continue;
    }
    if (f.entry && file_format) {
      Json expected = DatasetInfoEntry(*file_format, f.file_name);
      bool fits = f.entry->is_object();
      for (const auto& [key, value] : expected.items()) fits = fits && f.entry->contains(key) && (*f.entry)[key] == value;
      if (!fits) {
        ++report.dataset_info_problems;
        Note(report, info_path.string() + ": the entry for " + f.file_name + " does not read " +
                         std::string(ExportFormatName(*file_format)) + " data; expected " + expected.dump());
      }
    }
  }
  return report;
}

}  // namespace villa
