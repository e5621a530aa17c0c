// villa_bench_furnish: `villa furnish` end to end on the bundled examples and on synthesized villas (the
// layouts `villa synth --count N --seed S` writes): per room type and room shape, the exact metrics (CR, FR,
// OBR, CSR), NO, outcomes and the seconds a room (thread CPU time: rooms run one at a time here), seconds
// by object count, the mean NO over the five rich room types, every room that did not end clean with its
// reason, and the ratio to the paper's ~15 minutes a room. With a critic (`--critic offline`, the default
// of `villa furnish`), also the share of the graphs' semantic edges satisfied per relation type and of the
// interaction zones kept clear, before the critic (the solver alone) and after it, and the critic's
// seconds a room. `make bench` runs it with procedural assets, without and with the offline critic;
//   villa_bench_furnish [--villas N] [--seed S] [--library DIR] [--critic none|offline] [--verbose] [--unmet] [--type T]
// --library furnishes with an imported asset library instead (villa assets import --library DIR).
// --unmet lists, room by room, every relation and zone that does not hold after the critic; --type furnishes
// only the rooms of one type (kitchen, living-room, ...), for quick measures while working on one.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "assets/procedural.h"
#include "bench/support/furnish_setup.h"
#include "bench/support/villas.h"
#include "critic/critic.h"
#include "critic/relations.h"
#include "layout/geometry.h"
#include "scene/acquire.h"
#include "solver/furnish.h"
#include "util/text_table.h"

using namespace villa;
namespace fs = std::filesystem;

namespace {

constexpr double kPaperSecondsPerRoom = 15.0 * 60.0;

struct Tally {
  int rooms = 0, converged = 0, clean = 0, objects = 0, colliding = 0, floating = 0, consumers = 0, out = 0, inside = 0,
      contained = 0, removed = 0;
  std::vector<double> seconds;
  void Add(const solver::RoomReport& r) {
    const solver::ExactMetrics& m = r.solve->metrics;
    ++rooms;
    converged += r.solve->outcome == solver::Outcome::kConverged;
    clean += m.Clean();
    objects += m.objects, colliding += m.colliding, floating += m.floating, consumers += m.consumers;
    out += m.out_of_bounds, inside += m.inside_edges, contained += m.contained;
    removed += static_cast<int>(r.solve->removed.size());
    seconds.push_back(r.cpu_seconds);
  }
  double Mean() const {
    double s = 0;
    for (double x : seconds) s += x;
    return seconds.empty() ? 0.0 : s / seconds.size();
  }
  double Quantile(double q) const {
    if (seconds.empty()) return 0.0;
    std::vector<double> v = seconds;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, static_cast<size_t>(q * (v.size() - 1) + 0.5))];
  }
  std::vector<std::string> Row(const std::string& label) const {
    auto pct = [](double n, double d) { return FormatFixed(d > 0 ? 100.0 * n / d : 0.0, 1); };
    return {label, std::to_string(rooms), FormatFixed(rooms ? double(objects) / rooms : 0.0, 1), pct(colliding, objects),
            pct(floating, consumers), pct(out, objects), inside ? pct(contained, inside) : "-", pct(converged, rooms),
            std::to_string(removed), FormatFixed(Mean(), 3), FormatFixed(Quantile(0.95), 3), FormatFixed(Quantile(1.0), 3)};
  }
};
const std::vector<std::string> kHeader{"", "rooms", "NO", "CR %", "FR %", "OBR %", "CSR %", "conv %", "removed", "s mean", "s p95", "s max"};

// Rectangle (4 right angles), L (non-convex, axis-aligned), angled (an edge off the axes).
std::string ShapeOf(const Ring& polygon) {
  const Ring ring = WithoutCollinearCorners(polygon, 1e-6);
  bool angled = false;
  for (size_t i = 0; i < ring.size(); ++i) {
    const Point a = ring[i], b = ring[(i + 1) % ring.size()];
    angled = angled || (std::abs(a.x - b.x) > 1e-6 && std::abs(a.y - b.y) > 1e-6);
  }
  if (angled) return "angled";
  return IsConvex(ring) ? "rectangle" : "L / non-convex";
}

}  // namespace

