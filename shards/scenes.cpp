#include "shards/scenes.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <map>
#include <set>

#include "critic/critic.h"
#include "finetune/sample_format.h"
#include "layout/layout_io.h"
#include "layout/validate.h"
#include "scene/acquire.h"
#include "scene/file_digest.h"
#include "util/atomic_file.h"
#include "util/excerpt.h"
#include "util/folder_lock.h"
#include "util/hash.h"
#include "util/version.h"

namespace villa::shards {
namespace fs = std::filesystem;

namespace {

double Round(double v, double unit) { return std::round(v / unit) * unit; }

std::string IsoTime(std::time_t t) {
  char text[32];
  std::tm tm{};
  gmtime_r(&t, &tm);
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

// The index line a villa's folder holds, if it still matches its files and this recipe's view of the villa.
std::optional<Json> VerifiedEntry(const fs::path& item, const LayoutItem& want, uint64_t seed, const std::string& recipe_sha256) {
  auto text = ReadFile(item / kEntry);
  if (!text) return std::nullopt;
  Json entry = Json::parse(*text, nullptr, false);
  if (entry.is_discarded() || !entry.is_object() || entry.value("id", "") != want.id || entry.value("seed", uint64_t{0}) != seed ||
      entry.value("layout_sha256", "") != scene::Sha256Hex(want.layout_json + "\n") ||
      entry.value("recipe_sha256", "") != recipe_sha256 || !entry.contains("files"))
    return std::nullopt;
  auto files = HashFolder(item);
  if (!files || *files != entry["files"]) return std::nullopt;
  return entry;
}

Json Metrics(const solver::FurnishedVilla& villa) {
  const solver::FurnishSummary& s = villa.summary;
  Json m = Json::object();
  m["rooms"] = s.rooms;
  m["furnished"] = s.furnished;
  m["objects"] = s.objects;
  m["CR"] = Round(s.cr(), 1e-4);
  m["FR"] = Round(s.fr(), 1e-4);
  m["OBR"] = Round(s.obr(), 1e-4);
  m["CSR"] = Round(s.csr(), 1e-4);
  if (s.reach_checked) {
    m["RCH"] = Round(s.rch(), 1e-4);
    m["ACC"] = Round(s.acc(), 1e-4);
  }
  if (s.physics_checked) {
    m["physics_free"] = s.stability.free;
    m["physics_strict"] = s.stability.strict;
  }
  m["functional_groups"] = s.functional.groups;
  m["functional_groups_ok"] = s.functional.groups_ok;
  m["library_assets"] = s.library_assets;
  m["procedural_assets"] = s.procedural_assets;
  return m;
}

}  // namespace

std::string VillaIdProblem(const std::string& id) {
  const bool control = std::any_of(id.begin(), id.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; });
  if (id.empty() || id.size() > 200 || id.find('/') != std::string::npos || id.starts_with(".") || control)
    return "\"" + Printable(Excerpt(id)) + "\" cannot name a folder (1 to 200 bytes, no '/', no leading '.', no control bytes)";
  return "";
}

uint64_t VillaSeed(uint64_t seed, const std::string& id) { return SplitMix64Hash(seed ^ Fnv1a64(id)); }

Result<LayoutInput> ReadLayoutInput(const fs::path& file) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) return Error{file.string() + ": no such file (expected a layouts JSONL file)"};
  auto digest = scene::FileSha256(file);  // streamed: an input may be gigabytes
  if (!digest) return Error{digest.error()};
  LayoutInput input;
  input.sha256 = *digest;
  std::set<std::string> ids;
  std::string problem;
  Status read = ReadJsonl(file, [&](const Json& record, int line) {
    const std::string where = file.string() + ":" + std::to_string(line);
    LayoutItem item;
    item.line = line;
    if (!record.is_object()) {
      problem = where + ": expected a JSON object";
      return false;
    }
    Result<Layout> layout = Error{""};
    if (record.contains("layout") || record.contains("rooms")) {
      if (!record.contains("id") || !record["id"].is_string() || record["id"].get<std::string>().empty()) {
        problem = where + ": \"id\": expected a non-empty string";
        return false;
      }
      item.id = record["id"].get<std::string>();
      if (record.value("status", "") == "rejected") {
        ++input.rejected;
        return true;
      }
      layout = LayoutFromRecord(record, where);
    } else {
      auto sample = ParseSampleLine(record);
      if (!sample) {
        problem = where + ": neither a layout record (id, layout) nor a fine-tune sample: " + sample.error();
        return false;
      }
      item.id = "sample-" + std::to_string(line);
      layout = ParseLayoutText(sample->assistant, where + " (the sample's answer)");
    }
    if (!layout) {
      problem = layout.error();
      return false;
    }
    if (std::string bad = VillaIdProblem(item.id); !bad.empty()) {
      problem = where + ": \"id\": " + bad;
      return false;
    }
    if (!ids.insert(item.id).second) {
      problem = where + ": \"id\": \"" + item.id + "\" appears twice";
      return false;
    }
    item.layout_json = LayoutToString(*layout, -1);
    input.items.push_back(std::move(item));
    return true;
  });
  if (!read) return Error{read.error()};
  if (!problem.empty()) return Error{problem};
  if (input.items.empty()) return Error{file.string() + ": no layouts"};
  return input;
}

