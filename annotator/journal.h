#pragma once
// The annotation journal: DIR/annotations.journal.jsonl, one JSON object a line, appended and fsync'ed
// before the screen shows an action as done, so a crash or kill -9 loses nothing shown. Replayed on start.
//
// A line: {"seq": 12, "time": "2026-11-22T01:40:00Z", "id": "villa-000042", "kind": "do"|"undo"|"redo",
//          "action": "label kitchen_0/0 -> bathroom_0/0", "state": {...}}
// where state is the layout's whole annotation after the action (see AnnotationState in session.h), so a
// replay is "last state per id wins" and never depends on re-running an edit.
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "util/result.h"

namespace villa::annotator {

using JournalJson = nlohmann::ordered_json;

struct JournalLine {
  JournalJson json;
  int line = 0;  // 1-based line in the file
};

struct JournalContents {
  std::vector<JournalLine> lines;
  std::vector<std::string> warnings;  // e.g. a torn last line that was set aside
};

// Reads the journal (a missing file is an empty journal). A last line without its newline that is not
// complete JSON is a torn write: it is skipped with a warning, its bytes moved to
// annotations.journal.torn beside the journal, and the journal truncated to its last complete line (so
// the next append starts on a fresh line). Any other line that is not a JSON object is an error naming
// the file and the line.
// With `repair` false the file is left untouched (the torn line is still skipped with a warning).
Result<JournalContents> ReadJournal(const std::filesystem::path& path, bool repair = true);

class JournalWriter {
 public:
  JournalWriter() = default;
  ~JournalWriter();
  JournalWriter(const JournalWriter&) = delete;
  JournalWriter& operator=(const JournalWriter&) = delete;

  // Opens for appending (creating the file).
  Status Open(const std::filesystem::path& path);
  // Appends the lines (each one JSON object, written compact) and fsyncs before returning.
  Status Append(const std::vector<JournalJson>& lines);
  Status Append(const JournalJson& line) { return Append(std::vector<JournalJson>{line}); }
  const std::filesystem::path& path() const { return path_; }

 private:
  int fd_ = -1;
  std::filesystem::path path_;
};

}  // namespace villa::annotator
