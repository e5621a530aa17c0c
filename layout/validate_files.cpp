#include "layout/validate_files.h"

#include <cmath>
#include <filesystem>

#include "util/atomic_file.h"

namespace villa {
namespace {

std::string IdOf(const Json& record) {
  if (!record.is_object()) return "";
  auto it = record.find("id");
  if (it == record.end()) return "";
  return it->is_string() ? it->get<std::string>() : it->dump();
}

CheckedLayout Check(std::string source, std::string id, const Result<Layout>& layout, const ValidateOptions& options) {
  CheckedLayout out;
  out.source = std::move(source);
  out.id = std::move(id);
  if (!layout) {
    out.parse_error = layout.error();
    out.metrics.parsed = false;
    out.metrics.format_success = false;
    return out;
  }
  out.report = ValidateLayout(*layout, options);
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


void ReadFileInto(const std::string& file, const ValidateOptions& options, std::vector<CheckedLayout>& out) {
  std::filesystem::path path(file);
  if (path.extension() == ".jsonl") {
    Status status = ReadJsonl(
        path,
        [&](const Json& record, int line) {
          std::string source = file + ":" + std::to_string(line);
          out.push_back(Check(source, IdOf(record), LayoutOfRecord(record, source), options));
          return true;
        },
        [&](const std::string& message) {
          auto at = message.find(": not valid JSON");
          std::string source = at == std::string::npos ? file : message.substr(0, at);
          out.push_back(Check(source, "", Error{message}, options));
        });
    if (!status) out.push_back(Check(file, "", Error{status.error()}, options));
    return;
  }
  // A .json file holds one layout, or one record with a "layout" key (and maybe an "id").
  auto text = ReadFile(path);
  if (!text) {
    out.push_back(Check(file, "", Error{text.error()}, options));
    return;
  }
  Json json;
  try {
    json = Json::parse(*text);
  } catch (const Json::parse_error& e) {
    out.push_back(Check(file, "", Error{file + ": not valid JSON: " + e.what()}, options));
    return;
  }
  out.push_back(Check(file, IdOf(json), LayoutOfRecord(json, file), options));
}

Json RatioJson(std::optional<double> value) { return value ? Json(*value) : Json(nullptr); }

}  // namespace

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


ValidateFilesSummary ValidateFiles(const std::vector<std::string>& files, const ValidateFilesOptions& options) {
  ValidateFilesSummary summary;
  for (const auto& file : files) ReadFileInto(file, options.validate, summary.layouts);
  for (const auto& c : summary.layouts) {
    summary.metrics.Add(c.metrics);
    summary.valid += c.valid();
    summary.unparsable += c.parse_error.has_value();
    for (int rule = 1; rule <= 10; ++rule) {
      int count = c.report.CountRule(rule);
      summary.violations_by_rule[rule] += count;
      summary.layouts_by_rule[rule] += count > 0;
    }
  }
  return summary;
}

Json ValidateFilesReportJson(const ValidateFilesSummary& s) {
  const std::vector<CheckedLayout>& checked = s.layouts;
  const MetricsSummary& summary = s.metrics;
  const int valid = s.valid, unparsable = s.unparsable;
  const std::vector<int>& layouts_by_rule = s.layouts_by_rule;
  const std::vector<int>& violations_by_rule = s.violations_by_rule;
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

}  // namespace villa
