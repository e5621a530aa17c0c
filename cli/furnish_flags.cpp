#include "cli/furnish_flags.h"

#include <cstdint>

#include "cli/flags.h"

namespace villa::cli {

void AddFurnishFlags(CLI::App* sub, solver::FurnishOptions& o, const FurnishFlagSet& set) {
  const std::string& s = set.scope;
  if (set.seed)
    sub->add_option("--seed", o.seed, s + "seed of every random choice (plans, procedural assets, solver)")
        ->capture_default_str()
        ->transform(Seed());
  if (set.jobs)
    sub->add_option("--jobs", o.jobs, s + "rooms furnished at once (0: one per hardware thread)")
        ->capture_default_str()
        ->transform(WholeIn(0, 256));
  sub->add_option("--library", o.library,
                  s + "asset library folder (default: $VILLA_ASSETS, else ~/.local/share/villa/assets when installed, "
                      "else procedural assets only)");
  sub->add_flag("--procedural", o.procedural_only, s + "procedural assets only, whatever library is installed");
  if (set.reach) {
    sub->add_flag("--no-reach", [&o](std::int64_t) { o.check_reach = false; },
                  s + "skip reachability (a person walking from the entrance to every room and interaction zone, and "
                      "the feedback that clears what furniture blocks); RCH and ACC are then not measured");
    sub->add_flag("--no-physics", [&o](std::int64_t) { o.check_physics = false; },
                  s + "skip the physics check (the villa dropped into Bullet for 2 s: how many objects stay put)");
    sub->add_option("--radius", o.reach.reach.radius, s + "the person's radius for reachability, m")
        ->capture_default_str()
        ->check(NumberIn(0.0, 2.0, /*above_min=*/true));
  }
}

}  // namespace villa::cli
