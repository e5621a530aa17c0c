#include "util/spelling.h"

namespace villa {

bool OneEditApart(std::string_view a, std::string_view b) {
  if (a == b) return false;
  const std::size_t n = a.size(), m = b.size();
  if (n + 1 < m || m + 1 < n) return false;
  std::size_t i = 0;
  while (i < n && i < m && a[i] == b[i]) ++i;
  if (n == m) {
    if (a.substr(i + 1) == b.substr(i + 1)) return true;  // substituted
    return i + 1 < n && a[i] == b[i + 1] && a[i + 1] == b[i] && a.substr(i + 2) == b.substr(i + 2);  // swapped
  }
  return n < m ? a.substr(i) == b.substr(i + 1)   // a letter left out
               : a.substr(i + 1) == b.substr(i);  // one too many
}

bool MaybeMisspeltNoun(std::string_view word) {
  return word.size() >= 7 && !word.ends_with("ed") && !word.ends_with("ing");
}

std::optional<std::string> OneEditFrom(std::string_view word, const std::vector<std::string>& names) {
  std::optional<std::string> found;
  for (const std::string& name : names) {
    const bool one = OneEditApart(word, name), many = OneEditApart(word, name + "s");
    if (!one && !many) continue;
    if (found) return std::nullopt;  // near two names
    found = many && (!one || word.ends_with('s')) ? name + "s" : name;
  }
  return found;
}

}  // namespace villa
