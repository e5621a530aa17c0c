// villa_bench_rooms: do furnished rooms read as rooms (issue 27)? Synthesizes villas as `villa synth --count
// N --seed S` does, furnishes each as `villa furnish` does by default (the offline critic, reachability and
// its feedback), and prints per room type issue 27's functional checks (solver/functional.h: essentials,
// dining and meeting chairs at their table, seating groups, desks with a chair, nightstands and pillows at
// the bed's head, floor use in rooms of 14 m2 or more, wishes, support slips) beside CR, FR, OBR, CSR and NO,
// and the seconds a room.
//   villa_bench_rooms [--villas N] [--seed S] [--library DIR] [--critic none|offline] [--no-reach]
//                     [--text "request"] [--failing] [--type T] [--only I,J,...]
// --failing lists every room whose check fails and why; --type furnishes only rooms of one type; --text
// furnishes every villa with that request's wishes; --only furnishes only the villas of those indices (0 is
// villa-000000). The seed 2027 is the default: no test uses it.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "assets/category.h"
#include "bench/support/furnish_setup.h"
#include "bench/support/villas.h"
#include "critic/critic.h"
#include "scene/acquire.h"
#include "solver/furnish.h"
#include "solver/functional.h"
#include "util/text_table.h"

using namespace villa;

namespace {

struct Row {
  solver::FunctionalTally f;
  int rooms = 0, objects = 0, colliding = 0, floating = 0, consumers = 0, out = 0, inside = 0, contained = 0;
  double cpu = 0.0;
  void Add(const solver::RoomReport& r) {
    if (r.functional) f.Add(*r.functional);
    ++rooms;
    cpu += r.cpu_seconds;
    if (!r.solve) return;
    const solver::ExactMetrics& m = r.solve->metrics;
    objects += m.objects, colliding += m.colliding, floating += m.floating, consumers += m.consumers;
    out += m.out_of_bounds, inside += m.inside_edges, contained += m.contained;
  }
  std::vector<std::string> Cells(const std::string& label) const {
    auto pct = [](int n, int d) { return d ? FormatFixed(100.0 * n / d, 1) : std::string("-"); };
    std::vector<std::string> cells{label, std::to_string(rooms), FormatFixed(rooms ? double(objects) / rooms : 0.0, 1)};
    for (std::string& c : f.Cells()) cells.push_back(std::move(c));
    for (std::string c : {pct(colliding, objects) + "/" + pct(floating, consumers) + "/" + pct(out, objects),
                          inside ? pct(contained, inside) : std::string("-"), FormatFixed(rooms ? cpu / rooms : 0.0, 3)})
      cells.push_back(std::move(c));
    return cells;
  }
};
std::vector<std::string> Header() {
  std::vector<std::string> h{"room type", "rooms", "NO"};
  for (const std::string& c : solver::FunctionalTally::Header()) h.push_back(c);
  for (const char* c : {"CR/FR/OBR %", "CSR %", "s a room"}) h.push_back(c);
  return h;
}

}  // namespace

