// The six input and screen defects of issue 16, each driven through a real terminal (tmux): bytes that
// are not UTF-8, Alt-keys and unknown escape sequences, bracketed paste, one edited flag per description,
// the picture at exactly 80x24, and the small ones (a no-op accept, the editor's exit status, wide
// characters, Esc, cut violation lines, `#` lines in $EDITOR, the stair glyph).
#include <algorithm>
#include <filesystem>
#include <regex>
#include <sstream>

#include <catch2/catch.hpp>

#include "annotator/relabel.h"
#include "annotator/session.h"
#include "layout/topology.h"
#include "layout/validate.h"
#include "terminal.h"
#include "test_support.h"

using namespace villa;
using namespace villa::annotator;
using test::HaveTmux;
using test::Quote;
using test::Terminal;

namespace {

// Code points of a UTF-8 line: every glyph the tool draws in the plan is one terminal column.
std::vector<std::string> Cells(const std::string& line) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < line.size();) {
    unsigned char c = static_cast<unsigned char>(line[i]);
    std::size_t n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : 4;
    out.push_back(line.substr(i, n));
    i += n;
  }
  return out;
}

std::string Join(const std::vector<std::string>& cells, std::size_t from, std::size_t to) {
  std::string out;
  for (std::size_t i = from; i < std::min(to, cells.size()); ++i) out += cells[i];
  return out;
}

// Words of a text, whitespace collapsed.
std::string Squeeze(const std::string& text) {
  std::istringstream in(text);
  std::string word, out;
  while (in >> word) out += (out.empty() ? "" : " ") + word;
  return out;
}

int JournalLines(const test::TempDataset& ds) {
  std::string text = test::Slurp(ds.journal());
  return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

// The plan's west wall on screen: the outline's top-left corner, its bottom-left corner below it, and a
// wall, window, door or entrance glyph on every row between. Returns how many of those are windows.
int CheckWestWall(const std::vector<std::string>& lines, int separator) {
  int left = -1, top = -1, bottom = -1;
  for (int y = 1; y < static_cast<int>(lines.size()) - 2; ++y) {
    auto cells = Cells(lines[y]);
    for (int x = 0; x < std::min<int>(separator, static_cast<int>(cells.size())); ++x) {
      if (cells[x] == " ") continue;
      if (cells[x] == "┌" && top < 0) {
        top = y;
        left = x;
      }
      if (cells[x] == "└" && x == left) bottom = y;
      break;
    }
  }
  INFO("top-left corner at row " << top << ", column " << left << "; bottom-left at row " << bottom);
  REQUIRE(top > 0);
  REQUIRE(bottom > top);
  int windows = 0;
  for (int y = top + 1; y < bottom; ++y) {
    auto cells = Cells(lines[y]);
    INFO("row " << y << ": " << lines[y]);
    REQUIRE(left < static_cast<int>(cells.size()));
    const std::string& c = cells[left];
    CHECK((c == "│" || c == "├" || c == "║" || c == "▒" || c == "▓"));
    if (c == "║") ++windows;
  }
  return windows;
}

// Every room of `level` is listed with all its connections, none cut: a room's line and its
// continuation lines (indented) hold each of its connection tokens as a whole word.
void CheckRoomList(const std::vector<std::string>& lines, int separator, const Layout& layout, int level) {
  std::vector<std::string> panel;
  for (const std::string& line : lines) {
    auto cells = Cells(line);
    panel.push_back(static_cast<int>(cells.size()) > separator ? Join(cells, separator + 1, cells.size()) : "");
  }
  auto connections = RoomConnections(layout);
  std::regex room_line(R"(^[> ](\d+) (\S+))");
  for (int r : layout.RoomsOnLevel(level)) {
    const Room& room = layout.rooms[r];
    std::string block;
    for (std::size_t y = 0; y < panel.size(); ++y) {
      std::smatch m;
      if (!std::regex_search(panel[y], m, room_line) || m[2] != room.name()) continue;
      block = panel[y];
      for (std::size_t k = y + 1; k < panel.size() && panel[k].rfind("    ", 0) == 0 && !Squeeze(panel[k]).empty(); ++k)
        block.append(" ").append(panel[k]);
    }
    INFO("room " << room.name() << " listed as: " << block);
    REQUIRE(!block.empty());
    std::string words = " ";
    words.append(Squeeze(block)).append(" ");
    for (const Connection& c : connections) {
      if (c.room_a != r && c.room_b != r) continue;
      int other = c.room_a == r ? c.room_b : c.room_a;
      std::string token = c.via == Via::kDoor ? " " : c.via == Via::kOpen ? " ~" : " ^";
      token.append(RoomToken(layout.rooms[other])).append(" ");
      CHECK(words.find(token) != std::string::npos);
    }
  }
}

// The column of the plan / panel separator: the bar just before the panel's "Rooms on" title.
int Separator(const std::vector<std::string>& lines) {
  for (const std::string& line : lines) {
    auto cells = Cells(line);
    for (std::size_t x = 0; x + 1 < cells.size(); ++x)
      if (cells[x] == "│" && Join(cells, x + 1, x + 9) == "Rooms on") return static_cast<int>(x);
  }
  return -1;
}

}  // namespace

