#include "assets/category_phrase.h"

#include <cctype>
#include <set>
#include <string>
#include <vector>

namespace villa {
namespace {

struct Word {
  std::string lower;    // lowercase
  bool capitalised;     // starts with an upper-case letter in the catalog ("Chambord", "BZ")
  bool numeric;         // starts with a digit ("2", "16:9", "1998")
};

// The words of a name; apostrophes stay inside words ("captain's"), everything else separates them.
std::vector<Word> Words(const std::string& text) {
  std::vector<Word> out;
  std::string current;
  bool capital = false;
  auto flush = [&] {
    if (!current.empty()) out.push_back({current, capital, std::isdigit(static_cast<unsigned char>(current[0])) != 0});
    current.clear();
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(text[i]);
    bool separator = c == ',' || c == ';' || c == '(' || c == ')';
    if (std::isalnum(c) || (c == '\'' && !current.empty()) || c >= 0x80) {
      if (current.empty()) capital = std::isupper(c) != 0;
      current.push_back(static_cast<char>(std::tolower(c)));
    } else {
      flush();
      if (separator) out.push_back({",", false, false});
    }
  }
  flush();
  return out;
}

std::string Join(const std::vector<Word>& words, std::size_t begin, std::size_t end) {
  std::string out;
  for (std::size_t i = begin; i < end; ++i) out += (out.empty() ? "" : " ") + words[i].lower;
  return out;
}

// The first segment of a name: up to a comma, a joining word ("Chair with cushion", "Plate, glass and
// cutlery", "Table on trestles") or a number ("Sofa 2 seats", "TV 16:9", "Concept Sedan 01").
std::vector<Word> FirstSegment(const std::vector<Word>& words) {
  static const std::set<std::string> kJoins = {",", "with", "and", "on", "for", "in", "of", "&"};
  std::vector<Word> out;
  for (const Word& w : words) {
    if (kJoins.count(w.lower) || (w.numeric && !out.empty())) break;
    out.push_back(w);
  }
  return out;
}

// English compounds put the head last ("coffee table" is a table, "toilet brush" a brush): try the
// phrases that end at the last word, longest first.
const CategoryInfo* HeadCategory(const std::vector<Word>& words) {
  for (std::size_t begin = 0; begin < words.size(); ++begin)
    if (const CategoryInfo* c = CategoryForWord(Join(words, begin, words.size()))) return c;
  return nullptr;
}

}  // namespace

const CategoryInfo* CategoryInPhrase(std::string_view phrase) {
  std::vector<Word> words = Words(std::string(phrase));
  // Leading articles name nothing ("a stack of books").
  static const std::set<std::string> kArticles = {"a", "an", "the", "some"};
  while (!words.empty() && kArticles.count(words.front().lower)) words.erase(words.begin());
  if (const CategoryInfo* c = CategoryForWord(Join(words, 0, words.size()))) return c;
  std::vector<Word> segment = FirstSegment(words);
  if (const CategoryInfo* c = HeadCategory(segment)) return c;
  // Trailing proper nouns and brands ("Frame Chambord", "Convertible sofa BZ") are not the head.
  while (segment.size() > 1 && segment.back().capitalised) {
    segment.pop_back();
    if (const CategoryInfo* c = HeadCategory(segment)) return c;
  }
  return nullptr;
}

std::string HeadPhrase(std::string_view phrase) {
  std::vector<Word> segment = FirstSegment(Words(std::string(phrase)));
  return Join(segment, 0, segment.size());
}

}  // namespace villa
