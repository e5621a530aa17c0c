// The brief parser: tokeniser, phrase lexicons, and a per-sentence interpretation of what was matched
// (counts, floors, connections, attachments). See brief.h for what it understands.
#include "generator/text/brief.h"

#ifdef VILLA_HAVE_ASSET_VOCABULARY
#include "assets/category.h"
#endif

#include <algorithm>
#include <array>
#include <cctype>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

#include "util/spelling.h"

namespace villa {
namespace {

using Json = nlohmann::ordered_json;

// ---------------------------------------------------------------------------------------------------
// Tokens

struct Token {
  std::string word;  // lower-case, apostrophes dropped ("children's" -> "children", "don't" -> "dont")
  std::string stem;  // singular form of `word`
  std::size_t begin = 0;
  std::size_t end = 0;
  bool joined = false;  // glued to the previous token by a hyphen ("three-story")
  char punct = 0;       // non-zero: a punctuation token
  bool number = false;  // all digits
  int value = 0;        // its value when `number`
  bool negative = false;  // a number written with a minus sign before it ("-3 bedrooms"): no count
  int ordinal = 0;      // "1st", "2nd", ... as digits
  int sentence = 0;
  bool consumed = false;  // part of something understood
  bool filler = false;    // a word that carries no requirement (articles, politeness, "villa", ...)
  int item = -1;          // the item it belongs to
};

bool IsWordByte(unsigned char c) { return std::isalnum(c) || c >= 0x80; }

std::string Singular(const std::string& w) {
  static const std::unordered_map<std::string, std::string> kIrregular = {
      {"shelves", "shelf"}, {"children", "children"}, {"stories", "story"}, {"storeys", "storey"},
      {"series", "series"}, {"glass", "glass"}, {"bus", "bus"}, {"this", "this"}, {"its", "its"},
      {"has", "has"}, {"was", "was"}, {"is", "is"}, {"us", "us"}, {"yes", "yes"}, {"does", "does"},
      {"always", "always"}, {"plus", "plus"}, {"ensuites", "ensuite"}, {"wcs", "wc"}, {"tvs", "tv"},
      {"couches", "couch"}, {"benches", "bench"}, {"lavatories", "lavatory"}, {"nurseries", "nursery"},
      {"studies", "study"}, {"balconies", "balcony"}, {"libraries", "library"}, {"verandas", "veranda"},
      {"less", "less"}, {"across", "across"}, {"upstairs", "upstairs"}, {"downstairs", "downstairs"},
      {"stairs", "stairs"}, {"towards", "towards"}, {"kids", "kid"}, {"lounges", "lounge"},
      {"offices", "office"}, {"terraces", "terrace"}, {"wardrobes", "wardrobe"}, {"houses", "house"},
      {"spaces", "space"}, {"places", "place"}, {"sides", "side"}, {"suites", "suite"},
  };
  if (auto it = kIrregular.find(w); it != kIrregular.end()) return it->second;
  if (w.size() > 7 && w.ends_with("shelves")) return w.substr(0, w.size() - 3) + "f";  // "bookshelves"
  if (w.size() > 4 && w.ends_with("ies")) return w.substr(0, w.size() - 3) + "y";
  if (w.size() > 4 && (w.ends_with("ches") || w.ends_with("shes") || w.ends_with("sses") || w.ends_with("xes")))
    return w.substr(0, w.size() - 2);
  if (w.size() > 3 && w.back() == 's' && !w.ends_with("ss") && !w.ends_with("us") && !w.ends_with("is"))
    return w.substr(0, w.size() - 1);
  return w;
}

std::vector<Token> Tokenise(std::string_view text) {
  std::vector<Token> tokens;
  std::size_t i = 0;
  int sentence = 0;
  int depth = 0;  // brackets open
  bool pending_hyphen = false;
  auto is_apostrophe = [&](std::size_t at) -> int {  // byte length of an apostrophe at `at`, or 0
    if (at < text.size() && text[at] == '\'') return 1;
    if (at + 2 < text.size() && static_cast<unsigned char>(text[at]) == 0xE2 &&
        static_cast<unsigned char>(text[at + 1]) == 0x80 && static_cast<unsigned char>(text[at + 2]) == 0x99)
      return 3;
    return 0;
  };
  while (i < text.size()) {
    unsigned char c = static_cast<unsigned char>(text[i]);
    // "Lounge ×2": the multiplication sign is the letter x of "x2"; en and em dashes and bullets are
    // the hyphen of a list ("Level 1 – office", "• Kitchen").
    auto byte = [&](std::size_t k) { return k < text.size() ? static_cast<unsigned char>(text[k]) : 0; };
    const bool times = c == 0xC3 && byte(i + 1) == 0x97;
    const bool dash = c == 0xE2 && byte(i + 1) == 0x80 && (byte(i + 2) == 0x93 || byte(i + 2) == 0x94 || byte(i + 2) == 0xA2);
    if (times || dash) {
      Token t;
      t.begin = i;
      t.end = i + (times ? 2 : 3);
      t.punct = times ? 0 : '-';
      t.word = t.stem = times ? "x" : "-";
      t.sentence = sentence;
      i = t.end;
      tokens.push_back(std::move(t));
      continue;
    }
    // A word starts at a letter, a digit or a UTF-8 lead byte (never inside a multi-byte character).
    if (IsWordByte(c) && !(c >= 0x80 && c < 0xC0) && !is_apostrophe(i)) {
      Token t;
      t.begin = i;
      std::string word;
      while (i < text.size()) {
        unsigned char d = static_cast<unsigned char>(text[i]);
        if (int a = is_apostrophe(i); a) {
          // "children's" -> "children"; "don't" -> "dont"; "kids'" -> "kids".
          std::size_t after = i + a;
          if (after < text.size() && IsWordByte(static_cast<unsigned char>(text[after])) &&
              !is_apostrophe(after)) {
            std::size_t j = after;
            while (j < text.size() && IsWordByte(static_cast<unsigned char>(text[j])) && !is_apostrophe(j)) ++j;
            std::string tail(text.substr(after, j - after));
            for (auto& ch : tail) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
            if (tail != "s") word += tail;
            i = j;
          } else {
            i = after;
          }
          break;
        }
        if (!IsWordByte(d)) break;
        // Digits followed by a decimal point and digits stay one number ("2.5").
        if (d == '.' && i + 1 < text.size() && !word.empty() && std::isdigit(static_cast<unsigned char>(word.back())) &&
            std::isdigit(static_cast<unsigned char>(text[i + 1]))) {
          word += '.';
          ++i;
          continue;
        }
        word += static_cast<char>(std::tolower(d));
        ++i;
      }
      // A decimal point inside a number was consumed by the loop above only when followed by a digit.
      while (i < text.size() && text[i] == '.' && i + 1 < text.size() &&
             std::isdigit(static_cast<unsigned char>(text[i + 1])) && !word.empty() &&
             std::all_of(word.begin(), word.end(), [](char ch) { return std::isdigit(static_cast<unsigned char>(ch)) || ch == '.'; })) {
        word += '.';
        ++i;
        while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) word += text[i++];
      }
      t.end = i;
      t.word = word;
      t.joined = pending_hyphen;
      pending_hyphen = false;
      t.sentence = sentence;
      if (!word.empty() && std::all_of(word.begin(), word.end(), [](char ch) { return std::isdigit(static_cast<unsigned char>(ch)); })) {
        t.number = true;
        t.value = word.size() > 6 ? 1000000 : std::stoi(word);
        // A minus sign right before it, not a hyphen joining words ("-3 bedrooms", not "3-bedroom").
        t.negative = t.begin > 0 && text[t.begin - 1] == '-' && (t.begin == 1 || !IsWordByte(static_cast<unsigned char>(text[t.begin - 2])));
      } else if (word.size() >= 3 && word.size() <= 4 && word.compare(word.size() - 2, 2, ".5") == 0 &&
                 std::all_of(word.begin(), word.end() - 2, [](char ch) { return std::isdigit(static_cast<unsigned char>(ch)); })) {
        // "2.5 baths": two and a half bathrooms are three rooms (the half bath is a room too).
        t.number = true;
        t.value = std::stoi(word.substr(0, word.size() - 2)) + 1;
      } else if (word.size() >= 3 && std::isdigit(static_cast<unsigned char>(word[0]))) {
        std::string digits, suffix;
        std::size_t k = 0;
        while (k < word.size() && std::isdigit(static_cast<unsigned char>(word[k]))) digits += word[k++];
        suffix = word.substr(k);
        if ((suffix == "st" || suffix == "nd" || suffix == "rd" || suffix == "th") && digits.size() < 4) {
          t.ordinal = std::stoi(digits);
        } else if (digits.size() < 4 && std::all_of(suffix.begin(), suffix.end(), [](char ch) { return std::isalpha(static_cast<unsigned char>(ch)); })) {
          // "2br", "3bed", "1ba": the count and the word, two tokens.
          Token count = t;
          count.end = t.begin + digits.size();
          count.word = count.stem = digits;
          count.number = true;
          count.value = std::stoi(digits);
          tokens.push_back(std::move(count));
          t.begin += digits.size();
          t.joined = false;
          t.word = word = suffix;
        }
      }
      t.stem = Singular(word);
      tokens.push_back(std::move(t));
      continue;
    }
    if (c == '-' && !tokens.empty() && tokens.back().punct == 0 && tokens.back().end == i && i + 1 < text.size() &&
        IsWordByte(static_cast<unsigned char>(text[i + 1]))) {
      pending_hyphen = true;
      ++i;
      continue;
    }
    pending_hyphen = false;
    // "Floors ... 1", "Rooms.....bedroom, bathroom" (a form's leaders): a run of dots is a colon.
    if (c == '.' && i + 1 < text.size() && text[i + 1] == '.') {
      Token t;
      t.begin = i;
      while (i < text.size() && (text[i] == '.' || (text[i] == ' ' && i + 1 < text.size() && text[i + 1] == '.'))) ++i;
      t.end = i;
      t.punct = ':';
      t.sentence = sentence;
      t.word = ":";
      t.stem = t.word;
      tokens.push_back(t);
      continue;
    }
    // Inside brackets only a line break ends a sentence: "one bath (with a bathtub, not a shower!) upstairs".
    if (c == '(') ++depth;
    else if (c == ')' && depth > 0) --depth;
    else if (c == '\n') depth = 0;
    const bool ends_sentence = c == '\n' || (depth == 0 && (c == '.' || c == '!' || c == '?' || c == ';'));
    if (ends_sentence || c == ',' || c == ':' || c == '(' || c == ')' || c == '/' || c == '&' || c == '+' || c == '|' ||
        c == '-' || c == '*' || c == '=') {
      Token t;
      t.begin = i;
      t.end = i + 1;
      t.punct = static_cast<char>(c);
      t.sentence = sentence;
      t.word = std::string(1, static_cast<char>(c));
      t.stem = t.word;
      tokens.push_back(std::move(t));
      if (ends_sentence) ++sentence;
      ++i;
      continue;
    }
    // Quotes, spaces and other symbols carry nothing; skip a whole multi-byte character at once.
    if (int a = is_apostrophe(i); a) i += a;
    else ++i;
  }
  return tokens;
}

// ---------------------------------------------------------------------------------------------------
// Word classes

const std::unordered_map<std::string, int>& CardinalWords() {
  static const std::unordered_map<std::string, int> words = {
      {"zero", 0}, {"one", 1}, {"two", 2}, {"three", 3}, {"four", 4}, {"five", 5}, {"six", 6},
      {"seven", 7}, {"eight", 8}, {"nine", 9}, {"ten", 10}, {"eleven", 11}, {"twelve", 12},
      {"single", 1}, {"double", 2}, {"triple", 3}};
  return words;
}

std::optional<int> Cardinal(const Token& t) {
  if (t.punct || t.negative) return std::nullopt;
  if (t.number) return t.value;
  auto it = CardinalWords().find(t.word);
  if (it != CardinalWords().end()) return it->second;
  return std::nullopt;
}

std::optional<int> Ordinal(const Token& t) {
  static const std::unordered_map<std::string, int> words = {
      {"first", 1}, {"second", 2}, {"third", 3}, {"fourth", 4}, {"fifth", 5}, {"sixth", 6}};
  if (t.ordinal) return t.ordinal;
  auto it = words.find(t.word);
  if (it != words.end()) return it->second;
  return std::nullopt;
}

// Children named as people ("three kids", "for each son"); `plural`: the plural forms only.
bool IsChildWord(const Token& t, bool plural) {
  static const std::unordered_set<std::string> singular = {"kid", "child", "son", "daughter", "boy", "girl", "teen",
                                                           "teenager", "grandchild", "twin"};
  if (t.punct) return false;
  if (t.word == "children" || t.word == "grandchildren") return true;
  return singular.count(t.stem) > 0 && (!plural || t.stem != t.word);
}

bool IsFloorNoun(const Token& t) {
  static const std::unordered_set<std::string> nouns = {"floor", "story", "storey", "level", "storied",
                                                        "storeyed", "stories", "storeys", "floors", "levels",
                                                        "fl", "flr", "flrs", "lvl", "lvls"};
  return !t.punct && (nouns.count(t.stem) || nouns.count(t.word));
}

bool In(const Token& t, std::initializer_list<std::string_view> words) {
  for (auto w : words)
    if (t.word == w || t.stem == w) return true;
  return false;
}

// Words that carry no requirement of their own: they are understood as glue and never reported.
const std::unordered_set<std::string>& FillerWords() {
  static const std::unordered_set<std::string> words = {
      // articles, pronouns, conjunctions, prepositions
      "a", "an", "the", "this", "that", "these", "those", "it", "its", "they", "them", "their", "there",
      "here", "i", "me", "my", "we", "us", "our", "you", "your", "he", "she", "his", "her", "and", "or",
      "but", "nor", "so", "as", "of", "for", "to", "in", "on", "at", "by", "from", "into", "onto", "with",
      "within", "inside", "upon", "over", "across", "throughout", "between", "also", "too", "well",
      "both", "each", "every", "all", "any", "some", "which", "where", "what", "who", "whose", "whom",
      "then", "than", "while", "whereas", "plus", "including", "include", "includes", "included",
      "along", "together", "other", "another", "such", "either", "neither", "just", "only", "one",
      "ones", "if", "possible", "ideally", "preferably", "maybe", "perhaps", "altogether", "total",
      "overall", "in", "about", "around", "like", "alike", "same", "more", "most", "much", "many", "very",
      "really", "quite", "rather", "somewhat", "really", "s", "etc", "e", "g", "ie", "eg", "x", "via",
      "through", "up", "out", "down", "off", "per", "respectively", "additionally", "addition",
      "furthermore", "moreover", "finally", "lastly", "first", "firstly", "second", "secondly", "next",
      "then", "further", "else", "whole", "entire", "rest", "remaining", "other", "others", "own",
      "directly", "direct", "immediately", "right", "straight", "conveniently", "easily", "kindly",
      // verbs of wanting, having, building, placing
      "want", "wants", "wanted", "would", "like", "love", "need", "needs", "needed", "require",
      "requires", "required", "hope", "wish", "prefer", "please", "thank", "thanks", "can", "could",
      "should", "must", "may", "might", "will", "shall", "be", "is", "are", "was", "were", "been",
      "being", "am", "have", "has", "had", "having", "do", "does", "did", "get", "got", "let", "make",
      "made", "build", "built", "building", "design", "designed", "designing", "create", "created",
      "plan", "planned", "planning", "place", "placed", "put", "add", "added", "provide", "provided",
      "contain", "contains", "containing", "feature", "features", "featuring", "featured", "hold",
      "holds", "holding", "house", "houses", "housing", "offer", "offers", "give", "gives", "host",
      "hosts", "keep", "set", "sit", "sits", "lie", "lies", "located", "situated", "positioned",
      "arranged", "arrange", "find", "found", "see", "go", "goes", "come", "comes", "take", "takes",
      "use", "used", "serve", "serves", "serving", "equip", "equipped", "furnish", "furnished",
      "fit", "fitted", "occupy", "occupies", "stack", "stacked", "spread", "split", "divided",
      "distributed", "organised", "organized", "laid", "lay", "layout", "come", "look", "looking",
      "think", "thinking", "imagine", "picture", "envision", "dream", "consider", "request", "asking",
      "ask", "suggest", "wanting", "needing", "sketch", "draw", "generate", "produce", "new", "own",
      "reserve", "reserved", "dedicate", "dedicated", "allocate", "allocated", "go", "follow",
      "following", "below", "above", "overall", "share", "shares", "shared", "rise", "rises",
      // the building itself and generic nouns
      "villa", "home", "building", "residence", "mansion", "cottage", "dwelling", "property", "family",
      "detached", "semi", "terraced", "townhouse", "farmhouse", "colonial", "craftsman", "victorian",
      "georgian", "cabin", "chalet", "pavilion", "lodge",
      "footprint", "structure", "floorplan", "project", "place", "space", "area", "room", "rooms",
      "design", "style", "version", "option", "setup", "arrangement", "configuration", "program",
      "programme", "brief", "request", "requirement", "requirements", "spec", "specification",
      "summary", "note", "notes", "detail", "details", "yes", "no", "ok", "okay", "hi", "hello",
      "dear", "regards", "architect", "everything", "something", "thing", "things", "lot", "lots",
      "kind", "sort", "type", "way", "part", "stairs", "staircase", "stairway", "stair", "staircases",
      "stairwell", "window", "windows", "wall", "walls", "door", "doors", "shaped", "shape", "form",
      "floors", "mix", "people", "guests", "guest", "friends", "kid", "kids", "children", "parents",
      "nook", "breakfast", "im", "ive", "id", "youre", "theyre", "its", "count", "storey", "story", "wed", "weve", "youd",
      "youll", "ill", "itll", "thats", "theres", "heres", "whats", "lets", "hes", "shes", "theyll", "hoping",
      "looking", "searching", "wondering", "planning", "considering", "thinking", "floor", "number",
      "connections", "furniture", "extras", "layouts", "storeys", "stories", "levels", "great",
      // quality adjectives and adverbs that ask for nothing checkable
      "large", "big", "huge", "spacious", "generous", "roomy", "small", "little", "compact", "tiny",
      "cozy", "cosy", "bright", "sunny", "airy", "light", "modern", "contemporary", "classic",
      "traditional", "elegant", "luxurious", "luxury", "comfortable", "nice", "beautiful", "lovely",
      "good", "great", "quiet", "calm", "simple", "practical", "functional", "separate", "private",
      "additional", "extra", "main", "decent", "proper", "sizable", "sizeable", "wide", "long",
      "bigger", "smaller", "larger", "warm", "welcoming", "open", "convenient", "typical", "standard",
      "usual", "neat", "clean", "fine", "real", "actual", "dream", "perfect", "ideal", "charming",
      "stylish", "lavish", "formal", "informal", "casual", "grand", "stunning", "gorgeous", "pleasant", "relaxing", "peaceful",
      "fully", "nicely", "properly", "generously", "comfortably", "totally", "exactly", "precisely",
      "approximately", "roughly", "least", "most", "highly", "clearly", "simply", "naturally",
      "respective", "individual", "current", "several", "multiple", "few", "couple", "pair",
      "number", "also", "always", "definitely", "certainly", "absolutely", "especially",
      "particularly", "mainly", "mostly", "primarily", "primary", "important", "essential", "key",
      "nearby", "close", "near", "adjacent", "beside", "next", "side", "end", "corner", "part",
      "portion", "half", "wing", "toward", "towards", "facing", "face", "faces", "level",
      "hmm", "um", "uh", "oh", "plenty", "enough", "holiday", "vacation", "weekend", "eat",
  };
  return words;
}

bool IsFiller(const Token& t) {
  if (t.punct) return true;
  return FillerWords().count(t.word) > 0 || FillerWords().count(t.stem) > 0;
}

// Words allowed between a quantifier and its room noun ("two large, bright bedrooms").
bool IsAdjective(const Token& t) {
  static const std::unordered_set<std::string> words = {
      "large", "big", "huge", "spacious", "generous", "roomy", "small", "little", "compact", "tiny",
      "cozy", "cosy", "bright", "sunny", "airy", "light", "modern", "contemporary", "classic",
      "elegant", "luxurious", "comfortable", "nice", "beautiful", "lovely", "good", "great", "quiet",
      "simple", "practical", "functional", "separate", "private", "additional", "extra", "main",
      "decent", "proper", "sizable", "sizeable", "wide", "warm", "welcoming", "open", "plan", "own",
      "attached", "en", "suite", "ensuite", "full", "half", "dedicated", "shared", "second", "third",
      "further", "new", "more", "stylish", "calm", "peaceful", "formal", "informal", "cosy", "home",
      "adjoining", "connected", "spare", "fully", "equipped", "well", "lit", "sized", "large-sized", "guest",
      "family"};
  return !t.punct && (words.count(t.word) > 0 || words.count(t.stem) > 0);
}

bool IsNegation(const Token& t) {
  return In(t, {"no", "not", "without", "dont", "doesnt", "never", "zero", "nor", "neither", "cannot",
                "wont", "none", "exclude", "excluding", "except", "skip", "omit", "cant", "shouldnt",
                "wouldnt", "isnt", "arent", "didnt", "forget", "scratch", "ditch", "cancel"});
}

// ---------------------------------------------------------------------------------------------------
// Lexicons: phrases as sequences of stems (hyphens and apostrophes already gone).

struct Phrase {
  std::vector<std::string> words;
};

std::vector<std::string> Split(std::string_view s) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : s) {
    if (c == ' ') {
      if (!cur.empty()) out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

// Length of the match of `phrase` at tokens[i], 0 if none. Words match a token's word or stem.
int MatchPhrase(const std::vector<Token>& tokens, std::size_t i, const std::vector<std::string>& phrase) {
  if (i + phrase.size() > tokens.size()) return 0;
  for (std::size_t k = 0; k < phrase.size(); ++k) {
    const Token& t = tokens[i + k];
    if (t.punct || t.item >= 0) return 0;
    if (k > 0 && t.sentence != tokens[i].sentence) return 0;
    if (t.word != phrase[k] && t.stem != phrase[k]) return 0;
  }
  return static_cast<int>(phrase.size());
}

struct RoomWord {
  std::vector<std::string> words;
  Category category;
  bool ensuite = false;    // "en-suite", "ensuite": a bathroom of a bedroom
  bool open_plan = false;  // "open-plan kitchen"
};

const std::vector<RoomWord>& RoomLexicon() {
  static const std::vector<RoomWord> lexicon = [] {
    std::vector<RoomWord> out;
    auto add = [&](Category c, std::initializer_list<std::string_view> phrases, bool ensuite = false,
                   bool open_plan = false) {
      for (auto p : phrases) out.push_back({Split(p), c, ensuite, open_plan});
    };
    using C = Category;
    add(C::kLivingRoom, {"living room", "living", "lounge", "sitting room", "family room", "living area",
                         "living space", "salon", "drawing room", "parlor", "parlour", "great room",
                         "tv room", "media room", "day room", "living hall", "livingroom", "living-room",
                         "lounge area", "sitting area", "den", "reception room", "snug", "front room", "living rm",
                         "games room", "game room", "rumpus room", "family area"});
    add(C::kBedroom, {"bedroom", "master bedroom", "main bedroom", "primary bedroom", "guest bedroom",
                      "guest room", "master suite", "sleeping room", "bed room", "parent bedroom",
                      "parents bedroom", "parent room", "parents room", "double bedroom", "spare bedroom",
                      "spare room", "master", "principal bedroom", "adult bedroom", "sleeping area", "box room",
                      "twin room", "twin bedroom", "primary suite", "guest suite", "double room", "bedrm", "bdrm",
                      "br", "doubles", "master bed"});  // "two doubles and a box room" (the plural only: a "double" is a bed)
    add(C::kKitchen, {"kitchen", "kitchenette", "cooking area", "galley kitchen", "cookhouse", "kitchen diner",
                      "eat in kitchen", "kitchen breakfast room", "kitchen breakfast area", "kitchen breakfast"});
    add(C::kKitchen, {"open plan kitchen", "open kitchen", "openplan kitchen"}, false, true);
    add(C::kBathroom, {"bathroom", "bath room", "wc", "toilet", "washroom", "restroom", "lavatory",
                       "powder room", "shower room", "wet room", "half bath", "full bath", "bath", "loo",
                       "water closet", "toilet room", "bathroom suite", "shower", "cloakroom", "cloakroom wc",
                       "cloakroom toilet", "cloakroom loo", "downstairs loo", "guest loo", "bathrm", "ba", "hall bath", "guest bath", "guest bathroom",
                       "jack and jill bathroom", "jack and jill bath"});
    add(C::kBathroom, {"en suite bathroom", "ensuite bathroom", "en suite", "ensuite", "en suite shower room",
                       "ensuite shower room", "en suite wc", "ensuite wc", "attached bathroom",
                       "private bathroom", "own bathroom", "en suite bath", "ensuite bath", "own bath"},
        true);
    add(C::kDiningRoom, {"dining room", "dining", "dining area", "dining hall", "dining space",
                         "breakfast room", "eating area", "dining corner", "diningroom", "dining-room", "dining rm"});
    add(C::kChildrenRoom, {"children room", "child room", "kid room", "kids room", "kid bedroom",
                           "kids bedroom", "children bedroom", "child bedroom", "nursery", "playroom",
                           "play room", "baby room", "youth room", "teen room", "kiddie room",
                           "children-room", "childrens room", "childs room", "kid s room"});
    add(C::kOffice, {"office", "study", "home office", "study room", "workroom", "work room",
                     "workspace", "work space", "library", "studio", "home study", "office room",
                     "working room", "den office"});
    add(C::kMeetingRoom, {"meeting room", "conference room", "boardroom", "board room", "meeting space",
                          "meeting area", "meeting-room", "conference area"});
    add(C::kUtilityRoom, {"utility room", "utility", "staircase room", "stair room", "stairwell room",
                          "stair hall", "stairway room", "staircase-room", "utility-room", "stair core",
                          "stairs room", "utility area", "service room", "laundry room", "laundry", "laundry area",
                          "pantry", "mudroom", "mud room", "boot room", "scullery", "storage room", "store room", "storage", "store",
                          "storeroom"});
    add(C::kBalcony, {"balcony", "terrace", "veranda", "verandah", "loggia", "deck", "sun deck",
                      "roof terrace", "balconette"});
    return out;
  }();
  return lexicon;
}

// "two rooms for the kids", "a room for the grandchildren when they come": children's rooms, written
// as "two kids rooms" for the parser to count.
std::vector<Token> RoomsForChildren(const std::vector<Token>& tokens) {
  std::vector<Token> out;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const Token& t = tokens[i];
    std::size_t j = i + 1;
    if (!t.punct && In(t, {"room", "rooms"}) && j < tokens.size() && tokens[j].word == "for") {
      ++j;
      while (j < tokens.size() && !tokens[j].punct && (In(tokens[j], {"the", "our", "my", "his", "her", "their", "both", "all"}) || Cardinal(tokens[j])))
        ++j;
      if (j < tokens.size() && IsChildWord(tokens[j], false) && tokens[j].sentence == t.sentence) {
        Token kids = tokens[j], rooms = t;
        kids.begin = rooms.begin = t.begin;
        kids.end = rooms.end = tokens[j].end;
        kids.word = "kids";
        kids.stem = "kid";
        out.push_back(kids);
        out.push_back(rooms);
        i = j;
        continue;
      }
    }
    out.push_back(t);
  }
  return out;
}

// "our three kids each want their own room", "the two boys each get their own bedroom": that many
// children's rooms, written as "3 kids rooms" for the parser to count.
std::vector<Token> OwnRooms(const std::vector<Token>& tokens) {
  std::vector<Token> out;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const Token& n = tokens[i];
    std::size_t j = i + 1;
    const bool people = j < tokens.size() && IsChildWord(tokens[j], /*plural=*/true);
    // "both kids get their own children's room": two, with or without "each".
    const bool both = n.word == "both";
    bool ok = !n.punct && (both || (Cardinal(n) && *Cardinal(n) >= 2)) && people;
    std::size_t own = 0;  // the room noun after "their own"
    if (ok) {
      ++j;
      // "Two kids, each gets their own bedroom": a comma before "each".
      if (j + 1 < tokens.size() && tokens[j].punct == ',' && tokens[j + 1].word == "each") ++j;
      if (j < tokens.size() && tokens[j].word == "each") ++j;
      else ok = both;
      while (ok && j < tokens.size() && In(tokens[j], {"want", "wants", "need", "needs", "get", "gets", "have", "has", "should",
                                                       "will", "would", "like", "deserve", "must"}))
        ++j;
      own = j + 2;
      if (own + 1 < tokens.size() && IsChildWord(tokens[own], false)) ++own;  // "their own children's room"
      ok = ok && own < tokens.size() && tokens[j].word == "their" && tokens[j + 1].word == "own" &&
           In(tokens[own], {"room", "bedroom"});
    }
    if (!ok) {
      out.push_back(n);
      continue;
    }
    const std::size_t begin = n.begin, end = tokens[own].end;
    Token count = n, kids = tokens[i + 1], rooms = tokens[own];
    if (both) {
      count.word = count.stem = "2";
      count.number = true;
      count.value = 2;
    }
    count.begin = kids.begin = rooms.begin = begin;
    count.end = kids.end = rooms.end = end;
    kids.word = "kids";
    kids.stem = "kid";
    rooms.word = "rooms";
    rooms.stem = "room";
    out.push_back(count);
    out.push_back(kids);
    out.push_back(rooms);
    i = own;
    // "...; plus one for us", "and one for the two of us": a bedroom for the parents.
    std::size_t k = own + 1;
    if (k < tokens.size() && tokens[k].punct && tokens[k].punct != '.') ++k;
    if (k + 2 < tokens.size() && In(tokens[k], {"plus", "and"}) && In(tokens[k + 1], {"one", "1"}) && tokens[k + 2].word == "for") {
      Token one = tokens[k + 1], bedroom = tokens[k + 1];
      one.word = one.stem = "1";
      one.number = true;
      one.value = 1;
      bedroom.word = "bedroom";
      bedroom.stem = "bedroom";
      for (std::size_t x = own + 1; x <= k; ++x) out.push_back(tokens[x]);
      out.push_back(one);
      out.push_back(bedroom);
      i = k + 1;
    }
  }
  return out;
}

