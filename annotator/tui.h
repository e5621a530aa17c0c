#pragma once
// The interactive annotator (ncurses): floor plan, room list, live rule violations, the two
// descriptions, a status line; one key per category, accept / reject / edit / redraft / fix / undo.
// Every action goes through Session (journaled and fsync'ed) before the screen shows it as done.
#include <string>

#include "annotator/session.h"

namespace villa::annotator {

struct TuiOptions {
  bool ascii = false;     // plain ASCII instead of box-drawing characters
  std::string start_id;   // open this layout first (default: the first pending one)
};

// Runs until `q`. Returns the process exit code (0; 1 when the terminal cannot be used).
int RunAnnotatorTui(Session& session, const TuiOptions& options);

}  // namespace villa::annotator
