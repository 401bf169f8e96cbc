#include "block_emitter.hpp"

#include <tbb/parallel_for.h>

#include <array>

namespace amrstream::synth {

bricks::AmrField emitCells(const std::vector<Block>& leaves, const WorldTransform& transform,
                           const std::vector<std::string>& channelNames,
                           const BlockSampler& sampler, std::string source) {
  const std::size_t cellCount = leaves.size() * kBlockCells;
  std::vector<glm::ivec3> lowers(cellCount);
  std::vector<std::uint8_t> levels(cellCount);
  std::vector<Channel> channels;
  for (const std::string& name : channelNames)
    channels.push_back({name, std::vector<float>(cellCount)});

  tbb::parallel_for(std::size_t(0), leaves.size(), [&](std::size_t b) {
    const Block& block = leaves[b];
    const int width = bricks::AmrField::cellWidth(block.level);
    const std::size_t first = b * kBlockCells;
    std::array<glm::dvec3, kBlockCells> centres;
    for (int i = 0; i < int(kBlockCells); ++i) {
      const glm::ivec3 index(i % kBlockSide, i / kBlockSide % kBlockSide,
                             i / kBlockSide / kBlockSide);
      const glm::ivec3 lower = block.lower + width * index;
      lowers[first + i] = lower;
      levels[first + i] = std::uint8_t(block.level);
      centres[i] = transform.toPhysical(glm::dvec3(lower) + 0.5 * width);
    }
    std::vector<float*> values;
    values.reserve(channels.size());
    for (Channel& channel : channels) values.push_back(channel.values.data() + first);
    sampler(blockBox(block, transform), centres, values);
  });

  return bricks::AmrField(std::move(lowers), std::move(levels), std::move(channels), transform,
                          std::move(source));
}

}  // namespace amrstream::synth