// A count whose floors follow it in brackets, written out as one phrase per floor: "Bathrooms - 2 (1
// downstairs, 1 upstairs)" and "2 bathrooms (one up, one down)" read as "1 Bathrooms downstairs, 1 Bathrooms
// upstairs", "Kitchen - 1 (downstairs)" and "Bedrooms: 3 (all upstairs)" as "1 Kitchen downstairs", "3
// Bedrooms upstairs". The noun is the one to three words between the separator before them ('|', ',', '/',
// a sentence's start) and the count, or right after the count; the floors are "upstairs", "downstairs",
// "up" or "down"; the counts in the brackets must add up to the count. So does a count whose floors follow
// it one by one: "2 living rooms, the first downstairs, the second upstairs".
std::vector<Token> FloorsInBrackets(const std::vector<Token>& tokens) {
  auto floor_word = [](const Token& t) { return !t.punct && In(t, {"upstairs", "downstairs", "up", "down"}); };
  // The floors of the brackets opening at `open` and the index of their ')', when they are floors.
  auto floors_at = [&](std::size_t open, int total) -> std::optional<std::pair<std::vector<std::pair<int, const Token*>>, std::size_t>> {
    std::vector<std::pair<int, const Token*>> floors;
    // ", the first downstairs, the second upstairs": one each, in order; ends on the last floor word.
    if (open + 3 < tokens.size() && tokens[open].punct == ',' && tokens[open + 1].word == "the") {
      std::size_t j = open + 1;
      while (j + 2 < tokens.size() && tokens[j].word == "the" && Ordinal(tokens[j + 1]) == static_cast<int>(floors.size()) + 1 &&
             floor_word(tokens[j + 2])) {
        floors.push_back({1, &tokens[j + 2]});
        j += 3;
        if (static_cast<int>(floors.size()) == total) break;
        if (j < tokens.size() && (tokens[j].punct == ',' || tokens[j].word == "and")) ++j;
        if (j < tokens.size() && tokens[j].word == "and") ++j;
      }
      if (static_cast<int>(floors.size()) != total || total < 2) return std::nullopt;
      return std::pair{std::move(floors), j - 1};
    }
    if (open + 1 >= tokens.size() || tokens[open].punct != '(') return std::nullopt;
    std::size_t j = open + 1;
    if (floor_word(tokens[j]) || (tokens[j].word == "all" && j + 1 < tokens.size() && floor_word(tokens[j + 1]))) {
      if (tokens[j].word == "all") ++j;
      floors.push_back({total, &tokens[j++]});
    } else {
      while (j + 1 < tokens.size() && tokens[j].punct != ')') {
        const std::optional<int> n = Cardinal(tokens[j]);
        if (!n || !floor_word(tokens[j + 1])) return std::nullopt;
        floors.push_back({*n, &tokens[j + 1]});
        j += 2;
        if (j < tokens.size() && (tokens[j].punct == ',' || tokens[j].word == "and")) ++j;
      }
    }
    int sum = 0;
    for (const auto& [n, f] : floors) sum += n;
    if (floors.empty() || sum != total || j >= tokens.size() || tokens[j].punct != ')') return std::nullopt;
    return std::pair{std::move(floors), j};
  };
  std::vector<Token> out;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const Token& count = tokens[i];
    const std::optional<int> total = count.punct ? std::nullopt : Cardinal(count);
    std::vector<Token> noun;
    std::size_t open = i + 1, noun_start = out.size();  // noun_start: where a noun before the count begins in out
    if (total) {
      // The noun after the count: up to three words, then the brackets.
      while (open < tokens.size() && open <= i + 3 && !tokens[open].punct && !Cardinal(tokens[open]) &&
             tokens[open].sentence == count.sentence)
        ++open;
      if (open == i + 1) {
        // The noun before it: what out has since the last separator, less a ':' or '-' before the count.
        std::size_t start = out.size();
        while (start > 0 && !(out[start - 1].punct && out[start - 1].punct != '-' && out[start - 1].punct != ':') &&
               out[start - 1].sentence == count.sentence)
          --start;
        std::size_t end = out.size();
        if (end > start && (out[end - 1].punct == ':' || out[end - 1].punct == '-')) --end;
        if (end > start && end - start <= 3) {
          noun.assign(out.begin() + static_cast<std::ptrdiff_t>(start), out.begin() + static_cast<std::ptrdiff_t>(end));
          noun_start = start;
        }
      } else {
        noun.assign(tokens.begin() + static_cast<std::ptrdiff_t>(i + 1), tokens.begin() + static_cast<std::ptrdiff_t>(open));
      }
    }
    const auto floors = noun.empty() ? std::nullopt : floors_at(open, *total);
    if (!floors) {
      out.push_back(count);
      continue;
    }
    out.resize(noun_start);  // a noun before the count is written again below
    // Each token written spans the whole phrase, to the ')' (what a report quotes).
    const std::size_t begin = std::min(noun.front().begin, count.begin), finish = tokens[floors->second].end;
    auto put = [&](Token t) {
      t.begin = begin;
      t.end = finish;
      out.push_back(std::move(t));
    };
    for (std::size_t k = 0; k < floors->first.size(); ++k) {
      if (k > 0) {
        Token comma = tokens[open];
        comma.punct = ',';
        comma.word = comma.stem = ",";
        put(comma);
      }
      Token n = count;
      n.word = n.stem = std::to_string(floors->first[k].first);
      n.number = true;
      n.value = floors->first[k].first;
      put(n);
      for (const Token& w : noun) put(w);
      put(*floors->first[k].second);
    }
    i = floors->second;  // the ')'
  }
  return out;
}

const std::vector<std::vector<std::string>>& FurnitureLexicon();

// The tokens as the parser reads them: a count repeated in digits ("three (3) bedrooms") once; "half a
// dozen" six, "a dozen" twelve; a misspelt room word of six letters or more one edit from exactly one
// of the lexicon's one-word room names ("bedroms", "bathrom", "balcny") read as it.
// Shorthand of listings and notes, written out: "3bd/2ba", "kit, din, fam rm", "2 balc", "dining tbl for
// 8", "GF: ... 1F: ...", "Grnd = office, meeting rm".
const std::unordered_map<std::string, std::vector<std::string>>& Shorthand() {
  static const std::unordered_map<std::string, std::vector<std::string>> words = {
      {"rm", {"room"}}, {"rms", {"rooms"}}, {"tbl", {"table"}}, {"grnd", {"ground"}}, {"gnd", {"ground"}},
      {"sep", {"separate"}}, {"balc", {"balcony"}}, {"balcs", {"balconies"}}, {"bd", {"bedroom"}}, {"bds", {"bedrooms"}},
      {"bdrm", {"bedroom"}}, {"hse", {"house"}}, {"ea", {"each"}}, {"bdrms", {"bedrooms"}}, {"bth", {"bathroom"}}, {"bthrm", {"bathroom"}}, {"bthrms", {"bathrooms"}}, {"kit", {"kitchen"}},
      {"din", {"dining"}}, {"fam", {"family"}}, {"liv", {"living"}}, {"lvg", {"living"}}, {"conf", {"conference"}},
      {"mstr", {"master"}}, {"gf", {"ground", "floor"}}, {"ff", {"first", "floor"}}, {"sf", {"second", "floor"}}, {"1f", {"1st", "floor"}}, {"2f", {"2nd", "floor"}},
      {"3f", {"3rd", "floor"}}, {"incl", {"including"}}, {"inc", {"including"}}, {"mtg", {"meeting"}}, {"pls", {"please"}},
      {"plz", {"please"}}};
  return words;
}

std::vector<Token> Normalised(std::vector<Token> tokens) {
  std::vector<Token> out;
  // The full stop of an abbreviation ends no sentence ("Bedrooms: 5 (incl. master)", "kitchen + sep. dining").
  for (std::size_t i = 0; i + 1 < tokens.size(); ++i)
    if (tokens[i + 1].punct == '.' && tokens[i + 1].begin == tokens[i].end &&
        In(tokens[i], {"incl", "inc", "approx", "appx", "excl", "sq", "ft", "nr", "sep"})) {
      for (std::size_t k = i + 2; k < tokens.size(); ++k) tokens[k].sentence -= 1;
      tokens.erase(tokens.begin() + static_cast<std::ptrdiff_t>(i) + 1);
    }
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const Token& t = tokens[i];
    if (t.punct == '=') {  // "Grnd = office, ...": a heading
      Token colon = t;
      colon.punct = ':';
      colon.word = colon.stem = ":";
      out.push_back(colon);
      continue;
    }
    if (auto it = Shorthand().find(t.word); it != Shorthand().end()) {
      for (const std::string& w : it->second) {
        Token full = t;
        full.word = w;
        full.stem = Singular(w);
        if (w.size() == 3 && std::isdigit(static_cast<unsigned char>(w[0]))) full.ordinal = w[0] - '0';
        out.push_back(full);
      }
      continue;
    }
    if (t.punct == '(' && i + 2 < tokens.size() && tokens[i + 1].number && tokens[i + 2].punct == ')' && !out.empty() &&
        Cardinal(out.back()) && *Cardinal(out.back()) == tokens[i + 1].value) {
      i += 2;
      continue;
    }
    // "w/ ensuite" (notes): with.
    if (t.word == "w" && i + 1 < tokens.size() && tokens[i + 1].punct == '/' && tokens[i + 1].begin == t.end) {
      Token with = t;
      with.word = with.stem = "with";
      with.end = tokens[i + 1].end;
      out.push_back(with);
      ++i;
      continue;
    }
    // "2nd lvg rm": a second living room (an ordinal before a room, not a floor's).
    if ((t.word == "2nd" || t.word == "3rd") && i + 1 < tokens.size() && !tokens[i + 1].punct && !IsFloorNoun(tokens[i + 1]) &&
        std::any_of(RoomLexicon().begin(), RoomLexicon().end(), [&](const RoomWord& r) {
          return r.words[0] == tokens[i + 1].word || (Shorthand().count(tokens[i + 1].word) && Shorthand().at(tokens[i + 1].word)[0] == r.words[0]);
        })) {
      Token word = t;
      word.word = word.stem = t.word == "2nd" ? "second" : "third";
      word.ordinal = 0;
      out.push_back(word);
      continue;
    }
    // "2x kids rm" (notes): two.
    if (!t.punct && t.word.size() >= 2 && t.word.back() == 'x' && t.word.size() <= 3 &&
        std::all_of(t.word.begin(), t.word.end() - 1, [](char c) { return std::isdigit(static_cast<unsigned char>(c)); })) {
      Token n = t;
      n.word = n.stem = t.word.substr(0, t.word.size() - 1);
      n.number = true;
      n.value = std::stoi(n.word);
      out.push_back(n);
      continue;
    }
    if (t.word == "half" && i + 2 < tokens.size() && tokens[i + 1].word == "a" && tokens[i + 2].word == "dozen") {
      Token six = tokens[i + 2];
      six.begin = t.begin;
      six.word = six.stem = "6";
      six.number = true;
      six.value = 6;
      out.push_back(six);
      i += 2;
      continue;
    }
    if (t.word == "dozen" && !out.empty() && out.back().word == "a") {
      out.back().word = out.back().stem = "12";
      out.back().number = true;
      out.back().value = 12;
      out.back().end = t.end;
      continue;
    }
    out.push_back(t);
  }
  out = OwnRooms(out);
  out = RoomsForChildren(out);
  out = FloorsInBrackets(out);
  static const std::vector<std::pair<std::string, Category>> names = [] {
    std::vector<std::pair<std::string, Category>> words;
    for (const RoomWord& r : RoomLexicon())
      if (r.words.size() == 1 && r.words[0].size() >= 6) words.push_back({r.words[0], r.category});
    return words;
  }();
  static const std::unordered_set<std::string> known = [] {
    std::unordered_set<std::string> words;
    for (const auto& [w, c] : names) words.insert(w);
    return words;
  }();
  // The lexicon's one-word pieces a misspelling may be read as ("dishwaser", "wardorbe", "bookcaes").
  static const std::vector<std::string> pieces = [] {
    std::vector<std::string> words;
    for (const auto& phrase : FurnitureLexicon())
      if (phrase.size() == 1 && phrase[0].size() >= 7) words.push_back(phrase[0]);
    return words;
  }();
  static const std::unordered_set<std::string> one_word_pieces = [] {
    std::unordered_set<std::string> words;
    for (const auto& phrase : FurnitureLexicon())
      if (phrase.size() == 1) words.insert(phrase[0]);
    return words;
  }();
  for (Token& t : out) {
    // (Words of their own are no misspellings: "double" beside the plural "doubles", "single".)
    if (t.punct || t.number || t.word.size() < 5 || known.count(t.stem) || known.count(t.word) || known.count(t.word + "s") ||
        Cardinal(t) || IsAdjective(t) || IsFiller(t))
      continue;
    // Common words one letter from a room's name: "no matter" is no master bedroom.
    if (In(t, {"matter", "matters", "latter", "batter", "hatter", "faster", "plaster", "mister", "sister", "sisters",
               "loom", "boom", "broom", "zoom", "doom", "gloom"}))
      continue;
    // One category among the names it is one edit from (it may be near two spellings of one room:
    // "bathrom" is near "bathroom" and "bathrm"), the first such name taken.
    std::string match;
    std::optional<Category> category;
    bool ambiguous = false;
    for (const auto& [name, c] : names)
      for (const std::string& form : {t.word, t.stem})
        if (OneEditApart(form, name) || OneEditApart(form, name + "s")) {
          if (category && *category != c) ambiguous = true;
          if (!category) match = name;
          category = c;
        }
    if (category && !ambiguous) {
      // The plural kept where the misspelling was of the plural ("bedroms").
      const bool plural = !OneEditApart(t.word, match) && !OneEditApart(t.stem, match);
      t.stem = match;
      t.word = plural ? match + "s" : match;
      continue;
    }
    // A piece of furniture's name, when one is that near (util/spelling.h).
    if (category || !MaybeMisspeltNoun(t.word) || one_word_pieces.count(t.word) || one_word_pieces.count(t.stem)) continue;
    if (std::optional<std::string> meant = OneEditFrom(t.word, pieces)) {
      t.stem = Singular(*meant);
      t.word = std::move(*meant);
    }
  }
  return out;
}

struct FurnitureWord {
  std::vector<std::string> words;
};

const std::vector<std::vector<std::string>>& FurnitureLexicon() {
  static const std::vector<std::vector<std::string>> lexicon = [] {
    std::vector<std::vector<std::string>> out;
    for (auto p : {"tv", "television", "tv set", "telly", "bed", "double bed", "single bed", "bunk bed", "king bed",
                   "queen bed", "king size bed", "queen size bed", "twin bed", "crib", "cot", "sofa",
                   "couch", "sofa bed", "armchair", "chair", "desk", "writing desk", "table", "dining table",
                   "coffee table", "conference table", "meeting table", "side table", "bedside table",
                   "wardrobe", "closet", "bookshelf", "bookcase", "shelf", "cabinet", "dresser",
                   "nightstand", "night stand", "piano", "grand piano", "fireplace", "bathtub", "bath tub",
                   "tub", "sink", "basin", "fridge", "refrigerator", "oven", "stove", "cooker", "hob",
                   "dishwasher", "washing machine", "washer", "dryer", "lamp", "floor lamp", "rug",
                   "carpet", "plant", "mirror", "whiteboard", "projector", "treadmill", "computer",
                   "monitor", "kitchen island", "island", "bar counter", "sideboard", "bench", "ottoman",
                   "stool", "bar stool", "toy", "toy box", "printer", "screen", "speaker", "aquarium",
                   "painting", "curtain", "vanity", "chest of drawer", "drawer", "office chair",
                   "gaming console", "console", "filing cabinet", "recliner", "sectional", "loveseat",
                   "love seat", "futon", "hammock", "bunk", "changing table", "tv stand", "tv cabinet",
                   "counter", "worktop", "microwave", "exercise bike", "pool table", "sound system", "shower", "bath"}) {
      out.push_back(Split(p));
    }
    return out;
  }();
  return lexicon;
}

struct CueWord {
  std::vector<std::string> words;
  LinkKind kind;
  bool mutual = false;  // "open to each other", "are connected": links the rooms before it
};

const std::vector<CueWord>& CueLexicon() {
  static const std::vector<CueWord> lexicon = [] {
    std::vector<CueWord> out;
    auto add = [&](LinkKind k, std::initializer_list<std::string_view> phrases, bool mutual = false) {
      for (auto p : phrases) out.push_back({Split(p), k, mutual});
    };
    add(LinkKind::kOpen,
        {"open to", "open onto", "open into", "open out to", "open out onto", "open up to", "openly connected to",
         "openly connected with", "openly connect to", "openly connect with", "openly linked to",
         "openly linked with", "openly joined to", "openly joined with", "openly join", "openly connect",
         "open connection to", "open connection with", "open plan with", "flow into", "flow onto",
         "flowing into", "merge into", "merge with", "merging into", "blend into", "open passage to",
         "open link to", "open link with", "open towards", "open toward", "opening to", "opening into",
         "opening onto", "without a door to", "without a wall to", "open-plan with", "in an open plan with",
         "openly adjoin", "openly adjoining"});
    add(LinkKind::kOpen, {"open to each other", "open onto each other", "openly connected", "openly connect",
                          "openly linked", "open to one another", "open plan", "openplan", "combined",
                          "form an open plan", "share an open space", "flow into each other",
                          "flow together", "openly joined"},
        true);
    add(LinkKind::kAny,
        {"connected to", "connected with", "connect to", "led to", "led into", "led onto", "lead out onto", "connect with", "connecting to", "connecting with",
         "linked to", "linked with", "link to", "link with", "lead to", "lead into", "lead onto", "leading to",
         "leading into", "leading onto", "access to", "access into", "access onto", "access", "accessing",
         "accessible from", "accessible via", "accessible through", "reach", "reaching", "reached from",
         "reached via", "adjacent to", "next to", "off", "adjoin", "adjoining", "adjoins", "communicate with",
         "give onto", "giving onto", "give access to", "giving access to", "connect", "connecting",
         "enter", "enter into", "entered from", "is off", "off of", "join", "joined to", "joined with",
         "lead out to", "step out to", "step out onto", "walk out to", "go out to", "open directly to",
         "open directly onto", "open directly into", "connection to", "connection with", "beside",
         "alongside", "attached to", "connected directly to"});
    add(LinkKind::kAny, {"connected", "linked", "connected to each other", "connected to one another",
                         "adjacent", "next to each other", "joined"},
        true);
    add(LinkKind::kDoor,
        {"door to", "door into", "door onto", "door leading to", "door opening to", "door opening onto",
         "through a door to", "via a door to", "reached through", "reached only through",
         "accessed through", "accessed only through", "accessible only through", "only through",
         "only from", "reached only from", "entered through", "entered only through", "door with",
         "by a door to", "a door to", "door connecting to", "door connection to"});
    return out;
  }();
  return lexicon;
}

// ---------------------------------------------------------------------------------------------------
// Items: what the matchers found

enum class ItemKind { kFloorCount, kFloorRef, kShape, kRoom, kCue, kPanoramic, kFurniture, kEntrance, kSide };

enum class RefType { kOrdinal, kNumbered, kGround, kTop, kUpper, kMiddle, kEach, kSame };

struct Item {
  ItemKind kind = ItemKind::kRoom;
  int first = 0;  // token range, inclusive
  int last = 0;
  // kFloorCount
  int floors = 0;
  bool floors_at_least = false;
  // kFloorRef
  RefType ref = RefType::kGround;
  int n = 0;
  bool each = false;  // kUpper: each of those floors on its own ("both upper floors get a balcony")
  // kShape
  std::optional<ShapeClass> shape;  // unset: unsupported
  // kRoom
  Category category = Category::kRoom;
  bool ensuite = false;
  bool open_plan = false;
  // kCue
  LinkKind link = LinkKind::kAny;
  bool mutual = false;
  // kSide
  std::string side;
  // kFurniture
  int item_first = 0;  // the item's words (modifiers + noun), for its name
};

Item MakeItem(ItemKind kind) {
  Item item;
  item.kind = kind;
  return item;
}

