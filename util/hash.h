#pragma once
// The two hashes villa uses wherever output must be the same on every machine and standard library
// (std::hash and std::*_distribution are not): SplitMix64 (Steele, Lea and Flood's splittable generator,
// used as a seeded stream and as a 64-bit mixer) and 64-bit FNV-1a (for text). One copy of each constant
// lives here; the partitioner, the describer, the procedural backend, the fine-tune split and the synth
// checksum all call it, so their streams stay byte-identical to what they were.
#include <cstdint>
#include <string_view>

namespace villa {

// SplitMix64's increment (2^64 / golden ratio) and its output function (the mixer): every input bit
// moves every output bit, so it also serves to hash integers and finish other hashes.
inline constexpr std::uint64_t kSplitMix64Gamma = 0x9e3779b97f4a7c15ULL;
constexpr std::uint64_t SplitMix64Mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}
// The mixer applied to `x + gamma`: the value a SplitMix64 stream seeded with `x` gives first; hashes
// integers and derives seeds.
constexpr std::uint64_t SplitMix64Hash(std::uint64_t x) { return SplitMix64Mix(x + kSplitMix64Gamma); }

// A SplitMix64 stream: the state advances by the gamma and each output is the mixed state. Cheap to copy
// and to seed; the same seed gives the same numbers everywhere.
class SplitMix64 {
 public:
  explicit constexpr SplitMix64(std::uint64_t seed) : state_(seed) {}

  constexpr std::uint64_t Next() {
    const std::uint64_t x = state_;
    state_ += kSplitMix64Gamma;
    return SplitMix64Hash(x);
  }
  // Uniform in [lo, hi] (inclusive), by multiplying into the range (no modulo bias worth speaking of for
  // spans far below 2^64); lo when hi <= lo.
  std::int64_t Int(std::int64_t lo, std::int64_t hi) {
    if (hi <= lo) return lo;
    const unsigned __int128 span = static_cast<unsigned __int128>(hi - lo) + 1;
    return lo + static_cast<std::int64_t>((static_cast<unsigned __int128>(Next()) * span) >> 64);
  }
  // Uniform in [0, 1) with 53 random bits.
  double Unit() { return static_cast<double>(Next() >> 11) * 0x1.0p-53; }
  bool Chance(double p) { return Unit() < p; }
  // An index drawn with probability proportional to `weights` (all >= 0, some > 0).
  int Weighted(const double* weights, int n) {
    double total = 0.0;
    for (int i = 0; i < n; ++i) total += weights[i];
    double x = Unit() * total;
    for (int i = 0; i < n; ++i) {
      if (x < weights[i]) return i;
      x -= weights[i];
    }
    return n - 1;
  }

 private:
  std::uint64_t state_;
};

// 64-bit FNV-1a of `text`. `hash` continues an earlier hash, so a stream can be hashed piece by piece:
// Fnv1a64(b, Fnv1a64(a)) == Fnv1a64(a + b).
inline constexpr std::uint64_t kFnv1a64Offset = 0xcbf29ce484222325ULL;
inline constexpr std::uint64_t kFnv1a64Prime = 0x100000001b3ULL;
constexpr std::uint64_t Fnv1a64(std::string_view text, std::uint64_t hash = kFnv1a64Offset) {
  for (char c : text) hash = (hash ^ static_cast<unsigned char>(c)) * kFnv1a64Prime;
  return hash;
}

}  // namespace villa
