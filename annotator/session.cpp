#include "annotator/session.h"

#include <pwd.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

#include "annotator/describe.h"
#include "annotator/mentions.h"
#include "annotator/relabel.h"
#include "layout/layout_io.h"
#include "layout/validate.h"
#include "util/hash.h"

namespace villa::annotator {
namespace {

std::optional<AnnotationStatus> ParseStatus(const std::string& name) {
  for (auto s : {AnnotationStatus::kPending, AnnotationStatus::kVerified, AnnotationStatus::kRejected,
                 AnnotationStatus::kAuto})
    if (StatusName(s) == name) return s;
  return std::nullopt;
}

std::optional<TextOrigin> ParseOrigin(const std::string& name) {
  for (auto o : {TextOrigin::kDrafted, TextOrigin::kEdited, TextOrigin::kWritten})
    if (OriginName(o) == name) return o;
  return std::nullopt;
}

// A bad value in a message, cut to about 80 characters.
std::string Shown(const JournalJson& value) {
  std::string text = value.dump(-1, ' ', false, JournalJson::error_handler_t::replace);
  return text.size() > 80 ? text.substr(0, 77) + "..." : text;
}

// Kinds of journal line a person's key made (as opposed to --auto, a split's seed or a merge).
bool PersonKind(const std::string& kind) { return kind == "do" || kind == "undo" || kind == "redo"; }

// Lower-case words (letters and digits) of a text.
std::vector<std::string> Words(const std::string& text) {
  std::vector<std::string> words;
  std::string word;
  for (char c : text) {
    unsigned char u = static_cast<unsigned char>(c);
    if (std::isalnum(u) || u >= 0x80) {
      word += static_cast<char>(std::tolower(u));
    } else if (!word.empty()) {
      words.push_back(word);
      word.clear();
    }
  }
  if (!word.empty()) words.push_back(word);
  return words;
}

std::string JoinAnd(const std::vector<std::string>& items) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i)
    out += (i == 0 ? "" : i + 1 == items.size() ? " and " : ", ") + items[i];
  return out;
}

