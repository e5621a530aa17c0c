#include "scene/request.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <optional>

#include "util/spelling.h"

namespace villa::scene {
namespace {

struct Token {
  std::string word;
  int sentence = 0;
};

// Lower-case words; '-' and '_' join words as spaces do; apostrophes vanish ("children's" -> "childrens");
// . ! ? ; end a sentence. Other punctuation separates words.
std::vector<Token> Tokenise(std::string_view text) {
  std::vector<Token> tokens;
  std::string word;
  int sentence = 0;
  auto flush = [&] {
    if (!word.empty()) tokens.push_back({word, sentence});
    word.clear();
  };
  for (size_t i = 0; i < text.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(text[i]);
    // A minus sign before a number keeps it ("-3 armchairs" is no request for three).
    if (c == '-' && word.empty() && i + 1 < text.size() && std::isdigit(static_cast<unsigned char>(text[i + 1]))) {
      word.push_back('-');
      continue;
    }
    if (std::isalnum(c) || c >= 0x80) {
      word.push_back(static_cast<char>(std::tolower(c)));
    } else if (c == '\'') {
      continue;
    } else {
      flush();
      if (c == '.' || c == '!' || c == '?' || c == ';' || c == '\n') ++sentence;
    }
  }
  flush();
  return tokens;
}

std::string Join(const std::vector<Token>& tokens, size_t begin, size_t end) {
  std::string out;
  for (size_t i = begin; i < end; ++i) out += (i > begin ? " " : "") + tokens[i].word;
  return out;
}

struct RoomWord {
  std::string_view words;
  Category category;
};

// Enough room names to bind furniture to rooms (the generator's brief parser has the full lexicon for
// layouts; scene/ sits below it and keeps its own short list).
constexpr RoomWord kRoomWords[] = {
    {"library", Category::kOffice},             {"studio", Category::kOffice},   {"workroom", Category::kOffice},
    {"master bed", Category::kBedroom},         {"guest bed", Category::kBedroom},
    // Rooms whose names are also fixtures' ("a WC", "a downstairs loo", "a half bath"): rooms, not wishes.
    {"wc", Category::kBathroom},                {"loo", Category::kBathroom},
    {"powder room", Category::kBathroom},       {"cloakroom", Category::kBathroom},
    {"en suite", Category::kBathroom},          {"ensuite", Category::kBathroom},
    {"half bath", Category::kBathroom},         {"full bath", Category::kBathroom},
    {"master bath", Category::kBathroom},       {"guest bath", Category::kBathroom},
    {"family bath", Category::kBathroom},       {"main bath", Category::kBathroom},
    {"wet room", Category::kBathroom},          {"wetroom", Category::kBathroom},
    {"den", Category::kLivingRoom},             {"great room", Category::kLivingRoom},
    {"study room", Category::kOffice},
    {"living room", Category::kLivingRoom},     {"lounge", Category::kLivingRoom},
    {"sitting room", Category::kLivingRoom},    {"family room", Category::kLivingRoom},
    {"living area", Category::kLivingRoom},     {"bedroom", Category::kBedroom},
    {"master bedroom", Category::kBedroom},     {"guest room", Category::kBedroom},
    {"guest bedroom", Category::kBedroom},      {"kitchen", Category::kKitchen},
    {"kitchenette", Category::kKitchen},        {"bathroom", Category::kBathroom},
    {"washroom", Category::kBathroom},          {"restroom", Category::kBathroom},
    {"shower room", Category::kBathroom},       {"dining room", Category::kDiningRoom},
    {"dining area", Category::kDiningRoom},     {"childrens room", Category::kChildrenRoom},
    {"children room", Category::kChildrenRoom}, {"kids room", Category::kChildrenRoom},
    {"kid room", Category::kChildrenRoom},      {"nursery", Category::kChildrenRoom},
    {"playroom", Category::kChildrenRoom},      {"office", Category::kOffice},
    {"study", Category::kOffice},               {"home office", Category::kOffice},
    {"meeting room", Category::kMeetingRoom},   {"conference room", Category::kMeetingRoom},
    {"boardroom", Category::kMeetingRoom},      {"utility room", Category::kUtilityRoom},
    {"laundry room", Category::kUtilityRoom},   {"laundry", Category::kUtilityRoom},
    {"staircase room", Category::kUtilityRoom}, {"stair room", Category::kUtilityRoom},
    {"balcony", Category::kBalcony},            {"terrace", Category::kBalcony},
    {"veranda", Category::kBalcony},            {"patio", Category::kBalcony},
    // British names and the short forms of notes ("Piano in living rm", "a piano in the front room").
    {"front room", Category::kLivingRoom},      {"reception room", Category::kLivingRoom},
    {"drawing room", Category::kLivingRoom},    {"snug", Category::kLivingRoom},
    {"parlour", Category::kLivingRoom},         {"parlor", Category::kLivingRoom},
    {"tv room", Category::kLivingRoom},         {"media room", Category::kLivingRoom},
    {"living rm", Category::kLivingRoom},       {"family rm", Category::kLivingRoom},
    {"sitting rm", Category::kLivingRoom},      {"dining rm", Category::kDiningRoom},
    {"kids rm", Category::kChildrenRoom},       {"kid rm", Category::kChildrenRoom},
    {"bdrm", Category::kBedroom},               {"bedrm", Category::kBedroom},
    {"bthrm", Category::kBathroom},             {"bathrm", Category::kBathroom},
    {"meeting rm", Category::kMeetingRoom},
    {"lvg rm", Category::kLivingRoom},          {"liv rm", Category::kLivingRoom},
    {"din rm", Category::kDiningRoom},          {"mtg rm", Category::kMeetingRoom},
    {"kit", Category::kKitchen},                {"powder rm", Category::kBathroom},
    {"childrens bedroom", Category::kChildrenRoom}, {"children bedroom", Category::kChildrenRoom},
    {"kids bedroom", Category::kChildrenRoom},  {"kid bedroom", Category::kChildrenRoom},
};

// Vocabulary words too common in prose to mean the object alone ("a range of plants", "seats four").
constexpr std::array<std::string_view, 7> kAmbiguous = {"range", "display", "seat", "seats", "screen", "frame", "trunk"};

std::optional<Category> RoomOf(const std::string& phrase) {
  for (const RoomWord& r : kRoomWords) {
    if (phrase == r.words) return r.category;
    // Plural room words ("bedrooms") bind like the singular.
    if (phrase.size() == r.words.size() + 1 && phrase.back() == 's' && phrase.compare(0, r.words.size(), r.words) == 0)
      return r.category;
  }
  return std::nullopt;
}

// A misspelt piece or room ("dishwaser", "wardorbe", "bookcaes", "dinning table"): a word of seven
// letters or more that names nothing, one edit from exactly one word (six letters or more) of the names
// of the categories and rooms (or its plural), read as that word. Verb forms are left alone ("dressed" is
// no dresser).
std::vector<Token> Misspellings(std::vector<Token> tokens) {
  // The words of the categories' names and of the rooms' ("dinning table", "dinning room").
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    auto add = [&](std::string_view phrase) {
      size_t begin = 0;
      while (begin < phrase.size()) {
        size_t end = phrase.find_first_of(" -", begin);
        if (end == std::string_view::npos) end = phrase.size();
        const std::string word(phrase.substr(begin, end - begin));
        if (word.size() >= 6 && std::find(out.begin(), out.end(), word) == out.end()) out.push_back(word);
        begin = end + 1;
      }
    };
    for (const CategoryInfo& c : Categories()) {
      add(c.name);
      for (std::string_view w : c.words) add(w);
    }
    for (const RoomWord& r : kRoomWords) add(r.words);
    return out;
  }();
  for (Token& t : tokens) {
    if (t.word == "ea") t.word = "each";  // (notes' short form: "Wardrobe in ea bdrm")
    if (!MaybeMisspeltNoun(t.word) || CategoryForWord(t.word) || RoomOf(t.word)) continue;
    if (std::optional<std::string> meant = OneEditFrom(t.word, names)) t.word = std::move(*meant);
  }
  return tokens;
}

struct Mention {
  bool room = false;
  size_t begin = 0, end = 0;  // token range
  const CategoryInfo* category = nullptr;
  Category room_category = Category::kRoom;
};

std::optional<int> NumberWord(const std::string& w);
bool IsOneOf(const std::string& w, std::initializer_list<std::string_view> words);

// Fixtures that belong to one kind of room: a bed to a bedroom, a toilet to a bathroom, a cooker to a kitchen.
bool FitsRoom(std::string_view category, Category room) {
  auto is = [&](std::initializer_list<std::string_view> names) { return std::find(names.begin(), names.end(), category) != names.end(); };
  if (is({"bed", "child-bed"})) return room == Category::kBedroom || room == Category::kChildrenRoom;
  if (is({"toilet", "bathtub", "shower", "washbasin", "towel-rack"})) return room == Category::kBathroom;
  if (is({"cooker", "counter", "range-hood", "dishwasher", "island"})) return room == Category::kKitchen;
  return true;
}

// Pieces no bathroom or utility room is furnished with: a "... in the bathroom" after them binds something
// else ("Dining table with 4 chairs, and one mirror in each of the 2 bathrooms").
bool OutOfPlace(std::string_view category, Category room) {
  if (room != Category::kBathroom && room != Category::kUtilityRoom) return false;
  static constexpr std::array<std::string_view, 12> kLiving = {"dining-table", "chair", "sofa", "armchair", "bed", "child-bed",
                                                               "desk", "piano", "coffee-table", "tv-stand", "conference-table", "bookcase"};
  return std::find(kLiving.begin(), kLiving.end(), category) != kLiving.end();
}

// "3 bed, 1 bath", "a four-bed house": a count of rooms, the singular after a number (two beds are
// "2 beds"; "1 bath" in digits is a bathroom too).
// "One" counts rooms too right after another room: "one bedroom and one bath".
std::optional<Category> RoomCount(const std::vector<Token>& tokens, size_t i, const std::string& phrase, bool after_room) {
  if ((phrase != "bed" && phrase != "bath") || i == 0 || tokens[i - 1].sentence != tokens[i].sentence) return std::nullopt;
  const std::string& before = tokens[i - 1].word;
  const std::optional<int> n = NumberWord(before);
  const bool digits = !before.empty() && std::isdigit(static_cast<unsigned char>(before[0]));
  if (!n || (*n < 2 && !digits && !after_room)) return std::nullopt;
  // "Both children's rooms get 1 bed and 1 desk each", "a room with 2 beds": furniture.
  if (i >= 2 && tokens[i - 2].sentence == tokens[i].sentence &&
      IsOneOf(tokens[i - 2].word, {"get", "gets", "has", "have", "with", "needs", "need", "wants", "want", "each", "per"}))
    return std::nullopt;
  return phrase == "bed" ? Category::kBedroom : Category::kBathroom;
}

// Longest match first (3, 2, 1 words): "study desk" is a desk, "study" alone an office.
std::vector<Mention> FindMentions(const std::vector<Token>& tokens) {
  std::vector<Mention> out;
  size_t i = 0;
  while (i < tokens.size()) {
    bool found = false;
    for (size_t n = std::min<size_t>(3, tokens.size() - i); n >= 1 && !found; --n) {
      if (tokens[i + n - 1].sentence != tokens[i].sentence) continue;
      std::string phrase = Join(tokens, i, i + n);
      const bool after_room = !out.empty() && out.back().room && out.back().end + 2 >= i &&
                              tokens[out.back().begin].sentence == tokens[i].sentence;
      // ("Both children's rooms: 1 bed and 1 desk each": right after a room named in words, a piece.)
      const bool note = !out.empty() && out.back().room && out.back().end == i - 1 &&
                        !IsOneOf(tokens[out.back().begin].word, {"bed", "bath", "beds", "baths"});
      if (auto room = RoomOf(phrase); room || (n == 1 && !note && (room = RoomCount(tokens, i, phrase, after_room)))) {
        out.push_back({true, i, i + n, nullptr, *room});
        found = true;
      } else if (n > 1 || std::find(kAmbiguous.begin(), kAmbiguous.end(), phrase) == kAmbiguous.end()) {
        if (const CategoryInfo* c = CategoryForWord(phrase)) {
          out.push_back({false, i, i + n, c, Category::kRoom});
          found = true;
        }
      }
      if (found) i += n;
    }
    if (!found) ++i;
  }
  return out;
}

std::optional<int> NumberWord(const std::string& w) {
  static constexpr std::array<std::string_view, 21> kWords = {
      "zero",   "one",    "two",    "three",    "four",     "five",    "six",     "seven",     "eight",    "nine",  "ten",
      "eleven", "twelve", "thirteen", "fourteen", "fifteen", "sixteen", "seventeen", "eighteen", "nineteen", "twenty"};
  for (size_t i = 0; i < kWords.size(); ++i)
    if (w == kWords[i]) return static_cast<int>(i);
  if (w == "thirty") return 30;
  if (w == "dozen") return 12;
  // Digits of any length keep their size (capped at a million: "10000 armchairs" is not two) and their sign.
  const bool negative = !w.empty() && w[0] == '-';
  const std::string digits = negative ? w.substr(1) : w;
  if (!digits.empty() && std::all_of(digits.begin(), digits.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); })) {
    const int n = digits.size() > 6 ? 1000000 : std::stoi(digits);
    return negative ? -n : n;
  }
  return std::nullopt;
}

