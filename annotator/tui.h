#pragma once
// The interactive annotator (ncurses): floor plans (all floors side by side when the terminal is wide
// enough), a room list with every connection, live rule violations, the two descriptions, who did what;
// one key per category, accept / reject / edit / redraft / fix / undo, filters and go-to for working
// through a large set. Every action goes through Session (journaled and fsync'ed) before the screen shows
// it as done; typed description text is kept as a draft while it is typed.
//
// Input is read as raw bytes and decoded by key_input.h, never by the terminal's key tables, so a byte
// that is not UTF-8, an Alt-key, an unknown escape sequence or a paste cannot stall the tool or run as
// commands.
#include <string>

#include "annotator/session.h"

namespace villa::annotator {

struct TuiOptions {
  bool ascii = false;           // plain ASCII instead of box-drawing characters
  std::string start_id;         // open this layout first (default: a recovered draft's, else the first to do)
  Filter filter = Filter::kAll; // the layouts n / p / space step through
  bool review = false;          // who did what beside every layout; starts on the disagreements
};

// Runs until `q`. Returns the process exit code (0; 1 when the terminal cannot be used; 2 for a bad
// --id).
int RunAnnotatorTui(Session& session, const TuiOptions& options);

}  // namespace villa::annotator
