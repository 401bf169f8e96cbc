#pragma once
// Where an HDF5 dataset's float values lie in its file, when they can be read there directly
// (float_runs.hpp) rather than through libhdf5, which Debian builds without thread safety: the
// dataset is stored contiguously, unfiltered, in the file itself (not an external one), its
// storage is allocated, and its type is IEEE float32 or float64 of either byte order.

#include <cstdint>
#include <optional>
#include <string>

#include "formats/float_runs.hpp"
#include "formats/hdf5_checks.hpp"

namespace amrstream::formats {

struct ContiguousFloats {
  std::uint64_t offset = 0;  // of the first value's bytes in the file
  FloatEncoding encoding;
};

// The dataset `stored` describes (named `name`, in `file`), or nullopt when it must be read with
// H5Dread. Throws InputError(file, "dataset 'NAME': ...") when its values would run past the end
// of the file (a truncated file).
std::optional<ContiguousFloats> contiguousFloats(const StoredDataset& stored,
                                                 const std::string& file, const std::string& name);

}  // namespace amrstream::formats
