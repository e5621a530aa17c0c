// villa reach DIR/scene.json [--radius R] [--json] [--no-paths]: can a person walk from the entrance to
// every room and every interaction zone of a furnished scene, across floors by the stairs? Prints per room
// and zone whether it is reachable, the length of the drawn path and what blocks it (solver/reach.h).
#include <iostream>
#include <memory>
#include <string>

#include "cli/command.h"
#include "solver/reach_scene.h"
#include "util/text_table.h"

namespace villa::cli {
namespace {

struct ReachCommand {
  std::string scene;
  bool json = false;
  bool no_paths = false;
  solver::ReachOptions options;
};

std::string Way(const solver::TargetResult& t) {
  if (t.path) return FormatFixed(t.path->length, 2);
  if (t.reachable) return FormatFixed(t.raster_length, 2) + " (raster)";
  return "-";
}

std::string Blockers(const solver::TargetResult& t) {
  if (t.reachable) return "";
  std::string out;
  for (const std::string& b : t.blockers) out += (out.empty() ? "" : ", ") + b;
  for (const std::string& b : t.door_leaves) out += (out.empty() ? "" : ", ") + ("door leaf " + b);
  return out.empty() ? t.note : out;
}

void Run(ReachCommand& command) {
  std::string problem;
  command.options.paths = !command.no_paths;
  if (!command.options.IsValid(&problem)) throw UsageError("reach: " + problem);
  auto result = solver::ReachOfScene(command.scene, command.options);
  if (!result.ok()) {
    std::cerr << "villa reach: " << result.error() << "\n";
    SetExitCode(kExitFailure);
    return;
  }
  for (const std::string& w : result->warnings) std::cerr << "villa reach: warning: " << w << "\n";
  const solver::ReachReport& r = result->report;
  if (command.json) {
    std::cout << r.ToJson().dump(2) << "\n";
    SetExitCode(kExitOk);
    return;
  }
  std::cout << command.scene << ": rooms " << r.rooms_reachable << "/" << r.rooms << " reachable (RCH " << FormatFixed(r.Rch(), 3)
            << "), interaction zones " << r.zones_reachable << "/" << r.zones << " (ACC, the mean share of a zone reached, "
            << FormatFixed(r.Acc(), 3)
            << "), radius " << FormatFixed(command.options.radius, 2) << " m"
            << (r.entrance_free ? "" : "; the entrance itself is blocked") << "\n";
  TextTable rooms({"room", "level", "reachable", "path m", "blocked by"});
  TextTable zones({"object", "room", "reachable", "share", "path m", "blocked by"});
  for (const solver::TargetResult& t : r.targets) {
    if (t.kind == solver::TargetKind::kRoom) {
      rooms.AddRow({t.name, std::to_string(t.level), t.reachable ? "yes" : "no", Way(t), Blockers(t)});
    } else {
      zones.AddRow({t.name, t.room, t.reachable ? "yes" : "no", FormatFixed(t.share, 2), Way(t), Blockers(t)});
    }
  }
  std::cout << rooms.Render();
  if (r.zones > 0) std::cout << zones.Render();
  SetExitCode(kExitOk);
}

Registration registration{85, [](CLI::App& app) {
  auto command = std::make_shared<ReachCommand>();
  CLI::App* reach = app.add_subcommand(
      "reach",
      "Check that a person (a disc) can walk from the entrance to every room and every interaction zone of a\n"
      "furnished scene, across floors by the stairs: a 2 cm raster decides, OMPL draws the paths. Reads the\n"
      "scene, the layout it names and rebuilds the building. Prints per room and zone: reachable or not, the\n"
      "path's length, and the objects (or door leaves) in the way; for a zone, the share of it reached (ACC).\n"
      "Exit status: 0 checked (whatever the outcome), 1 an unreadable scene or layout, 2 usage.");
  reach->add_option("scene", command->scene, "the scene file (DIR/scene.json)")->required()->check(CLI::ExistingFile);
  reach->add_option("--radius", command->options.radius, "the person's radius (m)")->capture_default_str();
  reach->add_flag("--json", command->json, "print the report as JSON (paths as [x, y, z] points)");
  reach->add_flag("--no-paths", command->no_paths, "decide by the raster only; draw no OMPL paths");
  reach->callback([command] { Run(*command); });
}};

}  // namespace
}  // namespace villa::cli
