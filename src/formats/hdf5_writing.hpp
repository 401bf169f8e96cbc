#pragma once
// Writing an HDF5 file for the format writers: numeric arrays (contiguous, unfiltered: the layout
// the readers read through file offsets), fixed-width string lists and FLASH-style {name, value}
// compound lists. Every failure throws InputError naming the file and the dataset.

#include <hdf5.h>

#include <filesystem>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "formats/hdf5_handle.hpp"

namespace amrstream::formats {

class Hdf5Writing {
 public:
  // Creates (or truncates) `path`; `name` is the file's name in messages.
  Hdf5Writing(const std::filesystem::path& path, std::string name);

  hid_t root() const { return file_.get(); }
  Hdf5Handle group(const std::string& name) const;
  // `memType` values (`dims`, C order) stored as `fileType` in `where` (the root or a group).
  void array(hid_t where, const std::string& name, std::span<const hsize_t> dims, hid_t memType,
             hid_t fileType, const void* values) const;
  void strings(const std::string& name, const std::vector<std::string>& values) const;
  // {name, value} compounds, names 80 characters wide; T: int, double or std::string.
  template <typename T>
  void pairs(const std::string& name, const std::vector<std::pair<std::string, T>>& values) const;
  // Flushes and closes the file.
  void close();

 private:
  [[noreturn]] void fail(const std::string& dataset) const;
  void dataset(hid_t where, const std::string& name, hid_t type, hid_t space, hid_t memType,
               const void* values) const;

  std::string name_;
  Hdf5Handle file_;
};

}  // namespace amrstream::formats
