// The asset library: import of Debian's whole sweethome3d-furniture (five .sh3f archives, 820 models) and
// retrieval over the result. Import: models per second on one thread (thread CPU time and wall time) and
// on every core (wall time); what the library then holds. Retrieval: building the index (embedding every
// asset) and ranking one query, single thread, offline lexical embedder.
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "assets/asset_library.h"
#include "assets/category.h"
#include "assets/retrieval.h"
#include "assets/sh3d_import.h"
#include "util/atomic_file.h"

namespace {

double ThreadSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + t.tv_nsec * 1e-9;
}

double WallSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  const fs::path from = argc > 1 ? fs::path(argv[1]) : villa::DefaultSh3dFurnitureDir();
  if (!fs::exists(from)) {
    std::fprintf(stderr, "%s: not there (install sweethome3d-furniture, or name a folder of .sh3f files)\n", from.c_str());
    return 1;
  }
  const fs::path dir = fs::temp_directory_path() / ("villa-bench-assets-" + std::to_string(::getpid()));
  fs::remove_all(dir);

  // ---- import, one thread (thread CPU time is what this thread spent; wall time includes waiting)
  villa::Sh3dImportOptions options;
  options.threads = 1;
  double cpu0 = ThreadSeconds(), wall0 = WallSeconds();
  auto one = villa::ImportSh3dLibraries(from, dir / "one", options);
  double cpu = ThreadSeconds() - cpu0, wall = WallSeconds() - wall0;
  if (!one.ok()) {
    std::fprintf(stderr, "%s\n", one.error().c_str());
    return 1;
  }
  const int models = one->models_read;
  std::printf("import of %s: %d archives, %d models\n", from.c_str(), one->archives, models);
  std::printf("  1 thread : %6.1f s thread CPU (%5.1f models/s), %6.1f s wall (%5.1f models/s)\n", cpu, models / cpu, wall,
              models / wall);
  options.threads = 0;
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  wall0 = WallSeconds();
  auto all = villa::ImportSh3dLibraries(from, dir / "all", options);
  wall = WallSeconds() - wall0;
  if (!all.ok()) {
    std::fprintf(stderr, "%s\n", all.error().c_str());
    return 1;
  }
  std::printf("  %u threads: %6.1f s wall (%5.1f models/s)\n", cores, wall, models / wall);
  bool same = *villa::ReadFile(dir / "one" / "assets.jsonl") == *villa::ReadFile(dir / "all" / "assets.jsonl");
  std::printf("  records identical across thread counts: %s\n", same ? "yes" : "NO");

  // ---- what the library holds
  auto library = villa::AssetLibrary::Open(dir / "one");
  if (!library.ok()) {
    std::fprintf(stderr, "%s\n", library.error().c_str());
    return 1;
  }
  auto report = nlohmann::json::parse(*villa::ReadFile(dir / "one" / "import-report.json"));
  std::vector<int> source;
  for (const auto& m : report["models"])
    if (m.contains("source_triangles") && m["outcome"] == "imported") source.push_back(m["source_triangles"]);
  std::sort(source.begin(), source.end());
  int in_vocabulary = 0, with_surface = 0, with_cavity = 0;
  std::map<std::string, int> placements;
  for (const villa::AssetRecord& r : library->records()) {
    in_vocabulary += villa::FindCategory(r.category) != nullptr;
    with_surface += !r.support_surfaces.empty();
    with_cavity += !r.cavities.empty();
    ++placements[std::string(villa::PlacementName(r.placement))];
  }
  const int n = static_cast<int>(library->records().size());
  std::printf("  imported %d, skipped %d (%d unreadable), decimated %d; watertight %d (%.1f%%)\n", one->imported, one->skipped,
              one->failed, one->decimated, one->watertight, 100.0 * one->watertight / std::max(1, n));
  if (!source.empty())
    std::printf("  source triangles: median %d, largest %d\n", source[source.size() / 2], source.back());
  std::printf("  in the vocabulary: %d (%.1f%%); with support surfaces: %d; with cavities: %d\n", in_vocabulary,
              100.0 * in_vocabulary / std::max(1, n), with_surface, with_cavity);
  std::printf("  placement:");
  for (const auto& [p, count] : placements) std::printf(" %s %d", p.c_str(), count);
  std::printf("\n");

  // ---- retrieval
  auto embedder = std::make_shared<villa::LexicalEmbedder>();
  cpu0 = ThreadSeconds();
  auto retriever = villa::AssetRetriever::Build(library->records(), embedder);
  double build = ThreadSeconds() - cpu0;
  if (!retriever.ok()) {
    std::fprintf(stderr, "%s\n", retriever.error().c_str());
    return 1;
  }
  std::vector<villa::RetrievalQuery> queries;
  for (const villa::CategoryInfo& c : villa::Categories()) {
    villa::RetrievalQuery q;
    q.text = c.words.empty() ? std::string(c.name) : std::string(c.words.front());
    queries.push_back(q);
  }
  int rounds = 0;
  cpu0 = ThreadSeconds();
  double elapsed = 0;
  std::size_t sink = 0;
  do {
    for (const auto& q : queries) sink += retriever->Rank(q)->ranked.size();
    ++rounds;
    elapsed = ThreadSeconds() - cpu0;
  } while (elapsed < 1.0);
  std::printf("retrieval over %d assets (lexical embedder, %s):\n", n, embedder->Name().c_str());
  std::printf("  index build (embed every asset): %.1f ms thread CPU\n", build * 1e3);
  std::printf("  one query (embed + rank + top 5): %.0f us thread CPU, %zu queries\n",
              elapsed * 1e6 / (rounds * queries.size()), static_cast<std::size_t>(rounds * queries.size()));
  fs::remove_all(dir);
  return sink > 0 ? 0 : 1;
}
