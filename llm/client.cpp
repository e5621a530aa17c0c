// OpenAI-compatible chat completions and embeddings over libcurl. The only file of villa that sees curl.
#include "llm/client.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <mutex>
#include <sstream>
#include <thread>

#include <curl/curl.h>

#include "util/excerpt.h"
#include "util/json_read.h"

namespace villa {
namespace {

using Json = nlohmann::ordered_json;

// What stands in for the API key wherever a server echoed it.
constexpr const char* kRedacted = "[redacted]";

// `text` with every occurrence of the key's value replaced, as sent and as a JSON string escapes it (a
// server that echoes the key in a JSON body may escape it). The client passes everything it hands back or
// quotes through this (answers, server messages, bodies, errors), so no caller can leak the key: not
// stderr, not report.json, not a critic's log (client.h).
std::string WithoutKey(std::string text, const std::string& key) {
  if (key.empty()) return text;
  const std::string quoted = Json(key).dump(-1, ' ', false, Json::error_handler_t::replace);
  const std::string escaped = quoted.substr(1, quoted.size() - 2);
  for (const std::string* form : {&key, &escaped}) {
    if (form->empty()) continue;
    for (std::size_t at = text.find(*form); at != std::string::npos; at = text.find(*form, at + std::strlen(kRedacted)))
      text.replace(at, form->size(), kRedacted);
  }
  return text;
}

// A JSON value of an answer quoted in an error: without the key, then cut (so no cut leaves half a key).
std::string Quoted(const Json& value, const std::string& key, std::size_t limit) {
  return Excerpt(WithoutKey(value.dump(-1, ' ', false, Json::error_handler_t::replace), key), limit);
}

void GlobalInit() {
  static std::once_flag once;
  std::call_once(once, [] { curl_global_init(CURL_GLOBAL_DEFAULT); });
}

struct Response {
  long status = 0;
  std::string body;
  std::optional<double> retry_after_s;
  CURLcode code = CURLE_OK;
  std::string curl_error;
};

size_t WriteBody(char* data, size_t size, size_t count, void* user) {
  static_cast<std::string*>(user)->append(data, size * count);
  return size * count;
}

// Collects Retry-After (seconds, or an HTTP date) from the response headers.
size_t ReadHeader(char* data, size_t size, size_t count, void* user) {
  std::string line(data, size * count);
  auto* response = static_cast<Response*>(user);
  std::string lower = line;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  if (lower.rfind("retry-after:", 0) == 0) {
    std::string value = line.substr(12);
    while (!value.empty() && std::isspace(static_cast<unsigned char>(value.front()))) value.erase(value.begin());
    while (!value.empty() && std::isspace(static_cast<unsigned char>(value.back()))) value.pop_back();
    if (!value.empty() && std::all_of(value.begin(), value.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)) || c == '.'; })) {
      response->retry_after_s = std::stod(value);
    } else if (!value.empty()) {
      time_t when = curl_getdate(value.c_str(), nullptr);
      if (when > 0) response->retry_after_s = std::max(0.0, static_cast<double>(when - std::time(nullptr)));
    }
  }
  return size * count;
}

