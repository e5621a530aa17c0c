#include "annotator/packages.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>

#include "layout/layout_io.h"
#include "util/atomic_file.h"
#include "util/hash.h"

namespace villa::annotator {
namespace {

namespace fs = std::filesystem;

// FNV-1a of the text, finished with SplitMix64's mixer (util/hash.h).
std::uint64_t HashText(const std::string& text) { return SplitMix64Mix(Fnv1a64(text)); }

std::string Hex(std::uint64_t v, int digits) {
  char buffer[24];
  std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(v));
  return std::string(buffer).substr(16 - digits);
}

std::string PackageName(int part, int parts) { return "part-" + std::to_string(part) + "-of-" + std::to_string(parts); }

double Since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The lines of a file as they are (without their '\n'), numbered from 1 like ReadJsonl.
Result<std::vector<std::string>> FileLines(const fs::path& path) {
  auto text = ReadFile(path);
  if (!text) return Error{text.error()};
  std::vector<std::string> lines;
  std::istringstream in(*text);
  std::string line;
  while (std::getline(in, line)) lines.push_back(line);
  return lines;
}

Result<JournalJson> ReadJsonFile(const fs::path& path) {
  auto text = ReadFile(path);
  if (!text) return Error{text.error()};
  try {
    return JournalJson::parse(*text);
  } catch (const JournalJson::parse_error& e) {
    return Error{path.string() + ": not valid JSON: " + e.what()};
  }
}

}  // namespace

std::string SplitOptions::Invalid() const {
  if (parts < 2 || parts > 1000) return "--split: " + std::to_string(parts) + " packages: give 2 to 1000";
  if (!(overlap >= 0 && overlap <= 0.5)) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%g", overlap);
    return std::string("--overlap: ") + buffer + " is not a share from 0 to 0.5";
  }
  return "";
}

std::string SplitSummary::Brief() const {
  std::ostringstream out;
  out << "split " << layouts << " layouts into " << packages.size() << " packages in " << folder.string() << " (";
  for (std::size_t i = 0; i < sizes.size(); ++i) out << (i ? ", " : "") << sizes[i];
  out << " layouts); " << overlap << " in two packages (the overlap sample, for agreement)";
  if (left_out > 0) out << "; " << left_out << " already decided by a person, not shared out";
  return out.str();
}

std::string MergeSummary::Brief() const {
  std::ostringstream out;
  out << "merged " << lines << " journal line" << (lines == 1 ? "" : "s") << " about " << layouts << " layout"
      << (layouts == 1 ? "" : "s") << " from " << packages << " package" << (packages == 1 ? "" : "s");
  if (!annotators.empty()) {
    out << " (";
    for (std::size_t i = 0; i < annotators.size(); ++i) out << (i ? ", " : "") << annotators[i];
    out << ")";
  }
  return out.str();
}

