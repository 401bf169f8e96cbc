#pragma once
// The threads the host's parallel loops use: every core, or fewer where a limit is in force
// (the ranks of one host under mpirun share its cores: MpiWorld::threadsPerRank).

#include <tbb/global_control.h>

#include <cstddef>
#include <string>

namespace amrstream {

inline std::size_t hostThreads() {
  return tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism);
}

// "1 thread", "16 threads": for reports.
inline std::string hostThreadsText() {
  const std::size_t n = hostThreads();
  return std::to_string(n) + (n == 1 ? " thread" : " threads");
}

}  // namespace amrstream
