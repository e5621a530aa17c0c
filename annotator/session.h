#pragma once
// An annotation session over one dataset folder: the state of every layout (status, reason, the two
// descriptions, the labelled layout), every change journaled (journal.h) before it counts as done,
// undo / redo across the session, and the batch modes (--auto, --export, --status).
//
// A layout nobody touched is `pending`: its labels are the partitioner's with the unlabelled rooms given
// drafted labels (relabel.h DraftLabels), its descriptions the drafts (describe.h).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "annotator/dataset.h"
#include "annotator/fixes.h"
#include "annotator/journal.h"
#include "layout/layout.h"
#include "util/result.h"

namespace villa::annotator {

enum class AnnotationStatus { kPending, kVerified, kRejected, kAuto };
std::string_view StatusName(AnnotationStatus status);  // "pending", "verified", "rejected", "auto"

struct AnnotationState {
  AnnotationStatus status = AnnotationStatus::kPending;
  std::string reason;  // why it was rejected; empty otherwise
  std::string coarse;
  std::string fine;
  bool edited = false;  // descriptions written by a person: relabels no longer redraft them
  int draft = 0;        // how many times the descriptions were redrafted: seeds the drafter
  Layout layout;
};

JournalJson StateToJson(const AnnotationState& state);
Result<AnnotationState> StateFromJson(const JournalJson& json, const std::string& source);

// The reasons offered when rejecting (free text is always possible too).
const std::vector<std::string>& PresetRejectReasons();

struct Counts {
  int pending = 0, verified = 0, rejected = 0, automatic = 0;
  int total() const { return pending + verified + rejected + automatic; }
};

class Session {
 public:
  // Loads DIR/layouts.jsonl and replays DIR/annotations.journal.jsonl. With `writable` false nothing is
  // written (for --status and --export): a torn journal tail is then reported but left in place.
  static Result<std::unique_ptr<Session>> Open(const std::filesystem::path& dir, bool writable = true);

  int size() const { return static_cast<int>(dataset_.records.size()); }
  const DatasetRecord& record(int item) const { return dataset_.records[item]; }
  const AnnotationState& state(int item) const { return states_[item]; }
  const Dataset& dataset() const { return dataset_; }
  const std::vector<std::string>& warnings() const { return warnings_; }
  Counts counts() const;
  // The first pending layout at or after `from` (wrapping around), or -1 when none is pending.
  int NextPending(int from = 0) const;

  // Actions. Each is journaled and fsync'ed before it returns; on a write error the state is unchanged.
  // `message` gets one line for the status bar.
  Status Relabel(int item, int room, Category category, std::string* message);
  Status Accept(int item, std::string* message);  // refused (error) while the layout breaks a rule
  Status Reject(int item, const std::string& reason, std::string* message);
  Status Reopen(int item, std::string* message);  // back to pending
  Status SetDescriptions(int item, const std::string& coarse, const std::string& fine, std::string* message);
  Status Redraft(int item, std::string* message);
  Status ApplyFixes(int item, const std::vector<Fix>& fixes, std::string* message);
  // Undo / redo the last action (of any layout); `item` gets the layout it changed.
  Status Undo(int* item, std::string* message);
  Status Redo(int* item, std::string* message);
  bool CanUndo() const { return !undo_.empty(); }
  bool CanRedo() const { return !redo_.empty(); }

  // --auto: every pending layout gets its drafted labels and descriptions and the mechanical fixes;
  // it becomes `auto` when it then passes ValidateLayout, else `rejected` with the first violation as
  // the reason ("auto: rule 9: kitchen_0/0 has no window"). Never `verified`. Returns how many changed.
  Result<Counts> AutoAnnotate();

  // The current state of every layout, one JSON object a line, in dataset order:
  // {"id", "status", "reason" (rejected only), "descriptions": {"coarse", "fine"}, "layout"}.
  std::string ExportJsonl() const;

  // The state a layout starts from (drafted labels and descriptions), `draft` redrafts along.
  AnnotationState InitialState(int item, int draft = 0) const;
  // Descriptions drafted for `layout` as record `item`, redraft `draft`.
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

  Dataset dataset_;
  std::vector<AnnotationState> states_;
  std::vector<UndoEntry> undo_;
  std::vector<UndoEntry> redo_;
  std::vector<std::string> warnings_;
  JournalWriter journal_;
  bool writable_ = true;
  long seq_ = 0;
};

// The seed of record `record`'s drafts after `draft` redrafts.
std::uint64_t DraftSeed(const DatasetRecord& record, int draft);

}  // namespace villa::annotator