Result<SplitSummary> SplitIntoPackages(const Session& session, const SplitOptions& options) {
  auto start = std::chrono::steady_clock::now();
  if (std::string why = options.Invalid(); !why.empty()) return Error{why};
  const fs::path dir = session.dataset().dir;
  SplitSummary summary;
  summary.folder = dir / "packages";
  std::error_code ec;
  if (fs::exists(summary.folder, ec)) {
    for (const auto& entry : fs::directory_iterator(summary.folder, ec))
      if (entry.path().filename().string().rfind("part-", 0) == 0 || entry.path().filename() == "split.json")
        return Error{entry.path().string() + ": exists (a split was made before: merge its packages with --merge, "
                                             "then move " + summary.folder.string() + " away)"};
  }

  // Layouts still waiting for a person: not decided by anyone but --auto.
  std::vector<int> items;
  for (int i = 0; i < session.size(); ++i) {
    const AnnotationState& s = session.state(i);
    bool decided_by_person = (s.status == AnnotationStatus::kVerified || s.status == AnnotationStatus::kRejected) &&
                             s.decided_by != kAutoAnnotator &&
                             !(s.decided_by.empty() && s.reason.rfind("auto:", 0) == 0);
    if (decided_by_person)
      ++summary.left_out;
    else
      items.push_back(i);
  }
  int n = static_cast<int>(items.size());
  if (n < options.parts)
    return Error{dir.string() + ": " + std::to_string(n) + " layouts wait for a person: too few for " +
                 std::to_string(options.parts) + " packages"};

  // The overlap sample: the ids with the smallest hashes.
  int k = static_cast<int>(std::lround(options.overlap * n));
  std::vector<std::pair<std::uint64_t, int>> ranked;
  for (int j = 0; j < n; ++j) ranked.push_back({HashText(session.record(items[j]).id), j});
  std::sort(ranked.begin(), ranked.end());
  std::vector<bool> overlap(n, false);
  for (int j = 0; j < k; ++j) overlap[ranked[j].second] = true;

  auto source = FileLines(LayoutsPath(dir));
  if (!source) return Error{source.error()};
  std::string split_id = Hex(HashText(fs::absolute(dir).string() + UtcNow() + std::to_string(::getpid()) +
                                      std::to_string(std::chrono::steady_clock::now().time_since_epoch().count())),
                             8);
  std::vector<std::vector<int>> members(options.parts);  // positions j into items, in dataset order
  for (int j = 0; j < n; ++j) {
    int part = static_cast<int>(static_cast<long long>(j) * options.parts / n);
    members[part].push_back(j);
    if (overlap[j]) members[(part + 1) % options.parts].push_back(j);
  }
  JournalJson overlap_ids = JournalJson::array();
  for (int j = 0; j < n; ++j)
    if (overlap[j]) overlap_ids.push_back(session.record(items[j]).id);

  for (int part = 0; part < options.parts; ++part) {
    std::vector<int>& m = members[part];
    std::sort(m.begin(), m.end());
    std::string name = PackageName(part + 1, options.parts);
    fs::path folder = summary.folder / name;
    fs::create_directories(folder, ec);
    if (ec) return Error{folder.string() + ": cannot create: " + ec.message()};
    std::string layouts, journal;
    long seq = 0;
    JournalJson shared = JournalJson::array();
    for (int j : m) {
      int item = items[j];
      const DatasetRecord& rec = session.record(item);
      if (rec.line < 1 || rec.line > static_cast<int>(source->size()))
        return Error{LayoutsPath(dir).string() + ":" + std::to_string(rec.line) + ": changed while splitting"};
      layouts += (*source)[rec.line - 1] + "\n";
      if (overlap[j]) shared.push_back(rec.id);
      if (!session.Touched(item)) continue;
      // The layout's state now (e.g. --auto's drafts), as the package's first line about it.
      JournalJson line;
      line["v"] = kJournalVersion;
      line["seq"] = ++seq;
      line["time"] = UtcNow();
      line["id"] = rec.id;
      line["kind"] = "batch";
      line["action"] = "split: the state in " + dir.string();
      line["annotator"] = session.annotator();
      line["seconds"] = 0;
      line["split"] = split_id + "/" + name;
      line["state"] = StateToJson(session.state(item));
      journal += line.dump(-1, ' ', false, JournalJson::error_handler_t::replace) + "\n";
    }
    JournalJson manifest;
    manifest["format"] = "villa annotate package";
    manifest["version"] = 1;
    manifest["split"] = split_id;
    manifest["package"] = name;
    manifest["part"] = part + 1;
    manifest["parts"] = options.parts;
    manifest["dataset"] = fs::absolute(dir).lexically_normal().string();
    manifest["layouts"] = static_cast<int>(m.size());
    manifest["overlap"] = shared;
    manifest["created"] = UtcNow();
    manifest["by"] = session.annotator();
    for (auto [file, text] : {std::pair{LayoutsPath(folder), layouts}, std::pair{JournalPath(folder), journal},
                              std::pair{folder / "package.json", manifest.dump(2) + "\n"}}) {
      if (text.empty()) continue;  // no journal yet: the package starts from the drafts
      if (Status s = WriteFileAtomic(file, text); !s) return Error{s.error()};
    }
    summary.packages.push_back(name);
    summary.sizes.push_back(static_cast<int>(m.size()));
  }
  JournalJson record;
  record["format"] = "villa annotate split";
  record["version"] = 1;
  record["id"] = split_id;
  record["parts"] = options.parts;
  record["overlap_share"] = options.overlap;
  record["packages"] = summary.packages;
  record["overlap"] = overlap_ids;
  record["created"] = UtcNow();
  record["by"] = session.annotator();
  if (Status s = WriteFileAtomic(summary.folder / "split.json", record.dump(2) + "\n"); !s) return Error{s.error()};
  summary.layouts = n;
  summary.overlap = k;
  summary.seconds = Since(start);
  return summary;
}

