#include "assets/asset_library.h"

#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <future>
#include <map>
#include <mutex>
#include <set>
#include <unistd.h>

#include "util/atomic_file.h"

namespace villa {
namespace fs = std::filesystem;

namespace {

std::string Env(const char* name) {
  const char* v = std::getenv(name);
  return v ? std::string(v) : std::string();
}

constexpr std::string_view kInsideStaging = ".villa-import-staging-";

// Empty, or holding only what an import staged inside it and never finished (no records yet).
bool IsEmptyDir(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return false;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name.rfind(kInsideStaging, 0) == 0) {
      fs::remove_all(e.path(), ec);  // a killed import's staging
      continue;
    }
    return false;
  }
  return true;
}

// Copies `from` (a file or a folder) to `to`, creating parents; the error names both.
Status CopyInto(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  fs::create_directories(to.parent_path(), ec);
  fs::copy(from, to, fs::copy_options::recursive | fs::copy_options::overwrite_existing, ec);
  if (ec) return Error{"cannot copy " + from.string() + " to " + to.string() + ": " + ec.message()};
  return {};
}

// Swaps two folders in one step where the file system can; else moves the old one aside first.
Status SwapDirs(const fs::path& fresh, const fs::path& dir) {
  std::error_code ec;
  if (!fs::exists(dir, ec)) {
    fs::rename(fresh, dir, ec);
    if (ec) return Error{"cannot move " + fresh.string() + " to " + dir.string() + ": " + ec.message()};
    return {};
  }
  if (::renameat2(AT_FDCWD, fresh.c_str(), AT_FDCWD, dir.c_str(), RENAME_EXCHANGE) == 0) return {};
  // No atomic exchange here (an old kernel or file system): two renames; the old library is kept aside
  // under `fresh` until the new one is in place.
  fs::path aside = fresh.string() + ".old";
  fs::rename(dir, aside, ec);
  if (ec) return Error{"cannot move " + dir.string() + " aside: " + ec.message()};
  fs::rename(fresh, dir, ec);
  if (ec) {
    std::error_code back;
    fs::rename(aside, dir, back);
    return Error{"cannot move " + fresh.string() + " to " + dir.string() + ": " + ec.message()};
  }
  fs::rename(aside, fresh, ec);
  return {};
}

}  // namespace

fs::path DefaultLibraryDir() {
  if (std::string v = Env("VILLA_ASSETS"); !v.empty()) return v;
  if (std::string xdg = Env("XDG_DATA_HOME"); !xdg.empty() && fs::path(xdg).is_absolute()) return fs::path(xdg) / "villa" / "assets";
  std::string home = Env("HOME");
  return fs::path(home.empty() ? "." : home) / ".local" / "share" / "villa" / "assets";
}

// ---- staging

Result<LibraryStaging> LibraryStaging::Begin(const fs::path& dir_in) {
  fs::path dir = fs::absolute(dir_in).lexically_normal();
  if (dir.filename().empty()) dir = dir.parent_path();
  std::error_code ec;
  if (fs::exists(dir, ec)) {
    if (!fs::is_directory(dir, ec)) return Error{dir.string() + ": exists and is not a folder"};
    if (!IsEmptyDir(dir) && !fs::exists(dir / kLibraryRecordsFile, ec))
      return Error{dir.string() + ": holds files but no " + std::string(kLibraryRecordsFile) +
                   ", so it is not an asset library; name a new or empty folder"};
  }
  fs::create_directories(dir.parent_path(), ec);
  if (ec) return Error{dir.parent_path().string() + ": cannot create: " + ec.message()};
  std::string staging_name = ".";
  staging_name += dir.filename().string();
  staging_name += ".staging-";
  staging_name += std::to_string(::getpid());
  fs::path staging = dir.parent_path() / staging_name;
  fs::remove_all(staging, ec);
  fs::create_directories(staging / kLibraryMeshFolder, ec);
  if (ec && IsEmptyDir(dir)) {
    // Issue 33: an empty library folder the user made under a parent we may not write (a read-only
    // share): staged inside it instead, and moved up on Commit.
    std::error_code inside_ec;
    staging = dir / (std::string(kInsideStaging) + std::to_string(::getpid()));
    fs::create_directories(staging / kLibraryMeshFolder, inside_ec);
    if (!inside_ec) return LibraryStaging(dir, staging);
  }
  if (ec) return Error{staging.string() + ": cannot create: " + ec.message()};
  return LibraryStaging(dir, staging);
}

LibraryStaging::LibraryStaging(LibraryStaging&& other) noexcept
    : dir_(std::move(other.dir_)), staging_(std::move(other.staging_)), done_(other.done_) {
  other.done_ = true;
}

LibraryStaging::~LibraryStaging() {
  if (done_ || staging_.empty()) return;
  std::error_code ec;
  fs::remove_all(staging_, ec);
}

Status LibraryStaging::WriteMesh(const std::string& relative, const AssetMesh& mesh) const {
  fs::path path = staging_ / relative;
  std::error_code ec;
  fs::create_directories(path.parent_path(), ec);  // safe to race: an existing folder is no error
  if (ec) return Error{path.parent_path().string() + ": cannot create: " + ec.message()};
  return WriteAssetMesh(path, mesh);
}

