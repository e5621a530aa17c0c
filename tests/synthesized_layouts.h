#pragma once
// A synthesized set for cross-checks between components: partitioner layouts of every footprint class
// and floor count. For test executables that link villa_partitioner (see their extra.cmake).
#include <cstdint>
#include <functional>
#include <string>

#include "partitioner/partitioner.h"

namespace villa::testing {

// Calls `visit` with each layout the partitioner makes for every footprint class, 1 to 3 floors and
// seeds 1..seeds (the partitioner seed mixes in `salt`), and a name for messages; returns how many.
inline int ForEachSynthesizedLayout(int seeds, std::uint64_t salt,
                                    const std::function<void(const Layout&, const std::string&)>& visit) {
  int count = 0;
  for (ShapeClass shape : AllShapeClasses())
    for (int floors = 1; floors <= 3; ++floors)
      for (int seed = 1; seed <= seeds; ++seed) {
        PartitionOptions options;
        options.shape = shape;
        options.floors = floors;
        PartitionSummary summary = GenerateLayout(options, static_cast<std::uint64_t>(seed) * salt + floors);
        if (!summary.ok()) continue;
        ++count;
        visit(summary.layout, std::string(ShapeClassName(shape)) + " floors " + std::to_string(floors) + " seed " +
                                  std::to_string(seed));
      }
  return count;
}

}  // namespace villa::testing
