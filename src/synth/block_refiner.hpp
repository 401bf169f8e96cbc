#pragma once
// The block layout shared by the generators: a root grid of rootBlocks^3 blocks of 8^3 cells at
// the coarsest level (levels - 1), each block splittable into 8 child blocks of 8^3 cells of the
// next finer level (an octree of blocks). The physical domain is the unit cube.
//
// refineBlocks() repeatedly splits the leaf block of highest priority while the split keeps the
// leaf cell count within targetCells; blocks of level 0 are never split. Ties go to the coarser
// block, then to the lower Morton key of the lower corner, so the layout is deterministic.

#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "amrstream/builtin.hpp"
#include "bricks/amr_field.hpp"
#include "generators.hpp"

namespace amrstream::synth {

inline constexpr int kBlockSide = 8;             // cells per block and axis
inline constexpr std::size_t kBlockCells = 512;  // kBlockSide^3

struct Block {
  glm::ivec3 lower{0};  // finest-cell units
  int level = 0;        // of its cells (0 = finest); the block spans 8 * 2^level finest cells

  int span() const { return kBlockSide << level; }
};

// A block in physical coordinates.
struct BlockBox {
  glm::dvec3 lower{0.0};
  glm::dvec3 upper{0.0};
  double cellWidth = 0.0;
};

// Maps finest-cell units onto the unit cube: spacing 1 / (rootBlocks * 8 * 2^(levels-1)).
WorldTransform generatorTransform(const BuiltinOptions& options);
BlockBox blockBox(const Block& block, const WorldTransform& transform);

// Throws InputError naming `source` and the offending option: levels outside 1..8, rootBlocks
// below 1 or too many for the cell-unit range, targetCells below the root grid's cell count.
void validateGeneratorOptions(const BuiltinOptions& options, const std::string& source);

// How much a block wants to be split; higher first. Deterministic; called concurrently.
using RefinementPriority = std::function<double(const BlockBox& box)>;

// The leaf blocks, in Morton order of their lower corners. Validates the options first.
std::vector<Block> refineBlocks(const BuiltinOptions& options, const std::string& source,
                                const RefinementPriority& priority);

}  // namespace amrstream::synth
