#pragma once
// Checking many layouts read from files, the library behind `villa validate`: a .json file holds one
// layout (or one record); a .jsonl stream holds a record a line, each the layout itself, {"layout": ...}
// (an object or its text) with an optional "id", or a fine-tuning sample whose answer is the layout
// (messages, ShareGPT conversations, Alpaca output). Every layout goes through ValidateLayout and the
// paper's metrics; the summary counts violations per rule.
#include <optional>
#include <string>
#include <vector>

#include "layout/layout_io.h"
#include "layout/metrics.h"
#include "layout/validate.h"

namespace villa {

// One checked output: a layout, or text that did not parse.
struct CheckedLayout {
  std::string source;  // "file" or "file:line"
  std::string id;      // the record's "id", if any
  std::optional<std::string> parse_error;
  ValidationReport report;
  LayoutMetrics metrics;
  bool valid() const { return !parse_error && report.valid(); }
};

// The layout of one record (see above); errors name `source` and, for a sample, the turn
// ("file:3: messages[2].content: ...").
Result<Layout> LayoutOfRecord(const Json& record, const std::string& source);

struct ValidateFilesOptions {
  ValidateOptions validate;  // tolerances and which rules
};

struct ValidateFilesSummary {
  std::vector<CheckedLayout> layouts;  // in file order, then line order
  MetricsSummary metrics;              // FSR, RR, VCR over all of them (an unparsable output counts)
  int valid = 0;
  int unparsable = 0;
  std::vector<int> layouts_by_rule = std::vector<int>(11, 0);     // [rule]: layouts breaking it (1..10)
  std::vector<int> violations_by_rule = std::vector<int>(11, 0);  // [rule]: its violations (1..10)
  int count() const { return static_cast<int>(layouts.size()); }
  bool all_valid() const { return valid == count(); }
};

// Reads and checks every file (which must exist: the caller says so to the user first). A file that
// cannot be read or a line that is not JSON becomes an unparsable entry naming it.
ValidateFilesSummary ValidateFiles(const std::vector<std::string>& files, const ValidateFilesOptions& options = {});

// The machine-readable report of `villa validate --json`: per layout its source, id, validity, violations
// (rule, elements, message, figure rounded to the tolerance) and metrics, then the summary.
Json ValidateFilesReportJson(const ValidateFilesSummary& summary);

}  // namespace villa