bool IsOneOf(const std::string& w, std::initializer_list<std::string_view> words) {
  return std::find(words.begin(), words.end(), w) != words.end();
}

// The count said before an object (up to three words back, past adjectives): a number, an article, "a pair
// of", "several", "no". `explicit_count` is false when nothing was said.
void CountBefore(const std::vector<Token>& tokens, const Mention& m, size_t floor, Wish& wish) {
  const std::string& last = tokens[m.end - 1].word;
  bool plural = last.size() > 3 && last.back() == 's' && last[last.size() - 2] != 's';
  wish.count = plural ? 2 : 1;
  wish.explicit_count = false;
  for (size_t back = 1; back <= 4 && m.begin >= floor + back; ++back) {
    const std::string& w = tokens[m.begin - back].word;
    if (tokens[m.begin - back].sentence != tokens[m.begin].sentence) break;
    if (IsOneOf(w, {"no", "without", "nor"})) {
      wish.count = 0;
      wish.explicit_count = true;
      return;
    }
    if (auto n = NumberWord(w)) {
      wish.count = *n;
      wish.explicit_count = true;
      return;
    }
    if (IsOneOf(w, {"a", "an", "single", "another", "any"})) {
      wish.count = 1;
      wish.explicit_count = true;
      // "without a TV", "not a single rug"
      for (size_t more = back + 1; more <= back + 2 && m.begin >= floor + more; ++more)
        if (IsOneOf(tokens[m.begin - more].word, {"without", "no", "not", "nor"})) wish.count = 0;
      return;
    }
    if (w == "pair" || w == "couple") {
      wish.count = 2;
      wish.explicit_count = true;
      return;
    }
    if (IsOneOf(w, {"several", "some", "few"})) {
      wish.count = 3;
      wish.explicit_count = true;
      return;
    }
    if (IsOneOf(w, {"many", "lots", "plenty"})) {
      wish.count = 4;
      wish.explicit_count = true;
      return;
    }
    if (IsOneOf(w, {"and", "or", "with", "in", "on", "for", "the", "of", "to", "by", "near", "next", "beside", "facing"}))
      break;  // the words before belong to something else
  }
}

