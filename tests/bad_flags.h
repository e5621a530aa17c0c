#pragma once
// Numeric flags given out of range (issue 17), checked the same way for every subcommand: exit 2 and a
// message naming the flag and the accepted range. Shared by the CLI tests of several components.
#include <catch2/catch.hpp>

#include <string>
#include <utility>
#include <vector>

namespace villa::test {

struct BadFlag {
  std::string args;     // appended to the command line
  std::string message;  // what the error output must contain
};

// `run(args)` runs the command with `args` added and returns {exit status, its output}.
template <class Run>
void CheckBadFlags(const std::vector<BadFlag>& cases, Run run) {
  for (const BadFlag& bad : cases) {
    const std::pair<int, std::string> result = run(bad.args);
    INFO(bad.args << "\n" << result.second);
    CHECK(result.first == 2);
    CHECK(result.second.find(bad.message) != std::string::npos);
  }
}

}  // namespace villa::test
