// AMReX plotfiles: the input is split into Header, Level_0/Cell_H, Level_0/Cell_D_00000,
// Level_1/Cell_H, Level_1/Cell_D_00000 and job_info (an empty part leaves its file absent).

#include <cstddef>
#include <cstdint>

#include "formats/amrex/amrex_reader.hpp"
#include "fuzz_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace amrstream;
  const auto parts = fuzz::splitParts({data, size});
  const auto& dir = fuzz::freshScratchDirectory();
  const char* names[] = {
      "plt/Header",         "plt/Level_0/Cell_H",       "plt/Level_0/Cell_D_00000",
      "plt/Level_1/Cell_H", "plt/Level_1/Cell_D_00000", "plt/job_info"};
  for (std::size_t i = 0; i < parts.size() && i < std::size(names); ++i)
    fuzz::writePart(dir, names[i], parts[i]);
  fuzz::expectInputErrorAtMost([&] { formats::readAmrexPlotfile(dir / "plt"); });
  fuzz::expectInputErrorAtMost([&] { formats::amrexPlotfileTime(dir / "plt"); });
  return 0;
}
