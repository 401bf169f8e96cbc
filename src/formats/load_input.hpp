#pragma once
// Opens any supported input, recognised by content and extension: `builtin:KIND` (a synthetic
// dataset), an ExaBricks `.exa` config, an AMReX plotfile directory, an Enzo dataset (parameter
// file, .hierarchy or .harrays), a FLASH HDF5 plotfile or checkpoint, or a Gerris text dump.

#include <string>
#include <string_view>

#include "bricks/amr_field.hpp"
#include "formats/value_window.hpp"
#include "synth/generators.hpp"

namespace amrstream::formats {

enum class Format { Builtin, ExaBricks, Amrex, Enzo, Flash, Gerris };

std::string_view formatName(Format format);

// Throws InputError when the input does not exist, is not a regular file or directory (a FIFO,
// a device), or is in no known format ("format not recognised", naming the formats tried).
Format detectFormat(const std::string& input);

// Whether the format reads the values of a window alone: AMReX, Enzo and FLASH.
bool readsValueWindows(Format format);
// `generatorOptions` sizes builtin datasets. Throws InputError for unknown formats or kinds.
// `window`: see value_window.hpp; formats that cannot read part of their values read them all.
bricks::AmrField loadInput(const std::string& input, const BuiltinOptions& generatorOptions,
                           const ValueWindow* window = nullptr, WindowedRead* read = nullptr);

}  // namespace amrstream::formats
