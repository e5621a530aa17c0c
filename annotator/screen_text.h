#pragma once
// The text of the annotator's screen that needs no curses, so it is unit-tested: word wrapping with hard
// line breaks, the room list with every connection whole, the header that always keeps the level.
#include <string>
#include <string_view>
#include <vector>

#include "layout/layout.h"

namespace villa::annotator {

// Greedy word wrap to `width` columns (terminal cells); '\n' always breaks; a word wider than a line is
// cut across lines. Whitespace runs inside a line collapse to one space.
std::vector<std::string> WrapText(std::string_view text, int width);

// One line of the room list: ">2 kitchen_0/0     16.0m²  living0 ~dining0", connections going on to
// indented continuation lines ("    ^utility1") instead of being cut.
struct RoomListLine {
  std::string text;  // exactly `width` columns wide
  int room = -1;     // index into Layout::rooms
  bool first = false;  // the line with the room's number and name (its category swatch is drawn there)
  int swatch = 0;    // column of the swatch on a first line
};
// `connections` tokens per room come from RoomConnections: "kitchen0" door, "~dining0" open, "^utility1"
// stairs. `selected` is a room index or -1.
std::vector<RoomListLine> RoomListLines(const Layout& layout, int level, int selected, int width, bool unicode);

// "ground floor", "top floor", "floor 2" (of a three-floor building).
std::string LevelName(int level, int floors);

// The header: id, position, shape, status on the left, the level on the right. Parts on the left are
// dropped (shape first, then position) before the level label would be: the level is always shown.
std::string HeaderText(const std::string& id, const std::string& position, const std::string& shape,
                       const std::string& status, const std::string& level, const std::string& extra, int width);

}  // namespace villa::annotator
