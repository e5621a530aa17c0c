// villa physics FILE.glb [--seconds S] [--json] [--movers K]: drops a furnished .glb into Bullet (issue 28)
// and reports how many free objects stood still, per room type, by the strict (1 cm / 0.1 rad) and loose
// (20 cm / 8 degrees) rules, with the objects that moved most (physics/glb_settle.h).
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/command.h"
#include "physics/glb_settle.h"
#include "physics/mjcf.h"
#include "physics/mujoco_run.h"
#include "util/text_table.h"

namespace villa::cli {
namespace {

struct PhysicsCommand {
  std::string glb;
  physics::SettleOptions options;
  int movers = 10;
  std::vector<std::string> only;
  std::string mjcf;  // --mjcf DIR
  bool json = false;
};

void Run(const PhysicsCommand& command) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(command.glb, ec)) throw UsageError("physics: " + command.glb + ": no such file");
  if (std::string bad = command.options.Check(); !bad.empty()) throw UsageError("physics: " + bad);
  std::optional<physics::MjcfExport> mjcf;
  if (!command.mjcf.empty()) {
    auto exported = physics::ExportMjcf(command.glb, command.mjcf, command.options);
    if (!exported.ok()) {
      std::cerr << "villa physics: " << exported.error() << "\n";
      SetExitCode(kExitFailure);
      return;
    }
    mjcf = *exported;
    const physics::MjcfSummary& w = mjcf->written;
    const physics::MujocoRun& r = mjcf->run;
    std::cerr << "wrote " << (std::filesystem::path(command.mjcf) / "villa.xml").string() << ": " << w.bodies << " bodies ("
              << w.free << " free), " << w.doors << " door leaves on hinges, " << w.geoms << " object geoms (" << w.merged
              << " boxes merged into their neighbours), " << w.static_geoms << " building geoms (" << w.prisms
              << " pieces cut into convex prisms, " << w.hulls << " left whole), " << w.sheets << " sheets left out, " << w.boxes << " boxes (as box meshes) and "
              << w.meshes << " meshes; buffers nconmax " << w.nconmax << ", njmax " << w.njmax << "\n"
              << "MuJoCo " << r.version << " loaded it and ran " << command.options.seconds << " s in "
              << FormatFixed(r.wall_seconds, 1) << " s: " << r.strict << " of " << r.free << " free objects within 1 cm and 0.1 rad ("
              << FormatPercent(r.strict, r.free) << "), " << r.loose << " within 20 cm and 8 degrees ("
              << FormatPercent(r.loose, r.free) << "); up to " << r.max_contacts << " contacts, " << r.max_rows << " rows"
              << (r.unstable ? "; MuJoCo called the simulation unstable" : "") << "\n";
    if (r.deep_at_start > 0)
      std::cerr << "  MuJoCo: " << r.deep_at_start << " contact(s) start more than 2 mm deep, the deepest "
                << FormatFixed(1000.0 * r.deepest_at_start, 1) << " mm between " << r.deepest_pair << "\n";
    for (size_t i = 0; i < r.movers.size() && static_cast<int>(i) < command.movers; ++i)
      std::cerr << "  MuJoCo: moved " << FormatFixed(100.0 * r.movers[i].moved, 1) << " cm, turned "
                << FormatFixed(r.movers[i].turned, 3) << " rad: " << r.movers[i].body << "\n";
  }
  auto settled = physics::SettleGlb(command.glb, command.options, command.only);
  if (!settled.ok()) {
    std::cerr << "villa physics: " << settled.error() << "\n";
    SetExitCode(kExitFailure);
    return;
  }
  const physics::GlbSettleSummary& s = *settled;
  if (s.objects.empty())
    std::cerr << "villa physics: " << command.glb << ": no object nodes (none whose extras name a room): nothing to settle\n";
  std::vector<const physics::GlbObjectMotion*> movers;
  std::vector<const physics::GlbObjectMotion*> inside;
  for (const auto& o : s.objects) {
    if (!o.motion.welded && !o.motion.strict) movers.push_back(&o);
    if (o.motion.start_depth > 0.002) inside.push_back(&o);
  }
  std::sort(inside.begin(), inside.end(), [](auto* a, auto* b) { return a->motion.start_depth > b->motion.start_depth; });
  if (static_cast<int>(inside.size()) > command.movers) inside.resize(command.movers);
  std::sort(movers.begin(), movers.end(), [](auto* a, auto* b) { return a->motion.moved > b->motion.moved; });
  if (static_cast<int>(movers.size()) > command.movers) movers.resize(command.movers);
  if (command.json) {
    nlohmann::ordered_json out{{"format", "villa-physics/1"}, {"glb", command.glb}};
    out.update(physics::SettleSummaryJson(s, command.options, command.movers));
    if (mjcf) {
      const physics::MujocoRun& r = mjcf->run;
      nlohmann::ordered_json movers = nlohmann::ordered_json::array();
      for (size_t i = 0; i < r.movers.size() && static_cast<int>(i) < command.movers; ++i)
        movers.push_back({{"id", r.movers[i].body}, {"moved_m", r.movers[i].moved}, {"turned_rad", r.movers[i].turned}});
      out["mjcf"] = {{"xml", (std::filesystem::path(command.mjcf) / "villa.xml").string()},
                     {"bodies", mjcf->written.bodies},
                     {"doors", mjcf->written.doors},
                     {"mujoco", r.version},
                     {"all", physics::StabilityJson({r.free, r.strict, r.loose})},
                     {"max_contacts", r.max_contacts},
                     {"nconmax", mjcf->written.nconmax},
                     {"njmax", mjcf->written.njmax},
                     {"unstable", r.unstable},
                     {"deep_at_start", r.deep_at_start},
                     {"deepest_at_start_m", r.deepest_at_start},
                     {"movers", movers}};
    }
    std::cout << out.dump(2) << "\n";
    return;
  }
  TextTable table({"room type", "free objects", "strict (1 cm, 0.1 rad)", "loose (20 cm, 8 deg)"});
  auto row = [&](const std::string& name, const physics::StabilityCount& c) {
    table.AddRow({name, std::to_string(c.free), FormatPercent(c.strict, c.free), FormatPercent(c.loose, c.free)});
  };
  for (const auto& [type, c] : s.by_room_type) row(type, c);
  row("all", s.all);
  std::cout << command.glb << ": " << s.objects.size() << " objects (" << s.all.free << " free, "
            << s.objects.size() - s.all.free << " welded), " << s.decals << " rugs as decals, " << s.parts
            << " convex parts, " << s.static_triangles << " building triangles; " << command.options.seconds
            << " s simulated in " << FormatFixed(s.seconds, 2) << " s\n"
            << table.Render();
  for (auto* o : movers)
    std::cout << "  moved " << FormatFixed(100.0 * o->motion.moved, 1) << " cm, turned " << FormatFixed(o->motion.turned, 3)
              << " rad (centre by " << FormatFixed(100.0 * o->motion.shift.x, 1) << ", " << FormatFixed(100.0 * o->motion.shift.y, 1)
              << ", " << FormatFixed(100.0 * o->motion.shift.z, 1) << " cm): " << o->id << "\n";
  std::cout << s.starts_inside << " object(s) start more than 2 mm inside another or the building\n";
  for (auto* o : inside)
    std::cout << "  " << FormatFixed(1000.0 * o->motion.start_depth, 1) << " mm into " << o->motion.start_against << ": " << o->id << "\n";
}

