#pragma once
// Deterministic random numbers for the solver (SplitMix64): the same stream on every standard library,
// so a seed gives the same arrangement everywhere (no std::*_distribution). Internal to villa_solver.
#include <cstdint>

namespace villa::solver {

class Rng {
 public:
  explicit Rng(uint64_t seed) : state_(seed) {}
  uint64_t Next() {
    uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double Unit() { return static_cast<double>(Next() >> 11) * 0x1.0p-53; }  // [0, 1)

 private:
  uint64_t state_;
};

}  // namespace villa::solver
