// The generator table, ids (parse, defaults, canonical form) and the asset record of a procedural asset.
#include <algorithm>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <sstream>

#include "assets/category_phrase.h"
#include "assets/procedural/generator.h"
#include "util/excerpt.h"

namespace villa {
namespace procedural {
namespace {

constexpr std::string_view kPrefix = "proc:";
constexpr double kMaxSeed = 4294967295.0;

struct Entry {
  GeneratorDef def;
  ProceduralGenerator listing;  // def's extras plus the standard parameters, sorted by name
};

ProceduralParam SizeParam(const std::string& name, const std::string& meaning, const std::vector<std::string>& cats,
                          double Vec3::*axis) {
  ProceduralParam p;
  p.name = name;
  p.meaning = meaning +
              " (m), within the category's usual range (the range here spans all the generator's"
              " categories); left out: the middle of it";
  p.min = 1e300;
  p.max = -1e300;
  for (const std::string& c : cats) {
    const CategoryInfo* info = FindCategory(c);
    assert(info && "a generator makes only categories of assets/category.cpp");
    p.min = std::min(p.min, info->size_min.*axis);
    p.max = std::max(p.max, info->size_max.*axis);
  }
  const CategoryInfo* first = FindCategory(cats.front());
  p.default_value = std::round((first->size_min.*axis + first->size_max.*axis) * 500.0) / 1000.0;
  p.automatic = true;
  return p;
}

ProceduralParam ChoiceParam(const std::string& name, const std::string& meaning, std::vector<std::string> choices) {
  ProceduralParam p;
  p.name = name;
  p.kind = ProceduralParam::Kind::kChoice;
  p.meaning = meaning;
  p.default_choice = choices.front();
  p.choices = std::move(choices);
  return p;
}

std::vector<Entry> MakeEntries() {
  std::vector<GeneratorDef> defs;
  for (auto* group : {StorageGenerators, TableGenerators, SeatingGenerators, FixtureGenerators, SmallGenerators})
    for (GeneratorDef& d : group()) defs.push_back(std::move(d));
  std::vector<Entry> entries;
  for (GeneratorDef& def : defs) {
    // A category a generator can make but this build's vocabulary lacks is left out (the vocabulary and the
    // generators grow on different branches); the tests check every category of the vocabulary is made.
    std::erase_if(def.categories, [](const std::string& c) { return FindCategory(c) == nullptr; });
    ProceduralGenerator g{def.name, def.description, def.categories, def.extra};
    if (def.categories.size() > 1) g.params.push_back(ChoiceParam("category", "what the asset is", def.categories));
    g.params.push_back(SizeParam("w", "width, along x", def.categories, &Vec3::x));
    g.params.push_back(SizeParam("d", "depth, along y (front at -y)", def.categories, &Vec3::y));
    g.params.push_back(SizeParam("h", "height, along z", def.categories, &Vec3::z));
    g.params.push_back(ChoiceParam("style", "colours, materials and details", ProceduralStyles()));
    ProceduralParam seed;
    seed.name = "seed";
    seed.kind = ProceduralParam::Kind::kInteger;
    seed.meaning = "varies colours and details";
    seed.max = kMaxSeed;
    g.params.push_back(seed);
    std::sort(g.params.begin(), g.params.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
    entries.push_back({std::move(def), std::move(g)});
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.def.name < b.def.name; });
  return entries;
}

const std::vector<Entry>& Entries() {
  static const std::vector<Entry> entries = MakeEntries();
  return entries;
}

const Entry* FindEntry(std::string_view name) {
  for (const Entry& e : Entries())
    if (e.def.name == name) return &e;
  return nullptr;
}

// Numbers in ids: at most 3 decimals, no trailing zeros ("0.45", "2", "1.2").
std::string FormatNumber(double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.3f", v);
  std::string s = buffer;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

std::string FormatRange(const ProceduralParam& p) {
  return "[" + FormatNumber(p.min) + ", " + FormatNumber(p.max) + "]";
}

std::string Join(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

// One value of an id: digits with at most 3 decimals, in range, whole for integers; words from the list.
Status ReadValue(const ProceduralParam& p, std::string_view text, const std::string& where, ParamValues* out) {
  const std::string key = p.name;
  const std::string shown = key + " = " + Excerpt(text);
  if (p.kind == ProceduralParam::Kind::kChoice) {
    if (std::find(p.choices.begin(), p.choices.end(), text) == p.choices.end())
      return Error{where + ": " + key + " = \"" + Excerpt(text) + "\" is not one of " + Join(p.choices)};
    out->words[key] = std::string(text);
    return {};
  }
  size_t dot = text.find('.');
  std::string_view whole = text.substr(0, dot);
  std::string_view fraction = dot == std::string_view::npos ? std::string_view() : text.substr(dot + 1);
  auto digits = [](std::string_view s) {
    return std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
  };
  if (whole.empty() || !digits(whole) || (dot != std::string_view::npos && (fraction.empty() || !digits(fraction))) ||
      whole.size() > 12)
    return Error{where + ": " + shown + " is not a number (digits, at most 3 decimals)"};
  if (fraction.size() > 3) return Error{where + ": " + shown + " has more than 3 decimals"};
  double value = std::stod(std::string(text));
  if (p.kind == ProceduralParam::Kind::kInteger && value != std::floor(value))
    return Error{where + ": " + shown + " must be a whole number"};
  if (value < p.min || value > p.max) return Error{where + ": " + shown + " is out of range " + FormatRange(p)};
  out->numbers[key] = value;
  return {};
}

// Parses `proc:<generator>?k=v&...` into the generator and the values given (defaults not yet applied).
Result<std::pair<const Entry*, ParamValues>> ParseId(std::string_view id) {
  const std::string where = Excerpt(id);
  if (id.substr(0, kPrefix.size()) != kPrefix) return Error{where + ": a procedural asset id starts with \"proc:\""};
  std::string_view rest = id.substr(kPrefix.size());
  size_t question = rest.find('?');
  std::string_view name = rest.substr(0, question);
  const Entry* entry = FindEntry(name);
  if (!entry) {
    std::vector<std::string> names;
    for (const Entry& e : Entries()) names.push_back(e.def.name);
    return Error{where + ": unknown generator \"" + Excerpt(name) + "\" (generators: " + Join(names) + ")"};
  }
  ParamValues values;
  if (question == std::string_view::npos) return std::make_pair(entry, values);
  std::string_view query = rest.substr(question + 1);
  for (size_t start = 0; start <= query.size();) {
    size_t amp = std::min(query.find('&', start), query.size());
    std::string_view pair = query.substr(start, amp - start);
    start = amp + 1;
    size_t eq = pair.find('=');
    if (eq == std::string_view::npos || eq == 0) return Error{where + ": \"" + Excerpt(pair) + "\" is not key=value"};
    std::string_view key = pair.substr(0, eq), text = pair.substr(eq + 1);
    auto param = std::find_if(entry->listing.params.begin(), entry->listing.params.end(),
                              [&](const ProceduralParam& p) { return p.name == key; });
    if (param == entry->listing.params.end()) {
      std::vector<std::string> keys;
      for (const ProceduralParam& p : entry->listing.params) keys.push_back(p.name);
      return Error{where + ": unknown key \"" + Excerpt(key) + "\" for generator " + entry->def.name +
                   " (keys: " + Join(keys) + ")"};
    }
    if (values.Has(key)) return Error{where + ": key \"" + std::string(key) + "\" given twice"};
    if (Status s = ReadValue(*param, text, where, &values); !s) return Error{s.error()};
  }
  return std::make_pair(entry, values);
}

// Defaults and automatic values, in a fixed order, so that the values (and the canonical id) depend only
// on what the id gave.
void Complete(const Entry& entry, ParamValues& values) {
  if (!values.words.count("category")) values.words["category"] = entry.def.categories.front();
  const CategoryInfo& category = *FindCategory(values.Word("category"));
  auto middle = [](double lo, double hi) { return std::round((lo + hi) * 500.0) / 1000.0; };
  SetIfMissing(values, "w", [&] { return middle(category.size_min.x, category.size_max.x); });
  SetIfMissing(values, "d", [&] { return middle(category.size_min.y, category.size_max.y); });
  SetIfMissing(values, "h", [&] { return middle(category.size_min.z, category.size_max.z); });
  if (!values.words.count("style")) values.words["style"] = ProceduralStyles().front();
  SetIfMissing(values, "seed", [] { return 0.0; });
  for (const ProceduralParam& p : entry.def.extra)
    if (!p.automatic) {
      if (p.kind == ProceduralParam::Kind::kChoice) {
        if (!values.words.count(p.name)) values.words[p.name] = p.default_choice;
      } else {
        SetIfMissing(values, p.name, [&] { return p.default_value; });
      }
    }
  if (entry.def.resolve) {
    Rng rng(MixSeed(static_cast<std::uint64_t>(values.Real("seed")), HashText(entry.def.name + "/resolve")));
    entry.def.resolve(values, category, rng);
  }
  for (const ProceduralParam& p : entry.def.extra) {
    // An automatic value is chosen inside the range; clamp guards the id's promise all the same.
    if (p.kind != ProceduralParam::Kind::kChoice)
      values.numbers[p.name] = std::clamp(values.Real(p.name), p.min, p.max);
  }
}

// w, d and h inside the category's own usual range (the listing's range is the union over the generator's
// categories: a 7 cm microwave is no microwave).
Status CheckCategorySize(std::string_view id, const ParamValues& values, const CategoryInfo& category) {
  const std::pair<const char*, double Vec3::*> axes[] = {{"w", &Vec3::x}, {"d", &Vec3::y}, {"h", &Vec3::z}};
  for (auto [key, axis] : axes) {
    const double v = values.Real(key), lo = category.size_min.*axis, hi = category.size_max.*axis;
    if (v < lo || v > hi)
      return Error{Excerpt(id) + ": " + key + " = " + FormatNumber(v) + " is out of range [" + FormatNumber(lo) + ", " +
                   FormatNumber(hi) + "] for category " + std::string(category.name)};
  }
  return {};
}

std::string CanonicalId(const Entry& entry, const ParamValues& values) {
  std::string id = std::string(kPrefix) + entry.def.name;
  char sep = '?';
  for (const ProceduralParam& p : entry.listing.params) {
    id += sep;
    sep = '&';
    id += p.name + "=";
    id += p.kind == ProceduralParam::Kind::kChoice ? values.Word(p.name) : FormatNumber(values.Real(p.name));
  }
  return id;
}

}  // namespace


namespace {

// What CheckSolid says of every piece, by vertex index (pieces share none) and in one sort rather than a
// map per piece: each directed edge used once and its reverse once (closed, consistently oriented), and
// each piece's signed volume > 0 (outward).
bool EveryPieceClosed(const TriangleMesh& mesh) {
  // An edge a->b as (min, max, a > b): closed and consistent means every undirected edge comes exactly
  // twice, once in each direction, i.e. sorted keys pair up as k, k + 1 with no third.
  std::vector<std::uint64_t> keys;
  keys.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const auto a = static_cast<std::uint64_t>(t[k]), b = static_cast<std::uint64_t>(t[(k + 1) % 3]);
      keys.push_back(std::min(a, b) << 33 | std::max(a, b) << 1 | (a > b ? 1u : 0u));
    }
  std::sort(keys.begin(), keys.end());
  for (size_t i = 0; i < keys.size(); i += 2)
    if (i + 1 == keys.size() || keys[i + 1] != (keys[i] | 1u) || (keys[i] & 1u) ||
        (i + 2 < keys.size() && keys[i + 2] >> 1 == keys[i] >> 1))
      return false;
  const std::vector<int> root = PieceRoots(mesh);
  std::vector<double> volume(mesh.vertices.size(), 0.0);
  std::vector<bool> used(mesh.vertices.size(), false);
  for (const auto& t : mesh.triangles) {
    volume[root[t[0]]] += Dot(mesh.vertices[t[0]], Cross(mesh.vertices[t[1]], mesh.vertices[t[2]])) / 6.0;
    used[root[t[0]]] = true;
  }
  for (size_t v = 0; v < volume.size(); ++v)
    if (used[v] && !(volume[v] > 0.0)) return false;
  return true;
}

std::string Title(std::string_view category) {
  std::string s(category);
  std::replace(s.begin(), s.end(), '-', ' ');
  if (!s.empty()) s[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(s[0])));
  return s;
}

}  // namespace
}  // namespace procedural

using procedural::Entries;
using procedural::Entry;

const std::vector<std::string>& ProceduralStyles() {
  static const std::vector<std::string> styles = {"modern", "classic", "rustic", "scandinavian"};
  return styles;
}

const std::vector<ProceduralGenerator>& ProceduralGenerators() {
  static const std::vector<ProceduralGenerator> list = [] {
    std::vector<ProceduralGenerator> out;
    for (const Entry& e : Entries()) out.push_back(e.listing);
    return out;
  }();
  return list;
}

const ProceduralGenerator* FindProceduralGenerator(std::string_view name) {
  for (const ProceduralGenerator& g : ProceduralGenerators())
    if (g.name == name) return &g;
  return nullptr;
}

Result<ProceduralAsset> MakeProceduralAsset(std::string_view id) {
  auto parsed = procedural::ParseId(id);
  if (!parsed) return Error{parsed.error()};
  const Entry& entry = *parsed->first;
  procedural::ParamValues& values = parsed->second;
  procedural::Complete(entry, values);
  const CategoryInfo& category = *FindCategory(values.Word("category"));
  if (Status s = procedural::CheckCategorySize(id, values, category); !s) return Error{s.error()};
  const std::string style = values.Word("style");
  const auto seed = static_cast<std::uint64_t>(values.Real("seed"));
  procedural::Gen gen{
      category,
      values,
      procedural::StylePalette(style),
      style,
      values.Real("w"),
      values.Real("d"),
      values.Real("h"),
      procedural::Rng(procedural::MixSeed(seed, procedural::HashText(entry.def.name + "/" + values.Word("category")))),
      {}};
  entry.def.build(gen);

  ProceduralAsset asset;
  asset.mesh = std::move(gen.out.mesh());
  const Box3 box = asset.mesh.Bounds();
  const Vec3 want_min{-procedural::Snap(gen.w / 2), -procedural::Snap(gen.d / 2), 0.0};
  const Vec3 want_max{procedural::Snap(gen.w / 2), procedural::Snap(gen.d / 2), gen.h};
  if (box.empty() || Norm(box.min - want_min) > 1e-9 || Norm(box.max - want_max) > 1e-9)
    return Error{Excerpt(id) + ": generator " + entry.def.name +
                 " built a mesh that is not its w x d x h box (a bug)"};

  AssetRecord& r = asset.record;
  r.id = procedural::CanonicalId(entry, values);
  r.name = procedural::Title(category.name) + " (" + style + ")";
  r.category = std::string(category.name);
  r.source.kind = "procedural";
  r.source.entry = entry.def.name;
  r.source.tags = {style};
  r.license = "CC0-1.0";
  r.creator = "villa procedural generators";
  r.size = box.max - box.min;
  r.placement = category.placement;
  r.affordances = category.affordances;
  r.support_surfaces = gen.out.surfaces();
  r.cavities = gen.out.cavities();
  r.interaction_zone = category.zone;
  r.mesh.file = "";
  r.mesh.triangles = asset.mesh.TriangleCount();
  r.mesh.watertight = std::all_of(asset.mesh.parts.begin(), asset.mesh.parts.end(),
                                  [](const AssetMeshPart& p) { return procedural::EveryPieceClosed(p.mesh); });
  r.mesh.manifold_edges = r.mesh.watertight ? 1.0 : 0.0;
  return asset;
}

std::vector<TriangleMesh> MeshPieces(const TriangleMesh& mesh) {
  const std::vector<int> root = PieceRoots(mesh);
  std::map<int, TriangleMesh> pieces;                // by root, so pieces come in a fixed order
  std::vector<int> local(mesh.vertices.size(), -1);  // a vertex's index in its piece
  for (const auto& t : mesh.triangles) {
    TriangleMesh& piece = pieces[root[t[0]]];
    std::array<int, 3> tri;
    for (int k = 0; k < 3; ++k) {
      if (local[t[k]] < 0) {
        local[t[k]] = static_cast<int>(piece.vertices.size());
        piece.vertices.push_back(mesh.vertices[t[k]]);
      }
      tri[k] = local[t[k]];
    }
    piece.triangles.push_back(tri);
  }
  std::vector<TriangleMesh> out;
  for (auto& [r, piece] : pieces) out.push_back(std::move(piece));
  return out;
}

Result<std::string> ProceduralAssetId(std::string_view category_name, Vec3 size, std::string_view style,
                                      std::uint32_t seed) {
  const CategoryInfo* category = FindCategory(category_name);
  if (!category) return Error{"unknown category \"" + Excerpt(category_name) + "\""};
  if (category->generator.empty())
    return Error{"category " + std::string(category_name) + " has no procedural generator"};
  const Entry* entry = procedural::FindEntry(category->generator);
  if (!entry || std::find(entry->def.categories.begin(), entry->def.categories.end(), category_name) ==
                    entry->def.categories.end())
    return Error{"category " + std::string(category_name) + " names generator \"" + std::string(category->generator) +
                 "\", which does not make it"};
  const auto& styles = ProceduralStyles();
  if (std::find(styles.begin(), styles.end(), style) == styles.end())
    return Error{"style \"" + Excerpt(style) + "\" is not one of " + procedural::Join(styles)};
  if (!std::isfinite(size.x) || !std::isfinite(size.y) || !std::isfinite(size.z))
    return Error{"size of a " + std::string(category_name) + " must be finite numbers (m)"};
  procedural::ParamValues values;
  if (entry->def.categories.size() > 1) values.words["category"] = std::string(category_name);
  auto fit = [](double v, double lo, double hi) {
    // Clamped, then to whole millimetres, then clamped again (the range ends are whole millimetres).
    return std::clamp(std::round(std::clamp(v, lo, hi) * 1000.0) / 1000.0, lo, hi);
  };
  values.numbers["w"] = fit(size.x, category->size_min.x, category->size_max.x);
  values.numbers["d"] = fit(size.y, category->size_min.y, category->size_max.y);
  values.numbers["h"] = fit(size.z, category->size_min.z, category->size_max.z);
  values.words["style"] = std::string(style);
  values.numbers["seed"] = seed;
  procedural::Complete(*entry, values);
  return procedural::CanonicalId(*entry, values);
}

Result<AssetMesh> MakeProceduralMesh(std::string_view id) {
  auto asset = MakeProceduralAsset(id);
  if (!asset) return Error{asset.error()};
  return std::move(asset->mesh);
}

std::string ProceduralStyleIn(std::string_view phrase, std::string_view fallback) {
  static const std::vector<std::pair<std::string, std::string>> words = {{"modern", "modern"},
                                                                         {"contemporary", "modern"},
                                                                         {"minimalist", "modern"},
                                                                         {"minimal", "modern"},
                                                                         {"industrial", "modern"},
                                                                         {"classic", "classic"},
                                                                         {"classical", "classic"},
                                                                         {"traditional", "classic"},
                                                                         {"antique", "classic"},
                                                                         {"victorian", "classic"},
                                                                         {"baroque", "classic"},
                                                                         {"rustic", "rustic"},
                                                                         {"farmhouse", "rustic"},
                                                                         {"country", "rustic"},
                                                                         {"cottage", "rustic"},
                                                                         {"cabin", "rustic"},
                                                                         {"scandinavian", "scandinavian"},
                                                                         {"scandi", "scandinavian"},
                                                                         {"nordic", "scandinavian"},
                                                                         {"danish", "scandinavian"}};
  // Whole words, case-insensitive; the first style word in the phrase wins.
  std::string lower;
  for (char c : phrase) lower += std::isalpha(static_cast<unsigned char>(c)) ? static_cast<char>(std::tolower(c)) : ' ';
  std::istringstream in(lower);
  for (std::string word; in >> word;)
    for (const auto& [w, style] : words)
      if (word == w) return style;
  return std::string(fallback);
}

std::vector<AssetRecord> ProceduralOffer(const RetrievalQuery& query) {
  const CategoryInfo* category = query.category.empty() ? CategoryInPhrase(query.text) : FindCategory(query.category);
  if (!category || category->generator.empty()) return {};
  const Vec3 size = query.size.value_or((category->size_min + category->size_max) * 0.5);
  const auto seed = static_cast<std::uint32_t>(procedural::HashText(query.Text()));
  auto id = ProceduralAssetId(category->name, size, ProceduralStyleIn(query.text), seed);
  if (!id) return {};
  auto asset = MakeProceduralAsset(*id);
  if (!asset) return {};
  return {std::move(asset->record)};
}

}  // namespace villa
