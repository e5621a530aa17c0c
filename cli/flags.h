#pragma once
// Range checks for the numeric flags of every subcommand: `->transform(WholeIn(1, 1000))` for whole numbers
// (a transform, so the canonical text reaches CLI11), `->check(NumberIn(0, 2))` for others. CLI11 alone reads
// an unsigned flag with strtoull: "--count -5" wraps to 2^64-5, "--seed 18446744073709551616" saturates to
// 2^64-1 without a word, "010" is octal. These validators see the text first: a value that is not a plain
// decimal number, or outside the accepted range, exits 2 naming the flag and the range
// ("--count: expected a whole number from 1 to 1000000000, got -5"); an accepted whole number is handed
// on in canonical decimal, so "010" is 10.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <system_error>
#include <type_traits>

#include <CLI/CLI.hpp>

#include "util/excerpt.h"

namespace villa::cli {

// The full range of a seed: any unsigned 64-bit value.
inline constexpr std::uint64_t kMaxSeed = std::numeric_limits<std::uint64_t>::max();

// A whole number from `min` to `max` (inclusive), in decimal digits with a leading '-' only for a signed
// type; give it to ->transform(), which passes the rewritten text on. Its description ("INT in [1, 1000]")
// shows in --help.
template <class T>
CLI::Validator WholeIn(T min, T max) {
  static_assert(std::is_integral_v<T>);
  const std::string range = "from " + std::to_string(min) + " to " + std::to_string(max);
  return CLI::Validator(
      [min, max, range](std::string& text) -> std::string {
        T value{};
        const char* last = text.data() + text.size();
        const auto [end, ec] = std::from_chars(text.data(), last, value);
        if (text.empty() || ec != std::errc() || end != last || value < min || value > max)
          return "expected a whole number " + range + ", got " + Excerpt(text);
        text = std::to_string(value);
        return std::string();
      },
      "INT in [" + std::to_string(min) + ", " + std::to_string(max) + "]", "WholeIn");
}

// A seed (->transform(Seed())): a whole number from 0 to 2^64-1; a negative one or one past 2^64-1 is
// refused, never wrapped.
inline CLI::Validator Seed() { return WholeIn<std::uint64_t>(0, kMaxSeed); }

// A finite decimal number from `min` to `max`; with `above_min`, `min` itself is excluded ("above 0 and
// at most 1").
inline CLI::Validator NumberIn(double min, double max, bool above_min = false) {
  auto shown = [](double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", v);
    return std::string(buffer);
  };
  const std::string range =
      above_min ? "above " + shown(min) + " and at most " + shown(max) : "from " + shown(min) + " to " + shown(max);
  return CLI::Validator(
      [min, max, above_min, range](std::string& text) -> std::string {
        double value = 0;
        const char* last = text.data() + text.size();
        const auto [end, ec] = std::from_chars(text.data(), last, value);
        const bool low = above_min ? !(value > min) : !(value >= min);
        if (text.empty() || ec != std::errc() || end != last || !std::isfinite(value) || low || !(value <= max))
          return "expected a number " + range + ", got " + Excerpt(text);
        return std::string();
      },
      std::string("NUMBER in ") + (above_min ? "(" : "[") + shown(min) + ", " + shown(max) + "]", "NumberIn");
}

// A file or folder name that is not empty (`-o ""` is a usage error, not a failure to create "").
inline CLI::Validator PathName() {
  return CLI::Validator(
      [](std::string& text) -> std::string { return text.empty() ? "an empty name is no file or folder" : std::string(); },
      "PATH", "PathName");
}

}  // namespace villa::cli
