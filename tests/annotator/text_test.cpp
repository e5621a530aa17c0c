// Text on the annotator's screen: UTF-8 widths, the editor's buffer (words, line breaks, wrapping, the
// cursor's cell), word wrapping with hard breaks, the room list and the header.
#include <clocale>
#include <cmath>
#include <sstream>

#include <catch2/catch.hpp>

#include "annotator/relabel.h"
#include "annotator/screen_text.h"
#include "annotator/text_edit.h"
#include "annotator/utf8.h"
#include "layout/topology.h"
#include "test_support.h"

using namespace villa;
using namespace villa::annotator;

namespace {

// Widths follow the locale, as the terminal's do: these tests speak UTF-8.
struct Utf8Locale {
  Utf8Locale() : before(std::setlocale(LC_CTYPE, nullptr)) { REQUIRE(std::setlocale(LC_CTYPE, "C.UTF-8")); }
  ~Utf8Locale() { std::setlocale(LC_CTYPE, before.c_str()); }
  std::string before;
};

}  // namespace

TEST_CASE("UTF-8 widths: wide characters take two columns, combining marks none", "[text]") {
  Utf8Locale locale;
  CHECK(TextWidth("abc") == 3);
  CHECK(TextWidth("日本") == 4);
  CHECK(TextWidth("e\xcc\x81") == 1);  // e + combining acute
  CHECK(TextWidth("═║≡▒") == 4);
  CHECK(ClipToWidth("日本語", 5) == "日本");
  CHECK(PadToWidth("日本", 6) == "日本  ");
  CHECK(AsciiOnly("salle à manger") == "salle ? manger");
  // Invalid bytes decode to U+FFFD and never swallow what follows.
  auto cps = DecodeUtf8("a\xff" "b\xc3");
  REQUIRE(cps.size() == 4);
  CHECK(cps[0] == 'a');
  CHECK(cps[1] == 0xFFFD);
  CHECK(cps[2] == 'b');
  CHECK(cps[3] == 0xFFFD);
  CHECK(EncodeUtf8(DecodeUtf8("日本 é")) == "日本 é");
}

TEST_CASE("the editor's buffer: words, line breaks, deletion", "[text]") {
  Utf8Locale locale;
  TextEdit t("Two floors");
  CHECK(!t.Modified());
  t.TextEnd();
  t.WordLeft();
  CHECK(t.cursor() == 4);
  t.Insert("big ");
  CHECK(t.Text() == "Two big floors");
  CHECK(t.Modified());
  t.TextEnd();
  t.Insert(".");
  t.DeleteWordBack();  // the word and the full stop after it
  CHECK(t.Text() == "Two big ");
  t.WordLeft();
  t.WordLeft();
  CHECK(t.cursor() == 0);
  t.DeleteWordForward();
  CHECK(t.Text() == " big ");
  t.Clear();
  t.Insert("Line one\nLine two");
  CHECK(t.Text() == "Line one\nLine two");
  t.LineStart();
  CHECK(t.cursor() == 9);
  t.Left();
  t.LineStart();
  CHECK(t.cursor() == 0);
  t.LineEnd();
  CHECK(t.cursor() == 8);
  t.DeleteToLineEnd();  // at the break: joins the lines
  CHECK(t.Text() == "Line oneLine two");
  // Control characters and invalid bytes are no text; tabs are spaces.
  TextEdit u("");
  u.Insert("a\tb\x01\xff" "c\r");
  CHECK(u.Text() == "a bc\n");
}

