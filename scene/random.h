#pragma once
// Deterministic randomness for the planner: SplitMix64 and integer draws by multiply-shift, so a seed gives
// the same graph with every standard library (no std::*_distribution).
// Issue 10 gathers the project's SplitMix64 and FNV-1a copies into one place in util/; this header then
// becomes an include of that one.
#include <cstdint>
#include <string_view>

namespace villa::scene {

class SplitMix64 {
 public:
  explicit SplitMix64(uint64_t seed) : state_(seed) {}
  uint64_t Next() {
    uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  // Uniform in [lo, hi], both included; lo when hi <= lo.
  int Int(int lo, int hi) {
    if (hi <= lo) return lo;
    uint64_t span = static_cast<uint64_t>(hi - lo) + 1;
    return lo + static_cast<int>((static_cast<unsigned __int128>(Next()) * span) >> 64);
  }
  double Unit() { return static_cast<double>(Next() >> 11) * 0x1.0p-53; }  // [0, 1)

 private:
  uint64_t state_;
};

// 64-bit FNV-1a of a name, to give each room its own stream from one seed.
inline uint64_t NameHash(std::string_view text) {
  uint64_t h = 0xcbf29ce484222325ull;
  for (unsigned char c : text) {
    h ^= c;
    h *= 0x100000001b3ull;
  }
  return h;
}

}  // namespace villa::scene
