// villa_bench_solver: the pose solver's speed. Seconds per room by room type and shape (the synthetic
// rooms of tests/solver/fixtures: PRIORS.md furniture, a door and a window, rectangular, L-shaped and angled),
// how a room's time grows with its object count (10, 20, 40, 80), sparse vs dense linear solver, the exact
// check's share, and the ratio to the paper's ~15 minutes a room. The exact metrics are printed beside
// every time so a figure never hides a bad room. Times are thread CPU seconds (one core; the machines are
// shared), the parts split by their share of the solve's wall time. `make bench` runs it.
//   villa_bench_solver [--seeds N] [--svg DIR] [--verbose]
// --svg writes a top view of every room, --verbose each room's report, findings and actions.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <time.h>

#include "solver/solve.h"
#include "tests/solver/fixtures.h"
#include "util/text_table.h"

using namespace villa;
using namespace villa::solver;

namespace {

constexpr double kPaperSecondsPerRoom = 15.0 * 60.0;

struct Run {
  double seconds = 0, ceres = 0, exact = 0, place = 0;
  int objects = 0, removed = 0;
  bool converged = false, clean = false;
  double cr = 0, fr = 0, obr = 0, csr = 1;
};

bool g_verbose = false;

// Thread CPU time (s): the machines are shared, so wall time carries other people's load.
double CpuSeconds() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

Run Solve(const RoomProblem& room, const SolveOptions& options, const std::string& label, const std::string& svg_path) {
  const double cpu0 = CpuSeconds();
  auto solved = SolveRoom(room, options);
  const double cpu = CpuSeconds() - cpu0;
  if (!solved.ok()) {
    std::fprintf(stderr, "%s\n", solved.error().c_str());
    std::exit(1);
  }
  const SolveSummary& s = solved->summary;
  if (g_verbose) {
    std::printf("== %s\n%s", label.c_str(), s.BriefReport().c_str());
    for (const std::string& f : s.energy.findings) std::printf("  %s\n", f.c_str());
    for (const std::string& f : s.log) std::printf("  %s\n", f.c_str());
    for (const ActionResult& a : s.actions) std::printf("  action %s\n", ActionResultToJson(a).dump().c_str());
  }
  // The parts as shares of the solve's wall time, applied to its CPU time.
  const double share = s.seconds > 0.0 ? cpu / s.seconds : 1.0;
  Run r;
  r.seconds = cpu;
  r.ceres = s.seconds_ceres * share;
  r.exact = s.seconds_exact * share;
  r.place = s.seconds_place * share;
  r.objects = s.metrics.objects;
  r.removed = static_cast<int>(s.removed.size());
  r.converged = s.outcome == Outcome::kConverged;
  r.clean = s.metrics.Clean();
  r.cr = s.metrics.cr;
  r.fr = s.metrics.fr;
  r.obr = s.metrics.obr;
  r.csr = s.metrics.csr;
  if (!svg_path.empty()) {
    // Top view: floor, keep-outs, footprints (floor objects blue, hung green, small objects orange).
    const double k = 100.0;
    std::string out = "<svg xmlns='http://www.w3.org/2000/svg' width='1000' height='1000' viewBox='-50 -950 1000 1000'>\n";
    auto poly = [&](const Ring& ring, const char* style) {
      out += "<polygon style='" + std::string(style) + "' points='";
      for (Point p : ring) out += std::to_string(p.x * k) + "," + std::to_string(-p.y * k) + " ";
      out += "'/>\n";
    };
    poly(room.free_floor, "fill:#eee;stroke:#000;stroke-width:2");
    for (const KeepOut& z : room.keep_outs) poly(z.polygon, "fill:rgba(255,0,0,0.2);stroke:red");
    for (size_t i = 0; i < solved->objects.size(); ++i) {
      const ProblemObject& o = solved->objects[i];
      const Pose& p = solved->placements[i].pose;
      const double hx = 0.5 * o.asset.size.x * p.scale, hy = 0.5 * o.asset.size.y * p.scale;
      const double c = std::cos(p.yaw), s2 = std::sin(p.yaw);
      Ring ring;
      for (auto [sx, sy] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
        ring.push_back({p.x + c * sx * hx - s2 * sy * hy, p.y + s2 * sx * hx + c * sy * hy});
      }
      const bool child = o.parent != "floor" && o.parent != "wall" && o.parent != "ceiling";
      poly(ring, child ? "fill:rgba(255,140,0,0.5);stroke:#a50" : o.parent == "floor" ? "fill:rgba(0,0,255,0.25);stroke:blue"
                                                                                    : "fill:none;stroke:green;stroke-dasharray:4");
      if (!child) {
        const Point front{p.x + std::sin(p.yaw) * hy, p.y - std::cos(p.yaw) * hy};
        out += "<line x1='" + std::to_string(p.x * k) + "' y1='" + std::to_string(-p.y * k) + "' x2='" + std::to_string(front.x * k) +
               "' y2='" + std::to_string(-front.y * k) + "' stroke='black'/>\n";
        out += "<text font-size='11' x='" + std::to_string(p.x * k - 20) + "' y='" + std::to_string(-p.y * k) + "'>" +
               o.id.substr(o.id.rfind('/') + 1) + "</text>\n";
      }
    }
    out += "</svg>\n";
    std::ofstream(svg_path) << out;
  }
  return r;
}

// Drops objects from the end (children come after their parents) until at most n remain.
RoomProblem TrimTo(RoomProblem room, size_t n) {
  while (room.objects.size() > n) {
    const std::string id = room.objects.back().id;
    room.objects.pop_back();
    std::erase_if(room.edges, [&](const SemanticEdge& e) { return e.source == id || e.target == id; });
  }
  return room;
}

double Mean(const std::vector<Run>& runs, double Run::*field) {
  double s = 0;
  for (const Run& r : runs) s += r.*field;
  return runs.empty() ? 0.0 : s / runs.size();
}
double Max(const std::vector<Run>& runs, double Run::*field) {
  double m = 0;
  for (const Run& r : runs) m = std::max(m, r.*field);
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  int seeds = 3;
  std::string svg_dir;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--seeds" && i + 1 < argc) {
      seeds = std::max(1, std::atoi(argv[++i]));
    } else if (a == "--verbose") {
      g_verbose = true;
    } else if (a == "--svg" && i + 1 < argc) {
      svg_dir = argv[++i];
      std::filesystem::create_directories(svg_dir);
    } else {
      std::fprintf(stderr, "usage: villa_bench_solver [--seeds N] [--svg DIR] [--verbose]\n");
      return 2;
    }
  }
  const SolveOptions options;

  // 1. Every room type, three shapes, `seeds` seeds.
  TextTable by_type({"room type", "rooms", "mean NO", "mean s", "max s", "converged", "CR max", "FR max", "OBR max",
                     "CSR min", "removed"});
  std::vector<Run> all;
  for (fixtures::RoomType type : fixtures::kRoomTypes) {
    std::vector<Run> runs;
    int removed = 0;
    for (fixtures::RoomShape shape : {fixtures::RoomShape::kRectangle, fixtures::RoomShape::kL, fixtures::RoomShape::kAngled}) {
      for (int seed = 0; seed < seeds; ++seed) {
        const RoomProblem room = fixtures::SyntheticRoom(type, shape, seed);
        SolveOptions o = options;
        o.seed = seed;
        const std::string label =
            std::string(fixtures::RoomTypeName(type)) + "-" + fixtures::RoomShapeName(shape) + "-" + std::to_string(seed);
        runs.push_back(Solve(room, o, label, svg_dir.empty() ? "" : svg_dir + "/" + label + ".svg"));
        removed += runs.back().removed;
      }
    }
    int converged = 0;
    double no = 0;
    for (const Run& r : runs) {
      converged += r.converged;
      no += r.objects;
    }
    double csr_min = 1.0;
    for (const Run& r : runs) csr_min = std::min(csr_min, r.csr);
    by_type.AddRow({fixtures::RoomTypeName(type), std::to_string(runs.size()), FormatFixed(no / runs.size(), 1),
                    FormatFixed(Mean(runs, &Run::seconds), 3), FormatFixed(Max(runs, &Run::seconds), 3),
                    std::to_string(converged) + "/" + std::to_string(runs.size()), FormatFixed(Max(runs, &Run::cr), 3),
                    FormatFixed(Max(runs, &Run::fr), 3), FormatFixed(Max(runs, &Run::obr), 3), FormatFixed(csr_min, 3),
                    std::to_string(removed)});
    all.insert(all.end(), runs.begin(), runs.end());
  }
  std::printf("Rooms by type (3 shapes x %d seeds each), one core:\n%s\n", seeds, by_type.Render().c_str());
  const double mean = Mean(all, &Run::seconds);
  std::printf("all %zu rooms: mean %.3f s a room, max %.3f s; the paper's ~900 s a room is %.0fx the mean\n\n", all.size(),
              mean, Max(all, &Run::seconds), kPaperSecondsPerRoom / mean);

  // 2. Growth with the object count: living rooms grown and trimmed to N objects.
  TextTable growth({"objects", "rooms", "mean s", "ms/object", "placement s", "ceres s", "exact s", "exact share", "converged",
                    "CR max", "CSR min"});
  TextTable linear({"objects", "dense QR: ceres s", "sparse Cholesky: ceres s", "dense / sparse", "dense s total",
                    "sparse s total"});
  for (int n : {10, 20, 40, 80}) {
    std::vector<Run> runs, dense, sparse;
    for (int seed = 0; seed < seeds; ++seed) {
      const RoomProblem room = TrimTo(fixtures::SyntheticRoom(fixtures::RoomType::kLiving, fixtures::RoomShape::kRectangle, seed,
                                                              std::max(1.0, n / 34.0 * 1.15)), n);
      SolveOptions o = options;
      o.seed = seed;
      const std::string label = std::to_string(n) + " objects, seed " + std::to_string(seed);
      runs.push_back(Solve(room, o, label, ""));
      o.linear_solver = LinearSolverChoice::kDenseQr;
      dense.push_back(Solve(room, o, label + ", dense", ""));
      o.linear_solver = LinearSolverChoice::kSparseNormalCholesky;
      sparse.push_back(Solve(room, o, label + ", sparse", ""));
    }
    int converged = 0;
    double csr_min = 1.0;
    for (const Run& r : runs) {
      converged += r.converged;
      csr_min = std::min(csr_min, r.csr);
    }
    const double s = Mean(runs, &Run::seconds);
    growth.AddRow({std::to_string(n), std::to_string(runs.size()), FormatFixed(s, 3), FormatFixed(1000.0 * s / n, 2),
                   FormatFixed(Mean(runs, &Run::place), 3), FormatFixed(Mean(runs, &Run::ceres), 3),
                   FormatFixed(Mean(runs, &Run::exact), 3), FormatPercent(Mean(runs, &Run::exact), s),
                   std::to_string(converged) + "/" + std::to_string(runs.size()), FormatFixed(Max(runs, &Run::cr), 3),
                   FormatFixed(csr_min, 3)});
    const double dc = Mean(dense, &Run::ceres), sc = Mean(sparse, &Run::ceres);
    linear.AddRow({std::to_string(n), FormatFixed(dc, 4), FormatFixed(sc, 4), FormatFixed(sc > 0 ? dc / sc : 0.0, 2),
                   FormatFixed(Mean(dense, &Run::seconds), 3), FormatFixed(Mean(sparse, &Run::seconds), 3)});
  }
  std::printf("Growth with the object count (living rooms grown to hold them), automatic linear solver:\n%s\n",
              growth.Render().c_str());
  std::printf("Linear solver, the same rooms forced dense or sparse:\n%s", linear.Render().c_str());
  return 0;
}
