#pragma once
// An annotation session over one dataset folder: the state of every layout (status, reason, the two
// descriptions and where each came from, the labelled layout, who decided), every change journaled
// (journal.h) before it counts as done, undo / redo across the session, who did what and how long it
// took, the unsaved text of an edit (drafts.h), and the batch modes (--auto, --export, --status).
//
// A layout nobody touched is `pending`: its labels are the partitioner's with the unlabelled rooms given
// drafted labels (relabel.h DraftLabels), its descriptions the drafts (describe.h).
//
// Journal format 2 (this version) adds to every line "v": 2, "annotator" and "seconds", and to the state
// "origin" (per description) and "decided_by"; it keeps "edited" (true when either description is a
// person's) so that format-1 readers, which ignore unknown keys, still replay it. Format-1 lines (no
// "v") are read as before: "edited" then counts for both descriptions, annotator and seconds are
// unknown. Lines of a newer format are read as far as this version understands them, with a warning.
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "annotator/agreement.h"
#include "annotator/dataset.h"
#include "annotator/drafts.h"
#include "annotator/fixes.h"
#include "annotator/journal.h"
#include "layout/layout.h"
#include "util/result.h"

namespace villa::annotator {

inline constexpr int kJournalVersion = 2;

enum class AnnotationStatus { kPending, kVerified, kRejected, kAuto };
std::string_view StatusName(AnnotationStatus status);  // "pending", "verified", "rejected", "auto"

// Where a description's text came from: the drafter, a person editing a draft (the words of the two,
// compared as difflib does, are at least half the same), or a person writing their own text.
enum class TextOrigin { kDrafted, kEdited, kWritten };
std::string_view OriginName(TextOrigin origin);  // "drafted", "edited", "written"

// Who set a status when no person did.
inline constexpr const char* kAutoAnnotator = "auto";

struct AnnotationState {
  AnnotationStatus status = AnnotationStatus::kPending;
  std::string reason;  // why it was rejected; empty otherwise
  std::string coarse;
  std::string fine;
  TextOrigin coarse_origin = TextOrigin::kDrafted;  // a drafted description is redrafted when the layout
  TextOrigin fine_origin = TextOrigin::kDrafted;    // changes; a person's is kept as written
  int draft = 0;           // how many times the descriptions were redrafted: seeds the drafter
  std::string decided_by;  // who set `status` to verified or rejected ("auto" for --auto); empty otherwise
  Layout layout;

  const std::string& text(DescriptionField f) const { return f == DescriptionField::kCoarse ? coarse : fine; }
  std::string& text(DescriptionField f) { return f == DescriptionField::kCoarse ? coarse : fine; }
  TextOrigin origin(DescriptionField f) const { return f == DescriptionField::kCoarse ? coarse_origin : fine_origin; }
  TextOrigin& origin(DescriptionField f) { return f == DescriptionField::kCoarse ? coarse_origin : fine_origin; }
  bool edited(DescriptionField f) const { return origin(f) != TextOrigin::kDrafted; }
};

JournalJson StateToJson(const AnnotationState& state);
Result<AnnotationState> StateFromJson(const JournalJson& json, const std::string& source);

// The reasons offered when rejecting (free text is always possible too).
const std::vector<std::string>& PresetRejectReasons();

struct Counts {
  int pending = 0, verified = 0, rejected = 0, automatic = 0;
  int total() const { return pending + verified + rejected + automatic; }
};

// Which layouts the interactive tool steps through.
enum class Filter {
  kAll,
  kToDo,           // pending or auto: not yet looked at by a person
  kPending,
  kAuto,
  kRejected,
  kVerified,
  kDecided,        // verified or rejected by a person
  kDisagreements,  // rated by two people who differ (decision, or a room's label)
};
std::string_view FilterName(Filter filter);  // "all", "to-do", "pending", ..., "disagreements"
std::optional<Filter> ParseFilter(std::string_view name);
inline constexpr Filter kAllFilters[] = {Filter::kAll,      Filter::kToDo,     Filter::kPending, Filter::kAuto,
                                         Filter::kRejected, Filter::kVerified, Filter::kDecided, Filter::kDisagreements};

// One journal line about a layout, for the review: who did what, when, and how long it took.
struct HistoryEntry {
  std::string time;       // UTC as written
  std::string annotator;  // empty in format-1 journals
  std::string kind;       // do, undo, redo, batch (merged lines: the kind in their package)
  std::string action;
  int seconds = 0;
  std::string package;    // the work package a merged line came from
};

struct Effort {
  int seconds = 0;                      // all the time people spent on the layout
  std::vector<std::string> annotators;  // who acted on it, in order of their first action
};

struct SessionOptions {
  bool writable = true;   // false for --status and --export: nothing is written, a torn tail is left
  std::string annotator;  // who acts, written into every journal line; empty: the login name
};

// The login name ($USER, $LOGNAME, the password database), or "unknown".
std::string LoginName();
// An annotator name is 1-64 printable characters without control characters; the error says why not.
Status CheckAnnotatorName(const std::string& name);

class Session {
 public:
  // Loads DIR/layouts.jsonl, replays DIR/annotations.journal.jsonl and reads the open drafts.
  static Result<std::unique_ptr<Session>> Open(const std::filesystem::path& dir, const SessionOptions& options);
  static Result<std::unique_ptr<Session>> Open(const std::filesystem::path& dir, bool writable = true) {
    SessionOptions o;
    o.writable = writable;
    return Open(dir, o);
  }