// A room mention after interpretation.
struct Mention {
  int item = -1;
  Category category = Category::kRoom;
  bool counting = false;  // "a kitchen", "two bathrooms", "no balcony": states how many
  int min = 1;
  int max = 1;
  bool plural = false;
  bool every = false;  // "each bedroom"
  bool with_before = false;
  int with_token = -1;
  int bound_ref = -1;   // floor ref item bound as an adjective ("second-floor bedroom")
  int ref = -1;         // floor ref item that places it (bound, scope or trailing)
  std::vector<int> partner_levels;  // levels taken from connection partners (resolved later)
  std::vector<int> partners;        // mention indices it connects with
  bool definite = false;       // "the kitchen", "its own bathroom"
  bool in_connection = false;
  bool by_cue = false;         // in a connection made by a cue ("open to", "reaches")
  bool in_attachment = false;  // furniture, panoramic, side or entrance refer to it
  int first = 0;  // token range of the whole phrase (quantifier included)
  int last = 0;
  int per_level = -1;  // "six bedrooms on the upper two floors, three on each": this many on each level of `ref`
  // One for each of other rooms (issue 32): "two bedrooms, each with an en-suite", "a bathroom each",
  // "every bedroom has a balcony", "a balcony for every bedroom"; set by Spread().
  bool spread = false;
};

class Parser {
 public:
  explicit Parser(std::string_view text) : text_(text), tokens_(Normalised(Tokenise(text))) {}

  Brief Run();

 private:
  // matching
  void MatchAll();
  int TryFloorCount(std::size_t i, Item& item);
  int TryFloorRef(std::size_t i, Item& item);
  int TryShape(std::size_t i, Item& item);
  int TryRoom(std::size_t i, Item& item);
  int TryCue(std::size_t i, Item& item);
  int TryPanoramic(std::size_t i, Item& item);
  int TryFurniture(std::size_t i, Item& item);
  // "no first floor", "without a second floor" (at the end of its clause): a floor denied, not a heading.
  bool NegatedFloor(std::size_t i) const;
  int TryCapacity(std::size_t i, Item& item);
  int TryEntrance(std::size_t i, Item& item);
  int TrySide(std::size_t i, Item& item);
  bool RoomStartsWithin(std::size_t i, int span) const;
  bool IsBedroomCount(std::size_t i) const;
  // A floor phrase that opens its clause ("...: ground floor lounge, kitchen and study; first floor ...")
  // and is followed by a list heads that list (a scope), rather than binding to its first room.
  bool HeadsList(int ref_item, int mention_last) const;
  bool FurnitureStartsWithin(std::size_t i, int span) const;
  int ObjectWordsAt(std::size_t i) const;

  // interpretation
  void Quantify(Mention& m);
  void PlaceLevels();
  int FloorsBefore(int at, int sentence) const;
  void Spread();
  void Distribute();
  void UsedAs();
  void Corrections();
  void FloorsOfTotals();
  void RoomTotals();
  bool ElidedFloor(std::size_t i) const;
  std::vector<int> RefLevels(int ref_item) const;
  void Connect();
  void Attach();
  void Finish(Brief& brief);
  int ResolveRef(int ref_item) const;
  int ItemAt(int token) const { return token >= 0 && token < static_cast<int>(tokens_.size()) ? tokens_[token].item : -1; }
  int MentionOfItem(int item) const {
    auto it = mention_of_item_.find(item);
    return it == mention_of_item_.end() ? -1 : it->second;
  }
  TextSpan Span(int first, int last) const {
    TextSpan s;
    s.begin = tokens_[first].begin;
    s.end = tokens_[last].end;
    s.text = std::string(text_.substr(s.begin, s.end - s.begin));
    return s;
  }
  void Consume(int first, int last) {
    for (int k = first; k <= last; ++k) tokens_[k].consumed = true;
  }
  std::vector<int> MentionLevels(const Mention& m) const;
  int OwnLevel(const Mention& m) const { return m.ref >= 0 ? ResolveRef(m.ref) : kAnyLevel; }
  bool bare_mention_ = false;  // set by Quantify for the mention it just read
  std::unordered_set<int> per_items_;  // room items named as a ratio's base ("for every two bedrooms"): counted elsewhere

  std::string_view text_;
  std::vector<Token> tokens_;
  std::vector<Item> items_;
  std::vector<Mention> mentions_;
  std::unordered_map<int, int> mention_of_item_;
  bool british_ = false;
  bool ground_heading_ = false;  // "Ground: ..." heads a list of the ground floor's rooms
  bool zero_based_numbers_ = false;
  std::optional<int> floors_;
  std::optional<TextSpan> floors_source_;
  int floors_source_last_ = 0;  // the last token of the floor count floors_ came from
  int floors_min_ = 0;
  std::vector<std::string> conflicts_;
  std::vector<int> sentence_scope_;  // per sentence: the floor ref scoping its end, or -1
  std::vector<bool> bare_;           // per mention: no quantifier at all ("bedrooms")

  struct PendingConnection {
    int a = -1;  // mention indices
    int b = -1;
    LinkKind kind = LinkKind::kAny;
    bool every = false;
    TextSpan source;
  };
  std::vector<PendingConnection> connections_;
  struct PendingAttachment {
    ItemKind kind;
    int item = -1;
    int mention = -1;     // the room it belongs to, or -1
    int ref = -1;         // a floor ref placing it when there is no room
    TextSpan source;
  };
  std::vector<PendingAttachment> attachments_;
};

bool Parser::RoomStartsWithin(std::size_t i, int span) const {
  for (std::size_t k = i; k < tokens_.size() && k < i + span; ++k) {
    if (tokens_[k].punct) return false;
    for (const auto& w : RoomLexicon())
      if (MatchPhrase(tokens_, k, w.words)) return true;
  }
  return false;
}

bool Parser::FurnitureStartsWithin(std::size_t i, int span) const {
  for (std::size_t k = i; k < tokens_.size() && k < i + span; ++k) {
    if (tokens_[k].punct) return false;
    if (ObjectWordsAt(k) > 0) return true;
  }
  return false;
}

// Length of the words naming an object at tokens[i] (0 if none): the furniture lexicon above, then the
// furnishing stage's own vocabulary (assets/category.h: "books", "clock", "plant", ...) when the build has
// it, so that a furniture wish is read as one for the furnish stage, not left as words not understood. A
// vocabulary word right before a room word names the room ("art studio"), not an object.
int Parser::ObjectWordsAt(std::size_t i) const {
  if (i >= tokens_.size() || IsBedroomCount(i)) return 0;
  int best = 0;
  for (const auto& p : FurnitureLexicon()) best = std::max(best, MatchPhrase(tokens_, i, p));
#ifdef VILLA_HAVE_ASSET_VOCABULARY
  const Token& t = tokens_[i];
  if (best == 0 && !t.punct && t.item < 0 && !IsFiller(t) && !Cardinal(t) && !IsFloorNoun(t) &&
      !RoomStartsWithin(i, 1)) {
    for (int len = 2; len >= 1 && best == 0; --len) {
      if (i + len > tokens_.size()) continue;
      std::string phrase;
      bool plain = true;
      for (int k = 0; k < len; ++k) {
        const Token& w = tokens_[i + k];
        if (w.punct || w.item >= 0 || w.sentence != t.sentence) plain = false;
        if (k > 0) phrase += ' ';
        phrase += w.word;
      }
      if (plain && CategoryForWord(phrase)) best = len;
    }
    if (best > 0 && RoomStartsWithin(i + best, 1)) best = 0;
  }
#endif
  return best;
}

int Parser::TryFloorCount(std::size_t i, Item& item) {
  const Token& t = tokens_[i];
  if (t.punct) return 0;
  if (In(t, {"bungalow", "ranch", "rambler"})) {  // the American single-storey house
    item.floors = 1;
    return 1;
  }
  if (t.word == "duplex") {
    item.floors = 2;
    return 1;
  }
  // "No upstairs please", "no stairs", "without an upper floor": one floor (not a scope for what follows).
  if (In(t, {"no", "without"})) {
    std::size_t k = i + 1;
    if (k < tokens_.size() && In(tokens_[k], {"a", "an", "any"})) ++k;
    if (k < tokens_.size() && In(tokens_[k], {"upstairs", "stairs", "staircase"})) {
      item.floors = 1;
      return static_cast<int>(k - i) + 1;
    }
    if (k + 1 < tokens_.size() && In(tokens_[k], {"upper", "second", "top"}) && IsFloorNoun(tokens_[k + 1])) {
      item.floors = 1;
      return static_cast<int>(k - i) + 2;
    }
  }
  if (t.word == "triplex") {
    item.floors = 3;
    return 1;
  }
  if (In(t, {"multi", "multistory", "multistorey", "multilevel", "multistoried"})) {
    int len = 1;
    if (t.word == "multi") {
      if (i + 1 < tokens_.size() && IsFloorNoun(tokens_[i + 1])) len = 2;
      else return 0;
    }
    item.floors = 2;
    item.floors_at_least = true;
    return len;
  }
  // "Floors: 3", "Number of stories: 2", "Storeys - 2" (spec style).
  if (IsFloorNoun(t) && i + 2 < tokens_.size() && (tokens_[i + 1].punct == ':' || tokens_[i + 1].punct == '-') &&
      Cardinal(tokens_[i + 2]) &&
      !In(tokens_[i + 2], {"single", "double", "triple"})) {
    item.floors = *Cardinal(tokens_[i + 2]);
    return 3;
  }
  auto n = Cardinal(t);
  if (!n || i + 1 >= tokens_.size()) return 0;
  const Token& next = tokens_[i + 1];
  if (!IsFloorNoun(next)) return 0;
  // "floor plan", "floor area": not a count of floors.
  if (i + 2 < tokens_.size() && In(tokens_[i + 2], {"plan", "area", "space", "lamp"})) return 0;
  item.floors = *n;
  return 2;
}

// "two bedrooms on the first, an office on the second": an ordinal after "on the" whose floor noun is left
// out (before a break or "and"), in a text that names floors elsewhere.
bool Parser::ElidedFloor(std::size_t i) const {
  if (i < 2 || !Ordinal(tokens_[i]) || tokens_[i - 1].word != "the" || tokens_[i - 2].word != "on") return false;
  if (i + 1 < tokens_.size() && !tokens_[i + 1].punct && tokens_[i + 1].sentence == tokens_[i].sentence && tokens_[i + 1].word != "and")
    return false;
  return std::any_of(tokens_.begin(), tokens_.end(), [](const Token& t) { return IsFloorNoun(t); });
}

bool Parser::NegatedFloor(std::size_t i) const {
  const bool denied = i > 0 && (In(tokens_[i - 1], {"no", "without"}) ||
                                (i > 1 && In(tokens_[i - 1], {"a", "any"}) && In(tokens_[i - 2], {"no", "without"})));
  return denied && i + 1 < tokens_.size() && Ordinal(tokens_[i]) &&
         IsFloorNoun(tokens_[i + 1]) && !(i + 2 < tokens_.size() && tokens_[i + 2].sentence == tokens_[i].sentence && !tokens_[i + 2].punct &&
                                          !In(tokens_[i + 2], {"at", "please", "thanks"}));
}

int Parser::TryFloorRef(std::size_t i, Item& item) {
  const Token& t = tokens_[i];
  if (t.punct) return 0;
  // "a bungalow - no first floor at all": a floor the building does not have, no heading.
  if (NegatedFloor(i)) {
    tokens_[i].consumed = tokens_[i + 1].consumed = true;
    return 0;
  }
  if (ElidedFloor(i)) {
    item.ref = RefType::kOrdinal;
    item.n = *Ordinal(t);
    return 1;
  }
  auto floor_at = [&](std::size_t k) { return k < tokens_.size() && IsFloorNoun(tokens_[k]); };
  if (In(t, {"upstairs", "upstair"})) {
    item.ref = RefType::kUpper;
    return 1;
  }
  if (In(t, {"downstairs", "downstair"})) {
    item.ref = RefType::kGround;
    return 1;
  }
  // "bedrooms upstairs, ... plus a bathroom up there".
  if (In(t, {"up", "down"}) && i + 1 < tokens_.size() && tokens_[i + 1].word == "there" && tokens_[i + 1].sentence == t.sentence) {
    item.ref = t.word == "up" ? RefType::kUpper : RefType::kGround;
    return 2;
  }
  // "3 bedrooms up, kitchen + lounge down" (terse notes): right after a room, then a break.
  // "... 3 bedrooms and a bathroom above." likewise (not "the bedroom above the kitchen": a relation).
  if (In(t, {"up", "down", "above", "below"}) && i > 0 && tokens_[i - 1].item >= 0 && items_[tokens_[i - 1].item].kind == ItemKind::kRoom &&
      (i + 1 >= tokens_.size() || tokens_[i + 1].punct || tokens_[i + 1].sentence != t.sentence || tokens_[i + 1].word == "and")) {
    item.ref = In(t, {"up", "above"}) ? RefType::kUpper : RefType::kGround;
    return 1;
  }
  // "Upper: three bedrooms", "Lower: kitchen", "Down: ... Up: ...", "upper = ..." (spec headings and notes).
  if (In(t, {"upper", "lower", "up", "down", "top", "bottom"}) && i + 1 < tokens_.size() &&
      (tokens_[i + 1].punct == ':' || tokens_[i + 1].punct == '=')) {
    item.ref = In(t, {"upper", "up"}) ? RefType::kUpper : t.word == "top" ? RefType::kTop : RefType::kGround;
    return 1;
  }
  if (auto o = Ordinal(t); o && floor_at(i + 1)) {
    item.ref = RefType::kOrdinal;
    item.n = *o;
    return 2;
  }
  // "first: 3 bedrooms" after a "ground: ..." heading (a spec's floors by their ordinals alone).
  if (auto o = Ordinal(t); o && i + 1 < tokens_.size() && tokens_[i + 1].punct == ':' && ground_heading_) {
    item.ref = RefType::kOrdinal;
    item.n = *o;
    return 1;
  }
  if (In(t, {"ground"})) {
    item.ref = RefType::kGround;
    return floor_at(i + 1) ? 2 : 1;
  }
  if (In(t, {"top", "uppermost", "highest", "topmost", "last"}) && floor_at(i + 1)) {
    item.ref = RefType::kTop;
    return 2;
  }
  // "both upper floors", "each of the upper floors", "all the upper two floors": each one on its own.
  if (In(t, {"both", "each", "every", "all"})) {
    std::size_t k = i + 1;
    if (k < tokens_.size() && tokens_[k].word == "of") ++k;
    if (k < tokens_.size() && tokens_[k].word == "the") ++k;
    // "each of the two upper floors"
    int n_before = 0;
    if (k + 1 < tokens_.size() && Cardinal(tokens_[k]) && *Cardinal(tokens_[k]) > 0 && In(tokens_[k + 1], {"upper", "higher"}))
      n_before = *Cardinal(tokens_[k++]);
    if (k < tokens_.size() && In(tokens_[k], {"upper", "higher"})) {
      std::size_t f = k + 1;
      int n = n_before;
      if (f < tokens_.size() && Cardinal(tokens_[f]) && *Cardinal(tokens_[f]) > 0 && !In(tokens_[f], {"single", "double", "triple"}))
        n = *Cardinal(tokens_[f++]);
      if (floor_at(f)) {
        item.ref = RefType::kUpper;
        item.n = n > 0 ? n : t.word == "both" ? 2 : 0;
        item.each = true;
        return static_cast<int>(f - i) + 1;
      }
    }
  }
  // "the two upper floors": the highest two together ("... each have" reads them one by one).
  if (Cardinal(t) && *Cardinal(t) >= 2 && !t.punct && i + 2 < tokens_.size() && In(tokens_[i + 1], {"upper", "higher"}) &&
      floor_at(i + 2) && IsFloorNoun(tokens_[i + 2]) && tokens_[i + 2].stem != tokens_[i + 2].word) {
    item.ref = RefType::kUpper;
    item.n = *Cardinal(t);
    return 3;
  }
  // "the upper two floors", "the top 2 levels": the highest n floors together.
  if (In(t, {"upper", "higher", "top", "uppermost", "topmost"}) && i + 1 < tokens_.size() && Cardinal(tokens_[i + 1]) &&
      *Cardinal(tokens_[i + 1]) > 0 && floor_at(i + 2) && !In(tokens_[i + 1], {"single", "double", "triple"})) {
    item.ref = RefType::kUpper;
    item.n = *Cardinal(tokens_[i + 1]);
    return 3;
  }
  if (In(t, {"upper", "higher"}) && floor_at(i + 1)) {
    item.ref = RefType::kUpper;
    return 2;
  }
  if (In(t, {"lower", "bottom", "main", "entry", "street", "entrance", "lowest"}) && floor_at(i + 1)) {
    item.ref = RefType::kGround;
    return 2;
  }
  if (In(t, {"middle", "intermediate", "central"}) && floor_at(i + 1)) {
    item.ref = RefType::kMiddle;
    return 2;
  }
  // "Middle: living room, office" (a heading between "Ground:" and "Top:"; not "In the middle: ..." of a
  // single floor's wings).
  if (In(t, {"middle", "mid"}) && i + 1 < tokens_.size() && (tokens_[i + 1].punct == ':' || tokens_[i + 1].punct == '=') &&
      (i == 0 || tokens_[i - 1].punct || tokens_[i - 1].sentence != t.sentence)) {
    item.ref = RefType::kMiddle;
    return 1;
  }
  if (In(t, {"each", "every", "all", "both", "per"}) && floor_at(i + 1)) {
    item.ref = RefType::kEach;
    return 2;
  }
  // "each of the floors", "on each of the three floors" (the count is matched on its own afterwards)
  if (In(t, {"each", "every"}) && i + 3 < tokens_.size() && tokens_[i + 1].word == "of" &&
      tokens_[i + 2].word == "the" && (floor_at(i + 3) || (Cardinal(tokens_[i + 3]) && floor_at(i + 4)))) {
    item.ref = RefType::kEach;
    return 3;
  }
  // "Three floors with a bathroom on each one": "on each one" after the floors were named.
  if (In(t, {"each", "every"}) && i > 0 && tokens_[i - 1].word == "on" && i + 1 < tokens_.size() && tokens_[i + 1].word == "one" &&
      (i + 2 >= tokens_.size() || tokens_[i + 2].punct || In(tokens_[i + 2], {"and", "too", "as"}))) {
    for (std::size_t k = 0; k < i; ++k)
      if (IsFloorNoun(tokens_[k]) && tokens_[k].sentence == t.sentence) {
        item.ref = RefType::kEach;
        return 2;
      }
  }
  if (In(t, {"this", "that", "same"}) && floor_at(i + 1)) {
    item.ref = RefType::kSame;
    return 2;
  }
  if (IsFloorNoun(t) && !In(t, {"storied", "storeyed"}) && i + 1 < tokens_.size()) {
    if (auto n = Cardinal(tokens_[i + 1]); n && tokens_[i + 1].word != "single" && tokens_[i + 1].word != "double") {
      item.ref = RefType::kNumbered;
      item.n = *n;
      return 2;
    }
  }
  return 0;
}

int Parser::TryShape(std::size_t i, Item& item) {
  const Token& t = tokens_[i];
  if (t.punct) return 0;
  auto shape_word = [&](std::size_t k) {
    return k < tokens_.size() && In(tokens_[k], {"shaped", "shape", "plan", "form", "footprint", "outline", "layout"});
  };
  int len = 0;
  // "Footprint: L", "Shape: U-shaped" (spec style): the letter after the heading.
  const bool headed = (i >= 2 && tokens_[i - 1].punct == ':' && In(tokens_[i - 2], {"footprint", "shape", "outline", "plan"}) &&
                       tokens_[i - 2].sentence == t.sentence) ||
                      // "shaped like a T", "in the shape of an L"
                      (i >= 3 && In(tokens_[i - 1], {"a", "an"}) && In(tokens_[i - 2], {"like", "of"}) &&
                       In(tokens_[i - 3], {"shaped", "shape"}) && tokens_[i - 3].sentence == t.sentence);
  if (t.word.size() == 1 && std::isalpha(static_cast<unsigned char>(t.word[0])) && (shape_word(i + 1) || (headed && In(t, {"l", "u", "t", "h"})))) {
    char c = t.word[0];
    len = 2;
    if (c == 'l') item.shape = ShapeClass::kL;
    else if (c == 'u') item.shape = ShapeClass::kU;
    else if (c == 't') item.shape = ShapeClass::kT;
    else if (c == 'h') item.shape = ShapeClass::kH;
    else item.shape.reset();  // "Z-shaped", "S-shaped": no such class
    if (!shape_word(i + 1)) len = 1;
  } else if (In(t, {"rectangular", "rectangle", "oblong", "boxy", "box"})) {
    if (t.word == "box" && !shape_word(i + 1)) return 0;
    item.shape = ShapeClass::kRectangle;
    len = 1;
  } else if (t.word == "square") {
    if (i + 1 < tokens_.size() && In(tokens_[i + 1], {"meter", "metre", "m", "feet", "foot", "ft", "kilometer"}))
      return 0;
    item.shape = ShapeClass::kRectangle;
    len = 1;
  } else if (In(t, {"hexagonal", "hexagon", "octagonal", "octagon", "trapezoidal", "trapezoid", "trapezium",
                    "wedge", "star", "cross", "cruciform", "plus"})) {
    if (In(t, {"star", "cross", "plus"}) && !shape_word(i + 1)) return 0;  // "a star" is not a footprint
    item.shape = In(t, {"hexagonal", "hexagon"})   ? ShapeClass::kHexagon
                 : In(t, {"octagonal", "octagon"}) ? ShapeClass::kOctagon
                 : In(t, {"star", "cross", "cruciform", "plus"}) ? ShapeClass::kCross
                                                                 : ShapeClass::kTrapezoid;
    len = 1;
  } else if (In(t, {"no", "without"}) && i + 2 < tokens_.size() && tokens_[i + 1].word == "right" &&
             In(tokens_[i + 2], {"angle", "angles", "angled", "corners"})) {
    item.shape = ShapeClass::kOctagon;  // "no right angles": every corner of an octagon is 135 degrees
    return 3;
  } else if (In(t, {"six", "eight", "6", "8"}) && i + 1 < tokens_.size() && In(tokens_[i + 1], {"sided", "sides", "cornered"})) {
    item.shape = In(t, {"six", "6"}) ? ShapeClass::kHexagon : ShapeClass::kOctagon;
    len = 2;
  } else if (t.word == "bay" && i + 1 < tokens_.size() && In(tokens_[i + 1], {"window", "windows", "front", "fronted", "projection"})) {
    item.shape = ShapeClass::kBay;
    len = 2;
    if (FurnitureStartsWithin(i + len, 2)) return 0;
    return len;  // "a bay window in the living room" still asks for the bay
  } else if (In(t, {"angled", "splayed", "skewed", "turned", "rotated"}) && i + 1 < tokens_.size() &&
             In(tokens_[i + 1], {"wing", "wings"})) {
    item.shape = ShapeClass::kAngledWing;
    len = 2;
  } else if (In(t, {"irregular", "irregularly", "slanted", "slanting", "angled", "angular", "chamfered",
                    "diagonal", "polygonal", "asymmetric", "asymmetrical", "sloped", "skewed",
                    "oblique", "bevelled", "beveled", "nonrectangular"})) {
    item.shape = ShapeClass::kIrregular;
    len = 1;
  } else if (In(t, {"odd", "oddly", "unusual", "unusually", "free", "non"}) && i + 1 < tokens_.size() &&
             (shape_word(i + 1) || In(tokens_[i + 1], {"rectangular", "form"}))) {
    item.shape = ShapeClass::kIrregular;
    len = 2;
  } else if (In(t, {"round", "circular", "curved", "oval", "elliptical", "pentagonal", "pentagon", "triangular",
                    "triangle", "cylindrical", "dome", "domed", "spiral", "crescent", "heart", "semicircular",
                    "zigzag", "circle", "ring", "curvy", "rounded"})) {
    // Nouns only with a shape word or a building after them ("heart-shaped", "a dome house"): "the living
    // room is the heart of it" asks for no footprint.
    if (In(t, {"heart", "circle", "ring", "triangle", "dome", "spiral", "crescent", "pentagon"}) &&
        !(i + 1 < tokens_.size() && (shape_word(i + 1) || In(tokens_[i + 1], {"house", "villa", "home", "building", "footprint", "plan"}))))
      return 0;
    item.shape.reset();
    len = 1;
  } else {
    return 0;
  }
  // A shape word describing a room or a piece of furniture ("a round table", "a rectangular living
  // room") is not the footprint.
  if (FurnitureStartsWithin(i + len, 2) || (RoomStartsWithin(i + len, 2) && !shape_word(i + len))) return 0;
  if (shape_word(i + len)) ++len;
  return len;
}

bool Parser::HeadsList(int ref_item, int mention_last) const {
  const Item& ref = items_[ref_item];
  const int sentence = tokens_[ref.first].sentence;
  const int before = ref.first - 1;
  const bool opens = before < 0 || tokens_[before].sentence != sentence || tokens_[before].punct == ':' ||
                     tokens_[before].punct == '-';
  if (!opens) return false;
  for (int k = mention_last + 1; k < static_cast<int>(tokens_.size()) && tokens_[k].sentence == sentence; ++k) {
    if (tokens_[k].item >= 0 && items_[tokens_[k].item].kind == ItemKind::kFloorRef) return false;
    if (tokens_[k].punct == ',') return true;
  }
  return false;
}

