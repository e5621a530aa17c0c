// SynthesizeDataset (the library behind `villa synth`): the files it writes, the manifest's checksum and
// recipe, the preview hook, and refusing a folder it may not write into.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "partitioner/dataset.h"
#include "util/atomic_file.h"
#include "util/hash.h"

using namespace villa;
namespace fs = std::filesystem;

// CheckSynthOutput as a number: -1 refused, 0 to write, 1 already done.
int Done(const SynthOptions& options) {
  const Result<bool> r = CheckSynthOutput(options);
  return r.ok() ? (*r ? 1 : 0) : -1;
}

TEST_CASE("a synthesized dataset holds its layouts, stats and a manifest with the layouts' checksum", "[synth]") {
  const fs::path dir = fs::temp_directory_path() / ("villa_dataset_test_" + std::to_string(getpid()));
  fs::remove_all(dir);
  SynthOptions options;
  options.count = 5;
  options.seed = 3;
  options.threads = 2;
  options.previews = 2;
  options.floors_text = "1:1:1";
  options.floor_weights[0] = options.floor_weights[1] = options.floor_weights[2] = 1.0;
  options.out = dir;
  std::string problem;
  REQUIRE(options.IsValid(&problem));
  REQUIRE(Done(options) == 0);
  std::vector<std::string> titles;
  const PreviewWriter preview = [&](const Layout& layout, const std::string& title, const fs::path& png) {
    titles.push_back(title);
    CHECK(!layout.rooms.empty());
    return WriteFileAtomic(png, "not really a png");
  };
  std::atomic<std::size_t> progress{0};  // called from the worker threads
  auto summary = SynthesizeDataset(options, preview, [&](std::size_t n) { progress += n; });
  REQUIRE(summary.ok());
  CHECK(summary->ok());
  CHECK(summary->stats.layouts == 5);
  CHECK(progress.load() == 5);
  REQUIRE(titles.size() == 2);
  CHECK(titles[0].rfind("villa-000000 (", 0) == 0);
  CHECK(summary->preview_files == std::vector<std::string>{"previews/villa-000000.png", "previews/villa-000001.png"});
  for (const auto& f : summary->preview_files) CHECK(fs::exists(dir / f));
  auto layouts = ReadFile(dir / "layouts.jsonl");
  REQUIRE(layouts.ok());
  CHECK(std::count(layouts->begin(), layouts->end(), '\n') == 5);
  char hex[32];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(Fnv1a64(*layouts)));
  auto manifest = ReadFile(dir / "manifest.json");
  REQUIRE(manifest.ok());
  const Json m = Json::parse(*manifest);
  CHECK(m == summary->manifest);
  CHECK(m["files"]["layouts.jsonl"]["fnv1a64"] == hex);
  CHECK(m["files"]["layouts.jsonl"]["records"] == 5);
  CHECK(m["regenerate"] == "villa synth --count 5 --seed 3 --floors 1:1:1 --grid 0.5 --shard 0/1 --out DIR");
  CHECK(fs::exists(dir / "stats.json"));
  // A second run of the same recipe finds the shard done; another recipe is another dataset (force
  // replaces it); a stranger's file in the folder is refused.
  CHECK(Done(options) == 1);
  CHECK(VerifySynthFolder(dir).ok());
  options.seed = 4;
  const Result<bool> other = CheckSynthOutput(options);
  REQUIRE_FALSE(other.ok());
  CHECK(other.error().find(": holds another dataset (its manifest's recipe is {\"count\":5,") != std::string::npos);
  options.force = true;
  CHECK(Done(options) == 0);
  options.force = false;
  options.seed = 3;
  // A torn run (layouts.jsonl changed after the manifest) is redone, not kept.
  REQUIRE(WriteFileAtomic(dir / "layouts.jsonl", layouts->substr(0, layouts->size() / 2)).ok());
  CHECK(VerifySynthFolder(dir).error().find("differs from the manifest's") != std::string::npos);
  CHECK(Done(options) == 0);
  REQUIRE(WriteFileAtomic(dir / "notes.txt", "mine").ok());
  const Result<bool> again = CheckSynthOutput(options);
  REQUIRE_FALSE(again.ok());
  CHECK(again.error() == "--out " + dir.string() + ": directory is not empty (use --force to write into it)");
  options.force = true;
  // Previews without a writer are an error, not a crash.
  options.previews = 1;
  CHECK_FALSE(SynthesizeDataset(options, nullptr, nullptr).ok());
  fs::remove_all(dir);
}
