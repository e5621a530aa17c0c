// The OpenAI-compatible client against a local scripted server: the requests it sends (text, images as
// image_url data URIs, the caller's response schema, embeddings batches), what it makes of the answers,
// and the errors it names. The retry policy is exercised through the generator's LLM backend too
// (tests/generator/text/llm_test.cpp).
#include <catch2/catch.hpp>

#include <string>

#include "llm/client.h"
#include "llm/scripted_server.h"

namespace villa {
namespace {

using testing::Completion;
using testing::Failure;
using testing::Json;
using testing::Reply;
using testing::ScriptedServer;

LlmOptions OptionsFor(const ScriptedServer& server) {
  LlmOptions o = testing::ScriptedOptions(server, "villa-critic", 2);
  o.backoff_initial_s = 0.01;
  o.backoff_max_s = 0.5;
  return o;
}

}  // namespace

TEST_CASE("server addresses and options are checked") {
  CHECK(ChatCompletionsUrl("http://h:8000") == "http://h:8000/v1/chat/completions");
  CHECK(ChatCompletionsUrl("http://h:8000/") == "http://h:8000/v1/chat/completions");
  CHECK(ChatCompletionsUrl("http://h:8000/v1") == "http://h:8000/v1/chat/completions");
  CHECK(ChatCompletionsUrl("https://api.x.com/v1/chat/completions") == "https://api.x.com/v1/chat/completions");
  CHECK(EmbeddingsUrl("http://h:8000") == "http://h:8000/v1/embeddings");
  CHECK(EmbeddingsUrl("http://h:8000/v1/") == "http://h:8000/v1/embeddings");
  CHECK(EmbeddingsUrl("https://api.x.com/v1/chat/completions") == "https://api.x.com/v1/embeddings");
  CHECK(EmbeddingsUrl("https://api.x.com/v1/embeddings") == "https://api.x.com/v1/embeddings");
  LlmOptions o;
  std::string message;
  CHECK(!o.IsValid(&message));
  CHECK(message.find("--llm") != std::string::npos);
  o.url = "ftp://x";
  o.model = "m";
  CHECK(!o.IsValid(&message));
  CHECK(message.find("ftp://x") != std::string::npos);
}

TEST_CASE("base64 encodes as RFC 4648 says") {
  CHECK(Base64("") == "");
  CHECK(Base64("f") == "Zg==");
  CHECK(Base64("fo") == "Zm8=");
  CHECK(Base64("foo") == "Zm9v");
  CHECK(Base64("foobar") == "Zm9vYmFy");
  CHECK(Base64(std::string("\x89PNG\r\n\x1a\n", 8)) == "iVBORw0KGgo=");
}

TEST_CASE("a chat with images sends them as image_url data URIs after the text, with the caller's schema") {
  ScriptedServer server({Completion("{\"score\": 7}")});
  const std::string png("\x89PNG\r\n\x1a\nfake", 12);
  const Json schema{{"type", "json_schema"}, {"json_schema", Json{{"name", "critique"}, {"strict", true}}}};
  int attempts = 0;
  auto answer = ChatCompletion(OptionsFor(server),
                               {{"system", "You rate rooms.", {}}, {"user", "Rate this bedroom.", {png, png}}}, schema,
                               &attempts);
  REQUIRE(answer);
  CHECK(answer->content == "{\"score\": 7}");
  CHECK(answer->finish_reason == "stop");
  CHECK(attempts == 1);
  const auto bodies = server.bodies();
  REQUIRE(bodies.size() == 1);
  CHECK(server.paths()[0] == "/v1/chat/completions");
  const Json& messages = bodies[0]["messages"];
  CHECK(messages[0]["content"] == "You rate rooms.");  // a plain string without images
  const Json& parts = messages[1]["content"];
  REQUIRE(parts.is_array());
  REQUIRE(parts.size() == 3);
  CHECK(parts[0] == Json{{"type", "text"}, {"text", "Rate this bedroom."}});
  CHECK(parts[1]["type"] == "image_url");
  CHECK(parts[1]["image_url"]["url"] == "data:image/png;base64," + Base64(png));
  CHECK(parts[2] == parts[1]);
  CHECK(bodies[0]["response_format"] == schema);
  CHECK(bodies[0]["model"] == "villa-critic");
  // Without a schema, no response_format at all.
  ScriptedServer plain({Completion("ok")});
  REQUIRE(ChatCompletion(OptionsFor(plain), {{"user", "hi", {}}}));
  CHECK_FALSE(plain.bodies()[0].contains("response_format"));
}

TEST_CASE("embeddings come back in input order whatever order the server lists them in") {
  ScriptedServer server({testing::EmbeddingsReply(Json::array({Json{{"object", "embedding"}, {"index", 1}, {"embedding", {0.5, 0.25}}},
                                                      Json{{"object", "embedding"}, {"index", 0}, {"embedding", {1, -2}}}}))});
  LlmOptions o = OptionsFor(server);
  o.api_key = "sk-embed";
  auto answer = Embeddings(o, {"a wooden chair", "a sofa"});
  REQUIRE(answer);
  REQUIRE(answer->vectors.size() == 2);
  CHECK(answer->vectors[0] == std::vector<float>{1.0f, -2.0f});
  CHECK(answer->vectors[1] == std::vector<float>{0.5f, 0.25f});
  CHECK(answer->http_attempts == 1);
  CHECK(server.paths()[0] == "/v1/embeddings");
  CHECK(server.bodies()[0] == Json{{"model", "villa-critic"}, {"input", {"a wooden chair", "a sofa"}}});
  CHECK(server.authorization()[0] == "Bearer sk-embed");
}

TEST_CASE("bad embedding answers are errors naming the entry") {
  auto error_for = [](const Json& data, int texts = 2) {
    ScriptedServer server({testing::EmbeddingsReply(data)});
    std::vector<std::string> input(texts, "x");
    auto answer = Embeddings(OptionsFor(server), input);
    REQUIRE_FALSE(answer);
    return answer.error();
  };
  auto item = [](const Json& index, const Json& embedding) { return Json{{"index", index}, {"embedding", embedding}}; };
  CHECK_THAT(error_for(Json::array({item(0, {1, 2})})), Catch::Contains("1 embeddings for 2 texts"));
  CHECK_THAT(error_for(Json::array({item(0, {1, 2}), item(0, {3, 4})})), Catch::Contains("data[1].index: 0 appears twice"));
  CHECK_THAT(error_for(Json::array({item(0, {1, 2}), item(5, {3, 4})})),
             Catch::Contains("data[1].index: 5 is not an index of the 2 texts"));
  CHECK_THAT(error_for(Json::array({item(0, {1, 2}), item(1, {3, "four"})})),
             Catch::Contains("data[1].embedding[1]: \"four\" is not a number"));
  CHECK_THAT(error_for(Json::array({item(0, {1, 2}), item(1, {3, 4, 5})})),
             Catch::Contains("the embedding of text 1 has 3 numbers, that of text 0 2"));
  CHECK_THAT(error_for(Json::array({item(0, {1, 2}), Json{{"index", 1}}})), Catch::Contains("data[1].embedding: missing"));
  ScriptedServer no_data({{200, Json{{"object", "list"}}.dump(), 0.0, ""}});
  auto answer = Embeddings(OptionsFor(no_data), {"x"});
  REQUIRE_FALSE(answer);
  CHECK_THAT(answer.error(), Catch::Contains("no \"data\" array"));
  CHECK_THAT(answer.error(), Catch::Contains("/v1/embeddings"));
}

TEST_CASE("embeddings follow the retry policy: 5xx retried, other 4xx fail at once with the server's words") {
  ScriptedServer flaky({Failure(503, "warming up"), testing::EmbeddingsReply(Json::array({Json{{"index", 0}, {"embedding", {1}}}}))});
  auto answer = Embeddings(OptionsFor(flaky), {"x"});
  REQUIRE(answer);
  CHECK(answer->http_attempts == 2);
  ScriptedServer refused({Failure(401, "invalid api key")});
  int attempts = 0;
  auto denied = Embeddings(OptionsFor(refused), {"x"}, &attempts);
  REQUIRE_FALSE(denied);
  CHECK(attempts == 1);
  CHECK_THAT(denied.error(), Catch::Contains("HTTP 401: invalid api key"));
  // No texts: no request.
  ScriptedServer idle({});
  auto none = Embeddings(OptionsFor(idle), {});
  REQUIRE(none);
  CHECK(none->vectors.empty());
  CHECK(idle.bodies().empty());
}

TEST_CASE("the JSON inside an answer is found under think blocks, fences and prose") {
  CHECK(ExtractJsonText("<think>plan it</think>\n```\n{\"a\": 1}\n```") == "{\"a\": 1}");
  CHECK(ExtractJsonText("Here it is: {\"a\": {\"b\": 2}} hope it helps") == "{\"a\": {\"b\": 2}}");
  CHECK(ExtractJsonText("{\"a\": [1, 2") == "{\"a\": [1, 2");
}

}  // namespace villa

