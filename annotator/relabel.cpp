#include "annotator/relabel.h"

#include <algorithm>
#include <map>
#include <set>

#include "layout/geometry.h"
#include "layout/topology.h"

namespace villa::annotator {
namespace {

// A name not used by another element of the same kind (`self` is the element being renamed).
std::string UniqueName(const std::vector<Element>& elements, const Element* self, const std::string& base) {
  auto taken = [&](const std::string& name) {
    for (const Element& e : elements)
      if (&e != self && e.name == name) return true;
    return false;
  };
  if (!taken(base)) return base;
  for (int k = 2;; ++k) {
    std::string name = base + "_" + std::to_string(k);
    if (!taken(name)) return name;
  }
}

bool HasWindow(const Layout& layout, int room) {
  for (const Element& w : layout.windows)
    if (w.OnLevel(layout.rooms[room].level) && RingHoldsSegment(layout.rooms[room].polygon, w.shape, kOnWallTolerance)) return true;
  return false;
}

}  // namespace

std::string RoomToken(const Room& room) {
  std::string token = std::string(CategoryToken(room.category)) + std::to_string(room.level);
  if (room.index > 0) token.append(".").append(std::to_string(room.index));
  return token;
}

std::string SchemeElementName(const Layout& layout, const Element& element) {
  std::vector<int> holders = RoomsHolding(layout, element);
  std::string base;
  if (element.kind == ElementKind::kEntrance) return element.name;
  if (element.kind == ElementKind::kWindow) {
    if (holders.size() != 1) return "";
    base = RoomToken(layout.rooms[holders[0]]) + (element.panoramic ? "_pano" : "_window");
  } else {
    if (holders.size() != 2) return "";
    std::sort(holders.begin(), holders.end());
    base = RoomToken(layout.rooms[holders[0]]) + "_" + RoomToken(layout.rooms[holders[1]]);
    if (element.kind == ElementKind::kInterior) base = "wall_" + base;
  }
  const auto& elements = layout.elements(element.kind);
  return UniqueName(elements, &element, base);
}

std::vector<Rename> RenameElementsOf(Layout& layout, const std::vector<int>& rooms) {
  std::vector<Rename> renames;
  std::set<int> wanted(rooms.begin(), rooms.end());
  for (ElementKind kind : kAllElementKinds) {
    if (kind == ElementKind::kEntrance) continue;
    auto& elements = layout.elements(kind);
    for (Element& element : elements) {
      std::vector<int> holders = RoomsHolding(layout, element);
      bool touches = std::any_of(holders.begin(), holders.end(), [&](int r) { return wanted.count(r) > 0; });
      if (!touches) continue;
      std::string name = SchemeElementName(layout, element);
      if (!name.empty() && name != element.name) {
        renames.push_back({element.name, name});
        element.name = name;
      }
    }
  }
  return renames;
}

std::vector<Rename> RelabelRoom(Layout& layout, int room, Category category) {
  std::vector<Rename> renames;
  Room& target = layout.rooms[room];
  if (target.category == category) return renames;
  Category old_category = target.category;
  int level = target.level;

  std::vector<int> touched{room};
  std::string old_name = target.name();
  int fresh = 0;
  for (int i : layout.RoomsOnLevel(level))
    if (i != room && layout.rooms[i].category == category) fresh = std::max(fresh, layout.rooms[i].index + 1);
  target.category = category;
  target.index = fresh;
  renames.push_back({old_name, target.name()});

  // Close the gap among the old category's indices, keeping their order.
  std::vector<int> old_ones;
  for (int i : layout.RoomsOnLevel(level))
    if (layout.rooms[i].category == old_category) old_ones.push_back(i);
  std::sort(old_ones.begin(), old_ones.end(),
            [&](int a, int b) { return layout.rooms[a].index < layout.rooms[b].index; });
  for (int k = 0; k < static_cast<int>(old_ones.size()); ++k) {
    Room& r = layout.rooms[old_ones[k]];
    if (r.index == k) continue;
    std::string before = r.name();
    r.index = k;
    renames.push_back({before, r.name()});
    touched.push_back(old_ones[k]);
  }
  auto element_renames = RenameElementsOf(layout, touched);
  renames.insert(renames.end(), element_renames.begin(), element_renames.end());
  return renames;
}

int DraftLabels(Layout& layout) {
  int labelled = 0;
  auto connections = RoomConnections(layout);
  auto connected = [&](int a, int b) {
    for (const Connection& c : connections)
      if ((c.room_a == a && c.room_b == b) || (c.room_a == b && c.room_b == a)) return true;
    return false;
  };
  for (int level = 0; level < layout.LevelCount(); ++level) {
    std::vector<int> free;
    std::map<Category, int> present;
    for (int i : layout.RoomsOnLevel(level)) {
      if (layout.rooms[i].category == Category::kRoom)
        free.push_back(i);
      else
        ++present[layout.rooms[i].category];
    }
    if (free.empty()) continue;
    // Largest first; ties by index so the result is deterministic.
    std::stable_sort(free.begin(), free.end(), [&](int a, int b) {
      return Area(layout.rooms[a].polygon) > Area(layout.rooms[b].polygon) + 1e-9;
    });
    auto take = [&](Category category, auto&& accept) -> int {
      for (auto it = free.begin(); it != free.end(); ++it) {
        if (!accept(*it)) continue;
        int room = *it;
        free.erase(it);
        RelabelRoom(layout, room, category);
        ++present[category];
        ++labelled;
        return room;
      }
      return -1;
    };
    auto any = [](int) { return true; };
    auto windowed = [&](int r) { return HasWindow(layout, r); };
    if (level == 0) {
      int living = present[Category::kLivingRoom] ? -1 : take(Category::kLivingRoom, any);
      int kitchen = -1;
      if (!present[Category::kKitchen]) {
        kitchen = take(Category::kKitchen, [&](int r) { return windowed(r) && (living < 0 || connected(r, living)); });
        if (kitchen < 0) kitchen = take(Category::kKitchen, windowed);
      }
      if (!present[Category::kDiningRoom] && kitchen >= 0)
        take(Category::kDiningRoom, [&](int r) { return connected(r, kitchen); });
    }
    if (!present[Category::kBathroom] && !free.empty()) {
      // The smallest windowed room.
      for (auto it = free.rbegin(); it != free.rend(); ++it) {
        if (!windowed(*it)) continue;
        int room = *it;
        free.erase(std::next(it).base());
        RelabelRoom(layout, room, Category::kBathroom);
        ++labelled;
        break;
      }
    }
    const Category upper[] = {Category::kBedroom, Category::kChildrenRoom, Category::kOffice, Category::kBedroom,
                              Category::kMeetingRoom, Category::kBedroom};
    const Category ground[] = {Category::kOffice, Category::kBedroom, Category::kMeetingRoom, Category::kBedroom,
                               Category::kOffice, Category::kBedroom};
    const Category* order = level == 0 ? ground : upper;
    for (int k = 0; !free.empty(); k = (k + 1) % 6) take(order[k], any);
  }
  return labelled;
}

}  // namespace villa::annotator
