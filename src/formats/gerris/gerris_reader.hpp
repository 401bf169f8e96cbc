#pragma once
// Gerris text leaf dumps (`OutputSimulation { format = text }`-style, one leaf per line):
//   header  `# 1:x 2:y 3:z 4:U ... N:Lev <time>` (column names, then the time)
//   rows    cell centre, values, octree level (whitespace separated)
// Gerris' root boxes are unit cubes centred on integer coordinates, so a level-Lev cell has size
// 2^-Lev and its centre lies on (k + 1/2) 2^-Lev - 1/2. The finest file level becomes our level
// 0 (our level = max Lev - Lev); cell units are finest cells counted from the lower corner of
// the cells' bounding box, which is the world origin; spacing = 2^-maxLev. Every column except
// x, y, z and Lev becomes a channel under its file name.
//
// DatasetInfo: the time is the header's last number (absent: unknown); Gerris levels count
// down from the finest (internal level L is Lev = max Lev - L). Units and periodicity are unknown:
// a text dump names neither (periodic boundaries, GfsBoundaryPeriodic, are only in the .gfs
// simulation file, and Gerris is dimensionless unless that file scales it).

#include <filesystem>
#include <optional>

#include "bricks/amr_field.hpp"

namespace amrstream::formats {

// Throws InputError naming the file (and the line) on a malformed or inconsistent dump, a path that
// is not a regular file, a value that is not finite or beyond the float range, or a file that
// shrinks while it is read.
bricks::AmrField readGerris(const std::filesystem::path& file);

// The header's time alone (nullopt when the header ends without one), reading only the header
// line; a malformed header throws as in readGerris.
std::optional<double> readGerrisTime(const std::filesystem::path& file);

}  // namespace amrstream::formats