TEST_CASE("defect 1: a byte that is not UTF-8 never wedges the tool", "[tui][input]") {
  REQUIRE(HaveTmux());
  test::TempDataset ds;
  {
    Terminal term(ds.dir());
    REQUIRE_SCREEN(term, "villa-000000");
    const std::pair<const char*, const char*> bytes[] = {{"ff", "2"}, {"e9", "3"}, {"c3", "4"}, {"80", "5"}};
    for (auto [byte, room] : bytes) {
      term.Bytes(byte);
      term.Keys(room);  // the next key still works: it selects a room
      REQUIRE_SCREEN(term, std::string(">") + room + " ");
    }
    // In the editor too: the stray byte is dropped, the typed text kept.
    REQUIRE(term.EditCleared("e"));
    term.Type("ab");
    term.Bytes("ff");
    term.Type("c");
    term.Keys("Enter");
    REQUIRE_SCREEN(term, "(edited)");
    REQUIRE(term.Quit());
  }
  CHECK(test::OpenSession(ds.dir(), false)->state(0).coarse == "abc");

  // A session in the C locale (no UTF-8 on screen) typing accented text.
  {
    Terminal term(ds.dir(), 80, 24, "LANG=C LC_ALL=C");
    REQUIRE_SCREEN(term, "villa-000000");
    REQUIRE(term.EditCleared("e"));
    term.Type("salle à manger");
    term.Keys("Enter");
    REQUIRE_SCREEN(term, "(edited)");
    REQUIRE(term.Quit());
  }
  CHECK(test::OpenSession(ds.dir(), false)->state(0).coarse == "salle à manger");
}

TEST_CASE("defect 2: Alt-keys and unknown escape sequences never discard text or run as commands", "[tui][input]") {
  REQUIRE(HaveTmux());
  test::TempDataset ds;
  {
    Terminal term(ds.dir());
    REQUIRE_SCREEN(term, "villa-000000");
    REQUIRE(term.EditCleared("e"));
    term.Type("Two floors");
    term.Keys("M-b");  // a word back
    term.Type("big ");
    term.Keys("End");  // \e[4~ or \e[F from tmux: not in xterm-256color's terminfo
    term.Type(".");
    term.Bytes("1b 5b 39 39 7e");  // \e[99~: no key at all
    term.Bytes("1b 5b 31 3b 35 51");  // \e[1;5Q: Ctrl-F2, unused
    term.Keys("Enter");
    REQUIRE_SCREEN(term, "(edited)");
    // Outside the editor an Alt-key is not its plain key.
    term.Keys("M-b");
    term.Keys("M-x");
    term.Bytes("1b 5b 39 39 7e");
    term.Keys("4");
    REQUIRE_SCREEN(term, ">4 bedroom_0/0");
    REQUIRE(term.Quit());
  }
  auto s = test::OpenSession(ds.dir(), false);
  CHECK(s->state(0).coarse == "Two big floors.");
  CHECK(s->state(0).status == AnnotationStatus::kPending);
  CHECK(s->state(0).layout.FindRoom("living-room_0/0") >= 0);
  CHECK(s->state(0).layout.FindRoom("bedroom_0/0") >= 0);
  CHECK(test::Slurp(ds.journal()).find("\"label ") == std::string::npos);
}

TEST_CASE("defect 3: a multi-line paste is text, never commands", "[tui][input]") {
  REQUIRE(HaveTmux());
  test::TempDataset ds;
  {
    Terminal term(ds.dir());
    REQUIRE_SCREEN(term, "villa-000000");
    REQUIRE(term.EditCleared("e"));
    term.Paste("A house.\nbn");
    REQUIRE_SCREEN(term, "A house.");
    term.Keys("Enter");
    REQUIRE_SCREEN(term, "(edited)");
    // A paste outside an editor does nothing either.
    term.Paste("bn");
    REQUIRE_SCREEN(term, "paste ignored");
    CHECK(term.Lines()[0].find("villa-000000") != std::string::npos);
    REQUIRE(term.Quit());
  }
  auto s = test::OpenSession(ds.dir(), false);
  CHECK(s->state(0).coarse == "A house.\nbn");
  CHECK(s->state(0).layout.FindRoom("living-room_0/0") >= 0);
  CHECK(test::Slurp(ds.journal()).find("\"label ") == std::string::npos);
}

