#pragma once
// The furnishing flags shared by `villa furnish`, `villa generate` and `villa eval --scenes` (defined in
// cli/furnish_flags.cpp): --library, --procedural, and where the command takes them --seed, --jobs,
// --no-reach and --radius. One place for their names, defaults, ranges and help text.
#include <string>

#include <CLI/CLI.hpp>

#include "solver/furnish.h"

namespace villa::cli {

// Which of the shared flags a command takes, beyond --library and --procedural (every one takes those).
struct FurnishFlagSet {
  bool seed = false;   // --seed (generate and eval take theirs from the backend flags: one seed for all)
  bool jobs = true;    // --jobs, rooms furnished at once (eval's --jobs means more and is its own)
  bool reach = true;   // --no-reach and --radius
  std::string scope;   // put before each help text, e.g. "with --scenes: "
};

// Adds the flags to `sub`, binding them into `options`; the options' values are the defaults shown.
void AddFurnishFlags(CLI::App* sub, solver::FurnishOptions& options, const FurnishFlagSet& set = {});

}  // namespace villa::cli
