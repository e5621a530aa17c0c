#pragma once
// A client for OpenAI-compatible chat completion servers (POST {base}/v1/chat/completions): vLLM, SGLang,
// llama.cpp server, Ollama and hosted APIs. libcurl stays inside llm_client.cpp.
//
// Transport policy:
//   - 429, 5xx and connection failures (refused, reset, DNS, TLS, connect timeout) are retried up to
//     `max_retries` times with exponential backoff (backoff_initial_s, doubling, capped at backoff_max_s);
//     a Retry-After header (seconds or an HTTP date) replaces the computed wait when present (capped too).
//   - Any other 4xx fails at once with the server's own error message ("HTTP 401 from URL: ...").
//   - A request that runs past `timeout_s` fails at once ("timed out after 30 s"): a slow model stays slow,
//     so the caller decides (a corrective round, or giving up).
//   - The API key is sent as "Authorization: Bearer ..." and never appears in errors or reports.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "util/result.h"

namespace villa {

struct LlmOptions {
  // Server address: "http://host:port", ".../v1" or the full ".../v1/chat/completions".
  std::string url;
  std::string model;              // "model" of the request, e.g. the LoRA adapter's served name
  std::string api_key;            // the key itself (the CLI reads it from --api-key-env); empty: none
  double temperature = 0.2;       // sampling temperature, >= 0
  std::optional<std::uint64_t> seed;  // sent as "seed" when set
  int max_tokens = 8192;          // answer budget; a layout of 3 floors takes about 3,000 tokens
  double timeout_s = 300.0;       // whole request, s (> 0)
  double connect_timeout_s = 10.0;  // connection set-up, s (> 0)
  int max_retries = 4;            // extra attempts on 429 / 5xx / connection errors (>= 0)
  double backoff_initial_s = 1.0; // first wait, s; doubles each retry
  double backoff_max_s = 30.0;    // cap on any wait, Retry-After included
  bool json_schema = true;        // send response_format json_schema (strict) with LayoutJsonSchema()
  bool disable_thinking = true;   // send chat_template_kwargs {"enable_thinking": false}

  bool IsValid(std::string* message) const;
};

// "http://h:8000" -> "http://h:8000/v1/chat/completions"; ".../v1" -> ".../v1/chat/completions".
std::string ChatCompletionsUrl(const std::string& url);

struct ChatMessage {
  std::string role;     // "system", "user", "assistant"
  std::string content;
};

// The JSON body ChatCompletion() sends (exposed for tests and logs).
nlohmann::ordered_json ChatRequestBody(const LlmOptions& options, const std::vector<ChatMessage>& messages);

struct ChatAnswer {
  std::string content;        // choices[0].message.content
  std::string finish_reason;  // "stop", "length", ...
  int http_attempts = 0;      // requests sent, retries included
  double seconds = 0.0;
};

// Sends one chat completion request (with the retries above). The error names the URL, the HTTP status
// or curl's reason, and the server's message; `attempts`, when given, receives the number of requests sent
// even on failure.
Result<ChatAnswer> ChatCompletion(const LlmOptions& options, const std::vector<ChatMessage>& messages,
                                  int* attempts = nullptr);

// The layout JSON inside a model's answer: strips a <think>...</think> block and ``` / ```json fences,
// and any prose around the outermost {...}. Returns the JSON text (not yet parsed as a layout).
std::string ExtractJsonText(const std::string& answer);

}  // namespace villa
