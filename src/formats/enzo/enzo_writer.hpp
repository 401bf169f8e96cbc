#pragma once
// Writes leaf cells as an Enzo packed-AMR output: the parameter file PREFIX, the text hierarchy
// PREFIX.hierarchy and the field files PREFIX.cpu0000, PREFIX.cpu0001, ... of about 256 MiB each.
// The grids are boxes of whole 8^3 cubes of one level (up to 8 cubes per axis), each a group
// /GridNNNNNNNN holding a contiguous float32 dataset (nz, ny, nx) per channel; Enzo level 0 is
// the coarsest leaf level, the domain the cells' bounding box from (0, 0, 0). Only leaf grids are
// written (no parents), which readEnzo reads; yt's Enzo frontend wants every grid's parent.

#include <filesystem>

#include "bricks/amr_field.hpp"

namespace amrstream::formats {

// Writes `field` (3D) as the Enzo output with parameter file `prefix`, every file through a
// temporary renamed over it when all are complete, the parameter file last. Throws InputError
// naming the file when the field is planar or a file cannot be written.
void writeEnzo(const bricks::AmrField& field, const std::filesystem::path& prefix);

}  // namespace amrstream::formats
