#pragma once
// The leaf cells of a 3D field grouped into boxes of one level each, for the writers of formats
// that store boxes of cells (FLASH blocks, Enzo grids, AMReX FABs). The cells are first grouped
// into aligned cubes of `side` cells of one level, the largest side of 8, 4, 2 or 1 for which
// every cube is whole; a box is then up to `maxCubes` cubes per axis.

#include <cstddef>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "bricks/amr_field.hpp"

namespace amrstream::formats {

struct LeafBox {
  glm::ivec3 lower{0};  // finest-cell units
  int level = 0;        // ours: 0 = finest, a cell 2^level finest cells wide
  glm::ivec3 cells{0};  // per axis
};

class LeafBoxes {
 public:
  // Boxes of whole cubes, at most `maxCubes` cubes along each axis; 1: the cubes alone.
  LeafBoxes(const bricks::AmrField& field, int maxCubes);

  int side() const { return side_; }
  const std::vector<LeafBox>& boxes() const { return boxes_; }
  // The values of `channel` (one per cell of the field) over box b's cells, x fastest.
  void gather(std::size_t b, std::span<const float> channel, float* into) const;

 private:
  struct Cube {
    glm::ivec3 at;  // in cubes of its level
    int level;
    std::size_t firstCell;  // into order_ (or the field's cells when order_ is empty)
  };
  std::size_t cellOf(const Cube& cube, std::size_t inCube) const {
    const std::size_t i = cube.firstCell + inCube;
    return order_.empty() ? i : order_[i];
  }
  void findCubes(const bricks::AmrField& field);
  void mergeCubes(int maxCubes);

  int side_ = 8;
  std::vector<std::size_t> order_;  // cells cube after cube, x fastest; empty: the field's order
  std::vector<Cube> cubes_;
  std::vector<LeafBox> boxes_;
  std::vector<std::vector<std::size_t>> boxCubes_;  // per box, its cubes, x fastest
};

}  // namespace amrstream::formats
