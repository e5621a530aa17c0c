#include "partitioner/dataset.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <vector>
#include <limits>
#include <fstream>
#include <sstream>
#include <thread>

#include "util/atomic_file.h"
#include "util/hash.h"
#include "util/number.h"
#include "util/shard.h"
#include "util/text_table.h"
#include "util/version.h"

namespace villa {

std::string DatasetRecordId(uint64_t index) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "villa-%06llu", static_cast<unsigned long long>(index));
  return buffer;
}

Json DatasetRecord(uint64_t index, uint64_t seed, const PartitionSummary& summary) {
  Json record = Json::object();
  record["id"] = DatasetRecordId(index);
  record["seed"] = seed;
  record["shape"] = std::string(ShapeClassName(summary.shape));
  record["floors"] = summary.floors;
  record["layout"] = LayoutToJson(summary.layout);
  return record;
}

std::string DatasetRecordLine(uint64_t index, uint64_t seed, const PartitionSummary& summary) {
  return DatasetRecord(index, seed, summary).dump();
}

Status ParseShapeWeights(const std::string& text, double* weights) {
  std::string names;
  for (ShapeClass c : AllShapeClasses()) names += (names.empty() ? "" : ", ") + std::string(ShapeClassName(c));
  for (int i = 0; i < kShapeClassCount; ++i) weights[i] = 0.0;
  double total = 0.0;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    const std::string part = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const std::size_t eq = part.find('=');
    const std::string name = part.substr(0, eq);
    const std::optional<ShapeClass> shape = ParseShapeClass(name);
    if (!shape) return Error{"--shapes \"" + text + "\": \"" + name + "\" is not a footprint class (" + names + ")"};
    const std::optional<double> w = ParseNumber(eq == std::string::npos ? "" : part.substr(eq + 1));
    if (!w || *w < 0.0)
      return Error{"--shapes \"" + text + "\": \"" + part + "\": expected NAME=WEIGHT with a non-negative weight"};
    weights[static_cast<int>(*shape)] = *w;
    total += *w;
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (!(total > 0.0)) return Error{"--shapes \"" + text + "\": at least one weight must be positive"};
  return {};
}

bool SynthOptions::IsValid(std::string* message) const {
  auto fail = [&](std::string text) {
    if (message) *message = std::move(text);
    return false;
  };
  if (count == 0) return fail("--count must be at least 1");
  if (shard_count == 0) return fail("--shard i/n: n must be at least 1");
  if (shard_index >= shard_count)
    return fail("--shard " + std::to_string(shard_index) + "/" + std::to_string(shard_count) + ": i must be below n");
  if (threads < 0) return fail("--threads " + std::to_string(threads) + ": must be >= 0 (0 = all cores)");
  if (previews < 0) return fail("--previews " + std::to_string(previews) + ": must be >= 0");
  double total = 0.0;
  for (double w : floor_weights) {
    if (!(w >= 0.0) || !std::isfinite(w)) return fail("--floors: weights must be non-negative numbers");
    total += w;
  }
  if (!(total > 0.0)) return fail("--floors: at least one weight must be positive");
  std::string inner;
  if (!partition.IsValid(&inner)) return fail(inner);
  return true;
}

Json SynthStats::ToJson() const {
  Json j = Json::object();
  j["layouts"] = layouts;
  j["first_index"] = first_index;
  j["failures"] = failures;
  j["validated"] = validated;
  j["retries"] = retries;
  j["retries_per_layout"] = layouts ? static_cast<double>(retries) / static_cast<double>(layouts) : 0.0;
  j["angled_layouts"] = angled;
  j["angled_interior_layouts"] = angled_interior;
  j["chamfered_layouts"] = chamfered;
  Json fl = Json::object();
  for (const auto& [f, n] : floors) fl[std::to_string(f)] = n;
  j["floors"] = fl;
  Json sh = Json::object();
  for (const auto& [s, n] : shapes) sh[s] = n;
  j["shapes"] = sh;
  Json rpf = Json::object();
  uint64_t floor_count = 0, room_count = 0;
  for (const auto& [r, n] : rooms_per_floor) {
    rpf[std::to_string(r)] = n;
    floor_count += n;
    room_count += n * static_cast<uint64_t>(r);
  }
  j["rooms_per_floor"] = rpf;
  j["mean_rooms_per_floor"] = floor_count ? static_cast<double>(room_count) / static_cast<double>(floor_count) : 0.0;
  Json cat = Json::object();
  for (const auto& [c, n] : categories) cat[c] = n;
  j["categories"] = cat;
  j["seconds"] = std::round(seconds * 1000.0) / 1000.0;
  return j;
}

