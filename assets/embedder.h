#pragma once
// Text embeddings for retrieval: an interface, the offline lexical embedder that is the default, and a
// disk cache that any embedder can sit behind (an OpenAI-compatible /v1/embeddings endpoint is slow and
// costs money; the same texts come back every run).
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include "util/result.h"

namespace villa {

using Embedding = std::vector<float>;

// Implementations must be safe to call from several threads.
class Embedder {
 public:
  virtual ~Embedder() = default;
  // Names the model and its settings; cache entries are keyed by it ("lexical-v1/1024").
  virtual std::string Name() const = 0;
  // One vector per text, in order, all of one length. Errors name the service and what went wrong.
  virtual Result<std::vector<Embedding>> Embed(const std::vector<std::string>& texts) const = 0;
};

// The offline default: a deterministic bag of hashed features, L2-normalised. Features: the words
// (lowercase, singular), word pairs, character trigrams of each word (so "bookshelves" meets
// "bookshelf"), and the vocabulary categories any one to three words name ("couch" and "settee" both add
// the feature of `sofa`: synonyms from assets/category.h). Feature hashing (FNV-1a 64) with a sign bit.
class LexicalEmbedder : public Embedder {
 public:
  explicit LexicalEmbedder(int dimensions = 1024);  // >= 16
  std::string Name() const override;
  Result<std::vector<Embedding>> Embed(const std::vector<std::string>& texts) const override;
  Embedding EmbedOne(std::string_view text) const;

 private:
  int dimensions_;
};

// $XDG_CACHE_HOME/villa/embeddings, else ~/.cache/villa/embeddings.
std::filesystem::path DefaultEmbeddingCacheDir();

// Keeps every vector `inner` returns in `dir`/<model>/<hash>.vemb (one small file a text, written
// atomically, holding the text itself so a hash collision is noticed), and in memory. Texts already
// cached are not sent again; the rest go to `inner` in one call.
class CachedEmbedder : public Embedder {
 public:
  CachedEmbedder(std::shared_ptr<const Embedder> inner, std::filesystem::path dir);
  std::string Name() const override { return inner_->Name(); }
  Result<std::vector<Embedding>> Embed(const std::vector<std::string>& texts) const override;
  int hits() const;    // texts answered from memory or disk so far
  int misses() const;  // texts sent to the inner embedder so far

 private:
  std::filesystem::path FileFor(const std::string& text) const;
  std::shared_ptr<const Embedder> inner_;
  std::filesystem::path dir_;
  mutable std::mutex mutex_;
  mutable std::map<std::string, Embedding> memory_;
  mutable int hits_ = 0;
  mutable int misses_ = 0;
};

}  // namespace villa
