#include "formats/enzo/enzo_fields.hpp"

#include <fmt/format.h>

#include <optional>

#include "amrstream/error.hpp"
#include "formats/cell_checks.hpp"
#include "formats/hdf5_checks.hpp"
#include "formats/hdf5_contiguous.hpp"
#include "formats/hdf5_handle.hpp"

namespace amrstream::formats::enzo {

namespace {

namespace fs = std::filesystem;

std::string zoneText(std::uint64_t index, glm::ivec3 dims, int axes) {
  const std::uint64_t i = index % dims.x, j = index / dims.x % dims.y, k = index / dims.x / dims.y;
  return axes == 2 ? fmt::format("(i, j) = ({}, {})", i, j)
                   : fmt::format("(i, j, k) = ({}, {}, {})", i, j, k);
}

[[noreturn]] void unusable(const fs::path& file, const std::string& dataset, double value,
                           const std::string& zone, const std::string& problem) {
  throw InputError(file.string(), fmt::format("dataset {}: value {} at zone {} is {}", dataset,
                                              value, zone, problem));
}

std::vector<hsize_t> shapeOf(hid_t set, const fs::path& file, const std::string& what) {
  const Hdf5Handle space(H5Dget_space(set), H5Sclose);
  const int rank = space.valid() ? H5Sget_simple_extent_ndims(space.get()) : -1;
  if (rank < 0 || rank > H5S_MAX_RANK)
    throw InputError(file.string(), fmt::format("HDF5 could not get the shape of {}", what));
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  if (rank > 0 && H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr) < 0)
    throw InputError(file.string(), fmt::format("HDF5 could not get the shape of {}", what));
  return dims;
}

void requireShape(hid_t set, const fs::path& file, const std::string& what, glm::ivec3 dims,
                  int axes) {
  const std::vector<hsize_t> expected{hsize_t(dims.z), hsize_t(dims.y), hsize_t(dims.x)};
  const std::vector<hsize_t> planar{hsize_t(dims.y), hsize_t(dims.x)};
  const auto shape = shapeOf(set, file, what);
  if (shape == expected || (axes == 2 && shape == planar)) return;
  std::string got;
  for (auto s : shape) got += fmt::format("{}{}", got.empty() ? "" : ",", s);
  throw InputError(file.string(),
                   axes == 2 ? fmt::format("dataset {} has shape ({}), expected ({},{}) = (ny,nx) "
                                           "active zones",
                                           what, got, dims.y, dims.x)
                             : fmt::format("dataset {} has shape ({}), expected ({},{},{}) = "
                                           "(nz,ny,nx) active zones",
                                           what, got, dims.z, dims.y, dims.x));
}

}  // namespace

void FieldReads::add(hid_t group, const fs::path& file, const std::string& groupName,
                     glm::ivec3 dims, int axes, std::span<float* const> into) {
  for (std::size_t c = 0; c < channels_.size(); ++c) {
    const std::string& name = channels_[c];
    const auto what = fmt::format("{}/{}", groupName, name);
    if (H5Lexists(group, name.c_str(), H5P_DEFAULT) <= 0)
      throw InputError(file.string(), fmt::format("dataset {} is missing", what));
    const Hdf5Handle set(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose);
    if (!set.valid())
      throw InputError(file.string(), fmt::format("HDF5 could not open dataset {}", what));
    requireShape(set.get(), file, what, dims, axes);
    const Hdf5Handle type(H5Dget_type(set.get()), H5Tclose);
    if (!type.valid() || H5Tget_class(type.get()) != H5T_FLOAT)
      throw InputError(file.string(), fmt::format("dataset {} is not floating point", what));
    const std::uint64_t count = requireStoredValues(set.get(), file.string(), what);
    if (const auto contiguous = contiguousFloats(set.get(), file.string(), what, count)) {
      queue(file, contiguous->valueBytes, {contiguous->offset, count, into[c]}, {what, dims, axes});
      continue;
    }
    std::vector<double> values(count);
    if (H5Dread(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
      throw InputError(file.string(), fmt::format("HDF5 could not read dataset {}", what));
    for (std::uint64_t i = 0; i < count; ++i) {
      if (const auto problem = unusableFieldValue(values[i]))
        unusable(file, what, values[i], zoneText(i, dims, axes), *problem);
      into[c][i] = static_cast<float>(values[i]);
    }
  }
}

void FieldReads::queue(const fs::path& file, int valueBytes, FloatRun run, Source source) {
  const auto [at, added] = fileIndex_.try_emplace({file.string(), valueBytes}, files_.size());
  if (added) files_.push_back({file, valueBytes, {}, {}});
  files_[at->second].runs.push_back(run);
  files_[at->second].sources.push_back(std::move(source));
}

void FieldReads::run() const {
  for (const FileReads& reads : files_) {
    const auto bad = readFloatRuns(reads.file, reads.valueBytes, reads.runs, "a grid field");
    if (!bad) continue;
    const Source& source = reads.sources[bad->run];
    unusable(reads.file, source.dataset, bad->value, zoneText(bad->index, source.dims, source.axes),
             bad->problem);
  }
}

}  // namespace amrstream::formats::enzo