bool WordsAt(const std::vector<Token>& tokens, size_t at, std::initializer_list<std::string_view> words) {
  size_t i = at;
  for (std::string_view w : words) {
    if (i >= tokens.size() || tokens[i].word != w || tokens[i].sentence != tokens[at].sentence) return false;
    ++i;
  }
  return true;
}

// Skips "the", "a", "an", "my", "our", "its" at `at`.
size_t SkipDeterminers(const std::vector<Token>& tokens, size_t at) {
  while (at < tokens.size() && IsOneOf(tokens[at].word, {"the", "a", "an", "my", "our", "its", "their", "his", "her"})) ++at;
  return at;
}

struct RelationPhrase {
  std::initializer_list<std::string_view> words;
  SemanticRelation relation;
};

bool IsSeat(const CategoryInfo* c) {
  return c->name == "chair" || c->name == "office-chair" || c->name == "stool" || c->name == "child-chair" ||
         c->name == "outdoor-chair" || c->name == "armchair" || c->name == "bench";
}

// The people a phrase at token i asks seats for, and the token after it; nullopt when none. "seat(s) /
// seating / sit(s) [for / up to / at least] N [people]", "room / space for N [people]", "for N people",
// "N-seat(er)", and a bare "for N" right after a table or a room that dines or meets (`after_table`).
std::optional<int> SeatsAt(const std::vector<Token>& tokens, size_t i, bool after_table) {
  auto same = [&](size_t k) { return k < tokens.size() && tokens[k].sentence == tokens[i].sentence; };
  auto people = [&](size_t k) { return same(k) && IsOneOf(tokens[k].word, {"people", "persons", "guests", "diners", "adults", "person"}); };
  auto count = [&](size_t k) -> std::optional<int> {
    if (!same(k)) return std::nullopt;
    const std::optional<int> n = NumberWord(tokens[k].word);
    return n && *n >= 2 && *n <= 40 ? n : std::nullopt;
  };
  const std::string& w = tokens[i].word;
  if (count(i) && same(i + 1) && IsOneOf(tokens[i + 1].word, {"seat", "seater"})) return count(i);
  size_t k = i + 1;
  const bool verb = IsOneOf(w, {"seat", "seats", "seating", "sit", "sits", "seated"});
  const bool room_for = IsOneOf(w, {"room", "space", "places"}) && same(k) && tokens[k].word == "for";
  if (!verb && !room_for && w != "for") return std::nullopt;
  if (room_for) ++k;
  for (int skip = 0; skip < 3 && same(k) && IsOneOf(tokens[k].word, {"for", "up", "to", "at", "least", "around", "about", "comfortably"}); ++skip) ++k;
  const std::optional<int> n = count(k);
  if (!n || (w == "for" && !after_table && !people(k + 1))) return std::nullopt;
  return n;
}