TEST_CASE("defect 4: one edited flag per description, and accept warns about rooms an edit names", "[tui]") {
  REQUIRE(HaveTmux());
  test::TempDataset ds;
  std::string drafted_fine = test::OpenSession(ds.dir(), false)->state(0).fine;
  REQUIRE(drafted_fine.find("bedroom") != std::string::npos);
  {
    Terminal term(ds.dir());
    REQUIRE_SCREEN(term, "villa-000000");
    REQUIRE(term.EditCleared("e"));
    term.Type("A one-storey house with a bedroom and a kitchen.");
    term.Keys("Enter");
    REQUIRE_SCREEN(term, "Coarse (edited)");
    REQUIRE_SCREEN(term, "Fine (draft)");
    term.Keys("4");
    REQUIRE_SCREEN(term, ">4 bedroom_0/0");
    term.Keys("o");
    REQUIRE_SCREEN(term, "label bedroom_0/0 -> office_0/0");
    term.Keys("a");
    REQUIRE_SCREEN(term, "no longer has");
    CHECK(test::OpenSession(ds.dir(), false)->state(0).status == AnnotationStatus::kPending);
    term.Keys("a");  // accepted anyway, knowingly
    REQUIRE_SCREEN(term, "verified 1");
    REQUIRE(term.Quit());
  }
  auto s = test::OpenSession(ds.dir(), false);
  CHECK(s->state(0).status == AnnotationStatus::kVerified);
  CHECK(s->state(0).coarse == "A one-storey house with a bedroom and a kitchen.");
  // The fine text nobody edited was redrafted for the office.
  CHECK(s->state(0).fine != drafted_fine);
  CHECK(s->state(0).fine.find("bedroom") == std::string::npos);
  CHECK(s->state(0).fine.find("office") != std::string::npos);
}

TEST_CASE("defect 5: at exactly 80x24 the plan keeps its west wall, windows and level, the list its connections",
          "[tui][screen]") {
  REQUIRE(HaveTmux());
  // A 19 m wide, two-storey L: at 80 columns its plan fills the width exactly.
  test::TempDataset ds("wide.jsonl");
  Layout layout = test::OpenSession(ds.dir(), false)->state(0).layout;
  Terminal term(ds.dir(), 80, 24);
  REQUIRE_SCREEN(term, "villa-wide-19m");
  for (int level : {0, 1}) {
    if (level == 1) {
      term.Keys("]");
      REQUIRE_SCREEN(term, "Rooms on top floor");
    }
    auto lines = term.Lines();
    INFO("screen:\n" << term.Screen());
    REQUIRE(lines.size() == 24);
    CHECK(lines[0].find(level == 0 ? "ground floor" : "top floor") != std::string::npos);
    int separator = Separator(lines);
    REQUIRE(separator > 20);
    // The living room (ground floor) and the bedroom (top floor) have a west window.
    CHECK(CheckWestWall(lines, separator) >= 1);
    CheckRoomList(lines, separator, layout, level);
  }
  REQUIRE(term.Quit());
}

