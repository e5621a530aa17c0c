#pragma once
// The paper's layout metrics (appendix "Custom Metrics"), for one layout and summed over many.
#include <optional>

#include "layout/layout.h"

namespace villa {

struct LayoutMetrics {
  bool parsed = true;          // false for an output that did not parse (counts against FSR)
  bool format_success = false; // parsed and passes the geometric rules 1-5
  // RR, paper's definition: per floor, breadth-first search from the floor's utility room (from the
  // entrance room on a one-floor building without one); reachable rooms / rooms, pooled over floors.
  int rooms = 0;
  int rooms_reached_per_floor = 0;
  // RR, stricter: one search over the whole building from the entrance through doors, opens and stairs.
  int rooms_reached_from_entrance = 0;
  // VCR: adjacent floor pairs, and those whose staircase footprint on the lower floor overlaps the upper
  // floor's stair hole (area > 0). The stair hole of floor L+1 is its utility room at the same place.
  int floor_pairs = 0;
  int floor_pairs_connected = 0;
};

LayoutMetrics MeasureLayout(const Layout& layout);
// The same, taking format success from a validation already made (ValidateLayout with any options: rules
// 1-5 do not depend on them), so a caller that validates anyway does not validate twice.
struct ValidationReport;
LayoutMetrics MeasureLayout(const Layout& layout, const ValidationReport& report);

// Sums over a set of outputs; ratios in [0, 1], empty when the denominator is zero.
struct MetricsSummary {
  int outputs = 0;
  int format_successes = 0;
  long rooms = 0;
  long rooms_reached_per_floor = 0;
  long rooms_reached_from_entrance = 0;
  int floor_pairs = 0;
  int floor_pairs_connected = 0;

  void Add(const LayoutMetrics& m);
  std::optional<double> fsr() const;
  std::optional<double> rr() const;             // per-floor search (paper)
  std::optional<double> rr_entrance() const;    // whole-building search
  std::optional<double> vcr() const;
};

}  // namespace villa