int main(int argc, char** argv) {
  uint64_t villas = 50, seed = 2027;
  std::set<uint64_t> only_villas;
  std::string library_dir, critic_name = "offline", text, only_type;
  bool reach = true, failing = false;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--villas" && i + 1 < argc) villas = std::strtoull(argv[++i], nullptr, 10);
    else if (a == "--seed" && i + 1 < argc) seed = std::strtoull(argv[++i], nullptr, 10);
    else if (a == "--library" && i + 1 < argc) library_dir = argv[++i];
    else if (a == "--critic" && i + 1 < argc) critic_name = argv[++i];
    else if (a == "--text" && i + 1 < argc) text = argv[++i];
    else if (a == "--type" && i + 1 < argc) only_type = argv[++i];
    else if (a == "--only" && i + 1 < argc) {
      // Villa indices to furnish, comma separated (the failing ones of a full run, to iterate on).
      std::stringstream list(argv[++i]);
      for (std::string item; std::getline(list, item, ',');) only_villas.insert(std::strtoull(item.c_str(), nullptr, 10));
    }
    else if (a == "--no-reach") reach = false;
    else if (a == "--failing") failing = true;
    else {
      std::fprintf(stderr,
                   "usage: villa_bench_rooms [--villas N] [--seed S] [--library DIR] [--critic none|offline] [--no-reach] "
                   "[--text \"request\"] [--failing] [--type T] [--only I,J,...]\n");
      return 2;
    }
  }
  const bench::FurnishSetup setup = bench::SetUpFurnishing(critic_name, library_dir);
  std::printf("rooms: %llu villas of `villa synth --count %llu --seed %llu`, furnished with seed %llu, critic %s, reach %s, assets: %s\n",
              static_cast<unsigned long long>(villas), static_cast<unsigned long long>(villas),
              static_cast<unsigned long long>(seed), static_cast<unsigned long long>(seed), critic_name.c_str(),
              reach ? "on" : "off",
              setup.assets.c_str());
  if (!text.empty()) std::printf("request: %s\n", text.c_str());
  const std::vector<bench::BenchVilla> all = bench::SynthesizedVillas(villas, seed);
  std::map<std::string, Row> by_type;
  Row total;
  std::vector<std::string> lines;
  int reach_rooms = 0, rooms_reachable = 0, reach_zones = 0, zones_reachable = 0, removed = 0;
  physics::StabilityCount stability;
  int starts_inside = 0, physics_removed = 0, furnished_rooms = 0;
  std::map<std::string, int> physics_taken;  // category: pieces the physics check took out (the first of each removal)
  int beds = 0, short_beds = 0;  // adult beds, and those shorter or narrower than a single (0.9 x 1.95 m)
  double physics_seconds = 0.0;
  const auto start = std::chrono::steady_clock::now();
  for (size_t index = 0; index < all.size(); ++index) {
    const bench::BenchVilla& v = all[index];
    if (!only_villas.empty() && !only_villas.count(index)) continue;
    solver::FurnishOptions options;
    options.jobs = 1;
    options.seed = seed;
    options.text = text;
    options.check_reach = reach;
    options.critic = critic::MakeRoomCritic(setup.critic);
    if (!only_type.empty()) {
      for (const Room& room : v.layout.rooms)
        if (CategoryName(room.category) == only_type) options.rooms.push_back(room.name());
      if (options.rooms.empty()) continue;
    }
    auto furnished = solver::FurnishLayout(v.layout, {v.name, std::string(64, '0')}, setup.library.library, setup.library.file, options);
    if (!furnished.ok()) {
      std::fprintf(stderr, "%s: %s\n", v.name.c_str(), furnished.error().c_str());
      return 1;
    }
    const solver::FurnishSummary& fs = furnished->summary;
    reach_rooms += fs.reach_rooms, rooms_reachable += fs.rooms_reachable;
    reach_zones += fs.reach_zones, zones_reachable += fs.zones_reachable;
    removed += fs.removed;
    stability += fs.stability;
    starts_inside += fs.starts_inside, physics_removed += fs.physics_removed;
    physics_seconds += fs.physics_seconds, furnished_rooms += fs.furnished;
    if (const CategoryInfo* bed = FindCategory("bed"))
      for (const scene::SceneObject& o : furnished->scene.objects)
        if (o.category == "bed" && o.pose) {
          ++beds;
          const bool small = o.size.x < bed->size_min.x - 1e-6 || o.size.y < bed->size_min.y - 1e-6;
          short_beds += small;
          if (small && failing)
            lines.push_back(v.name + " " + o.id + ": a bed of " + FormatFixed(o.size.x, 2) + " x " + FormatFixed(o.size.y, 2) +
                            " m, smaller than a single (" + FormatFixed(bed->size_min.x, 2) + " x " + FormatFixed(bed->size_min.y, 2) + ")");
        }
    if (failing && furnished->physics)
      for (const physics::GlbObjectMotion& o : furnished->physics->objects)
        if (o.motion.start_depth > physics::kStartsInside)
          lines.push_back(v.name + " " + o.id + ": starts " + FormatFixed(1000.0 * o.motion.start_depth, 1) + " mm inside " +
                          o.motion.start_against);
    for (const solver::RoomReport& r : furnished->rooms) {
      if (r.solve)
        for (const solver::ActionResult& a : r.solve->actions)
          if (a.status != solver::ActionStatus::kRefused && a.action.reason.rfind("physics:", 0) == 0) {
            const std::string id = a.action.id, tail = id.substr(id.rfind('/') + 1);
            ++physics_taken[tail.substr(0, tail.rfind('-'))];
          }
      if (!r.asked || !r.functional) continue;
      by_type[std::string(CategoryName(r.category))].Add(r);
      total.Add(r);
      const solver::FunctionalCheck& c = *r.functional;
      if (!failing || c.ok()) continue;
      const std::string line = v.name + " " + r.room + " (" + FormatFixed(r.area, 1) + " m2): " + solver::FailingLine(c);
      lines.push_back(line);
    }
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  TextTable table(Header());
  for (const auto& [name, row] : by_type) table.AddRow(row.Cells(name));
  table.AddRow(total.Cells("all"));
  std::printf("%zu villas, %d rooms; seconds are thread CPU seconds a room (plan, assets, solve, critic; reach not included)\n%s",
              all.size(), total.rooms, table.Render().c_str());
  double rich_objects = 0.0;
  int rich_rooms = 0;
  for (const char* t : {"living-room", "dining-room", "bedroom", "kitchen", "children-room"})
    if (by_type.count(t)) rich_objects += by_type[t].objects, rich_rooms += by_type[t].rooms;
  std::printf("mean NO over living, dining, bed, kitchen and children's rooms: %.1f (%d rooms); %.1f s wall\n",
              rich_rooms ? rich_objects / rich_rooms : 0.0, rich_rooms, wall);
  std::printf("%s\n", total.f.Line().c_str());
  std::printf("beds: %d of %d smaller than a single bed's 0.9 x 1.95 m (shrunk to fit)\n", short_beds, beds);
  std::printf("reach: %d/%d rooms, %d/%d zones reachable; %d objects removed by the solver (agent, critic, reach, physics)\n",
              rooms_reachable, reach_rooms, zones_reachable, reach_zones, removed);
  std::printf("physics (2 s in Bullet): %d/%d free objects strict (1 cm, 0.1 rad), %d loose (20 cm, 8 deg), %d start inside "
              "another; %d optional pieces that moved taken out; settle %.2f s a room\n",
              stability.strict, stability.free, stability.loose, starts_inside, physics_removed, furnished_rooms ? physics_seconds / furnished_rooms : 0.0);
  if (!physics_taken.empty()) {
    std::vector<std::pair<int, std::string>> most;
    for (const auto& [category, n] : physics_taken) most.push_back({-n, category});
    std::sort(most.begin(), most.end());
    std::string line = "taken out by physics, by category:";
    for (const auto& [n, category] : most) line += " " + category + " " + std::to_string(-n);
    std::printf("%s\n", line.c_str());
  }
  if (failing) {
    std::printf("\nrooms whose functional check fails, and objects that start inside another (%zu):\n", lines.size());
    for (const std::string& l : lines) std::printf("  %s\n", l.c_str());
  }
  return 0;
}
