#pragma once
// A floor plan as a grid of terminal cells (no curses here, so it is testable): rooms filled and
// labelled, walls in box-drawing characters, doors, opens, windows, panoramic windows, the entrance and
// the staircase marked. The terminal draws each cell in the colour of its room and kind.
//
// Plan y grows north (up on screen). Terminal cells are about twice as tall as wide, so one metre spans
// about twice as many columns as rows. All levels share one scale and origin, so switching floors keeps
// the building still on screen.
#include <string>
#include <vector>

#include "layout/layout.h"

namespace villa::annotator {

enum class CellKind { kEmpty, kFloor, kStair, kLabel, kWall, kDoor, kOpen, kWindow, kPanoramic, kEntrance };

struct CanvasCell {
  std::string glyph = " ";  // one character (UTF-8 when the canvas is unicode)
  CellKind kind = CellKind::kEmpty;
  int room = -1;            // index into Layout::rooms for floor, stair and label cells
};

struct Canvas {
  int width = 0;
  int height = 0;
  std::vector<CanvasCell> cells;  // row-major
  CanvasCell& at(int x, int y) { return cells[static_cast<std::size_t>(y) * width + x]; }
  const CanvasCell& at(int x, int y) const { return cells[static_cast<std::size_t>(y) * width + x]; }
  // The text of one row (glyphs concatenated), for tests and plain output.
  std::string Row(int y) const;
};

struct CanvasOptions {
  int width = 60;         // cells
  int height = 20;
  bool unicode = true;    // box-drawing characters; false: + - | / \ and ASCII marks
  double aspect = 2.0;    // columns per row for one metre (terminal cell height / width)
  // Labels per room index, longest first ("3 kitchen", "3 kit", "3"): the first that fits is drawn.
  std::vector<std::vector<std::string>> labels;
  bool show_stairs = true;  // hatch utility rooms of multi-story buildings (the staircase)
};

Canvas DrawFloorPlan(const Layout& layout, int level, const CanvasOptions& options);

}  // namespace villa::annotator
