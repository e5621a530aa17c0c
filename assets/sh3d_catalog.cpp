#include "assets/sh3d_catalog.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <set>
#include <sstream>

#include "assets/category.h"
#include "assets/category_phrase.h"
#include "util/excerpt.h"

namespace villa {
namespace {

bool Contains(const std::string& text, std::string_view part) { return text.find(part) != std::string::npos; }

std::string LicenseFromText(const std::string& text) {
  if (Contains(text, "Public domain") || Contains(text, "CC0") || Contains(text, "CC-0")) return "CC0-1.0";
  if (Contains(text, "Attribution 3.0 United States")) return "CC-BY-3.0-US";
  if (Contains(text, "Attribution 3.0")) return "CC-BY-3.0";
  return "";
}

// Debian's copyright file for sweethome3d-furniture, per library.
std::string LicenseFromArchive(const std::string& archive) {
  if (archive.rfind("BlendSwap-CC-0", 0) == 0) return "CC0-1.0";
  if (archive.rfind("KatorLegaz", 0) == 0 || archive.rfind("Reallusion", 0) == 0) return "CC-BY-3.0-US";
  if (archive.rfind("BlendSwap-CC-BY", 0) == 0 || archive.rfind("Scopia", 0) == 0) return "CC-BY-3.0";
  return "LicenseRef-unknown";
}

std::vector<std::string> SplitTags(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  std::string tag;
  while (std::getline(in, tag, ',')) {
    auto first = tag.find_first_not_of(' ');
    auto last = tag.find_last_not_of(' ');
    if (first != std::string::npos) out.push_back(tag.substr(first, last - first + 1));
  }
  return out;
}

bool ParseNumber(const std::string& text, double* out) {
  std::string_view s = text;
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), *out);
  return ec == std::errc() && end == s.data() + s.size() && !s.empty() && std::isfinite(*out);
}

const CategoryInfo* VocabularyCategory(const Sh3dPiece& piece) {
  // People, animals and vehicles are scenery, whatever their names say ("Seat Leon" is a car).
  if (piece.category == "Characters" || piece.category == "Vehicles") return nullptr;
  // Tables for games are not where one dines.
  static const std::set<std::string> kOther = {"pool table", "football table", "table tennis", "table tennis bat"};
  if (kOther.count(HeadPhrase(piece.name))) return nullptr;
  if (const CategoryInfo* c = CategoryInPhrase(piece.name)) return c;
  // Tags are left out here: they name a family more often than the thing ("Cooker" on a sandwich
  // maker, "Bed" on a hammock, "TV" on an antenna plug). Retrieval still reads them.
  return nullptr;
}

std::vector<std::string> RoomTypesOf(const std::string& sh3d_category) {
  if (sh3d_category == "Living room") return {"living-room"};
  if (sh3d_category == "Bedroom") return {"bedroom", "children-room"};
  if (sh3d_category == "Kitchen") return {"kitchen", "dining-room"};
  if (sh3d_category == "Bathroom") return {"bathroom"};
  if (sh3d_category == "Office") return {"office", "meeting-room"};
  if (sh3d_category == "Exterior") return {"balcony"};
  return {};
}

}  // namespace

std::string CategorySlug(const std::string& text) {
  std::string out;
  bool dash = false;
  for (unsigned char c : text) {
    if (std::isalnum(c) && c < 0x80) {
      if (dash && !out.empty()) out.push_back('-');
      dash = false;
      out.push_back(static_cast<char>(std::tolower(c)));
    } else if (c != '\'') {
      dash = true;
    }
  }
  return out;
}