TEST_CASE("wrapping: at spaces, at every line break, by display width, and the cursor's cell", "[text]") {
  Utf8Locale locale;
  TextEdit t("aaaa bbbb cc\ndd");
  auto rows = t.Wrap(6);
  REQUIRE(rows.size() == 4);
  CHECK(t.RowText(rows[0]) == "aaaa ");
  CHECK(t.RowText(rows[1]) == "bbbb ");
  CHECK(t.RowText(rows[2]) == "cc");
  CHECK(t.RowText(rows[3]) == "dd");
  t.TextEnd();
  auto cell = t.CursorCell(rows);
  CHECK(cell.row == 3);
  CHECK(cell.column == 2);
  // At a soft break the cursor is at the start of the next row.
  TextEdit s("aaaa bbbb");
  s.TextStart();
  for (int i = 0; i < 5; ++i) s.Right();
  cell = s.CursorCell(s.Wrap(6));
  CHECK(cell.row == 1);
  CHECK(cell.column == 0);
  // Wide characters: two columns each, so the cursor lands after them.
  TextEdit w("日本x");
  w.TextEnd();
  cell = w.CursorCell(w.Wrap(40));
  CHECK(cell.column == 5);
  // A word wider than the row is cut; an empty text still has a row for the cursor.
  CHECK(TextEdit("abcdefgh").Wrap(3).size() == 3);
  CHECK(TextEdit("").Wrap(10).size() == 1);
  // Up and down keep the column.
  TextEdit m("abcdef\nab\nabcdef");
  m.TextEnd();
  m.MoveRows(-1, 20);
  CHECK(m.cursor() == 9);  // end of "ab"
  m.MoveRows(-1, 20);
  CHECK(m.cursor() == 2);
  m.MoveRows(-5, 20);
  CHECK(m.cursor() == 0);
}

TEST_CASE("word wrap of descriptions keeps line breaks", "[text]") {
  Utf8Locale locale;
  auto lines = WrapText("A house.\nTwo floors, a big kitchen", 12);
  REQUIRE(lines.size() == 4);
  CHECK(lines[0] == "A house.");
  CHECK(lines[1] == "Two floors,");
  CHECK(lines[2] == "a big");
  CHECK(lines[3] == "kitchen");
  CHECK(WrapText("abcdefghij", 4) == std::vector<std::string>{"abcd", "efgh", "ij"});
  CHECK(WrapText("日本語の家", 4) == std::vector<std::string>{"日本", "語の", "家"});
}

TEST_CASE("the room list names every connection whole, at any width", "[text]") {
  Utf8Locale locale;
  Layout layout = test::FixtureLayout("villa-000001");
  auto connections = RoomConnections(layout);
  for (int width : {34, 36, 50, 78}) {
    for (int level : {0, 1}) {
      auto lines = RoomListLines(layout, level, layout.RoomsOnLevel(level)[0], width, true);
      std::map<int, std::string> text;
      for (const RoomListLine& l : lines) {
        CHECK(TextWidth(l.text) == width);
        text[l.room] += " " + l.text + " ";
        if (!l.first) CHECK(l.text.rfind("    ", 0) == 0);
      }
      for (int r : layout.RoomsOnLevel(level)) {
        INFO("width " << width << ", " << layout.rooms[r].name() << ": " << text[r]);
        CHECK(text[r].find(layout.rooms[r].name()) != std::string::npos);
        for (const Connection& c : connections) {
          if (c.room_a != r && c.room_b != r) continue;
          std::string token = c.via == Via::kDoor ? " " : c.via == Via::kOpen ? " ~" : " ^";
          token.append(RoomToken(layout.rooms[c.room_a == r ? c.room_b : c.room_a])).append(" ");
          CHECK(text[r].find(token) != std::string::npos);
        }
      }
      CHECK(lines.front().text.rfind(">1 ", 0) == 0);
    }
  }
}

TEST_CASE("the header keeps the level whatever the width", "[text]") {
  Utf8Locale locale;
  for (int width : {50, 60, 80, 120}) {
    std::string h = HeaderText("villa-000001", "2/1000", "L-shaped, 2 floors", "pending", "level 1: top floor", "filter: auto", width);
    INFO(width << ": " << h);
    CHECK(TextWidth(h) == width);
    CHECK(h.find("level 1: top floor") != std::string::npos);
    CHECK(h.find("[pending]") != std::string::npos);
  }
  CHECK(HeaderText("villa-000001", "2/1000", "L-shaped, 2 floors", "pending", "level 1: top floor", "", 120).find("L-shaped") !=
        std::string::npos);
  // An id too long for the line gives way to the level.
  std::string h = HeaderText(std::string(70, 'x'), "1/1", "L-shaped", "pending", "level 0: ground floor", "", 60);
  CHECK(h.find("level 0: ground floor") != std::string::npos);
}