// The first 16 hex digits of the SHA-256 of the running executable ("unknown" when it cannot be read).
std::string BuildId() {
  static const std::string id = [] {
    auto sha = scene::FileSha256("/proc/self/exe");
    return sha.ok() ? sha->substr(0, 16) : std::string("unknown");
  }();
  return id;
}

Json ScenesRecipe(const ScenesOptions& o, const LayoutInput& input, const std::optional<scene::FileRef>& library) {
  Json recipe = Json::object();
  recipe["input"] = {{"file", o.input.filename().string()}, {"sha256", input.sha256}, {"layouts", input.items.size()}};
  recipe["seed"] = o.seed;
  recipe["villa_seed"] = "SplitMix64Hash(seed ^ FNV-1a64(id))";
  recipe["critic"] = o.critic;
  recipe["reach"] = o.furnish.check_reach;
  recipe["radius"] = o.furnish.reach.reach.radius;
  recipe["physics"] = o.furnish.check_physics;
  recipe["pictures"] = o.furnish.pictures;
  recipe["allow_invalid"] = o.furnish.allow_invalid;
  recipe["library"] = library ? Json{{"sha256", library->sha256}} : Json("procedural");
  // The build that furnishes: the version string stays while the code changes, so a resume after an
  // upgrade would mix two builds' villas under one recipe; the executable's own hash tells them apart.
  recipe["build"] = BuildId();
  return recipe;
}

Json ScenesManifest(const Json& recipe, const Shard& shard, uint64_t first, uint64_t last, uint64_t total,
                    const std::string& index_sha256, uint64_t records) {
  Json m = Json::object();
  m["tool"] = "villa";
  m["version"] = kVersion;
  m["command"] = "scenes";
  m["recipe"] = recipe;
  m["shard"] = shard.Text();
  m["index_range"] = {first, last};
  m["layouts"] = total;
  m["complete"] = !index_sha256.empty();
  if (!index_sha256.empty()) m["files"] = {{kScenesIndex, {{"records", records}, {"sha256", index_sha256}}}};
  return m;
}

Result<Json> HashFolder(const fs::path& dir, const std::string& skip) {
  std::vector<std::string> names;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (!it->is_regular_file(ec)) {
      if (!it->is_directory(ec)) return Error{it->path().string() + ": not a regular file"};
      continue;
    }
    const std::string name = fs::relative(it->path(), dir, ec).generic_string();
    if (name != skip) names.push_back(name);
  }
  if (ec) return Error{dir.string() + ": " + ec.message()};
  std::sort(names.begin(), names.end());
  Json files = Json::object();
  for (const std::string& name : names) {
    auto digest = scene::FileSha256(dir / name);
    if (!digest) return Error{digest.error()};
    files[name] = *digest;
  }
  return files;
}