// "4 bed 3 bath", "a 3-bed house": a count of bedrooms, not beds (a bed is furniture in "a double bed",
// "two beds in the children's room").
bool Parser::IsBedroomCount(std::size_t i) const {
  const Token& t = tokens_[i];
  if (t.punct || (t.word != "bed" && t.word != "beds") || i == 0) return false;
  auto n = Cardinal(tokens_[i - 1]);
  if (!n || tokens_[i - 1].word == "single" || tokens_[i - 1].word == "double" || tokens_[i - 1].word == "triple")
    return false;
  if (i + 1 < tokens_.size() && In(tokens_[i + 1], {"in", "into", "inside", "for", "per"})) return false;
  // "Bunk beds in the kids' room, so two beds": the pieces counted, not bedrooms.
  if (i >= 2 && In(tokens_[i - 2], {"so", "i", "e", "ie", "meaning"})) return false;
  for (std::size_t k = i - 1; k-- > 0 && tokens_[k].sentence == t.sentence;)
    if (tokens_[k].item >= 0 && items_[tokens_[k].item].kind == ItemKind::kFurniture) return false;
  // "Both kids' rooms with one bed and 1 desk each": furniture of the rooms named.
  if (i >= 2 && In(tokens_[i - 2], {"with", "has", "have", "gets", "get", "needs", "need", "wants"})) return false;
  // "per bedroom: 1 bed", "guest room - 2 beds": a room's furnishing note.
  if (i >= 3 && (tokens_[i - 2].punct == ':' || tokens_[i - 2].punct == '-') && !tokens_[i - 3].punct &&
      In(tokens_[i - 3], {"bedroom", "bedrooms", "room", "rooms", "nursery", "suite"}))
    return false;
  return true;
}

int Parser::TryRoom(std::size_t i, Item& item) {
  if (IsBedroomCount(i)) {
    item.category = Category::kBedroom;
    return 1;
  }
  int best = 0;
  for (const auto& w : RoomLexicon()) {
    int len = MatchPhrase(tokens_, i, w.words);
    if (len > best) {
      best = len;
      item.category = w.category;
      item.ensuite = w.ensuite;
      item.open_plan = w.open_plan;
    }
  }
  if (best == 0) return 0;
  // "living" and "dining" alone name a room only where no other noun follows ("living and dining
  // room"), not in "dining table" (furniture wins by length) or "living space" (in the lexicon).
  // "master" alone only in "the master", and "study" / "office" as a verb is rare enough to accept.
  const Token& t = tokens_[i];
  if (best == 1 && t.word == "master" && i + 1 < tokens_.size() && !tokens_[i + 1].punct &&
      !In(tokens_[i + 1], {"and", "or", "with", "on", "upstairs", "has", "is"}))
    return 0;
  // "tired of renting office space": the space rented elsewhere, not a room of the house.
  if (best == 1 && t.word == "office" && i + 1 < tokens_.size() && tokens_[i + 1].word == "space" && i > 0 &&
      In(tokens_[i - 1], {"renting", "rent", "rented", "leasing", "lease", "shared", "coworking"})) {
    tokens_[i].consumed = tokens_[i + 1].consumed = true;
    return 0;
  }
  // "nobody is living out of a suitcase": the verb, not a room.
  if (best == 1 && t.word == "living" && i > 0 && In(tokens_[i - 1], {"is", "are", "am", "be", "been", "was", "were", "not", "start", "keep", "stop"}))
    return 0;
  // "Upstairs for living: ...", "the first floor is for living": what a floor is for, not a room.
  if (best == 1 && t.word == "living" && i > 0 && tokens_[i - 1].word == "for" &&
      (i + 1 == tokens_.size() || tokens_[i + 1].punct)) {
    tokens_[i].consumed = true;
    return 0;
  }
  // "a Victorian-style terrace", "an end terrace": the house, not a balcony (understood, asking nothing).
  if (t.word == "terrace" && i > 0 && In(tokens_[i - 1], {"style", "victorian", "georgian", "edwardian", "end", "mid", "period"})) {
    tokens_[i].consumed = true;
    return 0;
  }
  // "an office villa": a kind of building, not a room in it ("a three-bedroom bungalow" counts rooms).
  if (i + best < tokens_.size() && !tokens_[i + best].punct && !(i > 0 && Cardinal(tokens_[i - 1])) &&
      In(tokens_[i + best], {"villa", "house", "building", "bungalow", "home", "cottage", "block"})) {
    for (int k = 0; k < best; ++k) tokens_[i + k].consumed = true;
    return 0;
  }
  // "Bath not shower", "a bath, not just a shower", "bathtub + shower", "with bath and shower": the fixtures
  // set against each other, not rooms.
  if (best == 1 && In(t, {"bath", "shower", "bathtub", "tub"})) {
    const std::size_t size = tokens_.size();
    auto fixture = [&](std::size_t k) {
      return k < size && !tokens_[k].punct && tokens_[k].sentence == t.sentence && In(tokens_[k], {"bath", "shower", "bathtub", "tub"}) &&
             tokens_[k].word != t.word && !(k + 1 < size && In(tokens_[k + 1], {"room", "rooms"}));
    };
    auto link = [&](const Token& x) {
      return x.punct == '+' || x.punct == ',' || x.punct == '/' || x.punct == '&' ||
             In(x, {"not", "rather", "than", "instead", "of", "over", "and", "or", "plus", "just", "a", "an", "only", "no",
                    "one", "with", "the", "other"});
    };
    bool against = false;
    for (std::size_t k = i + 1, steps = 0; k < size && steps < 6 && !against; ++k, ++steps) {
      if (fixture(k)) against = steps > 0;
      else if (tokens_[k].sentence != t.sentence || !link(tokens_[k])) break;
    }
    for (std::size_t k = i, steps = 0; k-- > 0 && steps < 6 && !against; ++steps) {
      if (fixture(k)) against = steps > 0;
      else if (tokens_[k].sentence != t.sentence || !link(tokens_[k])) break;
    }
    if (against && !(i + 1 < size && In(tokens_[i + 1], {"room", "rooms"}))) return 0;
  }
  // "a building that doubles as home and office", "Home+office, 2 flrs": what the building is, not a room.
  if (best == 1 && t.word == "office" && i >= 2 && (In(tokens_[i - 1], {"and"}) || tokens_[i - 1].punct == '+' ||
                                                    tokens_[i - 1].punct == '&' || tokens_[i - 1].punct == '/') &&
      In(tokens_[i - 2], {"home", "house", "residence", "dwelling"}) && !(i + 1 < tokens_.size() && In(tokens_[i + 1], {"room", "space"}))) {
    tokens_[i].consumed = true;
    return 0;
  }
  // "storage" and "store" alone name a room only as an item of a list ("GF: kit, din, WC, store."), not in
  // "plenty of storage", "somewhere to store bikes".
  if (best == 1 && In(t, {"storage", "store"})) {
    const bool before = i == 0 || tokens_[i - 1].sentence != t.sentence || In(tokens_[i - 1], {"and", "a", "some", "plus", "one", "1"}) ||
                        tokens_[i - 1].punct == ',' || tokens_[i - 1].punct == ':' || tokens_[i - 1].punct == ';' || tokens_[i - 1].punct == '+';
    const bool after = i + 1 == tokens_.size() || tokens_[i + 1].sentence != t.sentence || In(tokens_[i + 1], {"and", "plus"}) ||
                       (tokens_[i + 1].punct && tokens_[i + 1].punct != '-');
    if (!before || !after) return 0;
  }
  // "a walk-in shower in the en-suite", "the downstairs bathroom gets a shower instead", "Both bathrooms
  // with a bathtub": a fixture of a bathroom named beside it, not a room.
  if (best == 1 && In(t, {"shower", "bath"}) && !(i + 1 < tokens_.size() && In(tokens_[i + 1], {"room", "rooms"}))) {
    const std::size_t size = tokens_.size();
    auto bathroom_at = [&](std::size_t k) {
      if (k >= size || tokens_[k].sentence != t.sentence) return false;
      if (tokens_[k].item >= 0)  // read already (the rooms before it)
        return items_[tokens_[k].item].kind == ItemKind::kRoom && items_[tokens_[k].item].category == Category::kBathroom &&
               !In(tokens_[k], {"shower", "bath"});
      for (const auto& w : RoomLexicon())
        if (w.category == Category::kBathroom && MatchPhrase(tokens_, k, w.words) > 0 && !In(tokens_[k], {"shower", "bath"})) return true;
      return false;
    };
    // "... in / inside the <bathroom>" right after it.
    std::size_t k = i + 1;
    if (k < size && In(tokens_[k], {"in", "inside", "for"})) {
      ++k;
      while (k < size && In(tokens_[k], {"the", "a", "an", "each", "every", "both", "our", "my", "upstairs", "downstairs", "main",
                                         "master", "family", "guest"}))
        ++k;
      if (bathroom_at(k)) return 0;
    }
    // A verb or "with" before it (past its article and adjectives) whose subject is a bathroom.
    std::size_t b = i;
    while (b > 0 && tokens_[b - 1].sentence == t.sentence &&
           In(tokens_[b - 1], {"a", "an", "the", "walk", "in", "big", "large", "separate", "rain", "corner", "double", "proper",
                               "freestanding", "free", "standing", "deep", "roll", "top", "only", "just"}))
      --b;
    if (b > 0 && In(tokens_[b - 1], {"with", "gets", "get", "has", "have", "wants", "want", "needs", "need", "getting"})) {
      for (std::size_t q = b - 1; q-- > 0 && q + 8 > b && tokens_[q].sentence == t.sentence;)
        if (bathroom_at(q)) return 0;
    }
    if (i > 0 && tokens_[i - 1].word == "walk") return 0;  // "walk-in shower": a fixture whatever follows
  }
  // "Bathtub in one of the bathrooms, the other shower only": what the other one holds, not a room.
  if (best == 1 && In(t, {"shower", "bath"}) &&
      ((i + 1 < tokens_.size() && tokens_[i + 1].word == "only") || (i > 0 && tokens_[i - 1].word == "other")))
    return 0;
  if (best == 1 && (t.word == "shower" || t.word == "bath") && i > 0 && In(tokens_[i - 1], {"a", "the"}) &&
      i + 1 < tokens_.size() && In(tokens_[i + 1], {"in", "inside"}))
    return 0;  // "a shower in the bathroom": furniture
  return best;
}

// Like MatchPhrase, but adverbs may sit between the words ("led directly into", "flows straight into").
int MatchCue(const std::vector<Token>& tokens, std::size_t i, const std::vector<std::string>& phrase) {
  std::size_t k = i;
  for (std::size_t w = 0; w < phrase.size(); ++w) {
    if (w > 0)
      while (k < tokens.size() && tokens[k].item < 0 && !tokens[k].punct && tokens[k].sentence == tokens[i].sentence &&
             In(tokens[k], {"directly", "straight", "right", "immediately", "also", "conveniently", "easily"}) &&
             tokens[k].word != phrase[w])
        ++k;
    if (k >= tokens.size()) return 0;
    const Token& t = tokens[k];
    if (t.punct || t.item >= 0 || t.sentence != tokens[i].sentence) return 0;
    if (t.word != phrase[w] && t.stem != phrase[w]) return 0;
    ++k;
  }
  return static_cast<int>(k - i);
}

int Parser::TryCue(std::size_t i, Item& item) {
  int best = 0;
  for (const auto& w : CueLexicon()) {
    int len = MatchCue(tokens_, i, w.words);
    if (len > best) {
      best = len;
      item.link = w.kind;
      item.mutual = w.mutual;
    }
  }
  return best;
}

int Parser::TryPanoramic(std::size_t i, Item& item) {
  static const std::vector<std::vector<std::string>> phrases = [] {
    std::vector<std::vector<std::string>> out;
    for (auto p : {"panoramic window", "panoramic windows", "panoramic glazing", "panoramic glass",
                   "panorama window", "panoramic view", "panoramic", "floor to ceiling window",
                   "floor to ceiling glazing", "floor to ceiling glass", "full height window",
                   "full height glazing", "picture window", "glass wall", "window wall", "panoramic glass wall",
                   "panoramic glazed wall", "panoramic opening", "wall of glass", "wall of window"})
      out.push_back(Split(p));
    return out;
  }();
  int best = 0;
  for (const auto& p : phrases) best = std::max(best, MatchPhrase(tokens_, i, p));
  return best;
}

int Parser::TryFurniture(std::size_t i, Item& item) {
  int best = ObjectWordsAt(i);
  if (best == 0) return 0;
  // "a kitchen, a shower": a shower is a room (a bathroom) unless the room reading takes it for a fixture
  // ("the downstairs bathroom gets a shower").
  if (best == 1 && (tokens_[i].stem == "shower" || tokens_[i].stem == "bath")) {
    Item room = MakeItem(ItemKind::kRoom);
    if (TryRoom(i, room) > 0) return 0;
  }
  // "flat-screen TV": the first noun is a modifier of the next one.
  if (FurnitureStartsWithin(i + best, 1)) return 0;
  // "bookshelves full of books", "a cabinet filled with toys": the contents belong to the wish.
  for (auto contents : {"full of", "filled with", "stocked with", "packed with", "loaded with", "lined with"}) {
    int len = MatchPhrase(tokens_, i + best, Split(contents));
    if (len == 0) continue;
    std::size_t k = i + best + len;
    while (k < tokens_.size() && !tokens_[k].punct && In(tokens_[k], {"a", "an", "some", "many", "lots", "of"})) ++k;
    if (int n = ObjectWordsAt(k); n > 0) best = static_cast<int>(k - i) + n;
    break;
  }
  // "a dining table for six": the seats belong to the item.
  if (i + best + 1 < tokens_.size() && tokens_[i + best].word == "for" && Cardinal(tokens_[i + best + 1]) &&
      tokens_[i + best + 1].sentence == tokens_[i].sentence)
    best += 2;
  item.item_first = static_cast<int>(i);
  // Modifiers before the noun belong to the item ("a large flat-screen TV"): unknown words and
  // adjectives back to a determiner, number or verb.
  int k = static_cast<int>(i) - 1;
  while (k >= 0 && !tokens_[k].punct && tokens_[k].item < 0 && tokens_[k].sentence == tokens_[i].sentence &&
         !Cardinal(tokens_[k]) &&
         (IsAdjective(tokens_[k]) || !IsFiller(tokens_[k])) && !IsNegation(tokens_[k]) &&
         !In(tokens_[k], {"a", "an", "the", "some", "own", "second"})) {
    item.item_first = k;
    --k;
  }
  // "a walk-in shower", "a walk-in wardrobe".
  if (k >= 1 && tokens_[k].word == "in" && tokens_[k - 1].word == "walk" && tokens_[k - 1].item < 0 &&
      tokens_[k - 1].sentence == tokens_[i].sentence)
    item.item_first = k - 1;
  return best;
}

// Seats asked of a room or its table, for the furnishing stage: "that can seat eight people", "seats 10",
// "seating for twelve", "for six guests", "a dining room for twelve", "an eight-seat table". The words
// from the verb to the number (and the people after it) are the wish; the room it names binds it.
int Parser::TryCapacity(std::size_t i, Item& item) {
  auto same = [&](std::size_t k) { return k < tokens_.size() && !tokens_[k].punct && tokens_[k].sentence == tokens_[i].sentence; };
  auto people = [&](std::size_t k) {
    return same(k) && In(tokens_[k], {"people", "persons", "guests", "diners", "adults", "comfortably", "person", "guest"});
  };
  const Token& t = tokens_[i];
  std::size_t k = i + 1;
  if (Cardinal(t) && same(k) && In(tokens_[k], {"seat", "seater", "seats"})) {  // "an eight-seat table"
    item.item_first = static_cast<int>(i);
    return 2;
  }
  const bool verb = In(t, {"seat", "seats", "seating", "sit", "sits", "sitting", "seated"});
  const bool room_for = In(t, {"room", "space", "place", "places"}) && same(k) && tokens_[k].word == "for";
  if (!verb && !room_for && t.word != "for") return 0;
  if (room_for) ++k;
  for (int skip = 0; skip < 3 && same(k) && In(tokens_[k], {"for", "up", "to", "at", "least", "around", "about", "comfortably"}); ++skip) ++k;
  if (!same(k) || !Cardinal(tokens_[k]) || *Cardinal(tokens_[k]) < 2 || *Cardinal(tokens_[k]) > 40) return 0;
  // A bare "for twelve" seats only after a room that dines or meets ("a dining room for twelve"), or with
  // people after it ("for six guests"): "a garage for two" is no table.
  if (t.word == "for") {
    const bool dines = i > 0 && tokens_[i - 1].item >= 0 && items_[tokens_[i - 1].item].kind == ItemKind::kRoom &&
                       (items_[tokens_[i - 1].item].category == Category::kDiningRoom ||
                        items_[tokens_[i - 1].item].category == Category::kMeetingRoom);
    if (!dines && !people(k + 1)) return 0;
  }
  item.item_first = static_cast<int>(i);
  return static_cast<int>(k - i) + 1 + (people(k + 1) ? 1 : 0);
}

int Parser::TryEntrance(std::size_t i, Item& item) {
  static const std::vector<std::vector<std::string>> phrases = [] {
    std::vector<std::vector<std::string>> out;
    for (auto p : {"entrance", "entry", "front door", "main door", "main entrance", "front entrance",
                   "entrance door", "entry door", "front entry", "way in", "entrance hall"})
      out.push_back(Split(p));
    return out;
  }();
  int best = 0;
  for (const auto& p : phrases) best = std::max(best, MatchPhrase(tokens_, i, p));
  // "entrance level" is a floor (matched before this), "entrance" alone an entrance.
  return best;
}

int Parser::TrySide(std::size_t i, Item& item) {
  const Token& t = tokens_[i];
  std::string side;
  if (In(t, {"north", "northern", "northward"})) side = "north";
  else if (In(t, {"south", "southern", "southward"})) side = "south";
  else if (In(t, {"east", "eastern", "eastward"})) side = "east";
  else if (In(t, {"west", "western", "westward"})) side = "west";
  else return 0;
  // "north-east" corners are not one side: keep only the plain sides.
  if (i + 1 < tokens_.size() && tokens_[i + 1].joined &&
      In(tokens_[i + 1], {"north", "south", "east", "west", "eastern", "western"}))
    return 0;
  item.side = side;
  int len = 1;
  if (i + 1 < tokens_.size() && In(tokens_[i + 1], {"side", "end", "part", "wing", "facing", "edge", "half"})) ++len;
  return len;
}

void Parser::MatchAll() {
  // Prescan for the numbering conventions.
  bool ground = false, first = false, glossed_ground = false;
  bool numbered = false;  // "Floor 1", "level 2"
  for (std::size_t i = 0; i + 1 < tokens_.size(); ++i) {
    // "ground floor", and the heading "Ground: ..." of a spec sheet.
    // ("ground and first floor": the ground floor named with the first.)
    if (tokens_[i].word == "ground" && (IsFloorNoun(tokens_[i + 1]) || tokens_[i + 1].punct == ':' ||
                                        (i + 3 < tokens_.size() && tokens_[i + 1].word == "and" && Ordinal(tokens_[i + 2]) == 1 &&
                                         IsFloorNoun(tokens_[i + 3]))))
      ground = true;
    if (Ordinal(tokens_[i]) == 1 && (IsFloorNoun(tokens_[i + 1]) || ElidedFloor(i)) && !NegatedFloor(i)) {
      // "1st floor (ground level)": the first floor is the ground floor (American).
      // ("1st floor (that's ground level)", "(i.e. street level)": a few words may come first.)
      std::size_t g = i + 3;
      while (g < tokens_.size() && g < i + 6 && In(tokens_[g], {"thats", "that", "is", "ie", "i", "e", ".", "the", "at", "on"})) ++g;
      if (i + 3 < tokens_.size() && tokens_[i + 2].punct == '(' && g < tokens_.size() && In(tokens_[g], {"ground", "street", "entry", "entrance"})) {
        glossed_ground = true;
        continue;
      }
      first = true;
    }
    if (IsFloorNoun(tokens_[i]) && (tokens_[i + 1].word == "0" || tokens_[i + 1].word == "zero")) zero_based_numbers_ = true;
    if (IsFloorNoun(tokens_[i]) && Cardinal(tokens_[i + 1]) && *Cardinal(tokens_[i + 1]) >= 1) numbered = true;
  }
  british_ = ground && first && !glossed_ground;
  for (std::size_t i = 0; i + 1 < tokens_.size(); ++i)
    if (tokens_[i].word == "ground" && (tokens_[i + 1].punct == ':' || (IsFloorNoun(tokens_[i + 1]) && i + 2 < tokens_.size() && tokens_[i + 2].punct == ':')))
      ground_heading_ = true;
  // A text that heads its floors "ground: ... first: ..." is British.
  if (ground_heading_)
    for (std::size_t i = 0; i + 1 < tokens_.size(); ++i)
      if (Ordinal(tokens_[i]) == 1 && tokens_[i + 1].punct == ':') british_ = true;
  // A text that names its ground floor counts numbered floors up from it: "Ground: ... Floor 1: ..." puts
  // floor 1 above the ground floor.
  if (ground && numbered) zero_based_numbers_ = true;

  for (std::size_t i = 0; i < tokens_.size();) {
    if (tokens_[i].punct) {
      ++i;
      continue;
    }
    struct Candidate {
      int len = 0;
      Item item = MakeItem(ItemKind::kRoom);
    };
    Candidate best;
    auto consider = [&](ItemKind kind, auto fn) {
      Item item = MakeItem(kind);
      int len = (this->*fn)(i, item);
      if (len > best.len) {
        best.len = len;
        best.item = item;
      }
    };
    // Order is priority on equal length.
    consider(ItemKind::kFloorCount, &Parser::TryFloorCount);
    consider(ItemKind::kFloorRef, &Parser::TryFloorRef);
    consider(ItemKind::kPanoramic, &Parser::TryPanoramic);
    consider(ItemKind::kFurniture, &Parser::TryFurniture);
    consider(ItemKind::kFurniture, &Parser::TryCapacity);
    consider(ItemKind::kRoom, &Parser::TryRoom);
    consider(ItemKind::kShape, &Parser::TryShape);
    consider(ItemKind::kEntrance, &Parser::TryEntrance);
    consider(ItemKind::kCue, &Parser::TryCue);
    consider(ItemKind::kSide, &Parser::TrySide);
    if (best.len == 0) {
      ++i;
      continue;
    }
    Item item = best.item;
    item.first = static_cast<int>(i);
    item.last = static_cast<int>(i) + best.len - 1;
    if (item.kind == ItemKind::kFurniture) item.first = std::min(item.first, item.item_first);
    int index = static_cast<int>(items_.size());
    for (int k = item.first; k <= item.last; ++k) tokens_[k].item = index;
    Consume(item.first, item.last);
    items_.push_back(item);
    i = static_cast<std::size_t>(item.last) + 1;
  }
}