Sh3dCatalog ReadSh3dCatalog(const JavaProperties& p, const std::string& archive_name, const std::string& where) {
  Sh3dCatalog catalog;
  auto get = [&](const std::string& key) -> const std::string* {
    auto it = p.find(key);
    return it == p.end() ? nullptr : &it->second;
  };
  if (const std::string* id = get("id")) catalog.library_id = *id;
  const std::string* license_text = get("license");
  catalog.license = license_text ? LicenseFromText(*license_text) : "";
  if (catalog.license.empty()) catalog.license = LicenseFromArchive(archive_name);

  // Pieces are numbered from 1 without gaps in SH3D's own catalogs; take every id#N there is, in order.
  std::set<int> indices;
  for (const auto& [key, value] : p) {
    if (key.rfind("id#", 0) != 0) continue;
    int n = 0;
    auto [end, ec] = std::from_chars(key.data() + 3, key.data() + key.size(), n);
    if (ec == std::errc() && end == key.data() + key.size() && n > 0) indices.insert(n);
  }
  for (int n : indices) {
    const std::string suffix = "#" + std::to_string(n);
    std::string problem;
    auto text = [&](const std::string& key) -> std::string {
      const std::string* v = get(key + suffix);
      return v ? *v : std::string();
    };
    auto number = [&](const std::string& key, bool required, bool positive) -> std::optional<double> {
      const std::string* v = get(key + suffix);
      if (!v) {
        if (required && problem.empty()) problem = where + ": " + key + suffix + ": missing";
        return std::nullopt;
      }
      double value = 0;
      // Issue 33: within 100 m either way (a width of 1e308 cm once became "size": [null, ...] in the library).
      constexpr double kMaxCm = 10000.0;
      if (!ParseNumber(*v, &value) || !std::isfinite(value) || (positive && value <= 0) || std::abs(value) > kMaxCm) {
        if (problem.empty())
          problem = where + ": " + key + suffix + ": expected a number" + (positive ? " of cm in (0, 10000]" : " of cm within 10000") +
                    ", got \"" + Excerpt(*v) + "\"";
        return std::nullopt;
      }
      return value;
    };
    Sh3dPiece piece;
    piece.index = n;
    piece.id = text("id");
    piece.category = text("category");
    piece.tags = SplitTags(text("tags"));
    piece.creator = text("creator");
    piece.model = text("model");
    while (!piece.model.empty() && piece.model.front() == '/') piece.model.erase(0, 1);
    piece.name = text("name");
    if (piece.name.empty()) piece.name = piece.id.substr(piece.id.find('#') + 1);
    piece.width = number("width", true, true).value_or(0);
    piece.depth = number("depth", true, true).value_or(0);
    piece.height = number("height", true, true).value_or(0);
    piece.elevation = number("elevation", false, false).value_or(0);
    piece.drop_on_top = number("dropOnTopElevation", false, false);
    piece.door_or_window = text("doorOrWindow") == "true";
    piece.staircase = get("staircaseCutOutShape" + suffix) != nullptr;
    if (const std::string* rotation = get("modelRotation" + suffix)) {
      std::istringstream in(*rotation);
      std::array<double, 9> m{};
      std::string token;
      int count = 0;
      bool ok = true;
      while (in >> token) {
        if (count < 9 && !ParseNumber(token, &m[count])) ok = false;
        ++count;
      }
      if (!ok || count != 9) {
        if (problem.empty()) problem = where + ": modelRotation" + suffix + ": expected 9 numbers, got \"" + Excerpt(*rotation) + "\"";
      } else {
        piece.model_rotation = m;
      }
    }
    if (piece.model.empty() && problem.empty()) problem = where + ": model" + suffix + ": missing";
    if (!problem.empty()) {
      catalog.problems.push_back(problem);
      continue;
    }
    catalog.pieces.push_back(std::move(piece));
  }
  return catalog;
}

Sh3dMapping MapSh3dPiece(const Sh3dPiece& piece) {
  Sh3dMapping m;
  const CategoryInfo* info = VocabularyCategory(piece);
  const double w = piece.width / 100, d = piece.depth / 100, h = piece.height / 100;
  const double elevation = piece.elevation / 100;
  const bool light = piece.category == "Lights";

  // Where it goes. SH3D's elevation says "hung": from the ceiling when it reaches SH3D's default wall
  // height (2.5 m, with a 5 cm margin), on a wall otherwise, unless it is a small thing hung inside
  // furniture (clothes on a rail: deeper than a wall item).
  if (elevation > 0) {
    bool small_thing = info && info->placement == Placement::kSurface;
    if (elevation + h >= 2.45 && (!small_thing || light)) m.placement = Placement::kCeiling;
    else if (small_thing && d > 0.15) m.placement = Placement::kSurface;
    else m.placement = Placement::kWall;
  } else if (info) {
    m.placement = info->placement;
  } else {
    m.placement = std::max(w, d) <= 0.4 && h <= 0.45 ? Placement::kSurface : Placement::kFloor;
  }

  // The same word names different things by where they hang and how tall they are.
  auto is = [&](std::string_view name) { return info && info->name == name; };
  auto to = [&](std::string_view name) { info = FindCategory(name); };
  bool lamp = is("table-lamp") || is("floor-lamp") || is("ceiling-lamp") || is("wall-lamp");
  if (m.placement == Placement::kCeiling && (lamp || light)) to("ceiling-lamp");
  else if (m.placement == Placement::kWall && (lamp || (light && !info))) to("wall-lamp");
  else if (m.placement == Placement::kWall && (is("cabinet") || is("glass-cabinet") || is("counter"))) to("upper-cabinet");
  else if (is("table-lamp") && h > 1.0) { to("floor-lamp"); m.placement = Placement::kFloor; }

  m.in_vocabulary = info != nullptr;
  if (info) {
    m.category = std::string(info->name);
  } else {
    m.category = CategorySlug(HeadPhrase(piece.name));
    if (m.category.empty()) m.category = CategorySlug(piece.name);
    if (m.category.empty()) m.category = "object";
  }
  m.room_types = RoomTypesOf(piece.category);
  return m;
}

}  // namespace villa
