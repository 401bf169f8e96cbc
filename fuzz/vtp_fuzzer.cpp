// VTK XML PolyData traces: the input is the .vtp file.

#include <cstddef>
#include <cstdint>

#include "fuzz_files.hpp"
#include "output/vtp_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace amrstream;
  const auto& dir = fuzz::freshScratchDirectory();
  fuzz::writePart(dir, "traces.vtp", {reinterpret_cast<const char*>(data), size});
  fuzz::expectInputErrorAtMost([&] { output::readVtpTraces(dir / "traces.vtp"); });
  return 0;
}
