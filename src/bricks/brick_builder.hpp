#pragma once
// Groups the leaf cells of an AmrField into bricks: boxes of same-level cells with no holes
// (docs/architecture.md, "Bricks"). Every cell lies in exactly one brick.

#include <cstdint>
#include <vector>

#include "../../shaders/glsl/shared/amr_types.h"
#include "amr_field.hpp"

namespace amrstream::bricks {

struct BrickBuildOptions {
  int maxBrickSide = 32;  // cap on the cells per axis of one brick (ExaBricks uses 127)
};

struct BrickSet {
  std::vector<shared::Brick> bricks;
  // Brick-ordered slot -> index of the AmrField cell stored there. Slots of brick b are
  // [b.valueOffset, b.valueOffset + b.size.x * b.size.y * b.size.z); every cell appears once.
  std::vector<std::uint32_t> cellIds;

  // The channel's values in brick-ordered slots.
  std::vector<float> gather(const Channel& channel) const;
};

// Parallel, O(N log N) in the number of cells.
BrickSet buildBricks(const AmrField& field, const BrickBuildOptions& options = {});

// A brick's domain: its bounds padded by half a cell of its level on every side. Returned in
// half-finest-cell units (coordinates doubled) so that it stays integral.
CellBox brickDomainDoubled(const shared::Brick& brick);

}  // namespace amrstream::bricks
