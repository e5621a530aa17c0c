// OpenAI-compatible chat completions over libcurl. The only file of villa that sees curl.
#include "generator/text/llm_client.h"

#include <curl/curl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <mutex>
#include <sstream>
#include <thread>

#include "finetune/layout_schema.h"

namespace villa {
namespace {

using Json = nlohmann::ordered_json;

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
  curl_easy_setopt(curl, CURLOPT_USERAGENT, "villa-plan");
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
// {"detail": ...}), else the body's first 300 bytes.
std::string ServerMessage(const std::string& body) {
  try {
    Json j = Json::parse(body);
    if (j.contains("error")) {
      const Json& e = j["error"];
      if (e.is_string()) return e.get<std::string>();
      if (e.is_object() && e.contains("message") && e["message"].is_string()) return e["message"].get<std::string>();
    }
    if (j.contains("detail")) return j["detail"].is_string() ? j["detail"].get<std::string>() : j["detail"].dump();
    if (j.contains("message") && j["message"].is_string()) return j["message"].get<std::string>();
  } catch (const std::exception&) {
  }
  std::string text = body.substr(0, 300);
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
  if (u.size() >= 17 && u.compare(u.size() - 17, 17, "/chat/completions") == 0) return u;
  if (u.size() >= 3 && u.compare(u.size() - 3, 3, "/v1") == 0) return u + "/chat/completions";
  return u + "/v1/chat/completions";
}

nlohmann::ordered_json ChatRequestBody(const LlmOptions& options, const std::vector<ChatMessage>& messages) {
  Json body;
  body["model"] = options.model;
  Json list = Json::array();
  for (const auto& m : messages) list.push_back(Json{{"role", m.role}, {"content", m.content}});
  body["messages"] = list;
  body["temperature"] = options.temperature;
  if (options.seed) body["seed"] = *options.seed;
  body["max_tokens"] = options.max_tokens;
  if (options.json_schema) body["response_format"] = LayoutResponseFormat();
  if (options.disable_thinking) body["chat_template_kwargs"] = Json{{"enable_thinking", false}};
  body["stream"] = false;
  return body;
}

Result<ChatAnswer> ChatCompletion(const LlmOptions& options, const std::vector<ChatMessage>& messages, int* attempts) {
  GlobalInit();
  const std::string url = ChatCompletionsUrl(options.url);
  const std::string body = ChatRequestBody(options, messages).dump();
  const auto start = std::chrono::steady_clock::now();
  ChatAnswer answer;
  double wait = options.backoff_initial_s;
  std::string last_error;
  for (int attempt = 0; attempt <= options.max_retries; ++attempt) {
    if (attempt > 0) {
      std::this_thread::sleep_for(std::chrono::duration<double>(wait));
      wait = std::min(options.backoff_max_s, std::max(wait * 2, 0.001));
    }
    ++answer.http_attempts;
    if (attempts) *attempts = answer.http_attempts;
    Response response = Post(options, url, body);
    if (response.code != CURLE_OK) {
      if (response.code == CURLE_OPERATION_TIMEDOUT) {
        bool connecting = response.curl_error.find("onnect") != std::string::npos;
        last_error = url + ": " + (connecting ? "connection timed out after " + Seconds(options.connect_timeout_s) + " s"
                                             : "timed out after " + Seconds(options.timeout_s) + " s waiting for the answer");
        if (connecting) continue;
        return Error{last_error};
      }
      last_error = url + ": " + response.curl_error;
      if (RetryableCurl(response.code)) continue;
      return Error{last_error};
    }
    if (response.status == 429 || response.status >= 500) {
      last_error = url + ": HTTP " + std::to_string(response.status) + ": " + ServerMessage(response.body);
      if (response.retry_after_s) wait = std::min(options.backoff_max_s, *response.retry_after_s);
      continue;
    }
    if (response.status < 200 || response.status >= 300) {
      return Error{url + ": HTTP " + std::to_string(response.status) + ": " + ServerMessage(response.body)};
    }
    Json j;
    try {
      j = Json::parse(response.body);
    } catch (const std::exception& e) {
      return Error{url + ": the answer is not JSON: " + std::string(e.what())};
    }
    if (!j.contains("choices") || !j["choices"].is_array() || j["choices"].empty())
      return Error{url + ": the answer has no choices: " + response.body.substr(0, 200)};
    const Json& choice = j["choices"][0];
    if (choice.contains("finish_reason") && choice["finish_reason"].is_string())
      answer.finish_reason = choice["finish_reason"].get<std::string>();
    if (!choice.contains("message") || !choice["message"].is_object())
      return Error{url + ": choices[0] has no message"};
    const Json& message = choice["message"];
    if (message.contains("content") && message["content"].is_string()) answer.content = message["content"].get<std::string>();
    answer.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return answer;
  }
  return Error{last_error + " (gave up after " + std::to_string(answer.http_attempts) + " attempts)"};
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
