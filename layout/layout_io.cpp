#include "layout/layout_io.h"

#include <fstream>
#include <limits>
#include <set>

#include "layout/shape_codec.h"
#include "util/atomic_file.h"
#include "util/excerpt.h"
#include "util/json_read.h"

namespace villa {
namespace {

constexpr const char* kTopKeys[] = {"rooms", "entrance", "doors", "opens", "windows", "interiors"};

// A member of a named group in an error's JSON path: ["kitchen_0/0"], the name cut to an excerpt.
std::string Quote(std::string_view key) { return "[\"" + Excerpt(key) + "\"]"; }

std::string Prefix(std::string_view source) { return source.empty() ? std::string() : std::string(source) + ": "; }

// A JSON value as the file has it, cut to an excerpt (bytes that are not UTF-8 shown as U+FFFD).
std::string Shown(const Json& value) { return Excerpt(value.dump(-1, ' ', false, Json::error_handler_t::replace)); }

// Reads the element's "level": an integer >= 0, or absent (= every level).
Result<int> ReadLevel(const Json& element, const std::string& path) {
  auto it = element.find("level");
  if (it == element.end()) return kAllLevels;
  if (it->is_number_integer() && it->get<long long>() >= 0 && it->get<long long>() < 1000) return static_cast<int>(it->get<long long>());
  if (it->is_number_float()) {
    double v = it->get<double>();
    if (v >= 0 && v < 1000 && v == static_cast<double>(static_cast<int>(v))) return static_cast<int>(v);
  }
  return Error{path + ".level: expected an integer >= 0, got " + Shown(*it)};
}

// docs/RULES.md, "Reading": a missing "is_panoramic" is 0; a number equal to 0 or 1 (1.0 too, as "level"
// reads 1.0 as 1) or a JSON boolean is read; anything else is an error naming the value.
Result<bool> ReadPanoramic(const Json& element, const std::string& path) {
  auto it = element.find("is_panoramic");
  if (it == element.end()) return false;
  if (it->is_boolean()) return it->get<bool>();
  if (it->is_number() && (it->get<double>() == 0.0 || it->get<double>() == 1.0)) return it->get<double>() == 1.0;
  return Error{path + ".is_panoramic: expected 0 or 1, got " + Shown(*it)};
}

Status CheckKeys(const Json& object, const std::string& path, std::initializer_list<std::string_view> allowed) {
  for (auto it = object.begin(); it != object.end(); ++it) {
    bool ok = false;
    for (auto key : allowed) ok = ok || it.key() == key;
    if (!ok) {
      std::string list;
      for (auto key : allowed) list += (list.empty() ? "" : ", ") + std::string(key);
      return Error{path + ": unknown key \"" + Excerpt(it.key()) + "\" (expected " + list + ")"};
    }
  }
  return {};
}

Status ReadRooms(const Json& rooms, const std::string& prefix, Layout& layout) {
  if (!rooms.is_object()) return Error{prefix + "rooms: expected an object of named rooms, got " + Shown(rooms)};
  std::set<std::string> seen;
  for (auto it = rooms.begin(); it != rooms.end(); ++it) {
    std::string path = prefix + "rooms" + Quote(it.key());
    auto name = ParseRoomName(it.key());
    if (!name)
      return Error{path + ": bad room name \"" + Excerpt(it.key()) + "\" (expected category_L/i, e.g. kitchen_0/0, with category one of living-room, bedroom, kitchen, bathroom, dining-room, children-room, office, meeting-room, utility-room, balcony, room)"};
    if (!it->is_object()) return Error{path + ": expected an object {\"shape\": ...}, got " + Shown(*it)};
    if (auto s = CheckKeys(*it, path, {"shape"}); !s) return Error{s.error()};
    auto shape = it->find("shape");
    if (shape == it->end()) return Error{path + ": missing \"shape\""};
    if (!shape->is_string()) return Error{path + ".shape: expected a string, got " + Shown(*shape)};
    auto ring = ParsePolygonShape(shape->get<std::string>());
    if (!ring) return Error{path + ".shape: " + ring.error()};
    if (ring->size() > static_cast<std::size_t>(kMaxRingCorners))
      return Error{path + ".shape: " + std::to_string(ring->size()) + " corners; a room has at most " +
                   std::to_string(kMaxRingCorners) + " (docs/RULES.md)"};
    if (std::string problem = RoomExtentProblem(*ring); !problem.empty()) return Error{path + ".shape: " + problem};
    Room room{name->category, name->level, name->index, std::move(*ring)};
    if (!seen.insert(room.name()).second)
      return Error{path + ": duplicate room " + room.name() + " (staircase-room is an alias of utility-room)"};
    layout.rooms.push_back(std::move(room));
  }
  return {};
}

Status ReadElements(const Json& group, ElementKind kind, const std::string& prefix, Layout& layout) {
  std::string key(ElementKindKey(kind));
  if (!group.is_object()) return Error{prefix + key + ": expected an object of named elements, got " + Shown(group)};
  auto& out = layout.elements(kind);
  for (auto it = group.begin(); it != group.end(); ++it) {
    std::string path = prefix + key + Quote(it.key());
    if (!it->is_object()) return Error{path + ": expected an object {\"shape\": ..., \"level\": ...}, got " + Shown(*it)};
    Status keys = kind == ElementKind::kWindow ? CheckKeys(*it, path, {"shape", "level", "is_panoramic"})
                                               : CheckKeys(*it, path, {"shape", "level"});
    if (!keys) return Error{keys.error()};
    auto shape = it->find("shape");
    if (shape == it->end()) return Error{path + ": missing \"shape\""};
    if (!shape->is_string()) return Error{path + ".shape: expected a string, got " + Shown(*shape)};
    auto segment = ParseLineShape(shape->get<std::string>());
    if (!segment) return Error{path + ".shape: " + segment.error()};
    if (std::string problem = SegmentExtentProblem(*segment); !problem.empty()) return Error{path + ".shape: " + problem};
    auto level = ReadLevel(*it, path);
    if (!level) return Error{level.error()};
    if (kind == ElementKind::kEntrance && *level != 0 && *level != kAllLevels)
      return Error{path + ".level: the entrance is on level 0, got " + std::to_string(*level)};
    Element element;
    element.name = it.key();
    element.kind = kind;
    element.shape = *segment;
    element.level = *level;
    if (kind == ElementKind::kWindow) {
      auto panoramic = ReadPanoramic(*it, path);
      if (!panoramic) return Error{panoramic.error()};
      element.panoramic = *panoramic;
    }
    out.push_back(std::move(element));
  }
  return {};
}

Json ElementToJson(const Element& e) {
  Json j = Json::object();
  j["shape"] = FormatLineShape(e.shape);
  if (e.kind == ElementKind::kWindow) j["is_panoramic"] = e.panoramic ? 1 : 0;
  if (e.level != kAllLevels) j["level"] = e.level;
  return j;
}

}  // namespace

Result<Layout> LayoutFromJson(const Json& json, std::string_view source) {
  std::string prefix = Prefix(source);
  if (!json.is_object()) return Error{prefix + "expected a JSON object with the six layout keys, got " + Shown(json)};
  for (auto it = json.begin(); it != json.end(); ++it) {
    bool known = false;
    for (auto key : kTopKeys) known = known || it.key() == key;
    if (!known)
      return Error{prefix + "unknown key \"" + Excerpt(it.key()) + "\" (a layout has exactly rooms, entrance, doors, opens, windows, interiors)"};
  }
  for (auto key : kTopKeys)
    if (!json.contains(key)) return Error{prefix + "missing key \"" + key + "\" (a layout has exactly rooms, entrance, doors, opens, windows, interiors)"};
  // Absurd counts are refused before any shape is read (docs/RULES.md, "Extent").
  const Json& rooms = json.at("rooms");
  if (rooms.is_object() && rooms.size() > static_cast<std::size_t>(kMaxRooms))
    return Error{prefix + "rooms: " + std::to_string(rooms.size()) + " rooms; a layout has at most " +
                 std::to_string(kMaxRooms) + " (docs/RULES.md)"};
  std::size_t elements = 0;
  for (ElementKind kind : kAllElementKinds) {
    const Json& group = json.at(std::string(ElementKindKey(kind)));
    if (group.is_object()) elements += group.size();
  }
  if (elements > static_cast<std::size_t>(kMaxElements))
    return Error{prefix + std::to_string(elements) + " elements (entrance, doors, opens, windows, interiors); a layout has at most " +
                 std::to_string(kMaxElements) + " (docs/RULES.md)"};
  Layout layout;
  if (auto s = ReadRooms(rooms, prefix, layout); !s) return Error{s.error()};
  for (ElementKind kind : kAllElementKinds)
    if (auto s = ReadElements(json.at(std::string(ElementKindKey(kind))), kind, prefix, layout); !s) return Error{s.error()};
  return layout;
}

Result<Layout> ParseLayoutText(std::string_view text, std::string_view source) {
  Result<Json> json = ParseJson<Json>(text, source);
  if (!json) return Error{json.error()};
  return LayoutFromJson(*json, source);
}

Result<Layout> LoadLayout(const std::filesystem::path& path) {
  auto text = ReadFile(path);
  if (!text) return Error{text.error()};
  return ParseLayoutText(*text, path.string());
}

Json LayoutToJson(const Layout& layout) {
  Json out = Json::object();
  Json rooms = Json::object();
  for (const auto& room : layout.rooms) rooms[room.name()] = Json{{"shape", FormatPolygonShape(room.polygon)}};
  out["rooms"] = std::move(rooms);
  for (ElementKind kind : kAllElementKinds) {
    Json group = Json::object();
    for (const auto& e : layout.elements(kind)) group[e.name] = ElementToJson(e);
    out[std::string(ElementKindKey(kind))] = std::move(group);
  }
  return out;
}

std::string LayoutToString(const Layout& layout, int indent) {
  return indent < 0 ? LayoutToJson(layout).dump() : LayoutToJson(layout).dump(indent);
}

Status SaveLayout(const Layout& layout, const std::filesystem::path& path) {
  return WriteFileAtomic(path, LayoutToString(layout, 2) + "\n");
}

namespace {
constexpr std::size_t kMaxJsonlLine = std::size_t{64} << 20;
}  // namespace

Status ReadJsonl(const std::filesystem::path& path, const std::function<bool(const Json&, int)>& on_record,
                 const std::function<void(const std::string&)>& on_bad_line) {
  if (Status s = CheckReadable(path, std::numeric_limits<std::uintmax_t>::max()); !s) return s;
  std::ifstream in(path);
  if (!in) return Error{path.string() + ": cannot open"};
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.size() > kMaxJsonlLine)
      return Error{path.string() + ":" + std::to_string(number) + ": a line of " + std::to_string(line.size() >> 20) +
                   " MB, more than the 64 MB a record may be"};
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    Result<Json> record = ParseJson<Json>(line, path.string() + ":" + std::to_string(number));
    if (!record) {
      if (!on_bad_line) return Error{record.error()};
      on_bad_line(record.error());
      continue;
    }
    if (!on_record(*record, number)) break;
  }
  if (in.bad()) return Error{path.string() + ": read error"};
  return {};
}

Result<Layout> LayoutFromRecord(const Json& record, std::string_view source) {
  if (record.is_object() && record.contains("rooms")) return LayoutFromJson(record, source);
  if (record.is_object() && record.contains("layout")) {
    std::string where = std::string(source) + (source.empty() ? "layout" : ": layout");
    return LayoutFromJson(record.at("layout"), where);
  }
  return Error{Prefix(source) + "a record needs the layout keys or a \"layout\" key"};
}

}  // namespace villa
