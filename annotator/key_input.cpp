#include "annotator/key_input.h"

#include <cstdio>
#include <vector>

#include "annotator/utf8.h"

namespace villa::annotator {
namespace {

constexpr unsigned char kEsc = 0x1b;
constexpr std::size_t kMaxSequence = 32;  // longer escape sequences are nobody's key
const std::string kPasteEnd = "\x1b[201~";

// The numbers of a CSI parameter string "1;5" (sub-parameters after ':' dropped); empty fields are 0.
std::vector<int> Parameters(const std::string& text) {
  std::vector<int> out(1, 0);
  bool sub = false;
  for (char c : text) {
    if (c == ';') {
      out.push_back(0);
      sub = false;
    } else if (c == ':') {
      sub = true;
    } else if (c >= '0' && c <= '9' && !sub) {
      out.back() = out.back() * 10 + (c - '0');
      if (out.back() > 1000000) out.back() = 1000000;
    }
  }
  return out;
}

KeyEvent EscapeEvent() {
  KeyEvent e;
  e.kind = KeyKind::kEscape;
  return e;
}

}  // namespace

std::string PrintableBytes(const std::string& bytes) {
  std::string out;
  for (unsigned char c : bytes) {
    if (c == kEsc) {
      out += "ESC";
    } else if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "%s0x%02x", out.empty() ? "" : " ", c);
      out += hex;
    }
  }
  return out;
}

void KeyDecoder::Emit(KeyEvent event) {
  event.alt = event.alt || alt_;
  alt_ = false;
  out_.push_back(std::move(event));
}

void KeyDecoder::EmitChar(char32_t ch) {
  KeyEvent e;
  e.kind = KeyKind::kChar;
  e.ch = ch;
  Emit(std::move(e));
}

void KeyDecoder::EmitKey(Key key, int modifiers) {
  KeyEvent e;
  e.kind = KeyKind::kKey;
  e.key = key;
  int m = modifiers > 1 ? modifiers - 1 : 0;  // xterm: 1 + shift(1) + alt(2) + ctrl(4)
  e.shift = (m & 1) != 0;
  e.alt = (m & 2) != 0;
  e.ctrl = (m & 4) != 0;
  Emit(std::move(e));
}

void KeyDecoder::Ignore(const std::string& what) {
  KeyEvent e;
  e.kind = KeyKind::kIgnored;
  e.text = PrintableBytes(what);
  alt_ = false;
  out_.push_back(std::move(e));
}

void KeyDecoder::Ground(unsigned char byte) {
  state_ = State::kGround;
  sequence_.clear();
  if (byte == kEsc) {
    state_ = State::kEscape;
    sequence_.assign(1, static_cast<char>(kEsc));
  } else if (byte == '\r') {
    EmitKey(Key::kEnter);
  } else if (byte == '\t') {
    EmitKey(Key::kTab);
  } else if (byte == 0x7f || byte == 0x08) {
    EmitKey(Key::kBackspace);
  } else if (byte < 0x80) {
    EmitChar(byte);
  } else if (byte >= 0xC2 && byte <= 0xF4) {
    state_ = State::kUtf8;
    sequence_ = std::string(1, static_cast<char>(byte));
    utf8_need_ = byte <= 0xDF ? 2 : byte <= 0xEF ? 3 : 4;
  } else {
    Ignore(std::string(1, static_cast<char>(byte)));
  }
}

