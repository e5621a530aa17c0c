#include "scene/acquire.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>

#include "assets/category.h"
#include "assets/embedder.h"
#include "assets/procedural.h"
#include "layout/geometry.h"
#include "scene/file_digest.h"
#include "scene/random.h"

namespace villa::scene {
namespace {

// m left between a child and the sides of its surface or cavity (the solver's child gap, both sides).
constexpr double kChildMargin = 0.01;
// m kept between a low object's top and the window sill above it (the solver's object gap).
constexpr double kSillClearance = 0.02;
// Objects up to this much (m) taller than what passes under a sill are meant to pass under it.
constexpr double kUnderSillReach = 0.1;

struct Extent {
  double x = 0, y = 0, z = 0;
};

// The usable box of each support surface (its polygon's bounding box, its clear height) and cavity.
std::vector<Extent> SurfaceExtents(const AssetRecord& a) {
  std::vector<Extent> out;
  for (const SupportSurface& s : a.support_surfaces) {
    const Box2 b = BoundingBox(s.polygon);
    out.push_back({b.max_x - b.min_x, b.max_y - b.min_y, s.clear_height});
  }
  return out;
}
std::vector<Extent> CavityExtents(const AssetRecord& a) {
  std::vector<Extent> out;
  for (const Cavity& c : a.cavities) out.push_back({c.max.x - c.min.x, c.max.y - c.min.y, c.max.z - c.min.z});
  return out;
}

bool FitsIn(const Vec3& size, const Extent& e) {
  return size.x + kChildMargin <= e.x && size.y + kChildMargin <= e.y && size.z + 0.5 * kChildMargin <= e.z;
}
bool FitsAny(const Vec3& size, const std::vector<Extent>& extents) {
  return std::any_of(extents.begin(), extents.end(), [&](const Extent& e) { return FitsIn(size, e); });
}

// The container a child's wanted size is cut to: the roomiest surface or cavity.
std::optional<Extent> Roomiest(const std::vector<Extent>& extents) {
  std::optional<Extent> best;
  for (const Extent& e : extents)
    if (!best || e.x * e.y * std::max(e.z, 0.01) > best->x * best->y * std::max(best->z, 0.01)) best = e;
  return best;
}

Placement PlacementFor(const SceneObject& o) {
  if (o.parent == kParentWall) return Placement::kWall;
  if (o.parent == kParentCeiling) return Placement::kCeiling;
  if (o.parent == kParentFloor) return Placement::kFloor;
  return Placement::kSurface;
}

// What the children of one object ask of its asset.
struct ChildNeeds {
  bool surface = false;  // something goes on top
  bool cavity = false;   // something goes inside
  // The smallest size of each child category (assets/category.h): an asset whose surfaces (cavities)
  // cannot hold these cannot hold the smallest generator-made child either.
  std::vector<Vec3> on_top_min;
  std::vector<Vec3> inside_min;
};

bool CanHold(const AssetRecord& a, const ChildNeeds& needs) {
  if (needs.surface && a.support_surfaces.empty()) return false;
  if (needs.cavity && a.cavities.empty()) return false;
  const std::vector<Extent> surfaces = SurfaceExtents(a), cavities = CavityExtents(a);
  for (const Vec3& s : needs.on_top_min)
    if (!FitsAny(s, surfaces)) return false;
  for (const Vec3& s : needs.inside_min)
    if (!FitsAny(s, cavities)) return false;
  return true;
}

std::string Cut(std::string text) {
  if (text.size() > 80) text = text.substr(0, 77) + "...";
  return text;
}

}  // namespace

std::string_view AcquireRuleName(AcquireRule rule) {
  switch (rule) {
    case AcquireRule::kLibrary: return "library";
    case AcquireRule::kRanked: return "ranked";
    case AcquireRule::kStructural: return "structural";
    case AcquireRule::kFallback: return "fallback";
    case AcquireRule::kProcedural: return "procedural";
  }
  return "procedural";
}

std::string AcquireOptions::Check() const {
  if (!style.empty()) {
    const auto& styles = ProceduralStyles();
    if (std::find(styles.begin(), styles.end(), style) == styles.end())
      return "style = \"" + Cut(style) + "\": must be modern, classic, rustic or scandinavian";
  }
  if (candidates < 1 || candidates > 100) return "candidates = " + std::to_string(candidates) + ": must be in [1, 100]";
  return retrieval.Check();
}

Result<std::shared_ptr<AssetAcquirer>> AssetAcquirer::Make(const AssetLibrary& library, AcquireOptions options,
                                                          uint64_t seed, std::string_view request_text) {
  if (std::string problem = options.Check(); !problem.empty()) return Error{"acquire options: " + problem};
  std::shared_ptr<AssetAcquirer> a(new AssetAcquirer());
  a->library_ = &library;
  a->seed_ = seed;
  if (!options.style.empty()) {
    a->style_ = options.style;
  } else {
    // The request's style word, else one of the four drawn from the seed (seed 0: modern).
    const std::string named = ProceduralStyleIn(request_text, "");
    const auto& styles = ProceduralStyles();
    a->style_ = !named.empty() ? named : styles[seed % styles.size()];
  }
  a->options_ = std::move(options);
  a->options_.retrieval.k = a->options_.candidates;
  if (!library.records().empty()) {
    std::shared_ptr<const Embedder> embedder = a->options_.embedder;
    if (!embedder) embedder = std::make_shared<LexicalEmbedder>();
    auto retriever = AssetRetriever::Build(library.records(), embedder);
    if (!retriever.ok()) return Error{"asset retrieval: " + retriever.error()};
    a->retriever_ = std::move(*retriever);
    // The procedural offer competing in every ranking is the asset rule 3 would fall back to: same
    // style and seed, so every procedural object of a category looks alike and instances share meshes.
    AssetAcquirer* self = a.get();
    a->retriever_->SetOffer([self](const RetrievalQuery& query) -> std::vector<AssetRecord> {
      if (query.category.empty() || !query.size) return {};
      auto made = self->Procedural(query.category, *query.size);
      if (!made.ok()) return {};
      return {**made};
    });
  }
  return a;
}

uint32_t AssetAcquirer::ProceduralSeed(std::string_view category) const {
  return static_cast<uint32_t>(SplitMix64(seed_ ^ NameHash(category)).Next() & 0xffffffffu);
}

Result<const AssetRecord*> AssetAcquirer::Procedural(std::string_view category, Vec3 size) const {
  auto id = ProceduralAssetId(category, size, style_, ProceduralSeed(category));
  if (!id.ok()) return Error{id.error()};
  {
    std::lock_guard lock(mutex_);
    if (auto it = made_.find(*id); it != made_.end()) return it->second.get();
  }
  auto made = MakeProceduralAsset(*id);
  if (!made.ok()) return Error{made.error()};
  std::lock_guard lock(mutex_);
  auto [it, added] = made_.emplace(*id, std::make_unique<AssetRecord>(std::move(made->record)));
  return it->second.get();
}

const AssetRecord* AssetAcquirer::Find(std::string_view id) const {
  {
    std::lock_guard lock(mutex_);
    if (auto it = made_.find(id); it != made_.end()) return it->second.get();
  }
  if (const AssetRecord* r = library_->Find(id)) return r;
  if (id.substr(0, 5) != "proc:") return nullptr;
  auto made = MakeProceduralAsset(id);
  if (!made.ok()) return nullptr;
  std::lock_guard lock(mutex_);
  auto [it, added] = made_.emplace(std::string(id), std::make_unique<AssetRecord>(std::move(made->record)));
  return it->second.get();
}

Result<RoomAssets> AssetAcquirer::Acquire(const RoomContext& room, std::vector<SceneObject>& objects) const {
  const auto start = std::chrono::steady_clock::now();
  const std::string room_type(CategoryName(room.category));
  std::map<std::string, int> index;
  for (size_t i = 0; i < objects.size(); ++i) index[objects[i].id] = static_cast<int>(i);

  // Children's needs, and each object's depth in the parent forest (parents are chosen first).
  std::vector<ChildNeeds> needs(objects.size());
  std::vector<int> depth(objects.size(), 0);
  for (size_t i = 0; i < objects.size(); ++i) {
    const SceneObject& o = objects[i];
    auto p = index.find(o.parent);
    if (p == index.end()) continue;
    const CategoryInfo* c = FindCategory(o.category);
    const Vec3 smallest = c ? c->size_min : Vec3{0.02, 0.02, 0.02};
    if (o.relation == Relation::kInside) {
      needs[p->second].cavity = true;
      needs[p->second].inside_min.push_back(smallest);
    } else {
      needs[p->second].surface = true;
      needs[p->second].on_top_min.push_back(smallest);
    }
    int d = 0;
    std::set<int> seen{static_cast<int>(i)};
    for (auto q = p; q != index.end() && seen.insert(q->second).second; q = index.find(objects[q->second].parent)) ++d;
    depth[i] = d;
  }
  std::vector<int> order(objects.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return depth[a] < depth[b]; });

