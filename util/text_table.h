#pragma once
// Plain-text tables for summaries printed by the commands (columns aligned, numbers right-aligned).
#include <string>
#include <vector>

namespace villa {

class TextTable {
 public:
  explicit TextTable(std::vector<std::string> header);
  void AddRow(std::vector<std::string> row);
  std::string Render() const;

 private:
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

// "12.3%" with one decimal; "-" for a ratio whose denominator is zero.
std::string FormatPercent(double numerator, double denominator);
// Fixed notation with `decimals` places.
std::string FormatFixed(double value, int decimals);

}  // namespace villa
