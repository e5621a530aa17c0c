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

}  // namespace villa