SynthStats SynthStats::FromJson(const Json& j) {
  SynthStats s;
  s.layouts = j.value("layouts", uint64_t{0});
  s.first_index = j.value("first_index", uint64_t{0});
  s.failures = j.value("failures", uint64_t{0});
  s.validated = j.value("validated", uint64_t{0});
  s.retries = j.value("retries", uint64_t{0});
  s.angled = j.value("angled_layouts", uint64_t{0});
  s.angled_interior = j.value("angled_interior_layouts", uint64_t{0});
  s.chamfered = j.value("chamfered_layouts", uint64_t{0});
  // (value() returns a copy: held here, since items() of a temporary would dangle in the loop)
  const Json floors = j.value("floors", Json::object()), shapes = j.value("shapes", Json::object()),
             per_floor = j.value("rooms_per_floor", Json::object()), categories = j.value("categories", Json::object());
  for (const auto& [k, v] : floors.items()) s.floors[std::stoi(k)] = v.get<uint64_t>();
  for (const auto& [k, v] : shapes.items()) s.shapes[k] = v.get<uint64_t>();
  for (const auto& [k, v] : per_floor.items()) s.rooms_per_floor[std::stoi(k)] = v.get<uint64_t>();
  for (const auto& [k, v] : categories.items()) s.categories[k] = v.get<uint64_t>();
  s.seconds = j.value("seconds", 0.0);
  return s;
}

SynthStats& SynthStats::operator+=(const SynthStats& o) {
  layouts += o.layouts;
  failures += o.failures;
  retries += o.retries;
  validated += o.validated;
  angled += o.angled;
  angled_interior += o.angled_interior;
  chamfered += o.chamfered;
  for (const auto& [k, v] : o.floors) floors[k] += v;
  for (const auto& [k, v] : o.shapes) shapes[k] += v;
  for (const auto& [k, v] : o.rooms_per_floor) rooms_per_floor[k] += v;
  for (const auto& [k, v] : o.categories) categories[k] += v;
  seconds += o.seconds;
  return *this;
}

std::string SynthStats::Report() const {
  std::ostringstream out;
  const double n = static_cast<double>(layouts);
  out << "layouts: " << layouts;
  if (layouts > 0)
    out << " (ids " << DatasetRecordId(first_index) << " .. " << DatasetRecordId(first_index + layouts - 1) << ")";
  out << ", all valid: "
      << (validated == layouts && failures == 0 ? "yes" : "NO") << ", failed seeds: " << failures << "\n";
  {
    TextTable t({"floors", "layouts", "share"});
    for (const auto& [f, c] : floors) t.AddRow({std::to_string(f), std::to_string(c), FormatPercent(double(c), n)});
    out << t.Render();
  }
  {
    TextTable t({"shape", "layouts", "share"});
    for (const auto& [s, c] : shapes) t.AddRow({s, std::to_string(c), FormatPercent(double(c), n)});
    out << t.Render();
    out << "angled outside edge: " << angled << " (" << FormatPercent(double(angled), n)
        << "), angled interior wall: " << angled_interior << " (" << FormatPercent(double(angled_interior), n)
        << "), chamfered corners: " << chamfered << " (" << FormatPercent(double(chamfered), n) << ")\n";
  }
  {
    TextTable t({"rooms/floor", "floors", "share"});
    uint64_t total = 0, rooms = 0;
    for (const auto& [r, c] : rooms_per_floor) total += c, rooms += c * static_cast<uint64_t>(r);
    for (const auto& [r, c] : rooms_per_floor)
      t.AddRow({std::to_string(r), std::to_string(c), FormatPercent(double(c), double(total))});
    out << t.Render();
    out << "mean rooms per floor: " << FormatFixed(total ? double(rooms) / double(total) : 0.0, 2) << "\n";
  }
  {
    TextTable t({"category", "rooms"});
    for (const auto& [c, k] : categories) t.AddRow({c, std::to_string(k)});
    out << t.Render();
  }
  out << "angled edges: " << FormatPercent(double(angled), n) << " of layouts\n";
  out << "retries: " << retries << " (" << FormatFixed(n > 0 ? double(retries) / n : 0.0, 2) << " a layout)\n";
  out << "time: " << FormatFixed(seconds, 2) << " s (" << FormatFixed(seconds > 0 ? n / seconds : 0.0, 0)
      << " layouts/s)\n";
  return out.str();
}

