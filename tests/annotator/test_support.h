#pragma once
// Shared helpers of the annotator tests: fixture datasets copied into fresh temporary folders.
#include <atomic>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <unistd.h>

#include <catch2/catch.hpp>

#include "annotator/dataset.h"
#include "annotator/session.h"
#include "layout/layout_io.h"

namespace villa::annotator::test {

inline std::filesystem::path FixtureLayouts(const std::string& name = "layouts.jsonl") {
  return std::filesystem::path(VILLA_FIXTURE_DIR) / "annotator" / name;
}

// A fresh folder holding a copy of a fixture dataset (tests/fixtures/annotator/NAME as layouts.jsonl);
// removed when the object goes.
class TempDataset {
 public:
  explicit TempDataset(const std::string& fixture = "layouts.jsonl") {
    static std::atomic<int> counter{0};
    dir_ = std::filesystem::temp_directory_path() /
           ("villa-annotator-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    std::filesystem::copy_file(FixtureLayouts(fixture), LayoutsPath(dir_));
  }
  ~TempDataset() {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  const std::filesystem::path& dir() const { return dir_; }
  std::filesystem::path journal() const { return JournalPath(dir_); }

 private:
  std::filesystem::path dir_;
};

inline std::string Slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

inline void Spit(const std::filesystem::path& path, const std::string& text, bool append = false) {
  std::ofstream out(path, std::ios::binary | (append ? std::ios::app : std::ios::trunc));
  out << text;
}

// The fixture's layouts by id: villa-000000 (one floor, valid), villa-000001 (two floors, L, valid, with
// a balcony), villa-000002 (kitchen without a window, one unlabelled room), villa-000003 (bedroom unreachable).
inline Layout FixtureLayout(const std::string& id) {
  auto dataset = LoadDataset(FixtureLayouts().parent_path());
  for (const auto& r : dataset->records)
    if (r.id == id) return r.layout;
  return {};
}

// The session of `dir`, as `annotator` (default: the login name); the test stops if it does not open.
inline std::unique_ptr<Session> OpenSession(const std::filesystem::path& dir, bool writable,
                                            const std::string& annotator = "") {
  SessionOptions o;
  o.writable = writable;
  o.annotator = annotator;
  auto s = Session::Open(dir, o);
  INFO((s ? std::string() : s.error()));
  REQUIRE(s.ok());
  return std::move(s).value();
}

}  // namespace villa::annotator::test
