#include "assets/remote_embedder.h"

#include <algorithm>

namespace villa {

RemoteEmbedder::RemoteEmbedder(LlmOptions options, int batch) : options_(std::move(options)), batch_(std::max(1, batch)) {}

std::string RemoteEmbedder::Name() const { return "remote:" + options_.model + "@" + EmbeddingsUrl(options_.url); }

Result<std::vector<Embedding>> RemoteEmbedder::Embed(const std::vector<std::string>& texts) const {
  std::vector<Embedding> out;
  out.reserve(texts.size());
  for (size_t first = 0; first < texts.size(); first += batch_) {
    const std::vector<std::string> part(texts.begin() + first, texts.begin() + std::min(texts.size(), first + batch_));
    ++requests_;
    auto answer = Embeddings(options_, part);
    if (!answer.ok()) return Error{"embeddings: " + answer.error()};
    if (!out.empty() && !answer->vectors.empty() && answer->vectors[0].size() != out[0].size())
      return Error{"embeddings: " + EmbeddingsUrl(options_.url) + " answered vectors of " + std::to_string(answer->vectors[0].size()) +
                   " numbers after vectors of " + std::to_string(out[0].size())};
    for (Embedding& v : answer->vectors) out.push_back(std::move(v));
  }
  return out;
}

}  // namespace villa
