// `villa synth` end to end through the real binary (VILLA_BINARY): files, determinism across threads and
// shards, the exact floors ratio, refusal of a non-empty directory, bad flags.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "bad_flags.h"
#include "layout/footprint.h"
#include "layout/layout_io.h"
#include "layout/validate.h"

namespace fs = std::filesystem;

namespace {

struct Run {
  int code = -1;
  std::string output;
};

Run Villa(const std::string& args) {
  Run run;
  const std::string command = std::string("'") + VILLA_BINARY + "' " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  REQUIRE(pipe != nullptr);
  char buffer[4096];
  std::size_t n;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) run.output.append(buffer, n);
  const int status = pclose(pipe);
  run.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

std::string Slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

struct TempDir {
  fs::path path;
  TempDir() {
    path = fs::temp_directory_path() / ("villa-synth-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
  static inline int counter = 0;
};

}  // namespace

TEST_CASE("villa synth writes valid records with the exact floors ratio", "[partitioner][synth]") {
  TempDir tmp;
  const fs::path out = tmp.path / "ds";
  const Run run = Villa("synth --count 50 --seed 7 --floors 2:4:4 --threads 2 --out '" + out.string() + "'");
  INFO(run.output);
  REQUIRE(run.code == 0);
  CHECK(run.output.find("layouts: 50") != std::string::npos);
  REQUIRE(fs::exists(out / "layouts.jsonl"));
  REQUIRE(fs::exists(out / "manifest.json"));
  REQUIRE(fs::exists(out / "stats.json"));
  std::map<int, int> floors;
  int lines = 0;
  std::set<std::string> shapes;
  villa::Status status = villa::ReadJsonl(out / "layouts.jsonl", [&](const villa::Json& record, int line) {
    // Keys in the contract's order.
    std::vector<std::string> keys;
    for (auto it = record.begin(); it != record.end(); ++it) keys.push_back(it.key());
    CHECK(keys == std::vector<std::string>{"id", "seed", "shape", "floors", "layout"});
    char id[32];
    std::snprintf(id, sizeof id, "villa-%06d", lines);
    CHECK(record.at("id").get<std::string>() == id);
    auto layout = villa::LayoutFromRecord(record, "line " + std::to_string(line));
    REQUIRE(layout.ok());
    CHECK(villa::ValidateLayout(*layout).valid());
    CHECK(layout->LevelCount() == record.at("floors").get<int>());
    ++floors[record.at("floors").get<int>()];
    shapes.insert(record.at("shape").get<std::string>());
    ++lines;
    return true;
  });
  REQUIRE(status.ok());
  CHECK(lines == 50);
  CHECK(floors[1] == 10);
  CHECK(floors[2] == 20);
  CHECK(floors[3] == 20);
  for (const std::string& s : shapes) CHECK(villa::ParseShapeClass(s).has_value());

  const villa::Json manifest = villa::Json::parse(Slurp(out / "manifest.json"));
  CHECK(manifest.at("command") == "synth");
  CHECK(manifest.at("recipe").at("count") == 50);
  CHECK(manifest.at("recipe").at("seed") == 7);
  CHECK(!manifest.at("version").get<std::string>().empty());
  const villa::Json stats = villa::Json::parse(Slurp(out / "stats.json"));
  CHECK(stats.at("layouts") == 50);
  CHECK(stats.at("validated") == 50);
  CHECK(stats.at("floors").at("2") == 20);
}

TEST_CASE("villa synth output is identical for any thread count and across shards", "[partitioner][synth]") {
  TempDir tmp;
  const std::string common = "synth --count 37 --seed 11 ";
  REQUIRE(Villa(common + "--threads 1 --out '" + (tmp.path / "t1").string() + "'").code == 0);
  REQUIRE(Villa(common + "--threads 2 --out '" + (tmp.path / "t2").string() + "'").code == 0);
  REQUIRE(Villa(common + "--threads 3 --out '" + (tmp.path / "t3").string() + "'").code == 0);
  const std::string one = Slurp(tmp.path / "t1" / "layouts.jsonl");
  CHECK(!one.empty());
  CHECK(one == Slurp(tmp.path / "t2" / "layouts.jsonl"));
  CHECK(one == Slurp(tmp.path / "t3" / "layouts.jsonl"));
  std::string joined;
  for (int i = 0; i < 3; ++i) {
    const fs::path dir = tmp.path / ("s" + std::to_string(i));
    REQUIRE(Villa(common + "--threads 2 --shard " + std::to_string(i) + "/3 --out '" + dir.string() + "'").code == 0);
    joined += Slurp(dir / "layouts.jsonl");
  }
  CHECK(joined == one);
  // Another seed, another dataset.
  REQUIRE(Villa("synth --count 37 --seed 12 --out '" + (tmp.path / "other").string() + "'").code == 0);
  CHECK(Slurp(tmp.path / "other" / "layouts.jsonl") != one);
}

TEST_CASE("villa synth refuses a non-empty directory without --force", "[partitioner][synth]") {
  TempDir tmp;
  std::ofstream(tmp.path / "notes.txt") << "mine";
  const Run refused = Villa("synth --count 3 --out '" + tmp.path.string() + "'");
  CHECK(refused.code == 2);
  CHECK(refused.output.find("not empty") != std::string::npos);
  CHECK(!fs::exists(tmp.path / "layouts.jsonl"));
  const Run forced = Villa("synth --count 3 --force --out '" + tmp.path.string() + "'");
  CHECK(forced.code == 0);
  CHECK(fs::exists(tmp.path / "layouts.jsonl"));
  CHECK(Slurp(tmp.path / "notes.txt") == "mine");  // the user's file is untouched
  // No temporaries left behind.
  for (const auto& entry : fs::directory_iterator(tmp.path)) {
    const std::string name = entry.path().filename().string();
    CHECK((name == "notes.txt" || name == "layouts.jsonl" || name == "manifest.json" || name == "stats.json"));
  }
}

TEST_CASE("villa synth --shapes makes only the classes named, in their shares, and the manifest says how",
          "[partitioner][synth]") {
  TempDir tmp;
  const fs::path out = tmp.path / "ds";
  const Run run = Villa("synth --count 40 --seed 5 --shapes hexagon=1,angled-wing=3 --out '" + out.string() + "'");
  INFO(run.output);
  REQUIRE(run.code == 0);
  std::map<std::string, int> shapes;
  std::ifstream in(out / "layouts.jsonl");
  for (std::string line; std::getline(in, line);) {
    const villa::Json record = villa::Json::parse(line);
    ++shapes[record.at("shape").get<std::string>()];
    // The record's class is the geometry's.
    const auto layout = villa::LayoutFromRecord(record, "layouts.jsonl");
    REQUIRE(layout.ok());
    CHECK(std::string(villa::ShapeClassName(villa::ClassifyFootprint(*layout, 0).value())) == record.at("shape"));
  }
  CHECK(shapes.size() == 2);
  CHECK(shapes["hexagon"] + shapes["angled-wing"] == 40);
  CHECK(shapes["angled-wing"] > shapes["hexagon"]);
  const villa::Json manifest = villa::Json::parse(Slurp(out / "manifest.json"));
  CHECK(manifest.at("regenerate").get<std::string>().find("--shapes hexagon=1,angled-wing=3") != std::string::npos);
  CHECK(manifest.at("recipe").at("shapes").at("octagon").get<double>() == 0.0);
  const villa::Json stats = villa::Json::parse(Slurp(out / "stats.json"));
  CHECK(stats.at("angled_layouts").get<int>() == 40);  // both classes always have a slanted outside edge
  CHECK(stats.at("angled_interior_layouts").get<int>() >= 20);
}

TEST_CASE("villa synth rejects bad arguments with exit 2 and a clear message", "[partitioner][synth]") {
  TempDir tmp;
  const std::string out = " --out '" + (tmp.path / "x").string() + "'";
  struct Case {
    std::string args;
    std::string says;
  };
  const Case cases[] = {
      {"synth --count 0" + out, "--count"},
      {"synth --count 5 --floors 2:4" + out, "--floors"},
      {"synth --count 5 --floors 2:a:4" + out, "\"a\""},
      {"synth --count 5 --shard 3/3" + out, "--shard"},
      {"synth --count 5 --shard x" + out, "--shard"},
      {"synth --count 5 --grid 0.3" + out, "grid 0.3"},
      {"synth --count 5 --threads -1" + out, "--threads"},
      {"synth --count 5 --shapes hexagon=1,star=2" + out, "\"star\" is not a footprint class"},
      {"synth --count 5 --shapes hexagon" + out, "expected NAME=WEIGHT"},
      {"synth --count 5 --shapes octagon=-1" + out, "\"octagon=-1\""},
      {"synth --count 5 --shapes L=0" + out, "at least one weight must be positive"},
      {"synth --out x", "--count"},
  };
  for (const Case& c : cases) {
    const Run run = Villa(c.args);
    INFO(c.args << "\n" << run.output);
    CHECK(run.code == 2);
    CHECK(run.output.find(c.says) != std::string::npos);
  }
  CHECK(!fs::exists(tmp.path / "x" / "layouts.jsonl"));
}

#ifdef VILLA_HAVE_RENDER
TEST_CASE("villa synth --previews renders the first layouts of the shard", "[partitioner][synth]") {
  TempDir tmp;
  const Run run = Villa("synth --count 6 --shard 1/2 --previews 2 --out '" + tmp.path.string() + "'");
  INFO(run.output);
  REQUIRE(run.code == 0);
  // Shard 1/2 of 6 holds ids 3..5; the first two are previewed.
  for (const char* id : {"villa-000003", "villa-000004"}) {
    const std::string png = Slurp(tmp.path / "previews" / (std::string(id) + ".png"));
    REQUIRE(png.size() > 1000);
    CHECK(png.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);
  }
  CHECK(!fs::exists(tmp.path / "previews" / "villa-000005.png"));
  const villa::Json manifest = villa::Json::parse(Slurp(tmp.path / "manifest.json"));
  CHECK(manifest.at("files").at("previews").size() == 2);
}
#endif

TEST_CASE("villa synth range-checks its numeric flags: exit 2 naming the flag and the range, nothing written",
          "[synth][cli][flags]") {
  TempDir dir;
  const std::string out = " --out '" + (dir.path / "out").string() + "'";
  villa::test::CheckBadFlags(
      {
          {"--count -5", "--count: expected a whole number from 1 to 1000000000, got -5"},
          {"--count 99999999999999999999", "--count: expected a whole number from 1 to 1000000000, got 99999999999999999999"},
          {"--count 0", "--count: expected a whole number from 1 to 1000000000, got 0"},
          {"--count 2 --seed -1", "--seed: expected a whole number from 0 to 18446744073709551615, got -1"},
          {"--count 2 --seed 18446744073709551616",
           "--seed: expected a whole number from 0 to 18446744073709551615, got 18446744073709551616"},
          {"--count 2 --seed 1e3", "--seed: expected a whole number from 0 to 18446744073709551615, got 1e3"},
          {"--count 2 --threads -1", "--threads: expected a whole number from 0 to 1024, got -1"},
          {"--count 2 --previews -2", "--previews: expected a whole number from 0 to 100000, got -2"},
          {"--count 2 --grid 0", "--grid: expected a number from 0.01 to 1, got 0"},
      },
      [&](const std::string& args) {
        Run run = Villa("synth " + args + out);
        CHECK_FALSE(fs::exists(dir.path / "out" / "layouts.jsonl"));
        return std::pair{run.code, run.output};
      });
  // The largest seed is a seed; a zero-padded number is decimal, not octal.
  Run top = Villa("synth --count 1 --threads 1 --seed 18446744073709551615" + out);
  INFO(top.output);
  CHECK(top.code == 0);
  Run padded = Villa("synth --count 1 --threads 1 --seed 010 --force --out '" + (dir.path / "padded").string() + "'");
  REQUIRE(padded.code == 0);
  CHECK(Slurp(dir.path / "padded" / "manifest.json").find("\"seed\": 10,") != std::string::npos);
}
