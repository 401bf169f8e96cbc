#pragma once
// What the HDF5 readers check before allocating for a dataset, and how they read its strings.

#include <hdf5.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace amrstream::formats {

// No dataset the readers use holds more values than this (16 GiB of float64).
inline constexpr std::uint64_t kMaxDatasetValues = std::uint64_t{1} << 31;
// A filtered (compressed) dataset may store its bytes this many times smaller, no more: zlib
// stays under 1032:1.
inline constexpr std::uint64_t kMaxCompressionRatio = 4096;

// The number of values dataset `set` declares, once it is known that they are really stored:
// throws InputError(file, "dataset 'NAME': ...") when their count exceeds kMaxDatasetValues, when
// the file stores fewer bytes for them than they need (unfiltered) or than
// 1 / kMaxCompressionRatio of that (filtered), or when HDF5 cannot tell. A declared shape that
// the file does not back is refused before any allocation.
std::uint64_t requireStoredValues(hid_t set, const std::string& file, const std::string& name);

// The number of values a dataset of `shape` declares, each of `elementBytes` (0: the type could
// not be read), with `storedBytes` in a file of `fileBytes`: throws InputError(file, "dataset
// 'NAME': ...") when their count exceeds kMaxDatasetValues, when the file stores fewer bytes for
// them than they need (unfiltered) or than 1 / kMaxCompressionRatio of that (filtered), or more
// than the file holds.
std::uint64_t checkedValueCount(const std::vector<hsize_t>& shape, std::uint64_t elementBytes,
                                bool filtered, std::uint64_t storedBytes, std::uint64_t fileBytes,
                                const std::string& file, const std::string& name);

// What dataset `set` declares and how its values are stored, each asked of HDF5 once (a reader
// of thousands of datasets pays for every call on one thread), with requireStoredValues' checks.
struct StoredDataset {
  std::vector<hsize_t> shape;
  std::uint64_t count = 0;  // values
  H5T_class_t typeClass = H5T_NO_CLASS;
  int floatBytes = 0;      // 4 or 8 when the type is IEEE float32 or float64, else 0
  bool bigEndian = false;  // and stored big-endian (the machine's order is little-endian)
  bool inPlace = false;    // contiguous, unfiltered and in the file itself (not external)
  haddr_t offset = HADDR_UNDEF;
  std::uint64_t fileBytes = 0;
};
StoredDataset inspectStoredDataset(hid_t set, const std::string& file, const std::string& name);

// The strings of dataset `set`: each element, or the compound member `member` of each element,
// of file type `stringType` (an H5T_STRING), `count` of them, whatever their storage: fixed
// length null-terminated, null-padded or space-padded, or variable length. Each string is cut at
// its first NUL; blanks are kept. nullopt when HDF5 cannot read them.
std::optional<std::vector<std::string>> readHdf5Strings(hid_t set, hid_t stringType,
                                                        const char* member, std::uint64_t count);

}  // namespace amrstream::formats
