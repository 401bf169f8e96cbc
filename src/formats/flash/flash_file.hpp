#pragma once
// Read access to the datasets of a FLASH HDF5 file: numeric arrays, string lists and the
// {name, value} compound lists (`integer scalars`, `real runtime parameters`, ...). Every
// failure throws InputError naming the file and the dataset; no dataset is allocated before its
// declared size is known to be stored in the file. Used only inside src/formats.

#include <fmt/format.h>
#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "formats/hdf5_checks.hpp"
#include "formats/hdf5_handle.hpp"

namespace amrstream::formats::flash {

using Handle = Hdf5Handle;

template <typename T>
struct Array {
  std::vector<T> values;
  std::vector<hsize_t> dims;
};

class FlashFile {
 public:
  explicit FlashFile(const std::filesystem::path& path);

  [[noreturn]] void fail(const std::string& problem) const;
  [[noreturn]] void fail(const std::string& dataset, const std::string& problem) const;

  bool has(const std::string& name) const;
  Handle open(const std::string& name, const std::string& why = "") const;
  std::vector<hsize_t> dims(const std::string& name, const Handle& set) const;
  H5T_class_t typeClass(const std::string& name, const Handle& set, std::size_t* size) const;

  // Reads a numeric dataset, converted by HDF5 to T (int, float or double).
  template <typename T>
  Array<T> read(const std::string& name, const std::string& why = "") const;

  // The values of the blocks `blocks` (increasing indices along the first axis) of a float
  // dataset, as doubles, block after block: the rest is not read.
  std::vector<double> readBlocks(const std::string& name,
                                 const std::vector<std::size_t>& blocks) const;

  // Strings, fixed length (any padding) or variable length, cut at the first NUL and trimmed of
  // blanks.
  std::vector<std::string> readStrings(const std::string& name) const;

  // A {name, value} compound list such as `integer scalars` or `string runtime parameters`, with
  // T = int, double or std::string and names and string values (fixed length of any padding, or
  // variable length) cut at the first NUL and trimmed of trailing blanks; empty when the dataset
  // is absent.
  template <typename T>
  std::vector<std::pair<std::string, T>> readPairs(const std::string& name) const;

  const std::string& path() const { return path_; }

 private:
  std::string path_;
  Handle file_;
};

template <typename T>
Array<T> FlashFile::read(const std::string& name, const std::string& why) const {
  Handle set = open(name, why);
  Array<T> result{{}, dims(name, set)};
  std::size_t size = 0;
  const H5T_class_t cls = typeClass(name, set, &size);
  hid_t memType;
  if constexpr (std::is_same_v<T, int>) {
    if (cls != H5T_INTEGER) fail(name, "expected an integer dataset");
    memType = H5T_NATIVE_INT;
  } else {
    if (cls != H5T_FLOAT || (size != 4 && size != 8))
      fail(name, fmt::format("expected float32 or float64 data, found class {} size {}",
                             static_cast<int>(cls), size));
    memType = std::is_same_v<T, float> ? H5T_NATIVE_FLOAT : H5T_NATIVE_DOUBLE;
  }
  const std::uint64_t count = requireStoredValues(set.get(), path_, name);
  result.values.resize(count);
  if (count > 0 &&
      H5Dread(set.get(), memType, H5S_ALL, H5S_ALL, H5P_DEFAULT, result.values.data()) < 0)
    fail(name, "cannot read the data");
  return result;
}

}  // namespace amrstream::formats::flash
