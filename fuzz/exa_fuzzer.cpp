// ExaBricks: the input is split into the .exa config, the .cells file and two .scalars files
// (fuzz_files.hpp: parts separated by kPartSeparator), written as a.exa, a.cells, a.u.scalars and
// a.v.scalars; the config may name them or anything else.

#include <cstddef>
#include <cstdint>

#include "formats/exa/exa_format.hpp"
#include "fuzz_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace amrstream;
  const auto parts = fuzz::splitParts({data, size});
  const auto& dir = fuzz::freshScratchDirectory();
  const char* names[] = {"a.exa", "a.cells", "a.u.scalars", "a.v.scalars"};
  for (std::size_t i = 0; i < parts.size() && i < std::size(names); ++i)
    fuzz::writePart(dir, names[i], parts[i]);
  fuzz::expectInputErrorAtMost([&] { formats::readExa(dir / "a.exa"); });
  fuzz::expectInputErrorAtMost([&] { formats::readExaTime(dir / "a.exa"); });
  return 0;
}
