#include "progress.hpp"

#include <unistd.h>

#include <atomic>
#include <cstdio>

namespace amrstream::cli {

namespace {

std::atomic<bool> silenced{false};

}  // namespace

void Progress::silenceAll() { silenced = true; }

Progress::Progress(std::string label, std::size_t total)
    : label_(std::move(label)), total_(total), terminal_(isatty(STDERR_FILENO)) {}

Progress::~Progress() { clear(); }

void Progress::clear() {
  std::lock_guard lock(mutex_);
  if (printed_ && terminal_) {
    std::fprintf(stderr, "\r%*s\r", int(label_.size()) + 40, "");
    std::fflush(stderr);
  }
  printed_ = false;
}

void Progress::update(std::size_t done) {
  std::lock_guard lock(mutex_);
  const double now =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (now < 1.0 || total_ == 0 || silenced) return;
  const int percent = int(100.0 * double(done) / double(total_));
  if (terminal_) {
    if (now - lastPrint_ < 0.25) return;
    std::fprintf(stderr, "\r%s %3d%% (%zu of %zu)", label_.c_str(), percent, done, total_);
  } else {
    if (percent / 10 <= lastDecile_) return;
    lastDecile_ = percent / 10;
    std::fprintf(stderr, "%s %3d%% (%zu of %zu)\n", label_.c_str(), percent, done, total_);
  }
  std::fflush(stderr);
  lastPrint_ = now;
  printed_ = true;
}

}  // namespace amrstream::cli
