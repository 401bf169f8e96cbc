#pragma once
// What a dataset's cells are described with: the map from cell units to physical coordinates, a
// named channel of one value per cell, and a box of cells.

#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace amrstream {

// Maps cell units (finest-cell units) to the input's physical coordinates.
struct WorldTransform {
  glm::dvec3 origin{0.0};   // physical position of the cell-unit origin
  glm::dvec3 spacing{1.0};  // physical size of one finest cell, per axis

  glm::dvec3 toPhysical(glm::dvec3 cellUnits) const { return origin + spacing * cellUnits; }
  glm::dvec3 toCellUnits(glm::dvec3 physical) const { return (physical - origin) / spacing; }
};

struct Channel {
  std::string name;
  std::vector<float> values;  // one per cell, in cell order
};

// Integer box [lower, upper) in finest-cell units.
struct CellBox {
  glm::ivec3 lower{0};
  glm::ivec3 upper{0};
};

}  // namespace amrstream
