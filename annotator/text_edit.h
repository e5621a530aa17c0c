#pragma once
// The text being edited in the annotator's in-place editor: code points, a cursor, word movement and
// deletion, hard line breaks, and wrapping into rows of a given number of terminal columns (wide
// characters take two, so the cursor lands on the right cell). No curses here; the TUI draws the rows.
#include <string>
#include <string_view>
#include <vector>

namespace villa::annotator {

class TextEdit {
 public:
  explicit TextEdit(std::string_view text = "");

  std::string Text() const;
  bool empty() const { return text_.empty(); }
  std::size_t size() const { return text_.size(); }
  std::size_t cursor() const { return cursor_; }
  // True when the text differs from what the editor started with.
  bool Modified() const { return text_ != original_; }

  // Inserts at the cursor: '\n' is a line break, tabs become spaces, other control characters and
  // invalid bytes are dropped.
  void Insert(std::string_view utf8);
  void Clear();
  bool DeleteBack();          // the code point before the cursor
  bool DeleteForward();       // the code point at the cursor
  bool DeleteWordBack();      // to the start of the word before the cursor (Ctrl-W, Alt-Backspace)
  bool DeleteWordForward();   // to the end of the word after the cursor (Alt-D, Ctrl-Delete)
  bool DeleteToLineEnd();     // to the next line break (Ctrl-K)

  void Left();
  void Right();
  void WordLeft();   // to the start of this or the previous word (Alt-B, Ctrl-Left)
  void WordRight();  // to the end of this or the next word (Alt-F, Ctrl-Right)
  void LineStart();  // of the line (between hard breaks) holding the cursor
  void LineEnd();
  void TextStart() { cursor_ = 0; }
  void TextEnd() { cursor_ = text_.size(); }

  // The text wrapped to `width` columns: breaks after spaces where it can, at every '\n', and inside a
  // word only when the word alone is wider than a row. Rows are [begin, end) in code points; the '\n'
  // ending a row belongs to no row.
  struct Row {
    std::size_t begin = 0;
    std::size_t end = 0;
  };
  std::vector<Row> Wrap(int width) const;
  // Where the cursor is drawn in `rows`: row index and column (terminal cells from the row's start).
  struct Cell {
    int row = 0;
    int column = 0;
  };
  Cell CursorCell(const std::vector<Row>& rows) const;
  // Up (-1) / down (+1) one wrapped row, keeping the column as near as the row allows.
  void MoveRows(int delta, int width);
  // The text of one row as UTF-8.
  std::string RowText(const Row& row) const;

 private:
  bool IsWord(std::size_t i) const;
  bool Erase(std::size_t from, std::size_t to);

  std::vector<char32_t> text_;
  std::vector<char32_t> original_;
  std::size_t cursor_ = 0;
};

}  // namespace villa::annotator
