// Gerris: the input is the text dump.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "formats/gerris/gerris_reader.hpp"
#include "fuzz_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace amrstream;
  const auto& dir = fuzz::freshScratchDirectory();
  fuzz::writePart(dir, "dump.txt", {reinterpret_cast<const char*>(data), size});
  fuzz::expectInputErrorAtMost([&] { formats::readGerris(dir / "dump.txt"); });
  fuzz::expectInputErrorAtMost([&] { formats::readGerrisTime(dir / "dump.txt"); });
  return 0;
}
