#pragma once
// Unsaved description text, journalled while a person types, so that it survives the tool dying in the
// middle of an edit (a crash, a closed terminal, kill -9). DIR/annotations.drafts.jsonl, one JSON object
// a line, appended and fsync'ed:
//   {"v": 1, "time": "...", "id": "villa-000042", "field": "coarse", "annotator": "alice", "text": "..."}
//   {"v": 1, "time": "...", "id": "villa-000042", "field": "coarse", "closed": "saved" | "dropped"}
// The last line per (id, field) wins; a draft not closed is offered again on the next start. The main
// journal is not touched, so versions of villa that do not know drafts read it as before.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "annotator/journal.h"
#include "util/result.h"

namespace villa::annotator {

enum class DescriptionField { kCoarse, kFine };
std::string_view FieldName(DescriptionField field);  // "coarse", "fine"

struct OpenDraft {
  std::string id;
  DescriptionField field = DescriptionField::kCoarse;
  std::string text;
  std::string time;       // UTC, when it was last kept
  std::string annotator;
};

std::filesystem::path DraftsPath(const std::filesystem::path& dir);

class DraftJournal {
 public:
  // Reads the draft journal at `path` (missing: no drafts). With `writable` it is opened for appending,
  // and emptied first when every draft in it was saved or dropped, so it never grows past the drafts
  // that are open.
  Status Open(const std::filesystem::path& path, bool writable);

  std::optional<OpenDraft> Find(const std::string& id, DescriptionField field) const;
  // Open drafts in the order they were last kept.
  std::vector<OpenDraft> All() const;
  const std::vector<std::string>& warnings() const { return warnings_; }

  Status Keep(const std::string& id, DescriptionField field, const std::string& text, const std::string& annotator);
  // `how`: "saved" (the text went into the journal) or "dropped" (the person threw it away).
  Status Close(const std::string& id, DescriptionField field, const std::string& how);

 private:
  Status Append(const JournalJson& line);

  using Key = std::pair<std::string, int>;
  std::filesystem::path path_;
  std::map<Key, std::pair<long, OpenDraft>> open_;  // by (id, field): (order kept, draft)
  long order_ = 0;
  std::vector<std::string> warnings_;
  JournalWriter writer_;
  bool writable_ = false;
};

// UTC now as "2026-11-22T01:40:00Z".
std::string UtcNow();

}  // namespace villa::annotator
