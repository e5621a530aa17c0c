#pragma once
// Asset acquisition: an asset record for every object of a planned room (paper Sec. 3.3, "asset
// retrieval"), chosen by rules that keep the solver's job possible:
//
//   1. Storage with things on or in it (bookcase, wardrobe, dresser, cabinet, counter ...: the categories
//      of assets/category.h with cavities) comes from its procedural generator: its shelves and
//      compartments are exact, which is what lets books sit inside a bookcase.
//   2. Everything else is ranked (assets/retrieval.h): the library's records and a procedural offer of the
//      same category at the wanted size compete on one score. Hard needs filter first: a parent of things
//      on top must have a support surface, of things inside a cavity; the placement must match the
//      relation (floor, wall, ceiling, surface). A child must fit its parent's surface or one of its
//      cavities at scale 1 (its footprint within the surface's box, its height under the clear height).
//   3. A category the library lacks, or with no candidate that passes, falls back to its generator.
//   4. No library (CI, a fresh machine before `villa assets import`): procedural assets only.
//
// Wanted sizes: the planner's target size (fitted to the room), for children also cut to the parent's
// chosen surface or cavity, so parents are chosen before their children. Objects of one category on one
// parent (the chairs round a table, the books in a bookcase) share one asset: one mesh, instanced.
// Deterministic: the same plan, library and seed give the same choices (ranking ties break by id;
// procedural seeds come from the seed and the category).
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "assets/asset.h"
#include "assets/asset_library.h"
#include "assets/retrieval.h"
#include "scene/room_context.h"
#include "scene/scene.h"
#include "util/result.h"

namespace villa::scene {

struct AcquireOptions {
  // Procedural style (assets/procedural.h: modern, classic, rustic, scandinavian); "" = the style the
  // request text names, else one drawn from the seed.
  std::string style;
  // Ranked answers looked at per object before falling back to the generator, [1, 100].
  int candidates = 12;
  // Rule 1 above; off, storage is ranked like everything else (it still needs a cavity for its contents).
  bool structural_procedural = true;
  // Retrieval weights (assets/retrieval.h); `k` is replaced by `candidates`.
  RetrievalOptions retrieval;
  // The text embeddings retrieval ranks by; null: the offline lexical embedder. An OpenAI-compatible
  // endpoint (assets/remote_embedder.h) goes behind a CachedEmbedder.
  std::shared_ptr<const Embedder> embedder;

  std::string Check() const;  // empty when usable
};

// Which rule chose an object's asset.
enum class AcquireRule {
  kLibrary,     // a library record won the ranking
  kRanked,      // the procedural offer won the ranking against the library
  kStructural,  // rule 1: storage with contents, from its generator
  kFallback,    // the library had no candidate of the category that passed the needs
  kProcedural,  // no library: procedural only
};
std::string_view AcquireRuleName(AcquireRule rule);  // "library", "ranked", "structural", "fallback", "procedural"

struct AcquiredAsset {
  std::string object;  // object id
  std::string asset;   // asset id
  AcquireRule rule = AcquireRule::kProcedural;
  double score = 0.0;  // retrieval score of the chosen asset (0 when not ranked)
  std::string note;    // why a fallback happened ("no bathtub in the library passes: needs a surface")
};

struct AcquireSummary {
  int objects = 0;
  int library = 0;      // AcquireRule::kLibrary
  int procedural = 0;   // every other rule
  int fallbacks = 0;    // AcquireRule::kFallback
  int distinct_assets = 0;
  double seconds = 0.0;
};

struct RoomAssets {
  std::vector<AcquiredAsset> choices;  // parallel to the objects given
  AcquireSummary summary;
};

// Chooses assets from one library (possibly empty) for planned rooms. Safe to use from several threads
// at once (rooms are furnished in parallel); the library must outlive it.
class AssetAcquirer {
 public:
  // `library` holds the records to rank (empty: procedural only); it must make `proc:` meshes
  // (AssetLibrary::SetProceduralMeshMaker(MakeProceduralMesh)). Embeds the library's records once.
  static Result<std::shared_ptr<AssetAcquirer>> Make(const AssetLibrary& library, AcquireOptions options,
                                                     uint64_t seed, std::string_view request_text);

  // Sets `asset` and `size` (the asset's size: scale 1) of every object of one room, parents before
  // children whatever their order. `objects` are the room's (a plan's objects).
  Result<RoomAssets> Acquire(const RoomContext& room, std::vector<SceneObject>& objects) const;

  // The record of any asset chosen so far, or of a library asset; nullptr when unknown. Procedural
  // records are made on demand and kept.
  const AssetRecord* Find(std::string_view id) const;
  // The style procedural assets are made in.
  const std::string& style() const { return style_; }
  const AssetLibrary& library() const { return *library_; }

 private:
  AssetAcquirer() = default;
  Result<const AssetRecord*> Procedural(std::string_view category, Vec3 size) const;
  uint32_t ProceduralSeed(std::string_view category) const;

  const AssetLibrary* library_ = nullptr;
  AcquireOptions options_;
  uint64_t seed_ = 0;
  std::string style_;
  std::optional<AssetRetriever> retriever_;  // empty library: none
  mutable std::mutex mutex_;
  mutable std::map<std::string, std::unique_ptr<AssetRecord>, std::less<>> made_;  // procedural records by id
};

// The library the furnishing stage ranks, ready for procedural ids too (its mesh maker set):
//   `dir` given: that library (an error, naming the folder, when it holds none);
//   else, unless `procedural_only`: the default library (asset_library.h) when one is installed;
//   else an empty one: procedural assets only, and `note` says so.
struct FurnishingLibrary {
  std::shared_ptr<AssetLibrary> library;
  std::optional<FileRef> file;  // its assets.jsonl by path and SHA-256 (the scene's `library`); none when empty
  std::string note;             // "no asset library installed (...): procedural assets only"
};
Result<FurnishingLibrary> OpenFurnishingLibrary(const std::filesystem::path& dir, bool procedural_only);

}  // namespace villa::scene
