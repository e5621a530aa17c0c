// `villa furnish` with its critic flags: usage errors (exit 2), the default offline critic's report and
// logs, the room pictures, --critic none, and a model critic through the command line against the local
// scripted server with the key from the environment, written nowhere.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "llm/scripted_server.h"
#include "room_fixture.h"
#include "villa_cli.h"

namespace villa {
namespace {

namespace fs = std::filesystem;
using testing::TempDir;
using testing::Json;

std::string Read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

const std::string kFurnish = "furnish " + testing::kHouse + " --procedural -q ";

}  // namespace

TEST_CASE("villa furnish refuses bad critic flags with exit 2", "[critic][cli]") {
  TempDir out("usage");
  fs::remove_all(out.path);
  const std::string o = " -o " + out.path.string();
  auto no_url = testing::RunVilla(kFurnish + "--critic mllm --model m" + o);
  CHECK(no_url.status == 2);
  CHECK(no_url.out.find("--critic mllm needs --mllm URL") != std::string::npos);
  auto no_model = testing::RunVilla(kFurnish + "--critic mllm --mllm http://127.0.0.1:9" + o);
  CHECK(no_model.status == 2);
  CHECK(no_model.out.find("needs --model NAME") != std::string::npos);
  auto no_key = testing::RunVilla(kFurnish + "--critic mllm --mllm http://127.0.0.1:9 --model m --api-key-env VILLA_TEST_NO_SUCH_KEY" + o);
  CHECK(no_key.status == 2);
  CHECK(no_key.out.find("VILLA_TEST_NO_SUCH_KEY: that environment variable is not set") != std::string::npos);
  CHECK(testing::RunVilla(kFurnish + "--critic maybe" + o).status == 2);
  CHECK(testing::RunVilla(kFurnish + "--graph mllm" + o).status == 2);
  CHECK(testing::RunVilla(kFurnish + "--mllm http://127.0.0.1:9 --model m" + o).status == 2);  // no model-driven part asked for
  CHECK(testing::RunVilla(kFurnish + "--rounds 0" + o).status == 2);
  CHECK_FALSE(fs::exists(out.path / "scene.json"));
}

TEST_CASE("villa furnish: the offline critic by default, its report and round logs, a picture per room, --critic none", "[critic][cli]") {
  TempDir out("offline"), none("none");
  auto run = testing::RunVilla(kFurnish + "--room living-room_0/0 --room bathroom_0/0 -o " + out.path.string());
  REQUIRE(run.status == 0);
  const nlohmann::json report = nlohmann::json::parse(Read(out.path / "report.json"));
  CHECK(report["totals"]["critic"]["critic"] == "offline");
  CHECK(report["totals"]["critic"]["requests"] == 0);
  for (const char* room : {"living-room_0_0", "bathroom_0_0"}) {
    CHECK(fs::exists(out.path / "critic" / room / "critic.json"));
    CHECK(fs::exists(out.path / "critic" / room / "round-1" / "state.txt"));
  }
  // Every room of the layout has its picture (those not asked for stand empty), a PNG.
  for (const char* room : {"living-room_0_0", "kitchen_0_0", "dining-room_0_0", "bedroom_0_0", "bathroom_0_0", "office_0_0"}) {
    const std::string png = Read(out.path / "rooms" / (std::string(room) + ".png"));
    REQUIRE(png.size() > 1000);
    CHECK(png.compare(0, 8, std::string("\x89PNG\r\n\x1a\n", 8)) == 0);
  }
  auto plain = testing::RunVilla(kFurnish + "--room bathroom_0/0 --critic none -o " + none.path.string());
  REQUIRE(plain.status == 0);
  CHECK_FALSE(fs::exists(none.path / "critic"));
  const nlohmann::json plain_report = nlohmann::json::parse(Read(none.path / "report.json"));
  CHECK(plain_report["totals"]["critic"].is_null());
  for (const auto& room : plain_report["rooms"]) CHECK_FALSE(room.contains("critic"));
}

TEST_CASE("villa furnish --critic mllm asks the model, reports tokens, and writes the key nowhere", "[critic][cli]") {
  TempDir out("mllm");
  const std::string key = "sk-villa-cli-SECRET-77";
  ::setenv("VILLA_TEST_CRITIC_KEY", key.c_str(), 1);
  Json answer{{"id", "c"},
              {"object", "chat.completion"},
              {"choices", Json::array({Json{{"index", 0},
                                            {"message", Json{{"role", "assistant"}, {"content", Json{{"score", 10}, {"problems", Json::array()}}.dump()}}},
                                            {"finish_reason", "stop"}}})},
              {"usage", Json{{"prompt_tokens", 900}, {"completion_tokens", 30}}}};
  testing::ScriptedServer server({{200, answer.dump(), 0.0, ""}});
  auto run = testing::RunVilla(kFurnish + "--room bathroom_0/0 --critic mllm --mllm " + server.url() +
                               " --model villa-critic --api-key-env VILLA_TEST_CRITIC_KEY --no-cache --rounds 2 -o " + out.path.string());
  ::unsetenv("VILLA_TEST_CRITIC_KEY");
  INFO(run.out);
  REQUIRE(run.status == 0);
  REQUIRE(server.bodies().size() == 1);
  CHECK(server.authorization()[0] == "Bearer " + key);
  const nlohmann::json report = nlohmann::json::parse(Read(out.path / "report.json"));
  const auto& critic = report["totals"]["critic"];
  CHECK(critic["critic"] == "mllm");
  CHECK(critic["requests"] == 1);
  CHECK(critic["prompt_tokens"] == 900);
  CHECK(critic["completion_tokens"] == 30);
  CHECK(critic["seconds"].get<double>() > 0.0);
  CHECK(fs::exists(out.path / "critic" / "bathroom_0_0" / "round-1" / "view-top.png"));
  for (const auto& entry : fs::recursive_directory_iterator(out.path))
    if (entry.is_regular_file()) CHECK(Read(entry.path()).find("SECRET") == std::string::npos);
  CHECK(run.out.find("SECRET") == std::string::npos);
}

}  // namespace villa
