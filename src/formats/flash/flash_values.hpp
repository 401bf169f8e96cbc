#pragma once
// The values of one FLASH variable for some of its blocks, as floats, each block's into memory
// of the caller's. A contiguous, unfiltered dataset of the machine's float32 or float64 is read
// through its file offset in pieces on all cores (float_runs.hpp); any other goes through
// H5Dread. Used only by the FLASH reader.

#include <array>
#include <cstddef>
#include <span>
#include <string>

#include "formats/flash/flash_file.hpp"

namespace amrstream::formats::flash {

struct BlockValues {
  std::size_t block = 0;  // index along the dataset's first axis
  float* into = nullptr;  // room for the block's nxb * nyb * nzb values, x fastest
};

// Reads variable `name` (a dataset [nblocks][nzb][nyb][nxb], cells[a] cells per block along axis
// a) for `blocks`, in increasing block order. Throws InputError naming the file and dataset when
// it cannot be read, and naming the block and cell of the first value that is not finite or
// beyond the float range.
void readBlockValues(const FlashFile& file, const std::string& name,
                     std::span<const BlockValues> blocks, const std::array<int, 3>& cells);

}  // namespace amrstream::formats::flash
