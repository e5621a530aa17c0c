#include "annotator/mentions.h"

#include <algorithm>
#include <cctype>
#include <string>

namespace villa::annotator {
namespace {

struct Phrase {
  const char* words;
  Category category;
};

// Lower case, apostrophes as "'". Plurals are listed: a phrase must end on a word boundary.
const Phrase kPhrases[] = {
    {"living room", Category::kLivingRoom},   {"living rooms", Category::kLivingRoom},
    {"living-room", Category::kLivingRoom},   {"lounge", Category::kLivingRoom},
    {"sitting room", Category::kLivingRoom},  {"living area", Category::kLivingRoom},
    {"family room", Category::kLivingRoom},   {"bedroom", Category::kBedroom},
    {"bedrooms", Category::kBedroom},         {"kitchen", Category::kKitchen},
    {"kitchens", Category::kKitchen},         {"kitchenette", Category::kKitchen},
    {"bathroom", Category::kBathroom},        {"bathrooms", Category::kBathroom},
    {"wc", Category::kBathroom},              {"toilet", Category::kBathroom},
    {"en-suite", Category::kBathroom},        {"ensuite", Category::kBathroom},
    {"shower room", Category::kBathroom},     {"dining room", Category::kDiningRoom},
    {"dining rooms", Category::kDiningRoom},  {"dining-room", Category::kDiningRoom},
    {"dining area", Category::kDiningRoom},   {"children's room", Category::kChildrenRoom},
    {"childrens room", Category::kChildrenRoom}, {"children room", Category::kChildrenRoom},
    {"children-room", Category::kChildrenRoom},  {"kids' room", Category::kChildrenRoom},
    {"kids room", Category::kChildrenRoom},   {"kid's room", Category::kChildrenRoom},
    {"child's room", Category::kChildrenRoom}, {"nursery", Category::kChildrenRoom},
    {"playroom", Category::kChildrenRoom},    {"office", Category::kOffice},
    {"offices", Category::kOffice},           {"study", Category::kOffice},
    {"meeting room", Category::kMeetingRoom}, {"meeting rooms", Category::kMeetingRoom},
    {"meeting-room", Category::kMeetingRoom}, {"conference room", Category::kMeetingRoom},
    {"utility room", Category::kUtilityRoom}, {"utility rooms", Category::kUtilityRoom},
    {"utility-room", Category::kUtilityRoom}, {"laundry", Category::kUtilityRoom},
    {"balcony", Category::kBalcony},          {"balconies", Category::kBalcony},
};

bool WordChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Lower-cased ASCII; typographic apostrophes (U+2019) become "'"; other bytes are kept.
std::string Normalise(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text.compare(i, 3, "\xE2\x80\x99") == 0) {
      out += '\'';
      i += 2;
      continue;
    }
    out += static_cast<char>(std::tolower(static_cast<unsigned char>(text[i])));
  }
  return out;
}

// True when the phrase at `at` is negated: "no balcony", "without an office", "not a study".
bool Negated(const std::string& text, std::size_t at) {
  std::string before = text.substr(0, at);
  while (!before.empty() && !WordChar(before.back())) before.pop_back();
  for (const char* article : {" a", " an", " any"}) {
    std::string a(article);
    if (before.size() >= a.size() && before.compare(before.size() - a.size(), a.size(), a) == 0) {
      before.resize(before.size() - a.size());
      break;
    }
  }
  for (const char* negation : {"no", "without", "not", "nor", "neither"}) {
    std::string n(negation);
    if (before.size() >= n.size() && before.compare(before.size() - n.size(), n.size(), n) == 0 &&
        (before.size() == n.size() || !WordChar(before[before.size() - n.size() - 1])))
      return true;
  }
  return false;
}

}  // namespace

std::vector<Category> CategoriesNamed(std::string_view text) {
  std::string t = Normalise(text);
  std::vector<bool> named(kCategoryCount, false);
  for (const Phrase& p : kPhrases) {
    std::string phrase(p.words);
    for (std::size_t at = t.find(phrase); at != std::string::npos; at = t.find(phrase, at + 1)) {
      bool starts = at == 0 || !WordChar(t[at - 1]);
      std::size_t end = at + phrase.size();
      bool ends = end == t.size() || !WordChar(t[end]);
      if (starts && ends && !Negated(t, at)) named[static_cast<int>(p.category)] = true;
    }
  }
  std::vector<Category> out;
  for (int i = 0; i < kCategoryCount; ++i)
    if (named[i]) out.push_back(static_cast<Category>(i));
  return out;
}

std::vector<Category> CategoriesNamedButMissing(std::string_view text, const Layout& layout) {
  std::vector<Category> out;
  for (Category c : CategoriesNamed(text)) {
    bool present = std::any_of(layout.rooms.begin(), layout.rooms.end(), [&](const Room& r) { return r.category == c; });
    if (!present) out.push_back(c);
  }
  return out;
}

std::string_view CategoryWords(Category category) {
  switch (category) {
    case Category::kRoom: return "room";
    case Category::kLivingRoom: return "living room";
    case Category::kBedroom: return "bedroom";
    case Category::kKitchen: return "kitchen";
    case Category::kBathroom: return "bathroom";
    case Category::kDiningRoom: return "dining room";
    case Category::kChildrenRoom: return "children's room";
    case Category::kOffice: return "office";
    case Category::kMeetingRoom: return "meeting room";
    case Category::kUtilityRoom: return "utility room";
    case Category::kBalcony: return "balcony";
  }
  return "room";
}

}  // namespace villa::annotator
