#pragma once
// Helpers shared by the fine-tune tests: scratch folders, fixture layouts moved around to make many
// distinct geometries, annotated JSONL written from them, and running the real `villa` binary.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>

#include "layout/layout_io.h"

namespace villa::testing {

namespace fs = std::filesystem;

inline fs::path FixtureDir() { return fs::path(VILLA_FIXTURE_DIR) / "finetune"; }

// A fresh empty folder under the system temp folder, removed when the object goes.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& tag) {
    std::random_device rd;
    path_ = fs::temp_directory_path() / ("villa-finetune-" + tag + "-" + std::to_string(rd()));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }
  fs::path operator/(const std::string& name) const { return path_ / name; }

 private:
  fs::path path_;
};

inline std::string Slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void Spit(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

inline std::vector<std::string> Lines(const fs::path& path) {
  std::vector<std::string> lines;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) lines.push_back(line);
  return lines;
}

inline Layout LoadFixture(const std::string& name) {
  auto layout = LoadLayout(FixtureDir() / name);
  REQUIRE(layout.ok());
  return *layout;
}

// The layout moved by (dx, dy) metres: same shape, a different geometry.
inline Layout Moved(Layout layout, double dx, double dy) {
  for (auto& room : layout.rooms)
    for (auto& p : room.polygon) p.x += dx, p.y += dy;
  for (ElementKind kind : kAllElementKinds)
    for (auto& e : layout.elements(kind)) e.shape.a.x += dx, e.shape.a.y += dy, e.shape.b.x += dx, e.shape.b.y += dy;
  return layout;
}

inline Json Record(const std::string& id, const std::string& status, const Layout& layout, const std::string& coarse,
                   const std::string& fine) {
  return Json{{"id", id}, {"status", status}, {"descriptions", Json{{"coarse", coarse}, {"fine", fine}}},
              {"layout", LayoutToJson(layout)}};
}

// `count` distinct layouts (the two fixtures moved along a grid), alternately one- and two-storey, each
// with a coarse and a fine description naming its id.
inline std::string ManyRecords(int count, const std::string& status = "auto") {
  Layout one = LoadFixture("one_floor.json");
  Layout two = LoadFixture("two_floors.json");
  std::string jsonl;
  for (int i = 0; i < count; ++i) {
    const std::string id = "layout-" + std::to_string(i);
    Layout moved = Moved(i % 2 ? two : one, 20.0 * (i % 10), 20.0 * (i / 10));
    jsonl += Record(id, status, moved, "coarse description of " + id, "fine description of " + id).dump() + "\n";
  }
  return jsonl;
}

// Runs the real binary; returns its exit code, output in *output.
inline int RunVilla(const std::string& args, std::string* output = nullptr) {
  static int counter = 0;
  const fs::path log = fs::temp_directory_path() / ("villa-finetune-cli-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + ".log");
  const std::string command = std::string("\"") + VILLA_BINARY + "\" " + args + " > \"" + log.string() + "\" 2>&1";
  int status = std::system(command.c_str());
  if (output) *output = Slurp(log);
  fs::remove(log);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The keys of a YAML file we wrote: "key: value" per line (nested keys as "parent.key"; list items by
// their first key), comments and blank lines skipped. Enough for the flat configs of the export.
inline std::map<std::string, std::string> YamlKeys(const std::string& text) {
  std::map<std::string, std::string> keys;
  std::vector<std::pair<int, std::string>> parents;  // indent, key
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    auto first = line.find_first_not_of(' ');
    if (first == std::string::npos || line[first] == '#') continue;
    int indent = static_cast<int>(first);
    std::string body = line.substr(first);
    if (body.rfind("- ", 0) == 0) body = body.substr(2), indent += 2;
    auto colon = body.find(':');
    if (colon == std::string::npos) continue;
    std::string key = body.substr(0, colon);
    std::string value = colon + 1 < body.size() ? body.substr(colon + 1) : "";
    if (!value.empty() && value[0] == ' ') value.erase(0, 1);
    while (!parents.empty() && parents.back().first >= indent) parents.pop_back();
    std::string full;
    for (const auto& p : parents) full += p.second + ".";
    full += key;
    if (value.empty()) parents.push_back({indent, key});
    if (!keys.count(full)) keys[full] = value;
  }
  return keys;
}

}  // namespace villa::testing
