#include "cli/embedding_flags.h"

#include <cstdlib>

#include "assets/remote_embedder.h"
#include "cli/command.h"

namespace villa::cli {

std::shared_ptr<const Embedder> EmbedderFrom(const EmbeddingFlags& flags, const std::string& sub) {
  if (flags.url.empty()) {
    if (!flags.model.empty() && sub == "furnish") throw UsageError(sub + ": --embeddings-model needs --embeddings URL");
    return nullptr;
  }
  LlmOptions llm;
  llm.url = flags.url;
  llm.model = flags.model;
  if (llm.model.empty())
    throw UsageError(sub + ": --embeddings needs the embedding model's name (" + (sub == "furnish" ? "--embeddings-model" : "--model") + " NAME)");
  if (!flags.api_key_env.empty()) {
    const char* key = std::getenv(flags.api_key_env.c_str());
    if (!key || !*key) throw UsageError(sub + ": --api-key-env " + flags.api_key_env + ": that environment variable is not set");
    llm.api_key = key;
  }
  std::string message;
  if (!llm.IsValid(&message)) throw UsageError(sub + ": --embeddings: " + message);
  const std::filesystem::path cache = flags.cache_dir.empty() ? DefaultEmbeddingCacheDir() : std::filesystem::path(flags.cache_dir);
  return std::make_shared<CachedEmbedder>(std::make_shared<RemoteEmbedder>(llm), cache);
}

}  // namespace villa::cli