Response Post(const LlmOptions& options, const std::string& url, const std::string& body) {
  Response response;
  CURL* curl = curl_easy_init();
  if (!curl) {
    response.code = CURLE_FAILED_INIT;
    response.curl_error = "curl_easy_init failed";
    return response;
  }
  char error[CURL_ERROR_SIZE] = {0};
  curl_slist* headers = nullptr;
  headers = curl_slist_append(headers, "Content-Type: application/json");
  headers = curl_slist_append(headers, "Accept: application/json");
  std::string auth;
  if (!options.api_key.empty()) {
    auth = "Authorization: Bearer " + options.api_key;
    headers = curl_slist_append(headers, auth.c_str());
  }
  curl_easy_setopt(curl, CURLOPT_URL, url.c_str());
  curl_easy_setopt(curl, CURLOPT_POST, 1L);
  curl_easy_setopt(curl, CURLOPT_POSTFIELDS, body.data());
  curl_easy_setopt(curl, CURLOPT_POSTFIELDSIZE_LARGE, static_cast<curl_off_t>(body.size()));
  curl_easy_setopt(curl, CURLOPT_HTTPHEADER, headers);
  curl_easy_setopt(curl, CURLOPT_WRITEFUNCTION, WriteBody);
  curl_easy_setopt(curl, CURLOPT_WRITEDATA, &response.body);
  curl_easy_setopt(curl, CURLOPT_HEADERFUNCTION, ReadHeader);
  curl_easy_setopt(curl, CURLOPT_HEADERDATA, &response);
  curl_easy_setopt(curl, CURLOPT_ERRORBUFFER, error);
  curl_easy_setopt(curl, CURLOPT_NOSIGNAL, 1L);  // threads: no SIGALRM for timeouts
  curl_easy_setopt(curl, CURLOPT_TIMEOUT_MS, static_cast<long>(options.timeout_s * 1000));
  curl_easy_setopt(curl, CURLOPT_CONNECTTIMEOUT_MS, static_cast<long>(options.connect_timeout_s * 1000));
  curl_easy_setopt(curl, CURLOPT_USERAGENT, "villa");
  response.code = curl_easy_perform(curl);
  if (response.code == CURLE_OK) {
    curl_easy_getinfo(curl, CURLINFO_RESPONSE_CODE, &response.status);
  } else {
    response.curl_error = error[0] ? error : curl_easy_strerror(response.code);
  }
  curl_slist_free_all(headers);
  curl_easy_cleanup(curl);
  return response;
}

// The server's own words from an error body ({"error": {"message": ...}} or {"error": "..."} or
// {"detail": ...}), else the body's first 300 bytes; the key taken out before anything is cut.
std::string ServerMessage(const std::string& raw_body, const std::string& key) {
  const std::string body = WithoutKey(raw_body, key);
  if (Result<Json> parsed = ParseJson<Json>(body, ""); parsed.ok()) {
    const Json& j = *parsed;
    if (j.is_object() && j.contains("error")) {
      const Json& e = j["error"];
      if (e.is_string()) return Excerpt(e.get<std::string>(), 300);
      if (e.is_object() && e.contains("message") && e["message"].is_string()) return Excerpt(e["message"].get<std::string>(), 300);
    }
    if (j.is_object() && j.contains("detail")) return j["detail"].is_string() ? Excerpt(j["detail"].get<std::string>(), 300) : Quoted(j["detail"], key, 300);
    if (j.is_object() && j.contains("message") && j["message"].is_string()) return Excerpt(j["message"].get<std::string>(), 300);
  }
  std::string text = Excerpt(body, 300);
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text.empty() ? "(empty body)" : text;
}

bool RetryableCurl(CURLcode code) {
  switch (code) {
    case CURLE_COULDNT_CONNECT:
    case CURLE_COULDNT_RESOLVE_HOST:
    case CURLE_COULDNT_RESOLVE_PROXY:
    case CURLE_SEND_ERROR:
    case CURLE_RECV_ERROR:
    case CURLE_GOT_NOTHING:
    case CURLE_PARTIAL_FILE:
    case CURLE_SSL_CONNECT_ERROR:
    case CURLE_HTTP2:
    case CURLE_HTTP2_STREAM:
      return true;
    default:
      return false;
  }
}

std::string Seconds(double s) {
  std::ostringstream out;
  out << s;
  return out.str();
}

