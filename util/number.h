#pragma once
// A whole string as one finite number ("2", "0.5", "1e3"): the flags that take lists of weights or shares
// ("2:4:4", "0.9:0.05:0.05", "hexagon=2,L=1") read each part with it.
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

namespace villa {

inline std::optional<double> ParseNumber(const std::string& text) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (used == 0 || used != text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

}  // namespace villa
