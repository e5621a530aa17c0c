#include "annotator/utf8.h"

#include <cwchar>

namespace villa::annotator {
namespace {

constexpr char32_t kReplacement = 0xFFFD;

// Decodes one code point at text[i]; `length` gets the bytes used (1 for an invalid byte).
char32_t DecodeAt(std::string_view text, std::size_t i, std::size_t* length) {
  auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  unsigned char lead = byte(i);
  *length = 1;
  if (lead < 0x80) return lead;
  std::size_t n = lead >= 0xC2 && lead <= 0xDF ? 2 : lead >= 0xE0 && lead <= 0xEF ? 3 : lead >= 0xF0 && lead <= 0xF4 ? 4 : 0;
  if (n == 0 || i + n > text.size()) return kReplacement;
  char32_t cp = lead & (0x7F >> n);
  for (std::size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return kReplacement;
    cp = (cp << 6) | (byte(i + k) & 0x3F);
  }
  // Overlong forms, surrogates and code points past U+10FFFF are not UTF-8.
  static const char32_t kMinimum[] = {0, 0, 0x80, 0x800, 0x10000};
  if (cp < kMinimum[n] || (cp >= 0xD800 && cp <= 0xDFFF) || cp > 0x10FFFF) return kReplacement;
  *length = n;
  return cp;
}

}  // namespace

std::vector<char32_t> DecodeUtf8(std::string_view text) {
  std::vector<char32_t> out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    std::size_t n = 1;
    out.push_back(DecodeAt(text, i, &n));
    i += n;
  }
  return out;
}

std::string EncodeUtf8(const std::vector<char32_t>& code_points) {
  std::string out;
  for (char32_t cp : code_points) out += EncodeUtf8(cp);
  return out;
}

std::vector<std::string> Utf8Glyphs(std::string_view text) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < text.size();) {
    std::size_t n = 1;
    DecodeAt(text, i, &n);
    out.emplace_back(text.substr(i, n));
    i += n;
  }
  return out;
}

int CodePointWidth(char32_t cp) {
  if (cp < 0x20 || cp == 0x7F) return 0;
  if (cp < 0x7F) return 1;
  int w = ::wcwidth(static_cast<wchar_t>(cp));
  return w < 0 ? 1 : w;  // unknown to this locale: the terminal draws a one-column placeholder
}

int TextWidth(std::string_view text) {
  int width = 0;
  for (char32_t cp : DecodeUtf8(text)) width += CodePointWidth(cp);
  return width;
}

std::string ClipToWidth(std::string_view text, int width) {
  if (width <= 0) return "";
  int used = 0;
  for (std::size_t i = 0; i < text.size();) {
    std::size_t n = 1;
    char32_t cp = DecodeAt(text, i, &n);
    int w = CodePointWidth(cp);
    if (used + w > width) return std::string(text.substr(0, i));
    used += w;
    i += n;
  }
  return std::string(text);
}

std::string PadToWidth(std::string_view text, int width) {
  std::string out = ClipToWidth(text, width);
  int used = TextWidth(out);
  return used < width ? out + std::string(static_cast<std::size_t>(width - used), ' ') : out;
}

std::string AsciiOnly(std::string_view text) {
  std::string out;
  for (char32_t cp : DecodeUtf8(text)) {
    if (cp < 0x80)
      out += static_cast<char>(cp);
    else if (CodePointWidth(cp) > 0)
      out += '?';
  }
  return out;
}

}  // namespace villa::annotator