// POSTs `body` to `url` with the retry policy of client.h and returns the parsed JSON of a 2xx answer.
// `attempts` counts the requests sent, on failure too; `seconds` the wall clock of all of them.
Result<Json> PostJson(const LlmOptions& options, const std::string& url, const std::string& body, int* attempts,
                      double* seconds) {
  GlobalInit();
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  double wait = options.backoff_initial_s;
  std::string last_error;
  *attempts = 0;
  for (int attempt = 0; attempt <= options.max_retries; ++attempt) {
    if (attempt > 0) {
      std::this_thread::sleep_for(std::chrono::duration<double>(wait));
      wait = std::min(options.backoff_max_s, std::max(wait * 2, 0.001));
    }
    ++*attempts;
    Response response = Post(options, url, body);
    response.curl_error = WithoutKey(response.curl_error, options.api_key);
    if (response.code != CURLE_OK) {
      if (response.code == CURLE_OPERATION_TIMEDOUT) {
        bool connecting = response.curl_error.find("onnect") != std::string::npos;
        last_error = url + ": " + (connecting ? "connection timed out after " + Seconds(options.connect_timeout_s) + " s"
                                             : "timed out after " + Seconds(options.timeout_s) + " s waiting for the answer");
        if (connecting) continue;
        elapsed();
        return Error{last_error};
      }
      last_error = url + ": " + response.curl_error;
      if (RetryableCurl(response.code)) continue;
      elapsed();
      return Error{last_error};
    }
    if (response.status == 429 || response.status >= 500) {
      last_error = url + ": HTTP " + std::to_string(response.status) + ": " + ServerMessage(response.body, options.api_key);
      if (response.retry_after_s) wait = std::min(options.backoff_max_s, *response.retry_after_s);
      continue;
    }
    elapsed();
    if (response.status < 200 || response.status >= 300)
      return Error{url + ": HTTP " + std::to_string(response.status) + ": " + ServerMessage(response.body, options.api_key)};
    Result<Json> answer = ParseJson<Json>(response.body, "");
    if (!answer) return Error{url + ": the answer is " + WithoutKey(answer.error(), options.api_key)};
    return answer;
  }
  elapsed();
  return Error{last_error + " (gave up after " + std::to_string(*attempts) + " attempts)"};
}

// The server's path with its endpoint suffix ("/chat/completions", "/embeddings") and a trailing "/v1"
// taken off: what both endpoints are appended to.
std::string ServerBase(const std::string& url) {
  std::string u = url;
  while (!u.empty() && u.back() == '/') u.pop_back();
  for (std::string_view suffix : {std::string_view("/chat/completions"), std::string_view("/embeddings")})
    if (u.size() >= suffix.size() && u.compare(u.size() - suffix.size(), suffix.size(), suffix) == 0) {
      u.resize(u.size() - suffix.size());
      break;
    }
  if (u.size() >= 3 && u.compare(u.size() - 3, 3, "/v1") == 0) u.resize(u.size() - 3);
  return u;
}

