#pragma once
// Float values stored in a file as IEEE float32 or float64 of either byte order (the bytes of an
// unfiltered, contiguous HDF5 dataset of that type), read with pread in pieces on all cores and
// swapped where needed, converted to float and checked by the thread that read them: no library
// call per value, and none on one thread only.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>

namespace amrstream::formats {

// How the values are stored: 4 (float32) or 8 (float64) bytes, in the machine's byte order or
// the other (big-endian: the machines amrstream runs on are little-endian).
struct FloatEncoding {
  int bytes = 4;
  bool bigEndian = false;
  auto operator<=>(const FloatEncoding&) const = default;
};

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

// Reads every run of `path`, each value stored as `encoding` says, in pieces on all cores.
// Returns the unusable value that comes first (lowest run, then index), if any; runs may then
// be left part read. Throws InputError naming the path and `what` when the file cannot be read
// or ends before a run does.
std::optional<UnusableValue> readFloatRuns(const std::filesystem::path& path,
                                           FloatEncoding encoding, std::span<const FloatRun> runs,
                                           const std::string& what);

}  // namespace amrstream::formats
