#pragma once
// A client for OpenAI-compatible servers (vLLM, SGLang, llama.cpp server, Ollama and hosted APIs):
// chat completions (POST {base}/v1/chat/completions), with text and images (PNG, sent as data URIs in
// image_url content parts, the OpenAI vision format), and embeddings (POST {base}/v1/embeddings, a batch
// of texts to vectors). The caller brings its own response schema (the layout backend binds the layout
// JSON schema; a critic or a planner binds theirs). libcurl stays inside client.cpp.
//
// Transport policy (both endpoints):
//   - 429, 5xx and connection failures (refused, reset, DNS, TLS, connect timeout) are retried up to
//     `max_retries` times with exponential backoff (backoff_initial_s, doubling, capped at backoff_max_s);
//     a Retry-After header (seconds or an HTTP date) replaces the computed wait when present (capped too).
//   - Any other 4xx fails at once with the server's own error message ("HTTP 401 from URL: ...").
//   - A request that runs past `timeout_s` fails at once ("timed out after 30 s"): a slow model stays slow,
//     so the caller decides (a corrective round, or giving up).
//   - The API key is sent as "Authorization: Bearer ..." and nothing the client gives back holds its value:
//     a server that echoes it (in a 401's message, a body, an answer) has it replaced by "[redacted]" in
//     every error, server message and answer, so no caller can write it to stderr, a report or a log.
//   - Answers are read as JSON nested at most 64 deep (util/json_read.h).
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
  double temperature = 0.2;       // sampling temperature, [0, 2]
  std::optional<std::uint64_t> seed;  // sent as "seed" when set
  int max_tokens = 8192;          // answer budget; a layout of 3 floors takes about 3,000 tokens
  double timeout_s = 300.0;       // whole request, s (> 0)
  double connect_timeout_s = 10.0;  // connection set-up, s (> 0)
  int max_retries = 4;            // extra attempts on 429 / 5xx / connection errors (>= 0)
  double backoff_initial_s = 1.0; // first wait, s; doubles each retry
  double backoff_max_s = 30.0;    // cap on any wait, Retry-After included
  bool disable_thinking = true;   // send chat_template_kwargs {"enable_thinking": false}

  bool IsValid(std::string* message) const;
};

// "http://h:8000" -> "http://h:8000/v1/chat/completions"; ".../v1" -> ".../v1/chat/completions".
std::string ChatCompletionsUrl(const std::string& url);
// The same server's embeddings endpoint: "http://h:8000", ".../v1" or ".../v1/chat/completions" ->
// ".../v1/embeddings"; a URL already ending in "/embeddings" is kept.
std::string EmbeddingsUrl(const std::string& url);

struct ChatMessage {
  std::string role;     // "system", "user", "assistant"
  std::string content;  // the text
  // PNG files (their bytes), sent after the text as image_url parts with data:image/png;base64 URLs.
  // Without images the content goes as a plain string, as every OpenAI-compatible server accepts.
  std::vector<std::string> images_png;
};

// The JSON body ChatCompletion() sends (exposed for tests and logs). `response_format` is sent as it is
// when not null (e.g. {"type": "json_schema", "json_schema": {...}}).
nlohmann::ordered_json ChatRequestBody(const LlmOptions& options, const std::vector<ChatMessage>& messages,
                                       const nlohmann::ordered_json& response_format = nullptr);

struct ChatAnswer {
  std::string content;        // choices[0].message.content
  std::string finish_reason;  // "stop", "length", ...
  int http_attempts = 0;      // requests sent, retries included
  double seconds = 0.0;
  // The server's "usage" figures when it sends them (0 when it does not).
  int prompt_tokens = 0;
  int completion_tokens = 0;
};

// Sends one chat completion request (with the retries above). The error names the URL, the HTTP status
// or curl's reason, and the server's message; `attempts`, when given, receives the number of requests sent
// even on failure.
Result<ChatAnswer> ChatCompletion(const LlmOptions& options, const std::vector<ChatMessage>& messages,
                                  const nlohmann::ordered_json& response_format = nullptr, int* attempts = nullptr);

struct EmbeddingsAnswer {
  std::vector<std::vector<float>> vectors;  // one per input text, in input order, all of one length
  int http_attempts = 0;
  double seconds = 0.0;
};

// The JSON body Embeddings() sends: {"model", "input": [texts...]}.
nlohmann::ordered_json EmbeddingsRequestBody(const LlmOptions& options, const std::vector<std::string>& texts);

// Embeds a batch of texts (one request, with the retries above). The answer's data[i].index says which
// text each vector belongs to; a missing, repeated or out-of-range index, a vector that is not all
// numbers, vectors of different lengths or a count other than the texts' is an error naming the URL and
// the bad entry.
Result<EmbeddingsAnswer> Embeddings(const LlmOptions& options, const std::vector<std::string>& texts,
                                    int* attempts = nullptr);

// The JSON inside a model's answer: strips a <think>...</think> block and ``` / ```json fences, and any
// prose around the outermost {...}. Returns the JSON text (not yet parsed).
std::string ExtractJsonText(const std::string& answer);

// RFC 4648 base64 (with padding), as data URIs carry binary.
std::string Base64(const std::string& bytes);

}  // namespace villa