void Capacities(const std::vector<Token>& tokens, const std::vector<Mention>& mentions,
                const std::vector<std::optional<Category>>& bound, Category room, RoomRequest& out) {
  // Only where people sit at a table: not "a window seat for two" in a bedroom.
  if (room != Category::kDiningRoom && room != Category::kMeetingRoom && room != Category::kOffice && room != Category::kKitchen &&
      room != Category::kLivingRoom)
    return;
  const bool meets = room == Category::kMeetingRoom || room == Category::kOffice;
  const CategoryInfo* table = FindCategory(meets ? "conference-table" : "dining-table");
  const CategoryInfo* chair = FindCategory("chair");
  if (!table || !chair) return;
  for (size_t i = 0; i < tokens.size(); ++i) {
    if (!SeatsAt(tokens, i, true)) continue;  // no seats here however it is read
    // What the phrase speaks of: the nearest mention before it in its sentence (a room, or a table and
    // the room it is bound to).
    int before = -1;
    for (size_t k = 0; k < mentions.size(); ++k)
      if (mentions[k].end <= i && tokens[mentions[k].begin].sentence == tokens[i].sentence) before = static_cast<int>(k);
    const bool tabled = before >= 0 && (mentions[before].room ? (mentions[before].room_category == Category::kDiningRoom ||
                                                                 mentions[before].room_category == Category::kMeetingRoom)
                                                              : mentions[before].category->name.find("table") != std::string_view::npos);
    const std::optional<int> seats = SeatsAt(tokens, i, tabled && mentions[before].end == i);
    if (!seats) continue;
    // "a sofa that seats four", "a bench for three": the seats are that piece's, not a table's.
    if (before >= 0 && !mentions[before].room && !tabled) continue;
    const std::optional<Category> of = before < 0 ? std::optional<Category>(room)
                                       : mentions[before].room ? std::optional<Category>(mentions[before].room_category)
                                                               : bound[before];
    if (of != room) continue;
    auto find = [&](const CategoryInfo* c) {
      return std::find_if(out.wishes.begin(), out.wishes.end(), [&](const Wish& w) { return w.category == c; });
    };
    if (find(table) == out.wishes.end()) {
      Wish t;
      t.category = table;
      t.explicit_count = true;
      t.phrase = Join(tokens, i, std::min(tokens.size(), i + 3));
      out.wishes.insert(out.wishes.begin(), t);  // before the chairs it seats
      for (Wish& w : out.wishes)
        if (w.container >= 0) ++w.container;
      for (WishEdge& e : out.edges) ++e.source, ++e.target;
    }
    find(table)->seats = *seats;
    const int t = static_cast<int>(find(table) - out.wishes.begin());
    auto c = find(chair);
    if (c == out.wishes.end()) {
      Wish w;
      w.category = chair;
      w.count = *seats;
      w.explicit_count = true;
      w.phrase = Join(tokens, i, std::min(tokens.size(), i + 3));
      out.wishes.push_back(w);
      c = out.wishes.end() - 1;
    } else if (!c->explicit_count) {
      c->count = *seats;
      c->explicit_count = true;
    }
    const int seat = static_cast<int>(c - out.wishes.begin());
    out.edges.push_back({seat, SemanticRelation::kFaceTo, t});
    out.edges.push_back({seat, SemanticRelation::kNextTo, t});
  }
}

}  // namespace