std::string WithArticle(std::string_view noun) {
  std::string n(noun);
  return (n[0] == 'a' || n[0] == 'e' || n[0] == 'i' || n[0] == 'o' || n[0] == 'u' ? "an " : "a ") + n;
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

std::string_view OriginName(TextOrigin origin) {
  switch (origin) {
    case TextOrigin::kDrafted: return "drafted";
    case TextOrigin::kEdited: return "edited";
    case TextOrigin::kWritten: return "written";
  }
  return "drafted";
}

std::string_view FilterName(Filter filter) {
  switch (filter) {
    case Filter::kAll: return "all";
    case Filter::kToDo: return "to-do";
    case Filter::kPending: return "pending";
    case Filter::kAuto: return "auto";
    case Filter::kRejected: return "rejected";
    case Filter::kVerified: return "verified";
    case Filter::kDecided: return "decided";
    case Filter::kDisagreements: return "disagreements";
  }
  return "all";
}

std::optional<Filter> ParseFilter(std::string_view name) {
  for (Filter f : kAllFilters)
    if (FilterName(f) == name) return f;
  if (name == "todo") return Filter::kToDo;
  return std::nullopt;
}

std::string LoginName() {
  for (const char* var : {"USER", "LOGNAME"})
    if (const char* v = std::getenv(var); v && *v) return v;
  if (const passwd* pw = ::getpwuid(::geteuid()); pw && pw->pw_name && *pw->pw_name) return pw->pw_name;
  return "unknown";
}

Status CheckAnnotatorName(const std::string& name) {
  if (name.empty()) return Error{"--annotator: the name is empty"};
  if (name.size() > 64) return Error{"--annotator: \"" + name.substr(0, 61) + "...\" is longer than 64 characters"};
  for (unsigned char c : name)
    if (c < 0x20 || c == 0x7f) return Error{"--annotator: the name holds a control character"};
  if (name == kAutoAnnotator) return Error{"--annotator: \"auto\" is reserved for --auto"};
  return {};
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
  // Format 1's single flag, for readers that know only it: a person wrote either description.
  json["edited"] = state.edited(DescriptionField::kCoarse) || state.edited(DescriptionField::kFine);
  json["origin"] = {{"coarse", std::string(OriginName(state.coarse_origin))},
                    {"fine", std::string(OriginName(state.fine_origin))}};
  json["draft"] = state.draft;
  if (!state.decided_by.empty()) json["decided_by"] = state.decided_by;
  json["layout"] = LayoutToJson(state.layout);
  return json;
}

Result<AnnotationState> StateFromJson(const JournalJson& json, const std::string& source) {
  AnnotationState state;
  if (!json.is_object()) return Error{source + ": state: not an object"};
  auto status = json.find("status");
  if (status == json.end() || !status->is_string() || !ParseStatus(status->get<std::string>()))
    return Error{source + ": state.status: " + (status == json.end() ? "missing" : Shown(*status)) +
                 " is not pending, verified, rejected or auto"};
  state.status = *ParseStatus(status->get<std::string>());
  if (auto reason = json.find("reason"); reason != json.end()) {
    if (!reason->is_string()) return Error{source + ": state.reason: " + Shown(*reason) + " is not a string"};
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
  // Format 1: one flag for both descriptions.
  if (auto edited = json.find("edited"); edited != json.end() && edited->is_boolean() && edited->get<bool>())
    state.coarse_origin = state.fine_origin = TextOrigin::kEdited;
  if (auto origin = json.find("origin"); origin != json.end()) {
    if (!origin->is_object()) return Error{source + ": state.origin: " + Shown(*origin) + " is not an object"};
    for (DescriptionField f : {DescriptionField::kCoarse, DescriptionField::kFine}) {
      auto it = origin->find(std::string(FieldName(f)));
      if (it == origin->end()) continue;
      if (!it->is_string() || !ParseOrigin(it->get<std::string>()))
        return Error{source + ": state.origin." + std::string(FieldName(f)) + ": " + Shown(*it) +
                     " is not drafted, edited or written"};
      state.origin(f) = *ParseOrigin(it->get<std::string>());
    }
  }
  if (auto draft = json.find("draft"); draft != json.end() && draft->is_number_integer()) state.draft = draft->get<int>();
  if (auto by = json.find("decided_by"); by != json.end()) {
    if (!by->is_string()) return Error{source + ": state.decided_by: " + Shown(*by) + " is not a string"};
    state.decided_by = by->get<std::string>();
  }
  auto layout_json = json.find("layout");
  if (layout_json == json.end()) return Error{source + ": state.layout: missing"};
  auto layout = LayoutFromJson(*layout_json, source + ": state.layout");
  if (!layout) return Error{layout.error()};
  state.layout = std::move(layout).value();
  return state;
}

void Session::Redescribe(int item, AnnotationState& state) const {
  if (state.edited(DescriptionField::kCoarse) && state.edited(DescriptionField::kFine)) return;
  const DatasetRecord& rec = record(item);
  Drafts drafts = DraftDescriptions(state.layout, rec.shape, DraftSeed(rec, state.draft));
  if (!state.edited(DescriptionField::kCoarse)) state.coarse = drafts.coarse;
  if (!state.edited(DescriptionField::kFine)) state.fine = drafts.fine;
}

AnnotationState Session::InitialState(int item, int draft) const {
  AnnotationState state;
  state.layout = record(item).layout;
  DraftLabels(state.layout);
  state.draft = draft;
  Redescribe(item, state);
  return state;
}

Result<std::unique_ptr<Session>> Session::Open(const std::filesystem::path& dir, const SessionOptions& options) {
  auto dataset = LoadDataset(dir);
  if (!dataset) return Error{dataset.error()};
  std::unique_ptr<Session> session(new Session());
  Session& s = *session;
  s.dataset_ = std::move(dataset).value();
  s.writable_ = options.writable;
  s.annotator_ = options.annotator.empty() ? LoginName() : options.annotator;
  std::size_t n = s.dataset_.records.size();
  s.states_.resize(n);
  s.touched_.assign(n, false);
  s.history_.resize(n);
  s.effort_.resize(n);
  s.opinions_.resize(n);
  s.unjournalled_seconds_.assign(n, 0.0);

  std::filesystem::path path = JournalPath(dir);
  if (options.writable) {
    // Lock before reading, so a torn-tail repair never races another session's append.
    Status status = s.journal_.Open(path);
    if (!status) return Error{status.error()};
  }
  auto journal = ReadJournal(path, options.writable);
  if (!journal) return Error{journal.error()};
  s.warnings_ = journal->warnings;
  for (const JournalLine& line : journal->lines) {
    Status applied = s.Apply(line.json, path.string() + ":" + std::to_string(line.line));
    if (!applied) return Error{applied.error()};
  }
  for (std::size_t i = 0; i < n; ++i)
    if (!s.touched_[i]) s.states_[i] = s.InitialState(static_cast<int>(i));

  if (Status drafts = s.drafts_.Open(DraftsPath(dir), options.writable); !drafts) return Error{drafts.error()};
  for (const std::string& w : s.drafts_.warnings()) s.warnings_.push_back(w);
  return session;
}

Status Session::Apply(const JournalJson& json, const std::string& where) {
  if (auto v = json.find("v"); v != json.end() && v->is_number_integer() && v->get<int>() > kJournalVersion &&
                                !warned_newer_) {
    warnings_.push_back(where + ": written by a newer villa (journal format " + std::to_string(v->get<int>()) +
                        "); read as far as format " + std::to_string(kJournalVersion) + " goes");
    warned_newer_ = true;
  }
  auto id = json.find("id");
  if (id == json.end() || !id->is_string()) return Error{where + ": corrupt journal line: \"id\" missing"};
  int item = dataset_.Find(id->get<std::string>());
  if (item < 0) return Error{where + ": \"id\": " + Shown(*id) + " is not in layouts.jsonl"};
  auto state_json = json.find("state");
  if (state_json == json.end()) return Error{where + ": corrupt journal line: \"state\" missing"};
  auto parsed = StateFromJson(*state_json, where);
  if (!parsed) return Error{parsed.error()};
  AnnotationState state = std::move(parsed).value();
  std::string kind = json.value("kind", "do");
  std::string action = json.value("action", "");
  if (auto merged = json.find("merged"); merged != json.end() && merged->is_object())
    merged_.insert({merged->value("package", ""), merged->value("seq", 0L)});
  if (kind == "undo") {
    if (!undo_.empty() && undo_.back().item == item) {
      redo_.push_back(std::move(undo_.back()));
      undo_.pop_back();
    }
  } else if (kind == "redo") {
    if (!redo_.empty() && redo_.back().item == item) {
      undo_.push_back(std::move(redo_.back()));
      redo_.pop_back();
    }
  } else if (kind == "do") {
    AnnotationState before = touched_[item] ? states_[item] : InitialState(item);
    undo_.push_back({item, std::move(before), state, action});
    redo_.clear();
  }
  // "batch" (--auto, a split's seed, merged lines) and kinds of newer formats: the state, not undoable.
  Note(item, json, state);
  states_[item] = std::move(state);
  touched_[item] = true;
  seq_ = std::max(seq_, json.value("seq", 0L));
  return {};
}

void Session::Note(int item, const JournalJson& line, const AnnotationState& state) {
  HistoryEntry h;
  h.time = line.value("time", "");
  h.annotator = line.value("annotator", "");
  h.kind = line.value("kind", "do");
  h.action = line.value("action", "");
  if (auto s = line.find("seconds"); s != line.end() && s->is_number()) h.seconds = std::max(0, s->get<int>());
  if (auto merged = line.find("merged"); merged != line.end() && merged->is_object()) {
    h.package = merged->value("package", "");
    h.kind = merged->value("kind", h.kind);
  }
  Effort& e = effort_[item];
  e.seconds += h.seconds;
  if (PersonKind(h.kind) && !h.annotator.empty()) {
    if (std::find(e.annotators.begin(), e.annotators.end(), h.annotator) == e.annotators.end())
      e.annotators.push_back(h.annotator);
    // A person's opinion is their last word on the layout: a decision, or none after a reopen.
    if (state.status == AnnotationStatus::kVerified || state.status == AnnotationStatus::kRejected)
      opinions_[item][h.annotator] = state;
    else
      opinions_[item].erase(h.annotator);
  }
  history_[item].push_back(std::move(h));
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

int Session::NextPending(int from) const { return Step(from - 1, +1, Filter::kPending, false); }

bool Session::IsToDo(int item) const {
  AnnotationStatus s = states_[item].status;
  return s == AnnotationStatus::kPending || s == AnnotationStatus::kAuto;
}

bool Session::Matches(int item, Filter filter) const {
  const AnnotationState& s = states_[item];
  switch (filter) {
    case Filter::kAll: return true;
    case Filter::kToDo: return IsToDo(item);
    case Filter::kPending: return s.status == AnnotationStatus::kPending;
    case Filter::kAuto: return s.status == AnnotationStatus::kAuto;
    case Filter::kRejected: return s.status == AnnotationStatus::kRejected;
    case Filter::kVerified: return s.status == AnnotationStatus::kVerified;
    case Filter::kDecided:
      return (s.status == AnnotationStatus::kVerified || s.status == AnnotationStatus::kRejected) &&
             !s.decided_by.empty() && s.decided_by != kAutoAnnotator;
    case Filter::kDisagreements: return Disagreement(item);
  }
  return true;
}

int Session::CountMatching(Filter filter) const {
  int n = 0;
  for (int i = 0; i < size(); ++i) n += Matches(i, filter);
  return n;
}

int Session::Step(int from, int direction, Filter filter, bool to_do) const {
  int n = size();
  if (n == 0) return -1;
  for (int k = 1; k <= n; ++k) {
    int i = (((from + direction * k) % n) + n) % n;
    if (Matches(i, filter) && (!to_do || IsToDo(i))) return i;
  }
  return -1;
}

Result<int> Session::FindItem(std::string_view query) const {
  std::string q(query);
  while (!q.empty() && q.back() == ' ') q.pop_back();
  while (!q.empty() && q.front() == ' ') q.erase(q.begin());
  if (q.empty()) return Error{"no layout given"};
  if (q[0] == '#') {
    std::string digits = q.substr(1);
    bool number = !digits.empty() && digits.size() < 10 &&
                  std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
    int position = number ? std::stoi(digits) : 0;
    if (position < 1 || position > size())
      return Error{"\"" + q.substr(0, 40) + "\": positions run from #1 to #" + std::to_string(size())};
    return position - 1;
  }
  if (int exact = dataset_.Find(q); exact >= 0) return exact;
  std::vector<int> matches;
  for (int i = 0; i < size(); ++i) {
    const std::string& id = record(i).id;
    if (id.size() >= q.size() && id.compare(id.size() - q.size(), q.size(), q) == 0) matches.push_back(i);
  }
  if (matches.size() == 1) return matches[0];
  if (matches.empty()) return Error{"no layout \"" + q.substr(0, 40) + "\" (an id, its last digits, or #position)"};
  std::string some;
  for (std::size_t k = 0; k < matches.size() && k < 3; ++k) some += (k ? ", " : "") + record(matches[k]).id;
  return Error{std::to_string(matches.size()) + " ids end in \"" + q.substr(0, 40) + "\": " + some +
               (matches.size() > 3 ? ", ..." : "")};
}

std::vector<Rating> Session::Ratings(int item) const {
  std::vector<Rating> out;
  for (const auto& [who, s] : opinions_[item]) out.push_back({who, s.status == AnnotationStatus::kVerified, s.layout});
  return out;
}

bool Session::Disagreement(int item) const {
  auto ratings = Ratings(item);
  if (ratings.size() < 2) return false;
  Agreement a = ComputeAgreement({ratings});
  return a.all.decisions_agreed < a.all.layouts || a.all.rooms_agreed < a.all.rooms;
}

Agreement Session::AgreementFigures() const {
  std::vector<std::vector<Rating>> all;
  for (int i = 0; i < size(); ++i)
    if (opinions_[i].size() >= 2) all.push_back(Ratings(i));
  return ComputeAgreement(all);
}

void Session::Spend(int item, double seconds) {
  if (item >= 0 && item < size() && seconds > 0) unjournalled_seconds_[item] += seconds;
}

std::vector<std::string> Session::AcceptWarnings(int item) const {
  std::vector<std::string> out;
  const AnnotationState& s = states_[item];
  for (DescriptionField f : {DescriptionField::kCoarse, DescriptionField::kFine}) {
    if (!s.edited(f)) continue;
    std::vector<std::string> missing;
    for (Category c : CategoriesNamedButMissing(s.text(f), s.layout)) missing.push_back(WithArticle(CategoryWords(c)));
    if (missing.empty()) continue;
    out.push_back("the " + std::string(FieldName(f)) + " description names " + JoinAnd(missing) +
                  ", which the layout no longer has");
  }
  return out;
}

std::string Session::OverturnWarning(int item) const {
  const AnnotationState& s = states_[item];
  if (s.decided_by.empty() || s.decided_by == kAutoAnnotator || s.decided_by == annotator_) return "";
  if (s.status == AnnotationStatus::kRejected)
    return record(item).id + " was rejected by " + s.decided_by + (s.reason.empty() ? "" : ": " + s.reason);
  if (s.status == AnnotationStatus::kVerified) return record(item).id + " was verified by " + s.decided_by;
  return "";
}

JournalJson Session::Line(int item, const AnnotationState& state, const std::string& kind, const std::string& action) {
  JournalJson line;
  line["v"] = kJournalVersion;
  line["seq"] = ++seq_;
  line["time"] = UtcNow();
  line["id"] = record(item).id;
  line["kind"] = kind;
  line["action"] = action;
  line["annotator"] = kind == "batch" && action == "auto" ? std::string(kAutoAnnotator) : annotator_;
  line["seconds"] = static_cast<int>(std::lround(unjournalled_seconds_[item]));
  line["state"] = StateToJson(state);
  return line;
}

Status Session::Commit(int item, AnnotationState next, const std::string& action, std::string* message) {
  if (!writable_) return Error{"session opened read-only"};
  JournalJson line = Line(item, next, "do", action);
  Status status = journal_.Append(line);
  if (!status) {
    --seq_;
    return status;
  }
  unjournalled_seconds_[item] = 0;
  undo_.push_back({item, states_[item], next, action});
  redo_.clear();
  Note(item, line, next);
  states_[item] = std::move(next);
  touched_[item] = true;
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
  Redescribe(item, next);
  std::string action = "label " + old_name + " -> " + next.layout.rooms[room].name();
  if (next.status == AnnotationStatus::kVerified || next.status == AnnotationStatus::kAuto) {
    next.status = AnnotationStatus::kPending;
    next.decided_by.clear();
    action += " (reopened)";
  }
  return Commit(item, std::move(next), action, message);
}

Status Session::Accept(int item, std::string* message) {
  const AnnotationState& current = states_[item];
  if (current.status == AnnotationStatus::kVerified) {
    if (message) *message = record(item).id + " is already verified" +
                            (current.decided_by.empty() ? "" : " (by " + current.decided_by + ")");
    return {};
  }
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
  next.decided_by = annotator_;
  return Commit(item, std::move(next), "accept " + record(item).id, message);
}

Status Session::Reject(int item, const std::string& reason, std::string* message) {
  if (reason.empty()) return Error{"a rejection needs a reason"};
  AnnotationState next = states_[item];
  if (next.status == AnnotationStatus::kRejected && next.reason == reason && next.decided_by == annotator_) {
    if (message) *message = record(item).id + " is already rejected: " + reason;
    return {};
  }
  next.status = AnnotationStatus::kRejected;
  next.reason = reason;
  next.decided_by = annotator_;
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
  next.decided_by.clear();
  return Commit(item, std::move(next), "reopen " + record(item).id, message);
}

TextOrigin Session::OriginOfEdit(int item, const AnnotationState& current, DescriptionField field,
                                 const std::string& text) const {
  if (current.origin(field) == TextOrigin::kWritten) return TextOrigin::kWritten;
  std::string drafted = current.text(field);
  if (current.edited(field)) {
    AnnotationState fresh = current;
    fresh.coarse_origin = fresh.fine_origin = TextOrigin::kDrafted;
    Redescribe(item, fresh);
    drafted = fresh.text(field);
  }
  // How much of the draft the new text keeps, as difflib's ratio over words: twice the longest common
  // subsequence over both lengths. At least one half: an edit of the draft; below: the person's own.
  auto a = Words(drafted);
  auto b = Words(text);
  if (a.empty() || b.empty()) return TextOrigin::kWritten;
  std::vector<int> row(b.size() + 1, 0), next(b.size() + 1, 0);
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t j = 0; j < b.size(); ++j) next[j + 1] = a[i] == b[j] ? row[j] + 1 : std::max(row[j + 1], next[j]);
    std::swap(row, next);
  }
  double ratio = 2.0 * row[b.size()] / static_cast<double>(a.size() + b.size());
  return ratio >= 0.5 ? TextOrigin::kEdited : TextOrigin::kWritten;
}

Status Session::SetDescription(int item, DescriptionField field, const std::string& text, std::string* message) {
  const AnnotationState& current = states_[item];
  if (current.text(field) == text) {
    if (message) *message = std::string(FieldName(field)) + " description unchanged";
    if (Status s = DropDraft(item, field); !s) return s;
    return {};
  }
  AnnotationState next = current;
  next.origin(field) = OriginOfEdit(item, current, field, text);
  next.text(field) = text;
  Status status = Commit(item, std::move(next), "edit the " + std::string(FieldName(field)) + " description of " + record(item).id, message);
  if (!status) return status;
  // Saved in the journal: the draft has done its job. (If closing it fails, the draft is only offered
  // again on the next start: nothing is lost.)
  drafts_.Close(record(item).id, field, "saved");
  return {};
}

Status Session::SetDescriptions(int item, const std::string& coarse, const std::string& fine, std::string* message) {
  const AnnotationState& current = states_[item];
  if (current.coarse == coarse && current.fine == fine) {
    if (message) *message = "descriptions unchanged";
    return {};
  }
  AnnotationState next = current;
  for (DescriptionField f : {DescriptionField::kCoarse, DescriptionField::kFine}) {
    const std::string& text = f == DescriptionField::kCoarse ? coarse : fine;
    if (current.text(f) == text) continue;
    next.origin(f) = OriginOfEdit(item, current, f, text);
    next.text(f) = text;
  }
  return Commit(item, std::move(next), "edit descriptions of " + record(item).id, message);
}

Status Session::Redraft(int item, std::string* message) {
  AnnotationState next = states_[item];
  next.draft += 1;
  next.coarse_origin = next.fine_origin = TextOrigin::kDrafted;
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
  Redescribe(item, next);
  std::string action = made.size() == 1 ? made[0] : std::to_string(made.size()) + " fixes: " + made[0] + ", ...";
  return Commit(item, std::move(next), action, message);
}

Status Session::Undo(int* item, std::string* message) {
  if (undo_.empty()) return Error{"nothing to undo"};
  if (!writable_) return Error{"session opened read-only"};
  UndoEntry entry = undo_.back();
  JournalJson line = Line(entry.item, entry.before, "undo", "undo: " + entry.action);
  Status status = journal_.Append(line);
  if (!status) return status;
  unjournalled_seconds_[entry.item] = 0;
  Note(entry.item, line, entry.before);
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
  JournalJson line = Line(entry.item, entry.after, "redo", "redo: " + entry.action);
  Status status = journal_.Append(line);
  if (!status) return status;
  unjournalled_seconds_[entry.item] = 0;
  Note(entry.item, line, entry.after);
  states_[entry.item] = entry.after;
  redo_.pop_back();
  if (item) *item = entry.item;
  if (message) *message = "redone: " + entry.action;
  undo_.push_back(std::move(entry));
  return {};
}

std::optional<OpenDraft> Session::Draft(int item, DescriptionField field) const {
  return drafts_.Find(record(item).id, field);
}

Status Session::KeepDraft(int item, DescriptionField field, const std::string& text) {
  return drafts_.Keep(record(item).id, field, text, annotator_);
}

Status Session::DropDraft(int item, DescriptionField field) {
  if (!writable_) return {};
  return drafts_.Close(record(item).id, field, "dropped");
}

Result<Counts> Session::AutoAnnotate() {
  if (!writable_) return Error{"session opened read-only"};
  std::vector<JournalJson> lines;
  std::vector<std::pair<int, AnnotationState>> changes;
  Counts made;
  long first_seq = seq_;
  for (int item = 0; item < size(); ++item) {
    if (states_[item].status != AnnotationStatus::kPending) continue;
    AnnotationState next = states_[item];
    if (!ApplyAllFixes(next.layout).empty()) Redescribe(item, next);
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
    next.decided_by = kAutoAnnotator;
    lines.push_back(Line(item, next, "batch", "auto"));
    changes.push_back({item, std::move(next)});
  }
  if (!lines.empty()) {
    Status status = journal_.Append(lines);
    if (!status) {
      seq_ = first_seq;
      return Error{status.error()};
    }
  }
  for (std::size_t k = 0; k < changes.size(); ++k) {
    auto& [item, state] = changes[k];
    Note(item, lines[k], state);
    states_[item] = std::move(state);
    touched_[item] = true;
  }
  return made;
}

Result<int> Session::MergeLines(const std::string& package, const std::vector<JournalLine>& lines,
                                const std::filesystem::path& source) {
  if (!writable_) return Error{"session opened read-only"};
  std::vector<JournalJson> out;
  std::set<std::pair<std::string, long>> seen = merged_;
  long first_seq = seq_;
  for (const JournalLine& line : lines) {
    const JournalJson& j = line.json;
    std::string where = source.string() + ":" + std::to_string(line.line);
    if (j.contains("split")) continue;  // the package's starting state, taken from this journal
    auto id = j.find("id");
    if (id == j.end() || !id->is_string()) return Error{where + ": corrupt journal line: \"id\" missing"};
    if (dataset_.Find(id->get<std::string>()) < 0)
      return Error{where + ": \"id\": " + Shown(*id) + " is not in " + LayoutsPath(dataset_.dir).string()};
    auto state = j.find("state");
    if (state == j.end()) return Error{where + ": corrupt journal line: \"state\" missing"};
    if (auto parsed = StateFromJson(*state, where); !parsed) return Error{parsed.error()};
    long seq = j.value("seq", 0L);
    if (!seen.insert({package, seq}).second) continue;
    JournalJson m;
    m["v"] = kJournalVersion;
    m["seq"] = ++seq_;
    m["time"] = j.value("time", UtcNow());
    m["id"] = *id;
    m["kind"] = "batch";  // not undoable here: the package's own history stays in the package
    m["action"] = j.value("action", "");
    m["annotator"] = j.value("annotator", "");
    m["seconds"] = j.contains("seconds") && j["seconds"].is_number() ? j["seconds"].get<int>() : 0;
    m["merged"] = {{"package", package}, {"kind", j.value("kind", "do")}, {"seq", seq}};
    m["state"] = *state;
    out.push_back(std::move(m));
  }
  if (out.empty()) return 0;
  if (Status s = journal_.Append(out); !s) {
    seq_ = first_seq;
    return Error{s.error()};
  }
  std::string journal = JournalPath(dataset_.dir).string();
  for (const JournalJson& m : out)
    if (Status s = Apply(m, journal + " (merged from " + source.string() + ")"); !s) return Error{s.error()};
  return static_cast<int>(out.size());
}

std::string Session::ExportJsonl() const {
  std::string out;
  for (int item = 0; item < size(); ++item) {
    const AnnotationState& s = states_[item];
    const Effort& e = effort_[item];
    Json record;
    record["id"] = dataset_.records[item].id;
    record["status"] = std::string(StatusName(s.status));
    if (s.status == AnnotationStatus::kRejected) record["reason"] = s.reason;
    record["descriptions"] = {{"coarse", s.coarse}, {"fine", s.fine}};
    Json annotation;
    if (!s.decided_by.empty()) annotation["decided_by"] = s.decided_by;
    annotation["annotators"] = e.annotators;
    annotation["seconds"] = e.seconds;
    annotation["origin"] = {{"coarse", std::string(OriginName(s.coarse_origin))},
                            {"fine", std::string(OriginName(s.fine_origin))}};
    record["annotation"] = std::move(annotation);
    record["layout"] = LayoutToJson(s.layout);
    out += record.dump(-1, ' ', false, Json::error_handler_t::replace);
    out += '\n';
  }
  return out;
}

}  // namespace villa::annotator
