// Enzo: the input is split into the parameter file (sim), the text hierarchy (sim.hierarchy),
// and HDF5 recipes (hdf5_recipe.hpp) for the field files sim.cpu0000 and sim.cpu0001 and the
// grid table sim.harrays (an empty part leaves its file absent). The dataset is read through its
// hierarchy (or grid table), and its time through snapshotTime.

#include <cstddef>
#include <cstdint>

#include "formats/enzo/enzo_reader.hpp"
#include "formats/snapshot_time.hpp"
#include "fuzz_files.hpp"
#include "hdf5_recipe.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace amrstream;
  const auto parts = fuzz::splitParts({data, size});
  const auto& dir = fuzz::freshScratchDirectory();
  const auto part = [&](std::size_t i) { return i < parts.size() ? parts[i] : ""; };
  fuzz::writePart(dir, "sim", part(0));
  fuzz::writePart(dir, "sim.hierarchy", part(1));
  const char* recipes[] = {"sim.cpu0000", "sim.cpu0001", "sim.harrays"};
  for (std::size_t i = 0; i < std::size(recipes); ++i) {
    const auto recipe = part(2 + i);
    if (!recipe.empty())
      fuzz::writeRecipeFile({reinterpret_cast<const std::uint8_t*>(recipe.data()), recipe.size()},
                            dir / recipes[i]);
  }
  // Through a sibling: the parameter file is then optional, as readEnzo allows.
  const auto entry = dir / (part(1).empty() ? "sim.harrays" : "sim.hierarchy");
  fuzz::expectInputErrorAtMost([&] { formats::readEnzo(entry); });
  fuzz::expectInputErrorAtMost([&] { formats::snapshotTime((dir / "sim").string()); });
  fuzz::expectNoHdf5ObjectsOpen();
  return 0;
}
