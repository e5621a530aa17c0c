// JSON conversations with corrective turns and an answer cache keyed by the request's SHA-256.
#include "llm/json_chat.h"

#include <openssl/evp.h>

#include <chrono>
#include <cstdio>

#include "util/atomic_file.h"
#include "util/user_dirs.h"

namespace villa {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

constexpr const char* kCacheFormat = "villa-llm-cache/1";

std::string Sha256Hex(const std::string& bytes) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  if (EVP_Digest(bytes.data(), bytes.size(), digest, &length, EVP_sha256(), nullptr) != 1) return "";
  std::string hex;
  char pair[3];
  for (unsigned int i = 0; i < length; ++i) {
    std::snprintf(pair, sizeof pair, "%02x", digest[i]);
    hex += pair;
  }
  return hex;
}

fs::path CacheFile(const fs::path& dir, const std::string& key) { return dir / key.substr(0, 2) / (key + ".json"); }

// A cached answer, or nothing when there is none (or the file is damaged or belongs to another key).
bool ReadCached(const fs::path& dir, const std::string& key, JsonChatTurn* turn) {
  if (dir.empty() || key.empty()) return false;
  Result<std::string> text = ReadFile(CacheFile(dir, key));
  if (!text.ok()) return false;
  try {
    const nlohmann::json j = nlohmann::json::parse(*text);
    if (j.value("format", "") != kCacheFormat || j.value("key", "") != key || !j.contains("answer") || !j["answer"].is_string())
      return false;
    turn->answer = j["answer"].get<std::string>();
    turn->finish_reason = j.value("finish_reason", "");
    turn->prompt_tokens = j.value("prompt_tokens", 0);
    turn->completion_tokens = j.value("completion_tokens", 0);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

void WriteCached(const fs::path& dir, const JsonChatTurn& turn, const std::string& model) {
  if (dir.empty() || turn.key.empty()) return;
  Json j{{"format", kCacheFormat},
         {"key", turn.key},
         {"model", model},
         {"answer", turn.answer},
         {"finish_reason", turn.finish_reason},
         {"prompt_tokens", turn.prompt_tokens},
         {"completion_tokens", turn.completion_tokens},
         {"seconds", turn.seconds}};
  const fs::path path = CacheFile(dir, turn.key);
  std::error_code ec;
  fs::create_directories(path.parent_path(), ec);
  // A cache that cannot be written costs time on the next run, nothing else.
  if (!ec) (void)WriteFileAtomic(path, j.dump(1) + "\n");
}

}  // namespace

bool JsonChatOptions::IsValid(std::string* message) const {
  if (max_reasks < 0 || max_reasks > 10) {
    if (message) *message = "corrective turns " + std::to_string(max_reasks) + ": must be in [0, 10]";
    return false;
  }
  return true;
}

fs::path DefaultLlmCacheDir() { return UserCacheDir() / "llm"; }

std::string ChatRequestKey(const LlmOptions& llm, const nlohmann::ordered_json& body) {
  return Sha256Hex(ChatCompletionsUrl(llm.url) + "\n" + body.dump());
}

JsonChatResult AskJson(const LlmOptions& llm, std::vector<ChatMessage> messages, const nlohmann::ordered_json& response_format,
                       const JsonCheck& check, const JsonChatOptions& options) {
  JsonChatResult result;
  for (int turn_index = 0; turn_index <= options.max_reasks; ++turn_index) {
    const auto start = std::chrono::steady_clock::now();
    JsonChatTurn turn;
    turn.request = ChatRequestBody(llm, messages, response_format);
    turn.key = ChatRequestKey(llm, turn.request);
    if (ReadCached(options.cache_dir, turn.key, &turn)) {
      turn.cached = true;
      ++result.cache_hits;
    } else {
      Result<ChatAnswer> answer = ChatCompletion(llm, messages, response_format, &turn.http_attempts);
      ++result.requests;
      if (!answer.ok()) {
        turn.error = answer.error();
        turn.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        result.seconds += turn.seconds;
        result.error = answer.error();
        result.turns.push_back(std::move(turn));
        return result;
      }
      turn.answer = answer->content;
      turn.finish_reason = answer->finish_reason;
      turn.prompt_tokens = answer->prompt_tokens;
      turn.completion_tokens = answer->completion_tokens;
      turn.seconds = answer->seconds;
      WriteCached(options.cache_dir, turn, llm.model);
    }
    turn.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.prompt_tokens += turn.prompt_tokens;
    result.completion_tokens += turn.completion_tokens;
    result.seconds += turn.seconds;

    std::string feedback;
    nlohmann::json parsed;
    if (turn.finish_reason == "length") {
      turn.error = "the answer was cut off at max_tokens (finish_reason \"length\") after " +
                   std::to_string(turn.answer.size()) + " characters";
      feedback = "Your previous answer was cut off before the JSON was complete. Answer again, shorter: one compact "
                 "JSON object and nothing else.";
    } else {
      try {
        parsed = nlohmann::json::parse(ExtractJsonText(turn.answer));
        if (!parsed.is_object()) turn.error = "the answer is JSON but not an object";
      } catch (const std::exception& e) {
        turn.error = "the answer is not valid JSON: " + std::string(e.what());
      }
      if (turn.error.empty() && check) turn.error = check(parsed);
      if (!turn.error.empty())
        feedback = "Your previous answer cannot be used: " + turn.error +
                   "\nAnswer again with one JSON object that follows the schema, and nothing else.";
    }
    const bool accepted = turn.error.empty();
    const std::string answer_text = turn.answer;
    const bool cut_off = turn.finish_reason == "length";
    result.turns.push_back(std::move(turn));
    if (accepted) {
      result.accepted = true;
      result.value = std::move(parsed);
      result.error.clear();
      return result;
    }
    result.error = result.turns.back().error;
    if (turn_index == options.max_reasks) break;
    // A cut-off answer is not repeated back (it would only invite the same length again).
    if (!cut_off) messages.push_back({"assistant", answer_text, {}});
    messages.push_back({"user", feedback, {}});
  }
  result.error = "no usable answer in " + std::to_string(result.turns.size()) +
                 (result.turns.size() == 1 ? " turn" : " turns") + "; last: " + result.error;
  return result;
}

}  // namespace villa