  int size() const { return static_cast<int>(dataset_.records.size()); }
  const DatasetRecord& record(int item) const { return dataset_.records[item]; }
  const AnnotationState& state(int item) const { return states_[item]; }
  const Dataset& dataset() const { return dataset_; }
  const std::vector<std::string>& warnings() const { return warnings_; }
  const std::string& annotator() const { return annotator_; }
  Counts counts() const;
  // The first pending layout at or after `from` (wrapping around), or -1 when none is pending.
  int NextPending(int from = 0) const;

  // Not yet looked at by a person: pending or auto.
  bool IsToDo(int item) const;
  bool Matches(int item, Filter filter) const;
  int CountMatching(Filter filter) const;
  // The next layout after `from` in `direction` (+1 / -1, wrapping) that matches `filter` and, with
  // `to_do`, is still to do; -1 when there is none. `from` may be -1 to start at the first layout.
  int Step(int from, int direction, Filter filter, bool to_do) const;
  int NextToDo(int from = 0) const { return Step(from - 1, +1, Filter::kAll, true); }
  // A layout by its id, by the end of its id ("42" for villa-000042, when only one id ends so), or by
  // its position ("#17", 1-based). The error says why none or which several match.
  Result<int> FindItem(std::string_view query) const;

  // Who did what.
  const std::vector<HistoryEntry>& history(int item) const { return history_[item]; }
  const Effort& effort(int item) const { return effort_[item]; }
  // The last decision (verified or rejected) of each person who decided layout `item`, by name.
  std::vector<Rating> Ratings(int item) const;
  bool Disagreement(int item) const;
  Agreement AgreementFigures() const;

  // Seconds a person spent on layout `item` (on screen, while keys came): journalled with the next
  // action on it, so the journal and the export carry the time per layout.
  void Spend(int item, double seconds);

  // Before accepting: an edited description that names rooms the layout no longer has ("the coarse
  // description names a bedroom, which the layout no longer has"). Empty when there is nothing to say.
  std::vector<std::string> AcceptWarnings(int item) const;
  // Non-empty when `item`'s status was set by another person (not this session's annotator, not
  // --auto): "villa-000042 was rejected by bob: staircase badly placed". Changing it overturns them.
  std::string OverturnWarning(int item) const;

