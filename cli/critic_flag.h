#pragma once
// `--critic offline|none` for the commands that furnish on their way to something else (`villa generate`,
// `villa eval --scenes`): the offline critic (critic/critic.h) reviews every room after the solver, as in
// `villa furnish`, unless none is asked for. (`villa furnish` has the full set: mllm too, rounds, logs.)
// Header only: the villa executable links the critic when it is built (VILLA_HAVE_CRITIC).
#include <string>

#include <CLI/CLI.hpp>

#include "solver/furnish.h"
#ifdef VILLA_HAVE_CRITIC
#include "critic/critic.h"
#endif

namespace villa::cli {

// Sets `options.critic` to the offline critic and adds the flag that may take it away again.
inline void AddCriticChoice(CLI::App* sub, solver::FurnishOptions& options, const std::string& scope = "") {
#ifdef VILLA_HAVE_CRITIC
  options.critic = critic::MakeRoomCritic({});
  sub->add_option_function<std::string>(
         "--critic",
         [&options](const std::string& kind) {
           critic::CriticOptions c;
           c.kind = *critic::ParseCriticKind(kind);  // offline or none: checked by IsMember
           options.critic = critic::MakeRoomCritic(c);
         },
         scope + "offline (default: a geometric critic moves objects until the room's relations hold) or none (the "
                 "solver's arrangement as it is)")
      ->check(CLI::IsMember({"offline", "none"}));
#endif
}

}  // namespace villa::cli
