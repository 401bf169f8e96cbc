#pragma once
// Writing a dataset in one of the formats amrstream reads: ExaBricks files, a FLASH HDF5 file,
// an Enzo output or an AMReX plotfile (docs/formats.md, "Writing other formats").

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "amrstream/dataset.hpp"

namespace amrstream {

// "exa", "flash", "enzo", "amrex".
std::vector<std::string> writableFormats();

// The path load() reads a dataset written as `format` under `prefix` from: PREFIX.exa, PREFIX.h5,
// PREFIX (the Enzo parameter file, beside PREFIX.hierarchy and PREFIX.cpuNNNN) or PREFIX.plt
// (the AMReX plotfile folder). Throws InputError for an unknown format.
std::filesystem::path writtenPath(const std::filesystem::path& prefix, std::string_view format);

// Writes the dataset's cells (3D) as `format` under `prefix`; returns writtenPath. The files
// appear together or not at all. Throws InputError naming the file and the problem.
std::filesystem::path writeDataset(const Dataset& dataset, const std::filesystem::path& prefix,
                                   std::string_view format);

}  // namespace amrstream
