#include "util/staged_output.h"

#include <fstream>
#include <sstream>

#include "util/atomic_file.h"

namespace villa {
namespace fs = std::filesystem;

namespace {

constexpr const char* kMarker = ".commit";  // inside the staging folder: the names to move, one a line

// Moves the names listed in the staging folder's marker into `dir`, then removes the staging folder.
Status RollForward(const fs::path& dir, const fs::path& staging, const std::vector<std::string>& names) {
  std::error_code ec;
  for (const std::string& name : names) {
    const fs::path from = staging / name, to = dir / name;
    if (!fs::exists(from, ec)) continue;  // moved before the kill
    fs::create_directories(to.parent_path(), ec);
    if (fs::is_directory(from, ec)) fs::remove_all(to, ec);
    fs::rename(from, to, ec);
    if (ec) return Error{to.string() + ": cannot move the new output into place: " + ec.message()};
  }
  fs::remove_all(staging, ec);
  return Status{};
}

}  // namespace

StagedOutput::StagedOutput(fs::path dir, std::unique_ptr<FolderLock> lock)
    : dir_(std::move(dir)), staging_(dir_ / kStagingName), lock_(std::move(lock)) {}

StagedOutput::~StagedOutput() {
  std::error_code ec;
  if (!committed_) fs::remove_all(staging_, ec);
}

Result<std::unique_ptr<StagedOutput>> StagedOutput::Open(const fs::path& dir) {
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) return Error{dir.string() + ": exists and is not a folder"};
  fs::create_directories(dir, ec);
  if (ec) return Error{dir.string() + ": cannot create the folder: " + ec.message()};
  auto lock = FolderLock::Take(dir);
  if (!lock) return Error{lock.error()};
  std::unique_ptr<StagedOutput> out(new StagedOutput(dir, std::move(*lock)));
  // A killed run's staging folder: finished when it got as far as its marker, else discarded.
  if (fs::exists(out->staging_, ec)) {
    std::ifstream marker(out->staging_ / kMarker);
    if (marker) {
      std::vector<std::string> names;
      for (std::string line; std::getline(marker, line);)
        if (!line.empty()) names.push_back(line);
      if (Status s = RollForward(dir, out->staging_, names); !s) {
        out->committed_ = true;  // keep the staging folder and its marker: the next run tries again
        return Error{s.error()};
      }
    }
    fs::remove_all(out->staging_, ec);
  }
  fs::create_directories(out->staging_, ec);
  if (ec) return Error{out->staging_.string() + ": cannot create the folder: " + ec.message()};
  return out;
}

Status StagedOutput::Commit(const std::vector<std::string>& names) {
  std::string marker;
  for (const std::string& n : names) marker += n + "\n";
  if (Status s = WriteFileAtomic(staging_ / kMarker, marker); !s) return s;
  committed_ = true;  // from here on the next run finishes what this one does not
  return RollForward(dir_, staging_, names);
}

}  // namespace villa