Result<ScenesSummary> RunScenesShard(const ScenesOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  if (o.critic != "offline" && o.critic != "none") return Error{"usage: --critic " + o.critic + ": expected offline or none"};
  if (std::string problem = o.furnish.Check(); !problem.empty()) return Error{"usage: " + problem};
  auto input = ReadLayoutInput(o.input);
  if (!input) return Error{input.error()};
  auto library = scene::OpenFurnishingLibrary(o.furnish.library, o.furnish.procedural_only);
  if (!library) return Error{library.error()};

  const uint64_t total = input->items.size();
  const uint64_t first = o.shard.First(total), last = o.shard.Last(total);
  const Json recipe = ScenesRecipe(o, *input, library->file);
  const Json manifest = ScenesManifest(recipe, o.shard, first, last, total);
  // Every villa carries its recipe's hash: one made under another recipe is never kept.
  const std::string recipe_sha256 = scene::Sha256Hex(recipe.dump());

  std::error_code ec;
  fs::create_directories(o.out / kScenesFolder, ec);
  if (ec) return Error{(o.out / kScenesFolder).string() + ": cannot create the folder: " + ec.message()};
  // One run a shard: a task resubmitted while the first still runs is refused, not interleaved.
  auto lock = FolderLock::Take(o.out);
  if (!lock) return Error{lock.error().rfind("busy: ", 0) == 0 ? "usage: " + lock.error().substr(6) : lock.error()};

  // A folder of another recipe or shard is someone else's work: refused unless --force starts over.
  if (fs::exists(o.out / kManifest, ec)) {
    auto text = ReadFile(o.out / kManifest);
    Json old = text ? Json::parse(*text, nullptr, false) : Json();
    const bool same = !old.is_discarded() && old.is_object() && old.value("command", "") == "scenes" &&
                      old.value("version", "") == std::string(kVersion) && old.value("recipe", Json()) == recipe &&
                      old.value("shard", "") == o.shard.Text();
    if (!same && !o.force)
      return Error{"usage: " + (o.out / kManifest).string() +
                   ": this folder holds a shard of another recipe, shard or tool version (use --force to start it over)"};
    if (!same)  // the villas first, the manifest last: a kill midway leaves the old recipe's manifest to refuse
      for (const char* name : {kScenesFolder, kScenesIndex, kProgress, kManifest}) {
        fs::remove_all(o.out / name, ec);
        if (ec) return Error{(o.out / name).string() + ": cannot remove it to start over: " + ec.message()};
      }
    fs::create_directories(o.out / kScenesFolder, ec);
  }
  if (Status s = WriteFileAtomic(o.out / kManifest, manifest.dump(2) + "\n"); !s) return Error{s.error()};

  // Temporaries of a killed run go; villa folders that are not this shard's, or torn, are redone below.
  const std::string ours_prefix = ".tmp-";
  for (const fs::directory_entry& e : fs::directory_iterator(o.out / kScenesFolder, ec))
    if (e.path().filename().string().starts_with(ours_prefix)) fs::remove_all(e.path(), ec);

  critic::CriticOptions critic_options;
  critic_options.kind = o.critic == "none" ? critic::CriticKind::kNone : critic::CriticKind::kOffline;
  solver::FurnishOptions furnish = o.furnish;
  furnish.critic = critic::MakeRoomCritic(critic_options);
  furnish.force = false;
  furnish.report_timings = false;  // a villa's files the same on every run: its seconds go to the index

  ScenesSummary summary;
  summary.total = static_cast<int>(last - first);
  std::vector<Json> entries;
  const std::time_t started = std::time(nullptr);
  double furnish_seconds = 0.0;
  int furnished_now = 0;
  auto write_index = [&]() -> Result<std::string> {
    std::string index;
    for (const Json& e : entries) index += e.dump() + "\n";
    if (Status s = WriteFileAtomic(o.out / kScenesIndex, index); !s) return Error{s.error()};
    return index;
  };
  auto write_progress = [&](bool complete) {
    const int finished = summary.skipped + summary.done;
    const double rate = furnished_now > 0 ? furnished_now / furnish_seconds : 0.0;  // villas a second
    Json p = Json::object();
    p["shard"] = o.shard.Text();
    p["index_range"] = {first, last};
    p["villas"] = summary.total;
    p["done"] = finished - summary.failed;
    p["failed"] = summary.failed;
    p["left"] = summary.total - finished;
    p["villas_per_hour"] = Round(rate * 3600.0, 0.1);
    p["eta_seconds"] = rate > 0 ? Json(Round((summary.total - finished) / rate, 1.0)) : Json();
    p["pid"] = static_cast<int64_t>(::getpid());
    char host[256] = "";
    ::gethostname(host, sizeof host - 1);
    p["host"] = host;
    p["started"] = IsoTime(started);
    p["updated"] = IsoTime(std::time(nullptr));
    p["updated_unix"] = static_cast<int64_t>(std::time(nullptr));
    p["complete"] = complete;
    (void)WriteFileAtomic(o.out / kProgress, p.dump(2) + "\n");
  };

  for (uint64_t i = first; i < last; ++i) {
    const LayoutItem& item = input->items[i];
    const uint64_t seed = VillaSeed(o.seed, item.id);
    const fs::path folder = o.out / kScenesFolder / item.id;
    if (auto kept = VerifiedEntry(folder, item, seed, recipe_sha256)) {
      ++summary.skipped;
      if (kept->value("status", "") == "failed") ++summary.failed;
      entries.push_back(std::move(*kept));
      continue;
    }
    // Torn, stale or from another recipe: redone from scratch.
    fs::remove_all(folder, ec);
    const auto villa_start = std::chrono::steady_clock::now();
    const fs::path temp = o.out / kScenesFolder / (ours_prefix + item.id + "-" + std::to_string(::getpid()));
    fs::remove_all(temp, ec);
    fs::create_directories(temp, ec);
    if (ec) return Error{temp.string() + ": cannot create the folder: " + ec.message()};
    const std::string layout_bytes = item.layout_json + "\n";
    if (Status s = WriteFileAtomic(temp / kItemLayout, layout_bytes); !s) return Error{s.error()};

    Json entry = Json::object();
    entry["id"] = item.id;
    entry["index"] = i;
    entry["layout_sha256"] = scene::Sha256Hex(layout_bytes);
    entry["seed"] = seed;
    entry["recipe_sha256"] = recipe_sha256;
    std::string failure;
    auto layout = ParseLayoutText(item.layout_json, o.input.string() + ":" + std::to_string(item.line));
    if (!layout) failure = layout.error();
    if (failure.empty() && !o.furnish.allow_invalid) {
      ValidateOptions vo;
      vo.check_architecture = false;
      const ValidationReport report = ValidateLayout(*layout, vo);
      if (!report.geometric_ok()) {
        failure = "breaks the geometric rules 1-5:";
        for (const Violation& v : report.violations)
          if (v.rule <= 5) failure += " rule " + std::to_string(v.rule) + ": " + v.message + ";";
      }
    }
    if (failure.empty()) {
      solver::FurnishOptions fo = furnish;
      fo.seed = seed;
      auto villa = solver::FurnishLayout(*layout, {kItemLayout, entry["layout_sha256"].get<std::string>()}, library->library,
                                         library->file, fo);
      if (!villa) {
        failure = villa.error();
      } else {
        villa->library_note = library->note;
        auto written = solver::WriteFurnishedVillaFiles(*villa, temp, fo);
        if (!written) return Error{written.error()};  // a write failure is the machine's, not the villa's: stop
        entry["status"] = "ok";
        entry["metrics"] = Metrics(*villa);
      }
    }
    if (!failure.empty()) {
      entry["status"] = "failed";
      entry["error"] = failure;
      ++summary.failed;
    }
    auto files = HashFolder(temp);
    if (!files) return Error{files.error()};
    entry["files"] = *files;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - villa_start).count();
    entry["seconds"] = Round(seconds, 0.001);
    if (Status s = WriteFileAtomic(temp / kEntry, entry.dump(2) + "\n"); !s) return Error{s.error()};
    fs::rename(temp, folder, ec);
    if (ec) return Error{folder.string() + ": cannot move the finished villa into place: " + ec.message()};
    ++summary.done;
    ++furnished_now;
    furnish_seconds += seconds;
    entries.push_back(entry);
    if (auto index = write_index(); !index) return Error{index.error()};
    write_progress(false);
    if (o.on_villa) o.on_villa(entry, summary.skipped + summary.done - summary.failed, summary.failed, summary.total);
  }

  auto index = write_index();
  if (!index) return Error{index.error()};
  summary.complete = true;
  const Json done = ScenesManifest(recipe, o.shard, first, last, total, scene::Sha256Hex(*index), entries.size());
  if (Status s = WriteFileAtomic(o.out / kManifest, done.dump(2) + "\n"); !s) return Error{s.error()};
  write_progress(true);
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

}  // namespace villa::shards
