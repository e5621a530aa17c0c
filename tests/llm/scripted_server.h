#pragma once
// A local OpenAI-compatible server for tests (cpp-httplib on 127.0.0.1, an ephemeral port) that replays
// scripted replies, one per request to /v1/chat/completions or /v1/embeddings, and records each request
// (path, body, Authorization header). Used by the llm/ and generator tests; link cpp-httplib.
#include <httplib.h>

#include <chrono>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "llm/client.h"

namespace villa::testing {

using Json = nlohmann::ordered_json;

struct Reply {
  int status = 200;
  std::string body;
  double delay_s = 0.0;
  std::string retry_after;  // header value, empty: none
};

inline Reply Completion(const std::string& content, const std::string& finish_reason = "stop") {
  Json body{{"id", "chatcmpl-test"},
            {"object", "chat.completion"},
            {"model", "villa-test"},
            {"choices", Json::array({Json{{"index", 0},
                                          {"message", Json{{"role", "assistant"}, {"content", content}}},
                                          {"finish_reason", finish_reason}}})}};
  return {200, body.dump(), 0.0, ""};
}

// An /v1/embeddings answer holding `data` (a list of {"object": "embedding", "index", "embedding"}).
inline Reply EmbeddingsReply(const Json& data) {
  return {200, Json{{"object", "list"}, {"data", data}, {"model", "embedder"}}.dump(), 0.0, ""};
}

inline Reply Failure(int status, const std::string& message, const std::string& retry_after = "") {
  Json body{{"error", Json{{"message", message}, {"type", "server_error"}}}};
  return {status, body.dump(), 0.0, retry_after};
}

class ScriptedServer {
 public:
  explicit ScriptedServer(std::vector<Reply> script) : script_(std::move(script)) {
    for (const char* path : {"/v1/chat/completions", "/v1/embeddings"})
      server_.Post(path, [this](const httplib::Request& request, httplib::Response& response) {
        Reply reply;
        {
          std::lock_guard<std::mutex> lock(mutex_);
          paths_.push_back(request.path);
          bodies_.push_back(Json::parse(request.body));
          authorization_.push_back(request.get_header_value("Authorization"));
          reply = next_ < script_.size() ? script_[next_] : Failure(500, "script exhausted");
          ++next_;
        }
        if (reply.delay_s > 0) std::this_thread::sleep_for(std::chrono::duration<double>(reply.delay_s));
        response.status = reply.status;
        if (!reply.retry_after.empty()) response.set_header("Retry-After", reply.retry_after);
        response.set_content(reply.body, "application/json");
      });
    port_ = server_.bind_to_any_port("127.0.0.1");
    REQUIRE(port_ > 0);
    thread_ = std::thread([this] { server_.listen_after_bind(); });
    for (int i = 0; i < 200 && !server_.is_running(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ~ScriptedServer() {
    server_.stop();
    thread_.join();
  }
  std::string url() const { return "http://127.0.0.1:" + std::to_string(port_); }
  std::vector<Json> bodies() {
    std::lock_guard<std::mutex> lock(mutex_);
    return bodies_;
  }
  std::vector<std::string> paths() {
    std::lock_guard<std::mutex> lock(mutex_);
    return paths_;
  }
  std::vector<std::string> authorization() {
    std::lock_guard<std::mutex> lock(mutex_);
    return authorization_;
  }

 private:
  httplib::Server server_;
  std::thread thread_;
  int port_ = 0;
  std::mutex mutex_;
  std::vector<Reply> script_;
  std::size_t next_ = 0;
  std::vector<std::string> paths_;
  std::vector<Json> bodies_;
  std::vector<std::string> authorization_;
};

// Options that reach `server` as `model`: a 5 s timeout and `max_retries` retries (none unless asked).
inline LlmOptions ScriptedOptions(const ScriptedServer& server, const std::string& model, int max_retries = 0) {
  LlmOptions o;
  o.url = server.url();
  o.model = model;
  o.timeout_s = 5;
  o.max_retries = max_retries;
  return o;
}

}  // namespace villa::testing
