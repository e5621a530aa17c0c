#pragma once
// Running the `villa` binary from a test: its exit status and everything it printed (stdout and stderr
// together). VILLA_BINARY comes from tests/CMakeLists.txt.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace villa::testing {

struct CliRun {
  int status = -1;  // the exit status; -1 when the program did not exit normally
  std::string out;  // stdout and stderr together
};

// `villa ARGS` through the shell (quote what needs quoting), its output captured in a temporary file.
inline CliRun RunVilla(const std::string& args) {
  namespace fs = std::filesystem;
  const fs::path log = fs::temp_directory_path() / ("villa_cli_" + std::to_string(::getpid()) + ".log");
  const int status = std::system((std::string(VILLA_BINARY) + " " + args + " > " + log.string() + " 2>&1").c_str());
  std::ifstream in(log);
  CliRun run{WIFEXITED(status) ? WEXITSTATUS(status) : -1, std::string((std::istreambuf_iterator<char>(in)), {})};
  fs::remove(log);
  return run;
}

}  // namespace villa::testing
