#include "formats/flash/flash_values.hpp"

#include <fmt/format.h>

#include <vector>

#include "formats/cell_checks.hpp"
#include "formats/float_runs.hpp"
#include "formats/hdf5_contiguous.hpp"

namespace amrstream::formats::flash {

namespace {

[[noreturn]] void unusable(const FlashFile& file, const std::string& name, std::size_t block,
                           std::size_t inBlock, double value, const std::string& problem,
                           const std::array<int, 3>& n) {
  file.fail(name,
            fmt::format("value {} of block {} cell (i, j, k) = ({}, {}, {}) is {}", value, block,
                        inBlock % n[0], inBlock / n[0] % n[1], inBlock / n[0] / n[1], problem));
}

// Runs of blocks consecutive in the file and in memory, each read as one.
struct BlockRuns {
  std::vector<FloatRun> runs;
  std::vector<std::size_t> firstBlocks;
};

BlockRuns blockRuns(std::span<const BlockValues> blocks, std::uint64_t offset, int valueBytes,
                    std::size_t perBlock) {
  BlockRuns result;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const BlockValues& b = blocks[i];
    if (i > 0 && b.block == blocks[i - 1].block + 1 && b.into == blocks[i - 1].into + perBlock) {
      result.runs.back().count += perBlock;
      continue;
    }
    result.runs.push_back(
        {offset + std::uint64_t(b.block) * perBlock * std::uint64_t(valueBytes), perBlock, b.into});
    result.firstBlocks.push_back(b.block);
  }
  return result;
}

}  // namespace

void readBlockValues(const FlashFile& file, const std::string& name,
                     std::span<const BlockValues> blocks, const std::array<int, 3>& cells) {
  if (blocks.empty()) return;
  const std::size_t perBlock = std::size_t(cells[0]) * cells[1] * cells[2];
  std::optional<ContiguousFloats> contiguous;
  {
    const Handle set = file.open(name);
    std::size_t size = 0;
    if (file.typeClass(name, set, &size) != H5T_FLOAT || (size != 4 && size != 8))
      file.fail(name, "expected float32 or float64 data");
    const StoredDataset stored = inspectStoredDataset(set.get(), file.path(), name);
    if (blocks.back().block >= stored.count / perBlock)
      file.fail(name, fmt::format("has no block {}", blocks.back().block));
    contiguous = contiguousFloats(stored, file.path(), name);
  }
  if (contiguous) {
    const BlockRuns runs =
        blockRuns(blocks, contiguous->offset, contiguous->encoding.bytes, perBlock);
    const auto bad = readFloatRuns(file.path(), contiguous->encoding, runs.runs,
                                   fmt::format("dataset '{}'", name));
    if (bad)
      unusable(file, name, runs.firstBlocks[bad->run] + bad->index / perBlock,
               bad->index % perBlock, bad->value, bad->problem, cells);
    return;
  }
  std::vector<std::size_t> indices;
  for (const BlockValues& b : blocks) indices.push_back(b.block);
  const std::vector<double> values = file.readBlocks(name, indices);
  for (std::size_t slot = 0; slot < blocks.size(); ++slot)
    for (std::size_t i = 0; i < perBlock; ++i) {
      const double v = values[slot * perBlock + i];
      if (const auto problem = unusableFieldValue(v))
        unusable(file, name, blocks[slot].block, i, v, *problem, cells);
      blocks[slot].into[i] = static_cast<float>(v);
    }
}

}  // namespace amrstream::formats::flash
