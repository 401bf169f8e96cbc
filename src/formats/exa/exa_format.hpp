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
//               time T                (our addition, optional; the snapshot's simulation time)
//               periodic X Y Z        (our addition, optional; 0 or 1 per axis)
//               length-unit TEXT      (our addition, optional; the unit of origin and spacing)
//               time-unit TEXT        (our addition, optional; the unit of `time`)
//             ExaBricks' own `bricks FILE` line (a prebuilt brick file) is accepted and ignored:
//             amrstream builds its own bricks from the cells.

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "bricks/amr_field.hpp"

namespace amrstream::formats {

// Throws InputError naming the offending file (and line) and the problem: a missing file or one
// that is not a regular file, a size that does not match, a malformed directive or number, cells
// beyond 32-bit or the supported extent, an origin and spacing that do not give finite, distinct
// positions (spacing must be positive and not subnormal), or a non-finite value (naming the
// .scalars file, the channel and the first such cell). The field's DatasetInfo holds the optional
// lines above and ExaBricks level numbering (0 = finest).
bricks::AmrField readExa(const std::filesystem::path& config);

// One channel of an .exa, to be read when it is needed.
struct ExaChannelFile {
  std::string name;
  std::filesystem::path path;       // the .scalars file
  std::filesystem::path cellsPath;  // the .cells file, for messages
  std::size_t cellCount = 0;
};

// The cells of an .exa without their channels, and every channel's file in the config's order,
// to be read one at a time when needed (readExaChannel; AmrField::addChannel): a dataset's
// channels need not all be in memory at once, nor beside the cells' checks. Every scalars file's
// size is checked here, so that a missing or short one fails before any work; otherwise errors
// are readExa's.
struct ExaCells {
  bricks::AmrField field;
  std::vector<ExaChannelFile> channels;
};
ExaCells readExaCells(const std::filesystem::path& config);

// One channel's values, one per cell in .cells order, checked as readExa checks them (the error
// names the cell by its index).
std::vector<float> readExaChannel(const ExaChannelFile& channel);
// The same into `into` (channel.cellCount values; InputError naming the file otherwise), memory
// the caller made: a std::vector's zeroing by one thread took longer than the reading.
void readExaChannelInto(const ExaChannelFile& channel, std::span<float> into);

// The `time` line's value (nullopt without one), reading only the config: its lines are checked
// as readExa checks them, but the cells and scalar files are not opened.
std::optional<double> readExaTime(const std::filesystem::path& config);

// Writes PREFIX.cells, PREFIX.NAME.scalars for every channel and PREFIX.exa, with the optional
// lines for what the field's DatasetInfo knows; returns the .exa path. The files appear together
// or not at all (file_set_writer.hpp): a failed write throws InputError naming the file and leaves
// none of them. A unit text holding '#' or a line break, or a channel name or prefix holding a
// blank, '#' or '/', cannot be written and throws InputError naming the .exa before any file is
// written.
std::filesystem::path writeExa(const bricks::AmrField& field, const std::filesystem::path& prefix);

}  // namespace amrstream::formats
