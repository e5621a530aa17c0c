// villa_bench_generate: `villa generate` end to end, text to a furnished villa with every file written,
// on three-floor villas of 15 rooms (the paper's standard villa: ~225 minutes each, ~15 a room). For each
// request and seed: the wall time of the whole run and of its steps (plan, build, furnish, export, preview),
// the rooms and objects, the time a room (wall: furnish / rooms; and the rooms' own thread CPU time), the
// clean rooms (CR = FR = OBR = 0, CSR = 1). Offline: the procedural planner and procedural assets; each room
// reviewed by the offline critic as `villa generate` does by default (`--critic none`: the solver alone).
//   villa_bench_generate [--seeds N] [--jobs J] [--library DIR] [--critic offline|none]
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

#include "critic/critic.h"
#include "generator/generate.h"
#include "util/text_table.h"

using namespace villa;
namespace fs = std::filesystem;

namespace {

constexpr double kPaperSecondsPerVilla = 225 * 60.0;
constexpr double kPaperSecondsPerRoom = 15 * 60.0;

// Three floors of four rooms each around the staircase (utility) room: 15 rooms.
const char* const kRequests[] = {
    "A three-story villa. On the ground floor a living room with a TV, a kitchen, a dining room and a bathroom; on "
    "the second floor two bedrooms, a bathroom and a study with bookshelves full of books; on the top floor a "
    "children's room, a bedroom, a meeting room and a balcony with panoramic windows.",
    "I want a three-storey L-shaped villa. Ground floor: a lounge, an open-plan kitchen, a dining room and an office. "
    "Second floor: three bedrooms and a bathroom. Top floor: a kids' room, a bathroom, a meeting room and a balcony.",
};

}  // namespace

int main(int argc, char** argv) {
  int seeds = 3, jobs = 0;
  std::string library, critic_name = "offline";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--seeds" && i + 1 < argc) seeds = std::atoi(argv[++i]);
    else if (a == "--jobs" && i + 1 < argc) jobs = std::atoi(argv[++i]);
    else if (a == "--library" && i + 1 < argc) library = argv[++i];
    else if (a == "--critic" && i + 1 < argc) critic_name = argv[++i];
    else {
      std::fprintf(stderr, "usage: villa_bench_generate [--seeds N] [--jobs J] [--library DIR] [--critic offline|none]\n");
      return 2;
    }
  }
  critic::CriticOptions critic_options;
  if (auto kind = critic::ParseCriticKind(critic_name); kind && *kind != critic::CriticKind::kMllm) {
    critic_options.kind = *kind;
  } else {
    std::fprintf(stderr, "--critic %s: expected offline or none\n", critic_name.c_str());
    return 2;
  }
  const fs::path dir = fs::temp_directory_path() / ("villa_bench_generate_" + std::to_string(::getpid()));
  TextTable table({"request", "seed", "floors", "rooms", "objects", "clean", "plan s", "build s", "furnish s", "export s",
                   "preview s", "total s", "s/room wall", "s/room cpu"});
  double total = 0.0, furnish = 0.0, cpu = 0.0;
  int runs = 0, rooms = 0, fifteen = 0;
  for (size_t r = 0; r < std::size(kRequests); ++r) {
    for (int seed = 1; seed <= seeds; ++seed) {
      GenerateOptions options;
      options.plan.seed = seed;
      options.out = dir / (std::to_string(r) + "_" + std::to_string(seed));
      options.force = true;
      options.furnishing.jobs = jobs;
      options.furnishing.library = library;
      options.furnishing.procedural_only = library.empty();
      options.furnishing.critic = critic::MakeRoomCritic(critic_options);
      auto summary = GenerateVilla(kRequests[r], options);
      if (!summary.ok() || !summary->furnished) {
        std::fprintf(stderr, "request %zu seed %d: %s\n", r + 1, seed,
                     summary.ok() ? (summary->problems.empty() ? "not furnished" : summary->problems.front().c_str())
                                  : summary.error().c_str());
        continue;
      }
      const GenerateSummary& s = *summary;
      const solver::FurnishSummary& f = s.furnish;
      int clean = 0;
      for (const auto& room : s.report["furnish"]["rooms"]) {
        if (!room.contains("metrics")) continue;
        const auto& m = room["metrics"];
        clean += m.value("CR", 0.0) == 0.0 && m.value("FR", 0.0) == 0.0 && m.value("OBR", 0.0) == 0.0 &&
                 m.value("CSR", 1.0) == 1.0;
      }
      table.AddRow({std::to_string(r + 1), std::to_string(seed), std::to_string(s.building.value("levels", 0)),
                    std::to_string(f.rooms), std::to_string(f.objects), std::to_string(clean) + "/" + std::to_string(f.rooms),
                    FormatFixed(s.plan_s, 2), FormatFixed(s.build_s, 3), FormatFixed(s.furnish_s, 2), FormatFixed(s.export_s, 2),
                    FormatFixed(s.preview_s, 2), FormatFixed(s.seconds, 2), FormatFixed(s.furnish_s / f.rooms, 3),
                    FormatFixed(f.room_seconds / f.rooms, 3)});
      total += s.seconds, furnish += s.furnish_s, cpu += f.room_seconds;
      rooms += f.rooms;
      fifteen += f.rooms == 15 && s.building.value("levels", 0) == 3;
      ++runs;
    }
  }
  fs::remove_all(dir);
  std::printf("%s", table.Render().c_str());
  if (runs == 0) return 1;
  const double villa = total / runs, room = furnish / rooms;
  std::printf("%d villas (%d of them three floors and 15 rooms), %d rooms, jobs %d: %.2f s a villa end to end (the paper: "
              "~225 min, %.0fx), %.3f s wall a room furnished (%.3f s of one core; the paper: ~15 min, %.0fx)\n",
              runs, fifteen, rooms, jobs, villa, kPaperSecondsPerVilla / villa, room, cpu / rooms,
              kPaperSecondsPerRoom / (cpu / rooms));
  return 0;
}