// A bare count that corrects the one before it: "Dining table for four... make that six", "six chairs...
// sorry, eight", "two armchairs - no, three": the earlier count (the last number in the twelve words before
// the cue) is rewritten, and the cue's words dropped.
std::vector<Token> BareCorrections(std::vector<Token> tokens) {
  for (size_t i = 0; i + 1 < tokens.size(); ++i) {
    size_t n = 0;  // the new count's token
    if (IsOneOf(tokens[i].word, {"make", "change"}) && IsOneOf(tokens[i + 1].word, {"that", "it"})) n = i + 2 + (i + 2 < tokens.size() && tokens[i + 2].word == "to");
    else if (IsOneOf(tokens[i].word, {"sorry", "no", "wait", "oops"}) && (i == 0 || tokens[i - 1].sentence != tokens[i].sentence || !NumberWord(tokens[i - 1].word)))
      n = i + 1;
    // "for six - no wait, for eight"
    while (n > 0 && n + 1 < tokens.size() && IsOneOf(tokens[n].word, {"wait", "sorry", "actually", "for"})) ++n;
    if (n == 0 || n >= tokens.size() || tokens[n].sentence != tokens[i].sentence || !NumberWord(tokens[n].word) || *NumberWord(tokens[n].word) <= 0)
      continue;
    // A bare count: no piece or room named right after it ("make that two, by the fire" is bare).
    if (n + 1 < tokens.size() && tokens[n + 1].sentence == tokens[n].sentence &&
        (CategoryForWord(tokens[n + 1].word) || RoomOf(tokens[n + 1].word) ||
         (n + 2 < tokens.size() && (CategoryForWord(Join(tokens, n + 1, n + 3)) || RoomOf(Join(tokens, n + 1, n + 3))))))
      continue;
    for (size_t j = i; j-- > 0;) {
      if (j + 12 < i) break;  // ("..." ends three sentences: the distance is counted in words)
      if (NumberWord(tokens[j].word) && *NumberWord(tokens[j].word) > 0) {
        tokens[j].word = tokens[n].word;
        tokens.erase(tokens.begin() + static_cast<std::ptrdiff_t>(i), tokens.begin() + static_cast<std::ptrdiff_t>(n) + 1);
        break;
      }
    }
  }
  return tokens;
}

// "I wanted a TV in the living room, but actually put it in the office": the piece named last before the
// pronoun, moved.
std::vector<Token> PiecePronouns(std::vector<Token> tokens) {
  for (size_t i = 1; i + 1 < tokens.size(); ++i) {
    if (!IsOneOf(tokens[i].word, {"it", "them"}) || !IsOneOf(tokens[i - 1].word, {"put", "move", "place", "stick", "putting", "moving"}) ||
        !IsOneOf(tokens[i + 1].word, {"in", "into", "to"}))
      continue;
    for (size_t j = i - 1; j-- > 0 && tokens[j].sentence == tokens[i].sentence;) {
      if (RoomOf(tokens[j].word) || std::find(kAmbiguous.begin(), kAmbiguous.end(), tokens[j].word) != kAmbiguous.end()) continue;
      if (CategoryForWord(tokens[j].word)) {
        tokens[i].word = tokens[j].word;
        break;
      }
    }
  }
  return tokens;
}

