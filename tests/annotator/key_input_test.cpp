// The key decoder: bytes a terminal sends in, key events out. Every way input can be odd (bytes that are
// not UTF-8, Alt-keys, escape sequences known and unknown, bracketed pastes, a lone Esc) gives a
// definite event and never holds back what follows.
#include <catch2/catch.hpp>

#include "annotator/key_input.h"

using namespace villa::annotator;

namespace {

// Feeds `bytes`; with `pause`, the escape delay then passes. Returns every event.
std::vector<KeyEvent> Decode(const std::string& bytes, bool pause = true) {
  KeyDecoder d;
  for (unsigned char c : bytes) d.Feed(c);
  if (pause && d.WaitMs() >= 0) d.Timeout();
  std::vector<KeyEvent> out;
  KeyEvent e;
  while (d.Next(&e)) out.push_back(e);
  return out;
}

bool IsChar(const KeyEvent& e, char32_t ch, bool alt = false) {
  return e.kind == KeyKind::kChar && e.ch == ch && e.alt == alt;
}
bool IsKey(const KeyEvent& e, Key key, bool ctrl = false, bool alt = false) {
  return e.kind == KeyKind::kKey && e.key == key && e.ctrl == ctrl && e.alt == alt;
}

}  // namespace

TEST_CASE("plain keys: characters, Enter, Tab, Backspace, control characters", "[keys]") {
  auto e = Decode("a1 \r\t\x7f\x08\x15\n");
  REQUIRE(e.size() == 9);
  CHECK(IsChar(e[0], 'a'));
  CHECK(IsChar(e[1], '1'));
  CHECK(IsChar(e[2], ' '));
  CHECK(IsKey(e[3], Key::kEnter));
  CHECK(IsKey(e[4], Key::kTab));
  CHECK(IsKey(e[5], Key::kBackspace));
  CHECK(IsKey(e[6], Key::kBackspace));
  CHECK(IsChar(e[7], 0x15));  // Ctrl-U
  CHECK(IsChar(e[8], '\n'));  // Ctrl-J
}

TEST_CASE("UTF-8 is decoded, and a byte that is not UTF-8 is dropped and never holds back the next key", "[keys]") {
  auto e = Decode("\xc3\xa9\xe6\x97\xa5\xf0\x9f\x8f\xa0");
  REQUIRE(e.size() == 3);
  CHECK(IsChar(e[0], 0xE9));
  CHECK(IsChar(e[1], 0x65E5));
  CHECK(IsChar(e[2], 0x1F3E0));

  for (const char* bad : {"\xff", "\x80", "\xc0", "\xf5"}) {
    auto d = Decode(std::string(bad) + "q", false);
    REQUIRE(d.size() == 2);
    CHECK(d[0].kind == KeyKind::kIgnored);
    CHECK(IsChar(d[1], 'q'));
  }
  CHECK(Decode("\xff", false)[0].text == "0xff");
  // A lead byte without its continuation (Latin-1 é in a UTF-8 session): dropped, the next key kept.
  auto latin = Decode("\xe9q", false);
  REQUIRE(latin.size() == 2);
  CHECK(latin[0].kind == KeyKind::kIgnored);
  CHECK(IsChar(latin[1], 'q'));
  auto two = Decode("\xc3q", false);
  REQUIRE(two.size() == 2);
  CHECK(IsChar(two[1], 'q'));
  // Overlong and surrogate forms are not UTF-8 either.
  CHECK(Decode("\xe0\x80\xaf", false)[0].kind == KeyKind::kIgnored);
  CHECK(Decode("\xed\xa0\x80", false)[0].kind == KeyKind::kIgnored);
  // A character cut short by a pause: dropped once the delay is over.
  KeyDecoder d;
  d.Feed(0xe2);
  d.Feed(0x82);
  KeyEvent ev;
  CHECK(!d.Next(&ev));
  CHECK(d.WaitMs() == KeyDecoder::kEscapeDelayMs);
  d.Timeout();
  REQUIRE(d.Next(&ev));
  CHECK(ev.kind == KeyKind::kIgnored);
  CHECK(d.WaitMs() == -1);
}

TEST_CASE("Esc alone, and Esc with a key as Alt-key", "[keys]") {
  auto esc = Decode("\x1b");
  REQUIRE(esc.size() == 1);
  CHECK(esc[0].kind == KeyKind::kEscape);
  auto alt = Decode("\x1b" "b");
  REQUIRE(alt.size() == 1);
  CHECK(IsChar(alt[0], 'b', true));
  auto alt_enter = Decode("\x1b\r");
  REQUIRE(alt_enter.size() == 1);
  CHECK(IsKey(alt_enter[0], Key::kEnter, false, true));
  auto alt_utf8 = Decode("\x1b\xc3\xa9");
  REQUIRE(alt_utf8.size() == 1);
  CHECK(IsChar(alt_utf8[0], 0xE9, true));
  // Alt-[ and Alt-O look like the start of a sequence until the delay passes.
  CHECK(IsChar(Decode("\x1b[")[0], '[', true));
  CHECK(IsChar(Decode("\x1bO")[0], 'O', true));
  // Esc Esc [ D: Alt-Left from terminals that send Alt as a second Esc.
  auto alt_left = Decode("\x1b\x1b[D");
  REQUIRE(alt_left.size() == 1);
  CHECK(IsKey(alt_left[0], Key::kLeft, false, true));
}

