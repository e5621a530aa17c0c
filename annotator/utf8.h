#pragma once
// UTF-8 text as the annotator shows and edits it: code points, their terminal width, and decoding that
// never fails (a byte that does not belong to a valid sequence is set aside, never allowed to stop the
// text after it). Widths come from wcwidth() in the current LC_CTYPE, so they agree with the terminal
// when the program runs in a UTF-8 locale; without one every printable code point counts one column.
#include <string>
#include <string_view>
#include <vector>

#include "util/utf8.h"

namespace villa::annotator {

// The code points of `text`; a byte that starts no valid sequence becomes U+FFFD.
std::vector<char32_t> DecodeUtf8(std::string_view text);
using villa::EncodeUtf8;  // one code point (util/utf8.h)
std::string EncodeUtf8(const std::vector<char32_t>& code_points);

// Each code point of `text` as its own UTF-8 string (the cells of a plan row, a label's glyphs).
std::vector<std::string> Utf8Glyphs(std::string_view text);

// Terminal columns: 0 for combining marks and controls, 2 for wide (CJK) characters, else 1.
int CodePointWidth(char32_t code_point);
int TextWidth(std::string_view text);

// The longest prefix of `text` at most `width` columns wide.
std::string ClipToWidth(std::string_view text, int width);
// `text` clipped, then padded with spaces to exactly `width` columns.
std::string PadToWidth(std::string_view text, int width);

// For a terminal without UTF-8: every code point outside ASCII becomes '?', so the layout of the screen
// (one column a character) still holds. The text itself is never changed, only what is drawn.
std::string AsciiOnly(std::string_view text);

}  // namespace villa::annotator
