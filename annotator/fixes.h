#pragma once
// Mechanical fixes for the rule breaks a relabel typically causes (FORMAT.md rules 9 and 10): a room made
// a kitchen or a bathroom without a window gets one on its longest free exterior wall; a balcony gets a
// panoramic window (an existing window of it made panoramic, or a new one) and a door to a neighbour (its
// open made a door, or a new door on the longest shared wall); a kitchen gets an open to the dining room of
// its floor and a living room a door to the kitchen when they share a wall; a nested room's open becomes a
// door. A fix is offered only when it can be made exactly: new elements are on the 2-decimal grid of the
// text format, on the right wall, clear of the elements already there, at least as wide as rule 5 asks.
#include <string>
#include <vector>

#include "layout/layout.h"
#include "util/result.h"

namespace villa::annotator {

enum class FixKind {
  kAddWindow,        // room gets a window on its exterior wall
  kAddPanoramic,     // room (a balcony) gets a panoramic window
  kMakePanoramic,    // an existing window of the room becomes panoramic
  kOpenToDoor,       // an open becomes a door
  kAddDoor,          // a door on the wall shared by room and other
  kAddOpen,          // an open on the wall shared by room and other
};

struct Fix {
  FixKind kind = FixKind::kAddWindow;
  int rule = 0;            // the FORMAT.md rule it repairs
  std::string room;        // room name
  std::string other;       // second room (doors, opens) or the element changed (windows, opens)
  std::string title;       // for a person: "add a window on kitchen_0/0's exterior wall"
};

// The fixes that apply to `layout` now, in a fixed order (rooms in layout order).
std::vector<Fix> FindFixes(const Layout& layout);

// Applies one fix; an error (naming the room) when it no longer applies or cannot be placed.
Result<Layout> ApplyFix(const Layout& layout, const Fix& fix);

// Applies the fixes found, repeatedly, until none is left (at most a few rounds). Returns the titles of
// the fixes made.
std::vector<std::string> ApplyAllFixes(Layout& layout);

}  // namespace villa::annotator
