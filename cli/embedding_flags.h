#pragma once
// --embeddings URL (--model NAME | --embeddings-model NAME) [--api-key-env VAR]: retrieval ranks assets by
// the embeddings of an OpenAI-compatible /v1/embeddings endpoint instead of the offline lexical ones,
// every text cached on disk by its hash (assets/embedder.h). Shared by `villa assets search`,
// `villa scene plan` and `villa furnish`.
#include <memory>
#include <string>

#include "assets/embedder.h"

namespace villa::cli {

struct EmbeddingFlags {
  std::string url;          // empty: the offline lexical embedder
  std::string model;
  std::string api_key_env;  // the variable holding the key ("" = none)
  std::string cache_dir;    // default: DefaultEmbeddingCacheDir()
};

// Null when no URL was given; throws UsageError (naming `sub`) for a URL without a model, an unset key
// variable or a bad URL.
std::shared_ptr<const Embedder> EmbedderFrom(const EmbeddingFlags& flags, const std::string& sub);

}  // namespace villa::cli
