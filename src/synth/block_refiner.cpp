#include "block_refiner.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <queue>

#include "amrstream/error.hpp"
#include "util/morton.hpp"

namespace amrstream::synth {

namespace {

struct Candidate {
  double priority;
  std::uint64_t morton;
  Block block;
};

// std::priority_queue pops the largest: highest priority, then coarser, then lower Morton key.
struct PopsLater {
  bool operator()(const Candidate& a, const Candidate& b) const {
    if (a.priority != b.priority) return a.priority < b.priority;
    if (a.block.level != b.block.level) return a.block.level < b.block.level;
    return a.morton > b.morton;
  }
};

std::int64_t finestCellsPerAxis(const BuiltinOptions& options) {
  return std::int64_t(options.rootBlocks) * kBlockSide * (std::int64_t(1) << (options.levels - 1));
}

}  // namespace

WorldTransform generatorTransform(const BuiltinOptions& options) {
  return {glm::dvec3(0.0), glm::dvec3(1.0 / double(finestCellsPerAxis(options)))};
}

BlockBox blockBox(const Block& block, const WorldTransform& transform) {
  const glm::dvec3 lower = transform.toPhysical(glm::dvec3(block.lower));
  const glm::dvec3 upper = transform.toPhysical(glm::dvec3(block.lower + block.span()));
  return {lower, upper, (upper.x - lower.x) / kBlockSide};
}

void validateGeneratorOptions(const BuiltinOptions& options, const std::string& source) {
  if (options.levels < 1 || options.levels > kMaxBuiltinLevels)
    throw InputError(source, fmt::format("option levels is {}; it must be between 1 and {}",
                                         options.levels, kMaxBuiltinLevels));
  if (options.rootBlocks < 1)
    throw InputError(
        source, fmt::format("option rootBlocks is {}; it must be at least 1", options.rootBlocks));
  const std::int64_t axisLimit = std::int64_t(1) << bricks::kMaxExtentBits;
  if (finestCellsPerAxis(options) > axisLimit)
    throw InputError(source, fmt::format("option rootBlocks is {}; with {} levels the domain would "
                                         "span {} finest cells per axis, at most {} are supported",
                                         options.rootBlocks, options.levels,
                                         finestCellsPerAxis(options), axisLimit));
  const double rootCells = std::pow(double(options.rootBlocks), 3) * kBlockCells;
  if (rootCells > double(std::numeric_limits<std::int32_t>::max()))
    throw InputError(source, fmt::format("option rootBlocks is {}; the root grid of {}^3 blocks "
                                         "would have {:.3g} cells, more than the 2^31 - 1 cells "
                                         "supported",
                                         options.rootBlocks, options.rootBlocks, rootCells));
  if (double(options.targetCells) < rootCells)
    throw InputError(source, fmt::format("option targetCells is {}; the root grid of {}^3 blocks "
                                         "alone has {} cells",
                                         options.targetCells, options.rootBlocks, rootCells));
}

std::vector<Block> refineBlocks(const BuiltinOptions& options, const std::string& source,
                                const RefinementPriority& priority) {
  validateGeneratorOptions(options, source);
  const WorldTransform transform = generatorTransform(options);
  const auto candidate = [&](const Block& block) {
    const double p = priority(blockBox(block, transform));
    return Candidate{std::isnan(p) ? -std::numeric_limits<double>::infinity() : p,
                     mortonKey(glm::uvec3(block.lower)), block};
  };

  const int n = options.rootBlocks;
  const int top = options.levels - 1;
  std::vector<Candidate> roots(std::size_t(n) * n * n);
  tbb::parallel_for(std::size_t(0), roots.size(), [&](std::size_t i) {
    const glm::ivec3 index(int(i % n), int(i / n % n), int(i / n / n));
    roots[i] = candidate(Block{index * (kBlockSide << top), top});
  });
  std::priority_queue<Candidate, std::vector<Candidate>, PopsLater> queue(PopsLater{},
                                                                          std::move(roots));

  std::vector<Block> leaves;
  std::size_t cells = queue.size() * kBlockCells;
  const std::size_t splitCost = 7 * kBlockCells;
  while (!queue.empty()) {
    const Candidate best = queue.top();
    if (best.block.level > 0 && cells + splitCost > options.targetCells) break;
    queue.pop();
    if (best.block.level == 0) {
      leaves.push_back(best.block);
      continue;
    }
    cells += splitCost;
    std::array<Candidate, 8> children;
    const int half = best.block.span() / 2;
    tbb::parallel_for(0, 8, [&](int i) {
      const glm::ivec3 offset(i & 1, (i >> 1) & 1, (i >> 2) & 1);
      children[i] = candidate(Block{best.block.lower + half * offset, best.block.level - 1});
    });
    for (const Candidate& child : children) queue.push(child);
  }
  for (; !queue.empty(); queue.pop()) leaves.push_back(queue.top().block);

  std::sort(leaves.begin(), leaves.end(), [](const Block& a, const Block& b) {
    return mortonKey(glm::uvec3(a.lower)) < mortonKey(glm::uvec3(b.lower));
  });
  return leaves;
}

}  // namespace amrstream::synth
