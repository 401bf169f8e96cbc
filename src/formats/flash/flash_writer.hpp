#pragma once
// Writes leaf cells as a FLASH (PARAMESH) HDF5 plotfile: one leaf block (node type 1) per aligned
// cube of 8^3 cells of one level (4^3, 2^3 or single cells when the cells do not fill such
// cubes), refine level 1 for the coarsest, the values float32 in contiguous datasets [nblocks]
// [nzb][nyb][nxb]. It holds what readFlash and yt's FLASH frontend read: `unknown names`,
// `refine level`, `node type`, `gid` (no parents: the leaves alone), `bounding box`, `block size`,
// `coordinates`, the scalar and runtime parameter lists (nxb, nyb, nzb, dimensionality, time,
// domain, nblockx..z, geometry, boundary types, pc_unitsbase) and `file format version` 9.

#include <filesystem>

#include "bricks/amr_field.hpp"

namespace amrstream::formats {

// Writes `field` (3D) to `path` through a temporary file renamed over it when complete. Throws
// InputError naming the file when the field is planar or the file cannot be written.
void writeFlash(const bricks::AmrField& field, const std::filesystem::path& path);

}  // namespace amrstream::formats
