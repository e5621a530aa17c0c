// Scene planning speed: a room's context (free floor, walls, keep-outs) and its A-PSSG from the priors,
// per room, single thread. Layouts: the bundled examples and the reference dataset's test split (50
// layouts, about 500 rooms), or the JSONL / layout files given. Figures are thread CPU time, so a busy
// machine slows them less; each room is planned with 5 seeds.
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "building/building.h"
#include "layout/layout_io.h"
#include "scene/planner.h"
#include "scene/room_context.h"

using namespace villa;
using namespace villa::scene;

namespace {

double CpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

std::vector<Layout> LoadCorpus(const std::vector<std::string>& files) {
  std::vector<Layout> out;
  for (const std::string& file : files) {
    if (file.size() > 6 && file.compare(file.size() - 6, 6, ".jsonl") == 0) {
      std::ifstream in(file);
      std::string line;
      while (std::getline(in, line)) {
        auto record = nlohmann::json::parse(line, nullptr, false);
        if (!record.is_object() || !record.contains("messages")) continue;
        auto layout = ParseLayoutText(record["messages"][2]["content"].get<std::string>(), file);
        if (layout) out.push_back(*layout);
      }
    } else if (auto layout = LoadLayout(file)) {
      out.push_back(*layout);
    }
  }
  return out;
}

struct Figures {
  std::vector<double> context_us;
  std::vector<double> plan_us;
  double objects = 0.0;
  int plans = 0;
};

double Median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double Percentile95(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, v.size() * 95 / 100)];
}

}  // namespace

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  const fs::path root = VILLA_SOURCE_DIR;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) files.push_back(argv[i]);
  if (files.empty()) {
    for (const auto& entry : fs::directory_iterator(root / "examples"))
      if (entry.path().extension() == ".json") files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    files.push_back((root / "datasets/villa-1k/test.jsonl").string());
  }
  std::vector<Layout> layouts = LoadCorpus(files);
  std::map<std::string, Figures> by_type;
  Figures all;
  double build_s = 0.0;
  int rooms = 0;
  for (const Layout& layout : layouts) {
    BuildOptions options;
    double t0 = CpuSeconds();
    auto building = BuildBuilding(layout, options);
    build_s += CpuSeconds() - t0;
    if (!building) continue;
    for (const Room& room : layout.rooms) {
      t0 = CpuSeconds();
      auto context = RoomContextOf(layout, *building, options, room.name());
      double context_us = 1e6 * (CpuSeconds() - t0);
      if (!context) continue;
      ++rooms;
      Figures& f = by_type[std::string(CategoryName(room.category))];
      f.context_us.push_back(context_us);
      all.context_us.push_back(context_us);
      for (uint64_t seed = 1; seed <= 5; ++seed) {
        t0 = CpuSeconds();
        auto plan = PriorsPlanner().Plan({&*context, "", seed});
        double plan_us = 1e6 * (CpuSeconds() - t0);
        if (!plan) continue;
        for (Figures* g : {&f, &all}) {
          g->plan_us.push_back(plan_us);
          g->objects += plan->objects.size();
          ++g->plans;
        }
      }
    }
  }
  std::printf("%zu layouts, %d rooms, %d plans; building %.2f ms a layout (thread CPU time)\n", layouts.size(), rooms,
              all.plans, layouts.empty() ? 0.0 : 1e3 * build_s / layouts.size());
  std::printf("%-16s %6s %8s %14s %12s %12s %10s\n", "room type", "rooms", "objects", "context med us",
              "plan med us", "plan p95 us", "us/object");
  auto row = [](const std::string& name, const Figures& f) {
    double objects = f.plans ? f.objects / f.plans : 0.0;
    double plan = Median(f.plan_us);
    std::printf("%-16s %6zu %8.1f %14.0f %12.0f %12.0f %10.1f\n", name.c_str(), f.context_us.size(), objects,
                Median(f.context_us), plan, Percentile95(f.plan_us), objects > 0 ? plan / objects : 0.0);
  };
  for (const auto& [name, f] : by_type) row(name, f);
  row("all", all);
  return 0;
}
