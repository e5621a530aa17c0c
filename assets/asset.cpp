#include "assets/asset.h"

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "util/atomic_file.h"
#include "util/excerpt.h"
#include "util/json_read.h"

namespace villa {
namespace {

using ojson = nlohmann::ordered_json;
using json = nlohmann::json;

// Files hold at most 4 decimals (SCENE.md); -0 is written as 0.
double Round4(double v) {
  double r = std::round(v * 1e4) / 1e4;
  return r == 0.0 ? 0.0 : r;
}

// to_asset keeps 8 decimals: a cm -> m factor such as 0.0091336 loses up to 0.5 % at 4 (docs/SCENE.md).
// Entries below 1e-4 keep 4, so no number is ever written with an exponent.
double RoundMatrixEntry(double v) {
  if (std::abs(v) < 1e-4) return Round4(v);
  double r = std::round(v * 1e8) / 1e8;
  return r == 0.0 ? 0.0 : r;
}

// A strict reader over one JSON object: every access names its path; unknown keys are errors.
class Reader {
 public:
  Reader(const json& object, std::string where, std::string path)
      : object_(object), where_(std::move(where)), path_(std::move(path)) {}

  bool IsObject() const { return object_.is_object(); }
  std::string Fail(const std::string& key, const std::string& what) const {
    std::string at = path_.empty() ? key : (key.empty() ? path_ : path_ + "." + key);
    return where_ + ": " + at + ": " + what;
  }
  std::string Got(const json& value) const { return Excerpt(value.dump()); }

