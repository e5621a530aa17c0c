// Drafted descriptions: every fact the drafter states is checked against the layout's geometry and
// topology, over many seeds and both fixture layouts; the text carries the facts it claims.
#include <algorithm>
#include <cctype>
#include <set>

#include <catch2/catch.hpp>

#include "annotator/describe.h"
#include "layout/geometry.h"
#include "layout/topology.h"
#include "test_support.h"

using namespace villa;
using namespace villa::annotator;

namespace {

std::string Lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool Linked(const Layout& l, const std::vector<Connection>& cs, int a, int b, bool open_only, bool door_only) {
  for (const Connection& c : cs) {
    if (!((c.room_a == a && c.room_b == b) || (c.room_a == b && c.room_b == a))) continue;
    if (open_only && c.via != Via::kOpen) continue;
    if (door_only && c.via != Via::kDoor) continue;
    if (c.via == Via::kStair) continue;
    return true;
  }
  return false;
}

}  // namespace

// Independent check of one fact against the layout; returns an empty string when it holds.
std::string CheckDescriptionFact(const Layout& l, const std::string& shape, const Fact& f) {
  auto cs = RoomConnections(l);
  int a = f.a.empty() ? -1 : l.FindRoom(f.a);
  int b = f.b.empty() ? -1 : l.FindRoom(f.b);
  switch (f.kind) {
    case FactKind::kFloors: return f.value == l.LevelCount() ? "" : "wrong floor count";
    case FactKind::kShape: return f.text == shape ? "" : "wrong shape";
    case FactKind::kCount: {
      int n = 0;
      for (const Room& r : l.rooms) n += r.category == f.category;
      return n == f.value ? "" : "count is " + std::to_string(n);
    }
    case FactKind::kCountOnLevel: {
      int n = 0;
      for (const Room& r : l.rooms) n += r.category == f.category && r.level == f.level;
      return n == f.value ? "" : "count on level is " + std::to_string(n);
    }
    case FactKind::kOpenLink:
      if (a < 0 || b < 0) return "no such room";
      return Linked(l, cs, a, b, true, false) ? "" : "not joined by an open";
    case FactKind::kDirectLink:
      if (a < 0 || b < 0) return "no such room";
      return Linked(l, cs, a, b, false, false) ? "" : "not joined";
    case FactKind::kEnSuite: {
      if (a < 0 || b < 0) return "no such room";
      int links = 0;
      for (const Connection& c : cs)
        if (c.via != Via::kStair && (c.room_a == b || c.room_b == b)) ++links;
      return links == 1 && Linked(l, cs, a, b, false, true) ? "" : "not en-suite";
    }
    case FactKind::kBalcony: {
      if (a < 0 || b < 0) return "no such room";
      if (l.rooms[b].category != Category::kBalcony) return "not a balcony";
      bool pano = false;
      for (const Element& w : l.windows)
        pano = pano || (w.panoramic && w.OnLevel(l.rooms[b].level) && RingHoldsSegment(l.rooms[b].polygon, w.shape, kOnWallTolerance));
      return pano && Linked(l, cs, a, b, false, true) ? "" : "balcony without panoramic window or door";
    }
    case FactKind::kSide: {
      if (a < 0) return "no such room";
      Box2 bb = LevelBounds(l, l.rooms[a].level);
      Point c = Centroid(l.rooms[a].polygon);
      double fx = (c.x - bb.min_x) / bb.width(), fy = (c.y - bb.min_y) / bb.height();
      bool ok = (f.text == "north" && fy > 2.0 / 3) || (f.text == "south" && fy < 1.0 / 3) ||
                (f.text == "east" && fx > 2.0 / 3) || (f.text == "west" && fx < 1.0 / 3);
      return ok ? "" : "not on the " + f.text + " side";
    }
    case FactKind::kFurniture: {
      if (a < 0) return "no such room";
      int n = 0;
      for (const Room& r : l.rooms) n += r.category == l.rooms[a].category;
      return n == 1 ? "" : "the furnished room's category is not unique";
    }
  }
  return "unknown fact";
}

namespace {

std::string CheckFact(const Layout& l, const std::string& shape, const Fact& f) { return CheckDescriptionFact(l, shape, f); }

// The words the text must use for a fact (any one of them).
std::vector<std::string> Words(Category c) {
  switch (c) {
    case Category::kLivingRoom: return {"living room", "lounge"};
    case Category::kBedroom: return {"bedroom"};
    case Category::kKitchen: return {"kitchen"};
    case Category::kBathroom: return {"bathroom"};
    case Category::kDiningRoom: return {"dining room"};
    case Category::kChildrenRoom: return {"children's room", "kids' room"};
    case Category::kOffice: return {"office", "stud"};
    case Category::kMeetingRoom: return {"meeting room"};
    case Category::kUtilityRoom: return {"utility room"};
    default: return {"balcon"};
  }
}

const char* kNumbers[] = {"zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten"};

void CheckText(const std::string& text, const std::vector<Fact>& facts, const std::string& shape) {
  std::string t = Lower(text);
  INFO(text);
  CHECK(t.find("first floor") == std::string::npos);
  CHECK(t.find("  ") == std::string::npos);
  CHECK(t.find("..") == std::string::npos);
  for (const Fact& f : facts) {
    INFO(DescribeFact(f));
    switch (f.kind) {
      case FactKind::kFloors: {
        std::string digit = std::to_string(f.value), word = kNumbers[f.value];
        bool says = t.find(word) != std::string::npos || t.find(digit) != std::string::npos ||
                    (f.value == 1 && t.find("single") != std::string::npos);
        CHECK(says);
        break;
      }
      case FactKind::kShape: {
        std::string want = shape == "rectangle" ? "rectangular" : shape == "irregular" ? "irregular" : Lower(shape) + "-shaped";
        CHECK(t.find(want) != std::string::npos);
        break;
      }
      case FactKind::kCount:
      case FactKind::kCountOnLevel: {
        auto words = Words(f.category);
        bool says = std::any_of(words.begin(), words.end(), [&](const std::string& w) { return t.find(w) != std::string::npos; });
        CHECK(says);
        if (f.value > 1) {
          bool number = t.find(kNumbers[f.value]) != std::string::npos || t.find(std::to_string(f.value)) != std::string::npos;
          CHECK(number);
        }
        break;
      }
      case FactKind::kFurniture: CHECK(t.find(Lower(f.text)) != std::string::npos); break;
      case FactKind::kSide: CHECK(t.find(f.text + " side") != std::string::npos); break;
      case FactKind::kBalcony: CHECK(t.find("panoramic") != std::string::npos); break;
      case FactKind::kEnSuite: CHECK(t.find("own") != std::string::npos); break;
      case FactKind::kOpenLink: CHECK((t.find("open") != std::string::npos)); break;
      case FactKind::kDirectLink: CHECK(t.find("direct") != std::string::npos); break;
    }
  }
}

}  // namespace

