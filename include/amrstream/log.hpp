#pragma once
// Where the library says what it chose, how long things took and how far long work has got. Log
// takes one line at a time, without a trailing newline: the command line prints the lines, an
// empty Log drops them. StageProgress takes a stage's name ("tracing"), the work done and its
// total, from any thread; an empty one reports nothing.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

#include "amrstream/stage_clock.hpp"

namespace amrstream {

using Log = std::function<void(const std::string& line)>;

inline void say(const Log& log, const std::string& line) {
  if (log) log(line);
}

using StageProgress =
    std::function<void(std::string_view stage, std::size_t done, std::size_t total)>;

// "1234567" -> "1,234,567": how the library writes counts in its lines.
std::string withCommas(std::uint64_t n);

// Where a long run reports: its lines and its progress.
struct Reporter {
  Log log;
  StageProgress progress;
  StageClock* clock = nullptr;  // where a command's stages are timed, when one is

  // Closes the stage under way on the clock (StageClock::lap), if there is one.
  void lap(std::string_view stage, std::initializer_list<StageClock::Part> parts = {}) const {
    if (clock) clock->lap(stage, parts);
  }

  void say(const std::string& line) const { amrstream::say(log, line); }
  void advance(std::string_view stage, std::size_t done, std::size_t total) const {
    if (progress) progress(stage, done, total);
  }
};

}  // namespace amrstream