  // Actions. Each is journaled and fsync'ed before it returns; on a write error the state is unchanged.
  // `message` gets one line for the status bar.
  Status Relabel(int item, int room, Category category, std::string* message);
  // Refused (error) while the layout breaks a rule or a description is empty; a no-op on a verified one.
  Status Accept(int item, std::string* message);
  Status Reject(int item, const std::string& reason, std::string* message);
  Status Reopen(int item, std::string* message);  // back to pending
  Status SetDescription(int item, DescriptionField field, const std::string& text, std::string* message);
  Status SetDescriptions(int item, const std::string& coarse, const std::string& fine, std::string* message);
  Status Redraft(int item, std::string* message);
  Status ApplyFixes(int item, const std::vector<Fix>& fixes, std::string* message);
  // Undo / redo the last action (of any layout); `item` gets the layout it changed.
  Status Undo(int* item, std::string* message);
  Status Redo(int* item, std::string* message);
  bool CanUndo() const { return !undo_.empty(); }
  bool CanRedo() const { return !redo_.empty(); }

  // Unsaved description text (drafts.h): kept while a person types, offered again after a crash.
  std::optional<OpenDraft> Draft(int item, DescriptionField field) const;
  std::vector<OpenDraft> OpenDrafts() const { return drafts_.All(); }
  Status KeepDraft(int item, DescriptionField field, const std::string& text);
  Status DropDraft(int item, DescriptionField field);

  // --auto: every pending layout gets its drafted labels and descriptions and the mechanical fixes;
  // it becomes `auto` when it then passes ValidateLayout, else `rejected` with the first violation as
  // the reason ("auto: rule 9: kitchen_0/0 has no window"). Never `verified`. Returns how many changed.
  Result<Counts> AutoAnnotate();

  // The lines of a work package's journal (packages.h), added to this journal as "batch" lines that
  // keep their annotator, time, seconds and state and say where they came from; `package` names the
  // package, `source` its journal file (for messages). Lines merged before (same package and seq) and
  // the package's own starting lines are skipped. Returns how many lines were added.
  Result<int> MergeLines(const std::string& package, const std::vector<JournalLine>& lines,
                         const std::filesystem::path& source);
  // True when layout `item` was ever touched (journalled): its state is not the drafted starting one.
  bool Touched(int item) const { return touched_[item]; }

  // The current state of every layout, one JSON object a line, in dataset order:
  // {"id", "status", "reason" (rejected only), "descriptions": {"coarse", "fine"},
  //  "annotation": {"decided_by", "annotators", "seconds", "origin": {"coarse", "fine"}}, "layout"}.
  std::string ExportJsonl() const;

  // The state a layout starts from (drafted labels and descriptions), `draft` redrafts along.
  AnnotationState InitialState(int item, int draft = 0) const;
  // Redrafts the descriptions of `state` (as record `item`) that no person wrote.
  void Redescribe(int item, AnnotationState& state) const;

 private:
  struct UndoEntry {
    int item;
    AnnotationState before;
    AnnotationState after;
    std::string action;
  };
  Session() = default;
  Status Commit(int item, AnnotationState next, const std::string& action, std::string* message);
  JournalJson Line(int item, const AnnotationState& state, const std::string& kind, const std::string& action);
  // Replays one journal line (from the file or a merge): state, undo history, who did what.
  Status Apply(const JournalJson& json, const std::string& where);
  // Bookkeeping of a line about `item`: history, effort, ratings.
  void Note(int item, const JournalJson& line, const AnnotationState& state);
  TextOrigin OriginOfEdit(int item, const AnnotationState& current, DescriptionField field,
                          const std::string& text) const;

  Dataset dataset_;
  std::vector<AnnotationState> states_;
  std::vector<bool> touched_;
  std::vector<UndoEntry> undo_;
  std::vector<UndoEntry> redo_;
  std::vector<std::string> warnings_;
  std::vector<std::vector<HistoryEntry>> history_;
  std::vector<Effort> effort_;
  std::vector<std::map<std::string, AnnotationState>> opinions_;  // per layout: annotator -> last state
  std::vector<double> unjournalled_seconds_;
  std::set<std::pair<std::string, long>> merged_;  // (package, seq) already merged
  std::string annotator_;
  JournalWriter journal_;
  DraftJournal drafts_;
  bool writable_ = true;
  bool warned_newer_ = false;
  long seq_ = 0;
};

// The seed of record `record`'s drafts after `draft` redrafts.
std::uint64_t DraftSeed(const DatasetRecord& record, int draft);

}  // namespace villa::annotator
