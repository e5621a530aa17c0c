#include "util/progress.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace villa {

bool ProgressBar::Enabled() {
  const char* ci = std::getenv("CI");
  if (ci && *ci && std::strcmp(ci, "0") != 0 && std::strcmp(ci, "false") != 0) return false;
  return ::isatty(STDERR_FILENO) == 1;
}

ProgressBar::ProgressBar(std::string label, std::size_t total)
    : label_(std::move(label)), total_(total), enabled_(Enabled()),
      start_(std::chrono::steady_clock::now()), last_draw_(start_ - std::chrono::seconds(1)) {}

ProgressBar::~ProgressBar() { Finish(); }

void ProgressBar::Advance(std::size_t n) {
  std::size_t done = done_.fetch_add(n) + n;
  if (!enabled_) return;
  auto now = std::chrono::steady_clock::now();
  std::unique_lock lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock() || finished_ || now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  Draw(done, false);
}

void ProgressBar::Finish() {
  std::lock_guard lock(mutex_);
  if (finished_) return;
  finished_ = true;
  if (enabled_) Draw(done_.load(), true);
}

void ProgressBar::Draw(std::size_t done, bool final) {
  constexpr int kWidth = 30;
  double fraction = total_ ? static_cast<double>(done) / static_cast<double>(total_) : 1.0;
  if (fraction > 1.0) fraction = 1.0;
  int filled = static_cast<int>(fraction * kWidth);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  double eta = done ? seconds * (static_cast<double>(total_) - static_cast<double>(done)) / static_cast<double>(done) : 0.0;
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.resize(kWidth, '.');
  std::fprintf(stderr, "\r%s [%s] %zu/%zu %3.0f%%  %.1fs", label_.c_str(), bar.c_str(), done, total_, fraction * 100.0, seconds);
  if (!final && done) std::fprintf(stderr, "  eta %.1fs", eta);
  std::fprintf(stderr, "\033[K%s", final ? "\n" : "");
  std::fflush(stderr);
}

}  // namespace villa
