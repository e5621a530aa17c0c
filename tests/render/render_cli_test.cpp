// villa render end to end: exit codes, --force, JSONL records, messages that name the file.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "bad_flags.h"

namespace {

struct Run {
  int code = -1;
  std::string out;
  std::string err;
};

std::string Slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

class Sandbox {
 public:
  Sandbox() {
    dir_ = std::filesystem::temp_directory_path() / ("villa-render-cli-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  ~Sandbox() { std::filesystem::remove_all(dir_); }
  const std::filesystem::path& dir() const { return dir_; }

  Run Villa(const std::string& args) const {
    const std::string command = std::string("'") + VILLA_BINARY + "' " + args + " >'" + (dir_ / "stdout").string() +
                                "' 2>'" + (dir_ / "stderr").string() + "'";
    const int status = std::system(command.c_str());
    Run run;
    run.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.out = Slurp(dir_ / "stdout");
    run.err = Slurp(dir_ / "stderr");
    return run;
  }

 private:
  std::filesystem::path dir_;
};

std::string Example(const std::string& name) {
  return "'" + (std::filesystem::path(VILLA_SOURCE_DIR) / "examples" / name).string() + "'";
}

}  // namespace

TEST_CASE("villa render writes the picture and will not overwrite without --force", "[render][cli]") {
  Sandbox box;
  const auto png = box.dir() / "plan.png";
  Run run = box.Villa("render " + Example("l-shaped-house.json") + " -o '" + png.string() + "'");
  INFO(run.err);
  REQUIRE(run.code == 0);
  const std::string first = Slurp(png);
  REQUIRE(first.compare(0, 4, "\x89PNG") == 0);

  run = box.Villa("render " + Example("two-floor-house.json") + " -o '" + png.string() + "'");
  CHECK(run.code == 2);
  CHECK(run.err.find("plan.png exists") != std::string::npos);
  CHECK(run.err.find("--force") != std::string::npos);
  CHECK(Slurp(png) == first);

  run = box.Villa("render " + Example("two-floor-house.json") + " -o '" + png.string() + "' --force");
  CHECK(run.code == 0);
  CHECK(Slurp(png) != first);

  const auto svg = box.dir() / "plan.svg";
  run = box.Villa("render " + Example("three-floor-villa.json") + " -o '" + svg.string() + "' --width 900 --levels 0 1");
  CHECK(run.code == 0);
  const std::string text = Slurp(svg);
  CHECK(text.find("width=\"900\"") != std::string::npos);
  CHECK(text.find(">Floor 1</text>") != std::string::npos);
  CHECK(text.find(">Floor 2</text>") == std::string::npos);
  CHECK(text.find(">three-floor-villa.json</text>") != std::string::npos);
}

TEST_CASE("villa render usage errors exit 2, unreadable layouts exit 1, each naming the file", "[render][cli]") {
  Sandbox box;
  Run run = box.Villa("render " + Example("l-shaped-house.json") + " -o '" + (box.dir() / "plan.gif").string() + "'");
  CHECK(run.code == 2);
  CHECK(run.err.find("plan.gif") != std::string::npos);

  run = box.Villa("render '" + (box.dir() / "missing.json").string() + "' -o '" + (box.dir() / "p.png").string() + "'");
  CHECK(run.code == 2);
  CHECK(run.err.find("missing.json") != std::string::npos);

  std::ofstream(box.dir() / "broken.json") << "{\"rooms\": {\"kitchen_0/0\": {\"shape\": \"shapely.box(0, 0, 4\"}}}";
  run = box.Villa("render '" + (box.dir() / "broken.json").string() + "' -o '" + (box.dir() / "p.png").string() + "'");
  CHECK(run.code == 1);
  CHECK(run.err.find("broken.json") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(box.dir() / "p.png"));

  run = box.Villa("render " + Example("l-shaped-house.json") + " -o '" + (box.dir() / "p.png").string() + "' --scale 0");
  CHECK(run.code == 2);
  CHECK(run.err.find("--scale") != std::string::npos);

  run = box.Villa("render --help");
  CHECK(run.code == 0);
  CHECK(run.out.find("--force") != std::string::npos);
}

TEST_CASE("villa render draws one record of a JSONL stream", "[render][cli]") {
  Sandbox box;
  const std::string one = Slurp(std::filesystem::path(VILLA_SOURCE_DIR) / "examples" / "l-shaped-house.json");
  const std::string two = Slurp(std::filesystem::path(VILLA_SOURCE_DIR) / "examples" / "two-floor-house.json");
  auto flat = [](std::string text) {
    std::string out;
    for (char c : text) {
      if (c != '\n') out += c;
    }
    return out;
  };
  std::ofstream(box.dir() / "set.jsonl") << flat(one) << "\n" << "{\"id\": 7, \"layout\": " << flat(two) << "}\n";
  const auto svg = box.dir() / "second.svg";
  Run run = box.Villa("render '" + (box.dir() / "set.jsonl").string() + "' --line 2 -o '" + svg.string() + "'");
  INFO(run.err);
  REQUIRE(run.code == 0);
  const std::string text = Slurp(svg);
  CHECK(text.find(">set.jsonl:2</text>") != std::string::npos);
  CHECK(text.find("<title>office_1/0</title>") != std::string::npos);

  run = box.Villa("render '" + (box.dir() / "set.jsonl").string() + "' --line 5 -o '" + (box.dir() / "x.svg").string() + "'");
  CHECK(run.code == 1);
  CHECK(run.err.find("set.jsonl: no record on line 5") != std::string::npos);
}

TEST_CASE("villa render range-checks its numeric flags, naming the flag and the range", "[render][cli][flags]") {
  Sandbox box;
  const std::string out = " -o '" + (box.dir() / "p.png").string() + "'";
  villa::test::CheckBadFlags(
      {
          {"--width -1", "--width: expected a whole number from 1 to 30000, got -1"},
          {"--width 99999999999", "--width: expected a whole number from 1 to 30000, got 99999999999"},
          {"--levels 0,-1", "--levels: expected a whole number from 0 to 999, got -1"},
          {"--font-size 1e9", "--font-size: expected a number from 6 to 48, got 1e9"},
          {"--scale nan", "--scale: expected a number from 5 to 400, got nan"},
      },
      [&](const std::string& args) {
        Run run = box.Villa("render " + Example("l-shaped-house.json") + out + " " + args);
        CHECK_FALSE(std::filesystem::exists(box.dir() / "p.png"));
        return std::pair{run.code, run.err};
      });
}
