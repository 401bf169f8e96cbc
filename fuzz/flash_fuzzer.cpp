// FLASH: the input is an HDF5 recipe (hdf5_recipe.hpp) written as plt_cnt; the file is read
// through format detection, the reader and the snapshot time.

#include <cstddef>
#include <cstdint>

#include "formats/flash/flash_reader.hpp"
#include "formats/load_input.hpp"
#include "formats/snapshot_time.hpp"
#include "fuzz_files.hpp"
#include "hdf5_recipe.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace amrstream;
  const auto& dir = fuzz::freshScratchDirectory();
  const auto path = dir / "sim_hdf5_plt_cnt_0000";
  if (!fuzz::writeRecipeFile({data, size}, path)) return 0;
  fuzz::expectInputErrorAtMost([&] { formats::readFlash(path); });
  fuzz::expectInputErrorAtMost([&] { formats::detectFormat(path.string()); });
  fuzz::expectInputErrorAtMost([&] { formats::snapshotTime(path.string()); });
  fuzz::expectNoHdf5ObjectsOpen();
  return 0;
}
