// The cluster path on a real single-node Slurm cluster (scripts/slurm/selftest.sh: job arrays for synth
// and scenes, a cancelled and resubmitted array, merges as dependent jobs, byte and file comparisons
// with one machine's runs). On a machine that cannot run slurmd (not root, or slurm-wlm and munge not
// installed) it says so and checks nothing else; scripts/install-deps.sh installs them.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

TEST_CASE("synth and scenes run as Slurm job arrays, survive a scancel and merge to one machine's result", "[shards][slurm]") {
  namespace fs = std::filesystem;
  const fs::path work = fs::temp_directory_path() / ("villa_slurm_test_" + std::to_string(::getpid()));
  fs::remove_all(work);
  fs::create_directories(work);
  const std::string log = (work / "selftest.log").string();
  const std::string command = std::string(VILLA_SOURCE_DIR) + "/scripts/slurm/selftest.sh " + VILLA_BINARY + " " + work.string() + " > " + log + " 2>&1";
  const int status = std::system(command.c_str());
  std::ifstream in(log);
  const std::string out((std::istreambuf_iterator<char>(in)), {});
  INFO(out);
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (code == 77) {
    WARN("no Slurm cluster on this machine: " + out);
  } else {
    CHECK(code == 0);
    CHECK(out.find("merged byte-identical to one machine's run") != std::string::npos);
    CHECK(out.find("merged equal to one machine's run file for file (40 files)") != std::string::npos);
  }
  if (code == 0) fs::remove_all(work);
}
