#pragma once
// A command's output files written into a folder all or nothing (issue 33): everything is written into
// DIR/.villa-staging/ first; Commit() records the names in a marker file, then renames each into DIR and
// removes the staging folder. A run killed before the marker leaves DIR as it was (the next run discards
// the staging folder); one killed after it is finished by the next run (roll forward), so DIR always holds
// either the previous run's outputs or the new run's, never half of one. A lock (util/folder_lock.h) keeps
// two runs from writing one folder at once: the second is refused.
//   auto stage = StagedOutput::Open(dir);           // lock, recover, fresh staging folder
//   WriteFileAtomic(stage->path() / "report.json", ...);
//   stage->Commit({"report.json", "rooms"});        // a folder moves as a whole, replacing the old one
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "util/folder_lock.h"
#include "util/result.h"

namespace villa {

class StagedOutput {
 public:
  // Creates DIR if needed, takes its lock (an error starting "busy: " when another run holds it), finishes
  // or discards a killed run's staging folder, and makes a fresh one.
  static Result<std::unique_ptr<StagedOutput>> Open(const std::filesystem::path& dir);
  ~StagedOutput();  // without Commit: the staging folder is removed, DIR untouched; the lock is released
  StagedOutput(const StagedOutput&) = delete;
  StagedOutput& operator=(const StagedOutput&) = delete;

  const std::filesystem::path& path() const { return staging_; }
  const std::filesystem::path& dir() const { return dir_; }
  // Moves `names` (files or folders, relative to the staging folder) into DIR, replacing what is there.
  Status Commit(const std::vector<std::string>& names);

  static constexpr const char* kStagingName = ".villa-staging";

 private:
  StagedOutput(std::filesystem::path dir, std::unique_ptr<FolderLock> lock);
  std::filesystem::path dir_, staging_;
  std::unique_ptr<FolderLock> lock_;
  bool committed_ = false;
};

}  // namespace villa