TEST_CASE("defect 6: the small ones", "[tui]") {
  REQUIRE(HaveTmux());
  test::TempDataset ds;
  // An editor that fails, then one that keeps a line starting with '#'.
  std::filesystem::path failing = ds.dir() / "failing-editor.sh";
  test::Spit(failing, "#!/bin/sh\nexit 1\n");
  std::filesystem::path hashes = ds.dir() / "hash-editor.sh";
  test::Spit(hashes,
             "#!/bin/sh\n"
             "awk '/^# ---- fine/ {print; print \"One floor.\"; print \"\"; print \"#1 priority: a big kitchen.\"; exit} {print}' "
             "\"$1\" > \"$1.new\" && mv \"$1.new\" \"$1\"\n");
  for (const auto& p : {failing, hashes}) std::filesystem::permissions(p, std::filesystem::perms::owner_all);

  SECTION("accepting a verified layout again writes nothing and adds no undo step") {
    Terminal term(ds.dir());
    REQUIRE_SCREEN(term, "villa-000000");
    term.Keys("a");
    REQUIRE_SCREEN(term, "verified 1");
    REQUIRE_SCREEN(term, "villa-000001");
    int lines = JournalLines(ds);
    term.Keys("p");
    REQUIRE_SCREEN(term, "[verified]");
    term.Keys("a");
    REQUIRE_SCREEN(term, "already verified");
    CHECK(JournalLines(ds) == lines);
    term.Keys("u");
    REQUIRE_SCREEN(term, "undone: accept villa-000000");
    REQUIRE_SCREEN(term, "verified 0");
    REQUIRE(term.Quit());
  }
  SECTION("the editor's exit code, not a raw wait status") {
    Terminal term(ds.dir(), 80, 24, "VISUAL= EDITOR=" + Quote(failing.string()));
    REQUIRE_SCREEN(term, "villa-000000");
    term.Keys("v");
    REQUIRE_SCREEN(term, "exited with code 1");
    CHECK(term.Screen().find("status 256") == std::string::npos);
    REQUIRE(term.Quit());
  }
  SECTION("a line starting with # survives $EDITOR") {
    Terminal term(ds.dir(), 80, 24, "VISUAL= EDITOR=" + Quote(hashes.string()));
    REQUIRE_SCREEN(term, "villa-000000");
    std::string coarse = test::OpenSession(ds.dir(), false)->state(0).coarse;
    term.Keys("v");
    REQUIRE_SCREEN(term, "edit descriptions of villa-000000");
    REQUIRE(term.Quit());
    auto s = test::OpenSession(ds.dir(), false);
    CHECK(s->state(0).fine == "One floor.\n#1 priority: a big kitchen.");
    CHECK(s->state(0).coarse == coarse);
  }
  SECTION("the cursor stays on the text after wide characters") {
    Terminal term(ds.dir());
    REQUIRE_SCREEN(term, "villa-000000");
    REQUIRE(term.EditCleared("e"));
    term.Type("日本x");
    REQUIRE_SCREEN(term, "日本x");
    auto lines = term.Lines();
    for (std::size_t y = 0; y < lines.size(); ++y) {
      std::size_t at = lines[y].find("日本x");
      if (at == std::string::npos) continue;
      int column = static_cast<int>(Cells(lines[y].substr(0, at)).size());  // all one column wide
      CHECK(term.CursorY() == static_cast<int>(y));
      CHECK(term.CursorX() == column + 5);  // two wide characters and the x
    }
  }
  SECTION("Esc asks before it throws typed text away") {
    Terminal term(ds.dir());
    REQUIRE_SCREEN(term, "villa-000000");
    REQUIRE(term.EditCleared("e"));
    term.Type("abc");
    term.Keys("Escape");
    REQUIRE_SCREEN(term, "discard");
    term.Keys("n");  // no: go on editing
    term.Type("d");
    term.Keys("Enter");
    REQUIRE_SCREEN(term, "(edited)");
    REQUIRE(term.Quit());
    CHECK(test::OpenSession(ds.dir(), false)->state(0).coarse == "abcd");
  }
  SECTION("violation lines are wrapped, not cut") {
    Terminal term(ds.dir());
    REQUIRE_SCREEN(term, "villa-000000");
    term.Keys("n");
    term.Keys("n");
    term.Keys("n");
    REQUIRE_SCREEN(term, "villa-000003");
    REQUIRE_SCREEN(term, "rule violations");
    auto lines = term.Lines();
    int separator = Separator(lines);
    REQUIRE(separator > 0);
    std::string panel;
    for (const std::string& line : lines) {
      auto cells = Cells(line);
      if (static_cast<int>(cells.size()) > separator) panel += " " + Join(cells, separator + 1, cells.size());
    }
    panel = Squeeze(panel);
    ValidationReport report = ValidateLayout(test::OpenSession(ds.dir(), false)->state(3).layout);
    REQUIRE(report.violations.size() == 2);
    for (const Violation& v : report.violations) {
      INFO(panel);
      CHECK(panel.find(std::to_string(v.rule) + ": " + Squeeze(v.message)) != std::string::npos);
    }
  }
  SECTION("stair treads are not drawn like windows") {
    Terminal term(ds.dir());
    REQUIRE_SCREEN(term, "villa-000000");
    term.Keys("n");
    REQUIRE_SCREEN(term, "villa-000001");
    std::string screen = term.Screen();
    INFO(screen);
    CHECK(screen.find("≡") != std::string::npos);  // treads
    CHECK(screen.find("═") != std::string::npos);  // the kitchen's window on the south wall
  }
}
