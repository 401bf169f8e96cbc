#pragma once
// How much memory traces may take on this machine: the policy that the trace command's seed and
// step counts and the .vtp reader both check.

#include <unistd.h>

namespace amrstream {

// Traces may take at most this share of the machine's physical memory.
inline constexpr double kTraceMemoryShare = 0.75;

// Physical memory in bytes; 0 when the system does not say.
inline double physicalMemoryBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && pageSize > 0 ? double(pages) * double(pageSize) : 0.0;
}

}  // namespace amrstream
