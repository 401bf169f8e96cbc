#pragma once
// Enzo packed-AMR HDF5 output (`DD0010/moving7_0010` with `.hierarchy`, `.harrays`, `.cpuNNNN`).
//
// `file` may be the parameter file or its `.hierarchy` / `.harrays` / `.cpuNNNN` sibling. The grid
// table comes from `.harrays` when present, else from `.hierarchy`; field files are the basenames
// of the hierarchy's BaryonFileName entries, looked up next to `file`. Enzo levels are 0 = root;
// ours are 0 = finest (ourLevel = finestFileLevel - fileLevel). Cells of a grid covered by any
// finer grid are dropped. Channels are the grid datasets with one value per active zone (every
// non-`particle_*` dataset of the first grid), with their file names. The field's DatasetInfo
// (time, units, periodicity, Enzo level numbering) comes from the parameter file (enzo_info.hpp).

#include <filesystem>
#include <optional>

#include "bricks/amr_field.hpp"
#include "formats/value_window.hpp"

namespace amrstream::formats {

// Throws InputError naming the file (and the dataset) for unreadable or inconsistent input.
// With a window, only the grids meeting it are read (value_window.hpp), and `read` counts them.
bricks::AmrField readEnzo(const std::filesystem::path& file, const ValueWindow* window = nullptr,
                          WindowedRead* read = nullptr);

// The parameter file of the dataset `file` belongs to (`file` itself, or PREFIX for a `.hierarchy`,
// `.harrays`, `.cpuNNNN` or any other PREFIX.* file beside PREFIX.hierarchy), as readEnzo finds
// it; it need not exist. Throws InputError when `file` does not exist.
std::filesystem::path enzoParameterFile(const std::filesystem::path& file);

// PREFIX for a file named PREFIX.* (.boundary, .boundary.hdf, .procmap, ...) beside a
// PREFIX.hierarchy; nothing for any other file.
std::optional<std::filesystem::path> enzoCompanionOf(const std::filesystem::path& file);

}  // namespace amrstream::formats
