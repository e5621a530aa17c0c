#pragma once
// Agreement between annotators on the layouts two of them labelled (the overlap sample of `--split`):
// raw agreement and chance-corrected agreement (kappa) on the accept / reject decision, and on the
// category of every room of the layouts both accepted.
//
// Kappa = (p_o - p_e) / (1 - p_e): p_o the share of items on which the two agree, p_e the share expected
// by chance. Cohen's kappa takes p_e from each rater's own category shares and is given per pair of
// annotators; over all pairs together (different people rated different layouts) the pooled figure is
// Scott's pi / Fleiss' kappa for two ratings an item, p_e from the shares of both ratings pooled.
// Kappa is undefined (NaN) when p_e = 1 (both used one category only).
#include <string>
#include <utility>
#include <vector>

#include "layout/layout.h"

namespace villa::annotator {

// One person's final word on one layout.
struct Rating {
  std::string annotator;
  bool accepted = false;  // verified (true) or rejected (false)
  Layout layout;          // the labels they left
};

struct AgreementFigures {
  std::string who;               // "alice / bob", or "all pairs"
  int layouts = 0;               // layouts both rated (accepted or rejected)
  int decisions_agreed = 0;      // of those, how many got the same decision
  double decision_kappa = 0;     // Cohen's (a pair) or Fleiss' (all pairs); NaN when undefined
  int rooms = 0;                 // rooms of the layouts both accepted, matched by level and outline
  int rooms_agreed = 0;          // of those, how many got the same category
  double label_kappa = 0;
  double decision_agreement() const { return layouts ? static_cast<double>(decisions_agreed) / layouts : 0; }
  double label_agreement() const { return rooms ? static_cast<double>(rooms_agreed) / rooms : 0; }
};

struct Agreement {
  std::vector<AgreementFigures> pairs;  // one row per pair of annotators, by name
  AgreementFigures all;                 // every doubly rated layout, pooled
};

// `ratings`: per layout, the ratings of distinct annotators (layouts with fewer than two are skipped;
// with more than two, the first two by annotator name count).
Agreement ComputeAgreement(const std::vector<std::vector<Rating>>& ratings);

// Kappa for paired ratings (category indices in [0, categories)): Cohen's when `pooled` is false,
// Scott's pi / Fleiss' kappa for two raters when true.
double Kappa(const std::vector<std::pair<int, int>>& pairs, int categories, bool pooled);

}  // namespace villa::annotator