Result<MergeSummary> MergePackages(Session& session, const std::vector<fs::path>& packages) {
  auto start = std::chrono::steady_clock::now();
  MergeSummary summary;
  std::set<std::string> layouts;
  std::set<std::string> annotators;
  for (const fs::path& folder : packages) {
    fs::path manifest_path = folder / "package.json";
    std::error_code ec;
    if (!fs::exists(manifest_path, ec))
      return Error{manifest_path.string() + ": missing (not a package made by `villa annotate DIR --split N`)"};
    auto manifest = ReadJsonFile(manifest_path);
    if (!manifest) return Error{manifest.error()};
    if (!manifest->is_object() || manifest->value("format", "") != "villa annotate package")
      return Error{manifest_path.string() + ": \"format\" is not \"villa annotate package\""};
    std::string name = manifest->value("split", "") + "/" + manifest->value("package", folder.filename().string());
    // Every layout of the package must be this dataset's, unchanged.
    auto dataset = LoadDataset(folder);
    if (!dataset) return Error{dataset.error()};
    for (const DatasetRecord& rec : dataset->records) {
      int item = session.dataset().Find(rec.id);
      if (item < 0)
        return Error{LayoutsPath(folder).string() + ":" + std::to_string(rec.line) + ": \"" + rec.id + "\" is not in " +
                     LayoutsPath(session.dataset().dir).string() + " (a package of another dataset?)"};
      if (LayoutToString(session.record(item).layout, -1) != LayoutToString(rec.layout, -1))
        return Error{LayoutsPath(folder).string() + ":" + std::to_string(rec.line) + ": \"" + rec.id +
                     "\" differs from the layout in " + LayoutsPath(session.dataset().dir).string()};
    }
    auto journal = ReadJournal(JournalPath(folder), false);
    if (!journal) return Error{journal.error()};
    auto added = session.MergeLines(name, journal->lines, JournalPath(folder));
    if (!added) return Error{added.error()};
    for (const JournalLine& line : journal->lines) {
      if (line.json.contains("split")) continue;
      layouts.insert(line.json.value("id", ""));
      if (std::string who = line.json.value("annotator", ""); !who.empty() && who != kAutoAnnotator) annotators.insert(who);
    }
    summary.lines += *added;
    ++summary.packages;
  }
  summary.layouts = static_cast<int>(layouts.size());
  summary.annotators.assign(annotators.begin(), annotators.end());
  summary.seconds = Since(start);
  return summary;
}

std::optional<SplitRecord> ReadSplitRecord(const fs::path& dir) {
  std::error_code ec;
  fs::path path = dir / "packages" / "split.json";
  if (!fs::exists(path, ec)) return std::nullopt;
  auto json = ReadJsonFile(path);
  if (!json || !json->is_object()) return std::nullopt;
  SplitRecord r;
  r.id = json->value("id", "");
  r.parts = json->value("parts", 0);
  if (auto o = json->find("overlap"); o != json->end() && o->is_array())
    for (const auto& id : *o)
      if (id.is_string()) r.overlap.push_back(id.get<std::string>());
  return r;
}

}  // namespace villa::annotator
