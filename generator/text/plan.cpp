// PlanLayout: parse the brief, run a backend, then validate, measure and check whatever came out the same
// way for both backends.
#include "generator/text/plan.h"

#include <chrono>
#include <cmath>
#include <map>
#include <sstream>

#include "generator/text/backends.h"
#include "util/version.h"

namespace villa {
namespace {

using Json = nlohmann::ordered_json;

std::string Number(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

Json Ratio(std::optional<double> r) { return r ? Json(std::round(*r * 10000.0) / 10000.0) : Json(nullptr); }

}  // namespace

std::string_view PlanBackendName(PlanBackend backend) {
  return backend == PlanBackend::kLlm ? "llm" : "procedural";
}

std::string_view PlanOutcomeName(PlanOutcome outcome) {
  switch (outcome) {
    case PlanOutcome::kMet: return "met";
    case PlanOutcome::kPartial: return "partial";
    case PlanOutcome::kInvalid: return "invalid";
    case PlanOutcome::kFailed: return "failed";
  }
  return "failed";
}

bool PlanOptions::IsValid(std::string* message) const {
  auto fail = [&](std::string m) {
    if (message) *message = std::move(m);
    return false;
  };
  if (!(time_budget_s > 0.0)) return fail("time budget " + Number(time_budget_s) + " s: must be > 0");
  if (max_attempts < 1) return fail("max_attempts " + std::to_string(max_attempts) + ": must be >= 1");
  if (rounds < 0) return fail("rounds " + std::to_string(rounds) + ": must be >= 0");
  if (backend == PlanBackend::kLlm) return llm.IsValid(message);
  return true;
}

PlanSummary PlanLayout(const std::string& text, const PlanOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  PlanSummary summary;
  summary.backend = options.backend;
  summary.brief = ParseBrief(text);
  std::string message;
  if (!options.IsValid(&message)) {
    summary.outcome = PlanOutcome::kFailed;
    summary.error = message;
    return summary;
  }
  if (options.backend == PlanBackend::kLlm) PlanWithLlm(text, options, summary);
  else PlanProcedural(summary.brief, options, summary);

  if (summary.layout) {
    ValidationReport report = ValidateLayout(*summary.layout);
    summary.violations = report.violations;
    summary.metrics = MeasureLayout(*summary.layout);
    summary.check = CheckBrief(summary.brief, *summary.layout);
    summary.unmet = summary.check.unmet();
    summary.recount = CheckRecount(text, *summary.layout);
    if (!summary.shape_class) {
      if (auto shape = ClassifyFootprint(*summary.layout, 0)) summary.shape_class = std::string(ShapeClassName(*shape));
    }
  } else {
    summary.metrics.parsed = false;
    summary.metrics.format_success = false;
    // Nothing to check: every requirement counts as unmet.
    Layout empty;
    summary.check = CheckBrief(summary.brief, empty);
    for (auto& r : summary.check.results) {
      r.met = false;
      r.detail = "no layout";
    }
    summary.unmet = summary.check.unmet();
  }
  if (summary.valid()) {
    // Words the parser could not place may hold a requirement it missed (issue 17), and a second, independent
    // count of the text's rooms may read more than the layout has (issue 32): never "met" then.
    summary.outcome = summary.unmet.empty() && summary.brief.unparsed.empty() && summary.recount.empty() ? PlanOutcome::kMet
                                                                                                        : PlanOutcome::kPartial;
    summary.error.clear();
  } else if (summary.layout || summary.attempts > 0) {
    summary.outcome = PlanOutcome::kInvalid;
    if (summary.error.empty()) summary.error = "the layout breaks " + std::to_string(summary.violations.size()) + " rules";
  } else {
    summary.outcome = PlanOutcome::kFailed;
  }
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  summary.added = AddedRooms(summary);
  return summary;
}

std::vector<std::pair<Category, int>> AddedRooms(const PlanSummary& s) {
  std::vector<std::pair<Category, int>> out;
  if (!s.layout || s.brief.rooms.empty()) return out;
  std::map<Category, int> has, most;  // rooms of each kind; the most the brief allows (-1: no most)
  for (const Room& r : s.layout->rooms)
    if (r.category != Category::kUtilityRoom) ++has[r.category];
  for (const BriefRooms& b : s.brief.rooms) {
    int& m = most[b.category];
    if (m >= 0) m = b.max < 0 ? -1 : m + b.max;
  }
  for (const auto& [category, n] : has) {
    const auto it = most.find(category);
    const int allowed = it == most.end() ? 0 : it->second;
    if (allowed >= 0 && n > allowed) out.push_back({category, n - allowed});
  }
  return out;
}

std::string PlanSummary::BriefReport() const {
  std::ostringstream out;
  out << PlanOutcomeName(outcome) << " (" << PlanBackendName(backend) << "): ";
  if (layout) {
    out << layout->LevelCount() << (layout->LevelCount() == 1 ? " floor" : " floors");
    for (int l = 0; l < layout->LevelCount(); ++l) out << (l == 0 ? ", rooms a floor " : "/") << layout->RoomsOnLevel(l).size();
    if (shape_class) out << ", " << *shape_class << " footprint";
  } else {
    out << "no layout";
  }
  out << "; brief " << check.met() << "/" << check.total() << " met";
  out << "; " << attempts << (backend == PlanBackend::kLlm ? (attempts == 1 ? " answer" : " answers") : " attempts");
  out << "; " << (seconds < 1.0 ? Number(std::round(seconds * 10000) / 10) + " ms" : Number(std::round(seconds * 100) / 100) + " s")
      << "\n";
  out << "brief: " << BriefOneLine(brief) << "\n";
  for (const auto& f : brief.furniture)
    out << "furnishing wish (for the furnish stage, not a layout requirement): \"" << f.source.text << "\"\n";
  for (const auto& u : brief.unparsed) out << "not understood: \"" << u.text << "\"\n";
  for (const auto& c : brief.conflicts) out << "conflict: " << c << "\n";
  for (const auto& u : unmet) out << "unmet: " << u.requirement << (u.detail.empty() ? "" : " (" + u.detail + ")") << "\n";
  for (const auto& r : recount) out << "count check: " << r.Message() << "\n";
  if (!added.empty()) {
    out << "added beyond the brief (the floors' area is filled with rooms):";
    for (size_t k = 0; k < added.size(); ++k) out << (k ? ", " : " ") << added[k].second << " " << CategoryName(added[k].first);
    out << "\n";
  }
  const std::size_t shown = std::min<std::size_t>(violations.size(), 10);
  for (std::size_t i = 0; i < shown; ++i)
    out << "violation: rule " << violations[i].rule << ": " << violations[i].message << "\n";
  if (shown < violations.size()) out << "... " << violations.size() - shown << " more violations\n";
  if (!error.empty()) out << "error: " << error << "\n";
  return out.str();
}

nlohmann::ordered_json PlanReportJson(const PlanSummary& s) {
  Json j;
  j["tool"] = std::string("villa ") + kVersion;
  j["text"] = s.brief.text;
  j["backend"] = std::string(PlanBackendName(s.backend));
  j["outcome"] = std::string(PlanOutcomeName(s.outcome));
  j["valid"] = s.valid();
  j["seconds"] = std::round(s.seconds * 1000.0) / 1000.0;
  j["attempts"] = s.attempts;
  j["shape_class"] = s.shape_class ? Json(*s.shape_class) : Json(nullptr);
  if (s.layout) {
    Json floors = Json::array();
    for (int l = 0; l < s.layout->LevelCount(); ++l) floors.push_back(s.layout->RoomsOnLevel(l).size());
    j["rooms_per_floor"] = floors;
  }
  j["brief"] = BriefToJson(s.brief);
  j["check"] = BriefCheckToJson(s.check);
  Json unmet = Json::array();
  for (const auto& u : s.unmet) {
    Json e{{"requirement", u.requirement}};
    if (!u.detail.empty()) e["detail"] = u.detail;
    if (!u.source.empty()) e["source"] = u.source;
    unmet.push_back(e);
  }
  j["unmet"] = unmet;
  // The independent count of the text's rooms against the layout (recount.h): what may have been misread.
  Json recount = Json::array();
  for (const auto& r : s.recount)
    recount.push_back(Json{{"category", std::string(CategoryName(r.category))}, {"asked", r.asked}, {"has", r.has},
                           {"phrase", r.phrase}, {"message", r.Message()}});
  j["count_check"] = recount;
  Json added = Json::array();
  for (const auto& [category, n] : s.added) added.push_back(Json{{"category", std::string(CategoryName(category))}, {"count", n}});
  j["added"] = added;
  Json violations = Json::array();
  for (const auto& v : s.violations)
    violations.push_back(Json{{"rule", v.rule}, {"elements", v.elements}, {"message", v.message}, {"figure", v.figure}});
  j["violations"] = violations;
  MetricsSummary m;
  m.Add(s.metrics);
  j["metrics"] = Json{{"fsr", Ratio(m.fsr())},
                      {"rr", Ratio(m.rr())},
                      {"rr_entrance", Ratio(m.rr_entrance())},
                      {"vcr", Ratio(m.vcr())},
                      {"brief_adherence", std::round(s.check.adherence() * 10000.0) / 10000.0}};
  Json rounds = Json::array();
  for (const auto& r : s.rounds) {
    Json e{{"round", r.round}, {"parsed", r.parsed}, {"valid", r.valid}, {"violations", r.violations},
           {"requirements_met", r.requirements_met}, {"seconds", std::round(r.seconds * 1000.0) / 1000.0}};
    if (s.backend == PlanBackend::kLlm) {
      e["http_attempts"] = r.http_attempts;
      e["finish_reason"] = r.finish_reason;
    }
    if (!r.error.empty()) e["error"] = r.error;
    rounds.push_back(e);
  }
  j["rounds"] = rounds;
  if (!s.error.empty()) j["error"] = s.error;
  if (s.backend == PlanBackend::kLlm && !s.valid() && !s.raw_answer.empty()) j["last_answer"] = s.raw_answer;
  return j;
}

}  // namespace villa
