#pragma once
// Misspellings of known words, for readers of requests written by people ("dishwaser", "wardorbe").
#include <string_view>

namespace villa {

// True when `a` and `b` differ by exactly one edit: a letter changed, left out or added, or two
// neighbouring letters swapped ("wardorbe" / "wardrobe").
bool OneEditApart(std::string_view a, std::string_view b);

}  // namespace villa
