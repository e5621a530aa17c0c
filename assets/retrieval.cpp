#include "assets/retrieval.h"

#include <algorithm>
#include <cmath>

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

// Cosine of two vectors whose norms are known (0 when either is zero or their lengths differ).
double Cosine(const Embedding& a, double norm_a, const Embedding& b, double norm_b) {
  if (a.size() != b.size() || norm_a == 0 || norm_b == 0) return 0.0;
  // Eight running sums, added in a fixed order: the compiler may vectorise them, and the result is the
  // same on every machine (no reassociation is left to -ffast-math).
  float sum[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  std::size_t i = 0;
  for (; i + 8 <= a.size(); i += 8)
    for (int k = 0; k < 8; ++k) sum[k] += a[i + k] * b[i + k];
  for (; i < a.size(); ++i) sum[0] += a[i] * b[i];
  double dot = 0;
  for (float s : sum) dot += s;
  return dot / (norm_a * norm_b);
}

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
  const double sigma = std::log(tolerance);
  const double got[3] = {size.x, size.y, size.z};
  double sum = 0;
  if (wanted) {
    const double want[3] = {wanted->x, wanted->y, wanted->z};
    for (int i = 0; i < 3; ++i)
      if (want[i] > 0 && got[i] > 0) sum += std::pow(std::log(got[i] / want[i]), 2);
  } else if (const CategoryInfo* c = FindCategory(category)) {
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
  std::vector<double> norms;
  for (const Embedding& v : *vectors) norms.push_back(Norm(v));
  r.norms_ = std::make_shared<const std::vector<double>>(std::move(norms));
  r.vectors_ = std::make_shared<const std::vector<Embedding>>(std::move(*vectors));
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
  auto consider = [&](const AssetRecord& a, const Embedding& v, double norm, bool from_library) {
    if (query.needs_surface && a.support_surfaces.empty()) return;
    if (query.needs_cavity && a.cavities.empty()) return;
    if (query.placement && a.placement != *query.placement) return;
    bool same_category = !query.category.empty() && a.category == query.category;
    if (from_library) category_seen = category_seen || same_category;
    RankedAsset r;
    r.asset = &a;
    r.similarity = Cosine(qv, qn, v, norm);
    r.size_fit = SizeFit(a.size, query.size, query.category.empty() ? a.category : query.category, options.size_tolerance);
    bool other_room = !query.room_type.empty() && !a.room_types.empty() &&
                      std::find(a.room_types.begin(), a.room_types.end(), query.room_type) == a.room_types.end();
    r.score = options.similarity_weight * r.similarity + (query.size ? options.size_weight : options.range_weight) * r.size_fit +
              (same_category ? options.category_weight : 0.0) - (other_room ? options.room_weight : 0.0);
    result.ranked.push_back(r);
  };
  for (std::size_t i = 0; i < candidates_->size(); ++i) consider((*candidates_)[i], (*vectors_)[i], (*norms_)[i], true);
  for (std::size_t i = 0; i < offered->size(); ++i) consider((*offered)[i], (*embedded)[i + 1], Norm((*embedded)[i + 1]), false);
  // Best first; ties by id so the order never depends on the candidates' order.
  std::sort(result.ranked.begin(), result.ranked.end(), [](const RankedAsset& x, const RankedAsset& y) {
    return x.score != y.score ? x.score > y.score : x.asset->id < y.asset->id;
  });
  if (result.ranked.size() > static_cast<std::size_t>(options.k)) result.ranked.resize(options.k);
  if (!query.category.empty() && !category_seen) {
    result.category_missing = true;
    if (const CategoryInfo* c = FindCategory(query.category)) result.fallback_generator = std::string(c->generator);
  }
  return result;
}

}  // namespace villa
