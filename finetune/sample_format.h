#pragma once
// One training sample as a JSONL line in each export format, the LLaMA-Factory dataset_info.json entry
// that reads it, and the reverse: a line of any of the three formats back to its three texts.
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "finetune/export.h"
#include "util/result.h"

namespace villa {

struct SampleTexts {
  std::string system;     // the system prompt
  std::string user;       // the description
  std::string assistant;  // the layout, compact canonical JSON
};

// The line's JSON object (write it with .dump()).
nlohmann::ordered_json SampleLine(ExportFormat format, const SampleTexts& texts);

// Reads a line written by SampleLine in any format; the error names what is missing or mistyped. The
// format found is stored in *format when given.
Result<SampleTexts> ParseSampleLine(const nlohmann::ordered_json& line, ExportFormat* format = nullptr);

// The dataset_info.json entry for a split file: for messages data "formatting": "sharegpt" with the
// messages column and the role/content tags (without them LLaMA-Factory skips every sample); for
// sharegpt data its conversations and system columns; for alpaca the prompt/query/response/system columns.
nlohmann::ordered_json DatasetInfoEntry(ExportFormat format, const std::string& file_name);

}  // namespace villa