Status LibraryStaging::Commit(const std::vector<AssetRecord>& records, const std::string& report,
                              const std::string& replaced_kind) {
  std::vector<AssetRecord> all = records;
  std::set<std::string> ids;
  for (const AssetRecord& r : records) ids.insert(r.id);
  std::error_code ec;
  // Carry over what the old library holds beyond this importer's output.
  if (fs::exists(dir_ / kLibraryRecordsFile, ec)) {
    Result<std::vector<AssetRecord>> old = ReadAssetRecords((dir_ / kLibraryRecordsFile).string());
    if (!old.ok()) return Error{"the library to replace is damaged, so nothing was replaced: " + old.error()};
    for (const AssetRecord& r : *old) {
      if (r.source.kind == replaced_kind || ids.count(r.id)) continue;
      if (!r.mesh.file.empty() && fs::exists(dir_ / r.mesh.file, ec))
        if (Status s = CopyInto(dir_ / r.mesh.file, staging_ / r.mesh.file); !s.ok()) return s;
      if (!r.mesh.full_file.empty() && fs::exists(dir_ / r.mesh.full_file, ec))
        if (Status s = CopyInto(dir_ / r.mesh.full_file, staging_ / r.mesh.full_file); !s.ok()) return s;
      all.push_back(r);
    }
    std::set<std::string> owned = {std::string(kLibraryRecordsFile), std::string(kImportReportFile), std::string(kLibraryMeshFolder)};
    for (const fs::directory_entry& e : fs::directory_iterator(dir_, ec)) {
      std::string name = e.path().filename().string();
      if (owned.count(name)) continue;
      if (Status s = CopyInto(e.path(), staging_ / name); !s.ok()) return s;
    }
  }
  if (Status s = WriteAssetRecords((staging_ / kLibraryRecordsFile).string(), all); !s.ok()) return s;
  if (Status s = WriteFileAtomic(staging_ / kImportReportFile, report); !s.ok()) return s;
  if (staging_.parent_path() == dir_) {
    // Staged inside the (empty) library folder: its entries move up, the records last, so a library is
    // there only once it is whole.
    for (const fs::directory_entry& e : fs::directory_iterator(staging_, ec)) {
      if (e.path().filename() == kLibraryRecordsFile) continue;
      fs::rename(e.path(), dir_ / e.path().filename(), ec);
      if (ec) return Error{"cannot move " + e.path().string() + " into " + dir_.string() + ": " + ec.message()};
    }
    fs::rename(staging_ / kLibraryRecordsFile, dir_ / kLibraryRecordsFile, ec);
    if (ec) return Error{"cannot move the records into " + dir_.string() + ": " + ec.message()};
    fs::remove_all(staging_, ec);
    done_ = true;
    return {};
  }
  if (Status s = SwapDirs(staging_, dir_); !s.ok()) return s;
  fs::remove_all(staging_, ec);  // now the old library
  done_ = true;
  return {};
}

// ---- the library

struct AssetLibrary::MeshCache {
  using Loaded = Result<std::shared_ptr<const AssetMesh>>;
  std::mutex mutex;
  std::map<std::string, std::shared_future<Loaded>, std::less<>> meshes;
  std::map<std::string, std::size_t, std::less<>> index;  // id -> position in records
};

Result<AssetLibrary> AssetLibrary::Open(const fs::path& dir) {
  std::error_code ec;
  fs::path file = dir / kLibraryRecordsFile;
  if (!fs::exists(file, ec))
    return Error{dir.string() + ": no asset library here (no " + std::string(kLibraryRecordsFile) +
                 "; run `villa assets import`)"};
  Result<std::vector<AssetRecord>> records = ReadAssetRecords(file.string());
  if (!records.ok()) return Error{records.error()};
  return FromRecords(std::move(*records), dir);
}

AssetLibrary AssetLibrary::FromRecords(std::vector<AssetRecord> records, fs::path dir) {
  AssetLibrary library;
  library.dir_ = std::move(dir);
  library.cache_ = std::make_shared<MeshCache>();
  for (std::size_t i = 0; i < records.size(); ++i) library.cache_->index.emplace(records[i].id, i);
  library.records_ = std::make_shared<const std::vector<AssetRecord>>(std::move(records));
  return library;
}

const AssetRecord* AssetLibrary::Find(std::string_view id) const {
  auto it = cache_->index.find(id);
  return it == cache_->index.end() ? nullptr : &(*records_)[it->second];
}

Result<std::shared_ptr<const AssetMesh>> AssetLibrary::Mesh(std::string_view id) const {
  std::promise<MeshCache::Loaded> promise;
  std::shared_future<MeshCache::Loaded> future;
  {
    std::lock_guard<std::mutex> lock(cache_->mutex);
    auto it = cache_->meshes.find(id);
    if (it != cache_->meshes.end()) {
      future = it->second;
    } else {
      cache_->meshes.emplace(std::string(id), promise.get_future().share());
    }
  }
  if (future.valid()) return future.get();  // loaded, or being loaded by another thread

  auto load = [&]() -> MeshCache::Loaded {
    if (id.rfind("proc:", 0) == 0) {
      if (!procedural_) return Error{std::string(id) + ": procedural asset, but no generator is available to build its mesh"};
      Result<AssetMesh> made = procedural_(id);
      if (!made.ok()) return Error{made.error()};
      return std::make_shared<const AssetMesh>(std::move(*made));
    }
    const AssetRecord* record = Find(id);
    if (!record) return Error{std::string(id) + ": no such asset in " + (dir_.empty() ? "the library" : dir_.string())};
    if (record->mesh.file.empty()) return Error{std::string(id) + ": the record names no mesh file"};
    Result<AssetMesh> mesh = ReadAssetMesh(dir_ / record->mesh.file);
    if (!mesh.ok()) return Error{std::string(id) + ": " + mesh.error()};
    return std::make_shared<const AssetMesh>(std::move(*mesh));
  };
  MeshCache::Loaded loaded = load();
  promise.set_value(loaded);
  return loaded;
}

}  // namespace villa
