#pragma once
// Where the library says what it chose and how long things took: one line at a time, without a
// trailing newline. The command line prints the lines; an empty Log drops them.

#include <functional>
#include <string>

namespace amrstream {

using Log = std::function<void(const std::string& line)>;

inline void say(const Log& log, const std::string& line) {
  if (log) log(line);
}

}  // namespace amrstream
