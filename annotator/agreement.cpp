#include "annotator/agreement.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace villa::annotator {
namespace {

// Room i of `a` and room i of `b` are the same room when they stand on the same level with the same
// outline: relabels and fixes rename rooms and add elements, never move or reorder rooms.
bool SameRoom(const Room& a, const Room& b) { return a.level == b.level && a.polygon == b.polygon; }

struct Pairs {
  std::vector<std::pair<int, int>> decisions;
  std::vector<std::pair<int, int>> labels;
};

AgreementFigures Figures(const std::string& who, const Pairs& p, bool pooled) {
  AgreementFigures f;
  f.who = who;
  f.layouts = static_cast<int>(p.decisions.size());
  for (auto [a, b] : p.decisions) f.decisions_agreed += a == b;
  f.rooms = static_cast<int>(p.labels.size());
  for (auto [a, b] : p.labels) f.rooms_agreed += a == b;
  f.decision_kappa = Kappa(p.decisions, 2, pooled);
  f.label_kappa = Kappa(p.labels, kCategoryCount, pooled);
  return f;
}

}  // namespace

double Kappa(const std::vector<std::pair<int, int>>& pairs, int categories, bool pooled) {
  if (pairs.empty()) return std::numeric_limits<double>::quiet_NaN();
  double n = static_cast<double>(pairs.size());
  std::vector<double> first(categories, 0), second(categories, 0);
  double agreed = 0;
  for (auto [a, b] : pairs) {
    first[a] += 1;
    second[b] += 1;
    agreed += a == b;
  }
  double observed = agreed / n;
  double expected = 0;
  for (int k = 0; k < categories; ++k) {
    if (pooled) {
      double share = (first[k] + second[k]) / (2 * n);
      expected += share * share;
    } else {
      expected += (first[k] / n) * (second[k] / n);
    }
  }
  if (expected >= 1 - 1e-12) return std::numeric_limits<double>::quiet_NaN();
  return (observed - expected) / (1 - expected);
}

Agreement ComputeAgreement(const std::vector<std::vector<Rating>>& ratings) {
  std::map<std::pair<std::string, std::string>, Pairs> by_pair;
  Pairs all;
  for (const auto& layout_ratings : ratings) {
    if (layout_ratings.size() < 2) continue;
    std::vector<const Rating*> sorted;
    for (const Rating& r : layout_ratings) sorted.push_back(&r);
    std::sort(sorted.begin(), sorted.end(), [](const Rating* a, const Rating* b) { return a->annotator < b->annotator; });
    const Rating& a = *sorted[0];
    const Rating& b = *sorted[1];
    if (a.annotator == b.annotator) continue;
    Pairs& p = by_pair[{a.annotator, b.annotator}];
    std::pair<int, int> decision{a.accepted ? 1 : 0, b.accepted ? 1 : 0};
    p.decisions.push_back(decision);
    all.decisions.push_back(decision);
    if (!a.accepted || !b.accepted || a.layout.rooms.size() != b.layout.rooms.size()) continue;
    for (std::size_t i = 0; i < a.layout.rooms.size(); ++i) {
      if (!SameRoom(a.layout.rooms[i], b.layout.rooms[i])) continue;
      std::pair<int, int> label{static_cast<int>(a.layout.rooms[i].category), static_cast<int>(b.layout.rooms[i].category)};
      p.labels.push_back(label);
      all.labels.push_back(label);
    }
  }
  Agreement out;
  for (const auto& [names, pairs] : by_pair) out.pairs.push_back(Figures(names.first + " / " + names.second, pairs, false));
  out.all = Figures("all pairs", all, true);
  return out;
}

}  // namespace villa::annotator
