#pragma once
// The critic loop of the paper's micro level (Sec. 3.4, issue 14): after the solver has placed a room,
// a critic observes it, evaluates it and modifies it through the solver's four actions, round after
// round, until the energy E = 5 E_col + 2 E_sup + E_sem is at most the threshold and the critic's score
// stops improving, or the round budget is spent. Physics stays the solver's: every action goes through
// RoomSolver::Apply, which repairs or refuses what would collide, float or leave the room, and the
// critic is told in the next round what became of its actions.
//
// Two critics speak the same actions:
//   offline  (the default) geometric: measures every semantic edge and interaction zone of the graph
//            exactly (critic/relations.h) and moves the objects of unmet ones where they hold, from either
//            end, keeping a move only when it lowers E with the exact check clean; no server needed.
//   mllm     a multimodal model behind any OpenAI-compatible endpoint: it sees a top view and four
//            corner views of the room (object ids as labels) and a compact text state, scores the room
//            0-10 naming problems (E_sem = 10 - score), then answers with actions under a strict JSON
//            schema. Answers are cached on disk by request hash; malformed ones are asked again.
// Every round can be logged to <log_dir>/<room>/round-N/ (state, pictures, requests, answers, actions
// with their results, energies) so a person can replay it. critic/prompts.h holds the prompts.
//
//   CriticOptions options;                       // offline, 4 rounds
//   furnish.critic = MakeRoomCritic(options);    // solver/furnish.h hook
#include <filesystem>
#include <string>

#include "llm/client.h"
#include "llm/json_chat.h"
#include "solver/furnish.h"
#include "solver/room_view.h"
#include "util/result.h"

namespace villa::critic {

enum class CriticKind { kNone, kOffline, kMllm };
std::string_view CriticKindName(CriticKind kind);  // "none", "offline", "mllm"
std::optional<CriticKind> ParseCriticKind(std::string_view name);

struct CriticOptions {
  CriticKind kind = CriticKind::kOffline;
  // Rounds of observe / evaluate / act per room, [1, 50]. The offline critic's rounds are cheap (no
  // pictures); a model's cost two requests each.
  int rounds = 6;
  // Stop when E <= this and the score did not improve on the best round (SCENE.md: 1.0), (0, 100].
  double energy_threshold = 1.0;

  // Offline: solver actions the critic may try per room (each one exact check), [1, 2000].
  int max_tries = 300;
  // Offline: a candidate pose must keep this much room (m) from other objects' boxes before it is tried
  // (the solver keeps 0.02; a little more saves a try that would be repaired), [0, 0.2].
  double clearance = 0.025;

  // Model: server, model name, key (from the environment), sampling; answers as strict JSON.
  LlmOptions llm;
  JsonChatOptions chat;        // corrective turns, the answer cache folder
  int max_actions = 8;         // actions taken from one answer, [1, 50]
  solver::RoomViewOptions views;  // 768 px, labels on for the model
  bool json_schema = true;     // send response_format json_schema (strict); off for servers without it

  // Where rounds are logged (DIR/critic); empty: not logged. Offline rounds log no pictures (the offline
  // critic does not look at any) unless `log_pictures`.
  std::filesystem::path log_dir;
  bool log_pictures = false;

  std::string Check() const;  // empty when usable
};

// The hook for FurnishOptions::critic; none when options.kind is kNone.
solver::RoomCritic MakeRoomCritic(const CriticOptions& options);

struct CritiqueResult {
  solver::RoomSolution solution;  // the session's arrangement at the end
  solver::CriticFigures figures;
};
// One room through the loop (what the hook runs) on `input.session` (initialised, the rule agent run), or,
// when it is null, on a session of its own that first solves the room as the pipeline does.
Result<CritiqueResult> CritiqueRoom(const solver::RoomCriticInput& input, const CriticOptions& options);

// "living-room_0/0" -> "living-room_0_0": the room's folder under the log folder.
std::string RoomLogFolder(const std::string& room);

}  // namespace villa::critic