  const json* Find(const std::string& key) {
    seen_.insert(key);
    auto it = object_.find(key);
    return it == object_.end() ? nullptr : &*it;
  }
  const json* Need(const std::string& key, std::string* error) {
    const json* v = Find(key);
    if (!v && error->empty()) *error = Fail(key, "missing");
    return v;
  }
  bool String(const std::string& key, std::string* out, std::string* error, bool required = true) {
    const json* v = required ? Need(key, error) : Find(key);
    if (!v) return !required;
    if (!v->is_string()) return SetError(error, Fail(key, "expected a string, got " + Got(*v)));
    *out = v->get<std::string>();
    return true;
  }
  bool Number(const std::string& key, double* out, std::string* error, bool required = true) {
    const json* v = required ? Need(key, error) : Find(key);
    if (!v) return !required;
    if (!v->is_number() || !std::isfinite(v->get<double>()))
      return SetError(error, Fail(key, "expected a finite number, got " + Got(*v)));
    *out = v->get<double>();
    return true;
  }
  bool Integer(const std::string& key, int* out, std::string* error, bool required = true) {
    const json* v = required ? Need(key, error) : Find(key);
    if (!v) return !required;
    if (!v->is_number_integer()) return SetError(error, Fail(key, "expected an integer, got " + Got(*v)));
    *out = v->get<int>();
    return true;
  }
  bool Bool(const std::string& key, bool* out, std::string* error) {
    const json* v = Find(key);
    if (!v) return true;
    if (!v->is_boolean()) return SetError(error, Fail(key, "expected true or false, got " + Got(*v)));
    *out = v->get<bool>();
    return true;
  }
  bool Strings(const std::string& key, std::vector<std::string>* out, std::string* error, bool required) {
    const json* v = required ? Need(key, error) : Find(key);
    if (!v) return !required;
    if (!v->is_array()) return SetError(error, Fail(key, "expected an array of strings, got " + Got(*v)));
    out->clear();
    for (size_t i = 0; i < v->size(); ++i) {
      if (!(*v)[i].is_string())
        return SetError(error, Fail(key + "[" + std::to_string(i) + "]", "expected a string, got " + Got((*v)[i])));
      out->push_back((*v)[i].get<std::string>());
    }
    return true;
  }
  // Numbers of a fixed count ([x, y, z]).
  bool Numbers(const json& value, const std::string& key, size_t count, double* out, std::string* error) {
    if (!value.is_array() || value.size() != count)
      return SetError(error, Fail(key, "expected " + std::to_string(count) + " numbers, got " + Got(value)));
    for (size_t i = 0; i < count; ++i) {
      if (!value[i].is_number() || !std::isfinite(value[i].get<double>()))
        return SetError(error, Fail(key + "[" + std::to_string(i) + "]", "expected a finite number, got " +
                                                                             Got(value[i])));
      out[i] = value[i].get<double>();
    }
    return true;
  }
  // After all reads: any key not asked for is an error.
  bool NoUnknownKeys(std::string* error) const {
    for (auto it = object_.begin(); it != object_.end(); ++it)
      if (!seen_.count(it.key())) return SetError(error, Fail(it.key(), "unknown key"));
    return true;
  }
  std::string Sub(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  const std::string& where() const { return where_; }

 private:
  static bool SetError(std::string* error, std::string message) {
    if (error->empty()) *error = std::move(message);
    return false;
  }
  const json& object_;
  std::string where_;
  std::string path_;
  std::set<std::string> seen_;
};

ojson Vec(const Vec3& v) { return ojson::array({Round4(v.x), Round4(v.y), Round4(v.z)}); }

ojson RingJson(const Ring& ring) {
  ojson out = ojson::array();
  for (const Point& p : ring) out.push_back(ojson::array({Round4(p.x), Round4(p.y)}));
  return out;
}

bool ReadRing(Reader& r, const json& value, const std::string& key, Ring* ring, std::string* error) {
  if (!value.is_array() || value.size() < 3) {
    if (error->empty()) *error = r.Fail(key, "expected a polygon of at least 3 [x, y] points, got " + r.Got(value));
    return false;
  }
  ring->clear();
  for (size_t i = 0; i < value.size(); ++i) {
    double xy[2];
    if (!r.Numbers(value[i], key + "[" + std::to_string(i) + "]", 2, xy, error)) return false;
    ring->push_back({xy[0], xy[1]});
  }
  if (SignedArea(*ring) <= 0.0) {
    if (error->empty()) *error = r.Fail(key, "polygon must be counter-clockwise with positive area");
    return false;
  }
  return true;
}

}  // namespace

std::string_view PlacementName(Placement placement) {
  switch (placement) {
    case Placement::kFloor: return "floor";
    case Placement::kWall: return "wall";
    case Placement::kCeiling: return "ceiling";
    case Placement::kSurface: return "surface";
  }
  return "floor";
}

std::optional<Placement> ParsePlacement(std::string_view name) {
  for (Placement p : {Placement::kFloor, Placement::kWall, Placement::kCeiling, Placement::kSurface})
    if (PlacementName(p) == name) return p;
  return std::nullopt;
}

std::vector<std::string> AffordanceNames(unsigned affordances) {
  std::vector<std::string> out;
  if (affordances & kConsumer) out.push_back("V_con");
  if (affordances & kProvider) out.push_back("V_pro");
  if (affordances & kInteractor) out.push_back("V_int");
  return out;
}

std::optional<unsigned> ParseAffordances(const std::vector<std::string>& names) {
  unsigned out = 0;
  for (const std::string& n : names) {
    unsigned bit = n == "V_con" ? kConsumer : n == "V_pro" ? kProvider : n == "V_int" ? kInteractor : 0u;
    if (bit == 0 || (out & bit)) return std::nullopt;
    out |= bit;
  }
  return out;
}

bool HangsFromRail(std::string_view category) { return category == "hanging-clothes"; }

bool CavitySuits(const Cavity& c, std::string_view category) { return !HangsFromRail(category) || c.rail.has_value(); }

double CavityClearHeight(const Cavity& c, std::string_view category) {
  if (HangsFromRail(category) && c.rail) return *c.rail + kHookRise - c.min.z;
  return c.max.z - c.min.z;
}

bool AssetRecord::ClosedCellFloor(int surface) const {
  for (const Cavity& c : cavities)
    if (c.floor_surface == surface && c.open == "closed") return true;
  return false;
}

std::string AssetRecord::Credit() const {
  if (license.rfind("CC-BY", 0) != 0) return "";
  return (name.empty() ? id : name) + " by " + (creator.empty() ? "unknown" : creator) + " (" + license + ")";
}

nlohmann::ordered_json AssetToJson(const AssetRecord& a) {
  ojson j;
  j["id"] = a.id;
  j["name"] = a.name;
  j["category"] = a.category;
  ojson src;
  src["kind"] = a.source.kind;
  if (!a.source.package.empty()) src["package"] = a.source.package;
  if (!a.source.library.empty()) src["library"] = a.source.library;
  if (!a.source.entry.empty()) src["entry"] = a.source.entry;
  if (!a.source.sh3d_category.empty()) src["sh3d_category"] = a.source.sh3d_category;
  if (!a.source.tags.empty()) src["tags"] = a.source.tags;
  j["source"] = src;
  j["license"] = a.license;
  j["creator"] = a.creator;
  j["room_types"] = a.room_types;
  j["size"] = Vec(a.size);
  ojson m = ojson::array();
  for (const auto& row : a.to_asset) {
    ojson r = ojson::array();
    for (double v : row) r.push_back(RoundMatrixEntry(v));
    m.push_back(r);
  }
  j["to_asset"] = m;
  j["front_yaw_offset"] = a.front_yaw_offset;
  if (!a.front_decided_by.empty()) j["front_decided_by"] = a.front_decided_by;
  j["placement"] = PlacementName(a.placement);
  j["affordances"] = AffordanceNames(a.affordances);
  ojson surfaces = ojson::array();
  for (const SupportSurface& s : a.support_surfaces) {
    ojson o;
    o["z"] = Round4(s.z);
    o["polygon"] = RingJson(s.polygon);
    o["clear_height"] = Round4(s.clear_height);
    o["from"] = s.from;
    surfaces.push_back(o);
  }
  j["support_surfaces"] = surfaces;
  ojson cavities = ojson::array();
  for (const Cavity& c : a.cavities) {
    ojson o;
    o["min"] = Vec(c.min);
    o["max"] = Vec(c.max);
    o["open"] = c.open;
    o["floor_surface"] = c.floor_surface;
    if (c.rail) o["rail"] = Round4(*c.rail);
    cavities.push_back(o);
  }
  j["cavities"] = cavities;
  if (a.interaction_zone) {
    j["interaction_zone"] = {{"side", a.interaction_zone->side}, {"depth", Round4(a.interaction_zone->depth)}};
  }
  ojson mesh;
  mesh["file"] = a.mesh.file;
  mesh["triangles"] = a.mesh.triangles;
  mesh["watertight"] = a.mesh.watertight;
  mesh["manifold_edges"] = Round4(a.mesh.manifold_edges);
  if (!a.mesh.full_file.empty()) mesh["full"] = {{"file", a.mesh.full_file}, {"triangles", a.mesh.full_triangles}};
  j["mesh"] = mesh;
  return j;
}

Result<AssetRecord> AssetFromJson(const nlohmann::json& j, const std::string& where) {
  Reader r(j, where, "");
  if (!r.IsObject()) return Error{where + ": expected an asset record (a JSON object), got " + Excerpt(j.dump())};
  AssetRecord a;
  std::string error;
  r.String("id", &a.id, &error);
  if (error.empty() && a.id.empty()) error = r.Fail("id", "must not be empty");
  r.String("name", &a.name, &error);
  r.String("category", &a.category, &error);
  if (error.empty() && a.category.empty()) error = r.Fail("category", "must not be empty");
  if (const json* src = r.Need("source", &error)) {
    Reader s(*src, where, "source");
    if (!s.IsObject()) {
      if (error.empty()) error = r.Fail("source", "expected an object, got " + r.Got(*src));
    } else {
      s.String("kind", &a.source.kind, &error);
      s.String("package", &a.source.package, &error, false);
      s.String("library", &a.source.library, &error, false);
      s.String("entry", &a.source.entry, &error, false);
      s.String("sh3d_category", &a.source.sh3d_category, &error, false);
      s.Strings("tags", &a.source.tags, &error, false);
      s.NoUnknownKeys(&error);
    }
  }
  r.String("license", &a.license, &error);
  r.String("creator", &a.creator, &error);
  r.Strings("room_types", &a.room_types, &error, true);
  if (const json* v = r.Need("size", &error)) {
    double s[3];
    if (r.Numbers(*v, "size", 3, s, &error)) {
      a.size = {s[0], s[1], s[2]};
      if (!(s[0] > 0 && s[1] > 0 && s[2] > 0) && error.empty())
        error = r.Fail("size", "every side must be > 0 m, got " + r.Got(*v));
    }
  }
  if (const json* v = r.Need("to_asset", &error)) {
    if (!v->is_array() || v->size() != 3) {
      if (error.empty()) error = r.Fail("to_asset", "expected a 3x4 matrix (3 rows of 4 numbers), got " + r.Got(*v));
    } else {
      for (int i = 0; i < 3; ++i) r.Numbers((*v)[i], "to_asset[" + std::to_string(i) + "]", 4, a.to_asset[i].data(), &error);
    }
  }
  r.Integer("front_yaw_offset", &a.front_yaw_offset, &error);
  if (error.empty() && a.front_yaw_offset % 90 != 0)
    error = r.Fail("front_yaw_offset", "must be a multiple of 90, got " + std::to_string(a.front_yaw_offset));
  r.String("front_decided_by", &a.front_decided_by, &error, false);
  std::string placement;
  if (r.String("placement", &placement, &error) && error.empty()) {
    auto p = ParsePlacement(placement);
    if (!p) error = r.Fail("placement", "expected floor, wall, ceiling or surface, got \"" + Excerpt(placement) + "\"");
    else a.placement = *p;
  }
  std::vector<std::string> affordances;
  if (r.Strings("affordances", &affordances, &error, true) && error.empty()) {
    auto aff = ParseAffordances(affordances);
    if (!aff) error = r.Fail("affordances", "expected distinct V_con, V_pro, V_int, got " + r.Got(j["affordances"]));
    else a.affordances = *aff;
  }
  if (const json* v = r.Need("support_surfaces", &error)) {
    if (!v->is_array()) {
      if (error.empty()) error = r.Fail("support_surfaces", "expected an array, got " + r.Got(*v));
    } else {
      for (size_t i = 0; i < v->size() && error.empty(); ++i) {
        std::string key = "support_surfaces[" + std::to_string(i) + "]";
        Reader s((*v)[i], where, key);
        if (!s.IsObject()) { error = r.Fail(key, "expected an object, got " + r.Got((*v)[i])); break; }
        SupportSurface surface;
        s.Number("z", &surface.z, &error);
        if (const json* poly = s.Need("polygon", &error)) ReadRing(s, *poly, "polygon", &surface.polygon, &error);
        s.Number("clear_height", &surface.clear_height, &error);
        s.String("from", &surface.from, &error);
        if (error.empty() && surface.from != "drop_on_top" && surface.from != "mesh" && surface.from != "procedural")
          error = s.Fail("from", "expected drop_on_top, mesh or procedural, got \"" + Excerpt(surface.from) + "\"");
        if (error.empty() && surface.clear_height <= 0)
          error = s.Fail("clear_height", "must be > 0 m, got " + std::to_string(surface.clear_height));
        s.NoUnknownKeys(&error);
        a.support_surfaces.push_back(surface);
      }
    }
  }
  if (const json* v = r.Need("cavities", &error)) {
    if (!v->is_array()) {
      if (error.empty()) error = r.Fail("cavities", "expected an array, got " + r.Got(*v));
    } else {
      for (size_t i = 0; i < v->size() && error.empty(); ++i) {
        std::string key = "cavities[" + std::to_string(i) + "]";
        Reader c((*v)[i], where, key);
        if (!c.IsObject()) { error = r.Fail(key, "expected an object, got " + r.Got((*v)[i])); break; }
        Cavity cavity;
        double lo[3], hi[3];
        if (const json* m = c.Need("min", &error); m && c.Numbers(*m, "min", 3, lo, &error)) cavity.min = {lo[0], lo[1], lo[2]};
        if (const json* m = c.Need("max", &error); m && c.Numbers(*m, "max", 3, hi, &error)) cavity.max = {hi[0], hi[1], hi[2]};
        c.String("open", &cavity.open, &error);
        c.Integer("floor_surface", &cavity.floor_surface, &error);
        if (c.Find("rail")) {
          double rail = 0.0;
          if (c.Number("rail", &rail, &error) && error.empty() && !(rail > cavity.max.z && rail <= cavity.max.z + 0.1))
            error = c.Fail("rail", "must lie just above the cavity's top (" + std::to_string(cavity.max.z) +
                                       " to 0.1 m more), got " + std::to_string(rail));
          cavity.rail = rail;
        }
        if (error.empty() && !(cavity.min.x < cavity.max.x && cavity.min.y < cavity.max.y && cavity.min.z < cavity.max.z))
          error = c.Fail("", "min must be below max on every axis");
        if (error.empty() && cavity.open != "closed" && cavity.open != "-y" && cavity.open != "+y" &&
            cavity.open != "-x" && cavity.open != "+x" && cavity.open != "+z")
          error = c.Fail("open", "expected -y, +y, -x, +x, +z or closed, got \"" + Excerpt(cavity.open) + "\"");
        if (error.empty() && (cavity.floor_surface < -1 ||
                              cavity.floor_surface >= static_cast<int>(a.support_surfaces.size())))
          error = c.Fail("floor_surface", "names no support surface: " + std::to_string(cavity.floor_surface));
        c.NoUnknownKeys(&error);
        a.cavities.push_back(cavity);
      }
    }
  }
  if (const json* v = r.Find("interaction_zone")) {
    Reader z(*v, where, "interaction_zone");
    if (!z.IsObject()) {
      if (error.empty()) error = r.Fail("interaction_zone", "expected an object, got " + r.Got(*v));
    } else {
      InteractionZoneSpec spec;
      z.String("side", &spec.side, &error);
      z.Number("depth", &spec.depth, &error);
      if (error.empty() && spec.side != "front" && spec.side != "back" && spec.side != "left" &&
          spec.side != "right" && spec.side != "sides")
        error = z.Fail("side", "expected front, back, left, right or sides, got \"" + Excerpt(spec.side) + "\"");
      if (error.empty() && !(spec.depth > 0)) error = z.Fail("depth", "must be > 0 m");
      z.NoUnknownKeys(&error);
      a.interaction_zone = spec;
    }
  }
  if (const json* v = r.Need("mesh", &error)) {
    Reader m(*v, where, "mesh");
    if (!m.IsObject()) {
      if (error.empty()) error = r.Fail("mesh", "expected an object, got " + r.Got(*v));
    } else {
      m.String("file", &a.mesh.file, &error);
      m.Integer("triangles", &a.mesh.triangles, &error);
      m.Bool("watertight", &a.mesh.watertight, &error);
      m.Number("manifold_edges", &a.mesh.manifold_edges, &error, false);
      if (const json* f = m.Find("full")) {
        Reader full(*f, where, "mesh.full");
        if (!full.IsObject()) {
          if (error.empty()) error = m.Fail("full", "expected an object, got " + m.Got(*f));
        } else {
          full.String("file", &a.mesh.full_file, &error);
          full.Integer("triangles", &a.mesh.full_triangles, &error);
          full.NoUnknownKeys(&error);
          if (error.empty() && (a.mesh.full_file.empty() || a.mesh.full_triangles < a.mesh.triangles))
            error = m.Fail("full", "expected the source's mesh file and its triangles (at least the mesh's " +
                                       std::to_string(a.mesh.triangles) + ")");
        }
      }
      m.NoUnknownKeys(&error);
    }
  }
  r.NoUnknownKeys(&error);
  if (!error.empty()) return Error{error};
  return a;
}

Result<std::vector<AssetRecord>> ReadAssetRecords(const std::string& path) {
  // A folder, a FIFO or a device is no library (a folder once read as an empty one: furnishing went
  // procedural without a word).
  if (Status s = CheckReadable(path, std::uintmax_t{1} << 30); !s) return Error{s.error()};
  std::ifstream in(path);
  if (!in) return Error{path + ": cannot open for reading"};
  std::vector<AssetRecord> out;
  std::map<std::string, int> line_of;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::string where = path + ":" + std::to_string(number);
    Result<json> j = ParseJson<json>(line, where);
    if (!j) return Error{j.error()};
    auto asset = AssetFromJson(*j, where);
    if (!asset) return Error{asset.error()};
    auto [it, fresh] = line_of.emplace(asset->id, number);
    if (!fresh)
      return Error{where + ": id \"" + Excerpt(asset->id) + "\" already used on line " + std::to_string(it->second)};
    out.push_back(std::move(asset).value());
  }
  return out;
}

Status WriteAssetRecords(const std::string& path, const std::vector<AssetRecord>& assets) {
  std::string text;
  for (const AssetRecord& a : assets) text += AssetToJson(a).dump() + "\n";
  return WriteFileAtomic(path, text);
}

}  // namespace villa
