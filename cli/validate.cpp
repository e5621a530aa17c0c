// villa validate FILE... [--json] [--quiet]: checks layouts against the rules of FORMAT.md and reports the
// paper's metrics (FSR, RR, VCR) over them (layout/validate_files.h does the reading and checking).
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "cli/command.h"
#include "layout/validate_files.h"
#include "util/text_table.h"

namespace villa::cli {
namespace {

struct ValidateCommand {
  std::vector<std::string> files;
  bool json = false;
  bool quiet = false;
};

constexpr const char* kRuleSummaries[] = {
    "",
    "polygons valid; rooms tile one footprint",
    "upper footprint inside the lower",
    "doors, windows, entrance on their boundaries",
    "interior walls cover shared boundaries",
    "widths: door/open 0.8, window 0.6, room 1.0 m",
    "at most 3 floors and 6 rooms a floor",
    "staircase room 4 x 4 m, stacked, off centre",
    "every room reachable from the entrance",
    "windows in kitchens/bathrooms; balconies",
    "kitchen-dining-living links; nested rooms use doors",
};

std::string Ratio(std::optional<double> value) {
  return value ? FormatFixed(100.0 * *value, 1) + "%" : "-";
}

std::string Label(const CheckedLayout& c) { return c.id.empty() ? c.source : c.source + " " + c.id; }

std::string ViolationLine(const CheckedLayout& c) {
  if (c.parse_error) {
    // The message starts with the source already; put the id in after it.
    std::string message = *c.parse_error;
    std::string prefix = c.source + ": ";
    if (message.rfind(prefix, 0) == 0) message = message.substr(prefix.size());
    return Label(c) + ": cannot parse: " + message;
  }
  std::string line = Label(c) + ": ";
  for (std::size_t i = 0; i < c.report.violations.size(); ++i) {
    const Violation& v = c.report.violations[i];
    line += (i ? "; " : "") + std::string("rule ") + std::to_string(v.rule) + ": " + v.message;
  }
  return line;
}

void Run(const ValidateCommand& command) {
  for (const auto& file : command.files) {
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) throw UsageError("validate: no such file: " + file);
    if (!std::filesystem::is_regular_file(file, ec)) throw UsageError("validate: not a regular file: " + file);
  }
  const ValidateFilesSummary summary = ValidateFiles(command.files);
  const std::vector<CheckedLayout>& checked = summary.layouts;
  const int valid = summary.valid, unparsable = summary.unparsable, count = summary.count();
  const std::vector<int>& layouts_by_rule = summary.layouts_by_rule;
  const std::vector<int>& violations_by_rule = summary.violations_by_rule;

  if (command.json) {
    std::cout << ValidateFilesReportJson(summary).dump(2) << "\n";
  } else {
    if (!command.quiet)
      for (const auto& c : checked)
        if (!c.valid()) std::cout << ViolationLine(c) << "\n";
    if (!command.quiet && valid < count) std::cout << "\n";
    std::cout << count << (count == 1 ? " layout: " : " layouts: ") << valid << " valid, " << count - valid
              << " invalid (" << unparsable << " unparsable)\n";
    const MetricsSummary& metrics = summary.metrics;
    std::cout << "FSR " << Ratio(metrics.fsr()) << "  RR " << Ratio(metrics.rr()) << " (per floor)  RR "
              << Ratio(metrics.rr_entrance()) << " (from the entrance)  VCR " << Ratio(metrics.vcr()) << " ("
              << metrics.floor_pairs << " floor pairs)\n";
    if (valid < count) {
      TextTable table({"rule", "checks", "layouts", "violations"});
      for (int rule = 1; rule <= 10; ++rule)
        table.AddRow({std::to_string(rule), kRuleSummaries[rule], std::to_string(layouts_by_rule[rule]),
                      std::to_string(violations_by_rule[rule])});
      std::cout << "\n" << table.Render();
    }
  }
  SetExitCode(valid == count ? kExitOk : kExitFailure);
}

Registration registration{20, [](CLI::App& app) {
  auto command = std::make_shared<ValidateCommand>();
  CLI::App* sub = app.add_subcommand(
      "validate",
      "Check layouts against the rules 1-10 of the layout format and report FSR, RR and VCR.\n"
      "FILE is a layout (.json) or a JSONL stream (.jsonl, one record a line). A record is the layout itself,\n"
      "{\"layout\": ...} (an object or its text) with an optional \"id\", or a fine-tuning sample whose answer is\n"
      "the layout (messages, ShareGPT conversations, Alpaca output). Prints a line per invalid layout, then\n"
      "a summary.\n"
      "Exit status: 0 all valid, 1 some layout invalid or unparsable, 2 usage (no file, missing file).");
  sub->add_option("files", command->files, "layout files (.json) or JSONL streams (.jsonl)")->required();
  sub->add_flag("--json", command->json,
                "print a machine-readable report on stdout instead: per layout its source, id, validity, "
                "violations (rule, elements, message, figure) and metrics, plus the summary");
  sub->add_flag("-q,--quiet", command->quiet, "print only the summary, not the line per invalid layout");
  sub->callback([command] { Run(*command); });
}};

}  // namespace
}  // namespace villa::cli
