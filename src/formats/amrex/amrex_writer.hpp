#pragma once
// Writes leaf cells as an AMReX plotfile folder (HyperCLaw-V1.1): Header, and per level
// Level_L/Cell_H with Cell_D_NNNNN files of about 256 MiB, each a run of FABs of float32 little
// endian values. The boxes are whole 8^3 cubes of one level (up to 8 cubes per axis); AMReX level
// 0 is the coarsest leaf level, each level twice as fine, the domain the cells' bounding box from
// (0, 0, 0). Only leaf boxes are written, which readAmrexPlotfile and yt read.

#include <filesystem>

#include "bricks/amr_field.hpp"

namespace amrstream::formats {

// Writes `field` (3D) as the plotfile folder `directory`, built under a temporary name and
// renamed over it when complete. Throws InputError naming the folder when the field is planar,
// a level between the coarsest and the finest has no leaf cells, or a file cannot be written.
void writeAmrexPlotfile(const bricks::AmrField& field, const std::filesystem::path& directory);

}  // namespace amrstream::formats
