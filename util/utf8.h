#pragma once
// UTF-8 encoding of one code point, shared by the JSON reader (escaped keys) and the annotator's text.
#include <string>

namespace villa {

// The UTF-8 bytes of `code_point`; a surrogate or a value past U+10FFFF becomes U+FFFD.
std::string EncodeUtf8(char32_t code_point);

}  // namespace villa
