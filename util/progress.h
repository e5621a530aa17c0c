#pragma once
// A progress bar on a terminal's stderr; silent in pipes, files and CI (CI=true), so logs stay clean.
// Thread-safe: workers call Advance() from any thread; redraws are throttled to about 10 a second.
#include <atomic>
#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>

namespace villa {

class ProgressBar {
 public:
  ProgressBar(std::string label, std::size_t total);
  ~ProgressBar();  // finishes the line if anything was drawn

  void Advance(std::size_t n = 1);
  void Finish();
  // True when stderr is a terminal and CI is not set: the bar draws.
  static bool Enabled();

 private:
  void Draw(std::size_t done, bool final);

  std::string label_;
  std::size_t total_;
  std::atomic<std::size_t> done_{0};
  bool enabled_;
  bool finished_ = false;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace villa
