#pragma once
// The Enzo grids' groups and field datasets found from their object headers (hdf5_headers.hpp)
// on all cores, rather than opened one by one through libhdf5 on one thread (about 27 us a
// dataset). What the headers do not answer is left to libhdf5, which also reports every error.
// Used only by the Enzo reader.

#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "formats/hdf5_headers.hpp"

namespace amrstream::formats::enzo {

// A field file libhdf5 has open (`id`), or one it could not open (`id` < 0).
struct FieldFile {
  std::filesystem::path path;
  hid_t id = H5I_INVALID_HID;
};

// A grid's group ("/Grid00000001") in files[file]; `values`: its channels' datasets are wanted.
struct GridGroup {
  std::size_t file = 0;
  std::string name;
  bool values = false;
};

struct GridDatasets {
  bool groupFound = false;              // listed in its file's root group
  std::vector<HeaderDataset> channels;  // every channel's, in order, or none: ask libhdf5
  std::uint64_t fileBytes = 0;
};

std::vector<GridDatasets> findGridDatasets(std::span<const FieldFile> files,
                                           std::span<const GridGroup> groups,
                                           std::span<const std::string> channels);

}  // namespace amrstream::formats::enzo