TEST_CASE("escape sequences: the keys terminals send, and unknown ones swallowed whole", "[keys]") {
  struct Case {
    const char* bytes;
    Key key;
    bool ctrl;
    bool alt;
  };
  const Case cases[] = {
      {"\x1b[A", Key::kUp, false, false},         {"\x1bOB", Key::kDown, false, false},
      {"\x1b[1;5C", Key::kRight, true, false},    {"\x1b[1;3D", Key::kLeft, false, true},
      {"\x1b[H", Key::kHome, false, false},       {"\x1b[1~", Key::kHome, false, false},
      {"\x1b[7~", Key::kHome, false, false},      {"\x1bOH", Key::kHome, false, false},
      {"\x1b[F", Key::kEnd, false, false},        {"\x1b[4~", Key::kEnd, false, false},
      {"\x1b[8~", Key::kEnd, false, false},       {"\x1bOF", Key::kEnd, false, false},
      {"\x1b[3~", Key::kDelete, false, false},    {"\x1b[3;5~", Key::kDelete, true, false},
      {"\x1b[2~", Key::kInsert, false, false},    {"\x1b[5~", Key::kPageUp, false, false},
      {"\x1b[6~", Key::kPageDown, false, false},  {"\x1b[Z", Key::kBackTab, false, false},
      {"\x1bOP", Key::kFunction, false, false},   {"\x1b[15~", Key::kFunction, false, false},
      {"\x1b[1;5Q", Key::kFunction, true, false}, {"\x1bOM", Key::kEnter, false, false},
      {"\x1b[13;3u", Key::kEnter, false, true},  {"\x1b[3^", Key::kDelete, true, false},
      {"\x1b[7$", Key::kHome, false, false},
  };
  for (const Case& c : cases) {
    INFO(PrintableBytes(c.bytes));
    auto e = Decode(std::string(c.bytes) + "x", false);
    REQUIRE(e.size() == 2);
    CHECK(IsKey(e[0], c.key, c.ctrl, c.alt));
    CHECK(IsChar(e[1], 'x'));
  }
  // kitty / fixterms: a character with modifiers.
  auto alt_a = Decode("\x1b[97;3u", false);
  REQUIRE(alt_a.size() == 1);
  CHECK(IsChar(alt_a[0], 'a', true));
  auto ctrl_w = Decode("\x1b[119;5u", false);
  REQUIRE(ctrl_w.size() == 1);
  CHECK(ctrl_w[0].ch == 23);
  // Unknown sequences: one ignored event naming the bytes, nothing else; the next key is whole.
  for (const char* unknown : {"\x1b[99~", "\x1b[<0;12;3M", "\x1b[?1;2c", "\x1bOz", "\x1b[12;34;56;78;90;12;34;56;78;90;1X"}) {
    INFO(PrintableBytes(unknown));
    auto e = Decode(std::string(unknown) + "q", false);
    REQUIRE(e.size() == 2);
    CHECK(e[0].kind == KeyKind::kIgnored);
    CHECK(IsChar(e[1], 'q'));
  }
  CHECK(Decode("\x1b[99~", false)[0].text == "ESC[99~");
  // A sequence broken by a control byte: dropped, the byte read afresh.
  auto broken = Decode("\x1b[1\r", false);
  REQUIRE(broken.size() == 2);
  CHECK(broken[0].kind == KeyKind::kIgnored);
  CHECK(IsKey(broken[1], Key::kEnter));
}

TEST_CASE("a bracketed paste is one event, its line ends text", "[keys]") {
  auto e = Decode("\x1b[200~A house.\rbn\r\nx\ty\xff\x1b[201~q", false);
  REQUIRE(e.size() == 2);
  CHECK(e[0].kind == KeyKind::kPaste);
  CHECK(e[0].text == "A house.\nbn\nx y");
  CHECK(IsChar(e[1], 'q'));
  // Escape sequences inside a paste are its text's problem, not keys.
  auto inside = Decode("\x1b[200~a\x1b[Ab\x1b[201~", false);
  REQUIRE(inside.size() == 1);
  CHECK(inside[0].kind == KeyKind::kPaste);
  CHECK(inside[0].text == "a[Ab");
  // A paste whose end never comes is delivered when the input stalls.
  KeyDecoder d;
  for (unsigned char c : std::string("\x1b[200~half")) d.Feed(c);
  KeyEvent ev;
  CHECK(!d.Next(&ev));
  CHECK(d.WaitMs() == KeyDecoder::kPasteStallMs);
  d.Timeout();
  REQUIRE(d.Next(&ev));
  CHECK(ev.kind == KeyKind::kPaste);
  CHECK(ev.text == "half");
  // A stray end marker is no key.
  auto stray = Decode("\x1b[201~q", false);
  REQUIRE(stray.size() == 2);
  CHECK(stray[0].kind == KeyKind::kIgnored);
}
