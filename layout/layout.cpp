#include "layout/layout.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace villa {
namespace {

// Every word villa uses for a category, in one table: the format's name, the token of element names, the
// name a person reads and its short form.
struct CategoryEntry {
  Category category;
  std::string_view name;     // FORMAT.md
  std::string_view token;    // element names: "living0_kitchen0"
  std::string_view display;  // legends and labels
  std::string_view shorter;  // labels in small rooms, terminal cells
};

constexpr std::array<CategoryEntry, kCategoryCount> kCategories = {{
    {Category::kRoom, "room", "room", "Room", "Room"},
    {Category::kLivingRoom, "living-room", "living", "Living room", "Living"},
    {Category::kBedroom, "bedroom", "bedroom", "Bedroom", "Bed"},
    {Category::kKitchen, "kitchen", "kitchen", "Kitchen", "Kitchen"},
    {Category::kBathroom, "bathroom", "bathroom", "Bathroom", "Bath"},
    {Category::kDiningRoom, "dining-room", "dining", "Dining room", "Dining"},
    {Category::kChildrenRoom, "children-room", "children", "Children's room", "Child"},
    {Category::kOffice, "office", "office", "Office", "Office"},
    {Category::kMeetingRoom, "meeting-room", "meeting", "Meeting room", "Meeting"},
    {Category::kUtilityRoom, "utility-room", "utility", "Utility room", "Utility"},
    {Category::kBalcony, "balcony", "balcony", "Balcony", "Balcony"},
}};

const CategoryEntry& EntryOf(Category category) {
  for (const auto& entry : kCategories)
    if (entry.category == category) return entry;
  return kCategories[0];
}

// %g: the value as a person wrote it for ordinary sizes, with an exponent for absurd ones (1e+12, 1e-320).
std::string Shortest(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%g", value);
  return buffer;
}

std::optional<int> ParseNonNegative(std::string_view text) {
  if (text.empty() || (text.size() > 1 && text[0] == '0')) return std::nullopt;
  int value = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || value < 0) return std::nullopt;
  return value;
}

}  // namespace

std::string_view CategoryName(Category category) { return EntryOf(category).name; }
std::string_view CategoryToken(Category category) { return EntryOf(category).token; }
std::string_view CategoryDisplayName(Category category) { return EntryOf(category).display; }
std::string_view CategoryShortName(Category category) { return EntryOf(category).shorter; }

bool IsHabitable(Category c) {
  return c == Category::kLivingRoom || c == Category::kBedroom || c == Category::kChildrenRoom ||
         c == Category::kDiningRoom || c == Category::kOffice || c == Category::kMeetingRoom || c == Category::kKitchen;
}

std::optional<Category> ParseCategory(std::string_view name) {
  for (const auto& entry : kCategories)
    if (entry.name == name) return entry.category;
  if (name == "staircase-room") return Category::kUtilityRoom;
  return std::nullopt;
}

const std::vector<Category>& LabelledCategories() {
  static const std::vector<Category> categories = [] {
    std::vector<Category> out;
    for (const auto& entry : kCategories)
      if (entry.category != Category::kRoom) out.push_back(entry.category);
    return out;
  }();
  return categories;
}

std::optional<RoomName> ParseRoomName(std::string_view name) {
  auto underscore = name.rfind('_');
  if (underscore == std::string_view::npos) return std::nullopt;
  auto slash = name.find('/', underscore);
  if (slash == std::string_view::npos) return std::nullopt;
  auto category = ParseCategory(name.substr(0, underscore));
  auto level = ParseNonNegative(name.substr(underscore + 1, slash - underscore - 1));
  auto index = ParseNonNegative(name.substr(slash + 1));
  if (!category || !level || !index) return std::nullopt;
  return RoomName{*category, *level, *index};
}

std::string FormatRoomName(const RoomName& name) {
  return std::string(CategoryName(name.category)) + "_" + std::to_string(name.level) + "/" + std::to_string(name.index);
}

