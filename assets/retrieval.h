#pragma once
// Retrieval: which asset to use for an object of a room's scene graph. Candidates (library records and
// procedural offers alike) are ranked by the cosine similarity of text embeddings (the query's text
// against each asset's name, category, tags), plus how well the asset's size fits the wanted size (or,
// more weakly, the category's usual sizes), plus a bonus for the exact category; hard requirements (a surface, a
// cavity, a placement) filter first. When the library has nothing of the wanted category, the result
// names the category's procedural generator to fall back to.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "assets/asset.h"
#include "assets/embedder.h"
#include "util/result.h"

namespace villa {

struct RetrievalQuery {
  std::string category;        // vocabulary name ("sofa"); empty: read from `text` (CategoryInPhrase)
  std::string text;            // free words ("dark leather couch"), may be empty
  std::string room_type;       // layout category ("living-room"); assets made for other rooms lose a little
  std::optional<Vec3> size;    // wanted size, m (w, d, h in the asset frame)
  bool needs_surface = false;  // must offer a support surface (something goes on top)
  bool needs_cavity = false;   // must offer a cavity (something goes inside)
  std::optional<Placement> placement;  // must be placed this way

  // The text that is embedded for the query: category words, free words, room words.
  std::string Text() const;
};

struct RetrievalOptions {
  int k = 5;                       // answers wanted, >= 1
  double similarity_weight = 1.0;  // weight of the cosine similarity in [-1, 1], >= 0
  double size_weight = 0.35;       // weight of the size fit in [0, 1] against the query's size, >= 0
  double range_weight = 0.15;      // the same against the category's usual sizes (no size asked), >= 0
  double category_weight = 0.25;   // bonus when the asset's category is the query's, >= 0
  double room_weight = 0.1;        // penalty when the asset names room types and not the query's, >= 0
  // Size fit: exp(-sum over axes of ln(asset/wanted)^2 / (2 ln(tolerance)^2)); a side off by the
  // tolerance factor alone scores 0.61. > 1. 1.25 is the largest scale the solver may apply (SCENE.md).
  double size_tolerance = 1.25;

  std::string Check() const;  // empty when usable
};

struct RankedAsset {
  // Into the retriever's candidates, or into `RetrievalResult::offered` for an offered asset.
  const AssetRecord* asset = nullptr;
  double score = 0.0;
  double similarity = 0.0;
  double size_fit = 0.0;
};

struct RetrievalResult {
  std::string category;               // the query's category (given or read from its text), may be empty
  std::vector<RankedAsset> ranked;    // best first, at most k
  // No library candidate of the query's category passed the filters: use this generator (category.h),
  // or nothing when the category has none. (Offered assets may still rank: they are that fallback.)
  bool category_missing = false;
  std::string fallback_generator;
  // Assets made for this query by the retriever's offer (procedural ones), ranked with the rest.
  std::shared_ptr<const std::vector<AssetRecord>> offered;
};

// Assets made on demand for one query: a procedural generator's asset for the query's category and size
// (assets/procedural.h), so that procedural assets compete in the same ranking as the library's.
using CandidateOffer = std::function<std::vector<AssetRecord>(const RetrievalQuery& query)>;

// The text embedded for an asset: "Couch. sofa. Blend Swap, Sofa. Living room".
std::string AssetText(const AssetRecord& asset);

// Size fit in [0, 1] of `size` against a wanted size, or against the category's usual range when no size
// is wanted (1 inside it); 1 when neither is known.
double SizeFit(const Vec3& size, const std::optional<Vec3>& wanted, const std::string& category, double tolerance);
struct CategoryInfo;
double SizeFitAgainst(const Vec3& size, const std::optional<Vec3>& wanted, const CategoryInfo* category, double tolerance);

class AssetRetriever {
 public:
  // Embeds every candidate once (a CachedEmbedder keeps them across runs). The candidates are copied.
  static Result<AssetRetriever> Build(std::vector<AssetRecord> candidates, std::shared_ptr<const Embedder> embedder);

  const std::vector<AssetRecord>& candidates() const { return *candidates_; }
  // Adds the offer's assets to every ranking (embedded per query; put the embedder behind a cache).
  void SetOffer(CandidateOffer offer) { offer_ = std::move(offer); }
  // Ranks the candidates for one query (embeds its text). Safe from several threads.
  Result<RetrievalResult> Rank(const RetrievalQuery& query, const RetrievalOptions& options = {}) const;

 private:
  struct SparseVector;
  std::shared_ptr<const std::vector<AssetRecord>> candidates_;
  std::shared_ptr<const std::vector<SparseVector>> vectors_;
  std::shared_ptr<const Embedder> embedder_;
  CandidateOffer offer_;
};

}  // namespace villa