namespace {

struct Outcome {
  std::string line;
  std::string failure;
  uint64_t retries = 0;
  SynthStats part;  // this layout's counts
};

Outcome MakeOne(const SynthOptions& o, const std::vector<int>& floor_plan, uint64_t index) {
  Outcome out;
  PartitionOptions p = o.partition;
  p.floors = floor_plan[index];
  p.shape.reset();
  p.validate = true;
  const uint64_t base = DatasetLayoutSeed(o.seed, index);
  // A seed with no valid layout in max_attempts is replaced by a derived one (recorded in the record's
  // "seed", so the record still regenerates); the floors stay those of the index.
  for (uint64_t k = 0; k < 8; ++k) {
    const uint64_t seed = k == 0 ? base : DatasetLayoutSeed(base, k);
    PartitionSummary s = GenerateLayout(p, seed);
    out.retries += static_cast<uint64_t>(s.retries);
    if (!s.ok()) {
      out.failure = DatasetRecordId(index) + " (seed " + std::to_string(seed) + "): " + s.message;
      continue;
    }
    out.failure.clear();
    out.line = DatasetRecordLine(index, seed, s);
    SynthStats& st = out.part;
    st.layouts = 1;
    st.validated = 1;
    st.angled = s.angled_edges ? 1 : 0;
    st.angled_interior = HasSlantedWallBetweenRooms(s.layout) ? 1 : 0;
    st.chamfered = FootprintChamfered(s.layout, 0) ? 1 : 0;
    st.floors[s.floors] = 1;
    st.shapes[std::string(ShapeClassName(s.shape))] = 1;
    for (int l = 0; l < s.floors; ++l) ++st.rooms_per_floor[static_cast<int>(s.layout.RoomsOnLevel(l).size())];
    for (const Room& r : s.layout.rooms) ++st.categories[std::string(CategoryName(r.category))];
    return out;
  }
  return out;
}

}  // namespace

