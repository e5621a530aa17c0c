#pragma once
// Deterministic randomness for the planner: util's SplitMix64 stream (integer draws by multiply-shift),
// so a seed gives the same graph with every standard library (no std::*_distribution), and a name's
// FNV-1a to give each room its own stream from one seed.
#include <cstdint>
#include <string_view>

#include "util/hash.h"

namespace villa::scene {

using SplitMix64 = villa::SplitMix64;

// 64-bit FNV-1a of a name, to give each room its own stream from one seed.
inline uint64_t NameHash(std::string_view text) { return Fnv1a64(text); }

}  // namespace villa::scene
