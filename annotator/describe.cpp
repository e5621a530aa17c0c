#include "annotator/describe.h"

#include <algorithm>
#include <array>
#include <map>
#include <sstream>

#include "layout/geometry.h"
#include "layout/topology.h"
#include "util/hash.h"

namespace villa::annotator {
namespace {

// The describer's draws: util's SplitMix64 stream with its own seed offset and a modulo pick, so the
// drafted texts stay what they were.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : stream_(seed ^ 0x5851f42d4c957f2dULL) {}
  std::uint64_t Next() { return stream_.Next(); }
  int Below(int n) { return n <= 1 ? 0 : static_cast<int>(Next() % static_cast<std::uint64_t>(n)); }
  bool Chance(int percent) { return Below(100) < percent; }
  template <class T>
  const T& Pick(const std::vector<T>& items) { return items[Below(static_cast<int>(items.size()))]; }

 private:
  SplitMix64 stream_;
};

const char* kNumberWords[] = {"zero", "one", "two", "three", "four", "five", "six", "seven",
                              "eight", "nine", "ten", "eleven", "twelve", "thirteen", "fourteen",
                              "fifteen", "sixteen", "seventeen", "eighteen"};

std::string NumberWord(int n) { return n >= 0 && n <= 18 ? kNumberWords[n] : std::to_string(n); }

std::string Capitalise(std::string s) {
  if (!s.empty() && s[0] >= 'a' && s[0] <= 'z') s[0] = static_cast<char>(s[0] - 'a' + 'A');
  return s;
}

std::string Article(const std::string& noun) {
  if (noun.empty()) return noun;
  // By sound: "an L-shaped", "a U-shaped", "a one-storey", "an 8-storey", "an office".
  if (noun.rfind("one", 0) == 0 || noun.rfind("U-", 0) == 0 || noun.rfind("utility", 0) == 0) return "a " + noun;
  for (const char* an : {"L-", "H-", "8", "11", "18"})
    if (noun.rfind(an, 0) == 0) return "an " + noun;
  char c = noun[0];
  return (c == 'a' || c == 'e' || c == 'i' || c == 'o' || c == 'u') ? "an " + noun : "a " + noun;
}

std::string JoinList(const std::vector<std::string>& items, bool oxford) {
  if (items.empty()) return "";
  if (items.size() == 1) return items[0];
  std::string out;
  for (std::size_t i = 0; i + 1 < items.size(); ++i) out += (i ? ", " : "") + items[i];
  return out + (oxford && items.size() > 2 ? ", and " : " and ") + items.back();
}

// Per description: which words to use, fixed once so a text stays consistent with itself.
struct Voice {
  bool digits = false;       // "2 bedrooms" rather than "two bedrooms"
  bool storey = false;       // British "storey"
  bool lounge = false;       // "lounge" for living room
  bool kids = false;         // "kids' room" for children's room
  bool study = false;        // "study" for office
  bool oxford = false;
  int level_scheme = 0;      // 0: ground/upstairs/top, 1: ground/upper|second/third, 2: ground/second/top
};

std::string Singular(Category c, const Voice& v) {
  switch (c) {
    case Category::kLivingRoom: return v.lounge ? "lounge" : "living room";
    case Category::kBedroom: return "bedroom";
    case Category::kKitchen: return "kitchen";
    case Category::kBathroom: return "bathroom";
    case Category::kDiningRoom: return "dining room";
    case Category::kChildrenRoom: return v.kids ? "kids' room" : "children's room";
    case Category::kOffice: return v.study ? "study" : "office";
    case Category::kMeetingRoom: return "meeting room";
    case Category::kUtilityRoom: return "utility room";
    case Category::kBalcony: return "balcony";
    case Category::kRoom: return "room";
  }
  return "room";
}

std::string Plural(Category c, const Voice& v) {
  switch (c) {
    case Category::kChildrenRoom: return v.kids ? "kids' rooms" : "children's rooms";
    case Category::kOffice: return v.study ? "studies" : "offices";
    case Category::kBalcony: return "balconies";
    default: return Singular(c, v) + "s";
  }
}

std::string Counted(Category c, int n, const Voice& v) {
  if (n == 1) return Article(Singular(c, v));
  return (v.digits ? std::to_string(n) : NumberWord(n)) + " " + Plural(c, v);
}

std::string FloorsAdjective(int floors, const Voice& v, Rng& rng) {
  std::string unit = v.storey ? "storey" : "story";
  if (floors == 1) return rng.Chance(50) ? "single-" + unit : "one-" + unit;
  return (v.digits ? std::to_string(floors) : NumberWord(floors)) + "-" + unit;
}

std::string FloorsNoun(int floors, const Voice& v, Rng& rng) {
  std::vector<std::string> units = {"floor", "level", v.storey ? "storey" : "story"};
  std::string unit = rng.Pick(units);
  std::string number = v.digits ? std::to_string(floors) : NumberWord(floors);
  if (floors == 1) return number + " " + unit;
  if (unit == "story") return number + " stories";
  return number + " " + unit + "s";
}

std::string ShapeAdjective(const std::string& shape, Rng& rng) {
  if (shape == "rectangle") return "rectangular";
  if (shape == "irregular") return rng.Chance(50) ? "irregularly shaped" : "irregular";
  if (shape == "hexagon") return "hexagonal";
  if (shape == "octagon") return "octagonal";
  if (shape == "trapezoid") return "trapezoidal";
  if (shape == "bay") return "bay-fronted";
  if (shape == "angled-wing") return "angled-wing";
  return shape + "-shaped";
}

// "the ground floor", "upstairs", "the top floor"... as a place ("on the ground floor" / "upstairs").
std::string LevelPlace(int level, int floors, const Voice& v) {
  if (level == 0) return "on the ground floor";
  if (floors == 2) {
    switch (v.level_scheme) {
      case 0: return "upstairs";
      case 1: return "on the upper floor";
      default: return "on the top floor";
    }
  }
  if (level == 1) return v.level_scheme == 1 ? "on the middle floor" : "on the second floor";
  return v.level_scheme == 1 ? "on the third floor" : "on the top floor";
}

// "ground floor", "upper floor", "second floor": the floor's name as a noun.
std::string LevelNoun(int level, int floors, const Voice& v) {
  if (level == 0) return "ground floor";
  if (floors == 2) return v.level_scheme == 2 ? "top floor" : "upper floor";
  if (level == 1) return v.level_scheme == 1 ? "middle floor" : "second floor";
  return v.level_scheme == 1 ? "third floor" : "top floor";
}

struct Analysis {
  int floors = 0;
  std::map<Category, int> counts;                    // whole building, labelled rooms only
  std::vector<std::map<Category, int>> level_counts;  // per level
  std::vector<Connection> connections;
};

bool UniqueOnLevel(const Layout& layout, const Analysis& an, int room) {
  const Room& r = layout.rooms[room];
  auto it = an.level_counts[r.level].find(r.category);
  return it != an.level_counts[r.level].end() && it->second == 1;
}

// Category order in room lists: the way people list a house.
const std::array<Category, 10> kListOrder = {Category::kLivingRoom, Category::kKitchen, Category::kDiningRoom,
                                             Category::kBedroom, Category::kChildrenRoom, Category::kBathroom,
                                             Category::kOffice, Category::kMeetingRoom, Category::kBalcony,
                                             Category::kUtilityRoom};

struct Statement {
  std::string text;
  std::vector<Fact> facts;
};

// The room list of the whole building, or of one level (level >= 0). `skip_utility` leaves utility
// rooms unstated (no fact either).
Statement RoomList(const std::map<Category, int>& counts, int level, const Voice& v, bool skip_utility,
                   const std::string& master_for_single_bedroom = "") {
  Statement s;
  std::vector<std::string> items;
  for (Category c : kListOrder) {
    auto it = counts.find(c);
    if (it == counts.end() || it->second == 0) continue;
    if (skip_utility && c == Category::kUtilityRoom) continue;
    std::string item = Counted(c, it->second, v);
    if (c == Category::kBedroom && it->second == 1 && !master_for_single_bedroom.empty())
      item = "a " + master_for_single_bedroom;
    items.push_back(item);
    Fact f;
    f.kind = level < 0 ? FactKind::kCount : FactKind::kCountOnLevel;
    f.category = c;
    f.level = level;
    f.value = it->second;
    s.facts.push_back(f);
  }
  s.text = JoinList(items, v.oxford);
  return s;
}

struct Links {
  std::vector<std::pair<int, int>> kitchen_open_dining;  // (kitchen, dining), both unique on their level
  std::vector<std::pair<int, int>> living_to_kitchen;    // (living, kitchen)
  std::vector<std::pair<int, int>> en_suite;             // (host, bathroom)
  std::vector<std::pair<int, int>> balcony;              // (room, balcony)
  std::vector<std::pair<int, std::string>> sides;        // (room, side)
};

Links FindLinks(const Layout& layout, const Analysis& an) {
  Links out;
  auto via = [&](int a, int b, bool open_only) {
    for (const Connection& c : an.connections) {
      if (c.via == Via::kStair) continue;
      if (!((c.room_a == a && c.room_b == b) || (c.room_a == b && c.room_b == a))) continue;
      if (!open_only || c.via == Via::kOpen) return true;
    }
    return false;
  };
  int n = static_cast<int>(layout.rooms.size());
  for (int a = 0; a < n; ++a) {
    const Room& ra = layout.rooms[a];
    for (int b = 0; b < n; ++b) {
      if (a == b) continue;
      const Room& rb = layout.rooms[b];
      if (ra.level != rb.level) continue;
      bool unique = UniqueOnLevel(layout, an, a) && UniqueOnLevel(layout, an, b);
      if (!unique) continue;
      if (ra.category == Category::kKitchen && rb.category == Category::kDiningRoom && via(a, b, true))
        out.kitchen_open_dining.push_back({a, b});
      if (ra.category == Category::kLivingRoom && rb.category == Category::kKitchen && via(a, b, false))
        out.living_to_kitchen.push_back({a, b});
    }
  }
  // En-suite: a bathroom whose only door or open leads to one bedroom-like room, through a door.
  for (int b = 0; b < n; ++b) {
    if (layout.rooms[b].category != Category::kBathroom) continue;
    std::vector<const Connection*> links;
    for (const Connection& c : an.connections)
      if (c.via != Via::kStair && (c.room_a == b || c.room_b == b)) links.push_back(&c);
    if (links.size() != 1 || links[0]->via != Via::kDoor) continue;
    int host = links[0]->room_a == b ? links[0]->room_b : links[0]->room_a;
    Category hc = layout.rooms[host].category;
    if ((hc == Category::kBedroom || hc == Category::kChildrenRoom) && UniqueOnLevel(layout, an, host))
      out.en_suite.push_back({host, b});
  }
  // Balconies with a panoramic window, entered through a door from a room unique on its floor.
  for (int b = 0; b < n; ++b) {
    if (layout.rooms[b].category != Category::kBalcony) continue;
    bool panoramic = false;
    for (const Element& w : layout.windows)
      if (w.panoramic && w.OnLevel(layout.rooms[b].level) && RingHoldsSegment(layout.rooms[b].polygon, w.shape, kOnWallTolerance))
        panoramic = true;
    if (!panoramic) continue;
    for (const Connection& c : an.connections) {
      if (c.via != Via::kDoor || (c.room_a != b && c.room_b != b)) continue;
      int room = c.room_a == b ? c.room_b : c.room_a;
      Category rc = layout.rooms[room].category;
      if (rc == Category::kBalcony || rc == Category::kUtilityRoom || rc == Category::kRoom) continue;
      if (!UniqueOnLevel(layout, an, room)) continue;
      out.balcony.push_back({room, b});
      break;
    }
  }
  // Sides: rooms unique on their floor whose centroid sits clearly towards one side of the floor.
  for (int r = 0; r < n; ++r) {
    const Room& room = layout.rooms[r];
    if (room.category == Category::kRoom || room.category == Category::kUtilityRoom) continue;
    if (!UniqueOnLevel(layout, an, r)) continue;
    Box2 bounds = LevelBounds(layout, room.level);
    if (bounds.width() <= 0 || bounds.height() <= 0) continue;
    Point c = Centroid(room.polygon);
    double fx = (c.x - bounds.min_x) / bounds.width();
    double fy = (c.y - bounds.min_y) / bounds.height();
    // Outer third, with a small margin so the statement is never borderline.
    double dx = std::abs(fx - 0.5), dy = std::abs(fy - 0.5);
    if (std::max(dx, dy) < 1.0 / 6.0 + 0.03) continue;
    std::string side = dy >= dx ? (fy > 0.5 ? "north" : "south") : (fx > 0.5 ? "east" : "west");
    out.sides.push_back({r, side});
  }
  return out;
}

Fact RoomFact(FactKind kind, const Layout& layout, int a, int b, const std::string& text = "") {
  Fact f;
  f.kind = kind;
  f.a = layout.rooms[a].name();
  if (b >= 0) f.b = layout.rooms[b].name();
  f.category = layout.rooms[a].category;
  f.level = layout.rooms[a].level;
  f.text = text;
  return f;
}

// "the kitchen on the ground floor" / "the kitchen" when the building has only one.
std::string TheRoom(const Layout& layout, const Analysis& an, int room, const Voice& v, bool always_level = false) {
  const Room& r = layout.rooms[room];
  std::string noun = "the " + Singular(r.category, v);
  if (an.floors > 1 && (always_level || an.counts.at(r.category) > 1)) noun.append(" ").append(LevelPlace(r.level, an.floors, v));
  return noun;
}

struct FurnitureChoice {
  Category category;
  const char* item;
};
const std::vector<FurnitureChoice> kFurniture = {
    {Category::kMeetingRoom, "a TV"},          {Category::kMeetingRoom, "a long conference table"},
    {Category::kChildrenRoom, "a double bed"}, {Category::kChildrenRoom, "a bunk bed"},
    {Category::kChildrenRoom, "a desk"},       {Category::kBedroom, "a double bed"},
    {Category::kBedroom, "a wardrobe"},        {Category::kLivingRoom, "a sofa"},
    {Category::kLivingRoom, "a TV"},           {Category::kOffice, "a desk"},
    {Category::kOffice, "a bookshelf"},        {Category::kDiningRoom, "a dining table for six"},
    {Category::kKitchen, "a kitchen island"},  {Category::kBathroom, "a bathtub"},
};

// Furniture requests for rooms whose category is unique in the building (so "the X" names one room).
std::vector<std::pair<int, std::string>> PickFurniture(const Layout& layout, const Analysis& an, Rng& rng, int max) {
  std::vector<std::pair<int, std::string>> out;
  std::vector<int> order;
  for (int i = 0; i < static_cast<int>(kFurniture.size()); ++i) order.push_back(i);
  for (int i = static_cast<int>(order.size()) - 1; i > 0; --i) std::swap(order[i], order[rng.Below(i + 1)]);
  std::vector<Category> used;
  for (int i : order) {
    if (static_cast<int>(out.size()) >= max) break;
    Category c = kFurniture[i].category;
    if (std::find(used.begin(), used.end(), c) != used.end()) continue;
    auto it = an.counts.find(c);
    if (it == an.counts.end() || it->second != 1) continue;
    for (int r = 0; r < static_cast<int>(layout.rooms.size()); ++r)
      if (layout.rooms[r].category == c) {
        out.push_back({r, kFurniture[i].item});
        used.push_back(c);
        break;
      }
  }
  return out;
}

std::string FurnitureSentence(const Layout& layout, const Analysis& an, const std::vector<std::pair<int, std::string>>& items,
                              const Voice& v, Rng& rng, std::vector<Fact>& facts) {
  if (items.empty()) return "";
  std::vector<std::string> parts;
  for (std::size_t i = 0; i < items.size(); ++i) {
    auto [room, item] = items[i];
    std::string where = "in " + TheRoom(layout, an, room, v);
    static const std::vector<std::string> verbs = {"include", "place", "put"};
    std::string verb = i == 0 ? "" : rng.Pick(verbs) + " ";
    parts.push_back(verb + item + " " + where);
    facts.push_back(RoomFact(FactKind::kFurniture, layout, room, -1, item));
  }
  return JoinList(parts, false);
}

Voice MakeVoice(Rng& rng) {
  Voice v;
  v.digits = rng.Chance(30);
  v.storey = rng.Chance(35);
  v.lounge = rng.Chance(25);
  v.kids = rng.Chance(35);
  v.study = rng.Chance(35);
  v.oxford = rng.Chance(40);
  v.level_scheme = rng.Below(3);
  return v;
}

Fact FloorsFact(int floors) {
  Fact f;
  f.kind = FactKind::kFloors;
  f.value = floors;
  return f;
}
Fact ShapeFact(const std::string& shape) {
  Fact f;
  f.kind = FactKind::kShape;
  f.text = shape;
  return f;
}

// The connection sentences of the fine description, in the voice of `style`.
std::vector<std::string> LinkSentences(const Layout& layout, const Analysis& an, const Links& links, const Voice& v,
                                       DescriptionStyle style, Rng& rng, std::vector<Fact>& facts, bool with_sides) {
  std::vector<std::string> out;
  bool terse = style == DescriptionStyle::kBrief || style == DescriptionStyle::kSpec;
  for (auto [k, d] : links.kitchen_open_dining) {
    std::string kitchen = TheRoom(layout, an, k, v);
    std::string dining = "the " + Singular(Category::kDiningRoom, v);
    std::string s;
    if (terse)
      s = rng.Chance(50) ? Capitalise(kitchen) + " open to " + dining : "Open-plan kitchen flowing into " + dining;
    else if (style == DescriptionStyle::kRequest)
      s = "I hope " + kitchen + " can be openly connected to " + dining;
    else
      s = "we'd love an open-plan kitchen that flows straight into " + dining;
    out.push_back(s);
    facts.push_back(RoomFact(FactKind::kOpenLink, layout, k, d));
  }
  for (auto [l, k] : links.living_to_kitchen) {
    std::string living = TheRoom(layout, an, l, v);
    std::string kitchen = "the " + Singular(Category::kKitchen, v);
    std::string s;
    if (terse)
      s = Capitalise(living) + " connected directly to " + kitchen;
    else if (style == DescriptionStyle::kRequest)
      s = Capitalise(living) + " should directly access " + kitchen;
    else
      s = "it would be great if " + living + " led directly into " + kitchen;
    out.push_back(s);
    facts.push_back(RoomFact(FactKind::kDirectLink, layout, l, k));
  }
  for (auto [host, bath] : links.en_suite) {
    std::string who = TheRoom(layout, an, host, v, true);
    std::string s = terse ? Capitalise(who) + " with its own en-suite bathroom"
                          : (style == DescriptionStyle::kRequest ? Capitalise(who) + " should have its own bathroom"
                                                                 : who + " could have its own en-suite bathroom");
    out.push_back(s);
    facts.push_back(RoomFact(FactKind::kEnSuite, layout, host, bath));
  }
  if (!links.balcony.empty()) {
    std::vector<std::string> rooms;
    for (auto [room, balcony] : links.balcony) {
      rooms.push_back(TheRoom(layout, an, room, v, true));
      facts.push_back(RoomFact(FactKind::kBalcony, layout, room, balcony));
    }
    bool many = rooms.size() > 1;
    std::string subject = (many && !terse ? "both " : "") + JoinList(rooms, v.oxford);
    if (rooms.size() > 2 && !terse) subject = JoinList(rooms, v.oxford);
    std::string balconies = many ? "balconies with panoramic windows" : "a balcony with panoramic windows";
    std::string s;
    if (terse)
      s = Capitalise(subject) + (many ? " each opening onto " : " opening onto ") + balconies;
    else if (style == DescriptionStyle::kRequest)
      s = Capitalise(subject) + " should directly connect to " + balconies;
    else
      s = subject + (many ? " should each open onto " : " should open onto ") + balconies;
    out.push_back(s);
  }
  if (with_sides && !links.sides.empty()) {
    // At most two, so the text stays readable.
    std::vector<std::pair<int, std::string>> sides = links.sides;
    for (int i = static_cast<int>(sides.size()) - 1; i > 0; --i) std::swap(sides[i], sides[rng.Below(i + 1)]);
    sides.resize(std::min<std::size_t>(sides.size(), 2));
    std::vector<std::string> parts;
    for (auto [room, side] : sides) {
      parts.push_back(TheRoom(layout, an, room, v, true) + " on the " + side + " side");
      facts.push_back(RoomFact(FactKind::kSide, layout, room, -1, side));
    }
    std::string s = terse ? Capitalise(JoinList(parts, v.oxford))
                          : (style == DescriptionStyle::kRequest ? "I would like " : "we'd like ") + JoinList(parts, v.oxford);
    out.push_back(s);
  }
  return out;
}

std::string Sentences(const std::vector<std::string>& parts) {
  std::string out;
  for (const std::string& p : parts) {
    if (p.empty()) continue;
    if (!out.empty()) out += " ";
    out += Capitalise(p);
    if (out.back() != '.' && out.back() != '?' && out.back() != '!') out += ".";
  }
  return out;
}

std::string Building(Rng& rng) {
  static const std::vector<std::string> nouns = {"villa", "house", "home", "villa"};
  return rng.Pick(nouns);
}

Drafts Draft(const Layout& layout, const std::string& shape, std::uint64_t seed) {
  Analysis an;
  an.floors = layout.LevelCount();
  an.level_counts.resize(std::max(an.floors, 1));
  for (const Room& r : layout.rooms) {
    if (r.category == Category::kRoom) continue;
    ++an.counts[r.category];
    ++an.level_counts[r.level][r.category];
  }
  an.connections = RoomConnections(layout);
  Links links = FindLinks(layout, an);

  Rng rng(seed);
  Drafts d;
  d.coarse_style = static_cast<DescriptionStyle>(rng.Below(kDescriptionStyleCount));
  d.fine_style = static_cast<DescriptionStyle>(rng.Below(kDescriptionStyleCount));
  int floors = an.floors;
  bool single_bedroom = an.counts.count(Category::kBedroom) && an.counts[Category::kBedroom] == 1;

  // ---- coarse: floors, footprint, the rooms ----
  {
    Voice v = MakeVoice(rng);
    std::vector<Fact>& facts = d.coarse_facts;
    facts.push_back(FloorsFact(floors));
    facts.push_back(ShapeFact(shape));
    std::string master = single_bedroom && rng.Chance(40) ? "master bedroom" : "";
    Statement rooms = RoomList(an.counts, -1, v, d.coarse_style == DescriptionStyle::kConversational, master);
    facts.insert(facts.end(), rooms.facts.begin(), rooms.facts.end());
    std::string building = Building(rng);
    std::string sh = ShapeAdjective(shape, rng);
    switch (d.coarse_style) {
      case DescriptionStyle::kRequest: {
        static const std::vector<std::string> openers = {"I want to build", "I would like to build", "I'd like",
                                                         "Please design"};
        d.coarse = Sentences({rng.Pick(openers) + " " + Article(FloorsAdjective(floors, v, rng) + ", " + sh + " " + building),
                              (rng.Chance(50) ? "The house needs " : "It should have ") + rooms.text});
        break;
      }
      case DescriptionStyle::kBrief:
        d.coarse = Sentences({Capitalise(FloorsAdjective(floors, v, rng)) + " " + sh + " " + building,
                              rng.Chance(50) ? "Rooms: " + rooms.text : Capitalise(rooms.text)});
        break;
      case DescriptionStyle::kSpec:
        d.coarse = Sentences({"Floors: " + (v.digits ? std::to_string(floors) : NumberWord(floors)),
                              "Footprint: " + sh, "Rooms: " + rooms.text});
        break;
      case DescriptionStyle::kConversational: {
        std::string start = rng.Chance(50) ? "Hi! We're looking for " : "Hello, we're hoping to build ";
        d.coarse = Sentences({start + Article(sh + " " + building) + " with " + FloorsNoun(floors, v, rng),
                              "We need " + rooms.text + (rng.Chance(50) ? ", if possible" : "")});
        break;
      }
    }
  }

  // ---- fine: floors, footprint, rooms per floor, connections, balconies, sides, furniture ----
  {
    Voice v = MakeVoice(rng);
    std::vector<Fact>& facts = d.fine_facts;
    facts.push_back(FloorsFact(floors));
    facts.push_back(ShapeFact(shape));
    DescriptionStyle style = d.fine_style;
    std::string building = Building(rng);
    std::string sh = ShapeAdjective(shape, rng);
    std::vector<std::string> parts;
    // Per-floor room lists (a single-storey building lists the whole house).
    std::vector<std::string> per_level;
    bool skip_utility = style == DescriptionStyle::kConversational || style == DescriptionStyle::kRequest;
    for (int level = 0; level < floors; ++level) {
      bool single_bedroom_here = single_bedroom && an.level_counts[level].count(Category::kBedroom);
      std::string master = single_bedroom_here && rng.Chance(40) ? "master bedroom" : "";
      Statement rooms = RoomList(an.level_counts[level], floors > 1 ? level : -1, v, skip_utility, master);
      if (rooms.text.empty()) continue;
      facts.insert(facts.end(), rooms.facts.begin(), rooms.facts.end());
      std::string place = LevelPlace(level, floors, v);
      if (floors == 1) {
        per_level.push_back(rooms.text);
      } else if (style == DescriptionStyle::kSpec || style == DescriptionStyle::kBrief) {
        per_level.push_back(Capitalise(LevelNoun(level, floors, v)) + ": " + rooms.text);
      } else if (style == DescriptionStyle::kRequest) {
        per_level.push_back(Capitalise(place) + " I need " + rooms.text);
      } else {
        per_level.push_back(Capitalise(place) + " we'd like " + rooms.text);
      }
    }
    if (per_level.empty()) per_level.push_back("");
    int furniture_count = rng.Below(3);  // 0, 1 or 2 requests
    auto furniture = PickFurniture(layout, an, rng, furniture_count);
    bool with_sides = rng.Chance(45);
    std::vector<Fact> link_facts;
    auto link_sentences = LinkSentences(layout, an, links, v, style, rng, link_facts, with_sides);
    std::vector<Fact> furniture_facts;
    std::string furniture_text = FurnitureSentence(layout, an, furniture, v, rng, furniture_facts);

    switch (style) {
      case DescriptionStyle::kRequest: {
        static const std::vector<std::string> openers = {"I want to build", "I would like to build", "I'd like"};
        parts.push_back(rng.Pick(openers) + " " + Article(FloorsAdjective(floors, v, rng) + ", " + sh + " " + building));
        if (floors == 1)
          parts.push_back("The house needs " + per_level[0]);
        else
          for (const std::string& p : per_level) parts.push_back(p);
        if (!link_sentences.empty()) {
          std::string first = link_sentences[0];  // lower-case after the comma, but keep the pronoun "I"
          if (first.size() > 1 && first[0] >= 'A' && first[0] <= 'Z' && first.rfind("I ", 0) != 0)
            first[0] = static_cast<char>(first[0] - 'A' + 'a');
          parts.push_back("For the layout, " + first);
          for (std::size_t i = 1; i < link_sentences.size(); ++i) parts.push_back(link_sentences[i]);
        }
        if (!furniture_text.empty()) parts.push_back("In addition, please include " + furniture_text);
        break;
      }
      case DescriptionStyle::kBrief: {
        parts.push_back(Capitalise(FloorsAdjective(floors, v, rng)) + " " + sh + " " + building);
        std::string rooms;
        for (std::string p : per_level) {
          if (!rooms.empty() && !p.empty() && p[0] >= 'A' && p[0] <= 'Z') p[0] = static_cast<char>(p[0] - 'A' + 'a');
          rooms += (rooms.empty() ? "" : "; ") + p;
        }
        parts.push_back(rooms);
        for (const std::string& s : link_sentences) parts.push_back(s);
        if (!furniture_text.empty()) parts.push_back("Furniture: " + furniture_text);
        break;
      }
      case DescriptionStyle::kSpec: {
        parts.push_back("Floors: " + (v.digits ? std::to_string(floors) : NumberWord(floors)));
        parts.push_back("Footprint: " + sh);
        if (floors == 1)
          parts.push_back("Rooms: " + per_level[0]);
        else
          for (const std::string& p : per_level) parts.push_back(p);
        if (!link_sentences.empty()) {
          std::string joined;
          for (const std::string& s : link_sentences) {
            std::string lower = s;
            if (!lower.empty() && lower[0] >= 'A' && lower[0] <= 'Z')
              lower[0] = static_cast<char>(lower[0] - 'A' + 'a');
            joined += (joined.empty() ? "" : "; ") + lower;
          }
          parts.push_back("Connections: " + joined);
        }
        if (!furniture_text.empty()) parts.push_back("Furniture: " + furniture_text);
        break;
      }
      case DescriptionStyle::kConversational: {
        std::string start = rng.Chance(50) ? "Hi! We're looking for " : "Hello, we're hoping to build ";
        parts.push_back(start + Article(sh + " " + building) + " with " + FloorsNoun(floors, v, rng));
        if (floors == 1)
          parts.push_back("We'd like " + per_level[0]);
        else
          for (const std::string& p : per_level) parts.push_back(p);
        for (const std::string& s : link_sentences) parts.push_back(s);
        if (!furniture_text.empty()) parts.push_back("Could you also put " + furniture_text + "? Thanks");
        break;
      }
    }
    facts.insert(facts.end(), link_facts.begin(), link_facts.end());
    facts.insert(facts.end(), furniture_facts.begin(), furniture_facts.end());
    d.fine = Sentences(parts);
  }
  return d;
}

}  // namespace

Drafts DraftDescriptions(const Layout& layout, const std::string& shape, std::uint64_t seed) {
  return Draft(layout, shape, seed);
}

std::string DescribeFact(const Fact& f) {
  std::ostringstream out;
  switch (f.kind) {
    case FactKind::kFloors: out << "floors = " << f.value; break;
    case FactKind::kShape: out << "shape = " << f.text; break;
    case FactKind::kCount: out << CategoryName(f.category) << " count = " << f.value; break;
    case FactKind::kCountOnLevel:
      out << CategoryName(f.category) << " count on level " << f.level << " = " << f.value;
      break;
    case FactKind::kOpenLink: out << f.a << " open to " << f.b; break;
    case FactKind::kDirectLink: out << f.a << " connects to " << f.b; break;
    case FactKind::kEnSuite: out << f.b << " reached only through " << f.a; break;
    case FactKind::kBalcony: out << f.a << " reaches balcony " << f.b << " (panoramic)"; break;
    case FactKind::kSide: out << f.a << " on the " << f.text << " side"; break;
    case FactKind::kFurniture: out << f.text << " in " << f.a; break;
  }
  return out.str();
}

}  // namespace villa::annotator