bool EndsWith(const std::string& text, std::string_view suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

bool LlmOptions::IsValid(std::string* message) const {
  auto fail = [&](std::string m) {
    if (message) *message = std::move(m);
    return false;
  };
  if (url.empty()) return fail("llm url is empty: give --llm http://host:port");
  if (url.rfind("http://", 0) != 0 && url.rfind("https://", 0) != 0)
    return fail("llm url \"" + url + "\": must start with http:// or https://");
  if (model.empty()) return fail("llm model is empty: give --model NAME (the served model or LoRA adapter name)");
  if (!(temperature >= 0.0 && temperature <= 2.0)) return fail("temperature " + Seconds(temperature) + ": must be in [0, 2]");
  if (max_tokens < 1) return fail("max_tokens " + std::to_string(max_tokens) + ": must be >= 1");
  if (!(timeout_s > 0.0)) return fail("timeout " + Seconds(timeout_s) + " s: must be > 0");
  if (!(connect_timeout_s > 0.0)) return fail("connect timeout " + Seconds(connect_timeout_s) + " s: must be > 0");
  if (max_retries < 0) return fail("max_retries " + std::to_string(max_retries) + ": must be >= 0");
  if (!(backoff_initial_s >= 0.0) || !(backoff_max_s >= 0.0)) return fail("backoff times must be >= 0");
  return true;
}

std::string ChatCompletionsUrl(const std::string& url) {
  std::string u = url;
  while (!u.empty() && u.back() == '/') u.pop_back();
  if (EndsWith(u, "/chat/completions")) return u;
  return ServerBase(u) + "/v1/chat/completions";
}

std::string EmbeddingsUrl(const std::string& url) {
  std::string u = url;
  while (!u.empty() && u.back() == '/') u.pop_back();
  if (EndsWith(u, "/embeddings")) return u;
  if (EndsWith(u, "/chat/completions")) return u.substr(0, u.size() - 17) + "/embeddings";
  return ServerBase(u) + "/v1/embeddings";
}

nlohmann::ordered_json ChatRequestBody(const LlmOptions& options, const std::vector<ChatMessage>& messages,
                                       const nlohmann::ordered_json& response_format) {
  Json body;
  body["model"] = options.model;
  Json list = Json::array();
  for (const auto& m : messages) {
    if (m.images_png.empty()) {
      list.push_back(Json{{"role", m.role}, {"content", m.content}});
      continue;
    }
    Json parts = Json::array();
    if (!m.content.empty()) parts.push_back(Json{{"type", "text"}, {"text", m.content}});
    for (const std::string& png : m.images_png)
      parts.push_back(Json{{"type", "image_url"}, {"image_url", Json{{"url", "data:image/png;base64," + Base64(png)}}}});
    list.push_back(Json{{"role", m.role}, {"content", parts}});
  }
  body["messages"] = list;
  body["temperature"] = options.temperature;
  if (options.seed) body["seed"] = *options.seed;
  body["max_tokens"] = options.max_tokens;
  if (!response_format.is_null()) body["response_format"] = response_format;
  if (options.disable_thinking) body["chat_template_kwargs"] = Json{{"enable_thinking", false}};
  body["stream"] = false;
  return body;
}

Result<ChatAnswer> ChatCompletion(const LlmOptions& options, const std::vector<ChatMessage>& messages,
                                  const nlohmann::ordered_json& response_format, int* attempts) {
  const std::string url = ChatCompletionsUrl(options.url);
  ChatAnswer answer;
  Result<Json> posted = PostJson(options, url, ChatRequestBody(options, messages, response_format).dump(),
                                 &answer.http_attempts, &answer.seconds);
  if (attempts) *attempts = answer.http_attempts;
  if (!posted) return Error{WithoutKey(posted.error(), options.api_key)};
  const Json& j = *posted;
  if (!j.is_object() || !j.contains("choices") || !j["choices"].is_array() || j["choices"].empty())
    return Error{WithoutKey(url, options.api_key) + ": the answer has no choices: " + Quoted(j, options.api_key, 200)};
  const Json& choice = j["choices"][0];
  if (choice.is_object() && choice.contains("finish_reason") && choice["finish_reason"].is_string())
    answer.finish_reason = WithoutKey(choice["finish_reason"].get<std::string>(), options.api_key);
  if (!choice.is_object() || !choice.contains("message") || !choice["message"].is_object())
    return Error{WithoutKey(url, options.api_key) + ": choices[0] has no message"};
  const Json& message = choice["message"];
  if (message.contains("content") && message["content"].is_string())
    answer.content = WithoutKey(message["content"].get<std::string>(), options.api_key);
  if (j.contains("usage") && j["usage"].is_object()) {
    const Json& usage = j["usage"];
    auto count = [&](const char* key) { return usage.contains(key) && usage[key].is_number_integer() ? usage[key].get<int>() : 0; };
    answer.prompt_tokens = count("prompt_tokens");
    answer.completion_tokens = count("completion_tokens");
  }
  return answer;
}

nlohmann::ordered_json EmbeddingsRequestBody(const LlmOptions& options, const std::vector<std::string>& texts) {
  Json body;
  body["model"] = options.model;
  body["input"] = texts;
  return body;
}

namespace {

Result<EmbeddingsAnswer> EmbeddingsWithKey(const LlmOptions& options, const std::vector<std::string>& texts, int* attempts) {
  const std::string url = EmbeddingsUrl(options.url);
  EmbeddingsAnswer answer;
  if (texts.empty()) return answer;
  Result<Json> posted =
      PostJson(options, url, EmbeddingsRequestBody(options, texts).dump(), &answer.http_attempts, &answer.seconds);
  if (attempts) *attempts = answer.http_attempts;
  if (!posted) return Error{posted.error()};
  const Json& j = *posted;
  if (!j.contains("data") || !j["data"].is_array())
    return Error{url + ": the answer has no \"data\" array: " + Quoted(j, options.api_key, 200)};
  const Json& data = j["data"];
  if (data.size() != texts.size())
    return Error{url + ": " + std::to_string(data.size()) + " embeddings for " + std::to_string(texts.size()) + " texts"};
  answer.vectors.assign(texts.size(), {});
  std::vector<bool> seen(texts.size(), false);
  for (std::size_t k = 0; k < data.size(); ++k) {
    const Json& item = data[k];
    const std::string where = url + ": data[" + std::to_string(k) + "]";
    // Servers give "index"; without it the position in "data" is the input's.
    std::size_t index = k;
    if (item.contains("index")) {
      if (!item["index"].is_number_integer() || item["index"].get<long long>() < 0 ||
          item["index"].get<long long>() >= static_cast<long long>(texts.size()))
        return Error{where + ".index: " + Quoted(item["index"], options.api_key, kExcerptLength) + " is not an index of the " +
                     std::to_string(texts.size()) + " texts"};
      index = item["index"].get<std::size_t>();
    }
    if (seen[index]) return Error{where + ".index: " + std::to_string(index) + " appears twice"};
    seen[index] = true;
    if (!item.contains("embedding") || !item["embedding"].is_array() || item["embedding"].empty())
      return Error{where + ".embedding: missing or not a list of numbers"};
    std::vector<float>& vector = answer.vectors[index];
    for (std::size_t i = 0; i < item["embedding"].size(); ++i) {
      const Json& value = item["embedding"][i];
      if (!value.is_number())
        return Error{where + ".embedding[" + std::to_string(i) + "]: " + Quoted(value, options.api_key, kExcerptLength) +
                     " is not a number"};
      vector.push_back(value.get<float>());
    }
  }
  const std::size_t dimension = answer.vectors[0].size();
  for (std::size_t i = 0; i < answer.vectors.size(); ++i)
    if (answer.vectors[i].size() != dimension)
      return Error{url + ": the embedding of text " + std::to_string(i) + " has " + std::to_string(answer.vectors[i].size()) +
                   " numbers, that of text 0 " + std::to_string(dimension)};
  return answer;
}

}  // namespace

Result<EmbeddingsAnswer> Embeddings(const LlmOptions& options, const std::vector<std::string>& texts, int* attempts) {
  Result<EmbeddingsAnswer> answer = EmbeddingsWithKey(options, texts, attempts);
  if (!answer) return Error{WithoutKey(answer.error(), options.api_key)};
  return answer;
}

std::string Base64(const std::string& bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const std::uint32_t n = (std::uint32_t{static_cast<unsigned char>(bytes[i])} << 16) |
                            (std::uint32_t{static_cast<unsigned char>(bytes[i + 1])} << 8) |
                            static_cast<unsigned char>(bytes[i + 2]);
    out += kAlphabet[(n >> 18) & 63], out += kAlphabet[(n >> 12) & 63], out += kAlphabet[(n >> 6) & 63],
        out += kAlphabet[n & 63];
  }
  if (i < bytes.size()) {
    std::uint32_t n = std::uint32_t{static_cast<unsigned char>(bytes[i])} << 16;
    if (i + 1 < bytes.size()) n |= std::uint32_t{static_cast<unsigned char>(bytes[i + 1])} << 8;
    out += kAlphabet[(n >> 18) & 63], out += kAlphabet[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(n >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

std::string ExtractJsonText(const std::string& answer) {
  std::string text = answer;
  // A reasoning block some servers leave in the content.
  if (auto open = text.find("<think>"); open != std::string::npos) {
    auto close = text.find("</think>", open);
    text.erase(open, close == std::string::npos ? std::string::npos : close + 8 - open);
  }
  // ``` or ```json fences: take what is inside the first fenced block.
  if (auto fence = text.find("```"); fence != std::string::npos) {
    auto line_end = text.find('\n', fence);
    if (line_end != std::string::npos) {
      auto close = text.find("```", line_end);
      text = text.substr(line_end + 1, close == std::string::npos ? std::string::npos : close - line_end - 1);
    }
  }
  // Prose around the object.
  auto first = text.find('{');
  auto last = text.rfind('}');
  if (first != std::string::npos && last != std::string::npos && last > first) return text.substr(first, last - first + 1);
  // No closing brace (a truncated answer): hand back what there is so the parser names the problem.
  if (first != std::string::npos) return text.substr(first);
  return text;
}

}  // namespace villa
