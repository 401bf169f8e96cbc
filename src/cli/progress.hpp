#pragma once
// Progress of long work on stderr: "tracing  45% (460 of 1024)". Silent for work that ends within
// a second; rewrites one line on a terminal, prints every 10% otherwise. Thread-safe.

#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>

namespace amrstream::cli {

class Progress {
 public:
  // Silences every Progress of this process from now on (MPI ranks other than 0).
  static void silenceAll();

  Progress(std::string label, std::size_t total);
  ~Progress();
  void update(std::size_t done);
  // Takes a progress line off the terminal, so that other output starts on a line of its own.
  void clear();

 private:
  std::string label_;
  std::size_t total_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::mutex mutex_;
  double lastPrint_ = 0.0;
  int lastDecile_ = 0;
  bool printed_ = false;
  bool terminal_;
};

}  // namespace amrstream::cli
