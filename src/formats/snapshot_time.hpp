#pragma once
// Snapshot times read cheaply, for ordering a series of snapshots (the `pathlines` command): each
// input's simulation time from its metadata alone (headers, parameter and config files), never
// its cells, and the expansion of the snapshot list's glob patterns into files.

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace amrstream::formats {

// The time `input` states, equal to loadInput(input, {}).info().time: FLASH `real scalars`
// "time", Enzo InitialTime (nullopt without the parameter file), the AMReX Header's time, the
// Gerris header's last number, the `.exa` config's `time` line; 0 for builtin:KIND (generated at
// time 0). nullopt when the file states no time. Throws InputError naming the file and the
// problem for a missing file, an unknown format or a malformed time (or header).
std::optional<double> snapshotTime(const std::string& input);

// The dataset `path` belongs to: for a file named after an Enzo parameter file beside it
// (DD0010/data0010.hierarchy, .harrays, .cpu0000, .boundary, .procmap, ...), that parameter file;
// otherwise `path` itself. A glob such as 'DD*/data*' then names each Enzo dataset once.
std::string snapshotDataset(const std::string& path);

// Each argument in turn: an existing path (file or directory, such as an AMReX plotfile) or a
// builtin:KIND input is kept as it is; anything else is a glob(3) pattern replaced by its matches
// in glob's sorted order. A path named again (also through another pattern) is dropped, the first
// kept. Throws InputError naming the pattern when it matches no file.
std::vector<std::string> expandSnapshotPatterns(std::span<const std::string> patterns);

}  // namespace amrstream::formats
