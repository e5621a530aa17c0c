// `villa scenes` and `villa dataset merge|verify|status` on three single-storey villas (critic, physics
// and reachability off to keep it quick: the furnishing itself is tested elsewhere): shards merged equal
// the one-machine run file for file, a torn villa is redone and the rest kept, foreign, missing, doubled
// and unfinished shards are refused, a changed file is found.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "layout/layout_io.h"
#include "partitioner/dataset.h"
#include "shards/dataset_tools.h"
#include "shards/scenes.h"
#include "util/atomic_file.h"
#include "villa_cli.h"

using namespace villa;
namespace fs = std::filesystem;

namespace {

struct Folder {
  fs::path path;
  explicit Folder(const std::string& name) : path(fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~Folder() { fs::remove_all(path); }
};

// Three single-storey layouts as `villa synth --count 3 --seed 5 --floors 1:0:0` writes them.
fs::path SynthLayouts(const fs::path& dir) {
  SynthOptions o;
  o.count = 3;
  o.seed = 5;
  o.floor_weights[0] = 1, o.floor_weights[1] = 0, o.floor_weights[2] = 0;
  o.floors_text = "1:0:0";
  o.threads = 1;
  o.out = dir / "synth";
  REQUIRE(SynthesizeDataset(o, nullptr, nullptr).ok());
  return dir / "synth" / "layouts.jsonl";
}

shards::ScenesOptions Quick(const fs::path& input, const fs::path& out, Shard shard) {
  shards::ScenesOptions o;
  o.input = input;
  o.out = out;
  o.shard = shard;
  o.seed = 3;
  o.critic = "none";
  o.furnish.procedural_only = true;
  o.furnish.check_physics = false;
  o.furnish.check_reach = false;
  o.furnish.pictures = false;
  o.furnish.jobs = 2;
  return o;
}

std::string Bytes(const fs::path& p) {
  auto b = ReadFile(p);
  REQUIRE(b.ok());
  return *b;
}

// The index's lines without their timing.
std::vector<shards::Json> IndexWithoutSeconds(const fs::path& dir) {
  std::vector<shards::Json> lines;
  std::istringstream in(Bytes(dir / "scenes.jsonl"));
  for (std::string line; std::getline(in, line);) {
    shards::Json j = shards::Json::parse(line);
    j.erase("seconds");
    lines.push_back(j);
  }
  return lines;
}

}  // namespace

TEST_CASE("scenes shards merged equal the one-machine run, reruns keep verified villas and redo torn ones", "[shards][scenes]") {
  Folder tmp("villa_scenes_test");
  const fs::path layouts = SynthLayouts(tmp.path);

  auto one = shards::RunScenesShard(Quick(layouts, tmp.path / "one", {0, 1}));
  REQUIRE(one.ok());
  CHECK((one->total == 3 && one->done == 3 && one->skipped == 0 && one->failed == 0 && one->complete));
  for (const char* f : {"layout.json", "scene.json", "furnished.glb", "report.json", "entry.json"})
    CHECK(fs::is_regular_file(tmp.path / "one/scenes/villa-000001" / f));
  REQUIRE(shards::VerifyDataset(tmp.path / "one").ok());

  // Two shards (1 + 2 villas), merged in either order of arguments.
  auto a = shards::RunScenesShard(Quick(layouts, tmp.path / "s0", {0, 2}));
  auto b = shards::RunScenesShard(Quick(layouts, tmp.path / "s1", {1, 2}));
  REQUIRE((a.ok() && b.ok()));
  CHECK((a->total == 1 && b->total == 2));
  auto merged = shards::MergeShards(tmp.path / "merged", {tmp.path / "s1", tmp.path / "s0"});
  REQUIRE(merged.ok());
  CHECK((merged->kind == "scenes" && merged->records == 3 && merged->shards == 2));
  auto verified = shards::VerifyDataset(tmp.path / "merged");
  REQUIRE(verified.ok());
  CHECK(verified->records == 3);
  // File for file: every villa's files the same bytes (the entries differ only in their seconds), the index
  // the same but for the seconds.
  int compared = 0;
  for (const auto& e : fs::recursive_directory_iterator(tmp.path / "one/scenes")) {
    if (!e.is_regular_file() || e.path().filename() == "entry.json") continue;
    const fs::path rel = fs::relative(e.path(), tmp.path / "one");
    INFO(rel.string());
    CHECK(Bytes(e.path()) == Bytes(tmp.path / "merged" / rel));
    ++compared;
  }
  CHECK(compared == 15);
  CHECK(IndexWithoutSeconds(tmp.path / "one") == IndexWithoutSeconds(tmp.path / "merged"));
  // report.json carries no timing (so that it is the same on every run).
  CHECK(Bytes(tmp.path / "one/scenes/villa-000000/report.json").find("\"seconds\"") == std::string::npos);

  // A rerun keeps the verified villas; a torn one (a changed glb) and a temporary left by a kill are redone.
  const fs::path glb = tmp.path / "s1/scenes/villa-000002/furnished.glb";
  const std::string good = Bytes(glb);
  REQUIRE(WriteFileAtomic(glb, good.substr(0, good.size() / 2)).ok());
  fs::create_directories(tmp.path / "s1/scenes/.tmp-villa-000002-99");
  auto broken = shards::VerifyDataset(tmp.path / "s1");
  REQUIRE_FALSE(broken.ok());
  CHECK(broken.error().find("furnished.glb: SHA-256 ") != std::string::npos);
  auto again = shards::RunScenesShard(Quick(layouts, tmp.path / "s1", {1, 2}));
  REQUIRE(again.ok());
  CHECK((again->skipped == 1 && again->done == 1));
  CHECK(Bytes(glb) == good);
  CHECK_FALSE(fs::exists(tmp.path / "s1/scenes/.tmp-villa-000002-99"));
  CHECK(shards::VerifyDataset(tmp.path / "s1").ok());

  // Refused merges: a missing shard, one twice, a shard of another seed, into a non-empty folder.
  CHECK(shards::MergeShards(tmp.path / "m2", {tmp.path / "s1"}).error() == "missing shard(s) 0/2 of 2");
  CHECK(shards::MergeShards(tmp.path / "m2", {tmp.path / "s0", tmp.path / "s0", tmp.path / "s1"}).error().find("shard 0/2 given twice") == 0);
  shards::ScenesOptions other = Quick(layouts, tmp.path / "other", {0, 2});
  other.seed = 4;
  REQUIRE(shards::RunScenesShard(other).ok());
  auto foreign = shards::MergeShards(tmp.path / "m2", {tmp.path / "other", tmp.path / "s1"});
  REQUIRE_FALSE(foreign.ok());
  CHECK(foreign.error().find("a shard of another recipe") != std::string::npos);
  CHECK_FALSE(fs::exists(tmp.path / "m2"));
  CHECK(shards::MergeShards(tmp.path / "merged", {tmp.path / "s0", tmp.path / "s1"}).error().find("exists and is not an empty folder") !=
        std::string::npos);
  // The recipe names the build (the executable's hash): a rerun by another build is another recipe's work.
  auto recipe = shards::Json::parse(Bytes(tmp.path / "s1/manifest.json"))["recipe"];
  REQUIRE(recipe.contains("build"));
  const std::string build = recipe["build"].get<std::string>();
  CHECK(build.size() == 16);
  CHECK(build.find_first_not_of("0123456789abcdef") == std::string::npos);
  const std::string kept = Bytes(tmp.path / "s1/manifest.json");
  auto rebuilt = shards::Json::parse(kept);
  rebuilt["recipe"]["build"] = "0000000000000000";
  REQUIRE(WriteFileAtomic(tmp.path / "s1/manifest.json", rebuilt.dump(2)).ok());
  auto by_another_build = shards::RunScenesShard(Quick(layouts, tmp.path / "s1", {1, 2}));
  REQUIRE_FALSE(by_another_build.ok());
  CHECK(by_another_build.error().find("holds a shard of another recipe") != std::string::npos);
  REQUIRE(WriteFileAtomic(tmp.path / "s1/manifest.json", kept).ok());
  // Running another recipe into a shard's folder is refused without --force.
  other.out = tmp.path / "s0";
  auto clash = shards::RunScenesShard(other);
  REQUIRE_FALSE(clash.ok());
  CHECK(clash.error().find("usage: ") == 0);
  CHECK(clash.error().find("holds a shard of another recipe") != std::string::npos);

  // An unfinished shard (its manifest not complete) is not merged; status says what is left.
  auto manifest = shards::Json::parse(Bytes(tmp.path / "s0/manifest.json"));
  manifest["complete"] = false;
  REQUIRE(WriteFileAtomic(tmp.path / "s0/manifest.json", manifest.dump(2)).ok());
  CHECK(shards::MergeShards(tmp.path / "m3", {tmp.path / "s0", tmp.path / "s1"}).error().find("the shard is not complete") != std::string::npos);
  auto status = shards::DatasetStatus({tmp.path / "s1"}, 0);
  REQUIRE(status.ok());
  CHECK(status->find("complete") != std::string::npos);
}

TEST_CASE("the layouts of a synth file, an annotator export and a fine-tune export", "[shards][scenes]") {
  Folder tmp("villa_scenes_input");
  const fs::path layouts = SynthLayouts(tmp.path);
  auto synth = shards::ReadLayoutInput(layouts);
  REQUIRE(synth.ok());
  REQUIRE(synth->items.size() == 3);
  CHECK(synth->items[2].id == "villa-000002");
  const std::string layout = synth->items[0].layout_json;

  // An annotator export: a rejected layout is left out.
  {
    std::ofstream f(tmp.path / "annotated.jsonl");
    f << R"({"id":"a","status":"accepted","layout":)" << layout << "}\n";
    f << R"({"id":"b","status":"rejected","reason":"odd","layout":)" << layout << "}\n";
  }
  auto annotated = shards::ReadLayoutInput(tmp.path / "annotated.jsonl");
  REQUIRE(annotated.ok());
  CHECK((annotated->items.size() == 1 && annotated->rejected == 1 && annotated->items[0].id == "a"));

  // A fine-tune sample: the answer is the layout.
  {
    std::ofstream f(tmp.path / "train.jsonl");
    f << shards::Json{{"messages", {{{"role", "system"}, {"content", "s"}}, {{"role", "user"}, {"content", "a villa"}},
                                    {{"role", "assistant"}, {"content", layout}}}}}.dump()
      << "\n";
  }
  auto samples = shards::ReadLayoutInput(tmp.path / "train.jsonl");
  REQUIRE(samples.ok());
  CHECK(samples->items.at(0).id == "sample-1");
  CHECK(samples->items[0].layout_json == layout);

  // Errors name the file and line.
  {
    std::ofstream f(tmp.path / "twice.jsonl");
    f << R"({"id":"a","layout":)" << layout << "}\n" << R"({"id":"a","layout":)" << layout << "}\n";
  }
  CHECK(shards::ReadLayoutInput(tmp.path / "twice.jsonl").error() == (tmp.path / "twice.jsonl").string() + ":2: \"id\": \"a\" appears twice");
  {
    std::ofstream f(tmp.path / "slash.jsonl");
    f << R"({"id":"../x","layout":)" << layout << "}\n";
  }
  CHECK(shards::ReadLayoutInput(tmp.path / "slash.jsonl").error().find(":1: \"id\": \"../x\" cannot name a folder") != std::string::npos);
  {
    // A NUL in an id would cut the folder's path to scenes/ itself (and remove every villa there).
    std::ofstream f(tmp.path / "nul.jsonl");
    f << R"({"id":"a\u0000b","layout":)" << layout << "}\n";
  }
  CHECK(shards::ReadLayoutInput(tmp.path / "nul.jsonl").error().find(":1: \"id\": \"a\\x00b\" cannot name a folder") != std::string::npos);
  CHECK(shards::ReadLayoutInput(tmp.path / "none.jsonl").error().find("none.jsonl: no such file") != std::string::npos);
}

TEST_CASE("villa synth and villa dataset on the command line: shards merged byte-identical, a done shard skipped", "[shards][cli]") {
  Folder tmp("villa_dataset_cli");
  const std::string d = tmp.path.string();
  REQUIRE(testing::RunVilla("synth --count 300 --seed 9 --out " + d + "/one").status == 0);
  for (int i = 0; i < 3; ++i) {
    // As a Slurm array task with IDs 1..3 would.
    const std::string env = "SLURM_ARRAY_TASK_ID=" + std::to_string(i + 1) + " SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_COUNT=3 ";
    auto run = testing::RunVilla("synth --count 300 --seed 9 --shard auto --out " + d + "/s" + std::to_string(i));
    CHECK(run.status == 2);  // no Slurm variables in this process: a usage error that says so
    CHECK(run.out.find("neither SLURM_ARRAY_TASK_ID") != std::string::npos);
    REQUIRE(std::system((env + VILLA_BINARY + " synth --count 300 --seed 9 --shard auto --out " + d + "/s" + std::to_string(i) + " > /dev/null").c_str()) == 0);
  }
  auto skipped = testing::RunVilla("synth --count 300 --seed 9 --shard 1/3 --out " + d + "/s1");
  CHECK(skipped.status == 0);
  CHECK(skipped.out.find("is already done") != std::string::npos);
  auto merged = testing::RunVilla("dataset merge " + d + "/m " + d + "/s2 " + d + "/s0 " + d + "/s1");
  REQUIRE(merged.status == 0);
  CHECK(merged.out == "merged 3 synth shard(s): 300 layouts in " + d + "/m\n");
  CHECK(Bytes(tmp.path / "m/layouts.jsonl") == Bytes(tmp.path / "one/layouts.jsonl"));
  CHECK(Bytes(tmp.path / "m/manifest.json") == Bytes(tmp.path / "one/manifest.json"));
  CHECK(testing::RunVilla("dataset verify " + d + "/m").out == d + "/m: synth dataset verified: 300 layouts\n");
  auto missing = testing::RunVilla("dataset merge " + d + "/m2 " + d + "/s0 " + d + "/s1");
  CHECK(missing.status == 1);
  CHECK(missing.out == "villa dataset merge: missing shard(s) 2/3 of 3\n");
  // An empty output name is a usage error for every command that writes (issue 33), not a failure to make "".
  for (const std::string& args : std::vector<std::string>{"scenes " + d + "/one/layouts.jsonl --out ''", "synth --count 2 --out ''",
                                  "furnish " + std::string(VILLA_SOURCE_DIR) + "/examples/l-shaped-house.json -o ''",
                                  "generate 'a small villa' -o ''", "plan 'a small villa' -o ''"}) {
    auto empty = testing::RunVilla(args);
    INFO(args << "\n" << empty.out);
    CHECK(empty.status == 2);
    CHECK(empty.out.find("an empty name is no file or folder") != std::string::npos);
  }
  auto status = testing::RunVilla("dataset status " + d);
  CHECK(status.status == 0);
  CHECK(status.out.find(" 5 shard(s) ") != std::string::npos);
}
