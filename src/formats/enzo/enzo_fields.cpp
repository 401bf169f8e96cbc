#include "formats/enzo/enzo_fields.hpp"

#include <fmt/format.h>

#include <optional>
#include <stdexcept>
#include <tuple>

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

void requireShape(const std::vector<hsize_t>& shape, const fs::path& file, const std::string& what,
                  glm::ivec3 dims, int axes) {
  const std::vector<hsize_t> expected{hsize_t(dims.z), hsize_t(dims.y), hsize_t(dims.x)};
  const std::vector<hsize_t> planar{hsize_t(dims.y), hsize_t(dims.x)};
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
    const Hdf5Handle set(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose);
    if (!set.valid())
      throw InputError(file.string(), H5Lexists(group, name.c_str(), H5P_DEFAULT) <= 0
                                          ? fmt::format("dataset {} is missing", what)
                                          : fmt::format("HDF5 could not open dataset {}", what));
    const StoredDataset stored = inspectStoredDataset(set.get(), file.string(), what);
    if (queueInPlace(stored, file, what, dims, axes, into[c])) continue;
    const std::uint64_t count = stored.count;
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

void FieldReads::addInPlace(const fs::path& file, const std::string& groupName, glm::ivec3 dims,
                            int axes, std::span<float* const> into,
                            std::span<const HeaderDataset> datasets, std::uint64_t fileBytes) {
  for (std::size_t c = 0; c < channels_.size(); ++c) {
    const auto what = fmt::format("{}/{}", groupName, channels_[c]);
    const HeaderDataset& d = datasets[c];
    StoredDataset stored;
    stored.shape = d.shape;
    stored.count = checkedValueCount(d.shape, std::uint64_t(d.encoding.bytes), false, d.storedBytes,
                                     fileBytes, file.string(), what);
    stored.typeClass = H5T_FLOAT;
    stored.floatBytes = d.encoding.bytes;
    stored.bigEndian = d.encoding.bigEndian;
    stored.inPlace = true;
    stored.offset = d.offset;
    stored.fileBytes = fileBytes;
    // a header found only a contiguous float at a defined address: it is read in place
    if (!queueInPlace(stored, file, what, dims, axes, into[c]))
      throw std::logic_error("FieldReads::addInPlace: " + what + " is not contiguous floats");
  }
}

bool FieldReads::queueInPlace(const StoredDataset& stored, const fs::path& file,
                              const std::string& what, glm::ivec3 dims, int axes, float* into) {
  requireShape(stored.shape, file, what, dims, axes);
  if (stored.typeClass != H5T_FLOAT)
    throw InputError(file.string(), fmt::format("dataset {} is not floating point", what));
  const auto contiguous = contiguousFloats(stored, file.string(), what);
  if (!contiguous) return false;
  queue(file, contiguous->encoding, {contiguous->offset, stored.count, into}, {what, dims, axes});
  return true;
}

FieldReads::~FieldReads() {
  reading_.cancel();
  try {
    reading_.wait();
  } catch (...) {  // the error that ended the reading is already on its way out
  }
}

void FieldReads::queue(const fs::path& file, FloatEncoding encoding, FloatRun run, Source source) {
  const auto [at, added] = fileIndex_.try_emplace({file.string(), encoding}, files_.size());
  if (added) files_.push_back({file, encoding, {}, {}, 0});
  FileReads& reads = files_[at->second];
  reads.sources.push_back(std::move(source));
  reads.pending.push_back(run);
  reads.pendingValues += run.count;
  if (reads.pendingValues >= batchValues_) launch(at->second);
}

void FieldReads::launch(std::size_t file) {
  FileReads& reads = files_[file];
  if (reads.pending.empty()) return;
  const std::size_t firstRun = reads.sources.size() - reads.pending.size();
  Batch& batch = batches_.emplace_back(Batch{file, firstRun, std::move(reads.pending), {}});
  reads.pending.clear();
  reads.pendingValues = 0;
  reading_.run([&batch, &reads] {
    batch.bad = readFloatRuns(reads.file, reads.encoding, batch.runs, "a grid field");
  });
}

void FieldReads::run() {
  for (std::size_t file = 0; file < files_.size(); ++file) launch(file);
  reading_.wait();
  const Batch* first = nullptr;
  auto key = [](const Batch& b) {
    return std::tuple(b.file, b.firstRun + b.bad->run, b.bad->index);
  };
  for (const Batch& batch : batches_)
    if (batch.bad && (!first || key(batch) < key(*first))) first = &batch;
  if (!first) return;
  const FileReads& reads = files_[first->file];
  const Source& source = reads.sources[first->firstRun + first->bad->run];
  unusable(reads.file, source.dataset, first->bad->value,
           zoneText(first->bad->index, source.dims, source.axes), first->bad->problem);
}

}  // namespace amrstream::formats::enzo