std::string_view ElementKindKey(ElementKind kind) {
  switch (kind) {
    case ElementKind::kEntrance: return "entrance";
    case ElementKind::kDoor: return "doors";
    case ElementKind::kOpen: return "opens";
    case ElementKind::kWindow: return "windows";
    case ElementKind::kInterior: return "interiors";
  }
  return "doors";
}

std::vector<Element>& Layout::elements(ElementKind kind) {
  switch (kind) {
    case ElementKind::kEntrance: return entrances;
    case ElementKind::kDoor: return doors;
    case ElementKind::kOpen: return opens;
    case ElementKind::kWindow: return windows;
    case ElementKind::kInterior: return interiors;
  }
  return doors;
}

const std::vector<Element>& Layout::elements(ElementKind kind) const {
  return const_cast<Layout*>(this)->elements(kind);
}

int Layout::LevelCount() const {
  int count = 0;
  for (const auto& room : rooms) count = std::max(count, room.level + 1);
  return count;
}

std::vector<int> Layout::RoomsOnLevel(int level) const {
  std::vector<int> out;
  for (int i = 0; i < static_cast<int>(rooms.size()); ++i)
    if (rooms[i].level == level) out.push_back(i);
  return out;
}

int Layout::FindRoom(std::string_view name) const {
  auto parsed = ParseRoomName(name);
  if (!parsed) return -1;
  for (int i = 0; i < static_cast<int>(rooms.size()); ++i) {
    const auto& r = rooms[i];
    if (r.category == parsed->category && r.level == parsed->level && r.index == parsed->index) return i;
  }
  return -1;
}

std::string PointExtentProblem(const Point& p) {
  for (const auto& [axis, value] : {std::pair{"x", p.x}, std::pair{"y", p.y}})
    if (!(std::abs(value) <= kMaxCoordinate))
      return std::string(axis) + " = " + Shortest(value) + " is outside the building extent (|x| and |y| at most " +
             Shortest(kMaxCoordinate) + " m)";
  return {};
}

std::string RoomExtentProblem(const Ring& ring) {
  if (ring.empty()) return {};
  for (const Point& p : ring)
    if (std::string problem = PointExtentProblem(p); !problem.empty()) return problem;
  double min_x = ring[0].x, max_x = ring[0].x, min_y = ring[0].y, max_y = ring[0].y;
  for (const Point& p : ring) {
    min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
    min_y = std::min(min_y, p.y), max_y = std::max(max_y, p.y);
  }
  struct Side {
    const char* axis;
    const char* adjective;  // "wide"
    const char* noun;       // "width"
    double from, to;
  };
  for (const Side& side : {Side{"x", "wide", "width", min_x, max_x}, Side{"y", "deep", "depth", min_y, max_y}}) {
    const double size = side.to - side.from;
    if (size >= kMinRoomSize) continue;
    if (size == 0) return std::string("zero ") + side.noun + " (every corner at " + side.axis + " = " + Shortest(side.from) + ")";
    return Shortest(size) + " m " + side.adjective + " (" + side.axis + " from " + Shortest(side.from) + " to " +
           Shortest(side.to) + "); a room is at least " + Shortest(kMinRoomSize) + " m wide and deep";
  }
  return {};
}

std::string SegmentExtentProblem(const Segment& segment) {
  if (std::string problem = PointExtentProblem(segment.a); !problem.empty()) return problem;
  return PointExtentProblem(segment.b);
}

double SignedArea(const Ring& ring) {
  double twice = 0.0;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point& p = ring[i];
    const Point& q = ring[(i + 1) % n];
    twice += p.x * q.y - q.x * p.y;
  }
  return 0.5 * twice;
}

double Area(const Ring& ring) { return std::abs(SignedArea(ring)); }

double Length(const Segment& s) { return std::hypot(s.b.x - s.a.x, s.b.y - s.a.y); }

}  // namespace villa
