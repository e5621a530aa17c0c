// The LLM backend against a local OpenAI-compatible server (tests/llm/scripted_server.h) that replays
// scripted answers. Each case asserts what the client did: the requests it sent and their
// bodies, the rounds, the error text, and the exit status of `villa plan`.
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <thread>

#include <catch2/catch.hpp>

#include "finetune/layout_schema.h"
#include "finetune/system_prompt.h"
#include "generator/text/backends.h"
#include "generator/text/plan.h"
#include "layout/layout_io.h"
#include "layout/validate.h"
#include "llm/client.h"
#include "llm/scripted_server.h"
#include "util/atomic_file.h"

namespace villa {
namespace {

using testing::Completion;
using testing::Failure;
using testing::Reply;
using testing::ScriptedServer;

Layout Fixture(const std::string& name) {
  Result<Layout> layout = LoadLayout(std::string(VILLA_FIXTURE_DIR) + "/layouts/" + name);
  REQUIRE(layout.ok());
  return *layout;
}

std::string ValidAnswer() { return LayoutToString(Fixture("house_two_floors.json"), -1); }
std::string InvalidAnswer() { return LayoutToString(Fixture("rule9_kitchen_without_window.json"), -1); }

const char* kRequest = "A two-story house with a living room, a kitchen and two bedrooms.";

PlanOptions LlmOptionsFor(const ScriptedServer& server) {
  PlanOptions options;
  options.backend = PlanBackend::kLlm;
  options.seed = 11;
  options.llm.url = server.url();
  options.llm.model = "villa-lora";
  options.llm.temperature = 0.3;
  options.llm.timeout_s = 5;
  options.llm.backoff_initial_s = 0.01;
  options.llm.backoff_max_s = 2.0;
  options.llm.max_retries = 2;
  return options;
}

// Runs `villa ARGS` and returns its exit status.
int RunVilla(const std::string& args) {
  std::string command = std::string(VILLA_BINARY) + " " + args + " >/dev/null 2>&1";
  int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::filesystem::path TempDir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() /
             ("villa-llm-test-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace

TEST_CASE("llm: a valid JSON answer is accepted in one round, with the request the fine-tune expects") {
  ScriptedServer server({Completion(ValidAnswer())});
  PlanSummary plan = PlanLayout(kRequest, LlmOptionsFor(server));
  INFO(plan.BriefReport());
  CHECK(plan.valid());
  CHECK(plan.rounds.size() == 1);
  CHECK(plan.attempts == 1);
  CHECK(plan.rounds[0].http_attempts == 1);
  CHECK(plan.rounds[0].finish_reason == "stop");
  auto bodies = server.bodies();
  REQUIRE(bodies.size() == 1);
  const Json& body = bodies[0];
  CHECK(body.at("model") == "villa-lora");
  REQUIRE(body.at("messages").size() == 2);
  CHECK(body["messages"][0]["role"] == "system");
  CHECK(body["messages"][0]["content"] == std::string(SystemPrompt()));
  CHECK(body["messages"][1]["role"] == "user");
  CHECK(body["messages"][1]["content"] == kRequest);
  CHECK(body.at("response_format").at("type") == "json_schema");
  CHECK(body["response_format"]["json_schema"]["strict"] == true);
  CHECK(body["response_format"]["json_schema"]["schema"] == LayoutJsonSchema());
  CHECK(body.at("chat_template_kwargs") == Json{{"enable_thinking", false}});
  CHECK(body.at("temperature") == 0.3);
  CHECK(body.at("seed") == 11);
  CHECK(!body.contains("guided_json"));
  CHECK(server.authorization()[0].empty());
}

TEST_CASE("llm: JSON wrapped in code fences and prose is accepted") {
  ScriptedServer server({Completion("Here is the layout you asked for:\n```json\n" + ValidAnswer() + "\n```\nEnjoy!")});
  PlanSummary plan = PlanLayout(kRequest, LlmOptionsFor(server));
  CHECK(plan.valid());
  CHECK(plan.rounds.size() == 1);
  CHECK(server.bodies().size() == 1);
  CHECK(ExtractJsonText("<think>plan it</think>\n```\n{\"a\": 1}\n```") == "{\"a\": 1}");
  CHECK(ExtractJsonText("{\"a\": {\"b\": 2}}") == "{\"a\": {\"b\": 2}}");
}

TEST_CASE("llm: an invalid layout is sent back with its violations and the fixed one is accepted") {
  ScriptedServer server({Completion(InvalidAnswer()), Completion(ValidAnswer())});
  PlanSummary plan = PlanLayout(kRequest, LlmOptionsFor(server));
  INFO(plan.BriefReport());
  CHECK(plan.valid());
  REQUIRE(plan.rounds.size() == 2);
  CHECK(plan.rounds[0].parsed);
  CHECK(!plan.rounds[0].valid);
  CHECK(plan.rounds[0].violations >= 1);
  CHECK(plan.rounds[1].valid);
  auto bodies = server.bodies();
  REQUIRE(bodies.size() == 2);
  const Json& messages = bodies[1]["messages"];
  REQUIRE(messages.size() == 4);
  CHECK(messages[2]["role"] == "assistant");
  CHECK(messages[2]["content"] == InvalidAnswer());
  CHECK(messages[3]["role"] == "user");
  const std::string feedback = messages[3]["content"].get<std::string>();
  CHECK(feedback.find("rule 9") != std::string::npos);
  CHECK(feedback.find("kitchen") != std::string::npos);
  CHECK(feedback == RepairMessage(ValidateLayout(Fixture("rule9_kitchen_without_window.json")).violations));
}

TEST_CASE("llm: invalid answers in every round give an invalid outcome and the rounds are bounded") {
  ScriptedServer server({Completion(InvalidAnswer()), Completion(InvalidAnswer()), Completion(InvalidAnswer()),
                         Completion(ValidAnswer())});
  PlanOptions options = LlmOptionsFor(server);
  options.rounds = 2;
  PlanSummary plan = PlanLayout(kRequest, options);
  CHECK(!plan.valid());
  CHECK(plan.outcome == PlanOutcome::kInvalid);
  CHECK(plan.rounds.size() == 3);
  CHECK(server.bodies().size() == 3);
  CHECK(plan.layout.has_value());  // the last answer that parsed, kept for the report
  CHECK(!plan.violations.empty());
  CHECK(plan.error.find("no valid layout in 3 answers") != std::string::npos);
}

TEST_CASE("llm: a truncated answer (finish_reason length) is a failed output, asked again") {
  const std::string valid = ValidAnswer();
  ScriptedServer server({Completion(valid.substr(0, valid.size() / 2), "length"), Completion(valid)});
  PlanSummary plan = PlanLayout(kRequest, LlmOptionsFor(server));
  CHECK(plan.valid());
  REQUIRE(plan.rounds.size() == 2);
  CHECK(!plan.rounds[0].parsed);
  CHECK(plan.rounds[0].finish_reason == "length");
  CHECK(plan.rounds[0].error.find("cut off") != std::string::npos);
  auto bodies = server.bodies();
  REQUIRE(bodies.size() == 2);
  // The cut answer is not replayed; the model is asked for a complete, compact one.
  REQUIRE(bodies[1]["messages"].size() == 3);
  CHECK(bodies[1]["messages"][2]["content"].get<std::string>().find("cut off") != std::string::npos);
}

TEST_CASE("llm: 429 is retried after Retry-After, then the answer is used") {
  ScriptedServer server({Failure(429, "rate limited", "1"), Completion(ValidAnswer())});
  const auto start = std::chrono::steady_clock::now();
  PlanSummary plan = PlanLayout(kRequest, LlmOptionsFor(server));
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CHECK(plan.valid());
  REQUIRE(plan.rounds.size() == 1);
  CHECK(plan.rounds[0].http_attempts == 2);
  CHECK(server.bodies().size() == 2);
  CHECK(server.bodies()[0] == server.bodies()[1]);  // the same request again
  CHECK(elapsed >= 0.9);                            // waited as told, not the 0.01 s backoff
}

TEST_CASE("llm: 500s are retried with backoff until the client gives up") {
  ScriptedServer server({Failure(500, "model overloaded"), Failure(502, "model overloaded"),
                         Failure(503, "model overloaded"), Completion(ValidAnswer())});
  PlanSummary plan = PlanLayout(kRequest, LlmOptionsFor(server));  // max_retries 2: three requests
  CHECK(!plan.valid());
  CHECK(plan.outcome == PlanOutcome::kFailed);
  CHECK(server.bodies().size() == 3);
  REQUIRE(plan.rounds.size() == 1);
  CHECK(plan.rounds[0].http_attempts == 3);
  CHECK(plan.error.find("HTTP 503") != std::string::npos);
  CHECK(plan.error.find("model overloaded") != std::string::npos);
  CHECK(plan.error.find("gave up after 3 attempts") != std::string::npos);
  CHECK(plan.error.find("/v1/chat/completions") != std::string::npos);
}

TEST_CASE("llm: other 4xx fail at once with the server's message") {
  ScriptedServer server({Failure(401, "invalid api key"), Completion(ValidAnswer())});
  PlanSummary plan = PlanLayout(kRequest, LlmOptionsFor(server));
  CHECK(plan.outcome == PlanOutcome::kFailed);
  CHECK(server.bodies().size() == 1);
  CHECK(plan.error.find("HTTP 401") != std::string::npos);
  CHECK(plan.error.find("invalid api key") != std::string::npos);
}

TEST_CASE("llm: an answer slower than the timeout fails that request without a retry") {
  Reply slow = Completion(ValidAnswer());
  slow.delay_s = 1.2;
  ScriptedServer server({slow, Completion(ValidAnswer())});
  PlanOptions options = LlmOptionsFor(server);
  options.llm.timeout_s = 0.3;
  PlanSummary plan = PlanLayout(kRequest, options);
  CHECK(plan.outcome == PlanOutcome::kFailed);
  CHECK(server.bodies().size() == 1);
  CHECK(plan.error.find("timed out after 0.3 s") != std::string::npos);
}

TEST_CASE("llm: a refused connection is retried, then reported") {
  PlanOptions options;
  options.backend = PlanBackend::kLlm;
  options.llm.url = "http://127.0.0.1:1/v1";  // a privileged port nothing listens on: refused at once
  options.llm.timeout_s = 5;
  options.llm.model = "m";
  options.llm.backoff_initial_s = 0.01;
  options.llm.max_retries = 1;
  PlanSummary plan = PlanLayout(kRequest, options);
  CHECK(plan.outcome == PlanOutcome::kFailed);
  REQUIRE(plan.rounds.size() == 1);
  CHECK(plan.rounds[0].http_attempts == 2);
  INFO(plan.error);
  CHECK(plan.error.find("gave up after 2 attempts") != std::string::npos);
  CHECK(plan.error.find("127.0.0.1:1/v1/chat/completions") != std::string::npos);
}

TEST_CASE("villa plan --llm: exit status, files beside the layout, and the API key kept secret") {
  const std::string request = "\"A two-story house with a living room, a kitchen and two bedrooms.\"";
  SECTION("a valid answer: exit 0, layout, report and picture written") {
    ScriptedServer server({Completion("```json\n" + ValidAnswer() + "\n```")});
    auto dir = TempDir("ok");
    ::setenv("VILLA_TEST_API_KEY", "sk-test-secret-123", 1);
    int status = RunVilla("plan " + request + " -o " + (dir / "layout.json").string() + " --llm " + server.url() +
                          " --model villa-lora --api-key-env VILLA_TEST_API_KEY --seed 3");
    CHECK(status == 0);
    CHECK(std::filesystem::exists(dir / "layout.json"));
    CHECK(std::filesystem::exists(dir / "layout.png"));
    REQUIRE(std::filesystem::exists(dir / "layout.report.json"));
    auto report_text = ReadFile(dir / "layout.report.json");
    REQUIRE(report_text.ok());
    CHECK(report_text->find("sk-test-secret-123") == std::string::npos);
    Json report = Json::parse(*report_text);
    CHECK(report["outcome"] != "failed");
    CHECK(report["valid"] == true);
    CHECK(report["backend"] == "llm");
    CHECK(report["metrics"]["fsr"] == 1.0);
    CHECK(report["rounds"].size() == 1);
    REQUIRE(server.authorization().size() == 1);
    CHECK(server.authorization()[0] == "Bearer sk-test-secret-123");
    CHECK(server.bodies()[0]["seed"] == 3);
    // Nothing is overwritten without --force.
    CHECK(RunVilla("plan " + request + " -o " + (dir / "layout.json").string() + " --llm " + server.url() +
                   " --model villa-lora") == 2);
    std::filesystem::remove_all(dir);
  }
  SECTION("only truncated answers: exit 1, a report saying why, no layout") {
    const std::string valid = ValidAnswer();
    ScriptedServer server({Completion(valid.substr(0, 100), "length"), Completion(valid.substr(0, 100), "length")});
    auto dir = TempDir("cut");
    int status = RunVilla("plan " + request + " -o " + (dir / "layout.json").string() + " --llm " + server.url() +
                          " --model m --rounds 1");
    CHECK(status == 1);
    CHECK(!std::filesystem::exists(dir / "layout.json"));
    REQUIRE(std::filesystem::exists(dir / "layout.report.json"));
    Json report = Json::parse(*ReadFile(dir / "layout.report.json"));
    CHECK(report["valid"] == false);
    CHECK(report["rounds"].size() == 2);
    CHECK(report["error"].get<std::string>().find("cut off") != std::string::npos);
    std::filesystem::remove_all(dir);
  }
  SECTION("usage errors: exit 2") {
    auto dir = TempDir("usage");
    CHECK(RunVilla("plan " + request + " -o " + (dir / "l.json").string() + " --backend llm") == 2);
    CHECK(RunVilla("plan " + request + " -o " + (dir / "l.json").string() +
                   " --llm http://127.0.0.1:9 --model m --api-key-env VILLA_TEST_UNSET_VARIABLE") == 2);
    CHECK(RunVilla("plan " + request + " -o " + (dir / "l.txt").string()) == 2);
    std::filesystem::remove_all(dir);
  }
}

}  // namespace villa

namespace villa {

TEST_CASE("villa eval: served-model requests in parallel, the macro table as JSON") {
  ScriptedServer server({Completion(ValidAnswer()), Completion(ValidAnswer()), Completion(InvalidAnswer()),
                         Completion(ValidAnswer()), Completion(ValidAnswer()), Completion(ValidAnswer()),
                         Completion(ValidAnswer()), Completion(ValidAnswer())});
  auto dir = TempDir("eval");
  {
    std::ofstream prompts(dir / "prompts.jsonl");
    for (int i = 0; i < 4; ++i)
      prompts << Json{{"id", "p" + std::to_string(i)}, {"text", "A two-story house with a kitchen and two bedrooms."}}.dump()
              << "\n";
  }
  std::string command = std::string(VILLA_BINARY) + " eval " + (dir / "prompts.jsonl").string() + " --llm " +
                        server.url() + " --model m --rounds 1 --jobs 4 --json > " + (dir / "out.json").string();
  int status = std::system(command.c_str());
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  Json out = Json::parse(*ReadFile(dir / "out.json"));
  CHECK(out["overall"]["count"] == 4);
  CHECK(out["overall"]["fsr"] == 1.0);  // the invalid answer was corrected in its second round
  CHECK(out["prompts"].size() == 4);
  CHECK(server.bodies().size() == 5);
  int two_rounds = 0;
  for (const auto& p : out["prompts"]) two_rounds += p["rounds"] == 2;
  CHECK(two_rounds == 1);
  // A line without "text" is a usage error naming the line.
  {
    std::ofstream bad(dir / "bad.jsonl");
    bad << "{\"text\": \"a kitchen\"}\n{\"prompt\": \"no text key\"}\n";
  }
  CHECK(RunVilla("eval " + (dir / "bad.jsonl").string()) == 2);
  std::filesystem::remove_all(dir);
}

}  // namespace villa
