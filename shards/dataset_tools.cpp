#include "shards/dataset_tools.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "partitioner/dataset.h"
#include "scene/file_digest.h"
#include "shards/scenes.h"
#include "util/atomic_file.h"
#include "util/folder_lock.h"
#include "util/hash.h"
#include "util/shard.h"
#include "util/text_table.h"
#include "util/version.h"

namespace villa::shards {
namespace fs = std::filesystem;

namespace {

Result<Json> ReadJsonFile(const fs::path& path) {
  auto text = ReadFile(path);
  if (!text) return Error{text.error()};
  Json j = Json::parse(*text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return Error{path.string() + ": not a JSON object"};
  return j;
}

// "3/8" -> the shard.
Result<Shard> ShardOf(const Json& manifest, const fs::path& dir) {
  const Json& text = manifest.contains("recipe") && manifest["recipe"].contains("shard") ? manifest["recipe"]["shard"]
                                                                                       : manifest.value("shard", Json());
  if (!text.is_string()) return Error{(dir / kManifest).string() + ": no shard"};
  auto shard = ParseShard(text.get<std::string>(), [](const char*) -> const char* { return nullptr; });
  if (!shard) return Error{(dir / kManifest).string() + ": " + shard.error()};
  return *shard;
}

// The recipe with the shard's own parts left out: what every shard of one job shares.
Json SharedRecipe(const Json& manifest) {
  Json r = manifest.value("recipe", Json::object());
  r.erase("shard");
  r.erase("index_range");
  return r;
}

// Hard link, else copy (another file system).
Status LinkOrCopy(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  fs::create_directories(to.parent_path(), ec);
  fs::create_hard_link(from, to, ec);
  if (!ec) return Status{};
  fs::copy_file(from, to, ec);
  if (ec) return Error{to.string() + ": cannot copy from " + from.string() + ": " + ec.message()};
  return Status{};
}

// --floors as the shard's user wrote it, from the manifest's regenerate line.
std::string FloorsText(const Json& manifest) {
  const std::string line = manifest.value("regenerate", "");
  const std::size_t at = line.find(" --floors ");
  if (at == std::string::npos) return "2:4:4";
  const std::size_t from = at + 10, to = line.find(' ', from);
  return line.substr(from, to == std::string::npos ? std::string::npos : to - from);
}

struct ShardFolder {
  fs::path dir;
  Json manifest;
  Shard shard;
};

// Reads and checks that the folders are the shards of one job: one kind, one recipe and tool version,
// every shard index once.
Result<std::vector<ShardFolder>> ReadShards(const std::vector<fs::path>& dirs, std::string* kind) {
  if (dirs.empty()) return Error{"no shard folders given"};
  std::vector<ShardFolder> shards;
  for (const fs::path& dir : dirs) {
    auto manifest = ReadJsonFile(dir / kManifest);
    if (!manifest) return Error{manifest.error() + " (is " + dir.string() + " a shard folder of villa synth or villa scenes?)"};
    const std::string command = manifest->value("command", "");
    if (command != "synth" && command != "scenes") return Error{(dir / kManifest).string() + ": not a villa synth or scenes manifest"};
    auto shard = ShardOf(*manifest, dir);
    if (!shard) return Error{shard.error()};
    shards.push_back({dir, std::move(*manifest), *shard});
  }
  const ShardFolder& a = shards.front();
  *kind = a.manifest["command"].get<std::string>();
  for (const ShardFolder& s : shards) {
    if (s.manifest["command"] != a.manifest["command"])
      return Error{s.dir.string() + ": a " + s.manifest["command"].get<std::string>() + " shard, " + a.dir.string() + " is a " + *kind + " shard"};
    if (s.manifest.value("version", "") != a.manifest.value("version", ""))
      return Error{s.dir.string() + ": made by villa " + s.manifest.value("version", "?") + ", " + a.dir.string() + " by villa " +
                   a.manifest.value("version", "?") + ": shards of one dataset come from one tool version"};
    if (SharedRecipe(s.manifest) != SharedRecipe(a.manifest))
      return Error{s.dir.string() + ": a shard of another recipe (" + SharedRecipe(s.manifest).dump() + ") than " + a.dir.string() + " (" +
                   SharedRecipe(a.manifest).dump() + ")"};
    if (s.shard.count != a.shard.count)
      return Error{s.dir.string() + ": shard " + s.shard.Text() + " of a " + std::to_string(s.shard.count) + "-way split, " +
                   a.dir.string() + " is of a " + std::to_string(a.shard.count) + "-way split"};
  }
  std::sort(shards.begin(), shards.end(), [](const ShardFolder& x, const ShardFolder& y) { return x.shard.index < y.shard.index; });
  for (size_t k = 1; k < shards.size(); ++k)
    if (shards[k].shard.index == shards[k - 1].shard.index)
      return Error{"shard " + shards[k].shard.Text() + " given twice: " + shards[k - 1].dir.string() + " and " + shards[k].dir.string()};
  std::string missing;
  for (uint64_t i = 0, k = 0; i < a.shard.count; ++i) {
    if (k < shards.size() && shards[k].shard.index == i) {
      ++k;
      continue;
    }
    missing += (missing.empty() ? "" : ", ") + Shard{i, a.shard.count}.Text();
  }
  if (!missing.empty()) return Error{"missing shard(s) " + missing + " of " + std::to_string(a.shard.count)};
  return shards;
}

// The output folder, made fresh under a temporary name; Commit renames it into place.
class StagedFolder {
 public:
  explicit StagedFolder(fs::path out) : out_(fs::absolute(out).lexically_normal()) {
    if (out_.filename().empty()) out_ = out_.parent_path();  // "merged/" names the folder "merged"
    temp_ = out_.parent_path() / ("." + out_.filename().string() + ".merge-" + std::to_string(::getpid()));
  }
  ~StagedFolder() {
    std::error_code ec;
    if (!committed_) fs::remove_all(temp_, ec);
  }
  Status Begin() {
    std::error_code ec;
    if (fs::exists(out_, ec) && (!fs::is_directory(out_, ec) || !fs::is_empty(out_, ec)))
      return Error{out_.string() + ": exists and is not an empty folder (merge writes a new dataset)"};
    fs::remove_all(temp_, ec);
    fs::create_directories(temp_, ec);
    if (ec) return Error{temp_.string() + ": cannot create the folder: " + ec.message()};
    return Status{};
  }
  const fs::path& path() const { return temp_; }
  Status Commit() {
    std::error_code ec;
    if (fs::exists(out_, ec)) fs::remove(out_, ec);  // empty (Begin checked)
    fs::rename(temp_, out_, ec);
    if (ec) return Error{out_.string() + ": cannot move the merged dataset into place: " + ec.message()};
    committed_ = true;
    return Status{};
  }

 private:
  fs::path out_, temp_;
  bool committed_ = false;
};

Result<MergeSummary> MergeSynth(const fs::path& out, const std::vector<ShardFolder>& shards) {
  MergeSummary summary{"synth", static_cast<int>(shards.size())};
  StagedFolder staged(out);
  if (Status s = staged.Begin(); !s) return Error{s.error()};
  // Streamed shard by shard (a dataset is gigabytes), hashed on the way.
  AtomicFileWriter layouts(staged.path() / "layouts.jsonl");
  if (!layouts.ok()) return Error{layouts.error()};
  uint64_t checksum = kFnv1a64Offset;
  SynthStats stats;
  std::vector<std::string> previews;
  std::vector<char> buffer(1 << 20);
  for (const ShardFolder& s : shards) {
    if (Status ok = VerifySynthFolder(s.dir); !ok) return Error{ok.error()};
    std::ifstream in(s.dir / "layouts.jsonl", std::ios::binary);
    while (in) {
      in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
      const std::string_view chunk(buffer.data(), static_cast<size_t>(in.gcount()));
      layouts.Write(chunk);
      checksum = Fnv1a64(chunk, checksum);
    }
    if (in.bad()) return Error{(s.dir / "layouts.jsonl").string() + ": read error"};
    auto st = ReadJsonFile(s.dir / "stats.json");
    if (!st) return Error{st.error()};
    SynthStats part = SynthStats::FromJson(*st);
    if (&s == &shards.front()) stats.first_index = part.first_index;
    stats += part;
    for (const std::string& p : s.manifest["files"].value("previews", std::vector<std::string>{})) {
      if (Status l = LinkOrCopy(s.dir / p, staged.path() / p); !l) return Error{l.error()};
      previews.push_back(p);
    }
  }
  const Json& first = shards.front().manifest;
  Json recipe = first["recipe"];
  recipe["shard"] = "0/1";
  recipe["index_range"] = {0, recipe.value("count", uint64_t{0})};
  summary.records = stats.layouts;
  if (Status s = layouts.Commit(); !s) return Error{s.error()};
  if (Status s = WriteFileAtomic(staged.path() / "stats.json", stats.ToJson().dump(2) + "\n"); !s) return Error{s.error()};
  const Json manifest = SynthManifest(recipe, FloorsText(first), stats.layouts, checksum, previews);
  if (Status s = WriteFileAtomic(staged.path() / kManifest, manifest.dump(2) + "\n"); !s) return Error{s.error()};
  if (Status s = staged.Commit(); !s) return Error{s.error()};
  return summary;
}

// One scenes folder's index, checked line by line against the villa folders (hashing every file).
Result<std::vector<Json>> CheckScenes(const fs::path& dir, const Json& manifest, uint64_t* files_hashed) {
  if (!manifest.value("complete", false))
    return Error{dir.string() + ": the shard is not complete (its run was stopped or is still running: rerun it to finish)"};
  if (!manifest.contains("files") || !manifest["files"].contains(kScenesIndex) || !manifest.contains("index_range") ||
      !manifest["index_range"].is_array() || manifest["index_range"].size() != 2)
    return Error{(dir / kManifest).string() + ": not a whole scenes manifest (files, index_range)"};
  auto index = ReadFile(dir / kScenesIndex);
  if (!index) return Error{index.error()};
  const Json& want = manifest["files"][kScenesIndex];
  if (scene::Sha256Hex(*index) != want.value("sha256", ""))
    return Error{(dir / kScenesIndex).string() + ": SHA-256 differs from the manifest's (changed or torn)"};
  std::vector<Json> entries;
  std::istringstream lines(*index);
  std::string line;
  const uint64_t first = manifest["index_range"][0].get<uint64_t>(), last = manifest["index_range"][1].get<uint64_t>();
  std::set<std::string> ids;
  while (std::getline(lines, line)) {
    const std::string where = (dir / kScenesIndex).string() + ":" + std::to_string(entries.size() + 1);
    Json e = Json::parse(line, nullptr, false);
    if (e.is_discarded() || !e.is_object() || !e.contains("id") || !e.contains("files")) return Error{where + ": not an index line"};
    const std::string id = e["id"].is_string() ? e["id"].get<std::string>() : std::string();
    if (std::string bad = VillaIdProblem(id); !bad.empty()) return Error{where + ": " + bad};
    if (e.value("index", uint64_t{0}) != first + entries.size())
      return Error{where + ": \"" + id + "\" has index " + e["index"].dump() + ", expected " + std::to_string(first + entries.size())};
    if (!ids.insert(id).second) return Error{where + ": \"" + id + "\" twice"};
    const fs::path item = dir / kScenesFolder / id;
    auto stored = ReadJsonFile(item / kEntry);
    if (!stored) return Error{stored.error()};
    if (*stored != e) return Error{(item / kEntry).string() + ": differs from its index line " + where};
    auto files = HashFolder(item);
    if (!files) return Error{files.error()};
    for (const auto& [name, sha] : e["files"].items()) {
      if (!files->contains(name)) return Error{(item / name).string() + ": listed in the index, missing"};
      if ((*files)[name] != sha)
        return Error{(item / name).string() + ": SHA-256 " + (*files)[name].get<std::string>() + " differs from the index's " +
                     sha.get<std::string>()};
    }
    for (const auto& [name, sha] : files->items())
      if (!e["files"].contains(name)) return Error{(item / name).string() + ": not in the index"};
    *files_hashed += files->size();
    entries.push_back(std::move(e));
  }
  if (entries.size() != last - first)
    return Error{(dir / kScenesIndex).string() + ": " + std::to_string(entries.size()) + " villas, the shard's range holds " +
                 std::to_string(last - first)};
  std::error_code ec;
  for (const fs::directory_entry& d : fs::directory_iterator(dir / kScenesFolder, ec))
    if (!ids.count(d.path().filename().string())) return Error{d.path().string() + ": a folder the index does not list"};
  return entries;
}

Result<MergeSummary> MergeScenes(const fs::path& out, const std::vector<ShardFolder>& shards) {
  MergeSummary summary{"scenes", static_cast<int>(shards.size())};
  StagedFolder staged(out);
  if (Status s = staged.Begin(); !s) return Error{s.error()};
  std::string index;
  uint64_t hashed = 0;
  for (const ShardFolder& s : shards) {
    auto entries = CheckScenes(s.dir, s.manifest, &hashed);
    if (!entries) return Error{entries.error()};
    for (const Json& e : *entries) {
      const std::string id = e["id"].get<std::string>();
      if (fs::exists(staged.path() / kScenesFolder / id)) return Error{s.dir.string() + ": villa " + id + " is in another shard too"};
      for (const auto& [name, sha] : e["files"].items())
        if (Status l = LinkOrCopy(s.dir / kScenesFolder / id / name, staged.path() / kScenesFolder / id / name); !l) return Error{l.error()};
      if (Status l = LinkOrCopy(s.dir / kScenesFolder / id / kEntry, staged.path() / kScenesFolder / id / kEntry); !l) return Error{l.error()};
      index += e.dump() + "\n";
      ++summary.records;
      if (e.value("status", "") == "failed") ++summary.failed;
    }
  }
  const Json& first = shards.front().manifest;
  const uint64_t total = first.value("layouts", uint64_t{0});
  const Json manifest = ScenesManifest(first["recipe"], Shard{0, 1}, 0, total, total, scene::Sha256Hex(index), summary.records);
  fs::create_directories(staged.path() / kScenesFolder);
  if (Status s = WriteFileAtomic(staged.path() / kScenesIndex, index); !s) return Error{s.error()};
  if (Status s = WriteFileAtomic(staged.path() / kManifest, manifest.dump(2) + "\n"); !s) return Error{s.error()};
  if (Status s = staged.Commit(); !s) return Error{s.error()};
  return summary;
}

std::string Duration(double seconds) {
  if (!(seconds >= 0)) return "-";
  const long s = std::lround(seconds);
  char text[32];
  if (s >= 3600) std::snprintf(text, sizeof text, "%ldh%02ldm", s / 3600, (s / 60) % 60);
  else if (s >= 60) std::snprintf(text, sizeof text, "%ldm%02lds", s / 60, s % 60);
  else std::snprintf(text, sizeof text, "%lds", s);
  return text;
}

}  // namespace

Result<MergeSummary> MergeShards(const fs::path& out, const std::vector<fs::path>& dirs) {
  std::string kind;
  auto shards = ReadShards(dirs, &kind);
  if (!shards) return Error{shards.error()};
  return kind == "synth" ? MergeSynth(out, *shards) : MergeScenes(out, *shards);
}

Result<VerifySummary> VerifyDataset(const fs::path& dir) {
  auto manifest = ReadJsonFile(dir / kManifest);
  if (!manifest) return Error{manifest.error()};
  VerifySummary summary;
  summary.kind = manifest->value("command", "");
  if (summary.kind == "synth") {
    if (Status s = VerifySynthFolder(dir); !s) return Error{s.error()};
    // Every line a record of the shard's range, in order.
    const Json& range = (*manifest)["recipe"]["index_range"];
    uint64_t next = range[0].get<uint64_t>();
    std::string problem;
    Status read = ReadJsonl(dir / "layouts.jsonl", [&](const Json& record, int line) {
      const std::string id = record.is_object() ? record.value("id", "") : "";
      if (id != DatasetRecordId(next)) {
        problem = (dir / "layouts.jsonl").string() + ":" + std::to_string(line) + ": id \"" + id + "\", expected \"" + DatasetRecordId(next) + "\"";
        return false;
      }
      ++next;
      return true;
    });
    if (!read) return Error{read.error()};
    if (!problem.empty()) return Error{problem};
    summary.records = next - range[0].get<uint64_t>();
    summary.files = 1;
    return summary;
  }
  if (summary.kind != "scenes") return Error{(dir / kManifest).string() + ": not a villa synth or scenes manifest"};
  auto entries = CheckScenes(dir, *manifest, &summary.files);
  if (!entries) return Error{entries.error()};
  summary.records = entries->size();
  for (const Json& e : *entries) summary.failed += e.value("status", "") == "failed";
  return summary;
}

Result<std::string> DatasetStatus(const std::vector<fs::path>& dirs, int64_t now) {
  std::vector<fs::path> shards;
  std::error_code ec;
  for (const fs::path& d : dirs) {
    if (!fs::is_directory(d, ec)) return Error{d.string() + ": no such folder"};
    if (fs::exists(d / kManifest, ec) || fs::exists(d / kProgress, ec)) {
      shards.push_back(d);
      continue;
    }
    std::vector<fs::path> found;
    for (const fs::directory_entry& e : fs::directory_iterator(d, ec))
      if (e.is_directory() && (fs::exists(e.path() / kManifest) || fs::exists(e.path() / kProgress))) found.push_back(e.path());
    if (found.empty()) return Error{d.string() + ": neither a shard folder nor a folder of shard folders (no manifest.json)"};
    std::sort(found.begin(), found.end());
    shards.insert(shards.end(), found.begin(), found.end());
  }
  TextTable table({"shard", "folder", "state", "done", "failed", "left", "per hour", "ETA"});
  uint64_t done = 0, failed = 0, left = 0;
  double rate = 0.0, eta = 0.0;
  int running = 0;
  for (const fs::path& d : shards) {
    Json manifest = Json::object(), progress = Json::object();
    if (auto m = ReadJsonFile(d / kManifest)) manifest = *m;
    if (auto p = ReadJsonFile(d / kProgress)) progress = *p;
    const std::string kind = manifest.value("command", "scenes");
    std::string shard = progress.value("shard", manifest.value("shard", manifest.contains("recipe") ? manifest["recipe"].value("shard", "?") : "?"));
    uint64_t d_done = 0, d_failed = 0, d_left = 0;
    std::string state, per_hour = "-", eta_text = "-";
    if (kind == "synth") {
      // A shard's manifest is written last, whole: its presence says done (`verify` re-hashes; status,
      // run often on a shard of gigabytes while others work, does not).
      const bool ok = manifest.contains("files");
      const Json& range = manifest["recipe"]["index_range"];
      const uint64_t n = range.is_array() ? range[1].get<uint64_t>() - range[0].get<uint64_t>() : 0;
      state = ok ? "complete" : "not done";
      d_done = ok ? n : 0, d_left = ok ? 0 : n;
    } else {
      d_done = progress.value("done", uint64_t{0});
      d_failed = progress.value("failed", uint64_t{0});
      const uint64_t villas = progress.value("villas", manifest.contains("index_range") ? manifest["index_range"][1].get<uint64_t>() - manifest["index_range"][0].get<uint64_t>() : 0);
      d_left = villas - std::min(villas, d_done + d_failed);
      const int64_t age = now - progress.value("updated_unix", int64_t{0});
      if (manifest.value("complete", false)) {
        state = "complete";
      } else if (progress.empty()) {
        state = "not started";
      } else if (age <= 600 || FolderLock::HeldElsewhere(d)) {
        state = "running (" + Duration(static_cast<double>(age)) + " ago)";
        const double r = progress.value("villas_per_hour", 0.0);
        rate += r;
        ++running;
        per_hour = FormatFixed(r, 1);
        if (r > 0) {
          const double e = d_left / r * 3600.0;
          eta = std::max(eta, e);
          eta_text = Duration(e);
        }
      } else {
        state = "stopped " + Duration(static_cast<double>(age)) + " ago: rerun it";
      }
    }
    done += d_done, failed += d_failed, left += d_left;
    table.AddRow({shard, d.string(), state, std::to_string(d_done), std::to_string(d_failed), std::to_string(d_left), per_hour, eta_text});
  }
  table.AddRow({"all", std::to_string(shards.size()) + " shard(s)", running ? std::to_string(running) + " running" : "-", std::to_string(done),
                std::to_string(failed), std::to_string(left), running ? FormatFixed(rate, 1) : "-", running && eta > 0 ? Duration(eta) : "-"});
  return table.Render();
}

}  // namespace villa::shards
