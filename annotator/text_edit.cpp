#include "annotator/text_edit.h"

#include <algorithm>
#include <cctype>
#include <cwctype>

#include "annotator/utf8.h"

namespace villa::annotator {

TextEdit::TextEdit(std::string_view text) {
  Insert(text);
  original_ = text_;
}

std::string TextEdit::Text() const { return EncodeUtf8(text_); }

void TextEdit::Insert(std::string_view utf8) {
  std::vector<char32_t> add;
  for (char32_t c : DecodeUtf8(utf8)) {
    if (c == '\r' || c == '\n')
      add.push_back('\n');
    else if (c == '\t')
      add.push_back(' ');
    else if (c < 0x20 || c == 0x7f || c == 0xFFFD || (c >= 0x80 && c < 0xA0))
      continue;
    else
      add.push_back(c);
  }
  text_.insert(text_.begin() + static_cast<long>(cursor_), add.begin(), add.end());
  cursor_ += add.size();
}

void TextEdit::Clear() {
  text_.clear();
  cursor_ = 0;
}

bool TextEdit::Erase(std::size_t from, std::size_t to) {
  if (from >= to || to > text_.size()) return false;
  text_.erase(text_.begin() + static_cast<long>(from), text_.begin() + static_cast<long>(to));
  if (cursor_ > to)
    cursor_ -= to - from;
  else if (cursor_ > from)
    cursor_ = from;
  return true;
}

bool TextEdit::DeleteBack() { return cursor_ > 0 && Erase(cursor_ - 1, cursor_); }
bool TextEdit::DeleteForward() { return Erase(cursor_, cursor_ + 1); }

bool TextEdit::IsWord(std::size_t i) const {
  char32_t c = text_[i];
  if (c < 0x80) return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '\'';
  return !std::iswspace(static_cast<wint_t>(c));
}

void TextEdit::WordLeft() {
  while (cursor_ > 0 && !IsWord(cursor_ - 1)) --cursor_;
  while (cursor_ > 0 && IsWord(cursor_ - 1)) --cursor_;
}

void TextEdit::WordRight() {
  while (cursor_ < text_.size() && !IsWord(cursor_)) ++cursor_;
  while (cursor_ < text_.size() && IsWord(cursor_)) ++cursor_;
}

bool TextEdit::DeleteWordBack() {
  std::size_t end = cursor_;
  WordLeft();
  return Erase(cursor_, end);
}

bool TextEdit::DeleteWordForward() {
  std::size_t start = cursor_;
  WordRight();
  std::size_t end = cursor_;
  cursor_ = start;
  return Erase(start, end);
}

bool TextEdit::DeleteToLineEnd() {
  std::size_t end = cursor_;
  while (end < text_.size() && text_[end] != '\n') ++end;
  if (end == cursor_ && end < text_.size()) ++end;  // at a line break: join the next line
  return Erase(cursor_, end);
}

void TextEdit::Left() {
  if (cursor_ > 0) --cursor_;
}
void TextEdit::Right() {
  if (cursor_ < text_.size()) ++cursor_;
}
void TextEdit::LineStart() {
  while (cursor_ > 0 && text_[cursor_ - 1] != '\n') --cursor_;
}
void TextEdit::LineEnd() {
  while (cursor_ < text_.size() && text_[cursor_] != '\n') ++cursor_;
}

std::vector<TextEdit::Row> TextEdit::Wrap(int width) const {
  width = std::max(width, 1);
  std::vector<Row> rows;
  std::size_t n = text_.size();
  std::size_t begin = 0;
  while (true) {
    std::size_t line_end = begin;
    while (line_end < n && text_[line_end] != '\n') ++line_end;
    std::size_t start = begin;
    while (true) {
      int used = 0;
      std::size_t i = start;
      std::size_t last_break = 0;
      bool have_break = false;
      while (i < line_end && used + CodePointWidth(text_[i]) <= width) {
        used += CodePointWidth(text_[i]);
        if (text_[i] == ' ') {
          last_break = i + 1;
          have_break = true;
        }
        ++i;
      }
      if (i >= line_end) {
        rows.push_back({start, line_end});
        break;
      }
      std::size_t end = have_break && last_break > start ? last_break : std::max(i, start + 1);
      rows.push_back({start, end});
      start = end;
    }
    if (line_end >= n) break;
    begin = line_end + 1;
  }
  return rows;
}

TextEdit::Cell TextEdit::CursorCell(const std::vector<Row>& rows) const {
  Cell cell;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const Row& row = rows[r];
    bool soft_wrapped = r + 1 < rows.size() && rows[r + 1].begin == row.end;
    if (cursor_ < row.begin || cursor_ > row.end || (cursor_ == row.end && soft_wrapped)) continue;
    cell.row = static_cast<int>(r);
    for (std::size_t i = row.begin; i < cursor_; ++i) cell.column += CodePointWidth(text_[i]);
    return cell;
  }
  return cell;
}

void TextEdit::MoveRows(int delta, int width) {
  auto rows = Wrap(width);
  Cell here = CursorCell(rows);
  int target = here.row + delta;
  if (target < 0) {
    cursor_ = 0;
    return;
  }
  if (target >= static_cast<int>(rows.size())) {
    cursor_ = text_.size();
    return;
  }
  const Row& row = rows[target];
  bool soft_wrapped = target + 1 < static_cast<int>(rows.size()) && rows[target + 1].begin == row.end;
  std::size_t last = soft_wrapped && row.end > row.begin ? row.end - 1 : row.end;
  std::size_t pos = row.begin;
  int column = 0;
  while (pos < last && column + CodePointWidth(text_[pos]) <= here.column) {
    column += CodePointWidth(text_[pos]);
    ++pos;
  }
  cursor_ = pos;
}

std::string TextEdit::RowText(const Row& row) const {
  return EncodeUtf8(std::vector<char32_t>(text_.begin() + static_cast<long>(row.begin), text_.begin() + static_cast<long>(row.end)));
}

}  // namespace villa::annotator