void KeyDecoder::Feed(unsigned char byte) {
  switch (state_) {
    case State::kGround:
      Ground(byte);
      return;
    case State::kEscape:
      if (byte == '[') {
        state_ = State::kCsi;
        sequence_ += '[';
      } else if (byte == 'O') {
        state_ = State::kSs3;
        sequence_ += 'O';
      } else if (byte == kEsc) {
        alt_ = true;  // ESC ESC [D and the like: Alt with a key sent as an escape sequence
      } else {
        alt_ = true;
        Ground(byte);
      }
      return;
    case State::kCsi:
      if (byte == '$' && sequence_.size() > 2 &&
          sequence_.find_first_not_of("0123456789", 2) == std::string::npos) {
        FinishCsi(byte);  // rxvt: ESC [ 2 $ is Shift-Insert; '$' ends the sequence there
      } else if (byte >= 0x20 && byte <= 0x3f) {
        if (sequence_.size() < kMaxSequence + 8) sequence_ += static_cast<char>(byte);
      } else if (byte >= 0x40 && byte <= 0x7e) {
        FinishCsi(byte);
      } else {
        // Not part of any sequence: drop what came so far, read the byte afresh.
        Ignore(sequence_);
        Ground(byte);
      }
      return;
    case State::kSs3:
      if (byte >= 0x40 && byte <= 0x7e) {
        FinishSs3(byte);
      } else {
        Ignore(sequence_);
        Ground(byte);
      }
      return;
    case State::kUtf8:
      if ((byte & 0xC0) == 0x80) {
        sequence_ += static_cast<char>(byte);
        if (sequence_.size() == utf8_need_) {
          auto cps = DecodeUtf8(sequence_);
          state_ = State::kGround;
          if (cps.size() == 1 && cps[0] != 0xFFFD)
            EmitChar(cps[0]);
          else
            Ignore(sequence_);
          sequence_.clear();
        }
      } else {
        Ignore(sequence_);
        Ground(byte);
      }
      return;
    case State::kPaste:
      paste_ += static_cast<char>(byte);
      if (paste_.size() >= kPasteEnd.size() && paste_.compare(paste_.size() - kPasteEnd.size(), kPasteEnd.size(), kPasteEnd) == 0) {
        paste_.resize(paste_.size() - kPasteEnd.size());
        FinishPaste();
      } else if (paste_.size() > kMaxPaste + 64) {
        // Keep watching for the end marker without keeping the text.
        paste_.erase(kMaxPaste, paste_.size() - kMaxPaste - 16);
        paste_cut_ = true;
      }
      return;
  }
}

void KeyDecoder::FinishCsi(unsigned char final_byte) {
  std::string params = sequence_.substr(2);
  std::string whole = sequence_ + static_cast<char>(final_byte);
  state_ = State::kGround;
  sequence_.clear();
  bool private_marker = !params.empty() && (params[0] == '<' || params[0] == '=' || params[0] == '>' || params[0] == '?');
  bool intermediate = params.find_first_of(" !\"#$%&'()*+,-./") != std::string::npos;
  if (whole.size() > kMaxSequence || private_marker || intermediate) {
    Ignore(whole);
    return;
  }
  std::vector<int> p = Parameters(params);
  int modifiers = p.size() > 1 ? p[1] : 1;
  // rxvt ends modified editing keys with $ (Shift), ^ (Ctrl) or @ (Ctrl-Shift) instead of ~.
  if (final_byte == '$' || final_byte == '^' || final_byte == '@') {
    modifiers = final_byte == '$' ? 2 : final_byte == '^' ? 5 : 6;
    final_byte = '~';
  }
  switch (final_byte) {
    case 'A': EmitKey(Key::kUp, modifiers); return;
    case 'B': EmitKey(Key::kDown, modifiers); return;
    case 'C': EmitKey(Key::kRight, modifiers); return;
    case 'D': EmitKey(Key::kLeft, modifiers); return;
    case 'H': EmitKey(Key::kHome, modifiers); return;
    case 'F': EmitKey(Key::kEnd, modifiers); return;
    case 'Z': EmitKey(Key::kBackTab, modifiers); return;
    case 'P': case 'Q': case 'R': case 'S': EmitKey(Key::kFunction, modifiers); return;
    case '~':
      switch (p[0]) {
        case 1: case 7: EmitKey(Key::kHome, modifiers); return;
        case 2: EmitKey(Key::kInsert, modifiers); return;
        case 3: EmitKey(Key::kDelete, modifiers); return;
        case 4: case 8: EmitKey(Key::kEnd, modifiers); return;
        case 5: EmitKey(Key::kPageUp, modifiers); return;
        case 6: EmitKey(Key::kPageDown, modifiers); return;
        case 200:
          state_ = State::kPaste;
          paste_.clear();
          paste_cut_ = false;
          alt_ = false;
          return;
        default:
          if ((p[0] >= 11 && p[0] <= 15) || (p[0] >= 17 && p[0] <= 21) || (p[0] >= 23 && p[0] <= 26) ||
              p[0] == 28 || p[0] == 29 || (p[0] >= 31 && p[0] <= 34)) {
            EmitKey(Key::kFunction, modifiers);
            return;
          }
          Ignore(whole);
          return;
      }
    case 'u': {  // CSI code ; modifiers u (the "fixterms" / kitty keyboard encoding)
      char32_t code = static_cast<char32_t>(p[0]);
      int m = modifiers > 1 ? modifiers - 1 : 0;
      if (code == 13) { EmitKey(Key::kEnter, modifiers); return; }
      if (code == 9) { EmitKey(Key::kTab, modifiers); return; }
      if (code == 127 || code == 8) { EmitKey(Key::kBackspace, modifiers); return; }
      if (code == 27) { Emit(EscapeEvent()); return; }
      if (code < 0x20 || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) { Ignore(whole); return; }
      if ((m & 4) && code >= 'a' && code <= 'z') code = code - 'a' + 1;  // Ctrl-letter: its control code
      KeyEvent e;
      e.kind = KeyKind::kChar;
      e.ch = code;
      e.alt = (m & 2) != 0;
      e.ctrl = (m & 4) != 0;
      Emit(std::move(e));
      return;
    }
    default:
      Ignore(whole);
      return;
  }
}

