// villa: one executable, subcommands registered by the files beside this one.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <vector>

#include "cli/command.h"
#include "util/version.h"

namespace villa::cli {
namespace {
struct Entry {
  int order;
  Setup setup;
};
std::vector<Entry>& Registry() {
  static std::vector<Entry> entries;
  return entries;
}
int g_exit_code = kExitOk;
}  // namespace

Registration::Registration(int order, Setup setup) { Registry().push_back({order, std::move(setup)}); }
void SetExitCode(int code) { g_exit_code = code; }

}  // namespace villa::cli

int main(int argc, char** argv) {
  using namespace villa::cli;
  CLI::App app{"villa: text to multi-story 3D villas, and the datasets that teach an LLM to make them"};
  app.set_version_flag("--version", std::string("villa ") + villa::kVersion);
  app.require_subcommand(1);
  app.fallthrough();
  auto entries = Registry();
  std::stable_sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) { return a.order < b.order; });
  for (const auto& entry : entries) entry.setup(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitUsage;
  } catch (const UsageError& e) {
    std::cerr << "villa: " << e.what() << "\n";
    return kExitUsage;
  } catch (const std::exception& e) {
    std::cerr << "villa: error: " << e.what() << "\n";
    return kExitFailure;
  }
  return g_exit_code;
}
