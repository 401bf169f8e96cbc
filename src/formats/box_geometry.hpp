#pragma once
// Where the boxes of a field's leaf cells lie, for the format writers: the coarsest and finest
// levels among them, and the domain they span in cells of the coarsest level.

#include <algorithm>
#include <glm/glm.hpp>

#include "bricks/amr_field.hpp"
#include "formats/leaf_boxes.hpp"

namespace amrstream::formats {

struct BoxGeometry {
  int finest = 0, coarsest = 0;  // our levels (0 = finest cells)
  glm::ivec3 domainCells{0};     // the cells' bounding box from (0, 0, 0), in coarsest cells

  BoxGeometry(const bricks::AmrField& field, const LeafBoxes& boxes) {
    finest = 1 << 30;
    for (const LeafBox& box : boxes.boxes()) {
      finest = std::min(finest, box.level);
      coarsest = std::max(coarsest, box.level);
    }
    const int width = 1 << coarsest;
    domainCells = (field.bounds().upper + width - 1) / width;
  }
  // A box's corner in physical coordinates.
  static glm::dvec3 physical(const bricks::AmrField& field, glm::ivec3 cells) {
    return field.transform().toPhysical(glm::dvec3(cells));
  }
};

}  // namespace amrstream::formats
