#pragma once
// The villas the furnishing benches run on: the four bundled examples and the layouts
// `villa synth --count N --seed S` writes, loaded once here for bench/furnish.cpp and bench/reach.cpp.
#include <cstdint>
#include <string>
#include <vector>

#include "layout/layout.h"

namespace villa::bench {

struct BenchVilla {
  std::string name;  // "examples/<file>" or the synthesized record's id
  Layout layout;
};

// The bundled examples (examples/*.json of the four kinds), in a fixed order; exits with a message when one
// cannot be read (the benches have nothing to measure without them).
std::vector<BenchVilla> ExampleVillas();
// The villas of `villa synth --count count --seed seed`, rooms in the order synth writes them (the builder's
// choices follow it); seeds synth could not turn into a layout are reported on stderr and left out.
std::vector<BenchVilla> SynthesizedVillas(std::uint64_t count, std::uint64_t seed);
// Both: the examples first.
std::vector<BenchVilla> BenchVillas(std::uint64_t count, std::uint64_t seed);

}  // namespace villa::bench
