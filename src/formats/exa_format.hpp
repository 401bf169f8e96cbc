#pragma once
// The ExaBricks raw formats.
//   .cells    per cell: int32 x, y, z, level (little endian, no header); lower corner in
//             finest-cell units, level 0 = finest, cell width 2^level.
//   .scalars  per channel: one float32 per cell, in .cells order.
//   .exa      text config, one directive per line, '#' starts a comment, paths relative to it:
//               cells FILE            (our addition; required)
//               scalar NAME FILE      (one per channel)
//               origin X Y Z          (our addition; physical position of cell-unit 0, default 0)
//               spacing SX SY SZ      (our addition; physical size of a finest cell, default 1)
//             ExaBricks' own `bricks FILE` line (a prebuilt brick file) is accepted and ignored:
//             amrstream builds its own bricks from the cells.

#include <filesystem>

#include "bricks/amr_field.hpp"

namespace amrstream::formats {

// Throws InputError naming the offending file and the problem (missing file, bad size, ...).
bricks::AmrField readExa(const std::filesystem::path& config);

// Writes PREFIX.cells, PREFIX.NAME.scalars for every channel and PREFIX.exa; returns the .exa path.
std::filesystem::path writeExa(const bricks::AmrField& field, const std::filesystem::path& prefix);

}  // namespace amrstream::formats
