#pragma once
// Shared helpers of the layout tests: fixtures by name, and violation lookups.
#include <catch2/catch.hpp>

#include <set>
#include <string>

#include "layout/layout_io.h"
#include "layout/validate.h"

namespace villa::test {

inline std::string FixturePath(const std::string& name) { return std::string(VILLA_FIXTURE_DIR) + "/layouts/" + name; }

inline Layout Fixture(const std::string& name) {
  auto layout = LoadLayout(FixturePath(name));
  INFO(name << ": " << (layout ? "" : layout.error()));
  REQUIRE(layout.ok());
  return *layout;
}

inline Layout FromText(const std::string& text) {
  auto layout = ParseLayoutText(text, "inline");
  INFO((layout ? "" : layout.error()));
  REQUIRE(layout.ok());
  return *layout;
}

// The error of reading `text` as the layout file "layout.json"; the test fails when it reads.
inline std::string LayoutError(const std::string& text) {
  auto r = ParseLayoutText(text, "layout.json");
  REQUIRE_FALSE(r.ok());
  return r.error();
}

inline std::set<int> RulesOf(const ValidationReport& report) {
  std::set<int> rules;
  for (const auto& v : report.violations) rules.insert(v.rule);
  return rules;
}

inline std::string Describe(const ValidationReport& report) {
  std::string out;
  for (const auto& v : report.violations) out += "rule " + std::to_string(v.rule) + ": " + v.message + "\n";
  return out.empty() ? "(valid)" : out;
}

// The violation with exactly this message, or nullptr.
inline const Violation* Find(const ValidationReport& report, const std::string& message) {
  for (const auto& v : report.violations)
    if (v.message == message) return &v;
  return nullptr;
}

inline Room& RoomNamed(Layout& layout, const std::string& name) {
  int i = layout.FindRoom(name);
  REQUIRE(i >= 0);
  return layout.rooms[i];
}

}  // namespace villa::test
