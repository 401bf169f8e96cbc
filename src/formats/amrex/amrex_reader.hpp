#pragma once
// AMReX plotfiles (HyperCLaw-V1.1): a directory with
//   Header            variable names, dim, prob_lo/hi, ref ratios, domain boxes, dx, and per level
//                     the grids' physical extents and the level's path (`Level_N/Cell`)
//   Level_N/Cell_H    the level's BoxArray and one `FabOnDisk: FILE OFFSET` per box, in box order
//   Level_N/Cell_D_*  FABs: an ASCII line `FAB ((bytes, (format)),(bytes, (byte order)))(box) n`,
//                     then n components of the box's values, component-major, x fastest
// Cell-centred boxes only. Power-of-two refinement ratios: the finest plotfile level is our level
// 0, a coarser one is log2(product of the ratios down to the finest). Coarse cells under a finer
// level's boxes are dropped. Cell units count finest cells from the domain's lower corner, the
// world origin is prob_lo and the spacing the finest cell size (prob_hi - prob_lo) / domain size.
// Every plotfile variable becomes a float channel under its name. The field's DatasetInfo (time,
// periodicity from job_info, AMReX level numbering) is read as amrex_info.hpp describes.

#include <filesystem>

#include "bricks/amr_field.hpp"
#include "formats/value_window.hpp"

namespace amrstream::formats {

// Throws InputError naming the offending file and the inconsistency: a path that is not a regular
// file, a malformed header, a level domain that is not the coarser one refined or spans 2^21 or
// more cells, a box outside its level's domain, a FAB whose header disagrees with Cell_H or whose
// declared value type does not fill its bytes exactly (float32 declared over float64 data), a
// truncated FAB, or a value that is not finite or beyond the float range (naming the FAB file,
// the variable and the cell).
// With a window, only the boxes meeting it are read (value_window.hpp), and `read` counts them.
bricks::AmrField readAmrexPlotfile(const std::filesystem::path& directory,
                                   const ValueWindow* window = nullptr,
                                   WindowedRead* read = nullptr);

// The Header's time alone, parsing only the Header (no level data); errors as readAmrexPlotfile's.
double amrexPlotfileTime(const std::filesystem::path& directory);

}  // namespace amrstream::formats
