#include "assets/java_properties.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace villa {
namespace {

bool IsBlank(char c) { return c == ' ' || c == '\t' || c == '\f'; }

void AppendUtf8(std::string* out, std::uint32_t cp) {
  if (cp < 0x80) {
    out->push_back(static_cast<char>(cp));
  } else if (cp < 0x800) {
    out->push_back(static_cast<char>(0xC0 | (cp >> 6)));
    out->push_back(static_cast<char>(0x80 | (cp & 0x3F)));
  } else if (cp < 0x10000) {
    out->push_back(static_cast<char>(0xE0 | (cp >> 12)));
    out->push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F)));
    out->push_back(static_cast<char>(0x80 | (cp & 0x3F)));
  } else {
    out->push_back(static_cast<char>(0xF0 | (cp >> 18)));
    out->push_back(static_cast<char>(0x80 | ((cp >> 12) & 0x3F)));
    out->push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F)));
    out->push_back(static_cast<char>(0x80 | (cp & 0x3F)));
  }
}

// Turns the escaped Latin-1 text of a key or a value into UTF-8, joining UTF-16 surrogate pairs written
// as two \u escapes. An unpaired surrogate becomes U+FFFD (it has no UTF-8 form).
class Unescaper {
 public:
  explicit Unescaper(std::string* out) : out_(out) {}
  void CodeUnit(std::uint32_t unit) {
    if (pending_high_ != 0) {
      std::uint32_t high = pending_high_;
      pending_high_ = 0;
      if (unit >= 0xDC00 && unit <= 0xDFFF) {
        AppendUtf8(out_, 0x10000 + ((high - 0xD800) << 10) + (unit - 0xDC00));
        return;
      }
      AppendUtf8(out_, 0xFFFD);
    }
    if (unit >= 0xD800 && unit <= 0xDBFF) {
      pending_high_ = unit;
    } else if (unit >= 0xDC00 && unit <= 0xDFFF) {
      AppendUtf8(out_, 0xFFFD);
    } else {
      AppendUtf8(out_, unit);
    }
  }
  void Finish() {
    if (pending_high_ != 0) AppendUtf8(out_, 0xFFFD);
    pending_high_ = 0;
  }

 private:
  std::string* out_;
  std::uint32_t pending_high_ = 0;  // a high surrogate waiting for its low half; 0 = none
};

int HexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

struct LogicalLine {
  std::string text;  // Latin-1, continuations joined
  int line = 0;      // 1-based number of its first natural line
};

std::vector<LogicalLine> LogicalLines(std::string_view text) {
  std::vector<LogicalLine> out;
  std::size_t at = 0;
  int line = 0;
  bool continuing = false;
  while (at < text.size()) {
    std::size_t end = at;
    while (end < text.size() && text[end] != '\n' && text[end] != '\r') ++end;
    std::string_view natural = text.substr(at, end - at);
    ++line;
    at = end;
    if (at < text.size() && text[at] == '\r') {
      ++at;
      if (at < text.size() && text[at] == '\n') ++at;  // CRLF
    } else if (at < text.size()) {
      ++at;  // LF
    }
    std::size_t first = 0;
    while (first < natural.size() && IsBlank(natural[first])) ++first;
    natural.remove_prefix(first);
    if (!continuing) {
      if (natural.empty() || natural.front() == '#' || natural.front() == '!') continue;
      out.push_back({"", line});
    }
    std::size_t backslashes = 0;
    while (backslashes < natural.size() && natural[natural.size() - 1 - backslashes] == '\\') ++backslashes;
    continuing = backslashes % 2 == 1;
    if (continuing) natural.remove_suffix(1);
    out.back().text.append(natural);
  }
  return out;
}

// Unescapes `s` (Latin-1) into UTF-8; false with `*bad` set at a malformed \uXXXX.
bool Unescape(std::string_view s, std::string* out, std::string* bad) {
  Unescaper unescape(out);
  for (std::size_t i = 0; i < s.size(); ++i) {
    char c = s[i];
    if (c != '\\') {
      unescape.CodeUnit(static_cast<unsigned char>(c));
      continue;
    }
    if (++i >= s.size()) break;  // a lone backslash at the very end escapes nothing
    switch (s[i]) {
      case 't': unescape.CodeUnit('\t'); break;
      case 'n': unescape.CodeUnit('\n'); break;
      case 'r': unescape.CodeUnit('\r'); break;
      case 'f': unescape.CodeUnit('\f'); break;
      case 'u': {
        std::uint32_t unit = 0;
        for (std::size_t k = 1; k <= 4; ++k) {
          int d = i + k < s.size() ? HexDigit(s[i + k]) : -1;
          if (d < 0) {
            bad->assign(1, '\\');
            bad->append(s.substr(i, std::min<std::size_t>(5, s.size() - i)));
            return false;
          }
          unit = unit * 16 + static_cast<std::uint32_t>(d);
        }
        unescape.CodeUnit(unit);
        i += 4;
        break;
      }
      default: unescape.CodeUnit(static_cast<unsigned char>(s[i]));
    }
  }
  unescape.Finish();
  return true;
}

// Where the key of a logical line ends: the first unescaped '=', ':' or blank.
std::size_t KeyEnd(std::string_view s) {
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '\\') {
      ++i;
      continue;
    }
    if (s[i] == '=' || s[i] == ':' || IsBlank(s[i])) return i;
  }
  return s.size();
}

}  // namespace

Result<JavaProperties> ParseJavaProperties(std::string_view latin1, const std::string& where) {
  JavaProperties properties;
  for (const LogicalLine& logical : LogicalLines(latin1)) {
    std::string_view s = logical.text;
    std::size_t end = KeyEnd(s);
    // After the key: blanks, at most one '=' or ':', blanks; the value is the rest.
    std::size_t at = end;
    while (at < s.size() && IsBlank(s[at])) ++at;
    if (at < s.size() && (s[at] == '=' || s[at] == ':')) ++at;
    while (at < s.size() && IsBlank(s[at])) ++at;
    std::string key, value, bad;
    if (!Unescape(s.substr(0, end), &key, &bad) || !Unescape(s.substr(at), &value, &bad))
      return Error{where + ":" + std::to_string(logical.line) + ": malformed \\uXXXX escape: " + bad};
    properties[std::move(key)] = std::move(value);
  }
  return properties;
}

}  // namespace villa
