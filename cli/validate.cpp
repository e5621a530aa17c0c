// villa validate FILE... [--json] [--quiet]: checks layouts against the rules of FORMAT.md and reports the
// paper's metrics (FSR, RR, VCR) over them.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "cli/command.h"
#include "layout/layout_io.h"
#include "layout/metrics.h"
#include "layout/validate.h"
#include "util/atomic_file.h"
#include "util/text_table.h"

namespace villa::cli {
namespace {

struct ValidateCommand {
  std::vector<std::string> files;
  bool json = false;
  bool quiet = false;
};

// One checked output: a layout, or text that did not parse.
struct Checked {
  std::string source;  // "file" or "file:line"
  std::string id;      // the record's "id", if any
  std::optional<std::string> parse_error;
  ValidationReport report;
  LayoutMetrics metrics;
  bool valid() const { return !parse_error && report.valid(); }
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

std::string IdOf(const Json& record) {
  if (!record.is_object()) return "";
  auto it = record.find("id");
  if (it == record.end()) return "";
  return it->is_string() ? it->get<std::string>() : it->dump();
}

Checked Check(std::string source, std::string id, const Result<Layout>& layout) {
  Checked out;
  out.source = std::move(source);
  out.id = std::move(id);
  if (!layout) {
    out.parse_error = layout.error();
    out.metrics.parsed = false;
    out.metrics.format_success = false;
    return out;
  }
  out.report = ValidateLayout(*layout);
  out.metrics = MeasureLayout(*layout, out.report);
  return out;
}

// The answer of the last turn by `role` in a chat array (`role_key`/`text_key`: "role"/"content" for the
// messages format, "from"/"value" for ShareGPT).
const Json* LastTurn(const Json& turns, const char* role_key, const char* text_key, std::initializer_list<const char*> roles,
                     std::size_t* index) {
  if (!turns.is_array()) return nullptr;
  for (std::size_t i = turns.size(); i-- > 0;) {
    const Json& turn = turns[i];
    if (!turn.is_object() || !turn.contains(role_key) || !turn.contains(text_key) || !turn[text_key].is_string()) continue;
    for (const char* role : roles)
      if (turn[role_key] == role) {
        *index = i;
        return &turn[text_key];
      }
  }
  return nullptr;
}

// A layout from one record: the layout itself; {"layout": {...}} or {"layout": "text"}; or a fine-tuning
// sample whose answer is the layout text (messages / ShareGPT conversations / Alpaca output).
Result<Layout> LayoutOfRecord(const Json& record, const std::string& source) {
  if (record.is_object() && !record.contains("rooms")) {
    if (record.contains("layout") && record.at("layout").is_string())
      return ParseLayoutText(record.at("layout").get<std::string>(), source + ": layout");
    std::size_t index = 0;
    if (record.contains("messages")) {
      if (const Json* text = LastTurn(record.at("messages"), "role", "content", {"assistant"}, &index))
        return ParseLayoutText(text->get<std::string>(), source + ": messages[" + std::to_string(index) + "].content");
      return Error{source + ": messages: no assistant answer"};
    }
    if (record.contains("conversations")) {
      if (const Json* text = LastTurn(record.at("conversations"), "from", "value", {"gpt", "assistant"}, &index))
        return ParseLayoutText(text->get<std::string>(), source + ": conversations[" + std::to_string(index) + "].value");
      return Error{source + ": conversations: no gpt answer"};
    }
    if (record.contains("output") && record.at("output").is_string())
      return ParseLayoutText(record.at("output").get<std::string>(), source + ": output");
    if (!record.contains("layout"))
      return Error{source + ": a record needs the layout keys, a \"layout\" key, or a fine-tuning answer (messages, "
                            "conversations or output)"};
  }
  return LayoutFromRecord(record, source);
}

void ReadFileInto(const std::string& file, std::vector<Checked>& out) {
  std::filesystem::path path(file);
  if (path.extension() == ".jsonl") {
    Status status = ReadJsonl(
        path,
        [&](const Json& record, int line) {
          std::string source = file + ":" + std::to_string(line);
          out.push_back(Check(source, IdOf(record), LayoutOfRecord(record, source)));
          return true;
        },
        [&](const std::string& message) {
          auto at = message.find(": not valid JSON");
          std::string source = at == std::string::npos ? file : message.substr(0, at);
          out.push_back(Check(source, "", Error{message}));
        });
    if (!status) out.push_back(Check(file, "", Error{status.error()}));
    return;
  }
  // A .json file holds one layout, or one record with a "layout" key (and maybe an "id").
  auto text = ReadFile(path);
  if (!text) {
    out.push_back(Check(file, "", Error{text.error()}));
    return;
  }
  Json json;
  try {
    json = Json::parse(*text);
  } catch (const Json::parse_error& e) {
    out.push_back(Check(file, "", Error{file + ": not valid JSON: " + e.what()}));
    return;
  }
  out.push_back(Check(file, IdOf(json), LayoutOfRecord(json, file)));
}

std::string Ratio(std::optional<double> value) {
  return value ? FormatFixed(100.0 * *value, 1) + "%" : "-";
}

Json RatioJson(std::optional<double> value) { return value ? Json(*value) : Json(nullptr); }

std::string Label(const Checked& c) { return c.id.empty() ? c.source : c.source + " " + c.id; }

std::string ViolationLine(const Checked& c) {
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

Json ReportJson(const std::vector<Checked>& checked, const MetricsSummary& summary, int valid, int unparsable,
                const std::vector<int>& layouts_by_rule, const std::vector<int>& violations_by_rule) {
  Json layouts = Json::array();
  for (const auto& c : checked) {
    Json entry = Json::object();
    entry["source"] = c.source;
    entry["id"] = c.id.empty() ? Json(nullptr) : Json(c.id);
    entry["parsed"] = !c.parse_error;
    entry["valid"] = c.valid();
    entry["error"] = c.parse_error ? Json(*c.parse_error) : Json(nullptr);
    Json violations = Json::array();
    for (const auto& v : c.report.violations)
      violations.push_back({{"rule", v.rule},
                            {"elements", v.elements},
                            {"message", v.message},
                            {"figure", std::round(v.figure * 1e6) / 1e6}});  // to the tolerance: 0.6, not 0.5999999999999996
    entry["violations"] = std::move(violations);
    entry["metrics"] = {{"format_success", c.metrics.parsed && c.metrics.format_success},
                        {"rooms", c.metrics.rooms},
                        {"rooms_reached_per_floor", c.metrics.rooms_reached_per_floor},
                        {"rooms_reached_from_entrance", c.metrics.rooms_reached_from_entrance},
                        {"floor_pairs", c.metrics.floor_pairs},
                        {"floor_pairs_connected", c.metrics.floor_pairs_connected}};
    layouts.push_back(std::move(entry));
  }
  Json rules = Json::object();
  for (int rule = 1; rule <= 10; ++rule)
    rules[std::to_string(rule)] = {{"layouts", layouts_by_rule[rule]}, {"violations", violations_by_rule[rule]}};
  Json out = Json::object();
  out["layouts"] = std::move(layouts);
  out["summary"] = {{"count", static_cast<int>(checked.size())},
                    {"valid", valid},
                    {"invalid", static_cast<int>(checked.size()) - valid},
                    {"unparsable", unparsable},
                    {"fsr", RatioJson(summary.fsr())},
                    {"rr", RatioJson(summary.rr())},
                    {"rr_entrance", RatioJson(summary.rr_entrance())},
                    {"vcr", RatioJson(summary.vcr())},
                    {"rules", std::move(rules)}};
  return out;
}

void Run(const ValidateCommand& command) {
  for (const auto& file : command.files) {
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) throw UsageError("validate: no such file: " + file);
    if (!std::filesystem::is_regular_file(file, ec)) throw UsageError("validate: not a regular file: " + file);
  }
  std::vector<Checked> checked;
  for (const auto& file : command.files) ReadFileInto(file, checked);

  MetricsSummary summary;
  int valid = 0, unparsable = 0;
  std::vector<int> layouts_by_rule(11, 0), violations_by_rule(11, 0);
  for (const auto& c : checked) {
    summary.Add(c.metrics);
    valid += c.valid();
    unparsable += c.parse_error.has_value();
    for (int rule = 1; rule <= 10; ++rule) {
      int count = c.report.CountRule(rule);
      violations_by_rule[rule] += count;
      layouts_by_rule[rule] += count > 0;
    }
  }
  const int count = static_cast<int>(checked.size());

  if (command.json) {
    std::cout << ReportJson(checked, summary, valid, unparsable, layouts_by_rule, violations_by_rule).dump(2) << "\n";
  } else {
    if (!command.quiet)
      for (const auto& c : checked)
        if (!c.valid()) std::cout << ViolationLine(c) << "\n";
    if (!command.quiet && valid < count) std::cout << "\n";
    std::cout << count << (count == 1 ? " layout: " : " layouts: ") << valid << " valid, " << count - valid
              << " invalid (" << unparsable << " unparsable)\n";
    std::cout << "FSR " << Ratio(summary.fsr()) << "  RR " << Ratio(summary.rr()) << " (per floor)  RR "
              << Ratio(summary.rr_entrance()) << " (from the entrance)  VCR " << Ratio(summary.vcr()) << " ("
              << summary.floor_pairs << " floor pairs)\n";
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
