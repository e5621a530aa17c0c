#pragma once
// Work packages: one dataset labelled by several people, each in a folder of their own (on their own
// machine if they like), and their journals merged back.
//
// `villa annotate DIR --split N [--overlap F]` writes DIR/packages/part-K-of-N/ for K = 1..N, each a
// dataset folder `villa annotate` opens as it is: layouts.jsonl (its share of the layouts no person has
// decided yet, the lines copied byte for byte), annotations.journal.jsonl (their current state, so
// --auto's drafts travel along) and package.json; and DIR/packages/split.json recording the split.
// Layouts are dealt in dataset order, in N blocks of nearly equal size. The overlap sample, a share F of
// them chosen by a hash of the id (the same layouts whatever the order of the file), is also put into the
// next package, so two people label it and `--status` reports how far they agree.
//
// `villa annotate DIR --merge PKG...` adds each package's journal lines to DIR's journal (Session::
// MergeLines): each keeps its annotator, time, seconds and state; merging a package again adds only
// what is new. The last line merged decides a layout's state; every person's own decision stays in the
// journal for the agreement figures and the review.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "annotator/session.h"
#include "util/result.h"

namespace villa::annotator {

struct SplitOptions {
  int parts = 2;         // packages, 2 to 1000
  double overlap = 0.1;  // share of the layouts shared out that two people label, 0 to 0.5
  // Empty when the options are usable; else why not.
  std::string Invalid() const;
};

struct SplitSummary {
  std::filesystem::path folder;        // DIR/packages
  std::vector<std::string> packages;   // "part-1-of-4", ...
  std::vector<int> sizes;              // layouts in each package, the overlap included
  int layouts = 0;                     // layouts shared out (each counted once)
  int overlap = 0;                     // of those, in two packages
  int left_out = 0;                    // layouts a person already decided: not shared out
  double seconds = 0;
  std::string Brief() const;
};

// Splits `session`'s dataset as described above. Refuses when DIR/packages already holds packages (they
// may hold someone's work: merge them and move them away first).
Result<SplitSummary> SplitIntoPackages(const Session& session, const SplitOptions& options);

struct MergeSummary {
  int packages = 0;
  int lines = 0;    // journal lines added
  int layouts = 0;  // layouts those lines are about
  std::vector<std::string> annotators;
  double seconds = 0;
  std::string Brief() const;
};

// Merges the packages' journals into `session`'s (opened writable). Checks first that each is a package
// of this dataset: package.json present, every layout in it the same as in DIR.
Result<MergeSummary> MergePackages(Session& session, const std::vector<std::filesystem::path>& packages);

// DIR/packages/split.json, when a split was made: the ids of the overlap sample.
struct SplitRecord {
  std::string id;
  int parts = 0;
  std::vector<std::string> overlap;
};
std::optional<SplitRecord> ReadSplitRecord(const std::filesystem::path& dir);

}  // namespace villa::annotator
