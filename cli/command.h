#pragma once
// Subcommand registration. Each cli/<name>.cpp defines one subcommand with a static
//   static villa::cli::Registration reg{order, [](CLI::App& app) { ... app.add_subcommand(...) ... }};
// binding its flags straight into a library Options struct, and a callback that returns through
// SetExitCode(). main() stays a few lines; no other file changes when a subcommand is added.
#include <functional>
#include <stdexcept>
#include <string>

#include <CLI/CLI.hpp>

namespace villa::cli {

using Setup = std::function<void(CLI::App& app)>;

struct Registration {
  Registration(int order, Setup setup);  // lower order = listed first in --help
};

// Exit codes of `villa`: 0 done, 1 failed, 2 usage error.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;

void SetExitCode(int code);

// Thrown from a callback for a usage problem found after parsing (bad value combinations, missing
// files named on the command line): printed as "villa SUB: message", exit 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace villa::cli
