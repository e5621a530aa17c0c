#pragma once
// `villa finetune check DIR`: re-reads an export and reports what would spoil training or evaluation:
// lines that are not samples, answers that are not valid canonical layouts, layouts (by geometry) that
// appear in more than one split, system prompts that differ from SystemPrompt(), and dataset_info.json
// entries that would not read their files.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "util/result.h"

namespace villa {

struct CheckReport {
  std::size_t files = 0;
  std::size_t samples = 0;               // lines read as samples
  std::size_t bad_lines = 0;             // not JSON, not a sample of any format, empty prompt, mixed formats
  std::size_t invalid_answers = 0;       // answer does not parse, is not canonical, breaks a rule, misses the schema
  std::size_t prompt_mismatches = 0;     // system prompt differs from the one compiled into villa
  std::size_t leaked_layouts = 0;        // geometries found in more than one split
  std::size_t dataset_info_problems = 0; // missing/unreadable dataset_info.json, or an entry that does not fit
  std::vector<std::string> messages;     // the first problems, "file:line: ..."

  bool ok() const {
    return bad_lines == 0 && invalid_answers == 0 && prompt_mismatches == 0 && leaked_layouts == 0 &&
           dataset_info_problems == 0 && samples > 0;
  }
  std::string BriefReport() const;
};

// Fails only when DIR cannot be read at all; problems in the data are counted in the report.
Result<CheckReport> CheckExport(const std::filesystem::path& dir);

}  // namespace villa