void KeyDecoder::FinishSs3(unsigned char final_byte) {
  std::string whole = sequence_ + static_cast<char>(final_byte);
  state_ = State::kGround;
  sequence_.clear();
  switch (final_byte) {
    case 'A': EmitKey(Key::kUp); return;
    case 'B': EmitKey(Key::kDown); return;
    case 'C': EmitKey(Key::kRight); return;
    case 'D': EmitKey(Key::kLeft); return;
    case 'H': EmitKey(Key::kHome); return;
    case 'F': EmitKey(Key::kEnd); return;
    case 'M': EmitKey(Key::kEnter); return;
    case 'P': case 'Q': case 'R': case 'S': EmitKey(Key::kFunction); return;
    default:
      // The application keypad: ESC O p .. y are 0 .. 9, j k l m n o are * + , - . /
      if (final_byte >= 'p' && final_byte <= 'y') {
        EmitChar(static_cast<char32_t>('0' + (final_byte - 'p')));
        return;
      }
      if (final_byte >= 'j' && final_byte <= 'o') {
        EmitChar(static_cast<char32_t>("*+,-./"[final_byte - 'j']));
        return;
      }
      Ignore(whole);
      return;
  }
}

void KeyDecoder::FinishPaste() {
  state_ = State::kGround;
  std::string text;
  auto cps = DecodeUtf8(paste_);
  for (std::size_t i = 0; i < cps.size(); ++i) {
    char32_t c = cps[i];
    if (c == '\r') {
      text += '\n';
      if (i + 1 < cps.size() && cps[i + 1] == '\n') ++i;
    } else if (c == '\n') {
      text += '\n';
    } else if (c == '\t') {
      text += ' ';
    } else if (c == 0xFFFD || c < 0x20 || c == 0x7f || (c >= 0x80 && c < 0xA0)) {
      continue;  // invalid bytes and control characters are no text
    } else {
      text += EncodeUtf8(c);
    }
  }
  paste_.clear();
  KeyEvent e;
  e.kind = KeyKind::kPaste;
  e.text = std::move(text);
  alt_ = false;
  out_.push_back(std::move(e));
  if (paste_cut_) Ignore("paste cut at 1 MiB");
  paste_cut_ = false;
}

void KeyDecoder::Timeout() {
  switch (state_) {
    case State::kGround:
      return;
    case State::kEscape:
      state_ = State::kGround;
      sequence_.clear();
      alt_ = false;
      Emit(EscapeEvent());
      return;
    case State::kCsi:
    case State::kSs3: {
      // Alt-[ and Alt-O look like the start of a sequence until nothing follows.
      bool alone = sequence_.size() == 2;
      char32_t ch = static_cast<unsigned char>(sequence_[1]);
      std::string what = sequence_;
      state_ = State::kGround;
      sequence_.clear();
      if (alone) {
        alt_ = true;
        EmitChar(ch);
      } else {
        Ignore(what);
      }
      return;
    }
    case State::kUtf8: {
      std::string what = sequence_;
      state_ = State::kGround;
      sequence_.clear();
      Ignore(what);
      return;
    }
    case State::kPaste:
      FinishPaste();
      return;
  }
}

int KeyDecoder::WaitMs() const {
  switch (state_) {
    case State::kGround: return -1;
    case State::kPaste: return kPasteStallMs;
    default: return kEscapeDelayMs;
  }
}

bool KeyDecoder::Next(KeyEvent* event) {
  if (out_.empty()) return false;
  *event = std::move(out_.front());
  out_.pop_front();
  return true;
}

}  // namespace villa::annotator