  // The height that passes under the lowest window sill of the room (0 when it has no window).
  double lowest_sill = 0.0;
  for (const WallEdge& w : room.walls)
    for (const WallWindow& win : w.windows)
      if (!win.panoramic && (lowest_sill == 0.0 || win.sill < lowest_sill)) lowest_sill = win.sill;
  const double under_sill = lowest_sill > 0.0 ? lowest_sill - kSillClearance : 0.0;

  RoomAssets out;
  out.choices.resize(objects.size());
  // One asset per (category, parent, relation): the chairs round a table share a mesh.
  std::map<std::tuple<std::string, std::string, int>, int> group_first;
  std::set<std::string> distinct;
  for (int i : order) {
    SceneObject& o = objects[i];
    AcquiredAsset& choice = out.choices[i];
    choice.object = o.id;
    const auto group = std::make_tuple(o.category, o.parent, static_cast<int>(o.relation));
    if (auto g = group_first.find(group); g != group_first.end()) {
      choice = out.choices[g->second];
      choice.object = o.id;
    } else {
      group_first.emplace(group, i);
      // The wanted size: the plan's, cut to the parent's roomiest surface or cavity for a child.
      Vec3 wanted = o.size;
      std::vector<Extent> containers;
      if (auto p = index.find(o.parent); p != index.end()) {
        const AssetRecord* parent = Find(objects[p->second].asset);
        if (!parent) return Error{o.id + ": parent " + o.parent + " has no asset (a bug: parents are chosen first)"};
        containers = o.relation == Relation::kInside ? CavityExtents(*parent) : SurfaceExtents(*parent);
        if (auto box = Roomiest(containers)) {
          wanted.x = std::min(wanted.x, box->x - kChildMargin);
          wanted.y = std::min(wanted.y, box->y - kChildMargin);
          wanted.z = std::min(wanted.z, box->z - kChildMargin);
        }
      }
      const CategoryInfo* category = FindCategory(o.category);
      // Low furniture against a wall (counters, a dishwasher) is made to pass under the room's windows
      // when its category allows it: a counter as high as the sill cannot stand under the window.
      if (o.relation == Relation::kAgainstWall && category && under_sill > 0.0 && wanted.z > under_sill &&
          wanted.z < under_sill + kUnderSillReach && category->size_min.z <= under_sill)
        wanted.z = under_sill;
      const bool structural = options_.structural_procedural && category && category->has_cavity &&
                              (needs[i].surface || needs[i].cavity);
      const AssetRecord* chosen = nullptr;
      if (!retriever_ || structural) {
        auto made = Procedural(o.category, wanted);
        if (!made.ok()) return Error{o.id + ": " + made.error()};
        chosen = *made;
        choice.rule = structural && retriever_ ? AcquireRule::kStructural : AcquireRule::kProcedural;
        if (!retriever_ && structural) choice.rule = AcquireRule::kProcedural;
      } else {
        RetrievalQuery query;
        query.category = o.category;
        query.room_type = room_type;
        query.size = wanted;
        query.needs_surface = needs[i].surface;
        query.needs_cavity = needs[i].cavity;
        query.placement = PlacementFor(o);
        auto ranked = retriever_->Rank(query, options_.retrieval);
        if (!ranked.ok()) return Error{o.id + ": " + ranked.error()};
        int seen = 0, refused = 0;
        for (const RankedAsset& r : ranked->ranked) {
          ++seen;
          // Only the category asked for: a bowl never stands in for a fruit bowl's generator.
          if (r.asset->category != o.category) continue;
          if (!CanHold(*r.asset, needs[i])) { ++refused; continue; }
          if (!containers.empty() && !FitsAny(r.asset->size, containers)) { ++refused; continue; }
          const bool offered = r.asset->id.rfind("proc:", 0) == 0;
          // A rug is a decal: a library mat of a centimetre or two is a solid furniture would stand in.
          if (!offered && o.category == "rug" && r.asset->size.z > 1.5 * kRugThickness) { ++refused; continue; }
          chosen = offered ? Find(r.asset->id) : library_->Find(r.asset->id);
          if (!chosen) continue;
          choice.rule = offered ? AcquireRule::kRanked : AcquireRule::kLibrary;
          choice.score = r.score;
          break;
        }
        // The offer is the generator's asset: when no library record of the category passed, it is the fallback.
        if (chosen && choice.rule == AcquireRule::kRanked && ranked->category_missing) {
          choice.rule = AcquireRule::kFallback;
          choice.note = "the library has no " + o.category + " that passes the needs";
        }
        if (!chosen) {
          auto made = Procedural(o.category, wanted);
          if (!made.ok()) return Error{o.id + ": " + made.error()};
          chosen = *made;
          choice.rule = AcquireRule::kFallback;
          choice.note = ranked->category_missing ? "the library has no " + o.category + " that passes the needs"
                                                 : std::to_string(refused) + " of the " + o.category +
                                                       " candidates cannot hold their contents or fit their parent";
        }
      }
      choice.asset = chosen->id;
    }
    const AssetRecord* record = Find(choice.asset);
    if (!record) return Error{o.id + ": asset " + choice.asset + " vanished (a bug)"};
    o.asset = record->id;
    o.size = record->size;
    // V_pro needs S or C (SCENE.md); an asset without either only consumes.
    if (record->support_surfaces.empty() && record->cavities.empty()) o.affordances &= ~static_cast<unsigned>(kProvider);
    distinct.insert(record->id);
    ++out.summary.objects;
    if (choice.rule == AcquireRule::kLibrary) ++out.summary.library;
    else ++out.summary.procedural;
    if (choice.rule == AcquireRule::kFallback) ++out.summary.fallbacks;
  }
  out.summary.distinct_assets = static_cast<int>(distinct.size());
  out.summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

Result<FurnishingLibrary> OpenFurnishingLibrary(const std::filesystem::path& dir, bool procedural_only) {
  namespace fs = std::filesystem;
  FurnishingLibrary out;
  fs::path where = dir;
  if (where.empty() && !procedural_only) {
    where = DefaultLibraryDir();
    std::error_code ec;
    if (!fs::exists(where / kLibraryRecordsFile, ec)) {
      out.note = "no asset library at " + where.string() + " (run `villa assets import`): procedural assets only";
      where.clear();
    }
  }
  if (where.empty()) {
    if (out.note.empty()) out.note = "procedural assets only";
    out.library = std::make_shared<AssetLibrary>(AssetLibrary::FromRecords({}));
  } else {
    auto opened = AssetLibrary::Open(where);
    if (!opened.ok()) return Error{opened.error()};
    out.library = std::make_shared<AssetLibrary>(std::move(*opened));
    const fs::path records = where / kLibraryRecordsFile;
    auto digest = FileSha256(records);
    if (!digest.ok()) return Error{digest.error()};
    out.file = FileRef{fs::absolute(records).lexically_normal().string(), *digest};
  }
  out.library->SetProceduralMeshMaker(MakeProceduralMesh);
  return out;
}

}  // namespace villa::scene
