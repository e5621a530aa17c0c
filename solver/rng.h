#pragma once
// Deterministic random numbers for the solver: util's SplitMix64 stream, the same on every standard library,
// so a seed gives the same arrangement everywhere (no std::*_distribution). Internal to villa_solver.
#include "util/hash.h"

namespace villa::solver {

using Rng = SplitMix64;

}  // namespace villa::solver
