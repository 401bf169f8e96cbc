#pragma once
// The cell of a volume that holds a point: its value slot, centre and width.

#include <cstdint>
#include <glm/glm.hpp>
#include <optional>

#include "vector_volume.hpp"

namespace amrstream::flow {

struct CellAt {
  std::uint32_t slot = 0;  // its value slot
  glm::dvec3 centre{0.0};  // cell units
  double width = 1.0;      // finest cells
};

// The cell of an original brick (not a periodic image) containing q (cell units, inside the
// domain); none in a hole of the domain or outside it.
std::optional<CellAt> cellAt(const VectorVolume& volume, glm::dvec3 q);

}  // namespace amrstream::flow
