#include "finetune/layout_schema.h"

#include <regex>
#include <string>
#include <unordered_map>

#include "util/excerpt.h"

namespace villa {
namespace {

using Json = nlohmann::ordered_json;

// Canonical numbers (shape_codec FormatNumber): optional minus, no leading zeros, at most 2 decimals.
constexpr const char* kNumber = R"(-?(0|[1-9][0-9]*)(\.[0-9]{1,2})?)";

std::string PointPattern() { return std::string(R"(\()") + kNumber + ", " + kNumber + R"(\))"; }

std::string BoxPattern() {
  return std::string(R"(shapely\.box\()") + kNumber + ", " + kNumber + ", " + kNumber + ", " + kNumber + R"(\))";
}

std::string PolygonPattern() {
  const std::string p = PointPattern();
  return R"(shapely\.Polygon\(\[)" + p + "(, " + p + R"(){2,}\]\))";
}

std::string LinePattern() {
  const std::string p = PointPattern();
  return R"(shapely\.LineString\(\[)" + p + ", " + p + R"(\]\))";
}

std::string RoomNamePattern() {
  // Categories of FORMAT.md (the labelled ten; the alias and unlabelled "room" are input-only), level
  // 0..2 (at most 3 floors), index 0..5 (at most 6 rooms a floor).
  return "^(living-room|bedroom|kitchen|bathroom|dining-room|children-room|office|meeting-room|utility-room|"
         "balcony)_[0-2]/[0-5]$";
}

// Element names are free text in FORMAT.md; the writers use identifiers like "living0_kitchen0".
constexpr const char* kElementNamePattern = "^[A-Za-z0-9][A-Za-z0-9_./-]{0,63}$";

Json StringWithPattern(const std::string& anchored) { return Json{{"type", "string"}, {"pattern", anchored}}; }

Json LevelSchema(bool ground_only) {
  return Json{{"type", "integer"}, {"enum", ground_only ? Json::array({0}) : Json::array({0, 1, 2})}};
}

Json ElementSchema(bool window, bool ground_only) {
  Json properties = Json::object();
  properties["shape"] = StringWithPattern(std::string("^") + LinePattern() + "$");  // not "^" + ...: GCC 12 -Wrestrict
  if (window) properties["is_panoramic"] = Json{{"type", "integer"}, {"enum", Json::array({0, 1})}};
  properties["level"] = LevelSchema(ground_only);
  Json required = Json::array({"shape"});
  if (window) required.push_back("is_panoramic");
  required.push_back("level");
  return Json{{"type", "object"}, {"properties", properties}, {"required", required}, {"additionalProperties", false}};
}

Json NamedObjects(const std::string& name_pattern, Json element) {
  return Json{{"type", "object"},
              {"propertyNames", Json{{"pattern", name_pattern}}},
              {"additionalProperties", std::move(element)}};
}

Json BuildSchema() {
  Json room{{"type", "object"},
            {"properties", Json{{"shape", StringWithPattern("^(" + BoxPattern() + "|" + PolygonPattern() + ")$")}}},
            {"required", Json::array({"shape"})},
            {"additionalProperties", false}};
  Json properties = Json::object();
  properties["rooms"] = NamedObjects(RoomNamePattern(), room);
  properties["entrance"] = NamedObjects(kElementNamePattern, ElementSchema(false, true));
  properties["doors"] = NamedObjects(kElementNamePattern, ElementSchema(false, false));
  properties["opens"] = NamedObjects(kElementNamePattern, ElementSchema(false, false));
  properties["windows"] = NamedObjects(kElementNamePattern, ElementSchema(true, false));
  properties["interiors"] = NamedObjects(kElementNamePattern, ElementSchema(false, false));
  return Json{{"type", "object"},
              {"properties", properties},
              {"required", Json::array({"rooms", "entrance", "doors", "opens", "windows", "interiors"})},
              {"additionalProperties", false}};
}

// --- The interpreter of the keyword subset above. ---

std::string Quote(const std::string& key) { return "[\"" + Excerpt(key) + "\"]"; }

std::string Shown(const Json& value) { return Excerpt(value.dump(-1, ' ', false, Json::error_handler_t::replace)); }

const std::regex& CachedRegex(const std::string& pattern) {
  static thread_local std::unordered_map<std::string, std::regex> cache;
  auto it = cache.find(pattern);
  if (it == cache.end()) it = cache.emplace(pattern, std::regex(pattern, std::regex::ECMAScript)).first;
  return it->second;
}

bool MatchesPattern(const std::string& text, const std::string& pattern) {
  return std::regex_search(text, CachedRegex(pattern));
}

Status Match(const Json& schema, const Json& value, const std::string& path) {
  const std::string where = path.empty() ? "(root)" : path;
  if (schema.contains("type")) {
    const std::string type = schema["type"];
    const bool ok = (type == "object" && value.is_object()) || (type == "string" && value.is_string()) ||
                    (type == "integer" && value.is_number_integer());
    if (!ok) return Error{where + ": expected " + type + ", got " + Shown(value)};
  }
  if (schema.contains("enum")) {
    bool found = false;
    for (const auto& option : schema["enum"]) found = found || option == value;
    if (!found) return Error{where + ": " + Shown(value) + " is not one of " + schema["enum"].dump()};
  }
  if (schema.contains("pattern") && value.is_string()) {
    if (!MatchesPattern(value.get<std::string>(), schema["pattern"])) {
      return Error{where + ": " + Shown(value) + " does not match " + schema["pattern"].get<std::string>()};
    }
  }
  if (!value.is_object()) return Status::Ok();
  if (schema.contains("required")) {
    for (const auto& key : schema["required"]) {
      if (!value.contains(key.get<std::string>())) return Error{where + ": missing key \"" + key.get<std::string>() + "\""};
    }
  }
  for (const auto& [key, child] : value.items()) {
    const std::string child_path = path + Quote(key);
    if (schema.contains("propertyNames")) {
      const auto& names = schema["propertyNames"];
      if (names.contains("pattern") && !MatchesPattern(key, names["pattern"])) {
        return Error{child_path + ": name does not match " + names["pattern"].get<std::string>()};
      }
    }
    if (schema.contains("properties") && schema["properties"].contains(key)) {
      if (auto status = Match(schema["properties"][key], child, child_path); !status) return status;
    } else if (schema.contains("additionalProperties")) {
      const auto& extra = schema["additionalProperties"];
      if (extra.is_boolean()) {
        if (!extra.get<bool>()) return Error{child_path + ": unexpected key"};
      } else if (auto status = Match(extra, child, child_path); !status) {
        return status;
      }
    }
  }
  return Status::Ok();
}

}  // namespace

const nlohmann::ordered_json& LayoutJsonSchema() {
  static const Json schema = BuildSchema();
  return schema;
}

const nlohmann::ordered_json& LayoutResponseFormat() {
  static const Json format{
      {"type", "json_schema"},
      {"json_schema", Json{{"name", "villa_layout"}, {"strict", true}, {"schema", LayoutJsonSchema()}}}};
  return format;
}

Status MatchLayoutJsonSchema(const nlohmann::ordered_json& value) { return Match(LayoutJsonSchema(), value, ""); }

}  // namespace villa
