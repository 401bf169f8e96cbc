#pragma once
// The formats a field's cells are written in (amrstream gen --format): ExaBricks files, a FLASH
// HDF5 file, an Enzo output or an AMReX plotfile, each as its writer describes.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "bricks/amr_field.hpp"

namespace amrstream::formats {

// "exa", "flash", "enzo", "amrex".
std::vector<std::string> writableFormats();

// The path a dataset written as `format` under `prefix` is read from: PREFIX.exa, PREFIX.h5,
// PREFIX (the Enzo parameter file) or PREFIX.plt (the AMReX plotfile folder).
std::filesystem::path writtenPath(const std::filesystem::path& prefix, std::string_view format);

// Writes `field` as `format` under `prefix` and returns writtenPath. Throws InputError naming
// the format for an unknown one, and as the writer does.
std::filesystem::path writeFieldAs(const bricks::AmrField& field,
                                   const std::filesystem::path& prefix, std::string_view format);

}  // namespace amrstream::formats