SynthStats SynthesizeShard(const SynthOptions& options, const std::function<void(const std::string&)>& write_line,
                           const std::function<void(std::size_t)>& on_progress, std::vector<std::string>* failures) {
  const auto start = std::chrono::steady_clock::now();
  const uint64_t first = options.count * options.shard_index / options.shard_count;
  const uint64_t last = options.count * (options.shard_index + 1) / options.shard_count;
  const std::vector<int> floor_plan = DatasetFloorPlan(options.count, options.floor_weights);
  int threads = options.threads > 0 ? options.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  SynthStats stats;
  stats.first_index = first;
  // Batches: workers take indices from a counter; the batch is written in index order once done.
  const uint64_t batch = 2048;
  std::vector<Outcome> results;
  for (uint64_t begin = first; begin < last; begin += batch) {
    const uint64_t end = std::min(last, begin + batch);
    results.assign(end - begin, {});
    std::atomic<uint64_t> next{begin};
    auto work = [&] {
      while (true) {
        const uint64_t i = next.fetch_add(1);
        if (i >= end) break;
        results[i - begin] = MakeOne(options, floor_plan, i);
        if (on_progress) on_progress(1);
      }
    };
    const int n = static_cast<int>(std::min<uint64_t>(static_cast<uint64_t>(threads), end - begin));
    if (n <= 1) {
      work();
    } else {
      std::vector<std::thread> pool;
      for (int t = 0; t < n; ++t) pool.emplace_back(work);
      for (auto& t : pool) t.join();
    }
    for (Outcome& r : results) {
      stats.retries += r.retries;
      if (!r.failure.empty()) {
        ++stats.failures;
        if (failures) failures->push_back(r.failure);
        continue;
      }
      stats += r.part;
      write_line(r.line);
    }
  }
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

Json SynthRecipe(const SynthOptions& options) {
  const Shard shard{options.shard_index, options.shard_count};
  Json recipe = Json::object();
  recipe["count"] = options.count;
  recipe["seed"] = options.seed;
  recipe["floors"] = {options.floor_weights[0], options.floor_weights[1], options.floor_weights[2]};
  recipe["grid"] = options.partition.grid;
  Json shapes = Json::object();
  for (ShapeClass c : AllShapeClasses())
    shapes[std::string(ShapeClassName(c))] = options.partition.shape_weights[static_cast<int>(c)];
  recipe["shapes"] = shapes;
  recipe["shard"] = shard.Text();
  recipe["index_range"] = {shard.First(options.count), shard.Last(options.count)};
  recipe["layout_seed"] = "DatasetLayoutSeed(seed, index); floors by index from DatasetFloorPlan(count, floors)";
  return recipe;
}

Json SynthManifest(const Json& recipe, const std::string& floors_text, uint64_t records, uint64_t checksum,
                   const std::vector<std::string>& previews) {
  Json manifest = Json::object();
  manifest["tool"] = "villa";
  manifest["version"] = kVersion;
  manifest["command"] = "synth";
  char hex[32];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(checksum));
  manifest["recipe"] = recipe;
  std::ostringstream grid_text;
  grid_text << recipe.at("grid").get<double>();
  // --shapes when the recipe's mix is not the default one (old manifests have none).
  std::string shapes_arg;
  if (const auto it = recipe.find("shapes"); it != recipe.end() && it->is_object()) {
    const PartitionOptions defaults;
    bool is_default = true;
    std::string list;
    for (ShapeClass c : AllShapeClasses()) {
      const std::string name(ShapeClassName(c));
      const double w = it->value(name, 0.0);
      is_default = is_default && w == defaults.shape_weights[static_cast<int>(c)];
      if (w > 0.0) {
        std::ostringstream weight;
        weight << w;
        list += (list.empty() ? "" : ",") + name + "=" + weight.str();
      }
    }
    if (!is_default) shapes_arg = " --shapes " + list;
  }
  manifest["regenerate"] = "villa synth --count " + std::to_string(recipe.at("count").get<uint64_t>()) + " --seed " +
                           std::to_string(recipe.at("seed").get<uint64_t>()) + " --floors " + floors_text + " --grid " +
                           grid_text.str() + shapes_arg + " --shard " + recipe["shard"].get<std::string>() + " --out DIR";
  manifest["record"] = "{\"id\", \"seed\", \"shape\", \"floors\", \"layout\"} one a line (layout: FORMAT.md JSON)";
  manifest["files"] = {{"layouts.jsonl", {{"records", records}, {"fnv1a64", hex}}},
                       {"stats.json", Json::object()},
                       {"previews", previews}};
  return manifest;
}

Status VerifySynthFolder(const std::filesystem::path& dir, Json* manifest_out) {
  const std::filesystem::path manifest_path = dir / "manifest.json";
  Result<std::string> text = ReadFile(manifest_path);
  if (!text) return Error{text.error()};
  Json manifest = Json::parse(*text, nullptr, false);
  if (manifest.is_discarded() || !manifest.is_object() || manifest.value("command", "") != "synth" ||
      !manifest.contains("recipe") || !manifest.contains("files"))
    return Error{manifest_path.string() + ": not a villa synth manifest"};
  try {
    const Json& entry = manifest.at("files").at("layouts.jsonl");
    const uint64_t records = entry.at("records").get<uint64_t>();
    const std::string want = entry.at("fnv1a64").get<std::string>();
    // Streamed: a shard of a million layouts is gigabytes.
    const std::filesystem::path file = dir / "layouts.jsonl";
    if (Status s = CheckReadable(file, std::numeric_limits<std::uintmax_t>::max()); !s) return Error{s.error()};
    std::ifstream in(file, std::ios::binary);
    if (!in) return Error{file.string() + ": cannot open"};
    uint64_t hash = kFnv1a64Offset, lines = 0;
    std::vector<char> buffer(1 << 20);
    while (in) {
      in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
      const std::string_view chunk(buffer.data(), static_cast<size_t>(in.gcount()));
      hash = Fnv1a64(chunk, hash);
      lines += static_cast<uint64_t>(std::count(chunk.begin(), chunk.end(), '\n'));
    }
    if (in.bad()) return Error{file.string() + ": read error"};
    char hex[32];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
    if (want != hex)
      return Error{file.string() + ": FNV-1a " + hex + " differs from the manifest's " + want + " (changed or torn)"};
    if (lines != records)
      return Error{(dir / "layouts.jsonl").string() + ": " + std::to_string(lines) + " lines, the manifest says " + std::to_string(records)};
    for (const std::string& preview : manifest.at("files").value("previews", std::vector<std::string>{}))
      if (!std::filesystem::is_regular_file(dir / preview)) return Error{(dir / preview).string() + ": listed in the manifest, missing"};
  } catch (const Json::exception& e) {
    return Error{manifest_path.string() + ": " + e.what()};
  }
  if (manifest_out) *manifest_out = std::move(manifest);
  return Status{};
}

