#pragma once
// Embeddings from any OpenAI-compatible /v1/embeddings endpoint (vLLM, llama.cpp server, Ollama, hosted
// APIs) for retrieval (assets/retrieval.h): `--embeddings URL --model NAME`. Put it behind a
// CachedEmbedder (assets/embedder.h): every text is sent once, then read from disk by its hash.
#include <atomic>
#include <string>
#include <vector>

#include "assets/embedder.h"
#include "llm/client.h"

namespace villa {

class RemoteEmbedder : public Embedder {
 public:
  // `batch`: texts per request, >= 1.
  explicit RemoteEmbedder(LlmOptions options, int batch = 64);
  // "remote:<model>@<endpoint>": a cache entry belongs to one model of one server.
  std::string Name() const override;
  // One request per `batch` texts (the client's retries inside); an error names the endpoint and the
  // server's words.
  Result<std::vector<Embedding>> Embed(const std::vector<std::string>& texts) const override;
  int requests() const { return requests_; }

 private:
  LlmOptions options_;
  int batch_;
  mutable std::atomic<int> requests_{0};
};

}  // namespace villa
