#pragma once
// Turns leaf blocks into an AmrField: every block emits its 512 cells (block after block, x
// fastest inside a block) with channel values from a sampler, filled in parallel over blocks.

#include <functional>
#include <span>
#include <string>
#include <vector>

#include "block_refiner.hpp"

namespace amrstream::synth {

// Fills one block: values[c][i] is channel c at the block's cell i (x fastest), whose physical
// centre is centres[i]. Called concurrently for different blocks.
using BlockSampler = std::function<void(const BlockBox& box, std::span<const glm::dvec3> centres,
                                        std::span<float* const> values)>;

// Cell centres are transform.toPhysical(lower + width / 2) from integer cell corners.
bricks::AmrField emitCells(const std::vector<Block>& leaves, const WorldTransform& transform,
                           const std::vector<std::string>& channelNames,
                           const BlockSampler& sampler, std::string source);

}  // namespace amrstream::synth
