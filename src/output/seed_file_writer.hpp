#pragma once
// Writes seed lists in the format flow::readSeedFile reads.

#include <filesystem>

#include "flow/seeds.hpp"

namespace amrstream::output {

// Writes one "x y z" line per seed with 17 significant digits, so that reading the file back gives
// the same doubles, through an AtomicFile: `path` is never left half written. Throws InputError
// naming the path when it cannot create or write the file.
void writeSeedFile(const std::filesystem::path& path, const flow::SeedList& seeds);

}  // namespace amrstream::output
