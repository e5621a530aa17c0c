#pragma once
// A question to a model that must be answered with JSON: the request goes out with the caller's response
// schema; the answer is parsed and checked by the caller; a truncated, malformed or refused answer is
// asked again with what was wrong (a bounded number of corrective turns, as the layout backend does); and
// every answer is kept on disk under the SHA-256 of the request that produced it, so the same question
// asked again (re-running a furnish) is answered from disk without a request. Corrective turns are
// requests too: a replay of the same conversation is answered from the cache turn by turn.
//
//   JsonChatOptions chat;                       // cache folder, corrective turns
//   JsonChatResult r = AskJson(llm, messages, schema, [](const nlohmann::json& j) { return ""; }, chat);
//   if (r.accepted) use(r.value);
//
// The API key (LlmOptions::api_key) is sent in a header by the client and is never part of the request
// body, the cache key, the cache files or the turns handed back.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "llm/client.h"

namespace villa {

struct JsonChatOptions {
  // Corrective turns after a truncated, malformed or refused answer, [0, 10]. Each is one more request
  // that carries the model's answer (unless it was cut off) and what was wrong with it.
  int max_reasks = 2;
  // Where answers are kept; empty: no cache (every question is a request).
  std::filesystem::path cache_dir;
  bool IsValid(std::string* message) const;
};

// $XDG_CACHE_HOME/villa/llm, else ~/.cache/villa/llm.
std::filesystem::path DefaultLlmCacheDir();

// One request and its answer.
struct JsonChatTurn {
  nlohmann::ordered_json request;  // the body as sent (images as data URIs; no key)
  std::string key;                 // SHA-256 (hex) of the endpoint and the body: the cache key
  std::string answer;              // the model's text as received
  std::string finish_reason;
  std::string error;               // what was wrong with this answer ("" when accepted), or the transport error
  bool cached = false;             // answered from the cache, no request sent
  int http_attempts = 0;           // requests sent for this turn, retries included (0 when cached)
  int prompt_tokens = 0;           // the server's usage figures (also when replayed from the cache)
  int completion_tokens = 0;
  double seconds = 0.0;            // wall time of this turn
};

struct JsonChatResult {
  bool accepted = false;
  nlohmann::json value;            // the accepted answer, parsed (null when none was accepted)
  std::vector<JsonChatTurn> turns;
  std::string error;               // why nothing was accepted: the transport error or the last answer's fault
  int requests = 0;                // turns that went to the server
  int cache_hits = 0;              // turns answered from the cache
  int prompt_tokens = 0;           // over the turns (cached ones count what they cost when first asked)
  int completion_tokens = 0;
  double seconds = 0.0;
};

// Checks a parsed answer: "" when usable, else what is wrong, in words the model can act on (it is sent
// back in the corrective turn).
using JsonCheck = std::function<std::string(const nlohmann::json& value)>;

// Asks `messages` with `response_format` (may be null) and returns the first answer that parses as a JSON
// object and passes `check` (may be empty). A transport failure (after the client's retries) ends the
// conversation at once: another turn would meet the same server.
JsonChatResult AskJson(const LlmOptions& llm, std::vector<ChatMessage> messages, const nlohmann::ordered_json& response_format,
                       const JsonCheck& check, const JsonChatOptions& options);

// The cache key of a request: SHA-256 (64 hex digits) of the endpoint URL, a newline and the body.
std::string ChatRequestKey(const LlmOptions& llm, const nlohmann::ordered_json& body);

}  // namespace villa
