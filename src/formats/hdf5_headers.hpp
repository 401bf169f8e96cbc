#pragma once
// HDF5 object headers read from the file's bytes (pread), on any thread and all at once: the
// links of a group and the storage of a contiguous dataset, as libhdf5 would report them, for
// readers that open thousands of datasets (libhdf5, built without thread safety, opens one at a
// time: about 27 us each). Only the plain case is read: version 1 or 2 object headers; a group's
// links in a version 1 symbol table or in link messages; a dataset of simple shape, IEEE float32
// or float64 of either byte order, stored contiguously in the file at a defined address, with no
// filter and no external file. Anything else, or anything unexpected, gives nullopt, and the reader
// asks libhdf5, which then also reports any error. The layouts are in docs/formats.md.

#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "formats/float_runs.hpp"

namespace amrstream::formats {

// A contiguous dataset's storage as a header declares it.
struct HeaderDataset {
  std::vector<hsize_t> shape;
  FloatEncoding encoding;
  std::uint64_t offset = 0;  // of the values in the file
  std::uint64_t storedBytes = 0;
};

class Hdf5Headers {
 public:
  // `file`: the same file opened by libhdf5 (for the sizes of its addresses and lengths).
  // Throws InputError naming `path` when it cannot be opened for reading.
  Hdf5Headers(const std::filesystem::path& path, hid_t file);
  ~Hdf5Headers();
  Hdf5Headers(const Hdf5Headers&) = delete;
  Hdf5Headers& operator=(const Hdf5Headers&) = delete;

  // False when the file's addresses or lengths are not 8 bytes: then every answer is nullopt.
  bool usable() const { return usable_; }
  std::uint64_t fileBytes() const { return fileBytes_; }

  // The hard links of the group whose object header is at `address`: (name, object header
  // address) in no particular order.
  std::optional<std::vector<std::pair<std::string, std::uint64_t>>> groupLinks(
      std::uint64_t address) const;

  // The dataset whose object header is at `address`, when it is of the plain kind above.
  std::optional<HeaderDataset> contiguousDataset(std::uint64_t address) const;

  // Bytes [offset, offset + count) of the file into `into`; false when they are not all there.
  bool read(std::uint64_t offset, void* into, std::uint64_t count) const;

 private:
  int fd_ = -1;
  std::uint64_t fileBytes_ = 0;
  bool usable_ = false;
};

// The hard links of the root group of `file`, through libhdf5: (name, object header address).
// nullopt when libhdf5 cannot list them.
std::optional<std::vector<std::pair<std::string, std::uint64_t>>> rootLinks(hid_t file);

}  // namespace amrstream::formats
