#pragma once
// ValidateLayout: the rules 1-10 of FORMAT.md. Each violation carries its rule, the elements involved
// and the figure that breaks it (an overlap area in m2, a gap area, how far a door is off a boundary in m).
#include <string>
#include <vector>

#include "layout/layout.h"

namespace villa {

struct Violation {
  int rule = 0;                        // 1..10, as numbered in FORMAT.md
  std::vector<std::string> elements;   // room / element names involved, e.g. {"kitchen_0/0"}
  std::string message;                 // one line for a person: "kitchen_0/0 has no window"
  double figure = 0.0;                 // the measured quantity (m or m2), 0 where none applies
};

struct ValidateOptions {
  double tolerance = kTolerance;  // m, lengths, distances and areas (layout.h's tolerance policy)
  double on_wall_tolerance = kOnWallTolerance;  // m, how far a 1D element may be off a boundary (rule 3)
  // Rules to check; the geometric rules 1-5 decide FSR, all ten decide validity.
  bool check_architecture = true;  // rules 6-10
};

struct ValidationReport {
  std::vector<Violation> violations;
  bool valid() const { return violations.empty(); }
  // No violation of the geometric rules 1-5 (the layout becomes a 3D building: counts for FSR).
  bool geometric_ok() const;
  // Number of violations of `rule`.
  int CountRule(int rule) const;
};

ValidationReport ValidateLayout(const Layout& layout, const ValidateOptions& options = {});

}  // namespace villa
