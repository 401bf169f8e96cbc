#pragma once
// Reading the values of part of space only (an MPI rank's part over data): a reader given a
// window lays out every cell, from its metadata, but reads the values of only the grids (Enzo),
// boxes (AMReX) or blocks (FLASH) near one of the window's boxes; the other cells keep their
// places with the value 0 in every channel, and their data is not read.

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "bricks/amr_field.hpp"

namespace amrstream::formats {

struct ValueWindow {
  std::vector<CellBox> boxes;  // finest-cell units of the field read, half open
  // A piece whose cells are w finest cells wide is read when it meets a box grown by
  // cellsAround * w: cells whose tents, or whose neighbours' tents, reach into a box.
  double cellsAround = 3.0;
  // The cells a first read of the same input laid out and checked: the field read must have
  // them, and their (long) overlap check is not repeated.
  const bricks::CheckedCells* checked = nullptr;
  // False: the cells alone, with no channel (a read for the cells' layout; their names are in
  // WindowedRead::channels).
  bool withChannels = true;

  // Whether the cells [lower, upper), each `width` finest cells wide, are read.
  bool meets(glm::ivec3 lower, glm::ivec3 upper, int width) const {
    const glm::dvec3 grow(cellsAround * width);
    for (const CellBox& box : boxes)
      if (glm::all(glm::lessThan(glm::dvec3(lower), glm::dvec3(box.upper) + grow)) &&
          glm::all(glm::lessThan(glm::dvec3(box.lower) - grow, glm::dvec3(upper))))
        return true;
    return false;
  }
};

// What a windowed read read: `pieces` is 0 when the format reads whole (ExaBricks, Gerris,
// builtin datasets).
struct WindowedRead {
  std::size_t pieces = 0, piecesRead = 0;
  std::vector<std::string> channels;  // the channels' names
};

}  // namespace amrstream::formats