TEST_CASE("every drafted fact holds on the layout and the text states it", "[describe]") {
  struct Case {
    const char* id;
    const char* shape;
  };
  std::set<FactKind> kinds_seen;
  std::set<int> styles_seen;
  for (Case c : {Case{"villa-000000", "rectangle"}, Case{"villa-000001", "L"}}) {
    Layout layout = test::FixtureLayout(c.id);
    REQUIRE(!layout.rooms.empty());
    std::set<std::string> texts;
    for (std::uint64_t seed = 0; seed < 150; ++seed) {
      Drafts d = DraftDescriptions(layout, c.shape, seed);
      REQUIRE(!d.coarse.empty());
      REQUIRE(!d.fine.empty());
      for (const auto* facts : {&d.coarse_facts, &d.fine_facts})
        for (const Fact& f : *facts) {
          INFO(c.id << " seed " << seed << ": " << DescribeFact(f));
          CHECK(CheckFact(layout, c.shape, f) == "");
          kinds_seen.insert(f.kind);
        }
      CheckText(d.coarse, d.coarse_facts, c.shape);
      CheckText(d.fine, d.fine_facts, c.shape);
      // The coarse one names floors, shape and rooms; the fine one more.
      CHECK(d.coarse_facts.size() >= 3);
      CHECK(d.fine_facts.size() > d.coarse_facts.size() - 1);
      styles_seen.insert(static_cast<int>(d.coarse_style));
      styles_seen.insert(static_cast<int>(d.fine_style));
      texts.insert(d.fine);
    }
    // Varied: many distinct wordings.
    CHECK(texts.size() > 100);
  }
  CHECK(styles_seen.size() == kDescriptionStyleCount);
  for (FactKind k : {FactKind::kFloors, FactKind::kShape, FactKind::kCount, FactKind::kCountOnLevel, FactKind::kOpenLink,
                     FactKind::kDirectLink, FactKind::kEnSuite, FactKind::kBalcony, FactKind::kSide, FactKind::kFurniture})
    CHECK(kinds_seen.count(k) == 1);
}

TEST_CASE("drafts are deterministic in layout, shape and seed", "[describe]") {
  Layout layout = test::FixtureLayout("villa-000001");
  Drafts a = DraftDescriptions(layout, "L", 42), b = DraftDescriptions(layout, "L", 42), c = DraftDescriptions(layout, "L", 43);
  CHECK(a.coarse == b.coarse);
  CHECK(a.fine == b.fine);
  CHECK((a.coarse != c.coarse || a.fine != c.fine));
}

TEST_CASE("the two-floor layout's fine facts cover its rooms per floor", "[describe]") {
  Layout layout = test::FixtureLayout("villa-000001");
  for (std::uint64_t seed = 0; seed < 40; ++seed) {
    Drafts d = DraftDescriptions(layout, "L", seed);
    // Every labelled category on every level (utility rooms may go unstated) has a count fact.
    for (const Room& r : layout.rooms) {
      if (r.category == Category::kUtilityRoom) continue;
      bool stated = std::any_of(d.fine_facts.begin(), d.fine_facts.end(), [&](const Fact& f) {
        return f.kind == FactKind::kCountOnLevel && f.category == r.category && f.level == r.level;
      });
      INFO("seed " << seed << " " << r.name() << ": " << d.fine);
      CHECK(stated);
    }
  }
}

TEST_CASE("a bathroom with a second way in is not called en-suite", "[describe]") {
  Layout layout = test::FixtureLayout("villa-000000");
  Element door;
  door.name = "bathroom0_dining0";
  door.kind = ElementKind::kDoor;
  door.shape = {{6, 6}, {6, 7}};
  door.level = 0;
  layout.doors.push_back(door);
  for (std::uint64_t seed = 0; seed < 60; ++seed) {
    Drafts d = DraftDescriptions(layout, "rectangle", seed);
    for (const Fact& f : d.fine_facts) {
      INFO("seed " << seed << ": " << DescribeFact(f));
      CHECK(f.kind != FactKind::kEnSuite);
      CHECK(CheckDescriptionFact(layout, "rectangle", f) == "");
    }
    CHECK(d.fine.find("own") == std::string::npos);
  }
}