namespace villa {

TEST_CASE("a server that echoes the API key: its value is in no error, message or answer the client gives back", "[llm][secret]") {
  const std::string key = "sk-live-0123456789abcdefSECRET";
  auto options = [&](const ScriptedServer& server) {
    LlmOptions o = OptionsFor(server);
    o.api_key = key;
    return o;
  };
  auto no_key = [&](const std::string& text) {
    INFO(text);
    CHECK(text.find(key) == std::string::npos);
    CHECK(text.find(key.substr(0, 12)) == std::string::npos);  // nor a piece of it left by a cut
  };
  // A 401 whose JSON message quotes the key.
  ScriptedServer denied({Failure(401, "Incorrect API key provided: " + key + ". Find yours at the dashboard.")});
  auto chat = ChatCompletion(options(denied), {{"user", "hello", {}}});
  REQUIRE_FALSE(chat);
  no_key(chat.error());
  CHECK_THAT(chat.error(), Catch::Contains("HTTP 401: Incorrect API key provided: [redacted]. Find yours"));
  REQUIRE(denied.authorization().size() == 1);
  CHECK(denied.authorization()[0] == "Bearer " + key);
  // A plain-text body with the key where the 300-byte cut falls, after retried 5xx that echo it too.
  const std::string padding(290, 'x');
  ScriptedServer plain({{503, "overloaded for " + key, 0.0, ""}, {403, padding + key + " denied", 0.0, ""}});
  auto cut = ChatCompletion(options(plain), {{"user", "hello", {}}});
  REQUIRE_FALSE(cut);
  no_key(cut.error());
  // An answer whose content and finish reason carry it.
  ScriptedServer echo({Completion("{\"note\": \"your key is " + key + "\"}", key)});
  auto answer = ChatCompletion(options(echo), {{"user", "hello", {}}});
  REQUIRE(answer);
  no_key(answer->content);
  no_key(answer->finish_reason);
  CHECK(answer->content == "{\"note\": \"your key is [redacted]\"}");
  // An answer without choices, quoted in the error.
  ScriptedServer odd({{200, Json{{"object", "error"}, {"key", key}}.dump(), 0.0, ""}});
  auto quoted = ChatCompletion(options(odd), {{"user", "hello", {}}});
  REQUIRE_FALSE(quoted);
  no_key(quoted.error());
  // Embeddings: the same.
  ScriptedServer embed({Failure(401, "bad key " + key)});
  auto vectors = Embeddings(options(embed), {"x"});
  REQUIRE_FALSE(vectors);
  no_key(vectors.error());
}

}  // namespace villa
