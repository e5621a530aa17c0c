// `villa plan --llm` against a server that answers as an adversary would (issue 17): a layout with a
// coordinate of -1e12, and a 401 that echoes the API key. The report is always written; the key never
// appears in it, on stderr or in any message.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <catch2/catch.hpp>

#include "bad_flags.h"
#include "generator/text/plan.h"
#include "layout/layout_io.h"
#include "llm/scripted_server.h"
#include "util/atomic_file.h"

namespace villa {
namespace {

using testing::Completion;
using testing::Failure;
using testing::ScriptedServer;

std::filesystem::path Sandbox(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("villa-hostile-answer-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// Runs `villa ARGS`, stderr into `err`; the exit status.
int RunVilla(const std::string& args, const std::filesystem::path& dir, std::string* err) {
  const std::string command = std::string(VILLA_BINARY) + " " + args + " >/dev/null 2>'" + (dir / "stderr").string() + "'";
  const int status = std::system(command.c_str());
  std::ifstream in(dir / "stderr");
  std::ostringstream text;
  text << in.rdbuf();
  *err = text.str();
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

const char* kRequest = "\"A one-story house with a living room and a kitchen.\"";
const char* kKey = "sk-villa-test-0123456789abcdef";

}  // namespace

TEST_CASE("villa plan --llm: an answer with a coordinate of -1e12 is refused, the report written", "[generator][hostile]") {
  const std::string answer = R"J({"rooms": {"living-room_0/0": {"shape": "shapely.box(-1000000000000, 0, 5, 4)"}},
    "entrance": {}, "doors": {}, "opens": {}, "windows": {}, "interiors": {}})J";
  ScriptedServer server({Completion(answer)});
  const auto dir = Sandbox("far");
  std::string err;
  const int status = RunVilla(std::string("plan ") + kRequest + " -o " + (dir / "layout.json").string() + " --llm " +
                                  server.url() + " --model m --rounds 0",
                              dir, &err);
  INFO(err);
  CHECK(status == 1);
  REQUIRE(std::filesystem::exists(dir / "layout.report.json"));
  CHECK_FALSE(std::filesystem::exists(dir / "layout.png"));
  CHECK_FALSE(std::filesystem::exists(dir / "layout.invalid.json"));
  const Json report = Json::parse(*ReadFile(dir / "layout.report.json"));
  CHECK(report["outcome"] == "invalid");
  REQUIRE(report["rounds"].size() == 1);
  CHECK(report["rounds"][0]["error"] ==
        "answer: rooms[\"living-room_0/0\"].shape: x = -1e+12 is outside the building extent (|x| and |y| at most 10000 m)");
  std::filesystem::remove_all(dir);
}

TEST_CASE("villa plan --llm: a 401 that echoes the API key leaves it out of stderr and the report", "[generator][hostile][secret]") {
  ScriptedServer server({Failure(401, std::string("invalid api key '") + kKey + "' for this server")});
  const auto dir = Sandbox("key");
  ::setenv("VILLA_HOSTILE_TEST_KEY", kKey, 1);
  std::string err;
  const int status = RunVilla(std::string("plan ") + kRequest + " -o " + (dir / "layout.json").string() + " --llm " +
                                  server.url() + " --model m --api-key-env VILLA_HOSTILE_TEST_KEY",
                              dir, &err);
  CHECK(status == 1);
  REQUIRE(server.authorization().size() == 1);
  CHECK(server.authorization()[0] == std::string("Bearer ") + kKey);  // sent, as it must be
  CHECK(err.find(kKey) == std::string::npos);
  CHECK(err.find("invalid api key '[redacted]' for this server") != std::string::npos);
  const std::string report = *ReadFile(dir / "layout.report.json");
  CHECK(report.find(kKey) == std::string::npos);
  CHECK(report.find("HTTP 401") != std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace villa

namespace villa {

TEST_CASE("villa plan and eval range-check their numeric flags, naming the flag and the range", "[generator][cli][flags]") {
  const auto dir = Sandbox("flags");
  const std::string out = " -o " + (dir / "layout.json").string();
  test::CheckBadFlags(
      {
          {"--seed -1", "--seed: expected a whole number from 0 to 18446744073709551615, got -1"},
          {"--seed 18446744073709551616", "--seed: expected a whole number from 0 to 18446744073709551615, got 18446744073709551616"},
          {"--rounds -1", "--rounds: expected a whole number from 0 to 100, got -1"},
          {"--temperature 3", "--temperature: expected a number from 0 to 2, got 3"},
          {"--budget 0", "--budget: expected a number above 0 and at most 86400, got 0"},
          {"--max-tokens 0", "--max-tokens: expected a whole number from 1 to 10000000, got 0"},
      },
      [&](const std::string& args) {
        std::string err;
        const int status = RunVilla(std::string("plan ") + kRequest + out + " " + args, dir, &err);
        CHECK_FALSE(std::filesystem::exists(dir / "layout.json"));
        return std::pair{status, err};
      });
  std::ofstream(dir / "prompts.jsonl") << "{\"text\": \"a kitchen\"}\n";
  std::string err;
  CHECK(RunVilla("eval " + (dir / "prompts.jsonl").string() + " --jobs -2", dir, &err) == 2);
  CHECK(err.find("--jobs: expected a whole number from 0 to 1024, got -2") != std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace villa
