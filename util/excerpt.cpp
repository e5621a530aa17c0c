#include "util/excerpt.h"

#include <algorithm>

namespace villa {

std::string Excerpt(std::string_view text, std::size_t limit) {
  limit = std::max<std::size_t>(limit, 4);
  if (text.size() <= limit) return std::string(text);
  std::size_t keep = limit - 3;
  // Step back over UTF-8 continuation bytes (10xxxxxx) so the cut falls before a character's lead byte.
  while (keep > 0 && (static_cast<unsigned char>(text[keep]) & 0xC0) == 0x80) --keep;
  return std::string(text.substr(0, keep)) + "...";
}

}  // namespace villa
