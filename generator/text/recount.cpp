// The independent room count of a request (recount.h). Deliberately simple and separate from brief.cpp:
// its own word lists, its own tokenizer, no floors or scopes.
#include "generator/text/recount.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>

namespace villa {
namespace {

struct Noun {
  std::vector<std::string_view> words;  // singular and plural forms are separate entries
  Category category;
};

// Room nouns, longest first at each start word (matched greedily).
const std::vector<Noun>& Nouns() {
  using C = Category;
  static const std::vector<Noun> nouns = [] {
    std::vector<Noun> n;
    auto add = [&](std::initializer_list<std::string_view> w, C c) { n.push_back({std::vector<std::string_view>(w), c}); };
    for (std::string_view kid : {"kids", "kid's", "kids'", "children's", "childrens", "child's", "childs", "children"}) {
      for (std::string_view room : {"room", "rooms", "bedroom", "bedrooms"}) add({kid, room}, C::kChildrenRoom);
    }
    add({"nursery"}, C::kChildrenRoom);
    add({"nurseries"}, C::kChildrenRoom);
    add({"playroom"}, C::kChildrenRoom);
    add({"playrooms"}, C::kChildrenRoom);
    add({"play", "room"}, C::kChildrenRoom);
    add({"play", "rooms"}, C::kChildrenRoom);
    add({"en", "suite", "bathroom"}, C::kBathroom);
    add({"en", "suite", "bathrooms"}, C::kBathroom);
    add({"en", "suite"}, C::kBathroom);
    add({"en", "suites"}, C::kBathroom);
    add({"ensuite", "bathroom"}, C::kBathroom);
    add({"ensuite", "bathrooms"}, C::kBathroom);
    add({"ensuite"}, C::kBathroom);
    add({"ensuites"}, C::kBathroom);
    for (std::string_view w : {"bathroom", "bathrooms", "washroom", "washrooms", "wc", "wcs", "toilet", "toilets",
                               "lavatory", "lavatories", "restroom", "restrooms", "cloakroom", "cloakrooms"})
      add({w}, C::kBathroom);
    for (std::string_view w : {"powder", "shower"}) {
      add({w, "room"}, C::kBathroom);
      add({w, "rooms"}, C::kBathroom);
    }
    for (std::string_view w : {"wc", "toilet", "loo"}) add({"cloakroom", w}, C::kBathroom);
    add({"half", "bath"}, C::kBathroom);
    add({"half", "baths"}, C::kBathroom);
    for (std::string_view w : {"bedroom", "bedrooms"}) add({w}, C::kBedroom);
    for (std::string_view w : {"guest", "spare"}) {
      add({w, "bedroom"}, C::kBedroom);
      add({w, "bedrooms"}, C::kBedroom);
      add({w, "room"}, C::kBedroom);
      add({w, "rooms"}, C::kBedroom);
    }
    for (std::string_view w : {"box", "twin", "double"}) {
      add({w, "room"}, C::kBedroom);
      add({w, "rooms"}, C::kBedroom);
    }
    add({"doubles"}, C::kBedroom);
    add({"master", "suite"}, C::kBedroom);
    add({"master", "suites"}, C::kBedroom);
    add({"bed", "room"}, C::kBedroom);
    add({"bed", "rooms"}, C::kBedroom);
    for (std::string_view w : {"kitchen", "kitchens", "kitchenette", "kitchenettes"}) add({w}, C::kKitchen);
    for (std::string_view w : {"living", "sitting", "family", "reception", "drawing"}) {
      add({w, "room"}, C::kLivingRoom);
      add({w, "rooms"}, C::kLivingRoom);
    }
    for (std::string_view w : {"snug", "snugs", "lounge"}) add({w}, C::kLivingRoom);
    add({"front", "room"}, C::kLivingRoom);
    for (std::string_view w : {"games", "game", "rumpus"}) {
      add({w, "room"}, C::kLivingRoom);
      add({w, "rooms"}, C::kLivingRoom);
    }
    add({"lounges"}, C::kLivingRoom);
    for (std::string_view w : {"room", "rooms", "area", "areas", "hall"}) add({"dining", w}, C::kDiningRoom);
    for (std::string_view w : {"office", "offices", "study", "studies"}) add({w}, C::kOffice);
    for (std::string_view w : {"meeting", "conference"}) {
      add({w, "room"}, C::kMeetingRoom);
      add({w, "rooms"}, C::kMeetingRoom);
    }
    add({"boardroom"}, C::kMeetingRoom);
    add({"boardrooms"}, C::kMeetingRoom);
    for (std::string_view w : {"balcony", "balconies", "terrace", "terraces"}) add({w}, C::kBalcony);
    std::stable_sort(n.begin(), n.end(), [](const Noun& a, const Noun& b) { return a.words.size() > b.words.size(); });
    return n;
  }();
  return nouns;
}

bool IsPlural(const Noun& noun) { return noun.words.back().back() == 's'; }

std::optional<int> NumberOf(std::string_view w) {
  static const std::map<std::string_view, int> words = {
      {"a", 1},     {"an", 1},     {"one", 1},     {"single", 1}, {"two", 2},   {"three", 3}, {"four", 4},
      {"five", 5},  {"six", 6},    {"seven", 7},   {"eight", 8},  {"nine", 9},  {"ten", 10},  {"eleven", 11},
      {"twelve", 12}, {"couple", 2}, {"pair", 2}};  // not "double" or "twin": a double bedroom is one
  if (auto it = words.find(w); it != words.end()) return it->second;
  if (!w.empty() && w.size() <= 2 && std::all_of(w.begin(), w.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
    return std::stoi(std::string(w));
  return std::nullopt;
}

std::optional<int> OrdinalOf(std::string_view w) {
  static const std::map<std::string_view, int> words = {
      {"second", 2}, {"third", 3}, {"fourth", 4}, {"fifth", 5}, {"sixth", 6}, {"2nd", 2}, {"3rd", 3}, {"4th", 4}, {"5th", 5}};
  if (auto it = words.find(w); it != words.end()) return it->second;
  return std::nullopt;
}

bool OneOf(std::string_view w, std::initializer_list<std::string_view> set) {
  return std::find(set.begin(), set.end(), w) != set.end();
}

bool Boundary(std::string_view w) { return OneOf(w, {".", ",", ";", ":", "!", "?", "(", ")", "-", "and", "or", "plus", "with", "&"}); }
bool Negation(std::string_view w) {
  return OneOf(w, {"no", "without", "not", "never", "nor", "neither", "don't", "dont", "won't", "wont", "instead", "except",
                   "skip", "forget", "drop", "needn't", "rather"});
}
bool Reference(std::string_view w) {
  return OneOf(w, {"the", "this", "that", "these", "those", "our", "my", "its", "their", "his", "her", "each", "every", "either",
                   "both", "which", "same", "any", "other", "per", "of"});
}
bool FloorWord(std::string_view w) {
  return OneOf(w, {"floor", "floors", "level", "levels", "storey", "storeys", "story", "stories"});
}

// Lowercase words and punctuation marks; hyphens and slashes split words ("two-bedroom", "en-suite").
std::vector<std::string> Tokens(std::string_view text) {
  std::vector<std::string> out;
  std::string word;
  auto flush = [&] {
    if (!word.empty()) out.push_back(word);
    word.clear();
  };
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = static_cast<char>(std::tolower(static_cast<unsigned char>(text[i])));
    // An en or em dash (UTF-8), or a hyphen standing alone ("2nd - office"), separates like a comma; a
    // hyphen inside a word splits it ("two-bedroom").
    const bool dash = text.compare(i, 3, "\xE2\x80\x93") == 0 || text.compare(i, 3, "\xE2\x80\x94") == 0;
    if (dash || (c == '-' && word.empty())) {
      flush();
      out.push_back("-");
      if (dash) i += 2;
    } else if (std::isalnum(static_cast<unsigned char>(c)) || c == '\'') {
      word += c;
    } else {
      flush();
      if (c == '.' || c == ',' || c == ';' || c == ':' || c == '!' || c == '?' || c == '(' || c == ')' || c == '&')
        out.push_back(std::string(1, c));
    }
  }
  flush();
  // Trailing apostrophes of possessives stay ("kids'"); a closing quote ("'x'") does not matter here.
  return out;
}

std::string Join(const std::vector<std::string>& t, size_t from, size_t to) {
  std::string s;
  for (size_t k = from; k < to && k < t.size(); ++k) {
    if (!s.empty() && !(t[k].size() == 1 && std::ispunct(static_cast<unsigned char>(t[k][0])))) s += ' ';
    s += t[k];
  }
  return s;
}

}  // namespace

std::vector<RoomRecount> RecountRooms(std::string_view text, int floors) {
  const std::vector<std::string> t = Tokens(text);
  // Within a sentence the rooms of a list add up ("a lounge, a separate sitting room"); across sentences a
  // kind counts as the most one sentence reads (a later sentence names the rooms again).
  std::map<Category, RoomRecount> best;      // over the sentences read
  std::map<Category, RoomRecount> sentence;  // this sentence's counts
  auto so_far = [&](Category c) {
    return std::max(best.count(c) ? best[c].count : 0, sentence.count(c) ? sentence[c].count : 0);
  };
  std::optional<int> last_count;  // the count of the last counted noun (for "..., each with an en-suite")
  // Token k a verb of having ("with", "has", "gets") after "each" / "all" / "every" within three words
  // ("each with", "each bedroom has"): how many rooms the distribution covers (the bedrooms read so far for
  // "each bedroom", else the last count read); nothing when it is no such verb. `at`: the index of "each".
  const auto EachAt = [&](size_t k, size_t* at) -> std::optional<int> {
    if (!OneOf(t[k], {"with", "has", "have", "having", "gets", "get", "includes", "include"})) return std::nullopt;
    for (size_t j = k, steps = 0; j > 0 && steps < 3; ++steps) {
      --j;
      if (OneOf(t[j], {".", ";", ":"})) break;
      if (!OneOf(t[j], {"each", "all", "every"})) continue;
      if (j + 1 < k && FloorWord(t[j + 1])) return std::nullopt;  // "each floor has a bathroom": the floors' (below)
      *at = j;
      if (j + 1 < k && OneOf(t[j + 1], {"bedroom", "bedrooms"})) return so_far(Category::kBedroom);
      return last_count.value_or(0);
    }
    return std::nullopt;
  };
  auto note = [&](Category c, int n, const std::string& phrase) {
    RoomRecount& r = best[c];
    r.category = c;
    if (n > r.count) {
      r.count = n;
      r.phrase = phrase;
    }
  };
  auto flush = [&] {
    for (const auto& [c, r] : sentence) note(c, r.count, r.phrase);
    sentence.clear();
  };
  std::optional<Category> last_category;
  std::map<Category, int> readings;             // how many times a kind was counted
  std::map<Category, bool> explicit_reading;    // the last of them a plain number of two or more
  for (size_t i = 0; i < t.size(); ++i) {
    if (OneOf(t[i], {".", "!", "?"})) {
      flush();
      continue;
    }
    // "another one", "a second one": one more of the kind just counted.
    if (last_category && i + 1 < t.size() && t[i + 1] == "one" && (t[i] == "another" || OrdinalOf(t[i])) &&
        (i + 2 >= t.size() || !OneOf(t[i + 2], {"of"}))) {
      const int n = t[i] == "another" ? so_far(*last_category) + 1 : *OrdinalOf(t[i]);
      RoomRecount& r = sentence[*last_category];
      r.category = *last_category;
      if (n > r.count) {
        r.count = n;
        r.phrase = Join(t, i, i + 2);
      }
      ++i;
      continue;
    }
    const Noun* noun = nullptr;
    for (const Noun& n : Nouns()) {
      if (i + n.words.size() > t.size()) continue;
      bool match = true;
      for (size_t k = 0; k < n.words.size() && match; ++k) match = t[i + k] == n.words[k];
      if (match) {
        noun = &n;
        break;
      }
    }
    if (!noun) continue;
    // "a Victorian-style terrace", "an end terrace": the house.
    if (t[i] == "terrace" && i > 0 && OneOf(t[i - 1], {"style", "victorian", "georgian", "edwardian", "end", "mid", "period"})) continue;
    const size_t end = i + noun->words.size();
    // "an office villa": the building ("a three-bedroom bungalow" counts rooms).
    if (end < t.size() && !(i > 0 && NumberOf(t[i - 1])) && OneOf(t[end], {"villa", "house", "building", "bungalow", "home", "cottage", "block"})) continue;
    size_t end_after = end;  // past a count written after the noun
    // Backwards: the quantity within four words, up to a boundary or another noun.
    std::optional<int> count, ordinal;
    bool negated = false, referred = false, distributed = false, another = false;
    size_t from = i;
    for (size_t k = i, steps = 0; k > 0 && steps < 4; ++steps) {
      --k;
      const std::string& w = t[k];
      if (Negation(w)) {
        negated = true;
        break;
      }
      // "each with / all with / each bedroom has (its own) en-suite": as many as those rooms.
      if (const std::optional<int> each = EachAt(k, &from)) {
        distributed = true;
        count = *each;
        break;
      }
      // "a second-floor bedroom": the ordinal is the floor's.
      if (Boundary(w) || FloorWord(w)) break;
      if (OneOf(w, {"own", "private", "separate", "individual"})) continue;
      // "each with its own bathroom" distributes; "its balcony" refers to one already named.
      if (OneOf(w, {"its", "their"})) {
        if (k > 0)
          if (const std::optional<int> each = EachAt(k - 1, &from)) {
            distributed = true;
            count = *each;
            break;
          }
        referred = true;
        break;
      }
      // "a couple of offices", "a pair of bedrooms".
      if (w == "of" && k > 0 && OneOf(t[k - 1], {"couple", "pair"})) {
        count = 2;
        from = k > 1 && t[k - 2] == "a" ? k - 2 : k - 1;
        break;
      }
      // "3 bedrooms, 2 of them en-suite", "2 of which have en-suites": that many.
      if (OneOf(w, {"them", "which"}) && k >= 2 && t[k - 1] == "of" && NumberOf(t[k - 2])) {
        count = NumberOf(t[k - 2]);
        from = k - 2;
        break;
      }
      if (OneOf(w, {"have", "has", "are"})) continue;
      // "both bathrooms" with none counted yet: two.
      if (w == "both" && IsPlural(*noun)) {
        count = 2;
        from = k;
        break;
      }
      if (Reference(w)) {
        referred = true;
        break;
      }
      if (const auto n = NumberOf(w)) {
        if (k > 0 && FloorWord(t[k - 1])) break;  // "level 3 office": the number is the floor's
        if (k > 0 && OneOf(t[k - 1], {"every", "each", "per", "the"})) {  // "for every two bedrooms": a ratio; "the three bedrooms": named before
          referred = true;
          break;
        }
        count = *n;
        from = k;
        // "..., each with a bathroom": the article belongs to the distribution.
        if (*n == 1 && k > 0) {
          if (const std::optional<int> each = EachAt(k - 1, &from)) {
            distributed = true;
            count = *each;
          }
        }
        break;
      }
      if (const auto o = OrdinalOf(w)) {
        ordinal = *o;
        from = k;
        break;
      }
      if (w == "another") {
        another = true;
        from = k;
        break;
      }
    }
    // "no / without / not a study", "no need for a balcony", "neither a study nor a dining room": a negation
    // up to four words before the number reads too (not across a full stop or a semicolon); "dining room
    // not needed" after it.
    for (size_t k = from, steps = 0; k > 0 && steps < 4 && !negated && !referred; ++steps) {
      if (OneOf(t[--k], {".", ";", ":", "!", "?"})) break;
      negated = Negation(t[k]);
      // "two bedrooms, including a master bedroom", "one of which is a study": one already counted.
      referred = OneOf(t[k], {"including", "incl", "among", "which", "whom", "them"});
    }
    if (end < t.size()) {
      const std::string& next = t[end];
      const bool is = OneOf(next, {"is", "are"}) && end + 1 < t.size() && t[end + 1] == "not";
      negated = negated || is || OneOf(next, {"not", "isn't", "aren't"});
    }
    if (negated || referred) {
      i = end - 1;
      continue;
    }
    // "Bathrooms: 2", "bedrooms x3", "bedrooms (3)" (spec sheets and lists): the number after the noun.
    if (!count && !ordinal && !another && !distributed && end < t.size()) {
      std::optional<int> after;
      size_t at = end + 1;
      if (t[end] == ":" && end + 1 < t.size() && t[end + 1] != "a" && t[end + 1] != "an") after = NumberOf(t[end + 1]);
      else if (t[end] == "(" && end + 2 < t.size() && t[end + 2] == ")") after = NumberOf(t[end + 1]), at = end + 2;
      else if (t[end].size() >= 2 && t[end][0] == 'x') after = NumberOf(t[end].substr(1)), at = end;
      if (after) {
        count = after;
        from = i;
        end_after = at + 1;
      }
    }
    int n = 0;
    if (distributed) {
      n = count.value_or(0);
    } else if (ordinal) {
      n = *ordinal;
    } else if (another) {
      n = std::max(2, so_far(noun->category) + 1);
    } else if (count) {
      n = *count;
    } else if (!IsPlural(*noun)) {
      n = 1;  // a bare singular in a list ("kitchen, lounge, 2 bedrooms")
    }
    // Backwards over a verb: "Both upper floors get a balcony", "each floor has a bathroom".
    if (n > 0 && !distributed && !ordinal && !another && (!count || *count == 1)) {
      for (size_t k = i, steps = 0; k > 1 && steps < 4; ++steps) {
        --k;
        if (OneOf(t[k], {"get", "gets", "has", "have", "needs", "need", "with"}) && FloorWord(t[k - 1])) {
          size_t q = k - 1;
          bool upper = false;
          while (q > 0 && OneOf(t[q - 1], {"upper", "other", "of", "the", "two", "three"})) upper = upper || t[--q] == "upper";
          if (q > 0 && OneOf(t[q - 1], {"each", "every", "both", "all"}))
            n *= t[q - 1] == "both" ? 2 : std::max(upper ? floors - 1 : floors, 1);
          break;
        }
        if (Boundary(t[k]) && t[k] != "with") break;
      }
    }
    // "the two upper floors each have two bedrooms": as many on each of those floors.
    if (n > 0 && !distributed && !ordinal && !another) {
      for (size_t k = i, steps = 0; k > 2 && steps < 4; ++steps) {
        --k;
        if (OneOf(t[k], {"get", "gets", "has", "have", "need", "needs"}) && t[k - 1] == "each" && FloorWord(t[k - 2])) {
          size_t q = k - 2;
          int named = 0;
          bool upper = false;
          while (q > 0 && OneOf(t[q - 1], {"upper", "other", "the", "two", "three"})) {
            --q;
            upper = upper || t[q] == "upper";
            if (t[q] == "two" || t[q] == "three") named = t[q] == "two" ? 2 : 3;
          }
          n *= named > 0 ? named : std::max(upper ? floors - 1 : floors, 1);
          break;
        }
        if (Boundary(t[k])) break;
      }
    }
    // Forwards: "on each floor", "per floor", "on both floors", "per bedroom", "for each bedroom".
    size_t to = std::max(end, end_after);
    for (size_t k = end; k < t.size() && k < end + 4; ++k) {
      const std::string& w = t[k];
      if (Boundary(w) && w != "with") break;
      if (OneOf(w, {"each", "every", "all", "both", "per"}) && k + 1 < t.size()) {
        // "on both floors", "on both upper floors", "on each of the floors".
        size_t f = k + 1;
        while (f < t.size() && f < k + 4 && OneOf(t[f], {"upper", "lower", "other", "of", "the", "two", "three"})) ++f;
        const std::string& next = f < t.size() ? t[f] : t[k + 1];
        // "on each one", after the floors were named ("Three floors with a bathroom on each one").
        const bool each_one = OneOf(w, {"each", "every"}) && t[k + 1] == "one" && k > 0 && t[k - 1] == "on" &&
                              std::any_of(t.begin(), t.begin() + static_cast<std::ptrdiff_t>(i), [](const std::string& x) { return FloorWord(x); });
        if (FloorWord(next) || each_one) {
          n = std::max(n, 1) * (w == "both" ? 2 : std::max(floors, 1));
          to = each_one ? k + 2 : f + 1;
          break;
        }
        if (OneOf(next, {"bedroom", "bedrooms"}) && (w == "per" || w == "each" || w == "every")) {
          const int bedrooms = so_far(Category::kBedroom);
          // "for every two bedrooms": one for each pair, rounded up.
          const int group = t[k + 1] == "two" ? 2 : t[k + 1] == "three" ? 3 : 1;
          if (bedrooms > 0) n = std::max(n, 1) * ((bedrooms + group - 1) / group);
          to = k + 2;
          break;
        }
      }
    }
    if (n > 0) {
      ++readings[noun->category];
      // ("two more bedrooms" adds to one named before: no exact count of its own)
      const bool more = std::any_of(t.begin() + static_cast<std::ptrdiff_t>(from), t.begin() + static_cast<std::ptrdiff_t>(i),
                                    [](const std::string& w) { return OneOf(w, {"more", "other", "additional", "extra", "further"}); });
      // ("two bedrooms and a bathroom on both upper floors": a list spread over floors later in the sentence)
      bool spread_later = false;  // (no comma between: "Bathrooms: 2, one on each floor" stays exact)
      for (size_t k = to; k + 1 < t.size() && !OneOf(t[k], {".", "!", "?", ";", ","}) && !spread_later; ++k)
        if (OneOf(t[k], {"each", "every", "both", "all"}))
          for (size_t f = k + 1; f < t.size() && f < k + 4 && !spread_later; ++f) spread_later = FloorWord(t[f]);
      explicit_reading[noun->category] = count && !distributed && !ordinal && !another && !more && !spread_later && n == *count && *count >= 2 &&
                                         !OneOf(t[from], {"a", "an", "one", "single", "couple", "pair"});
      RoomRecount& r = sentence[noun->category];
      r.category = noun->category;
      const std::string phrase = Join(t, from, to);
      if (ordinal || another) {  // a total: "a second bedroom" is two in all
        if (n > r.count) {
          r.count = n;
          r.phrase = phrase;
        }
      } else {
        r.count += n;
        r.phrase += (r.phrase.empty() ? "" : " + ") + phrase;
      }
      last_count = n;
      last_category = noun->category;
    }
    i = end - 1;
  }
  flush();
  std::vector<RoomRecount> out;
  for (auto [category, r] : best) {
    if (r.count <= 0) continue;
    r.exact = readings[category] == 1 && explicit_reading[category];
    out.push_back(r);
  }
  return out;
}

std::string RecountDisagreement::Message() const {
  const std::string kind(CategoryName(category));
  return "the text may ask for " + std::string(exact ? "exactly " : "") + std::to_string(asked) + " " + kind +
         (asked == 1 ? "" : "s") + " (\"" + phrase + "\"); the layout has " + std::to_string(has);
}

std::vector<RecountDisagreement> CheckRecount(std::string_view text, const Layout& layout) {
  std::map<Category, int> has;
  for (const Room& r : layout.rooms) ++has[r.category];
  std::vector<RecountDisagreement> out;
  for (const RoomRecount& r : RecountRooms(text, layout.LevelCount())) {
    if (has[r.category] < r.count) out.push_back({r.category, r.count, has[r.category], r.phrase, false});
    else if (r.exact && has[r.category] > r.count) out.push_back({r.category, r.count, has[r.category], r.phrase, true});
  }
  return out;
}

}  // namespace villa
