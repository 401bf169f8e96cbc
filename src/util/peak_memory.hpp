#pragma once
// The process's peak resident memory so far, for the summaries of long runs.

#include <sys/resource.h>

#include <cstdint>

namespace amrstream {

// Bytes; 0 when the system does not say.
inline std::uint64_t peakResidentBytes() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0;
  return std::uint64_t(usage.ru_maxrss) * 1024;  // Linux reports kilobytes
}

}  // namespace amrstream
