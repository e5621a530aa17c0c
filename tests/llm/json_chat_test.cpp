// JSON conversations (llm/json_chat.h) against the local scripted server: the accepted answer, corrective
// turns for a malformed, cut-off or refused answer, no second turn after a transport failure, and the
// answer cache keyed by the request (a replay sends nothing, a different question is asked, the key is in
// no cache file).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "llm/json_chat.h"
#include "llm/scripted_server.h"

namespace villa {
namespace {

namespace fs = std::filesystem;
using testing::Completion;
using testing::Failure;
using testing::Json;
using testing::ScriptedServer;

LlmOptions OptionsFor(const ScriptedServer& server) { return testing::ScriptedOptions(server, "villa-json"); }

struct TempDir {
  fs::path path;
  TempDir() : path(fs::temp_directory_path() / ("villa_json_chat_" + std::to_string(::getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
};

const std::vector<ChatMessage> kQuestion{{"system", "Answer with JSON.", {}}, {"user", "How many legs has a chair?", {}}};

// Accepts {"legs": n} with n > 0.
std::string Legs(const nlohmann::json& j) {
  if (!j.contains("legs") || !j["legs"].is_number_integer()) return "legs: missing or not an integer";
  return j["legs"].get<int>() > 0 ? "" : "legs: must be > 0";
}

}  // namespace

TEST_CASE("A JSON answer is accepted as it comes, fences and prose around it are taken off", "[llm][json_chat]") {
  ScriptedServer server({Completion("Sure:\n```json\n{\"legs\": 4}\n```")});
  JsonChatResult r = AskJson(OptionsFor(server), kQuestion, nullptr, Legs, {});
  REQUIRE(r.accepted);
  CHECK(r.value["legs"] == 4);
  CHECK(r.requests == 1);
  CHECK(r.turns.size() == 1);
  CHECK(r.turns[0].key.size() == 64);
}

TEST_CASE("Malformed, cut-off and refused answers are asked again with their fault, a bounded number of times", "[llm][json_chat]") {
  ScriptedServer server({Completion("{\"legs\": "), Completion("{\"legs\": 4, \"notes\": \"a long", "length"), Completion("{\"legs\": -1}"),
                         Completion("{\"legs\": 3}")});
  JsonChatOptions options;
  options.max_reasks = 3;
  JsonChatResult r = AskJson(OptionsFor(server), kQuestion, nullptr, Legs, options);
  REQUIRE(r.accepted);
  CHECK(r.value["legs"] == 3);
  REQUIRE(r.turns.size() == 4);
  CHECK(r.turns[0].error.find("not valid JSON") != std::string::npos);
  CHECK(r.turns[1].error.find("cut off") != std::string::npos);
  CHECK(r.turns[2].error == "legs: must be > 0");
  const auto bodies = server.bodies();
  // Turn 2 repeats the malformed answer and says what was wrong; turn 3 does not repeat the cut-off one.
  CHECK(bodies[1]["messages"][2]["role"] == "assistant");
  CHECK(bodies[1]["messages"][2]["content"] == "{\"legs\": ");
  CHECK(bodies[2]["messages"].size() == 5);
  CHECK(bodies[2]["messages"][4]["content"].get<std::string>().find("cut off") != std::string::npos);
  CHECK(bodies[3]["messages"].back()["content"].get<std::string>().find("legs: must be > 0") != std::string::npos);

  // With no turn left the last fault is the error.
  ScriptedServer stubborn({Completion("[1, 2]"), Completion("[1, 2]")});
  options.max_reasks = 1;
  JsonChatResult no = AskJson(OptionsFor(stubborn), kQuestion, nullptr, Legs, options);
  CHECK_FALSE(no.accepted);
  CHECK(no.requests == 2);
  CHECK(no.error == "no usable answer in 2 turns; last: the answer is JSON but not an object");
}

TEST_CASE("A transport failure ends the conversation without another turn", "[llm][json_chat]") {
  ScriptedServer server({Failure(401, "bad key"), Completion("{\"legs\": 4}")});
  JsonChatResult r = AskJson(OptionsFor(server), kQuestion, nullptr, Legs, {});
  CHECK_FALSE(r.accepted);
  CHECK(server.bodies().size() == 1);
  CHECK(r.error.find("HTTP 401") != std::string::npos);
  CHECK(r.error.find("bad key") != std::string::npos);
}

TEST_CASE("Answers are cached by request: the same conversation again sends nothing, another question is asked", "[llm][json_chat]") {
  TempDir cache;
  ScriptedServer server({Completion("not json"), Completion("{\"legs\": 4}"), Completion("{\"legs\": 3}")});
  LlmOptions llm = OptionsFor(server);
  llm.api_key = "sk-cache-SECRET";
  JsonChatOptions options;
  options.cache_dir = cache.path;
  JsonChatResult first = AskJson(llm, kQuestion, nullptr, Legs, options);
  REQUIRE(first.accepted);
  CHECK(first.requests == 2);
  JsonChatResult again = AskJson(llm, kQuestion, nullptr, Legs, options);
  REQUIRE(again.accepted);
  CHECK(again.value == first.value);
  CHECK(again.requests == 0);
  CHECK(again.cache_hits == 2);  // the corrective turn replays from the cache too
  CHECK(server.bodies().size() == 2);
  // Another question (or another model) is a new request.
  std::vector<ChatMessage> other = kQuestion;
  other[1].content = "How many legs has a stool?";
  JsonChatResult stool = AskJson(llm, other, nullptr, Legs, options);
  REQUIRE(stool.accepted);
  CHECK(stool.value["legs"] == 3);
  CHECK(server.bodies().size() == 3);
  CHECK(ChatRequestKey(llm, ChatRequestBody(llm, kQuestion)) != ChatRequestKey(llm, ChatRequestBody(llm, other)));
  int files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(cache.path)) {
    if (!entry.is_regular_file()) continue;
    ++files;
    std::ifstream in(entry.path());
    const std::string text((std::istreambuf_iterator<char>(in)), {});
    CHECK(text.find("SECRET") == std::string::npos);
  }
  CHECK(files == 3);
  CHECK(DefaultLlmCacheDir().filename() == "llm");
}

}  // namespace villa
