#include "assets/retrieval.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "assets/category.h"
#include "assets/category_phrase.h"

namespace villa {
namespace {

std::string Spaced(std::string text) {
  std::replace(text.begin(), text.end(), '-', ' ');
  return text;
}

double Norm(const Embedding& a) {
  double n = 0;
  for (float v : a) n += static_cast<double>(v) * v;
  return std::sqrt(n);
}

}  // namespace

// A candidate's vector by its nonzero entries: the lexical embedding has a few dozen of 1,024, and a
// ranking then reads kilobytes instead of megabytes; dense embeddings lose nothing but memory.
struct AssetRetriever::SparseVector {
  std::vector<std::uint32_t> index;
  std::vector<float> value;
  std::size_t dimensions = 0;
  double norm = 0.0;
  explicit SparseVector(const Embedding& v) : dimensions(v.size()), norm(Norm(v)) {
    for (std::size_t i = 0; i < v.size(); ++i)
      if (v[i] != 0.0f) {
        index.push_back(static_cast<std::uint32_t>(i));
        value.push_back(v[i]);
      }
  }
  // Cosine with a dense query of known norm (0 when either is zero or their lengths differ).
  double Cosine(const Embedding& query, double query_norm) const {
    if (query.size() != dimensions || norm == 0 || query_norm == 0) return 0.0;
    double dot = 0;
    for (std::size_t k = 0; k < index.size(); ++k) dot += static_cast<double>(value[k]) * query[index[k]];
    return dot / (norm * query_norm);
  }
};

namespace {

// ln(value / nearest end of [lo, hi]); 0 inside.
double LogOutside(double value, double lo, double hi) {
  if (value < lo) return std::log(value / lo);
  if (value > hi) return std::log(value / hi);
  return 0.0;
}

}  // namespace

std::string RetrievalQuery::Text() const {
  std::string out = Spaced(category);
  if (!text.empty()) out += (out.empty() ? "" : ": ") + text;
  if (!room_type.empty()) out += " (" + Spaced(room_type) + ")";
  return out;
}

std::string RetrievalOptions::Check() const {
  if (k < 1) return "k must be >= 1, got " + std::to_string(k);
  if (!(similarity_weight >= 0 && size_weight >= 0 && range_weight >= 0 && category_weight >= 0 && room_weight >= 0))
    return "weights must be >= 0";
  if (!(size_tolerance > 1)) return "size_tolerance must be > 1";
  return "";
}

std::string AssetText(const AssetRecord& a) {
  std::string out = a.name + ". " + Spaced(a.category) + ".";
  if (!a.source.tags.empty()) {
    out += " ";
    for (std::size_t i = 0; i < a.source.tags.size(); ++i) out += (i ? ", " : "") + a.source.tags[i];
    out += ".";
  }
  if (!a.source.sh3d_category.empty()) out += " " + a.source.sh3d_category + ".";
  return out;
}

double SizeFit(const Vec3& size, const std::optional<Vec3>& wanted, const std::string& category, double tolerance) {
  return SizeFitAgainst(size, wanted, FindCategory(category), tolerance);
}

double SizeFitAgainst(const Vec3& size, const std::optional<Vec3>& wanted, const CategoryInfo* c, double tolerance) {
  const double sigma = std::log(tolerance);
  const double got[3] = {size.x, size.y, size.z};
  double sum = 0;
  if (wanted) {
    const double want[3] = {wanted->x, wanted->y, wanted->z};
    for (int i = 0; i < 3; ++i)
      if (want[i] > 0 && got[i] > 0) sum += std::pow(std::log(got[i] / want[i]), 2);
  } else if (c) {
    const double lo[3] = {c->size_min.x, c->size_min.y, c->size_min.z};
    const double hi[3] = {c->size_max.x, c->size_max.y, c->size_max.z};
    for (int i = 0; i < 3; ++i)
      if (got[i] > 0 && lo[i] > 0) sum += std::pow(LogOutside(got[i], lo[i], hi[i]), 2);
  } else {
    return 1.0;
  }
  return std::exp(-sum / (2 * sigma * sigma));
}

Result<AssetRetriever> AssetRetriever::Build(std::vector<AssetRecord> candidates, std::shared_ptr<const Embedder> embedder) {
  std::vector<std::string> texts;
  texts.reserve(candidates.size());
  for (const AssetRecord& a : candidates) texts.push_back(AssetText(a));
  Result<std::vector<Embedding>> vectors = embedder->Embed(texts);
  if (!vectors.ok()) return Error{vectors.error()};
  AssetRetriever r;
  r.candidates_ = std::make_shared<const std::vector<AssetRecord>>(std::move(candidates));
  std::vector<SparseVector> sparse;
  sparse.reserve(vectors->size());
  for (const Embedding& v : *vectors) sparse.emplace_back(v);
  r.vectors_ = std::make_shared<const std::vector<SparseVector>>(std::move(sparse));
  r.embedder_ = std::move(embedder);
  return r;
}

Result<RetrievalResult> AssetRetriever::Rank(const RetrievalQuery& query_in, const RetrievalOptions& options) const {
  if (std::string problem = options.Check(); !problem.empty()) return Error{"retrieval options: " + problem};
  RetrievalQuery query = query_in;
  if (query.category.empty())
    if (const CategoryInfo* c = CategoryInPhrase(query.text)) query.category = std::string(c->name);
  RetrievalResult result;
  result.category = query.category;

  // The query's text and the offered assets' texts in one call to the embedder.
  auto offered = std::make_shared<std::vector<AssetRecord>>(offer_ ? offer_(query) : std::vector<AssetRecord>{});
  std::vector<std::string> texts{query.Text()};
  for (const AssetRecord& a : *offered) texts.push_back(AssetText(a));
  Result<std::vector<Embedding>> embedded = embedder_->Embed(texts);
  if (!embedded.ok()) return Error{embedded.error()};
  const Embedding& qv = (*embedded)[0];
  const double qn = Norm(qv);
  result.offered = offered;

  bool category_seen = false;
  const CategoryInfo* query_category = FindCategory(query.category);
  auto consider = [&](const AssetRecord& a, const SparseVector& v, bool from_library) {
    if (query.needs_surface && a.support_surfaces.empty()) return;
    if (query.needs_cavity && a.cavities.empty()) return;
    if (query.placement && a.placement != *query.placement) return;
    bool same_category = !query.category.empty() && a.category == query.category;
    if (from_library) category_seen = category_seen || same_category;
    RankedAsset r;
    r.asset = &a;
    r.similarity = v.Cosine(qv, qn);
    // Usual sizes of the query's category, or of the asset's own when the query names none.
    const CategoryInfo* usual = query.size ? nullptr : query.category.empty() ? FindCategory(a.category) : query_category;
    r.size_fit = SizeFitAgainst(a.size, query.size, usual, options.size_tolerance);
    bool other_room = !query.room_type.empty() && !a.room_types.empty() &&
                      std::find(a.room_types.begin(), a.room_types.end(), query.room_type) == a.room_types.end();
    r.score = options.similarity_weight * r.similarity + (query.size ? options.size_weight : options.range_weight) * r.size_fit +
              (same_category ? options.category_weight : 0.0) - (other_room ? options.room_weight : 0.0);
    result.ranked.push_back(r);
  };
  for (std::size_t i = 0; i < candidates_->size(); ++i) consider((*candidates_)[i], (*vectors_)[i], true);
  for (std::size_t i = 0; i < offered->size(); ++i) consider((*offered)[i], SparseVector((*embedded)[i + 1]), false);
  // Best first; ties by id so the order never depends on the candidates' order.
  std::size_t keep = std::min(result.ranked.size(), static_cast<std::size_t>(options.k));
  std::partial_sort(result.ranked.begin(), result.ranked.begin() + keep, result.ranked.end(),
                    [](const RankedAsset& x, const RankedAsset& y) {
                      return x.score != y.score ? x.score > y.score : x.asset->id < y.asset->id;
                    });
  result.ranked.resize(keep);
  if (!query.category.empty() && !category_seen) {
    result.category_missing = true;
    if (const CategoryInfo* c = FindCategory(query.category)) result.fallback_generator = std::string(c->generator);
  }
  return result;
}

}  // namespace villa