Result<bool> CheckSynthOutput(const SynthOptions& options) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const std::string dir = options.out.string();
  if (!fs::exists(options.out, ec)) return false;
  if (!fs::is_directory(options.out, ec)) return Error{"--out " + dir + ": exists and is not a directory"};
  if (fs::is_empty(options.out, ec) || options.force) return false;
  // A shard run before: the same recipe, whole and verified, is done; another recipe is another dataset.
  if (fs::exists(options.out / "manifest.json", ec)) {
    Json manifest;
    if (VerifySynthFolder(options.out, &manifest)) {
      if (manifest.at("recipe") == SynthRecipe(options) && manifest.value("version", "") == kVersion) return true;
      return Error{"--out " + dir + ": holds another dataset (its manifest's recipe is " + manifest.at("recipe").dump() +
                   "; use --force to replace it)"};
    }
  }
  // Only this command's own files, without a verified manifest: a run killed midway, redone.
  for (const fs::directory_entry& e : fs::directory_iterator(options.out, ec)) {
    const std::string name = e.path().filename().string();
    const bool own = name == "layouts.jsonl" || name == "stats.json" || name == "manifest.json" || name == "previews" ||
                     (name.starts_with(".") && name.find(".tmp-") != std::string::npos);
    if (!own) return Error{"--out " + dir + ": directory is not empty (use --force to write into it)"};
  }
  return false;
}

Result<SynthSummary> SynthesizeDataset(const SynthOptions& options, const PreviewWriter& preview,
                                       const std::function<void(std::size_t)>& on_progress) {
  namespace fs = std::filesystem;
  const fs::path& dir = options.out;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) return Error{dir.string() + ": cannot create directory: " + ec.message()};

  AtomicFileWriter layouts(dir / "layouts.jsonl");
  if (!layouts.ok()) return Error{layouts.error()};
  uint64_t checksum = kFnv1a64Offset;
  std::vector<std::string> preview_lines;
  SynthSummary summary;
  summary.stats = SynthesizeShard(
      options,
      [&](const std::string& line) {
        layouts.Write(line);
        layouts.Write("\n");
        checksum = Fnv1a64("\n", Fnv1a64(line, checksum));
        if (static_cast<int>(preview_lines.size()) < options.previews) preview_lines.push_back(line);
      },
      on_progress, &summary.failures);

  if (!preview_lines.empty()) {
    if (!preview) return Error{"previews asked for, but no preview writer given"};
    fs::create_directories(dir / "previews", ec);
    if (ec) return Error{(dir / "previews").string() + ": cannot create directory: " + ec.message()};
    for (const std::string& line : preview_lines) {
      const Json record = Json::parse(line);
      const std::string id = record.at("id").get<std::string>();
      Result<Layout> layout = LayoutFromRecord(record, id);
      if (!layout) return Error{layout.error()};
      Status written = preview(*layout, id + " (" + record.at("shape").get<std::string>() + ")",
                               dir / "previews" / (id + ".png"));
      if (!written) return Error{written.error()};
      summary.preview_files.push_back("previews/" + id + ".png");
    }
  }

  Status committed = layouts.Commit();
  if (!committed) return Error{committed.error()};
  if (!WriteFileAtomic(dir / "stats.json", summary.stats.ToJson().dump(2) + "\n"))
    return Error{(dir / "stats.json").string() + ": cannot write"};

  summary.manifest = SynthManifest(SynthRecipe(options), options.floors_text, summary.stats.layouts, checksum, summary.preview_files);
  const Json& manifest = summary.manifest;
  if (!WriteFileAtomic(dir / "manifest.json", manifest.dump(2) + "\n"))
    return Error{(dir / "manifest.json").string() + ": cannot write"};
  return summary;
}

}  // namespace villa
