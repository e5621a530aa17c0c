#pragma once
// What the furnishing benches (bench/furnish.cpp, bench/rooms.cpp) set up alike from their --critic and
// --library flags: the room critic (none or offline: a bench makes no network calls) and the asset library
// (procedural only when no folder is given). A bad flag ends the bench with a message: exit 2 for the critic,
// 1 for a library that cannot be opened.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "critic/critic.h"
#include "scene/acquire.h"

namespace villa::bench {

struct FurnishSetup {
  critic::CriticOptions critic;
  scene::FurnishingLibrary library;
  std::string assets;  // "procedural only" or "library DIR (N records)", for the bench's header line
};

inline FurnishSetup SetUpFurnishing(const std::string& critic_name, const std::string& library_dir) {
  FurnishSetup setup;
  const auto kind = critic::ParseCriticKind(critic_name);
  if (!kind || *kind == critic::CriticKind::kMllm) {
    std::fprintf(stderr, "--critic %s: expected none or offline\n", critic_name.c_str());
    std::exit(2);
  }
  setup.critic.kind = *kind;
  auto library = scene::OpenFurnishingLibrary(library_dir, library_dir.empty());
  if (!library.ok()) {
    std::fprintf(stderr, "%s\n", library.error().c_str());
    std::exit(1);
  }
  setup.library = std::move(*library);
  setup.assets = library_dir.empty() ? "procedural only"
                                     : "library " + library_dir + " (" + std::to_string(setup.library.library->records().size()) + " records)";
  return setup;
}

}  // namespace villa::bench
