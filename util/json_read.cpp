#include "util/json_read.h"

#include <cctype>
#include <unordered_map>

#include "util/excerpt.h"
#include "util/utf8.h"

namespace villa {
namespace {

// 1-based line and column (in bytes) of a byte offset.
std::pair<std::size_t, std::size_t> LineColumn(std::string_view text, std::size_t offset) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') ++line, column = 1;
    else ++column;
  }
  return {line, column};
}

int HexValue(std::string_view text, std::size_t at) {
  if (at + 4 > text.size()) return -1;
  int value = 0;
  for (std::size_t k = at; k < at + 4; ++k) {
    const char c = text[k];
    const int digit = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
    if (digit < 0) return -1;
    value = value * 16 + digit;
  }
  return value;
}

// Reads the string whose opening quote is at `at`; returns the offset past its closing quote (text.size()
// when it never closes) and, when `decoded` is given, its value with the escapes resolved, so that "a" and
// "\u0061" are the same key as the parser sees them.
std::size_t ReadString(std::string_view text, std::size_t at, std::string* decoded) {
  std::size_t i = at + 1;
  while (i < text.size() && text[i] != '"') {
    if (text[i] != '\\') {
      if (decoded) *decoded += text[i];
      ++i;
      continue;
    }
    if (i + 1 >= text.size()) return text.size();
    const char e = text[i + 1];
    if (e != 'u') {
      if (decoded) *decoded += e == 'n' ? '\n' : e == 't' ? '\t' : e == 'r' ? '\r' : e == 'b' ? '\b' : e == 'f' ? '\f' : e;
      i += 2;
      continue;
    }
    int code = HexValue(text, i + 2);
    i += 6;
    if (code < 0) continue;  // malformed: the parser will say so
    if (code >= 0xD800 && code < 0xDC00 && i + 1 < text.size() && text[i] == '\\' && text[i + 1] == 'u') {
      const int low = HexValue(text, i + 2);
      if (low >= 0xDC00 && low < 0xE000) {
        code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
        i += 6;
      }
    }
    if (decoded) *decoded += EncodeUtf8(static_cast<char32_t>(code));
  }
  return std::min(i + 1, text.size());
}

// A key as JSON writes it, cut to an excerpt ("kitchen_0/0" with its quotes); bytes that are not UTF-8
// are shown as U+FFFD rather than failing the message.
std::string Quoted(const std::string& key) {
  return nlohmann::json(Excerpt(key)).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

bool IsIdentifier(std::string_view key) {
  if (key.empty() || std::isdigit(static_cast<unsigned char>(key[0]))) return false;
  for (char c : key)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  return true;
}

// One open container of the scan. Objects remember their keys (a short list, a hash map past 8 keys: most
// objects of a layout have one to three members, a "doors" object may have thousands).
struct Frame {
  bool object = false;
  bool expect_key = false;
  std::size_t index = 0;  // arrays: the element being read
  std::string key;        // objects: the member being read
  std::vector<std::pair<std::string, std::size_t>> few;
  std::unordered_map<std::string, std::size_t> many;

  // The offset where `k` first appeared in this object, or npos (and `k` is remembered at `at`).
  std::size_t Seen(const std::string& k, std::size_t at) {
    if (many.empty()) {
      for (const auto& [name, where] : few)
        if (name == k) return where;
      if (few.size() < 8) {
        few.emplace_back(k, at);
        return std::string::npos;
      }
      for (auto& [name, where] : few) many.emplace(std::move(name), where);
      few.clear();
    }
    auto [it, inserted] = many.emplace(k, at);
    return inserted ? std::string::npos : it->second;
  }
};

// The JSON path of the innermost container: rooms["kitchen_0/0"], messages[2].
std::string PathOf(const std::vector<Frame>& stack) {
  std::string path;
  for (std::size_t d = 0; d + 1 < stack.size(); ++d) {
    const Frame& f = stack[d];
    // Appended piece by piece: GCC 12 warns (-Wrestrict, a false alarm) on "[" + string + "]" here.
    if (f.object && IsIdentifier(f.key) && f.key.size() <= kExcerptLength) {
      if (!path.empty()) path += '.';
      path += f.key;
      continue;
    }
    path += '[';
    path += f.object ? Quoted(f.key) : std::to_string(f.index);
    path += ']';
  }
  return path;
}

std::string Places(std::string_view text, std::size_t first, std::size_t second) {
  const auto [l1, c1] = LineColumn(text, first);
  const auto [l2, c2] = LineColumn(text, second);
  if (l1 != l2) return "on lines " + std::to_string(l1) + " and " + std::to_string(l2);
  const std::string columns = "columns " + std::to_string(c1) + " and " + std::to_string(c2);
  return text.find('\n') == std::string_view::npos ? "at " + columns : "on line " + std::to_string(l1) + ", " + columns;
}

}  // namespace

std::string JsonStructureProblem(std::string_view text, int max_depth, bool duplicate_keys) {
  std::vector<Frame> stack;
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c == '{' || c == '[') {
      if (static_cast<int>(stack.size()) >= max_depth) {
        const auto [line, column] = LineColumn(text, i);
        return "line " + std::to_string(line) + ", column " + std::to_string(column) + ": nested deeper than " +
               std::to_string(max_depth) + " levels";
      }
      Frame frame;
      frame.object = c == '{';
      frame.expect_key = frame.object;
      stack.push_back(std::move(frame));
      ++i;
    } else if (c == '}' || c == ']') {
      if (stack.empty()) return {};  // unbalanced: the parser's to describe
      stack.pop_back();
      ++i;
    } else if (c == ',') {
      if (!stack.empty()) {
        if (stack.back().object) stack.back().expect_key = true;
        else ++stack.back().index;
      }
      ++i;
    } else if (c == '"') {
      if (!duplicate_keys || stack.empty() || !stack.back().object || !stack.back().expect_key) {
        i = ReadString(text, i, nullptr);
        continue;
      }
      Frame& object = stack.back();
      std::string key;
      const std::size_t at = i;
      i = ReadString(text, i, &key);
      object.expect_key = false;
      const std::size_t first = object.Seen(key, at);
      if (first != std::string::npos) {
        const std::string path = PathOf(stack);
        return (path.empty() ? std::string() : path + ": ") + "duplicate key " + Quoted(key) +
               " " + Places(text, first, at);
      }
      object.key = std::move(key);
    } else {
      ++i;
    }
  }
  return {};
}

}  // namespace villa
