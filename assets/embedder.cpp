#include "assets/embedder.h"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <set>

#include "assets/category.h"
#include "util/atomic_file.h"
#include "util/user_dirs.h"

namespace villa {
namespace fs = std::filesystem;

namespace {

// FNV-1a, 64 bits: the feature hash and the cache key (util/ gets the one shared copy with issue 10).
std::uint64_t Fnv1a64(std::string_view text) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  return h;
}

std::string Hex(std::uint64_t v) {
  static const char* kDigits = "0123456789abcdef";
  std::string out(16, '0');
  for (int i = 15; i >= 0; --i, v >>= 4) out[i] = kDigits[v & 15];
  return out;
}

// Lowercase words: runs of ASCII letters and digits, and of bytes >= 0x80 (UTF-8 letters stay whole).
std::vector<std::string> WordsOf(std::string_view text) {
  std::vector<std::string> out;
  std::string word;
  for (unsigned char c : text) {
    if (std::isalnum(c) || c >= 0x80) {
      word.push_back(static_cast<char>(std::tolower(c)));
    } else if (!word.empty()) {
      out.push_back(std::move(word));
      word.clear();
    }
  }
  if (!word.empty()) out.push_back(std::move(word));
  return out;
}

// A plural's usual singular ("shelves" -> "shelf", "lamps" -> "lamp"); other words unchanged.
std::string Singular(const std::string& w) {
  auto ends = [&](std::string_view e) { return w.size() > e.size() + 1 && w.compare(w.size() - e.size(), e.size(), e) == 0; };
  if (ends("ves")) return w.substr(0, w.size() - 3) + "f";
  if (ends("ies")) return w.substr(0, w.size() - 3) + "y";
  if (ends("sses") || ends("xes") || ends("ches") || ends("shes")) return w.substr(0, w.size() - 2);
  if (ends("s") && !ends("ss") && !ends("us")) return w.substr(0, w.size() - 1);
  return w;
}

const std::set<std::string>& StopWords() {
  static const std::set<std::string> words = {"a", "an", "the", "of", "with", "and", "for", "in", "on", "to",
                                              "by", "at", "or", "some", "is", "are", "its", "it", "this", "that"};
  return words;
}

constexpr char kCacheMagic[8] = {'V', 'E', 'M', 'B', '1', '\0', '\0', '\0'};

void PutU32(std::string* out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out->push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}
bool GetU32(const std::string& in, std::size_t* at, std::uint32_t* v) {
  if (*at + 4 > in.size()) return false;
  *v = 0;
  for (int i = 0; i < 4; ++i) *v |= static_cast<std::uint32_t>(static_cast<unsigned char>(in[*at + i])) << (8 * i);
  *at += 4;
  return true;
}

}  // namespace

// ---- lexical

LexicalEmbedder::LexicalEmbedder(int dimensions) : dimensions_(std::max(16, dimensions)) {}

std::string LexicalEmbedder::Name() const { return "lexical-v1/" + std::to_string(dimensions_); }

Embedding LexicalEmbedder::EmbedOne(std::string_view text) const {
  Embedding v(dimensions_, 0.0f);
  auto add = [&](const std::string& feature, double weight) {
    std::uint64_t h = Fnv1a64(feature);
    v[h % static_cast<std::uint64_t>(dimensions_)] += static_cast<float>((h >> 63) ? -weight : weight);
  };
  std::vector<std::string> all = WordsOf(text);
  std::vector<std::string> words;
  for (std::string& w : all)
    if (!StopWords().count(w)) words.push_back(Singular(w));
  for (std::size_t i = 0; i < words.size(); ++i) {
    add("w:" + words[i], 1.0);
    if (i + 1 < words.size()) add("b:" + words[i] + " " + words[i + 1], 0.5);
    std::string marked = "^" + words[i] + "$";
    for (std::size_t k = 0; k + 3 <= marked.size(); ++k) add("c:" + marked.substr(k, 3), 0.2);
  }
  // Vocabulary categories named by one to three words: the synonyms of category.h meet here.
  std::set<std::string_view> named;
  for (std::size_t n = 1; n <= 3; ++n)
    for (std::size_t i = 0; i + n <= words.size(); ++i) {
      std::string phrase = words[i];
      for (std::size_t k = 1; k < n; ++k) phrase += " " + words[i + k];
      if (const CategoryInfo* c = CategoryForWord(phrase)) named.insert(c->name);
    }
  for (std::string_view name : named) add("k:" + std::string(name), 1.5);
  double norm = 0;
  for (float x : v) norm += static_cast<double>(x) * x;
  if (norm > 0)
    for (float& x : v) x = static_cast<float>(x / std::sqrt(norm));
  return v;
}

