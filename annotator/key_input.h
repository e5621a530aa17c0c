#pragma once
// Terminal input as the annotator reads it: raw bytes in, key events out. The terminal's own key tables
// (terminfo) are not trusted, because the tool runs under terminals and multiplexers that send keys
// their tables do not list; instead this decoder knows the sequences terminals actually send (xterm,
// VT220, rxvt, tmux/screen, kitty's CSI u) and turns everything else into an `ignored` event, so that:
// - a byte that is not UTF-8 is dropped, never allowed to stall what follows (a lone 0xff, Latin-1 text
//   typed into a UTF-8 session);
// - Esc followed by a key within the escape delay is that key with Alt, never Esc and then the key;
// - an escape sequence it does not know is swallowed whole, never run as the keys it is made of;
// - a bracketed paste (ESC[200~ ... ESC[201~) is one `paste` event, its newlines text.
// No curses here: the TUI feeds bytes and asks for events, so the decoder is unit-tested.
#include <cstdint>
#include <deque>
#include <string>

namespace villa::annotator {

enum class KeyKind {
  kChar,     // a code point (`ch`); control characters too (Ctrl-A = 1), Tab, Enter and Backspace are keys
  kKey,      // a named key (`key`)
  kPaste,    // a bracketed paste (`text`, UTF-8, line ends as '\n')
  kEscape,   // Esc on its own
  kIgnored,  // bytes that are no key: invalid UTF-8, an unknown sequence (`text` says what, for a message)
};

enum class Key {
  kNone,
  kUp, kDown, kLeft, kRight,
  kHome, kEnd, kPageUp, kPageDown, kInsert, kDelete,
  kTab, kBackTab, kEnter, kBackspace,
  kFunction,  // F1-F20: no action of the annotator; recognised so they are not read as text
};

struct KeyEvent {
  KeyKind kind = KeyKind::kIgnored;
  char32_t ch = 0;
  Key key = Key::kNone;
  bool alt = false;
  bool ctrl = false;
  bool shift = false;
  std::string text;
};

class KeyDecoder {
 public:
  // One byte from the terminal.
  void Feed(unsigned char byte);
  // Nothing arrived for WaitMs() milliseconds: an Esc waiting for its key is Esc, a sequence or UTF-8
  // character cut short is dropped, a paste whose end never came is delivered as it stands.
  void Timeout();
  // How long to wait for the next byte before calling Timeout(): -1 when no byte is held back.
  int WaitMs() const;
  // The next complete event, if any.
  bool Next(KeyEvent* event);

  static constexpr int kEscapeDelayMs = 40;     // Esc vs. Alt-key and escape sequences
  static constexpr int kPasteStallMs = 1000;    // a paste that stops without its end marker
  static constexpr std::size_t kMaxPaste = 1 << 20;  // bytes; beyond this a paste is cut (and says so)

 private:
  enum class State { kGround, kEscape, kCsi, kSs3, kUtf8, kPaste };
  void Ground(unsigned char byte);
  void FinishCsi(unsigned char final_byte);
  void FinishSs3(unsigned char final_byte);
  void FinishPaste();
  void Emit(KeyEvent event);
  void EmitChar(char32_t ch);
  void EmitKey(Key key, int modifiers = 1);
  void Ignore(const std::string& what);

  State state_ = State::kGround;
  bool alt_ = false;            // the event being decoded follows an Esc
  std::string sequence_;        // bytes of the escape sequence or UTF-8 character so far
  std::size_t utf8_need_ = 0;   // bytes the UTF-8 character needs in all
  std::string paste_;
  bool paste_cut_ = false;
  std::deque<KeyEvent> out_;
};

// "ESC[99~", "0xff": the bytes of an ignored sequence, printable, for a status line.
std::string PrintableBytes(const std::string& bytes);

}  // namespace villa::annotator
