#pragma once
// Float values stored in a file as the machine's own float32 or float64 (the bytes of an
// unfiltered, contiguous HDF5 dataset of that type), read with pread in pieces on all cores and
// converted to float and checked by the thread that read them: no library call per value, and
// none on one thread only.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>

namespace amrstream::formats {

struct FloatRun {
  std::uint64_t offset = 0;  // of the first value's bytes in the file
  std::uint64_t count = 0;   // values
  float* into = nullptr;     // room for `count` floats
};

// A value that cannot be a channel value (cell_checks.hpp: unusableFieldValue).
struct UnusableValue {
  std::size_t run = 0;      // among the runs read
  std::uint64_t index = 0;  // within its run
  double value = 0.0;
  std::string problem;
};

// Reads every run of `path`, each value `valueBytes` (4 or 8) bytes, in pieces on all cores.
// Returns the unusable value that comes first (lowest run, then index), if any; runs may then
// be left part read. Throws InputError naming the path and `what` when the file cannot be read
// or ends before a run does.
std::optional<UnusableValue> readFloatRuns(const std::filesystem::path& path, int valueBytes,
                                           std::span<const FloatRun> runs, const std::string& what);

}  // namespace amrstream::formats