Result<std::vector<Embedding>> LexicalEmbedder::Embed(const std::vector<std::string>& texts) const {
  std::vector<Embedding> out;
  out.reserve(texts.size());
  for (const std::string& t : texts) out.push_back(EmbedOne(t));
  return out;
}

// ---- cache

fs::path DefaultEmbeddingCacheDir() { return UserCacheDir() / "embeddings"; }

CachedEmbedder::CachedEmbedder(std::shared_ptr<const Embedder> inner, fs::path dir)
    : inner_(std::move(inner)), dir_(std::move(dir)) {}

fs::path CachedEmbedder::FileFor(const std::string& text) const {
  // One folder per model: its name, made safe, plus a hash so different names never share one.
  std::string model;
  for (char c : inner_->Name()) model.push_back(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.' ? c : '_');
  std::string key = Hex(Fnv1a64(text));
  return dir_ / (model + "-" + Hex(Fnv1a64(inner_->Name())).substr(0, 8)) / key.substr(0, 2) / (key + ".vemb");
}

int CachedEmbedder::hits() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return hits_;
}
int CachedEmbedder::misses() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return misses_;
}

Result<std::vector<Embedding>> CachedEmbedder::Embed(const std::vector<std::string>& texts) const {
  std::vector<Embedding> out(texts.size());
  std::vector<std::size_t> missing;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (std::size_t i = 0; i < texts.size(); ++i) {
      if (auto it = memory_.find(texts[i]); it != memory_.end()) {
        out[i] = it->second;
        ++hits_;
        continue;
      }
      // On disk: magic, u32 text length, the text, u32 dimensions, f32 values. A damaged or colliding
      // file is treated as absent (and rewritten below).
      Result<std::string> bytes = ReadFile(FileFor(texts[i]));
      std::size_t at = sizeof kCacheMagic;
      std::uint32_t length = 0, dims = 0;
      bool ok = bytes.ok() && bytes->compare(0, sizeof kCacheMagic, std::string(kCacheMagic, sizeof kCacheMagic)) == 0 &&
                GetU32(*bytes, &at, &length) && at + length <= bytes->size() && bytes->compare(at, length, texts[i]) == 0;
      if (ok) {
        at += length;
        ok = GetU32(*bytes, &at, &dims) && at + 4ull * dims == bytes->size() && dims > 0;
      }
      if (!ok) {
        missing.push_back(i);
        continue;
      }
      Embedding v(dims);
      std::memcpy(v.data(), bytes->data() + at, 4ull * dims);
      memory_.emplace(texts[i], v);
      out[i] = std::move(v);
      ++hits_;
    }
  }
  if (missing.empty()) return out;
  std::vector<std::string> ask;
  for (std::size_t i : missing) ask.push_back(texts[i]);
  Result<std::vector<Embedding>> fresh = inner_->Embed(ask);
  if (!fresh.ok()) return Error{fresh.error()};
  if (fresh->size() != ask.size())
    return Error{inner_->Name() + ": asked for " + std::to_string(ask.size()) + " embeddings, got " + std::to_string(fresh->size())};
  std::lock_guard<std::mutex> lock(mutex_);
  for (std::size_t k = 0; k < missing.size(); ++k) {
    const std::string& text = texts[missing[k]];
    const Embedding& v = (*fresh)[k];
    std::string file(kCacheMagic, sizeof kCacheMagic);
    PutU32(&file, static_cast<std::uint32_t>(text.size()));
    file += text;
    PutU32(&file, static_cast<std::uint32_t>(v.size()));
    file.append(reinterpret_cast<const char*>(v.data()), 4 * v.size());
    fs::path path = FileFor(text);
    std::error_code ec;
    fs::create_directories(path.parent_path(), ec);
    // A cache that cannot be written only costs time: the vectors are still returned.
    if (!ec) (void)WriteFileAtomic(path, file);
    memory_.emplace(text, v);
    out[missing[k]] = v;
    ++misses_;
  }
  return out;
}

}  // namespace villa