// The quantity of a room mention from the words before it (and "bedrooms: 3" after it).
void Parser::Quantify(Mention& m) {
  const Item& item = items_[m.item];
  const Token& noun = tokens_[item.last];
  m.plural = noun.stem != noun.word && noun.word != "children";
  m.first = item.first;
  m.last = item.last;
  if (per_items_.count(m.item)) {  // "for every two bedrooms": the bedrooms counted before
    m.definite = true;
    return;
  }
  int k = item.first - 1;
  int sentence = tokens_[item.first].sentence;
  // "1 mirror per bathroom", "two plants per balcony": the rooms counted elsewhere, each furnished.
  if (k >= 1 && In(tokens_[k], {"per"}) && tokens_[k].sentence == sentence && tokens_[k - 1].item >= 0 &&
      items_[tokens_[k - 1].item].kind == ItemKind::kFurniture) {
    m.definite = true;
    tokens_[k].consumed = true;
    return;
  }
  // "master suite - bedroom plus its own bathroom": the suite's bedroom, said again.
  if (k >= 1 && tokens_[k].punct == '-' && tokens_[k - 1].item >= 0 && tokens_[k].sentence == sentence &&
      items_[tokens_[k - 1].item].kind == ItemKind::kRoom && items_[tokens_[k - 1].item].category == item.category &&
      tokens_[k - 1].word == "suite") {
    m.definite = true;
    return;
  }
  bool determined = false;
  auto at = [&](int j) -> const Token* {
    return j >= 0 && tokens_[j].sentence == sentence ? &tokens_[j] : nullptr;
  };
  // "three or more bedrooms"
  if (at(k) && at(k - 1) && at(k - 2) && at(k)->word == "more" && at(k - 1)->word == "or" && Cardinal(*at(k - 2))) {
    m.counting = true;
    m.min = *Cardinal(*at(k - 2));
    m.max = -1;
    m.first = k - 2;
    Consume(k - 2, k);
    k = -1;  // quantified: skip the scans below
    determined = true;
  }
  // Adjectives, a bound floor ("second-floor"), en-suite / open-plan words.
  while (const Token* t = k >= 0 ? at(k) : nullptr) {
    if (t->item >= 0 && items_[t->item].kind == ItemKind::kFloorRef && m.bound_ref < 0 &&
        items_[t->item].ref != RefType::kSame && !HeadsList(t->item, item.last)) {
      m.bound_ref = t->item;
      k = items_[t->item].first - 1;
      continue;
    }
    if (t->item >= 0) break;
    if (In(*t, {"en", "suite", "ensuite", "attached", "private", "own"}) && item.category == Category::kBathroom) {
      m.first = k;
      if (!In(*t, {"private"})) items_[m.item].ensuite = true;
      tokens_[k].consumed = true;
      --k;
      continue;
    }
    if (In(*t, {"en", "suite", "ensuite"}) && (item.category == Category::kBedroom || item.category == Category::kChildrenRoom)) {
      items_[m.item].ensuite = true;  // "an en-suite bedroom": a bedroom with its own bathroom
      tokens_[k].consumed = true;
      m.first = k;
      --k;
      continue;
    }
    if (In(*t, {"open", "openplan"}) || (t->word == "plan" && k > 0 && tokens_[k - 1].word == "open")) {
      items_[m.item].open_plan = true;
      tokens_[k].consumed = true;
      m.first = k;
      --k;
      continue;
    }
    if (IsAdjective(*t) && !Cardinal(*t)) {
      m.first = k;
      --k;
      continue;
    }
    break;
  }
  // The quantifier.
  const Token* t = determined || k < 0 ? nullptr : at(k);
  auto negated_before = [&](int from) {
    for (int j = from, steps = 0; j >= 0 && steps < 4 && tokens_[j].sentence == sentence; --j, ++steps) {
      if (IsNegation(tokens_[j])) {
        tokens_[j].consumed = true;
        return true;
      }
      if (tokens_[j].punct || tokens_[j].item >= 0) return false;
      if (!In(tokens_[j], {"need", "want", "have", "require", "include", "any", "for", "a", "an", "will",
                           "should", "would", "do", "does", "is", "are", "there", "be", "like", "must", "it",
                           "at", "all", "add", "put", "build", "get", "really", "bother", "with", "the", "rather"}))
        return false;
    }
    return false;
  };
  // "3 bedrooms, 2 of them en-suite", "2 of which have en-suites": that many of the rooms named before get
  // one each.
  if (t && !determined) {
    int j = k;
    if (at(j) && In(*at(j), {"have", "has", "are", "is", "with", "get", "come"})) --j;
    if (at(j) && at(j - 1) && at(j - 2) && In(*at(j), {"them", "which", "these", "those"}) && at(j - 1)->word == "of" &&
        Cardinal(*at(j - 2))) {
      m.counting = true;
      m.min = m.max = *Cardinal(*at(j - 2));
      m.first = j - 2;
      Consume(j - 2, k);
      determined = true;
      t = nullptr;
    }
  }
  if (t) {
    if (IsNegation(*t)) {
      m.counting = true;
      m.min = m.max = 0;
      tokens_[k].consumed = true;
      m.first = k;
      determined = true;
    } else if (auto n = Cardinal(*t); n && at(k - 1) && at(k - 2) && at(k - 1)->word == "the" && at(k - 2)->word == "of") {
      determined = true;  // "each of the three bedrooms": the three counted elsewhere
      m.definite = true;
      m.first = k - 2;
    } else if (auto n = Cardinal(*t)) {
      m.counting = true;
      m.min = m.max = *n;
      m.first = k;
      tokens_[k].consumed = true;
      determined = true;
      // "at least two", "two or more", "up to three"
      if (const Token* p = at(k - 1); p && p->word == "least" && at(k - 2) && at(k - 2)->word == "at") {
        m.max = -1;
        m.first = k - 2;
        Consume(k - 2, k - 1);
      } else if (p && (p->word == "to" || p->word == "most") && at(k - 2) &&
                 (at(k - 2)->word == "up" || at(k - 2)->word == "at")) {
        m.min = std::min(1, *n);
        m.first = k - 2;
        Consume(k - 2, k - 1);
      } else if (p && p->word == "minimum" ) {
        m.max = -1;
      } else if (p && p->word == "x") {
        // "x 2 bedrooms" is odd; leave as is
      }
      if (item.last + 2 < static_cast<int>(tokens_.size()) && tokens_[item.last + 1].word == "or" &&
          In(tokens_[item.last + 2], {"more"})) {
        m.max = -1;
        Consume(item.last + 1, item.last + 2);
        m.last = item.last + 2;
      }
      if (negated_before(k - 1)) m.min = m.max = 0;
    } else if (In(*t, {"a", "an", "another", "one"})) {
      m.counting = true;
      m.min = m.max = 1;
      m.first = k;
      determined = true;
      if (negated_before(k - 1)) m.min = m.max = 0;
    } else if (In(*t, {"several", "multiple", "few", "couple", "pair"}) ||
               (t->word == "of" && at(k - 1) && In(*at(k - 1), {"couple", "pair"}))) {
      m.counting = true;
      bool exact_two = In(*t, {"couple", "pair"}) || t->word == "of";
      m.min = 2;
      m.max = exact_two ? 2 : -1;
      m.first = t->word == "of" ? k - 1 : k;
      Consume(m.first, k);
      if (at(m.first - 1) && In(*at(m.first - 1), {"a"})) --m.first;
      determined = true;
    } else if (In(*t, {"each", "every"})) {
      m.every = true;
      m.first = k;
      determined = true;
    } else if (t->word == "both" && m.plural &&
               std::none_of(mentions_.begin(), mentions_.end(),
                            [&](const Mention& o) { return o.category == item.category && !(o.counting && o.max == 0); })) {
      // "both bathrooms on the ground floor" with no bathrooms named before: two of them.
      m.counting = true;
      m.min = m.max = 2;
      m.first = k;
      tokens_[k].consumed = true;
      determined = true;
    } else if (In(*t, {"some"})) {
      m.counting = true;
      m.min = 1;
      m.max = -1;
      m.first = k;
      determined = true;
    } else if (item.category == Category::kBathroom && items_[m.item].ensuite && !m.plural &&
               In(*t, {"its", "his", "her", "my", "our"}) && at(k - 1) && at(k - 1)->word == "with" &&
               !mentions_.empty() && tokens_[mentions_.back().first].sentence == sentence && !mentions_.back().definite) {
      // "a master bedroom with its own bath" in a list of rooms: one more bathroom, the bedroom's (the link
      // is kept too). "The bedroom ... with its own bathroom" (a definite room, a relation sentence after
      // the list) still refers to a bathroom counted in the list.
      m.counting = true;
      m.min = m.max = 1;
      m.first = k;
      determined = true;
    } else if (In(*t, {"the", "this", "that", "these", "those", "its", "their", "our", "my", "his", "her",
                       "both", "all", "same"})) {
      determined = true;  // a reference to a room counted elsewhere
      m.definite = true;
      m.first = k;
      // "a guest bedroom downstairs ... Upstairs: the master bedroom": the master bedroom is no guest room,
      // so one more (where every bedroom named before is a guest or spare one).
      auto has = [&](int from, int to, std::initializer_list<std::string_view> words) {
        for (int q = from; q <= to; ++q)
          if (In(tokens_[q], words)) return true;
        return false;
      };
      // Whether any room of `c` was counted before, and whether every one counted is `lesser` (a guest
      // bedroom, a WC or an en-suite): then the named room is one more, not one of them.
      auto only_lesser_before = [&](Category c, auto&& lesser) {
        bool any = false, all = true;
        for (const Mention& o : mentions_)
          if (o.category == c && o.counting && o.max != 0) {
            any = true;
            all = all && lesser(o);
          }
        return std::pair{any, all};
      };
      auto guest = [&](const Mention& o) { return has(o.first, o.last, {"guest", "spare"}); };
      auto small = [&](const Mention& o) {
        return items_[o.item].ensuite || has(o.first, o.last, {"wc", "loo", "toilet", "powder", "cloakroom", "lavatory"});
      };
      bool one_more = false;
      if (t->word == "the" && item.category == Category::kBedroom && has(item.first, item.last, {"master", "main", "primary", "principal"})) {
        const auto [any, all] = only_lesser_before(Category::kBedroom, guest);
        one_more = any && all;
      }
      // "Upstairs should be our bedroom, a guest bedroom ...", "her bedroom, a spare bedroom": the bedroom of
      // the people asking is a room of the list (none but guest rooms counted before it); after bedrooms
      // counted, "our bedroom" is one of them.
      if (In(*t, {"our", "my", "her", "his", "their"}) && item.category == Category::kBedroom && !has(item.first, item.last, {"guest", "spare"}))
        one_more = only_lesser_before(Category::kBedroom, guest).second;
      // "... a loo. First floor: master bedroom with en-suite, the main bathroom": the family bathroom is
      // neither the en-suite nor the WC named before, so one more.
      if (t->word == "the" && item.category == Category::kBathroom && has(k, item.last, {"main", "family"})) {
        const auto [any, all] = only_lesser_before(Category::kBathroom, small);
        one_more = any && all;
      }
      if (one_more) {
        m.definite = false;
        m.counting = true;
        m.min = m.max = 1;
      }
      // "skip the dining room", "forget the balcony", "no need for the office": none of it.
      if (negated_before(k - 1)) {
        m.definite = false;
        m.counting = true;
        m.min = m.max = 0;
      }
    }
  }
  // A count after the noun: "Bedrooms: 3", "bathrooms x 2", "bedrooms x3", "bedrooms (3)" (spec sheets and lists).
  int after = item.last + 1;
  const int size = static_cast<int>(tokens_.size());
  auto trailing = [&]() -> std::optional<std::pair<int, int>> {  // the count and the last token it takes
    if (determined || after >= size || tokens_[after].sentence != sentence) return std::nullopt;
    const Token& next = tokens_[after];
    if (next.word.size() >= 2 && next.word[0] == 'x' &&
        std::all_of(next.word.begin() + 1, next.word.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
      return std::pair{std::stoi(next.word.substr(1)), after};
    if (next.punct == '(' && after + 2 < size && Cardinal(tokens_[after + 1]) && tokens_[after + 2].punct == ')')
      return std::pair{*Cardinal(tokens_[after + 1]), after + 2};
    // ("Lvg rm: 2 armchairs", "dining room: 1 table, 4 chairs", "bdrms: 2x single beds each": the count
    // is the furniture's.)
    auto furniture_at = [&](int k) {
      for (int q = k; q < size && q < k + 3 && !tokens_[q].punct && tokens_[q].sentence == sentence; ++q)
        if (tokens_[q].item >= 0) return items_[tokens_[q].item].kind == ItemKind::kFurniture;
      return false;
    };
    if ((next.punct == ':' || next.word == "x" || next.punct == '*' || next.punct == '-' || next.punct == '=') && after + 1 < size &&
        Cardinal(tokens_[after + 1]) && tokens_[after + 1].sentence == sentence &&
        !(after + 2 < size && IsFloorNoun(tokens_[after + 2])) && !furniture_at(after + 2))
      return std::pair{*Cardinal(tokens_[after + 1]), after + 1};
    // "bedroom count = 4", "bathrooms total: 2", "number = 3" (spec sheets and forms).
    if (In(next, {"count", "total", "number", "qty", "quantity"}) && after + 2 < size &&
        (tokens_[after + 1].punct == ':' || tokens_[after + 1].punct == '=' || tokens_[after + 1].punct == '-') &&
        Cardinal(tokens_[after + 2]) && tokens_[after + 2].sentence == sentence)
      return std::pair{*Cardinal(tokens_[after + 2]), after + 2};
    // "Study: no", "Kitchen - yes" (spec sheets).
    // ("living room - no dining room": the "no" is the dining room's, after a dash.)
    if ((next.punct == ':' || next.punct == '-') && after + 1 < size && tokens_[after + 1].sentence == sentence &&
        In(tokens_[after + 1], {"no", "none", "yes"}) &&
        (after + 2 >= size || tokens_[after + 2].punct || tokens_[after + 2].sentence != sentence ||
         (tokens_[after + 2].item >= 0 && next.punct == ':')))
      return std::pair{tokens_[after + 1].word == "yes" ? 1 : 0, after + 1};
    return std::nullopt;
  };
  // "Level 0 (ground): kitchen, living room, dining room, bathroom - 4", "Level 1: 3 bedrooms + 1 bathroom -
  // 4": the list's count, said after its last room, not this room's.
  if (after + 1 < size && tokens_[after].punct == '-' && tokens_[after].sentence == sentence && Cardinal(tokens_[after + 1]) &&
      (after + 2 >= size || tokens_[after + 2].punct || tokens_[after + 2].sentence != sentence)) {
    int heading = m.first;
    while (heading > 0 && tokens_[heading - 1].sentence == sentence && tokens_[heading - 1].punct != ':') --heading;
    int in_list = determined && m.counting ? std::max(m.min, 0) : 1;
    for (const Mention& o : mentions_)
      if (o.first >= heading && o.last < m.first && tokens_[o.first].sentence == sentence) in_list += o.counting ? std::max(o.min, 0) : 1;
    if (in_list >= 2 && in_list == *Cardinal(tokens_[after + 1])) {
      Consume(after, after + 1);
      after = size;  // no count after the noun
    }
  }
  if (const auto count = trailing()) {
    m.counting = true;
    m.min = m.max = count->first;
    Consume(after, count->second);
    m.last = count->second;
    determined = true;
  }
  // "Kids rm: desk.", "Lvg rm: big sectional + TV", "Mtg rm w/ 6 chairs", "Kit needs fridge & dishwasher":
  // a bare room noun heading a clause of furniture (and no room) after rooms of its kind were counted is
  // one of them, named for its furnishing (terse notes), not one more.
  if (!determined && after < size && tokens_[after].sentence == sentence &&
      (tokens_[after].punct == ':' || tokens_[after].punct == '-' ||
       In(tokens_[after], {"with", "needs", "need", "gets", "get", "has", "wants", "should"}))) {
    bool furniture = false, room = false;
    for (int q = after + 1; q < size && tokens_[q].sentence == sentence; ++q) {
      const int it = tokens_[q].item;
      if (it < 0 || it == m.item) continue;
      furniture = furniture || items_[it].kind == ItemKind::kFurniture;
      room = room || items_[it].kind == ItemKind::kRoom;
    }
    const bool counted = std::any_of(mentions_.begin(), mentions_.end(), [&](const Mention& o) {
      return o.category == item.category && o.counting && o.max != 0;
    });
    if (furniture && !room && counted) {
      m.definite = true;
      determined = true;
    }
  }
  // "piano in GF lvg rm", "2 plants on balc" (notes without articles): a piece put in a room of a kind
  // counted before is put in one of them, not in one more.
  if (!determined && m.first >= 2) {
    int b = m.first - 1;
    while (b >= 0 && tokens_[b].sentence == sentence && !tokens_[b].punct &&
           (In(tokens_[b], {"ground", "floor", "first", "second", "third", "top", "upstairs", "downstairs", "upper", "lower"}) ||
            tokens_[b].ordinal > 0))
      --b;
    bool furniture_before = false;
    for (int q = b - 1; q >= 0 && tokens_[q].sentence == sentence; --q)
      furniture_before = furniture_before || (tokens_[q].item >= 0 && items_[tokens_[q].item].kind == ItemKind::kFurniture);
    const bool counted = std::any_of(mentions_.begin(), mentions_.end(), [&](const Mention& o) {
      return o.category == item.category && o.counting && o.max != 0;
    });
    if (b >= 1 && tokens_[b].sentence == sentence && In(tokens_[b], {"in", "on", "into", "onto"}) && furniture_before && counted) {
      m.definite = true;
      determined = true;
    }
  }
  // "4 bedrooms (2 of them are kids' rooms)", "two bedrooms, one of them a guest bedroom": part of a count
  // before it in the sentence, not more rooms. Kids' rooms out of bedrooms are taken from the bedrooms.
  {
    int j = m.first - 1;
    auto word = [&](int x, std::initializer_list<std::string_view> ws) {
      return x >= 0 && tokens_[x].sentence == sentence && In(tokens_[x], ws);
    };
    while (word(j, {"a", "an", "are", "is", "being", "will", "be"})) --j;
    std::optional<int> part = j >= 2 && word(j, {"them", "which", "those", "these"}) && word(j - 1, {"of"}) &&
                                      tokens_[j - 2].sentence == sentence
                                  ? Cardinal(tokens_[j - 2])
                                  : std::nullopt;
    // The count already taken into the phrase: "(2 of them are kids' rooms)" read as "2 ... rooms".
    if (!part && m.first + 2 <= m.last && Cardinal(tokens_[m.first]) && word(m.first + 1, {"of"}) && word(m.first + 2, {"them"})) {
      part = Cardinal(tokens_[m.first]);
      j = m.first + 2;
    }
    // "3 bed (1 master)": a count in brackets right after the rooms it is part of.
    if (!part && m.counting && m.first >= 1 && tokens_[m.first - 1].punct == '(' && m.last + 1 < size &&
        tokens_[m.last + 1].punct == ')' && Cardinal(tokens_[m.first]) && !mentions_.empty() &&
        mentions_.back().last == m.first - 2 && mentions_.back().counting) {
      part = m.min;
      j = m.first + 2;  // Consume(j - 2, j) below takes the count and the noun's first token at most
      if (mentions_.back().category == item.category && mentions_.back().min >= *part) {
        m.counting = false;
        m.definite = true;
        determined = true;
        part.reset();
      }
    }
    // "two bedrooms (ours plus a guest room)", "Bedrooms: 5 (incl. master)", "the four bedrooms (well,
    // strictly three bedrooms and a nursery)": rooms named further into brackets that open right after a
    // count are parts of it ("(plus a study)" adds one).
    if (!part && (m.counting || !determined)) {  // (a bare "master" too)
      int b = m.first - 1;
      while (b >= 0 && tokens_[b].sentence == sentence && tokens_[b].punct != '(' && tokens_[b].punct != ')') --b;
      const bool more = b + 1 < size && (tokens_[b + 1].punct == '+' ||
                                         In(tokens_[b + 1], {"plus", "and", "also", "extra", "with", "another", "additional", "as"}));
      if (b >= 1 && b + 1 < m.first && tokens_[b].punct == '(' && tokens_[b].sentence == sentence && !more) {
        for (Mention& p : mentions_) {
          if (p.last != b - 1 || !p.counting) continue;
          if (p.category == item.category && p.min >= m.min) {
            m.counting = false;
            m.definite = true;
            determined = true;
          } else if (p.category == Category::kBedroom && item.category == Category::kChildrenRoom && p.min > m.min && p.max == p.min) {
            p.min -= m.min;
            p.max -= m.min;
            determined = true;
          }
          break;
        }
      }
    }
    if (part && *part > 0) {
      for (auto it = mentions_.rbegin(); it != mentions_.rend() && tokens_[it->first].sentence == sentence; ++it) {
        const bool same = it->category == item.category;
        const bool kids = it->category == Category::kBedroom && item.category == Category::kChildrenRoom;
        if (!it->counting || it->min < *part || it->max < *part || (!same && !kids)) continue;
        if (same) {
          m.counting = false;
          m.definite = true;
        } else {
          it->min -= *part;
          it->max -= *part;
          m.counting = true;
          m.min = m.max = *part;
        }
        Consume(j - 2, j);
        determined = true;
        break;
      }
    }
  }
  // "three kids: a children's room for each kid", "two sons, a bedroom per son": as many as the people
  // the text counts before it.
  if (m.counting && m.min == 1 && m.max == 1 && item.last + 2 < size && tokens_[item.last + 1].sentence == sentence) {
    int j = item.last + 1;
    if (tokens_[j].word == "for") ++j;
    if (j + 1 < size && In(tokens_[j], {"each", "every", "per"}) && IsChildWord(tokens_[j + 1], false)) {
      for (int q = m.first - 1; q >= 1; --q)
        if (IsChildWord(tokens_[q], false) && Cardinal(tokens_[q - 1]) && *Cardinal(tokens_[q - 1]) >= 2 && tokens_[q].item < 0) {
          m.min = m.max = *Cardinal(tokens_[q - 1]);
          Consume(q - 1, q);  // the people counted: no words left unread
          Consume(item.last + 1, j + 1);
          m.last = j + 1;
          break;
        }
    }
  }
  // "one bathroom for every two bedrooms": as many as the bedrooms counted before it make, rounded up; the
  // bedrooms named after it are those (per_items_).
  if (m.counting && m.min >= 1 && m.max == m.min && item.last + 4 < size && tokens_[item.last + 1].word == "for" &&
      In(tokens_[item.last + 2], {"every", "each"}) && Cardinal(tokens_[item.last + 3]) && *Cardinal(tokens_[item.last + 3]) >= 2 &&
      tokens_[item.last + 4].item >= 0 && items_[tokens_[item.last + 4].item].kind == ItemKind::kRoom) {
    const Category base = items_[tokens_[item.last + 4].item].category;
    const int per = *Cardinal(tokens_[item.last + 3]);
    int counted = 0;
    for (const Mention& o : mentions_)
      if (o.category == base && o.counting && o.max > 0) counted = std::max(counted, o.min);
    if (counted > 0) {
      m.min = m.max = m.min * ((counted + per - 1) / per);
      per_items_.insert(tokens_[item.last + 4].item);
      Consume(item.last + 1, item.last + 3);
    }
  }
  // "two baths including a Jack and Jill bathroom": one of those counted before it in the sentence.
  if (m.counting && m.first > 0 && In(tokens_[m.first - 1], {"including", "incl", "includes", "include"}) &&
      std::any_of(mentions_.begin(), mentions_.end(), [&](const Mention& o) {
        return o.category == item.category && o.counting && o.max != 0 && tokens_[o.last].sentence == sentence;
      })) {
    m.counting = false;
    m.definite = true;
    tokens_[m.first - 1].consumed = true;
    determined = true;
  }
  // "the kitchen, dining room and living room": a bare noun continuing a definite list is definite too.
  if (!determined && !mentions_.empty()) {
    const Mention& previous = mentions_.back();
    if (previous.definite && tokens_[previous.last].sentence == sentence && previous.last < m.first) {
      bool list = true;
      for (int j = previous.last + 1; j < m.first; ++j)
        if (!(tokens_[j].punct == ',' || tokens_[j].punct == '/' || tokens_[j].punct == '&' ||
              In(tokens_[j], {"and", "or"}) || IsAdjective(tokens_[j])))
          list = false;
      if (list) {
        determined = true;
        m.definite = true;
      }
    }
  }
  if (!determined) {
    bare_mention_ = true;
    // A bare noun: "kitchen, living room and bathrooms" states one kitchen, and some bathrooms.
    m.counting = true;
    m.min = m.plural ? 2 : 1;
    m.max = m.plural ? -1 : 1;
    if (negated_before(k)) m.min = m.max = 0;
  }
  // "no study or dining room", "won't need a study or a dining room": the negation runs on over "or" / "nor"
  // to the next room of the list.
  // So does it over "and" to a definite one: "skip the dining room and the office".
  if ((m.counting && m.max != 0) || m.definite) {
    const Mention* previous = mentions_.empty() ? nullptr : &mentions_.back();
    if (previous && previous->counting && previous->max == 0 && tokens_[previous->last].sentence == sentence &&
        previous->last < m.first) {
      bool joined = false, list = true;
      for (int j = previous->last + 1; j < m.first && list; ++j) {
        if (In(tokens_[j], {"or", "nor"}) || (m.definite && In(tokens_[j], {"and"}))) joined = true;
        else if (!(tokens_[j].punct == ',' || In(tokens_[j], {"a", "an", "any", "the"}) || IsAdjective(tokens_[j]))) list = false;
      }
      if (joined && list) {
        m.counting = true;
        m.definite = false;
        m.min = m.max = 0;
      }
    }
  }
  // "Dining room not needed.", "a balcony is not required": none.
  if (item.last + 2 < static_cast<int>(tokens_.size()) && tokens_[item.last + 1].sentence == sentence) {
    int j = item.last + 1;
    if (In(tokens_[j], {"is", "are"})) ++j;
    if (j + 1 < static_cast<int>(tokens_.size()) && In(tokens_[j], {"not", "isnt", "arent"}) &&
        In(tokens_[j + 1], {"needed", "required", "necessary", "wanted"})) {
      m.counting = true;
      m.definite = false;
      m.min = m.max = 0;
      Consume(item.last + 1, j + 1);
      m.last = j + 1;
    }
  }
  // "with" right before the phrase: "a bedroom with a balcony", "with its own bathroom".
  for (int j = m.first - 1, steps = 0; j >= 0 && steps < 3 && tokens_[j].sentence == sentence; --j, ++steps) {
    if (tokens_[j].word == "with") {
      m.with_before = true;
      m.with_token = j;
      break;
    }
    if (tokens_[j].item >= 0 || tokens_[j].punct) break;
    if (!In(tokens_[j], {"a", "an", "its", "their", "own", "private", "direct", "access", "to", "his", "her"})) break;
  }
}

// Resolves a floor reference to a level (or kUpperLevels / kEachLevel).
int Parser::ResolveRef(int ref_item) const {
  const Item& r = items_[ref_item];
  // "upstairs" is level 1 only when the text fixes two floors; "top" is the highest floor asked or implied.
  int floors = floors_.value_or(std::max(floors_min_, 0));
  switch (r.ref) {
    case RefType::kUpper: return floors_ == 2 ? 1 : kUpperLevels;
    case RefType::kGround: return 0;
    case RefType::kOrdinal: return british_ ? r.n : r.n - 1;
    case RefType::kNumbered: return zero_based_numbers_ ? r.n : std::max(0, r.n - 1);
    case RefType::kTop: return std::max(1, floors - 1);
    case RefType::kMiddle: return 1;
    case RefType::kEach: return kEachLevel;
    case RefType::kSame: return kAnyLevel;
  }
  return kAnyLevel;
}

bool IsBridge(const Token& t) {
  return In(t, {"on", "in", "at", "the", "is", "are", "be", "located", "situated", "placed", "will", "should",
                "must", "can", "all", "both", "each", "of", "sits", "sit", "lie", "lies", "go", "goes", "put",
                "also", "too", "both", "upon", "found", "one", "level", "floor", "which", "that", "would",
                "could", "and", "while", "a", "an"});
}

// Places each room mention on a level: a bound adjective ("second-floor bedroom"), a trailing phrase
// ("the kitchen on the first floor", "bedrooms upstairs") or the scope opened by a leading one ("On the
// ground floor, ...", "The top floor has ...", "Upstairs: ...").
void Parser::PlaceLevels() {
  int sentence_count = tokens_.empty() ? 0 : tokens_.back().sentence + 1;
  int carried_scope = -1;
  // A heading line ("Ground floor:" with its rooms on the lines below it) scopes those lines, up to a
  // blank line or the next floor.
  int heading_scope = -1;
  std::vector<bool> inside(tokens_.size(), false);  // within brackets: an aside on the room before them
  for (std::size_t k = 0, depth = 0; k < tokens_.size(); ++k) {
    if (tokens_[k].punct == ')' && depth > 0) --depth;
    inside[k] = depth > 0;
    if (tokens_[k].punct == '(') ++depth;
    if (k + 1 < tokens_.size() && tokens_[k + 1].sentence != tokens_[k].sentence && tokens_[k].punct == '\n') depth = 0;
  }
  std::size_t item_index = 0;
  for (int s = 0; s < sentence_count; ++s) {
    std::vector<int> sentence_items;
    while (item_index < items_.size() && tokens_[items_[item_index].first].sentence == s)
      sentence_items.push_back(static_cast<int>(item_index++));
    // A sentence that starts with "It" / "This floor" / "There" continues the previous scope.
    int first_word = -1;
    for (std::size_t k = 0; k < tokens_.size(); ++k)
      if (tokens_[k].sentence == s && !tokens_[k].punct) {
        first_word = static_cast<int>(k);
        break;
      }
    int scope = -1;
    // "It also has a bathroom." / "It has ..." (not "It would be great if ...").
    if (first_word >= 0 && tokens_[first_word].word == "it" && first_word + 1 < static_cast<int>(tokens_.size()) &&
        In(tokens_[first_word + 1], {"has", "also", "contains", "holds", "features", "includes", "offers", "houses", "gets"})) {
      scope = carried_scope;
    }
    bool own_floor = false, rooms = false;
    for (int it : sentence_items) {
      own_floor = own_floor || items_[it].kind == ItemKind::kFloorRef;
      rooms = rooms || items_[it].kind == ItemKind::kRoom;
    }
    if (first_word < 0) heading_scope = -1;
    else if (scope < 0 && !own_floor) scope = heading_scope;
    std::vector<int> pending;  // mention indices without a level since the last floor ref
    bool placed_before = false;  // a trailing floor phrase placed rooms earlier in the sentence
    int last_mention_end = -1;
    for (std::size_t n = 0; n < sentence_items.size(); ++n) {
      int it = sentence_items[n];
      const Item& item = items_[it];
      if (item.kind == ItemKind::kFloorRef) {
        bool bound = false;
        for (const auto& m : mentions_)
          if (m.bound_ref == it) bound = true;
        if (bound) continue;
        if (item.ref == RefType::kSame) {
          scope = carried_scope;
          continue;
        }
        bool attached = false;
        if (!pending.empty() && last_mention_end >= 0) {
          attached = true;
          for (int k = last_mention_end + 1; k < item.first; ++k)
            if (inside[k] || tokens_[k].punct == ')' || tokens_[k].punct == '(') continue;
            else if (!IsBridge(tokens_[k]) && !tokens_[k].punct) attached = false;
            else if (tokens_[k].punct && tokens_[k].punct != ',') attached = false;
          // a comma between the room and the floor: "a kitchen, upstairs two bedrooms"
          for (int k = last_mention_end + 1; k < item.first; ++k)
            if (tokens_[k].punct == ',' && !inside[k]) attached = false;
        }
        bool room_follows = false;
        for (std::size_t m2 = n + 1; m2 < sentence_items.size(); ++m2) {
          const Item& later = items_[sentence_items[m2]];
          if (later.kind == ItemKind::kFloorRef) break;
          if (later.kind == ItemKind::kRoom || later.kind == ItemKind::kPanoramic) {
            room_follows = true;
            break;
          }
        }
        if (attached || (!room_follows && !pending.empty())) {
          // A trailing floor phrase places the room right before it, and the rooms joined to that one by
          // "and" ("a kitchen and a dining room on the ground floor"), not a whole comma list ("a
          // living room, a kitchen, a bathroom on each floor": only the bathroom is on each floor).
          std::size_t from = pending.size() - 1;
          while (from > 0) {
            const Mention& earlier = mentions_[pending[from - 1]];
            const Mention& later = mentions_[pending[from]];
            bool joined = true;
            for (int k = earlier.last + 1; k < later.first; ++k)
              if (tokens_[k].punct == ',' || !(In(tokens_[k], {"and", "or", "as", "well", "plus", "with", "a", "an", "shared", "its",
                                                                 "their", "own", "private"}) ||
                                               tokens_[k].punct == '/' || tokens_[k].punct == '&'))
                joined = false;
            if (!joined) break;
            --from;
          }
          // "..., all upstairs", "..., all on the ground floor": the whole list.
          bool all = false;
          for (int k = item.first - 1; k >= 0 && k >= item.first - 3 && !all; --k) {
            if (In(tokens_[k], {"all", "both"})) all = true;
            else if (!In(tokens_[k], {"on", "the", "are", "is", "of", "them"})) break;
          }
          // "one bedroom upstairs, and a kitchen, a living room and a study downstairs": after a floor
          // phrase of its own sentence, a second one takes the whole list since.
          if (all || placed_before) from = 0;
          // The "and" that ends a comma list joins its last room to the list, not to the floor: "a living
          // room, a kitchen, a dining room and two bedrooms upstairs" puts only the bedrooms upstairs.
          if (!all && from > 0 && from + 1 < pending.size()) {
            bool comma = false;
            for (int k = mentions_[pending[from - 1]].last + 1; k < mentions_[pending[from]].first; ++k) comma = comma || tokens_[k].punct == ',';
            if (comma) from = pending.size() - 1;
          }
          for (std::size_t k = from; k < pending.size(); ++k) mentions_[pending[k]].ref = it;
          pending.clear();
          // (Only a contrast: "... upstairs, and ...".)
          int after = item.last + 1;
          if (after < static_cast<int>(tokens_.size()) && tokens_[after].punct == ',') ++after;
          placed_before = after < static_cast<int>(tokens_.size()) && tokens_[after].word == "and";
          // A trailing phrase at the very start of a list still scopes what follows a colon.
        } else {
          scope = it;
          pending.clear();
        }
        continue;
      }
      if (item.kind == ItemKind::kRoom) {
        int mi = MentionOfItem(it);
        Mention& m = mentions_[mi];
        if (m.bound_ref >= 0) m.ref = m.bound_ref;
        else if (scope >= 0) m.ref = scope;
        else if (inside[m.first] && !pending.empty()) continue;  // an aside: "one bath (not a shower!) upstairs"
        else pending.push_back(mi);
        last_mention_end = m.last;
      } else if (item.kind == ItemKind::kPanoramic || item.kind == ItemKind::kFurniture ||
                 item.kind == ItemKind::kSide) {
        // keep `last_mention_end` on the room: "balconies with panoramic windows on the top floor"
        if (!pending.empty() && !inside[item.first]) last_mention_end = item.last;
      }
    }
    if (own_floor) heading_scope = !rooms && scope >= 0 ? scope : -1;
    // Attachments without a room take the sentence's scope (resolved in Attach()).
    sentence_scope_.push_back(scope);
    carried_scope = scope;
  }
}

// "..., three on each", "..., two per floor" right after a mention's floor phrase: a count for every level
// that phrase names, instead of one total for them together.
void Parser::Distribute() {
  for (Mention& m : mentions_) {
    if (m.ref < 0 || !m.counting) continue;
    int sentence = tokens_[items_[m.ref].first].sentence;
    // "the two upper floors each have two bedrooms": each of them on its own.
    if (Item& ref = items_[m.ref]; ref.ref == RefType::kUpper && ref.last + 1 < static_cast<int>(tokens_.size()) &&
                                   tokens_[ref.last + 1].word == "each" && ref.last + 1 < m.first) {
      ref.each = true;
      tokens_[ref.last + 1].consumed = true;
    }
    auto at = [&](int k) -> const Token* {
      return k < static_cast<int>(tokens_.size()) && tokens_[k].sentence == sentence ? &tokens_[k] : nullptr;
    };
    int k = items_[m.ref].last + 1;
    while (at(k) && (at(k)->punct == ',' || In(*at(k), {"with", "and"}))) ++k;
    const Token* count = at(k);
    if (!count || count->item >= 0 || count->consumed || !Cardinal(*count)) continue;
    int n = *Cardinal(*count);
    int j = k + 1;
    if (at(j) && at(j)->item < 0 && In(*at(j), {"on", "in"})) ++j;
    const Token* each = at(j);
    if (!each) continue;
    int end = -1;
    if (each->item >= 0 && items_[each->item].kind == ItemKind::kFloorRef && items_[each->item].ref == RefType::kEach)
      end = items_[each->item].last;
    else if (each->item < 0 && In(*each, {"each", "every"}))
      end = j;
    if (end < 0) continue;
    m.per_level = n;
    Consume(k, end);
    m.last = std::max(m.last, end);
  }
}

// The levels a floor phrase names, each on its own: "the upper two floors" of three -> 1, 2; "each floor"
// -> every level when the number of floors is known (else none).
std::vector<int> Parser::RefLevels(int ref_item) const {
  const Item& r = items_[ref_item];
  int floors = floors_.value_or(std::max(floors_min_, 0));
  if (r.ref == RefType::kUpper) {
    int n = r.n > 0 ? r.n : floors - 1;
    std::vector<int> levels;
    for (int l = std::max(1, floors - n); l < floors; ++l) levels.push_back(l);
    return levels;
  }
  if (r.ref == RefType::kEach) {
    std::vector<int> levels;
    for (int l = 0; l < (floors_ ? *floors_ : 0); ++l) levels.push_back(l);
    return levels;
  }
  return {ResolveRef(ref_item)};
}

std::vector<int> Parser::MentionLevels(const Mention& m) const {
  if (m.ref >= 0) return {ResolveRef(m.ref)};
  std::vector<int> levels;
  for (int l : m.partner_levels)
    if (std::find(levels.begin(), levels.end(), l) == levels.end()) levels.push_back(l);
  if (levels.empty()) levels.push_back(kAnyLevel);
  return levels;
}

// The floors counted right before token `at` in its sentence, no room between ("Three storeys, each ..."); 0 if none.
int Parser::FloorsBefore(int at, int sentence) const {
  for (int j = at - 1, steps = 0; j >= 0 && steps < 8 && tokens_[j].sentence == sentence; --j, ++steps)
    if (tokens_[j].item >= 0) return items_[tokens_[j].item].kind == ItemKind::kFloorCount ? items_[tokens_[j].item].floors : 0;
  return 0;
}

// One room for each of others (issue 32): "four bedrooms, each with an en-suite bathroom" is four
// bathrooms, not one; so are "two bedrooms with a bathroom each", "a master and a guest bedroom, each with
// its own shower room", "every bedroom has a balcony", "a balcony for every bedroom" and "three storeys,
// each with its own bathroom". The rooms it is spread over are the bedrooms (and children's rooms) counted
// right before it in the sentence, the floors counted right before it, or, after "every bedroom", all the
// bedrooms the text counts.
void Parser::Spread() {
  auto word = [&](int j) -> const Token* { return j >= 0 && j < static_cast<int>(tokens_.size()) ? &tokens_[j] : nullptr; };
  auto sleeping = [](Category c) { return c == Category::kBedroom || c == Category::kChildrenRoom; };
  for (std::size_t mi = 0; mi < mentions_.size(); ++mi) {
    Mention& m = mentions_[mi];
    if (m.category != Category::kBathroom && m.category != Category::kBalcony) continue;
    if (m.counting && m.max == 0) continue;
    const int sentence = tokens_[m.first].sentence;
    bool preceding = false;             // over the bedrooms counted just before
    std::optional<Category> all_of;     // over every room of a kind the text counts
    // The "each" of a distribution before token j: "each", "all", "both", or "every one of them".
    auto each_before = [&](int j) {
      if (j <= 0 || tokens_[j - 1].sentence != sentence) return false;
      if (In(tokens_[j - 1], {"each", "all", "both"})) return true;
      return j >= 4 && tokens_[j - 1].word == "them" && tokens_[j - 2].word == "of" && tokens_[j - 3].word == "one" &&
             In(tokens_[j - 4], {"every", "each"});
    };
    // "each with (a|its own) ...": "each" right before the "with" of the phrase.
    if (m.with_before && m.with_token > 0 && each_before(m.with_token)) preceding = true;
    // "2 bedrooms, both en-suite".
    if (m.category == Category::kBathroom && items_[m.item].ensuite && In(tokens_[m.first], {"both", "each", "all"})) preceding = true;
    // "... with a bathroom each".
    if (const Token* after = word(m.last + 1); after && after->sentence == sentence && after->word == "each") preceding = true;
    // "each with a walk-in wardrobe and its own shower room": an "each with" earlier in the clause, across
    // what else each gets (no room between).
    if (!preceding)
      for (int j = m.first - 1, steps = 0; j > 0 && steps < 10 && tokens_[j].sentence == sentence; --j, ++steps) {
        if (tokens_[j].item >= 0 && items_[tokens_[j].item].kind == ItemKind::kRoom) break;
        if (tokens_[j].punct == ';' || tokens_[j].punct == '.' || tokens_[j].punct == ':') break;
        if (tokens_[j].word == "with" && each_before(j)) {
          preceding = true;
          break;
        }
      }
    // "every bedroom has (its own) a balcony", "every bedroom with its own bathroom": the mention before
    // the verb says "every".
    for (int j = m.first - 1, steps = 0; j >= 0 && steps < 4 && tokens_[j].sentence == sentence; --j, ++steps) {
      if (In(tokens_[j], {"has", "have", "gets", "get", "with"})) {
        // "two bedrooms that each have their own bathroom".
        if (j > 0 && In(tokens_[j - 1], {"each", "all", "both"})) {
          preceding = true;
          break;
        }
        const int before = j - 1;
        if (before >= 0 && tokens_[before].item >= 0 && items_[tokens_[before].item].kind == ItemKind::kRoom) {
          const Mention& owner = mentions_[MentionOfItem(tokens_[before].item)];
          if (owner.every && sleeping(owner.category)) all_of = owner.category;
        }
        break;
      }
      if (tokens_[j].punct || tokens_[j].item >= 0) break;
    }
    // "a balcony for every bedroom", "one bathroom per bedroom".
    // "a balcony for each of the three upstairs bedrooms": words between.
    if (const Token* t1 = word(m.last + 1); t1 && t1->sentence == sentence && In(*t1, {"for", "per"})) {
      int j = m.last + 2;
      if (const Token* t2 = word(j); t2 && In(*t2, {"each", "every"})) ++j;
      for (int steps = 0; steps < 4 && word(j) && (In(*word(j), {"of", "the", "upstairs", "downstairs"}) || Cardinal(*word(j)) ||
                                                     IsAdjective(*word(j)) || (word(j)->item >= 0 && items_[word(j)->item].kind == ItemKind::kFloorRef));
           ++steps)
        ++j;
      // (Not a ratio: "one bathroom for every two bedrooms" is counted by Quantify.)
      if (const Token* t3 = word(j); t3 && t3->item >= 0 && items_[t3->item].kind == ItemKind::kRoom &&
                                       sleeping(items_[t3->item].category) && !per_items_.count(t3->item))
        all_of = items_[t3->item].category;
    }
    // "each with its own en-suite and balcony": the next room of the phrase is spread alike.
    int chained = 0;
    if (!preceding && !all_of && mi > 0 && mentions_[mi - 1].spread && tokens_[mentions_[mi - 1].first].sentence == sentence) {
      bool list = true;
      for (int j = mentions_[mi - 1].last + 1; j < m.first && list; ++j)
        list = In(tokens_[j], {"and", "a", "an", "its", "their", "own"}) || IsAdjective(tokens_[j]);
      if (list) chained = mentions_[mi - 1].min;
    }
    int over = chained;
    if (all_of) {  // (every bedroom: the children's rooms are bedrooms too)
      for (std::size_t k = 0; k < mentions_.size(); ++k)
        if (k != mi && (mentions_[k].category == *all_of || (*all_of == Category::kBedroom && mentions_[k].category == Category::kChildrenRoom)) &&
            mentions_[k].counting && mentions_[k].max != 0)
          over += mentions_[k].min;
    } else if (const int floors = preceding ? FloorsBefore(m.first, sentence) : 0;
               floors > 1 && !(mi > 0 && sleeping(mentions_[mi - 1].category) && tokens_[mentions_[mi - 1].first].sentence == sentence)) {
      over = floors;  // "Three storeys, each with its own bathroom"
    } else if (preceding) {
      // The bedrooms of the list right before it in the sentence ("a master bedroom and a guest bedroom, each ...").
      for (int k = static_cast<int>(mi) - 1; k >= 0; --k) {
        const Mention& o = mentions_[k];
        if (tokens_[o.first].sentence != sentence) break;
        if (!sleeping(o.category)) {
          if (over > 0) break;
          continue;
        }
        if (o.counting && o.max != 0) over += o.min;
      }
    }
    if (over < 2) continue;  // one bedroom with its bathroom needs no spreading
    m.min = m.max = over * std::max(1, m.min);  // "two bathrooms each" spreads two
    m.spread = true;
    m.counting = true;
    m.definite = false;
  }
}

// Connections: a cue ("open to", "directly access", "reached through") between the rooms before it and
// the rooms after it in one clause; "with" + balcony / own bathroom; en-suite and open-plan words.
void Parser::Connect() {
  std::vector<bool> used_right(mentions_.size(), false);
  auto add = [&](int a, int b, LinkKind kind, bool every, TextSpan source, bool by_cue = true) {
    if (a < 0 || b < 0 || a == b) return;
    if (mentions_[a].category == mentions_[b].category) return;
    // A balcony or a bathroom "opening onto" a room does so through a door (FORMAT.md rules 9, 10).
    for (int m : {a, b})
      if (kind == LinkKind::kOpen &&
          (mentions_[m].category == Category::kBalcony || mentions_[m].category == Category::kBathroom))
        kind = LinkKind::kAny;
    connections_.push_back({a, b, kind, every, std::move(source)});
    mentions_[a].in_connection = mentions_[b].in_connection = true;
    // "a bedroom with a balcony" states both rooms; "connect to balconies" refers to rooms counted elsewhere.
    if (by_cue) mentions_[a].by_cue = mentions_[b].by_cue = true;
    mentions_[a].partners.push_back(b);
    mentions_[b].partners.push_back(a);
  };
  for (int ci = 0; ci < static_cast<int>(items_.size()); ++ci) {
    const Item& cue = items_[ci];
    if (cue.kind != ItemKind::kCue) continue;
    int sentence = tokens_[cue.first].sentence;
    // A room followed by a cue of its own is the subject of the next clause ("the kitchen opens onto the
    // dining room and the dining room opens onto the living room"), not another target of this one.
    auto starts_clause = [&](int mi) {
      for (int k = items_[mentions_[mi].item].last + 1; k < static_cast<int>(tokens_.size()) && tokens_[k].sentence == sentence; ++k) {
        const Token& t = tokens_[k];
        if (t.item >= 0) return items_[t.item].kind == ItemKind::kCue;
        if (t.punct || !(IsFiller(t) || IsAdjective(t))) return false;
      }
      return false;
    };
    auto walk = [&](int start, int step, bool left, bool* entrance) {
      std::vector<int> found;
      bool relative = false;  // "the kitchen, which is open to ...": "which" points at the room before it
      for (int k = start; k >= 0 && k < static_cast<int>(tokens_.size()) && tokens_[k].sentence == sentence; k += step) {
        const Token& t = tokens_[k];
        if (left && found.empty() && In(t, {"which", "that", "who"})) relative = true;
        if (t.item >= 0) {
          const Item& it = items_[t.item];
          if (it.kind == ItemKind::kRoom) {
            int mi = MentionOfItem(t.item);
            if (left && used_right[mi]) {
              if (relative && found.empty()) found.push_back(mi);
              break;
            }
            // "open to the living room and an office": a new, indefinite room after a definite one is the
            // next item of a list, not a second target.
            if (!left && !found.empty() && mentions_[mi].definite != mentions_[found.front()].definite) break;
            if (!left && !found.empty() && starts_clause(mi)) break;
            if (std::find(found.begin(), found.end(), mi) == found.end()) found.push_back(mi);
            k = step < 0 ? it.first : it.last;
            continue;
          }
          if (it.kind == ItemKind::kFloorRef || it.kind == ItemKind::kFloorCount || it.kind == ItemKind::kShape) {
            k = step < 0 ? it.first : it.last;
            continue;
          }
          if (it.kind == ItemKind::kEntrance && left && found.empty()) {
            if (entrance) *entrance = true;
            break;
          }
          break;
        }
        if (t.punct) {
          if ((t.punct == ',' || t.punct == '/' || t.punct == '(' || t.punct == ')') && found.empty()) continue;
          if (t.punct == '/' || t.punct == '&') continue;
          break;
        }
        if (!left && t.word == "with" && !found.empty()) break;
        if (IsFiller(t) || IsAdjective(t) || t.consumed) continue;
        if (!found.empty()) break;
      }
      return found;
    };
    bool entrance = false;
    std::vector<int> left = walk(cue.first - 1, -1, true, &entrance);
    std::vector<int> right = walk(cue.last + 1, +1, false, nullptr);
    std::reverse(left.begin(), left.end());
    TextSpan source = Span(left.empty() ? cue.first : std::min(cue.first, mentions_[left.front()].first),
                           right.empty() ? cue.last : std::max(cue.last, mentions_[right.back()].last));
    if (entrance && left.empty() && !right.empty()) {
      attachments_.push_back({ItemKind::kEntrance, ci, right.front(), -1, source});
      mentions_[right.front()].in_attachment = true;
      used_right[right.front()] = true;
      continue;
    }
    // "two balconies, each reached from a bedroom": every room on the left has its own link, and "a
    // bedroom" is one of the bedrooms counted before (not another one) when the text has counted some.
    bool distributive = false;
    if (!left.empty())
      for (int k = mentions_[left.back()].last + 1; k < cue.first; ++k)
        if (In(tokens_[k], {"each", "every"})) distributive = true;
    if (distributive)
      for (int b : right) {
        Mention& mb = mentions_[b];
        bool counted_before = std::any_of(mentions_.begin(), mentions_.begin() + b, [&](const Mention& o) {
          return o.category == mb.category && o.counting && o.max != 0;
        });
        if (mb.counting && mb.min == 1 && mb.max == 1 && counted_before) mb.counting = false;
      }
    if (!left.empty() && !right.empty() && !(cue.mutual && right.empty())) {
      for (int a : left)
        for (int b : right) add(a, b, cue.link, mentions_[a].every || distributive, source);
      for (int b : right) used_right[b] = true;
    } else if (left.size() >= 2 && (cue.mutual || right.empty())) {
      for (std::size_t k = 1; k < left.size(); ++k) add(left[0], left[k], cue.link, false, source);
    } else if (left.empty() && right.size() >= 2) {
      for (std::size_t k = 1; k < right.size(); ++k) add(right[0], right[k], cue.link, false, source);
      for (int b : right) used_right[b] = true;
    }
  }
  // "a bedroom with a balcony", "a master bedroom with its own bathroom".
  for (int mi = 0; mi < static_cast<int>(mentions_.size()); ++mi) {
    Mention& m = mentions_[mi];
    if (!m.with_before) continue;
    bool own = false;
    for (int k = m.with_token + 1; k < m.first + 1 && k < static_cast<int>(tokens_.size()); ++k)
      if (In(tokens_[k], {"own", "private", "attached"})) own = true;
    bool qualifies = m.category == Category::kBalcony ||
                     (m.category == Category::kBathroom && (own || items_[m.item].ensuite));
    if (!qualifies || m.in_connection) continue;
    // The room right before "with".
    int partner = -1;
    for (int k = m.with_token - 1; k >= 0 && tokens_[k].sentence == tokens_[m.with_token].sentence; --k) {
      const Token& t = tokens_[k];
      if (t.item >= 0 && items_[t.item].kind == ItemKind::kRoom) {
        partner = MentionOfItem(t.item);
        break;
      }
      if (t.item >= 0 && items_[t.item].kind == ItemKind::kFloorRef) continue;
      if (t.punct || !(IsFiller(t) || IsAdjective(t) || t.consumed)) break;
    }
    if (partner < 0) continue;
    TextSpan source = Span(mentions_[partner].first, m.last);
    add(partner, mi, LinkKind::kDoor, mentions_[partner].every, source, false);
  }
}

void Parser::Attach() {
  for (int ii = 0; ii < static_cast<int>(items_.size()); ++ii) {
    const Item& item = items_[ii];
    if (item.kind != ItemKind::kPanoramic && item.kind != ItemKind::kFurniture && item.kind != ItemKind::kSide &&
        item.kind != ItemKind::kEntrance)
      continue;
    if (item.kind == ItemKind::kEntrance) {
      bool done = false;
      for (const auto& a : attachments_)
        if (a.kind == ItemKind::kEntrance && a.item >= 0 && items_[a.item].kind == ItemKind::kCue &&
            tokens_[items_[a.item].first].sentence == tokens_[item.first].sentence)
          done = true;
      if (done) continue;
    }
    int sentence = tokens_[item.first].sentence;
    // Forward: "... in the children's room", "... on the top floor".
    auto forward = [&](int* ref) {
      bool preposition = false;
      for (int k = item.last + 1; k < static_cast<int>(tokens_.size()) && tokens_[k].sentence == sentence; ++k) {
        const Token& t = tokens_[k];
        if (t.item >= 0) {
          const Item& it = items_[t.item];
          if (it.kind == ItemKind::kRoom && preposition) return MentionOfItem(t.item);
          if (it.kind == ItemKind::kFloorRef && preposition) {
            *ref = t.item;
            return -1;
          }
          if (it.kind == item.kind && item.kind == ItemKind::kFurniture) {
            k = it.last;
            continue;
          }
          if (it.kind == ItemKind::kCue && item.kind == ItemKind::kEntrance) {
            preposition = true;
            k = it.last;
            continue;
          }
          return -1;
        }
        if (In(t, {"in", "into", "inside", "for", "within", "on", "to", "through", "of", "at", "from", "onto"})) {
          preposition = true;
          continue;
        }
        if (t.punct == ',' || In(t, {"the", "a", "an", "each", "every", "our", "my", "is", "are", "be", "should",
                                     "will", "placed", "located", "put", "and", "its", "their", "both", "all",
                                     "open", "opens", "lead", "leads", "side", "part", "end", "wing", "half",
                                     "house", "villa", "building", "home", "plan", "facing", "faces", "face"}) ||
            t.consumed)
          continue;
        return -1;
      }
      return -1;
    };
    auto backward = [&]() {
      for (int k = item.first - 1; k >= 0 && tokens_[k].sentence == sentence; --k) {
        const Token& t = tokens_[k];
        if (t.item >= 0) {
          const Item& it = items_[t.item];
          if (it.kind == ItemKind::kRoom) return MentionOfItem(t.item);
          if (it.kind == ItemKind::kFloorRef) {
            k = it.first;
            continue;
          }
          if (it.kind == item.kind) {
            k = it.first;
            continue;
          }
          return -1;
        }
        if (t.punct && t.punct != ',') return -1;
        if (t.punct || IsFiller(t) || IsAdjective(t) || t.consumed) continue;
        return -1;
      }
      return -1;
    };
    int ref = -1;
    int mention = -1;
    if (item.kind == ItemKind::kFurniture || item.kind == ItemKind::kEntrance) {
      mention = forward(&ref);
      if (mention < 0 && ref < 0) mention = backward();
    } else {
      mention = backward();
      if (mention < 0) mention = forward(&ref);
    }
    if (mention >= 0) mentions_[mention].in_attachment = true;
    if (mention < 0 && ref < 0 && sentence < static_cast<int>(sentence_scope_.size())) ref = sentence_scope_[sentence];
    TextSpan source = Span(item.first, item.last);
    if (mention >= 0) {
      const Mention& m = mentions_[mention];
      source = Span(std::min(item.first, m.first), std::max(item.last, m.last));
    }
    attachments_.push_back({item.kind, ii, mention, ref, source});
  }
}

// Utility rooms that are no staircase room (Finish).
constexpr std::string_view kServiceRooms[] = {"laundry", "pantry", "mudroom", "mud room", "boot room", "scullery", "storage", "store"};

void Parser::Finish(Brief& brief) {
  // Floors.
  for (const Item& item : items_) {
    if (item.kind != ItemKind::kFloorCount) continue;
    if (item.floors_at_least) {
      floors_min_ = std::max(floors_min_, item.floors);
      continue;
    }
    // "on three floors - wait, two floors is plenty": a second thought between two counts, the later holds.
    auto second_thought = [&](int from, int to) {
      for (int k = from; k < to; ++k)
        if (In(tokens_[k], {"wait", "actually", "sorry", "correction", "rather", "instead"}) ||
            (In(tokens_[k], {"make", "change"}) && k + 1 < to && In(tokens_[k + 1], {"that", "it"})) ||
            // "Let's do three floors. Hmm, no, two floors is plenty."
            (tokens_[k].word == "no" && k + 1 < to && tokens_[k + 1].punct == ',' && k > 0 && tokens_[k - 1].punct))
          return true;
      return false;
    };
    if (!floors_ || (*floors_ != item.floors && second_thought(floors_source_last_, item.first))) {
      floors_ = item.floors;
      floors_source_ = Span(item.first, item.last);
      floors_source_last_ = item.last;
    } else if (*floors_ != item.floors) {
      conflicts_.push_back("the text gives both " + std::to_string(*floors_) + " and " + std::to_string(item.floors) +
                           " floors; using " + std::to_string(*floors_));
    }
  }
  // Floors implied by the floors named (before "top floor" can be resolved).
  for (const Item& item : items_) {
    if (item.kind != ItemKind::kFloorRef) continue;
    int need = 0;
    switch (item.ref) {
      case RefType::kOrdinal: need = british_ ? item.n + 1 : item.n; break;
      case RefType::kNumbered: need = zero_based_numbers_ ? item.n + 1 : item.n; break;
      case RefType::kTop: need = 2; break;
      case RefType::kUpper: need = std::max(2, item.n + 1); break;
      case RefType::kMiddle: need = 3; break;
      default: break;
    }
    floors_min_ = std::max(floors_min_, need);
  }
  // "Bedrooms upstairs, the kitchen downstairs" with no count of floors and no other floor named: a house
  // of two floors (as people mean it), not two or more.
  if (!floors_ && floors_min_ <= 2) {
    int upstairs = -1;
    bool other = false;
    for (const Item& item : items_) {
      if (item.kind == ItemKind::kFloorCount) other = true;
      if (item.kind != ItemKind::kFloorRef) continue;
      if (item.ref == RefType::kUpper && item.n == 0 && !item.each && In(tokens_[item.first], {"upstairs", "upstair"})) upstairs = item.first;
      else if (item.ref != RefType::kGround && item.ref != RefType::kSame) other = true;
    }
    if (upstairs >= 0 && !other) {
      floors_ = 2;
      floors_source_ = Span(upstairs, upstairs);
    }
  }
  if (floors_ && floors_min_ > *floors_)
    conflicts_.push_back("the text names level " + std::to_string(floors_min_ - 1) + " but asks for " +
                         std::to_string(*floors_) + (*floors_ == 1 ? " floor" : " floors"));
  brief.floors = floors_;
  brief.floors_source = floors_source_;
  if (!floors_ && floors_min_ > 1) brief.floors_min = floors_min_;
  if (floors_ && *floors_ > kMaxFloors)
    conflicts_.push_back(std::to_string(*floors_) + " floors asked: a villa has at most " + std::to_string(kMaxFloors) +
                         " (FORMAT.md rule 6)");
  if (floors_ && *floors_ < 1) conflicts_.push_back("0 floors asked");

  // Shape.
  for (const Item& item : items_) {
    if (item.kind != ItemKind::kShape) continue;
    if (item.shape) {
      if (!brief.shape) {
        brief.shape = item.shape;
        brief.shape_source = Span(item.first, item.last);
      } else if (*brief.shape != *item.shape) {
        conflicts_.push_back("two footprint shapes asked: " + std::string(ShapeClassName(*brief.shape)) + " and " +
                             std::string(ShapeClassName(*item.shape)));
      }
    } else if (!brief.unsupported_shape) {
      brief.unsupported_shape = Span(item.first, item.last);
    }
  }

  // Levels taken from connection partners ("connect to balconies" -> balconies on those floors).
  for (const auto& c : connections_) {
    int la = OwnLevel(mentions_[c.a]);
    int lb = OwnLevel(mentions_[c.b]);
    if (la != kAnyLevel && lb == kAnyLevel) mentions_[c.b].partner_levels.push_back(la);
    if (lb != kAnyLevel && la == kAnyLevel) mentions_[c.a].partner_levels.push_back(lb);
  }

  // "A four-bed house: four bedrooms, ..." names the bedrooms twice: the "N-bed" of the house is a
  // reference when the text counts its bedrooms as rooms too.
  for (Mention& m : mentions_) {
    const Token& bed = tokens_[m.last];
    if (m.category != Category::kBedroom || !In(bed, {"bed", "beds"}) || !bed.joined) continue;
    const bool counted_elsewhere = std::any_of(mentions_.begin(), mentions_.end(), [&](const Mention& o) {
      return &o != &m && o.category == Category::kBedroom && o.counting && o.max != 0 && !In(tokens_[o.last], {"bed", "beds"});
    });
    if (counted_elsewhere) m.counting = false;
  }
  // "a primary suite (bedroom + bath)": a bedroom in brackets right after a suite is the suite itself.
  for (std::size_t mi = 1; mi < mentions_.size(); ++mi) {
    Mention& m = mentions_[mi];
    const Mention& suite = mentions_[mi - 1];
    if (m.category != Category::kBedroom || suite.category != Category::kBedroom || !In(tokens_[suite.last], {"suite"})) continue;
    bool bracketed = false;
    for (int k = suite.last + 1; k < m.first; ++k) bracketed = bracketed || tokens_[k].punct == '(';
    if (bracketed && m.first - suite.last <= 2) m.counting = false;
  }
  // Rooms: counted mentions add up per (category, level); references only say "at least one there".
  struct Acc {
    int min = 0;
    int max = 0;
    TextSpan source;
    bool counting = false;
  };
  std::map<std::pair<int, int>, Acc> counts;
  std::vector<std::pair<std::pair<int, int>, TextSpan>> references;
  for (std::size_t mi = 0; mi < mentions_.size(); ++mi) {
    const Mention& m = mentions_[mi];
    bool counting = m.counting && !(bare_[mi] && (m.by_cue || m.in_attachment));
    // "... two bedrooms. One bedroom should open onto the balcony": a room in a connection whose
    // category was already counted in an earlier sentence is one of those, not another.
    if (counting && (m.by_cue || m.in_attachment) && m.min == 1 && m.max == 1) {
      for (std::size_t k = 0; k < mi; ++k)
        if (mentions_[k].category == m.category && mentions_[k].counting &&
            tokens_[mentions_[k].first].sentence != tokens_[m.first].sentence)
          counting = false;
    }
    std::vector<int> levels = MentionLevels(m);
    TextSpan source = Span(m.first, m.last);
    int cat = static_cast<int>(m.category);
    auto add_count = [&](int level, int min, int max) {
      Acc& acc = counts[{cat, level}];
      if (!acc.counting) {
        acc.source = source;
        acc.counting = true;
      } else {
        acc.source.text += "; " + source.text;
      }
      acc.min += min;
      acc.max = (acc.max < 0 || max < 0) ? -1 : acc.max + max;
    };
    const bool each_ref = m.ref >= 0 && items_[m.ref].each && m.per_level < 0;  // "both upper floors get a balcony"
    std::vector<int> each_levels = counting && (m.per_level >= 0 || each_ref) ? RefLevels(m.ref) : std::vector<int>{};
    if (each_ref && !each_levels.empty()) {
      for (int l : each_levels) add_count(l, m.min, m.max);
    } else if (!each_levels.empty()) {
      const int spread = m.per_level * static_cast<int>(each_levels.size());
      if (spread != m.min || (m.max >= 0 && spread != m.max))
        conflicts_.push_back(std::to_string(m.min) + " " + std::string(CategoryName(m.category)) + " asked as " +
                             std::to_string(m.per_level) + " on each of " + std::to_string(each_levels.size()) +
                             " floors; using " + std::to_string(m.per_level) + " on each");
      for (int l : each_levels) add_count(l, m.per_level, m.per_level);
    } else if (counting) {
      if (levels.size() == 1) {
        add_count(levels[0], m.min, m.max);
      } else {
        add_count(kAnyLevel, m.min, m.max);
        for (int l : levels) references.push_back({{cat, l}, source});
      }
    } else if (!m.in_connection) {
      for (int l : levels) references.push_back({{cat, l}, source});
    }
  }
  for (const auto& [key, source] : references) {
    if (counts.count(key)) continue;
    if (key.second == kAnyLevel) {
      bool covered = false;
      for (const auto& [k2, acc] : counts)
        if (k2.first == key.first && acc.max != 0) covered = true;
      for (const auto& [k2, s2] : references)
        if (k2.first == key.first && k2.second != kAnyLevel) covered = true;
      if (covered) continue;
    }
    Acc& acc = counts[key];
    acc.min = 1;
    acc.max = -1;
    acc.source = source;
  }
  // Rooms of a kind counted with no floor and others counted on a floor are different rooms ("a WC under the
  // stairs and a family bathroom upstairs", "two en-suites ... Ground floor: a WC"): the total is their sum.
  for (auto& [key, acc] : counts) {
    if (key.second != kAnyLevel || !acc.counting || acc.min <= 0) continue;
    for (const auto& [other, placed] : counts) {
      if (other.first != key.first || other.second == kAnyLevel || !placed.counting || placed.min <= 0) continue;
      const int levels = other.second == kEachLevel ? std::max(1, floors_.value_or(floors_min_)) : 1;
      acc.min += placed.min * levels;
      if (acc.max >= 0) acc.max = placed.max < 0 ? -1 : acc.max + placed.max * levels;
    }
  }
  for (const auto& [key, acc] : counts) {
    BriefRooms r;
    r.category = static_cast<Category>(key.first);
    r.level = key.second;
    r.min = acc.min;
    r.max = acc.max;
    r.source = acc.source;
    brief.rooms.push_back(r);
  }
  // Keep text order for the report.
  std::stable_sort(brief.rooms.begin(), brief.rooms.end(),
                   [](const BriefRooms& a, const BriefRooms& b) { return a.source.begin < b.source.begin; });

  // Connections.
  auto connection_level = [&](const Mention& a, const Mention& b) {
    auto la = MentionLevels(a);
    if (la.size() == 1 && la[0] != kAnyLevel) return la[0];
    auto lb = MentionLevels(b);
    if (lb.size() == 1 && lb[0] != kAnyLevel) return lb[0];
    return kAnyLevel;
  };
  for (const auto& c : connections_) {
    const Mention& a = mentions_[c.a];
    const Mention& b = mentions_[c.b];
    // A balcony reached from several rooms on different floors: one requirement per floor.
    auto la = MentionLevels(a);
    std::vector<int> levels = la.size() == 1 ? std::vector<int>{connection_level(a, b)} : la;
    for (int level : levels) {
      BriefConnection bc;
      bc.from = a.category;
      bc.to = {b.category};
      bc.level = level;
      bc.kind = c.kind;
      bc.every = c.every;
      bc.source = c.source;
      brief.connections.push_back(bc);
    }
  }
  // En-suite bathrooms and bedrooms with no partner named; open-plan rooms.
  for (std::size_t mi = 0; mi < mentions_.size(); ++mi) {
    const Mention& m = mentions_[mi];
    const Item& item = items_[m.item];
    auto levels = MentionLevels(m);
    bool has_bedroom_link = false, has_open_link = false;
    for (int p : m.partners) {
      Category pc = mentions_[p].category;
      if (pc == Category::kBedroom || pc == Category::kChildrenRoom || pc == Category::kBathroom) has_bedroom_link = true;
    }
    for (const auto& c : connections_)
      if ((c.a == static_cast<int>(mi) || c.b == static_cast<int>(mi)) && c.kind == LinkKind::kOpen) has_open_link = true;
    // ("The en-suite only needs a shower" after "master bedroom with en-suite": that one, linked already.)
    const bool named_before = m.definite && !m.counting && std::any_of(mentions_.begin(), mentions_.begin() + static_cast<long>(mi), [&](const Mention& o) {
      return o.counting && o.max != 0 && items_[o.item].ensuite;
    });
    if (item.ensuite && !has_bedroom_link && m.max != 0 && !named_before) {
      BriefConnection bc;
      bc.level = levels.size() == 1 ? levels[0] : kAnyLevel;
      bc.every = m.every;
      if (m.category == Category::kBathroom) {
        // the nearest bedroom named before it in the text, else any bedroom
        Category from = Category::kBedroom;
        for (int k = static_cast<int>(mi) - 1; k >= 0; --k)
          if (mentions_[k].category == Category::kBedroom || mentions_[k].category == Category::kChildrenRoom) {
            from = mentions_[k].category;
            bc.every = mentions_[k].every;
            auto partner_levels = MentionLevels(mentions_[k]);
            if (bc.level == kAnyLevel && partner_levels.size() == 1) bc.level = partner_levels[0];
            break;
          }
        bc.from = from;
        bc.to = {Category::kBathroom};
      } else {
        bc.from = m.category;
        bc.to = {Category::kBathroom};
      }
      bc.kind = LinkKind::kDoor;
      bc.source = Span(m.first, m.last);
      brief.connections.push_back(bc);
    }
    if (item.open_plan && !has_open_link && m.max != 0 &&
        (m.category == Category::kKitchen || m.category == Category::kDiningRoom || m.category == Category::kLivingRoom)) {
      std::vector<Category> others;
      int sentence = tokens_[item.first].sentence;
      for (const auto& o : mentions_) {
        if (tokens_[o.first].sentence != sentence || o.category == m.category) continue;
        if (o.category == Category::kKitchen || o.category == Category::kDiningRoom || o.category == Category::kLivingRoom)
          if (std::find(others.begin(), others.end(), o.category) == others.end()) others.push_back(o.category);
      }
      if (others.empty()) {
        for (Category c : {Category::kKitchen, Category::kDiningRoom, Category::kLivingRoom})
          if (c != m.category) others.push_back(c);
      }
      BriefConnection bc;
      bc.from = m.category;
      bc.to = others;
      bc.level = levels.size() == 1 ? levels[0] : kAnyLevel;
      bc.kind = LinkKind::kOpen;
      bc.source = Span(m.first, m.last);
      brief.connections.push_back(bc);
    }
  }

  // Attachments.
  for (const auto& a : attachments_) {
    int level = kAnyLevel;
    std::vector<int> levels = {kAnyLevel};
    Category category = Category::kRoom;
    if (a.mention >= 0) {
      levels = MentionLevels(mentions_[a.mention]);
      category = mentions_[a.mention].category;
    } else if (a.ref >= 0) {
      levels = {ResolveRef(a.ref)};
    }
    level = levels.size() == 1 ? levels[0] : kAnyLevel;
    switch (a.kind) {
      case ItemKind::kPanoramic:
        for (int l : levels) brief.panoramic.push_back({category, l, a.source});
        break;
      case ItemKind::kEntrance:
        if (a.mention >= 0) brief.entrance.push_back({category, a.source});
        break;
      case ItemKind::kSide:
        if (a.mention >= 0) brief.sides.push_back({category, level, items_[a.item].side, a.source});
        break;
      case ItemKind::kFurniture: {
        const Item& item = items_[a.item];
        BriefFurniture f;
        int noun_first = item.item_first;
        f.item = std::string(text_.substr(tokens_[noun_first].begin, tokens_[item.last].end - tokens_[noun_first].begin));
        f.count = 1;
        if (item.item_first > 0 && tokens_[item.item_first - 1].sentence == tokens_[item.first].sentence) {
          if (auto n = Cardinal(tokens_[item.item_first - 1]); n && *n > 0) {
            f.count = *n;
            tokens_[item.item_first - 1].consumed = true;
          }
        }
        f.category = category;
        f.level = level;
        f.source = a.source;
        brief.furniture.push_back(f);
        break;
      }
      default: break;
    }
  }

  // A laundry, pantry or mudroom is a utility room, but in a building of more floors the format's utility
  // room holds the stairs: no separate one can be made, so the words stay unmet rather than met by the
  // staircase room.
  if (floors_.value_or(0) > 1 || floors_min_ > 1)
    for (size_t r = 0; r < brief.rooms.size();) {
      std::string words = brief.rooms[r].source.text;
      std::transform(words.begin(), words.end(), words.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
      const bool service = brief.rooms[r].category == Category::kUtilityRoom &&
                           std::any_of(std::begin(kServiceRooms), std::end(kServiceRooms),
                                       [&](std::string_view w) { return words.find(w) != std::string::npos; });
      if (!service) {
        ++r;
        continue;
      }
      conflicts_.push_back("\"" + brief.rooms[r].source.text + "\": in a building of more floors the utility room holds the stairs; "
                           "no separate laundry, pantry or store room can be made");
      brief.unparsed.push_back(brief.rooms[r].source);
      brief.rooms.erase(brief.rooms.begin() + static_cast<std::ptrdiff_t>(r));
    }

  // Conflicts between counts and with the format's limits.
  int floors_known = floors_.value_or(0);
  std::map<int, int> min_total;  // category -> sum of per-level minimums
  std::map<int, int> per_level_min;
  for (const auto& r : brief.rooms) {
    if (floors_known > 0 && r.level >= floors_known)
      conflicts_.push_back(std::string(CategoryName(r.category)) + " on level " + std::to_string(r.level) +
                           " but the building has " + std::to_string(floors_known) +
                           (floors_known == 1 ? " floor" : " floors"));
    if (r.level >= 0) {
      min_total[static_cast<int>(r.category)] += r.min;
      per_level_min[r.level] += r.min;
    } else if (r.level == kEachLevel && floors_known > 0) {
      min_total[static_cast<int>(r.category)] += r.min * floors_known;
      for (int l = 0; l < floors_known; ++l) per_level_min[l] += r.min;
    }
  }
  for (const auto& r : brief.rooms) {
    if (r.level != kAnyLevel || r.max < 0) continue;
    int placed = min_total[static_cast<int>(r.category)];
    if (placed > r.max)
      conflicts_.push_back(std::to_string(r.max) + " " + std::string(CategoryName(r.category)) + " in all, but " +
                           std::to_string(placed) + " placed on given floors");
    if (r.category == Category::kUtilityRoom && floors_known > 1 && (r.max < floors_known || r.min > floors_known))
      conflicts_.push_back("a " + std::to_string(floors_known) + "-floor villa has one utility (staircase) room a floor, " +
                           "not " + std::to_string(r.min));
  }
  // A multi-story building's staircase room takes one of the six places on every floor.
  const bool multi = floors_known > 1 || floors_min_ > 1;
  std::map<int, int> utility_on_level;
  for (const auto& r : brief.rooms)
    if (r.category == Category::kUtilityRoom && r.level >= 0) utility_on_level[r.level] += r.min;
  for (const auto& [level, n] : per_level_min) {
    int total = n + ((multi && utility_on_level[level] == 0) ? 1 : 0);
    if (total > kMaxRoomsPerFloor)
      conflicts_.push_back(std::to_string(n) + " rooms asked on level " + std::to_string(level) +
                           (total > n ? " besides its staircase room" : "") + ": at most " +
                           std::to_string(kMaxRoomsPerFloor) + " rooms a floor (FORMAT.md rule 6)");
  }
  {
    int total_min = 0;
    for (const auto& r : brief.rooms)
      if (r.level == kAnyLevel) total_min += r.min;
    int floors_for_cap = floors_known > 0 ? floors_known : kMaxFloors;
    if (total_min > kMaxRoomsPerFloor * floors_for_cap)
      conflicts_.push_back(std::to_string(total_min) + " rooms asked: at most " +
                           std::to_string(kMaxRoomsPerFloor * floors_for_cap) + " fit in " +
                           std::to_string(floors_for_cap) + " floors (FORMAT.md rule 6)");
  }
  // Issue 33: a number keeps its sign; a negative one counts nothing, and the report says so.
  for (const Token& t : tokens_)
    if (t.number && t.negative)
      conflicts_.push_back("\"-" + t.word + "\": a number below zero is no count of rooms or floors; not read as " + t.word);
  brief.conflicts = conflicts_;
  brief.british_ordinals = british_;

  // What was not understood.
  for (std::size_t k = 0; k < tokens_.size();) {
    const Token& t = tokens_[k];
    if (t.consumed || t.punct || IsFiller(t) || (t.number && false)) {
      ++k;
      continue;
    }
    std::size_t j = k;
    while (j + 1 < tokens_.size() && !tokens_[j + 1].consumed && !tokens_[j + 1].punct && !IsFiller(tokens_[j + 1]) &&
           tokens_[j + 1].sentence == t.sentence)
      ++j;
    brief.unparsed.push_back(Span(static_cast<int>(k), static_cast<int>(j)));
    k = j + 1;
  }
}

// "a small box room I can use as a study", "a spare room to use as an office", "a bedroom we'd use as a
// playroom": one room, of the kind it is to be used as.
void Parser::UsedAs() {
  for (std::size_t k = 0; k + 1 < mentions_.size(); ++k) {
    Mention& room = mentions_[k];
    Mention& as = mentions_[k + 1];
    if (!room.counting || room.max != 1 || room.min != 1 || !as.counting || as.min != 1 || as.max != 1 ||
        tokens_[room.last].sentence != tokens_[as.first].sentence)
      continue;
    bool use = false, as_word = false, filler = true;
    for (int j = room.last + 1; j < as.first && filler; ++j) {
      const Token& t = tokens_[j];
      if (In(t, {"use", "used", "using"})) use = true;
      else if (t.word == "as") as_word = use;
      else if (!In(t, {"that", "which", "i", "we", "you", "can", "could", "will", "would", "ll", "d", "to", "be", "also",
                       "maybe", "might", "then", "as", "a", "an", "(", "wed", "well", "id", "ill", "youd", "theyd", "shall"}))
        filler = false;
    }
    if (!filler || !use || !as_word) continue;
    // "a second living room we'd use as a den", "studio (used as office)": one room either way.
    room.category = as.category;
    items_[room.item].category = as.category;
    as.counting = false;
    as.definite = true;
    Consume(room.last + 1, as.first - 1);
  }
}

// Second thoughts: "Two bedrooms. Actually, make that three bedrooms", "four bedrooms... actually make it
// three", "make that two children's rooms and two bedrooms": the later count replaces the earlier one (which
// keeps nothing but its floor, when the new one names none).
void Parser::Corrections() {
  const int size = static_cast<int>(tokens_.size());
  // "Three floors - actually two is plenty": a bare count after a second thought, right after a floor
  // count and followed by no room, is the floors'.
  for (int i = 0; i + 2 < size; ++i) {
    if (!In(tokens_[i], {"actually", "wait", "sorry", "no"})) continue;
    int n = i + 1;
    while (n < size && (tokens_[n].punct == ',' || In(tokens_[n], {"wait", "actually"}))) ++n;
    if (n + 1 >= size || tokens_[n].item >= 0 || !Cardinal(tokens_[n]) || !In(tokens_[n + 1], {"is", "will", "would", "should", "are"})) continue;
    Item* floors = nullptr;
    for (Item& it : items_)
      if (it.kind == ItemKind::kFloorCount && it.last < i && tokens_[it.last].sentence + 1 >= tokens_[i].sentence) floors = &it;
    if (!floors) continue;
    floors->floors = *Cardinal(tokens_[n]);
    Consume(i, n + 1);
  }
  // Where "make that", "make it", "change that to" ends, for each such phrase.
  std::vector<int> cues;
  for (int i = 0; i + 1 < size; ++i) {
    if (In(tokens_[i], {"make", "change"}) && In(tokens_[i + 1], {"that", "it", "them", "this"})) {
      int end = i + 1;
      if (end + 1 < size && tokens_[end + 1].word == "to") ++end;
      cues.push_back(end);
    }
    // "a kitchen-diner - well, a kitchen and a separate dining room actually", "two bathrooms, or rather
    // three bathrooms": a restatement after a dash or comma and "well," / "or rather" / "I mean".
    const bool dash_before = i > 0 && (tokens_[i - 1].punct == '-' || tokens_[i - 1].punct == ',');
    if (dash_before && tokens_[i].word == "well" && tokens_[i + 1].punct == ',') cues.push_back(i + 1);
    if (tokens_[i].word == "or" && tokens_[i + 1].word == "rather") cues.push_back(i + 1);
    if (dash_before && tokens_[i].word == "i" && tokens_[i + 1].word == "mean") cues.push_back(i + 1);
    // "two bedrooms, each with a balcony - hmm, actually just one shared balcony"
    if (tokens_[i].word == "actually" && i > 0 && (tokens_[i - 1].punct == '-' || tokens_[i - 1].punct == ',' || In(tokens_[i - 1], {"hmm", "no"})))
      cues.push_back(i);
    // "two kids' rooms - no, three", "six chairs... sorry, eight", "three floors, no wait, two": a bare
    // count right after "no" / "sorry" / "wait" that follows a break.
    const bool broken = i > 0 && (tokens_[i - 1].punct == '-' || tokens_[i - 1].punct == ',' || tokens_[i - 1].punct == '.' ||
                                  tokens_[i - 1].punct == ';' || tokens_[i - 1].sentence != tokens_[i].sentence);
    if (broken && In(tokens_[i], {"no", "sorry", "wait", "oops"})) {
      int c = i;
      while (c + 1 < size && (tokens_[c + 1].punct == ',' || In(tokens_[c + 1], {"wait", "sorry", "actually"}))) ++c;
      if (c + 2 < size && tokens_[c + 1].word == "for" && Cardinal(tokens_[c + 2])) ++c;  // "for six - no wait, for eight"
      if (c + 1 < size && tokens_[c + 1].item < 0 && Cardinal(tokens_[c + 1])) cues.push_back(c);
    }
  }
  for (int cue : cues) {
    // "make it three": a bare count for the rooms named last before the cue.
    if (const int n = cue + 1; n < size && tokens_[n].item < 0 && Cardinal(tokens_[n]) &&
                               (n + 1 == size || tokens_[n + 1].punct || tokens_[n + 1].item < 0)) {
      Mention* last = nullptr;
      for (Mention& p : mentions_)
        if (p.last < cue && p.counting) last = &p;
      if (!last) continue;
      // "Dining table for four... make that six": the piece named since is what the count is for.
      bool piece = false;
      for (int k = last->last + 1; k < cue; ++k)
        piece = piece || (tokens_[k].item >= 0 && items_[tokens_[k].item].kind == ItemKind::kFurniture);
      if (piece) {  // the furnishing's to read
        Consume(cue - 1 - (tokens_[cue].word == "to"), n);
        continue;
      }
      last->min = last->max = *Cardinal(tokens_[n]);
      Consume(cue - 1 - (tokens_[cue].word == "to"), n);
      continue;
    }
    // The mentions of the correction: those in its sentence after the cue.
    std::vector<int> fresh;
    for (int k = 0; k < static_cast<int>(mentions_.size()); ++k) {
      const Mention& m = mentions_[k];
      if (m.first > cue && tokens_[m.first].sentence == tokens_[cue].sentence && m.counting) fresh.push_back(k);
    }
    auto earlier = [&](Category c, int before) -> Mention* {
      Mention* found = nullptr;
      for (Mention& p : mentions_)
        if (p.last < before && p.counting && p.category == c && p.max != 0) found = &p;
      return found;
    };
    bool any = false;
    for (int k : fresh) {
      Mention& m = mentions_[k];
      Mention* old = earlier(m.category, cue);
      if (!old) continue;
      old->counting = false;
      old->definite = true;
      old->spread = false;
      if (m.ref < 0) m.ref = old->ref;
      any = true;
    }
    if (any) Consume(cue - 1 - (tokens_[cue].word == "to"), cue);
  }
  // "an office - hmm, no, turn the office into a meeting room": the room named before becomes the other
  // (one fewer of its kind; the meeting room is counted where it is named).
  for (int i = 0; i + 3 < size; ++i) {
    if (!In(tokens_[i], {"turn", "convert", "change", "make"})) continue;
    int k = i + 1;
    while (k < size && In(tokens_[k], {"the", "that", "this", "my", "our"})) ++k;
    if (k >= size || tokens_[k].item < 0 || items_[tokens_[k].item].kind != ItemKind::kRoom) continue;
    const int from = MentionOfItem(tokens_[k].item);
    int j = items_[tokens_[k].item].last + 1;
    // ("make the office a nursery instead")
    const bool make_a = tokens_[i].word == "make" && j < size && In(tokens_[j], {"a", "an"});
    if (from < 0 || j >= size || !(In(tokens_[j], {"into", "to"}) || make_a)) continue;
    int y = make_a ? j : j + 1;
    while (y < size && In(tokens_[y], {"a", "an"})) ++y;
    if (y >= size || tokens_[y].item < 0 || items_[tokens_[y].item].kind != ItemKind::kRoom ||
        items_[tokens_[y].item].category == mentions_[from].category)
      continue;
    Mention* old = nullptr;
    for (Mention& p : mentions_)
      if (p.last < i && p.counting && p.category == mentions_[from].category && p.max > 0) old = &p;
    if (!old) continue;
    old->min = std::max(0, old->min - 1);
    old->max = std::max(0, old->max - 1);
    Consume(i, i);
    Consume(j, j);
  }
  // "the meeting room goes on the ground floor instead", "the office moves up to the top floor": the one
  // room of its kind named before, on the floor named now (not one more there).
  for (Mention& m : mentions_) {
    if (m.counting || !m.definite) continue;
    int verb = -1;
    for (int k = m.last + 1; k < size && k <= m.last + 2 && tokens_[k].item < 0 && !tokens_[k].punct; ++k)
      if (In(tokens_[k], {"goes", "go", "moves", "move", "moved", "belongs", "shifts", "shift"})) verb = k;
    if (verb < 0) continue;
    // The floor named right after the verb ("moves up to the top floor").
    int ref = -1;
    for (int k = verb + 1; k < size && k <= verb + 4 && !tokens_[k].punct && ref < 0; ++k)
      if (tokens_[k].item >= 0 && items_[tokens_[k].item].kind == ItemKind::kFloorRef) ref = tokens_[k].item;
    if (ref < 0) continue;
    m.ref = ref;
    Mention* old = nullptr;
    int olds = 0;
    for (Mention& p : mentions_)
      if (&p != &m && p.last < m.first && p.counting && p.category == m.category && p.max > 0) {
        old = &p;
        ++olds;
      }
    if (olds != 1 || old->min != 1 || old->max != 1 || old->ref == m.ref) continue;
    old->ref = m.ref;
    m.ref = -1;
    Consume(verb, verb);
  }
  // "No, scratch the meeting room", "forget the balcony": a room named before, taken back.
  for (Mention& m : mentions_) {
    if (!m.counting || m.max != 0) continue;
    bool the = false, taken_back = false;
    for (int k = m.first; k >= 0 && k >= m.first - 3; --k) {
      the = the || tokens_[k].word == "the";
      taken_back = taken_back || In(tokens_[k], {"scratch", "forget", "ditch", "cancel", "drop", "skip", "lose"});
    }
    if (!the || !taken_back) continue;
    for (Mention& p : mentions_)
      if (&p != &m && p.last < m.first && p.counting && p.category == m.category && p.max > 0) p.min = p.max = 0;
  }
  // "actually", "wait", "sorry" before a correction are read with it.
  for (int i = 0; i < size; ++i)
    if (In(tokens_[i], {"actually", "wait", "sorry", "scratch", "correction"}) && i + 1 < size &&
        (tokens_[i + 1].consumed || tokens_[i + 1].punct) && !cues.empty())
      tokens_[i].consumed = true;
  // Words that only mark a second thought, whatever it is about (a piece of furniture's, read by the
  // furnishing): "actually no, put it in the office", "on second thought", "a shower instead."
  for (int i = 0; i < size; ++i) {
    const Token& t = tokens_[i];
    const bool ends = i + 1 == size || tokens_[i + 1].punct || tokens_[i + 1].sentence != t.sentence;
    if ((In(t, {"actually", "wait", "sorry"}) && i + 1 < size && tokens_[i + 1].word == "no") ||
        (In(t, {"thought", "thoughts"}) && i > 0 && tokens_[i - 1].word == "second") ||
        (t.word == "after" && i + 1 < size && tokens_[i + 1].word == "all" && (i + 2 == size || tokens_[i + 2].punct)) ||
        (t.word == "instead" && (ends || (i + 1 < size && In(tokens_[i + 1], {"of", "make"})))) ||
        // "scratch the rug": a piece taken back (the furnishing's to read)
        (In(t, {"scratch", "forget", "drop", "skip"}) && i + 2 < size && In(tokens_[i + 1], {"the", "that"}) && tokens_[i + 2].item >= 0 &&
         items_[tokens_[i + 2].item].kind == ItemKind::kFurniture))
      tokens_[i].consumed = true;
  }
}

// Counts of the rooms listed, said again: "one floor, six rooms: 2 bedrooms, 1 bathroom, ...", "3 per
// floor", "2 bedrooms + 1 bathroom + 1 balcony (4)". Understood (they ask for nothing more) where they
// agree with the rooms counted; left as words not understood where they do not.
void Parser::RoomTotals() {
  const int size = static_cast<int>(tokens_.size());
  // "one floor, six rooms: 2 bedrooms, 1 bathroom, ...": a total the rooms listed make up.
  // ("..., 3 per floor" likewise, over the floors.)
  int listed = 0, floors = 0;  // (floors_ is set when the brief is finished)
  for (const Mention& m : mentions_)
    if (m.counting && m.min == m.max && m.min > 0) listed += m.min;
  for (const Item& it : items_)
    if (it.kind == ItemKind::kFloorCount) floors = std::max(floors, it.floors);
  for (int i = 0; i + 1 < size; ++i) {
    const std::optional<int> n = Cardinal(tokens_[i]);
    if (!n || tokens_[i].consumed || tokens_[i].item >= 0) continue;
    const bool per_floor = i + 2 < size && In(tokens_[i + 1], {"per", "a", "each", "every"}) && IsFloorNoun(tokens_[i + 2]);
    if ((In(tokens_[i + 1], {"rooms"}) && listed == *n) || (per_floor && listed == *n * floors))
      tokens_[i].consumed = true;
  }
  // "Each of the 3 bedrooms: 1 bed": the rooms counted before, each furnished.
  for (int i = 3; i + 1 < size; ++i)
    if (Cardinal(tokens_[i]) && !tokens_[i].consumed && tokens_[i - 1].word == "the" && tokens_[i - 2].word == "of" &&
        In(tokens_[i - 3], {"each", "all", "both", "every"}) && tokens_[i + 1].item >= 0 && items_[tokens_[i + 1].item].kind == ItemKind::kRoom)
      tokens_[i].consumed = true;
  // "1st floor: 2 bedrooms + 1 bathroom + 1 balcony (4)": the rooms of the list counted in brackets.
  for (int i = 1; i + 1 < size; ++i) {
    const std::optional<int> n = Cardinal(tokens_[i]);
    if (!n || tokens_[i].consumed || tokens_[i - 1].punct != '(' || tokens_[i + 1].punct != ')') continue;
    int in_list = 0;
    for (const Mention& m : mentions_) {
      if (m.last >= i || !m.counting || m.min != m.max || tokens_[m.first].sentence != tokens_[i].sentence) continue;
      bool heading_between = false;
      for (int k = m.last + 1; k < i; ++k) heading_between = heading_between || tokens_[k].punct == ':';
      if (!heading_between) in_list += m.min;
    }
    if (in_list == *n) tokens_[i].consumed = true;
  }
}

// A total first, its floors after: "Bedrooms x4 ... Top floor: 2 bedrooms + 1 bathroom only": the two are
// two of the four, not two more ("two more bedrooms upstairs", "another bathroom upstairs" add; a single
// room named before is no total, and en-suites are rooms of their own).
void Parser::FloorsOfTotals() {
  const int size = static_cast<int>(tokens_.size());
  // "a house with bedrooms for the two founders ... Top floor: 2 bedrooms": the plural without a number
  // is the rooms counted after it.
  for (Mention& m : mentions_) {
    if (!m.counting || !m.plural || m.max != -1 || m.ref >= 0 || m.spread || Cardinal(tokens_[m.first])) continue;
    const bool counted_after = std::any_of(mentions_.begin(), mentions_.end(), [&](const Mention& o) {
      return &o != &m && o.first > m.last && o.counting && o.category == m.category && o.min == o.max && o.min > 0;
    });
    if (!counted_after) continue;
    m.counting = false;
    m.definite = true;
  }
  // The floors first, the total after: "1st floor: ... 1 balcony. 2nd floor: ... 1 balcony. That's 2
  // balconies total": the rooms placed on the floors, counted again, not two more.
  for (Mention& m : mentions_) {
    if (!m.counting || m.ref >= 0 || m.min != m.max || m.min <= 0 || m.per_level >= 0) continue;
    const int sentence = tokens_[m.first].sentence;
    auto word = [&](int k, std::initializer_list<std::string_view> ws) { return k >= 0 && k < size && tokens_[k].sentence == sentence && In(tokens_[k], ws); };
    const bool total = word(m.last + 1, {"total", "altogether"}) || (word(m.last + 1, {"in"}) && word(m.last + 2, {"total", "all"})) ||
                       word(m.first - 1, {"thats", "makes", "totals"}) || (word(m.first - 1, {"is"}) && word(m.first - 2, {"that"}));
    if (!total) continue;
    int placed = 0;
    for (const Mention& p : mentions_)
      if (&p != &m && p.last < m.first && p.counting && p.category == m.category && p.ref >= 0 && p.min == p.max) placed += p.min;
    if (placed != m.min) continue;
    m.counting = false;
    m.definite = true;
    for (int k = m.last + 1; k <= m.last + 2 && word(k, {"total", "altogether", "in", "all"}); ++k) Consume(k, k);
  }
  for (Mention& m : mentions_) {
    if (!m.counting || m.ref < 0 || m.min != m.max || m.min <= 0 || m.per_level >= 0 || items_[m.ref].each) continue;
    const int sentence = tokens_[m.first].sentence;
    auto adds = [&](const Token& t) { return In(t, {"more", "another", "additional", "extra", "also", "too", "further"}); };
    bool more = false;
    for (int k = m.first; k <= m.last + 2 && k < size; ++k) more = more || adds(tokens_[k]) || In(tokens_[k], {"second", "third"});
    for (int k = m.first - 1; k >= 0 && tokens_[k].sentence == sentence && k >= m.first - 4; --k)
      more = more || adds(tokens_[k]) || tokens_[k].word == "plus";
    if (more) continue;
    for (Mention& p : mentions_) {
      if (&p == &m || !p.counting || p.ref >= 0 || p.category != m.category || p.min != p.max || p.min < m.min || p.min < 2 ||
          p.per_level >= 0 || p.spread || items_[p.item].ensuite || items_[m.item].ensuite || tokens_[p.first].sentence >= sentence)
        continue;
      if (p.min == m.min) {
        p.counting = false;
        p.definite = true;
      } else {
        p.min -= m.min;
        p.max -= m.min;
      }
      break;
    }
  }
}

Brief Parser::Run() {
  Brief brief;
  brief.text = std::string(text_);
  MatchAll();
  for (int i = 0; i < static_cast<int>(items_.size()); ++i) {
    if (items_[i].kind != ItemKind::kRoom) continue;
    Mention m;
    m.item = i;
    m.category = items_[i].category;
    bare_mention_ = false;
    Quantify(m);
    mention_of_item_[i] = static_cast<int>(mentions_.size());
    mentions_.push_back(m);
    bare_.push_back(bare_mention_);
  }
  UsedAs();
  Spread();
  PlaceLevels();
  Corrections();
  FloorsOfTotals();
  RoomTotals();
  Distribute();
  Connect();
  Attach();
  Finish(brief);
  return brief;
}

std::string LevelText(int level) {
  if (level == kAnyLevel) return "";
  if (level == kUpperLevels) return "upper floors";
  if (level == kEachLevel) return "each floor";
  return "level " + std::to_string(level);
}

Json LevelJson(int level) {
  if (level == kAnyLevel) return nullptr;
  if (level == kUpperLevels) return "upper";
  if (level == kEachLevel) return "each";
  return level;
}

Json SpanJson(const TextSpan& s) { return Json{{"text", s.text}, {"begin", s.begin}, {"end", s.end}}; }

}  // namespace

std::string_view LinkKindName(LinkKind kind) {
  switch (kind) {
    case LinkKind::kAny: return "any";
    case LinkKind::kOpen: return "open";
    case LinkKind::kDoor: return "door";
  }
  return "any";
}

int Brief::RequirementCount() const {
  int n = 0;
  if (floors) ++n;
  else if (floors_min) ++n;
  if (shape) ++n;
  if (unsupported_shape) ++n;
  n += static_cast<int>(rooms.size() + connections.size() + panoramic.size() + entrance.size() + sides.size());
  return n;
}

Brief ParseBrief(std::string_view text) { return Parser(text).Run(); }

nlohmann::ordered_json BriefToJson(const Brief& brief) {
  Json j;
  j["floors"] = brief.floors ? Json(*brief.floors) : Json(nullptr);
  if (brief.floors_min) j["floors_at_least"] = *brief.floors_min;
  j["shape"] = brief.shape ? Json(std::string(ShapeClassName(*brief.shape))) : Json(nullptr);
  if (brief.unsupported_shape) j["unsupported_shape"] = SpanJson(*brief.unsupported_shape);
  Json rooms = Json::array();
  for (const auto& r : brief.rooms) {
    Json e{{"category", std::string(CategoryName(r.category))}, {"level", LevelJson(r.level)}, {"min", r.min}};
    e["max"] = r.max < 0 ? Json(nullptr) : Json(r.max);
    e["source"] = r.source.text;
    rooms.push_back(e);
  }
  j["rooms"] = rooms;
  Json connections = Json::array();
  for (const auto& c : brief.connections) {
    Json to = Json::array();
    for (Category t : c.to) to.push_back(std::string(CategoryName(t)));
    connections.push_back(Json{{"from", std::string(CategoryName(c.from))}, {"to", to}, {"level", LevelJson(c.level)},
                               {"kind", std::string(LinkKindName(c.kind))}, {"every", c.every},
                               {"source", c.source.text}});
  }
  j["connections"] = connections;
  Json panoramic = Json::array();
  for (const auto& p : brief.panoramic)
    panoramic.push_back(Json{{"category", p.category == Category::kRoom ? Json(nullptr) : Json(std::string(CategoryName(p.category)))},
                             {"level", LevelJson(p.level)}, {"source", p.source.text}});
  j["panoramic_windows"] = panoramic;
  Json entrance = Json::array();
  for (const auto& e : brief.entrance)
    entrance.push_back(Json{{"category", std::string(CategoryName(e.category))}, {"source", e.source.text}});
  j["entrance"] = entrance;
  Json sides = Json::array();
  for (const auto& s : brief.sides)
    sides.push_back(Json{{"category", std::string(CategoryName(s.category))}, {"level", LevelJson(s.level)},
                         {"side", s.side}, {"source", s.source.text}});
  j["sides"] = sides;
  Json furniture = Json::array();
  for (const auto& f : brief.furniture)
    furniture.push_back(Json{{"item", f.item}, {"count", f.count},
                             {"room", f.category == Category::kRoom ? Json(nullptr) : Json(std::string(CategoryName(f.category)))},
                             {"level", LevelJson(f.level)}, {"source", f.source.text}});
  j["furniture"] = furniture;
  Json unparsed = Json::array();
  for (const auto& u : brief.unparsed) unparsed.push_back(SpanJson(u));
  j["unparsed"] = unparsed;
  j["conflicts"] = brief.conflicts;
  j["ordinals"] = brief.british_ordinals ? "british" : "american";
  j["requirements"] = brief.RequirementCount();
  return j;
}

std::string BriefOneLine(const Brief& brief) {
  std::vector<std::string> parts;
  if (brief.floors) parts.push_back(std::to_string(*brief.floors) + (*brief.floors == 1 ? " floor" : " floors"));
  else if (brief.floors_min) parts.push_back(">= " + std::to_string(*brief.floors_min) + " floors");
  if (brief.shape) parts.push_back(std::string(ShapeClassName(*brief.shape)) + " footprint");
  if (brief.unsupported_shape) parts.push_back("unsupported footprint \"" + brief.unsupported_shape->text + "\"");
  for (const auto& r : brief.rooms) {
    std::string count = r.min == r.max ? std::to_string(r.min)
                        : r.max < 0   ? ">=" + std::to_string(r.min)
                                      : std::to_string(r.min) + "-" + std::to_string(r.max);
    std::string where = LevelText(r.level);
    parts.push_back(count + " " + std::string(CategoryName(r.category)) + (where.empty() ? "" : " (" + where + ")"));
  }
  for (const auto& c : brief.connections) {
    std::string to;
    for (Category t : c.to) {
      if (!to.empty()) to += '|';
      to += CategoryName(t);
    }
    std::string where = LevelText(c.level);
    parts.push_back(std::string(CategoryName(c.from)) + " -" + std::string(LinkKindName(c.kind)) + "- " + to +
                    (where.empty() ? "" : " (" + where + ")"));
  }
  for (const auto& p : brief.panoramic) {
    std::string where = LevelText(p.level);
    parts.push_back("panoramic window" +
                    (p.category == Category::kRoom ? std::string() : " in " + std::string(CategoryName(p.category))) +
                    (where.empty() ? "" : " (" + where + ")"));
  }
  for (const auto& e : brief.entrance) parts.push_back("entrance into " + std::string(CategoryName(e.category)));
  for (const auto& s : brief.sides) parts.push_back(std::string(CategoryName(s.category)) + " on the " + s.side + " side");
  std::string out;
  for (const auto& p : parts) {
    if (!out.empty()) out += ", ";
    out += p;
  }
  return out.empty() ? "(no requirements)" : out;
}

}  // namespace villa
