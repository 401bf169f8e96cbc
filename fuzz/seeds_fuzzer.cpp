// Seed files (one "x y z" per line): the input is the file.

#include <cstddef>
#include <cstdint>

#include "flow/seeds.hpp"
#include "fuzz_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace amrstream;
  const auto& dir = fuzz::freshScratchDirectory();
  fuzz::writePart(dir, "seeds.txt", {reinterpret_cast<const char*>(data), size});
  fuzz::expectInputErrorAtMost([&] { flow::readSeedFile(dir / "seeds.txt"); });
  return 0;
}
