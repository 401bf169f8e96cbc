#pragma once
// One FAB of an AMReX Cell_D file: an ASCII header line
//   FAB ((BYTES, (FORMAT)),(BYTES, (BYTE ORDER)))((lo) (hi) (type)) NCOMP
// then NCOMP components of the box's values, component-major, x fastest. IEEE float32 and
// float64 of either byte order are read. Used only by the AMReX reader.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "formats/amrex/amrex_text.hpp"

namespace amrstream::formats::amrex {

// The values of the FAB at byte `offset` of `file`, over `stored` (the Cell_H box grown by the
// ghost cells), `ncomp` components, component-major. `nextFab` is the offset of the next FAB in
// the same file (nullopt: the FAB is the file's last). Throws InputError naming the file and the
// FAB's offset when the header line is malformed, its box or component count differ from
// `stored` and `ncomp`, its data is truncated, or the value size it declares does not fill the
// bytes up to the next FAB or the end of the file exactly (a float32 declaration over float64
// data, say). `axes`: the plotfile's dimension (a 2D FAB's box has two coordinates).
std::unique_ptr<double[]> readFab(const std::filesystem::path& file, std::uint64_t offset,
                                  std::optional<std::uint64_t> nextFab, const Box& stored,
                                  int ncomp, int axes);

}  // namespace amrstream::formats::amrex