Registration registration{86, [](CLI::App& app) {
  auto command = std::make_shared<PhysicsCommand>();
  CLI::App* sub = app.add_subcommand(
      "physics",
      "Drop a furnished .glb into a physics engine (Bullet) and report how many objects stay put.\n"
      "The building is static (its exact triangles); objects hung on a wall or from the ceiling and clothes on\n"
      "a rail are welded; rugs are decals (left out); everything else is a rigid body made of the convex hulls\n"
      "of its mesh's pieces, of one density and friction. After --seconds of simulated time an object is stable\n"
      "by the strict rule when it moved at most 1 cm and turned at most 0.1 rad, by the loose one 20 cm and\n"
      "8 degrees. Prints the shares per room type and the objects that moved most.\n"
      "Exit status: 0 done (whatever moved), 1 the file cannot be read, 2 usage.");
  sub->add_option("glb", command->glb, "furnished .glb (villa's or another method's with room extras)")->required();
  sub->add_option("--seconds", command->options.seconds, "simulated time (default 2)")->check(CLI::Range(0.01, 60.0));
  sub->add_option("--density", command->options.density, "kg/m3 of every convex part (default 600)")->check(CLI::Range(1.0, 20000.0));
  sub->add_option("--friction", command->options.friction, "friction coefficient (default 0.6)")->check(CLI::Range(0.01, 2.0));
  sub->add_option("--movers", command->movers, "list this many of the objects that moved most (default 10)")->check(CLI::Range(0, 100000));
  sub->add_option("--only", command->only, "only this object is free, the rest welded where they stand (repeatable)");
  sub->add_option("--mjcf", command->mjcf,
                  "also write the scene for MuJoCo: DIR/villa.xml and DIR/meshes/*.stl (a convex part each), door\n"
                  "leaves on hinges; MuJoCo runs it for --seconds and reports what stayed put");
  sub->add_flag("--json", command->json, "print a machine-readable report instead");
  sub->callback([command] { Run(*command); });
}};

}  // namespace
}  // namespace villa::cli
