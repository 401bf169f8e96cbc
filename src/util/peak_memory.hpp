#pragma once
// The process's peak resident memory, for the summaries of long runs. Linux keeps the peak in
// /proc/self/status (VmHWM) and lets a process reset it (writing 5 to /proc/self/clear_refs), so
// the peak of one stage can be told from the peak of the whole run.

#include <sys/resource.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <string>

namespace amrstream {

namespace detail {
// A size line of /proc/self/status ("VmHWM:", "VmRSS:") in bytes; 0 when the system does not say.
inline std::uint64_t statusBytes(const std::string& key) {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind(key, 0) == 0) return std::stoull(line.substr(key.size())) * 1024;
  return 0;
}
}  // namespace detail

// Peak since the last resetStagePeak(); bytes, 0 when the system does not say.
inline std::uint64_t stagePeakResidentBytes() { return detail::statusBytes("VmHWM:"); }

// Resident now; bytes, 0 when the system does not say.
inline std::uint64_t residentBytes() { return detail::statusBytes("VmRSS:"); }

namespace detail {
// The highest stage peak that a reset cleared (the reset clears getrusage's peak too).
inline std::uint64_t& clearedPeak() {
  static std::uint64_t peak = 0;
  return peak;
}
}  // namespace detail

// Peak since the process started; bytes, 0 when the system does not say.
inline std::uint64_t peakResidentBytes() {
  rusage usage{};
  const std::uint64_t sinceReset =
      getrusage(RUSAGE_SELF, &usage) == 0 ? std::uint64_t(usage.ru_maxrss) * 1024 : 0;  // kilobytes
  return std::max(sinceReset, detail::clearedPeak());
}

// Starts a new stage peak at the current resident size; false where the system does not allow it.
inline bool resetStagePeak() {
  detail::clearedPeak() = peakResidentBytes();
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
  return static_cast<bool>(clear.flush());
}

}  // namespace amrstream
