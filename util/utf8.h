#pragma once
// UTF-8 encoding of one code point, shared by the JSON reader (escaped keys) and the annotator's text.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace villa {

// The UTF-8 bytes of `code_point`; a surrogate or a value past U+10FFFF becomes U+FFFD.
std::string EncodeUtf8(char32_t code_point);

// The offset of the first byte that does not begin a well-formed UTF-8 sequence (overlong forms,
// surrogates and values past U+10FFFF are ill-formed), or nothing when all of `text` is UTF-8.
std::optional<std::size_t> FirstInvalidUtf8(std::string_view text);

// What is wrong with a request's text, or "" (issue 33): not UTF-8 ("not UTF-8 at byte 7"), longer than
// kMaxRequestBytes (a request is a paragraph; a 3 MB one ran past a minute), or without a single letter
// (only control bytes, digits or punctuation: nothing to read).
inline constexpr std::size_t kMaxRequestBytes = 16384;
std::string RequestTextProblem(std::string_view text);

}  // namespace villa