int main(int argc, char** argv) {
  uint64_t villas = 50, seed = 7;
  std::string library_dir;
  std::string critic_name = "none";
  bool verbose = false, unmet = false;
  std::string only_type;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--villas" && i + 1 < argc) villas = std::strtoull(argv[++i], nullptr, 10);
    else if (a == "--seed" && i + 1 < argc) seed = std::strtoull(argv[++i], nullptr, 10);
    else if (a == "--library" && i + 1 < argc) library_dir = argv[++i];
    else if (a == "--critic" && i + 1 < argc) critic_name = argv[++i];
    else if (a == "--verbose") verbose = true;
    else if (a == "--unmet") unmet = true;
    else if (a == "--type" && i + 1 < argc) only_type = argv[++i];
    else {
      std::fprintf(stderr, "usage: villa_bench_furnish [--villas N] [--seed S] [--library DIR] [--critic none|offline] [--verbose] [--unmet] [--type T]\n");
      return 2;
    }
  }
  const bench::FurnishSetup setup = bench::SetUpFurnishing(critic_name, library_dir);
  std::printf("furnish: the 4 examples and %llu villas of `villa synth --count %llu --seed %llu`, critic %s, assets: %s\n",
              static_cast<unsigned long long>(villas), static_cast<unsigned long long>(villas),
              static_cast<unsigned long long>(seed), critic_name.c_str(),
              setup.assets.c_str());
  const std::vector<bench::BenchVilla> all = bench::BenchVillas(villas, seed);

  std::map<std::string, Tally> by_type, by_shape, by_count;
  Tally total, rich, small_bath;
  int library_assets = 0, procedural_assets = 0, fallbacks = 0;
  std::vector<std::string> failures, unmet_lines;
  double wall = 0.0;
  critic::RelationTally before, after;
  std::vector<double> critic_seconds;
  int critic_removed = 0;
  for (const bench::BenchVilla& v : all) {
    solver::FurnishOptions options;
    options.jobs = 1;
    options.seed = seed;
    options.check_reach = false;  // the solver alone; bench/reach.cpp measures reachability and its feedback
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
    wall += furnished->summary.seconds;
    library_assets += furnished->summary.library_assets;
    procedural_assets += furnished->summary.procedural_assets;
    for (const solver::RoomReport& r : furnished->rooms) {
      for (const scene::AcquiredAsset& a : r.assets) fallbacks += a.rule == scene::AcquireRule::kFallback;
      if (!r.solve) continue;  // nothing to place (a staircase room)
      const std::string type(CategoryName(r.category));
      if (r.critic) {
        for (auto [tally, key] : {std::pair{&before, "relations_before"}, std::pair{&after, "relations_after"}})
          for (const auto& [name, n] : critic::TallyFromJson(r.critic->record[key]["by_relation"])) {
            (*tally)[type + " " + name].satisfied += n.satisfied, (*tally)[type + " " + name].measured += n.measured;
            (*tally)[type + " " + name].lost += n.lost;
            (*tally)[name].satisfied += n.satisfied, (*tally)[name].measured += n.measured, (*tally)[name].lost += n.lost;
          }
        critic_seconds.push_back(r.critic->seconds);
        if (unmet)
          for (const auto& line : r.critic->record["relations_after"]["unmet"])
            unmet_lines.push_back(v.name + " " + r.room + " (" + FormatFixed(r.area, 1) + " m2): " + line.get<std::string>());
        for (const solver::ActionResult& a : r.solve->actions)
          critic_removed += a.action.kind == solver::ActionKind::kRemoveEntity && a.action.reason.rfind("critic:", 0) == 0 &&
                            a.status != solver::ActionStatus::kRefused;
      }
      const Room& room = v.layout.rooms[v.layout.FindRoom(r.room)];
      by_type[type].Add(r);
      by_shape[ShapeOf(room.polygon)].Add(r);
      const int n = r.solve->metrics.objects;
      by_count[n < 10 ? "0-9" : n < 20 ? "10-19" : n < 30 ? "20-29" : "30+"].Add(r);
      total.Add(r);
      if (r.category == Category::kLivingRoom || r.category == Category::kDiningRoom || r.category == Category::kBedroom ||
          r.category == Category::kKitchen || r.category == Category::kChildrenRoom)
        rich.Add(r);
      if (r.category == Category::kBathroom && r.area < 7.0) small_bath.Add(r);
      const solver::ExactMetrics& m = r.solve->metrics;
      if (!m.Clean() || !r.solve->removed.empty() || verbose) {
        std::string line = v.name + " " + r.room + " (" + FormatFixed(r.area, 1) + " m2, " + ShapeOf(room.polygon) + "): " +
                           r.outcome + ", " + std::to_string(m.objects) + " objects";
        if (!m.Clean())
          line += ", NOT CLEAN: colliding " + std::to_string(m.colliding) + ", floating " + std::to_string(m.floating) +
                  ", out " + std::to_string(m.out_of_bounds) + ", contained " + std::to_string(m.contained) + "/" +
                  std::to_string(m.inside_edges);
        if (!r.solve->removed.empty()) {
          line += ", removed";
          for (const std::string& id : r.solve->removed) {
            line += ' ';
            line.append(id, r.room.size() + 1);  // the id without its room
          }
        }
        line += " (" + r.reason + ")";
        failures.push_back(line);
      }
    }
  }

  TextTable types(kHeader);
  for (const auto& [name, t] : by_type) types.AddRow(t.Row(name));
  types.AddRow(total.Row("all"));
  std::printf("%zu villas, %d rooms with objects; seconds are thread CPU seconds a room (plan + assets + solve)\n\nby room type:\n%s",
              all.size(), total.rooms, types.Render().c_str());
  TextTable shapes(kHeader);
  for (const auto& [name, t] : by_shape) shapes.AddRow(t.Row(name));
  shapes.AddRow(small_bath.Row("bathrooms < 7 m2"));
  std::printf("\nby room shape:\n%s", shapes.Render().c_str());
  TextTable counts(kHeader);
  for (const auto& [name, t] : by_count) counts.AddRow(t.Row(name + " objects"));
  std::printf("\nby object count:\n%s", counts.Render().c_str());
  std::printf("\nmean NO over living, dining, bed, kitchen and children's rooms: %.1f (%d rooms)\n",
              rich.rooms ? double(rich.objects) / rich.rooms : 0.0, rich.rooms);
  std::printf("assets: %d objects from the library, %d procedural (%d fallbacks)\n", library_assets, procedural_assets, fallbacks);
  std::printf("mean %.3f s a room, %.0fx faster than the paper's ~15 min a room; %.1f s wall for all villas\n", total.Mean(),
              total.Mean() > 0 ? kPaperSecondsPerRoom / total.Mean() : 0.0, wall);
  if (!critic_seconds.empty()) {
    // Per relation type over every room (then per room type): edges satisfied / edges whose two objects are
    // in the room; "lost": edges of objects removed (by the solver before the critic; by either after it),
    // counted as not satisfied in the "with lost" share.
    auto share = [](const critic::RelationCount& n, bool with_lost) {
      const int d = n.measured + (with_lost ? n.lost : 0);
      return d ? FormatFixed(100.0 * n.satisfied / d, 1) : std::string("-");
    };
    TextTable relations({"relation", "edges", "before %", "after %", "held after", "after, lost counted %", "lost before", "lost after"});
    for (bool by_type : {false, true})
      for (const auto& [name, n] : after) {
        if ((name.find(' ') != std::string::npos) != by_type) continue;
        const critic::RelationCount& b = before[name];
        relations.AddRow({name, std::to_string(n.measured + n.lost), share(b, false), share(n, false),
                          std::to_string(n.satisfied) + "/" + std::to_string(n.measured), share(n, true),
                          std::to_string(b.lost), std::to_string(n.lost)});
      }
    double sum = 0.0, worst = 0.0;
    for (double x : critic_seconds) sum += x, worst = std::max(worst, x);
    std::printf("\nsemantic relations (exact, docs/CRITIC.md), before the critic (the solver alone) and after it:\n%s",
                relations.Render().c_str());
    std::printf("critic: %.3f s a room on average (max %.3f s), included in the seconds above; %d objects removed by it\n",
                sum / critic_seconds.size(), worst, critic_removed);
  }
  if (unmet) {
    std::printf("\nrelations and zones that do not hold after the critic (%zu):\n", unmet_lines.size());
    for (const std::string& line : unmet_lines) std::printf("  %s\n", line.c_str());
  }
  std::printf("\nrooms not clean or with objects removed (%zu):\n", failures.size());
  for (const std::string& f : failures) std::printf("  %s\n", f.c_str());
  return 0;
}
