#pragma once
// Misspellings of known words, for readers of requests written by people ("dishwaser", "wardorbe").
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace villa {

// True when `a` and `b` differ by exactly one edit: a letter changed, left out or added, or two
// neighbouring letters swapped ("wardorbe" / "wardrobe").
bool OneEditApart(std::string_view a, std::string_view b);

// Whether a word that names nothing may be read as a misspelt noun: seven letters or more, and no verb
// form ("dressed" is no dresser, "starting" no starter).
bool MaybeMisspeltNoun(std::string_view word);

// The one of `names` that `word` is one edit from, or whose plural (name + "s") it is one edit from, as
// `word` means it: the plural where only the plural is that near, or both are and `word` ends in "s"
// ("bookcaes": bookcases); nullopt when none or more than one name is that near.
std::optional<std::string> OneEditFrom(std::string_view word, const std::vector<std::string>& names);

}  // namespace villa
