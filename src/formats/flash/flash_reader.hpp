#pragma once
// FLASH (PARAMESH) HDF5 plotfiles and checkpoints.
//
// Only leaf blocks (`node type` 1) become cells. Refine levels are 1-based with the finest leaf
// level rmax becoming our level 0 (our level = rmax - refine level). The finest cell size per
// axis, min over leaves of (bounding-box extent / cells per block), is the transform's spacing;
// the origin is the lower corner of the leaves' bounding boxes.
//
// 2D files (nzb = 1): the result is a flat slab, uniformly as thick as the coarsest leaf cell
// (2^Lc finest cells, Lc = coarsest leaf level). Every level-L cell is stacked 2^(Lc - L) times
// along z starting at z = 0, each copy carrying the same values; when all leaves share one level
// this is one cube per cell. spacing.z = spacing.x. The stacking may multiply the file's leaf
// cells by at most 256 (and give at most 2^31 cells); beyond that the file is refused.
//
// The field's DatasetInfo (time, units, periodicity, refine-level numbering) is read as
// flash_info.hpp describes.

#include <filesystem>

#include "bricks/amr_field.hpp"
#include "formats/value_window.hpp"

namespace amrstream::formats {

// Throws InputError naming the file (and the dataset) for unreadable or inconsistent input: a path
// that is not a regular file, a dataset whose declared shape the file does not store (checked
// before allocating), strings it cannot read, bounding boxes that give no finite, resolvable
// positions, or a leaf value that is not finite or beyond the float range (naming the dataset,
// the block and the cell).
// With a window, only the leaf blocks meeting it are read (value_window.hpp), and `read` counts
// them.
bricks::AmrField readFlash(const std::filesystem::path& file, const ValueWindow* window = nullptr,
                           WindowedRead* read = nullptr);

}  // namespace amrstream::formats