RoomRequest ParseRoomRequest(std::string_view text, Category room, int ordinal) {
  RoomRequest out;
  std::vector<Token> tokens = PiecePronouns(BareCorrections(Misspellings(Tokenise(text))));
  std::vector<Mention> mentions = FindMentions(tokens);
  const bool names_rooms = std::any_of(mentions.begin(), mentions.end(), [](const Mention& m) { return m.room; });
  // A room mention that names one room of several: "one of the bedrooms", "a bedroom", "one bedroom",
  // "either bedroom", "any of the bedrooms".
  auto names_one = [&](const Mention& m) {
    const size_t b = m.begin;
    static const std::string kNone;
    auto word = [&](size_t back) -> const std::string& {
      return b >= back && tokens[b - back].sentence == tokens[b].sentence ? tokens[b - back].word : kNone;
    };
    if (IsOneOf(word(1), {"a", "an", "one", "either", "another"})) return true;
    // "the master bedroom", "the main bedroom": one of the bedrooms (the first), not each.
    if (IsOneOf(tokens[b].word, {"master", "main", "principal"}) || IsOneOf(word(1), {"master", "main", "principal"})) return true;
    return IsOneOf(word(1), {"the", "our", "my", "their", "your"}) && word(2) == "of" && IsOneOf(word(3), {"one", "any"});
  };

  // The room each object mention belongs to, and whether that mention named one room of several.
  std::vector<std::optional<Category>> bound(mentions.size());
  std::vector<bool> bound_one(mentions.size(), false);
  std::vector<bool> named(mentions.size(), false);  // bound by "in / for the <room>" after it
  std::optional<Category> carried;  // the room the text last spoke of, across sentences
  bool carried_one = false;
  for (size_t k = 0; k < mentions.size(); ++k) {
    const Mention& m = mentions[k];
    if (m.room) {
      carried = m.room_category;
      carried_one = names_one(m);
      continue;
    }
    if (!names_rooms) {
      bound[k] = room;
      continue;
    }
    // "... in / for / into the <room>" after the object, before any other room is named. Not across a
    // clause that names another piece when a room was named before the object in its sentence: "Each of
    // the children's bedrooms should have a bookcase, and a big rug for the living room" (the bookcase is
    // the children's rooms').
    const bool room_before = std::any_of(mentions.begin(), mentions.begin() + static_cast<std::ptrdiff_t>(k), [&](const Mention& x) {
      return x.room && tokens[x.begin].sentence == tokens[m.begin].sentence;
    });
    // Nor into a clause whose piece has a verb of its own before the room: "a dining table for six with
    // matching chairs, and my daughter's upright piano has to fit in the lounge" (the table is not the
    // lounge's).
    bool clause = false;  // "and" / "plus" / "put" since the object, then another piece
    bool own_verb = false;
    for (size_t j = k + 1; j < mentions.size(); ++j) {
      if (tokens[mentions[j].begin].sentence != tokens[m.begin].sentence) break;
      if (!mentions[j].room) {
        for (size_t t = mentions[j - 1].end; t < mentions[j].begin && !clause; ++t)
          clause = IsOneOf(tokens[t].word, {"and", "plus", "also", "put", "add"});
        if (clause && room_before) break;
        if (clause)
          for (size_t t = mentions[j].end; t < tokens.size() && t < mentions[j].end + 4 && tokens[t].sentence == tokens[m.begin].sentence; ++t)
            own_verb = own_verb || IsOneOf(tokens[t].word, {"has", "have", "goes", "go", "fit", "fits", "should", "must", "needs",
                                                            "need", "is", "are", "stands", "belongs", "will"});
        continue;
      }
      if (own_verb) break;
      size_t p = mentions[j].begin;
      while (p > m.end && IsOneOf(tokens[p - 1].word, {"the", "a", "an", "my", "our", "their", "your", "his", "her", "one", "either",
                                                        "another", "each", "every", "both", "all", "any", "other"}))
        --p;
      // "an armchair by the lounge window": by a part of the room is in it.
      const size_t after = mentions[j].end;
      const bool part_after = after < tokens.size() && tokens[after].sentence == tokens[m.begin].sentence &&
                              IsOneOf(tokens[after].word, {"window", "windows", "wall", "door", "fireplace", "fire", "corner"});
      if (part_after && p > m.end && IsOneOf(tokens[p - 1].word, {"by", "near", "beside", "at", "against"})) {
        bound[k] = mentions[j].room_category;
        bound_one[k] = names_one(mentions[j]);
        named[k] = true;
        break;
      }
      // "in one of the bedrooms": the determiners before the room, then "one of".
      // ("in 1 of the bthrms", "in each of the 2 bathrooms" too.)
      if (p > m.end + 1 && NumberWord(tokens[p - 1].word) && IsOneOf(tokens[p - 2].word, {"the", "our", "my"})) p -= 2;
      while (p > m.end + 2 && tokens[p - 1].word == "of" && IsOneOf(tokens[p - 2].word, {"one", "any", "1", "each", "both", "all"})) p -= 2;
      // ("3 plants on the balcony", "a table on the terrace".)
      const bool on = mentions[j].room_category == Category::kBalcony && IsOneOf(tokens[p - 1].word, {"on", "onto", "out"});
      // (Nor a fixture across another piece into a room it does not fit: "Walk-in shower rather than a bath,
      // and a comfy armchair in the sitting room".)
      if (p > m.end && (on || IsOneOf(tokens[p - 1].word, {"in", "for", "into", "inside", "to"})) && !OutOfPlace(m.category->name, mentions[j].room_category) &&
          (!clause || FitsRoom(m.category->name, mentions[j].room_category))) {
        bound[k] = mentions[j].room_category;
        bound_one[k] = names_one(mentions[j]);
        named[k] = true;
      }
      break;
    }
    if (!bound[k]) {
      for (size_t j = k; j-- > 0;) {
        if (tokens[mentions[j].begin].sentence != tokens[m.begin].sentence) break;
        if (mentions[j].room) {
          bound[k] = mentions[j].room_category;
          bound_one[k] = names_one(mentions[j]);
          break;
        }
      }
    }
    // An armchair after "... and a wet room." is not the bathroom's by nearness, nor any room's.
    if (!bound[k] && carried && OutOfPlace(m.category->name, *carried)) continue;
    if (!bound[k]) {
      bound[k] = carried;
      bound_one[k] = carried_one;
      // "TV in lounge. Dining tbl + 6 chairs.": a dining table in a sentence that names no room is the dining
      // room's, not the room spoken of before, and what follows it in its sentence goes with it.
      const bool room_in_sentence = std::any_of(mentions.begin(), mentions.end(), [&](const Mention& x) {
        return x.room && tokens[x.begin].sentence == tokens[m.begin].sentence;
      });
      if (!room_in_sentence && m.category->name == "dining-table" && carried && *carried != Category::kDiningRoom &&
          *carried != Category::kKitchen) {
        bound[k] = carried = Category::kDiningRoom;
        bound_one[k] = carried_one = false;
      }
    }
    // Nor is a dining table an office's or a bathroom's by nearness: "The office gets three bookcases, and we
    // want a dining table for six" (the chairs after it go with it).
    if (bound[k] && !named[k] && m.category->name == "dining-table" && *bound[k] != Category::kDiningRoom &&
        *bound[k] != Category::kKitchen && *bound[k] != Category::kLivingRoom) {
      bound[k] = carried = Category::kDiningRoom;
      bound_one[k] = carried_one = false;
    }
    // A fixture of another kind of room is not carried into one by nearness alone: a bed named on a line
    // after "... guest WC" is no bathroom's ("a bed in the lounge" still is the lounge's).
    if (bound[k] && !named[k] && !FitsRoom(m.category->name, *bound[k])) {
      bound[k].reset();
      // "Walk-in shower rather than a bath, please" after "... a shower room and a small study": a fixture
      // of one kind of room is that kind's when the text names one.
      for (Category fits : {Category::kBathroom, Category::kKitchen})
        if (FitsRoom(m.category->name, fits) && !FitsRoom(m.category->name, Category::kLivingRoom) &&
            std::any_of(mentions.begin(), mentions.end(), [&](const Mention& x) { return x.room && x.room_category == fits; })) {
          bound[k] = fits;
          bound_one[k] = false;
        }
      if (!bound[k]) continue;
    }
    // Named before any room: the text is meant for the room being planned.
    if (!bound[k]) bound[k] = room;
  }

  // Second thoughts: "a desk in the bedroom - actually no, put the desk in the study", "two sofas ... but one
  // sofa is plenty": a later mention of the same thing after "actually", "instead", "rather", "on second
  // thought" or "make that", or one that "is plenty" / "is enough", replaces the earlier ones (their rooms and
  // counts).
  for (size_t k = 0; k < mentions.size(); ++k) {
    const Mention& m = mentions[k];
    if (m.room) continue;
    bool replaces = false;
    for (size_t t = m.end; t < tokens.size() && t < m.end + 3 && tokens[t].sentence == tokens[m.begin].sentence; ++t)
      replaces = replaces || (IsOneOf(tokens[t].word, {"is", "will", "would"}) && t + 1 < tokens.size() &&
                              IsOneOf(tokens[t + 1].word, {"plenty", "enough", "fine", "sufficient"}));
    for (size_t j = k; j-- > 0 && !replaces;) {
      if (mentions[j].room || mentions[j].category != m.category) continue;
      for (size_t t = mentions[j].end; t < m.begin && !replaces; ++t)
        replaces = IsOneOf(tokens[t].word, {"actually", "instead", "rather", "scratch"}) ||
                   (tokens[t].word == "second" && t + 1 < m.begin && IsOneOf(tokens[t + 1].word, {"thought", "thoughts"})) ||
                   (tokens[t].word == "make" && t + 1 < m.begin && tokens[t + 1].word == "that");
      break;  // only the nearest earlier mention of the thing is looked back from
    }
    if (!replaces) continue;
    for (size_t j = 0; j < k; ++j)
      if (!mentions[j].room && mentions[j].category == m.category) bound[j].reset();
  }

  // Wishes for this room, and how they relate.
  std::vector<int> wish_of(mentions.size(), -1);
  size_t floor = 0;  // counts are not read across an earlier mention
  for (size_t k = 0; k < mentions.size(); ++k) {
    const Mention& m = mentions[k];
    if (m.room) {
      floor = m.end;
      continue;
    }
    if (!bound[k] || *bound[k] != room) {
      if (bound[k]) out.other_rooms.push_back(std::string(m.category->name) + " (" + std::string(CategoryName(*bound[k])) + ")");
      floor = m.end;
      continue;
    }
    if (bound_one[k] && ordinal > 0) {  // for one room of this category: the first has it
      out.other_rooms.push_back(std::string(m.category->name) + " (the first " + std::string(CategoryName(room)) + ")");
      floor = m.end;
      continue;
    }
    Wish wish;
    wish.category = m.category;
    wish.phrase = Join(tokens, m.begin, m.end);
    CountBefore(tokens, m, floor, wish);
    floor = m.end;
    // "the sofa" after "a sofa" is the same sofa: a definite or count-less mention of a category already
    // wished for refers back to it.
    bool definite = m.begin > 0 && IsOneOf(tokens[m.begin - 1].word, {"the", "this", "that", "its", "their"});
    auto earlier = std::find_if(out.wishes.begin(), out.wishes.end(), [&](const Wish& w) { return w.category == m.category; });
    if (earlier != out.wishes.end() && (definite || !wish.explicit_count)) {
      wish_of[k] = static_cast<int>(earlier - out.wishes.begin());
      continue;
    }
    wish_of[k] = static_cast<int>(out.wishes.size());
    out.wishes.push_back(wish);
  }

  static const RelationPhrase kRelations[] = {
      {{"in", "front", "of"}, SemanticRelation::kFrontOf}, {{"next", "to"}, SemanticRelation::kNextTo},
      {{"facing"}, SemanticRelation::kFaceTo},             {{"opposite"}, SemanticRelation::kFaceTo},
      {{"beside"}, SemanticRelation::kNextTo},             {{"by"}, SemanticRelation::kNextTo},
      {{"near"}, SemanticRelation::kNear},                 {{"behind"}, SemanticRelation::kBehind},
      {{"left", "of"}, SemanticRelation::kLeftOf},         {{"right", "of"}, SemanticRelation::kRightOf},
      {{"above"}, SemanticRelation::kBehind},              {{"over"}, SemanticRelation::kBehind},
  };
  for (size_t k = 0; k < mentions.size(); ++k) {
    if (wish_of[k] < 0) continue;
    Wish& wish = out.wishes[wish_of[k]];
    const Mention& m = mentions[k];
    size_t at = m.end;
    // The next object mention, if it follows within a few words.
    auto next_object = [&](size_t from) -> int {
      for (size_t j = k + 1; j < mentions.size(); ++j) {
        if (mentions[j].begin < from) continue;
        if (mentions[j].begin > from + 3 || mentions[j].room) return -1;
        return wish_of[j];
      }
      return -1;
    };
    // Containment: "full of", "filled with", "stocked with", "lined with".
    for (auto phrase : {std::initializer_list<std::string_view>{"full", "of"}, {"filled", "with"}, {"stocked", "with"},
                        {"lined", "with"}, {"packed", "with"}}) {
      if (!WordsAt(tokens, at, phrase)) continue;
      int inner = next_object(at + phrase.size());
      if (inner >= 0) {
        Wish& child = out.wishes[inner];
        child.container = wish_of[k];
        child.relation = wish.category->has_cavity ? Relation::kInside : Relation::kOnTop;
        child.fill = !child.explicit_count;
      }
    }
    // "on (the) X" / "in (the) X" / "inside X": a parent among the named objects.
    for (std::string_view prep : {"on", "in", "inside", "onto"}) {
      if (at >= tokens.size() || tokens[at].word != prep || tokens[at].sentence != tokens[m.begin].sentence) continue;
      int parent = next_object(SkipDeterminers(tokens, at + 1));
      if (parent < 0 || parent == wish_of[k]) continue;
      const CategoryInfo* pc = out.wishes[parent].category;
      bool inside = prep != "on" && prep != "onto";
      if (inside ? pc->has_cavity : pc->has_surface) {
        wish.container = parent;
        wish.relation = inside ? Relation::kInside : Relation::kOnTop;
      }
    }
    // Places in the room.
    size_t place = SkipDeterminers(tokens, at + 1);
    bool prep_place = at < tokens.size() && IsOneOf(tokens[at].word, {"by", "near", "at", "under", "beside", "facing", "in", "into", "to"});
    if (WordsAt(tokens, at, {"next", "to"})) {
      place = SkipDeterminers(tokens, at + 2);
      prep_place = true;
    }
    if (prep_place && place < tokens.size() && IsOneOf(tokens[place].word, {"window", "windows"}))
      wish.hints.emplace_back(kHintNearWindow);
    if (WordsAt(tokens, at, {"far", "from"}) || WordsAt(tokens, at, {"away", "from"})) {
      size_t what = SkipDeterminers(tokens, at + 2);
      if (what < tokens.size() && IsOneOf(tokens[what].word, {"door", "doors", "entrance"})) wish.hints.emplace_back(kHintFarFromDoor);
    }
    if (at < tokens.size() && IsOneOf(tokens[at].word, {"in", "into"}) && place < tokens.size()) {
      if (IsOneOf(tokens[place].word, {"corner", "corners"})) wish.hints.emplace_back(kHintCorner);
      if (IsOneOf(tokens[place].word, {"middle", "centre", "center"})) wish.hints.emplace_back(kHintMiddle);
    }
    // Relations to the next named object.
    for (const RelationPhrase& r : kRelations) {
      if (!WordsAt(tokens, at, r.words)) continue;
      int target = next_object(SkipDeterminers(tokens, at + r.words.size()));
      if (target < 0 || target == wish_of[k]) continue;
      out.edges.push_back({wish_of[k], r.relation, target});
      if (r.words.size() == 1 && (*r.words.begin() == "above" || *r.words.begin() == "over"))
        out.edges.push_back({wish_of[k], SemanticRelation::kCentered, target});
      if (*r.words.begin() == "opposite") out.edges.push_back({target, SemanticRelation::kFaceTo, wish_of[k]});
      break;
    }
    // "a table with four chairs": seats around the table.
    if (WordsAt(tokens, at, {"with"})) {
      int seat = next_object(at + 1);
      if (seat >= 0 && IsSeat(out.wishes[seat].category) && wish.category->has_surface) {
        out.edges.push_back({seat, SemanticRelation::kFaceTo, wish_of[k]});
        out.edges.push_back({seat, SemanticRelation::kNextTo, wish_of[k]});
      }
    }
  }
  Capacities(tokens, mentions, bound, room, out);
  // "a dining table big enough for all of us ..., so eight chairs around it": a table no number sizes is
  // sized for the chairs asked with it (the planner makes it long enough for them where the room allows).
  for (Wish& t : out.wishes) {
    if (t.seats > 0 || (t.category->name != "dining-table" && t.category->name != "conference-table")) continue;
    for (const Wish& c : out.wishes)
      if (c.category->name == "chair" && c.explicit_count && c.count >= 3) t.seats = std::max(t.seats, c.count);
  }
  return out;
}

}  // namespace villa::scene
