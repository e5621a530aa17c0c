#pragma once
// A written MJCF scene (physics/mjcf.h) run in MuJoCo itself (Debian libmujoco-dev 2.2), the way a user's
// simulator would: it must load with no error, and after `seconds` every body with a free joint is judged
// by the strict and loose rules of physics/settle.h (its centre's displacement and its turn). Also
// measures the contacts and constraint rows the run needed, so the file's buffers can be sized to them
// (MuJoCo 2.2 allocates the square of the rows).
#include <filesystem>
#include <string>
#include <vector>

#include "physics/mjcf.h"
#include "physics/settle.h"
#include "util/result.h"

namespace villa::physics {

struct MujocoMover {
  std::string body;
  double moved = 0.0, turned = 0.0;  // m (its centre), rad
};

struct MujocoRun {
  std::string version;  // MuJoCo's, "2.2.2"
  int free = 0, strict = 0, loose = 0;
  int hinges = 0;               // hinge joints (door leaves)
  int max_contacts = 0, max_rows = 0;  // the most contacts and constraint rows in one step
  bool buffers_full = false;    // a step ran out of contacts or rows (the result is not to be trusted)
  bool unstable = false;        // MuJoCo reported a NaN or a huge acceleration (and restarted the run):
                                // no free body counts as stable then
  std::vector<MujocoMover> movers;  // the free bodies outside the strict rule, the largest first
  // MuJoCo's own contacts at the start (before the first step) deeper than 2 mm, and the deepest (its two
  // bodies, "world" for the building): a geom that starts inside another is pushed out hard.
  int deep_at_start = 0;
  double deepest_at_start = 0.0;  // m, positive
  std::string deepest_pair;
  double wall_seconds = 0.0;
};

Result<MujocoRun> RunMujoco(const std::filesystem::path& xml, const SettleOptions& options = {});

// `villa physics --mjcf`: writes the scene (physics/mjcf.h), runs it, and sizes its buffers to what the
// run needed (a quarter more); a run that filled them is redone with larger ones, up to kMjcfMaxRows.
struct MjcfExport {
  MjcfSummary written;
  MujocoRun run;
};
Result<MjcfExport> ExportMjcf(const std::filesystem::path& glb, const std::filesystem::path& dir,
                              const SettleOptions& options = {});

}  // namespace villa::physics
