#include "annotator/session.h"

#include <algorithm>
#include <ctime>

#include "annotator/describe.h"
#include "annotator/relabel.h"
#include "layout/layout_io.h"
#include "layout/validate.h"
#include "util/hash.h"

namespace villa::annotator {
namespace {

std::string UtcNow() {
  std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buffer;
}

std::optional<AnnotationStatus> ParseStatus(const std::string& name) {
  for (auto s : {AnnotationStatus::kPending, AnnotationStatus::kVerified, AnnotationStatus::kRejected,
                 AnnotationStatus::kAuto})
    if (StatusName(s) == name) return s;
  return std::nullopt;
}

}  // namespace

std::string_view StatusName(AnnotationStatus status) {
  switch (status) {
    case AnnotationStatus::kPending: return "pending";
    case AnnotationStatus::kVerified: return "verified";
    case AnnotationStatus::kRejected: return "rejected";
    case AnnotationStatus::kAuto: return "auto";
  }
  return "pending";
}

const std::vector<std::string>& PresetRejectReasons() {
  static const std::vector<std::string> reasons = {
      "rooms too small or too narrow to use",
      "footprint or room shapes unreasonable",
      "staircase badly placed",
      "circulation unreasonable (rooms reached through the wrong rooms)",
      "too few windows or poor daylight",
      "duplicate of another layout",
  };
  return reasons;
}

std::uint64_t DraftSeed(const DatasetRecord& record, int draft) {
  return (record.seed * kSplitMix64Gamma) ^ Fnv1a64(record.id) ^ (static_cast<std::uint64_t>(draft) * 0xd1b54a32d192ed03ULL);
}

JournalJson StateToJson(const AnnotationState& state) {
  JournalJson json;
  json["status"] = std::string(StatusName(state.status));
  if (!state.reason.empty()) json["reason"] = state.reason;
  json["descriptions"] = {{"coarse", state.coarse}, {"fine", state.fine}};
  json["edited"] = state.edited;
  json["draft"] = state.draft;
  json["layout"] = LayoutToJson(state.layout);
  return json;
}

Result<AnnotationState> StateFromJson(const JournalJson& json, const std::string& source) {
  AnnotationState state;
  if (!json.is_object()) return Error{source + ": state: not an object"};
  auto status = json.find("status");
  if (status == json.end() || !status->is_string() || !ParseStatus(status->get<std::string>()))
    return Error{source + ": state.status: " + (status == json.end() ? "missing" : status->dump()) +
                 " is not pending, verified, rejected or auto"};
  state.status = *ParseStatus(status->get<std::string>());
  if (auto reason = json.find("reason"); reason != json.end()) {
    if (!reason->is_string()) return Error{source + ": state.reason: " + reason->dump() + " is not a string"};
    state.reason = reason->get<std::string>();
  }
  auto descriptions = json.find("descriptions");
  if (descriptions == json.end() || !descriptions->is_object()) return Error{source + ": state.descriptions: missing"};
  for (const char* key : {"coarse", "fine"}) {
    auto it = descriptions->find(key);
    if (it == descriptions->end() || !it->is_string())
      return Error{source + ": state.descriptions." + key + ": missing or not a string"};
  }
  state.coarse = descriptions->at("coarse").get<std::string>();
  state.fine = descriptions->at("fine").get<std::string>();
  if (auto edited = json.find("edited"); edited != json.end() && edited->is_boolean()) state.edited = edited->get<bool>();
  if (auto draft = json.find("draft"); draft != json.end() && draft->is_number_integer()) state.draft = draft->get<int>();
  auto layout_json = json.find("layout");
  if (layout_json == json.end()) return Error{source + ": state.layout: missing"};
  auto layout = LayoutFromJson(*layout_json, source + ": state.layout");
  if (!layout) return Error{layout.error()};
  state.layout = std::move(layout).value();
  return state;
}

void Session::Redescribe(int item, AnnotationState& state) const {
  const DatasetRecord& rec = record(item);
  Drafts drafts = DraftDescriptions(state.layout, rec.shape, DraftSeed(rec, state.draft));
  state.coarse = drafts.coarse;
  state.fine = drafts.fine;
}

AnnotationState Session::InitialState(int item, int draft) const {
  AnnotationState state;
  state.layout = record(item).layout;
  DraftLabels(state.layout);
  state.draft = draft;
  Redescribe(item, state);
  return state;
}

Result<std::unique_ptr<Session>> Session::Open(const std::filesystem::path& dir, bool writable) {
  auto dataset = LoadDataset(dir);
  if (!dataset) return Error{dataset.error()};
  std::unique_ptr<Session> session(new Session());
  session->dataset_ = std::move(dataset).value();
  session->writable_ = writable;
  session->states_.resize(session->dataset_.records.size());
  std::vector<bool> touched(session->states_.size(), false);

  std::filesystem::path path = JournalPath(dir);
  if (writable) {
    // Lock before reading, so a torn-tail repair never races another session's append.
    Status status = session->journal_.Open(path);
    if (!status) return Error{status.error()};
  }
  auto journal = ReadJournal(path, writable);
  if (!journal) return Error{journal.error()};
  session->warnings_ = journal->warnings;
  for (const JournalLine& line : journal->lines) {
    std::string where = path.string() + ":" + std::to_string(line.line);
    const JournalJson& json = line.json;
    auto id = json.find("id");
    if (id == json.end() || !id->is_string()) return Error{where + ": corrupt journal line: \"id\" missing"};
    int item = session->dataset_.Find(id->get<std::string>());
    if (item < 0) return Error{where + ": \"id\": \"" + id->get<std::string>() + "\" is not in layouts.jsonl"};
    auto state_json = json.find("state");
    if (state_json == json.end()) return Error{where + ": corrupt journal line: \"state\" missing"};
    auto state = StateFromJson(*state_json, where);
    if (!state) return Error{state.error()};
    std::string kind = json.value("kind", "do");
    std::string action = json.value("action", "");
    auto& undo = session->undo_;
    auto& redo = session->redo_;
    if (kind == "undo") {
      if (!undo.empty() && undo.back().item == item) {
        redo.push_back(std::move(undo.back()));
        undo.pop_back();
      }
    } else if (kind == "redo") {
      if (!redo.empty() && redo.back().item == item) {
        undo.push_back(std::move(redo.back()));
        redo.pop_back();
      }
    } else if (kind == "batch") {
      // --auto runs are not undoable one by one.
    } else {
      AnnotationState before = touched[item] ? session->states_[item] : session->InitialState(item);
      undo.push_back({item, std::move(before), *state, action});
      redo.clear();
    }
    session->states_[item] = std::move(state).value();
    touched[item] = true;
    session->seq_ = std::max(session->seq_, json.value("seq", 0L));
  }
  for (std::size_t i = 0; i < touched.size(); ++i)
    if (!touched[i]) session->states_[i] = session->InitialState(static_cast<int>(i));
  return session;
}

Counts Session::counts() const {
  Counts c;
  for (const AnnotationState& s : states_) {
    switch (s.status) {
      case AnnotationStatus::kPending: ++c.pending; break;
      case AnnotationStatus::kVerified: ++c.verified; break;
      case AnnotationStatus::kRejected: ++c.rejected; break;
      case AnnotationStatus::kAuto: ++c.automatic; break;
    }
  }
  return c;
}

int Session::NextPending(int from) const {
  int n = size();
  for (int k = 0; k < n; ++k) {
    int i = ((from % n) + n + k) % n;
    if (states_[i].status == AnnotationStatus::kPending) return i;
  }
  return -1;
}

JournalJson Session::Line(int item, const AnnotationState& state, const std::string& kind, const std::string& action) {
  JournalJson line;
  line["seq"] = ++seq_;
  line["time"] = UtcNow();
  line["id"] = record(item).id;
  line["kind"] = kind;
  line["action"] = action;
  line["state"] = StateToJson(state);
  return line;
}

Status Session::Commit(int item, AnnotationState next, const std::string& action, std::string* message) {
  if (!writable_) return Error{"session opened read-only"};
  Status status = journal_.Append(Line(item, next, "do", action));
  if (!status) {
    --seq_;
    return status;
  }
  undo_.push_back({item, states_[item], next, action});
  redo_.clear();
  states_[item] = std::move(next);
  if (message) *message = action;
  return {};
}

Status Session::Relabel(int item, int room, Category category, std::string* message) {
  AnnotationState next = states_[item];
  if (room < 0 || room >= static_cast<int>(next.layout.rooms.size())) return Error{"no room " + std::to_string(room)};
  std::string old_name = next.layout.rooms[room].name();
  auto renames = RelabelRoom(next.layout, room, category);
  if (renames.empty()) {
    if (message) *message = old_name + " is already a " + std::string(CategoryName(category));
    return {};
  }
  if (!next.edited) Redescribe(item, next);
  std::string action = "label " + old_name + " -> " + next.layout.rooms[room].name();
  if (next.status == AnnotationStatus::kVerified || next.status == AnnotationStatus::kAuto) {
    next.status = AnnotationStatus::kPending;
    action += " (reopened)";
  }
  return Commit(item, std::move(next), action, message);
}

Status Session::Accept(int item, std::string* message) {
  const AnnotationState& current = states_[item];
  ValidationReport report = ValidateLayout(current.layout);
  if (!report.valid()) {
    std::string why = std::to_string(report.violations.size()) + " rule violation" +
                      (report.violations.size() == 1 ? "" : "s") + ": rule " +
                      std::to_string(report.violations[0].rule) + ": " + report.violations[0].message;
    return Error{"cannot accept: " + why};
  }
  if (current.coarse.empty() || current.fine.empty()) return Error{"cannot accept: a description is empty"};
  AnnotationState next = current;
  next.status = AnnotationStatus::kVerified;
  next.reason.clear();
  return Commit(item, std::move(next), "accept " + record(item).id, message);
}

Status Session::Reject(int item, const std::string& reason, std::string* message) {
  if (reason.empty()) return Error{"a rejection needs a reason"};
  AnnotationState next = states_[item];
  next.status = AnnotationStatus::kRejected;
  next.reason = reason;
  return Commit(item, std::move(next), "reject " + record(item).id + ": " + reason, message);
}

Status Session::Reopen(int item, std::string* message) {
  AnnotationState next = states_[item];
  if (next.status == AnnotationStatus::kPending) {
    if (message) *message = record(item).id + " is already pending";
    return {};
  }
  next.status = AnnotationStatus::kPending;
  next.reason.clear();
  return Commit(item, std::move(next), "reopen " + record(item).id, message);
}

Status Session::SetDescriptions(int item, const std::string& coarse, const std::string& fine, std::string* message) {
  AnnotationState next = states_[item];
  if (next.coarse == coarse && next.fine == fine) {
    if (message) *message = "descriptions unchanged";
    return {};
  }
  next.coarse = coarse;
  next.fine = fine;
  next.edited = true;
  return Commit(item, std::move(next), "edit descriptions of " + record(item).id, message);
}

Status Session::Redraft(int item, std::string* message) {
  AnnotationState next = states_[item];
  next.draft += 1;
  next.edited = false;
  Redescribe(item, next);
  return Commit(item, std::move(next), "redraft descriptions of " + record(item).id + " (#" + std::to_string(next.draft) + ")",
                message);
}

Status Session::ApplyFixes(int item, const std::vector<Fix>& fixes, std::string* message) {
  AnnotationState next = states_[item];
  std::vector<std::string> made;
  std::string failures;
  for (const Fix& fix : fixes) {
    auto fixed = ApplyFix(next.layout, fix);
    if (!fixed) {
      failures = fixed.error();
      continue;
    }
    next.layout = std::move(fixed).value();
    made.push_back(fix.title);
  }
  if (made.empty()) return Error{failures.empty() ? "no fix to apply" : failures};
  if (!next.edited) Redescribe(item, next);
  std::string action = made.size() == 1 ? made[0] : std::to_string(made.size()) + " fixes: " + made[0] + ", ...";
  return Commit(item, std::move(next), action, message);
}

Status Session::Undo(int* item, std::string* message) {
  if (undo_.empty()) return Error{"nothing to undo"};
  if (!writable_) return Error{"session opened read-only"};
  UndoEntry entry = undo_.back();
  Status status = journal_.Append(Line(entry.item, entry.before, "undo", "undo: " + entry.action));
  if (!status) return status;
  states_[entry.item] = entry.before;
  undo_.pop_back();
  if (item) *item = entry.item;
  if (message) *message = "undone: " + entry.action;
  redo_.push_back(std::move(entry));
  return {};
}

Status Session::Redo(int* item, std::string* message) {
  if (redo_.empty()) return Error{"nothing to redo"};
  if (!writable_) return Error{"session opened read-only"};
  UndoEntry entry = redo_.back();
  Status status = journal_.Append(Line(entry.item, entry.after, "redo", "redo: " + entry.action));
  if (!status) return status;
  states_[entry.item] = entry.after;
  redo_.pop_back();
  if (item) *item = entry.item;
  if (message) *message = "redone: " + entry.action;
  undo_.push_back(std::move(entry));
  return {};
}

Result<Counts> Session::AutoAnnotate() {
  if (!writable_) return Error{"session opened read-only"};
  std::vector<JournalJson> lines;
  std::vector<std::pair<int, AnnotationState>> changes;
  Counts made;
  for (int item = 0; item < size(); ++item) {
    if (states_[item].status != AnnotationStatus::kPending) continue;
    AnnotationState next = states_[item];
    if (!ApplyAllFixes(next.layout).empty() && !next.edited) Redescribe(item, next);
    ValidationReport report = ValidateLayout(next.layout);
    if (report.valid()) {
      next.status = AnnotationStatus::kAuto;
      ++made.automatic;
    } else {
      const Violation& v = report.violations[0];
      next.status = AnnotationStatus::kRejected;
      next.reason = "auto: rule " + std::to_string(v.rule) + ": " + v.message;
      ++made.rejected;
    }
    lines.push_back(Line(item, next, "batch", "auto"));
    changes.push_back({item, std::move(next)});
  }
  if (!lines.empty()) {
    Status status = journal_.Append(lines);
    if (!status) return Error{status.error()};
  }
  for (auto& [item, state] : changes) states_[item] = std::move(state);
  return made;
}

std::string Session::ExportJsonl() const {
  std::string out;
  for (int item = 0; item < size(); ++item) {
    const AnnotationState& s = states_[item];
    Json record;
    record["id"] = dataset_.records[item].id;
    record["status"] = std::string(StatusName(s.status));
    if (s.status == AnnotationStatus::kRejected) record["reason"] = s.reason;
    record["descriptions"] = {{"coarse", s.coarse}, {"fine", s.fine}};
    record["layout"] = LayoutToJson(s.layout);
    out += record.dump(-1, ' ', false, Json::error_handler_t::replace);
    out += '\n';
  }
  return out;
}

}  // namespace villa::annotator
