#include "formats/flash/flash_reader.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <hdf5.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "amrstream/error.hpp"
#include "formats/cell_checks.hpp"
#include "formats/cell_sink.hpp"
#include "formats/flash/flash_file.hpp"
#include "formats/flash/flash_info.hpp"
#include "formats/flash/flash_values.hpp"
#include "formats/hdf5_checks.hpp"

namespace amrstream::formats {
namespace {

using flash::Array;
using flash::FlashFile;
using flash::Handle;

constexpr int kMaxCellsPerBlockAxis = 4096;
constexpr std::size_t kMaxCells = std::size_t{1} << 31;

std::string shapeText(const std::vector<hsize_t>& dims) {
  return fmt::format("[{}]", fmt::join(dims, ", "));
}

// nxb/nyb/nzb and dimensionality from `integer scalars`, else `integer runtime parameters`.
struct BlockShape {
  int n[3] = {0, 0, 0};
  int dimensionality = 0;
};

BlockShape readBlockShape(const FlashFile& file) {
  BlockShape shape;
  const char* keys[3] = {"nxb", "nyb", "nzb"};
  for (const char* list : {"integer runtime parameters", "integer scalars"}) {
    for (const auto& [key, value] : file.readPairs<int>(list)) {
      for (int a = 0; a < 3; ++a)
        if (key == keys[a]) shape.n[a] = value;
      if (key == "dimensionality") shape.dimensionality = value;
    }
  }
  return shape;
}

struct Leaf {
  std::size_t block;
  int level;  // ours: 0 = finest
  glm::ivec3 lower;
};

// The per-block arrays, each checked against the block count.
struct BlockArrays {
  Array<int> refine, nodeType;
  Array<double> bbox, blockSize;
  std::size_t count = 0;

  double lo(std::size_t b, int a) const { return bbox.values[b * 6 + a * 2]; }
  double hi(std::size_t b, int a) const { return bbox.values[b * 6 + a * 2 + 1]; }
};

BlockArrays readBlockArrays(const FlashFile& file) {
  BlockArrays blocks{file.read<int>("refine level"), file.read<int>("node type"),
                     file.read<double>("bounding box"), file.read<double>("block size")};
  const auto& refine = blocks.refine;
  const std::size_t nb = refine.dims.empty() ? 0 : refine.dims[0];
  if (refine.dims.size() != 1 || nb == 0)
    file.fail("refine level", fmt::format("shape {} is not [nblocks]", shapeText(refine.dims)));
  if (blocks.nodeType.dims != std::vector<hsize_t>{nb})
    file.fail("node type",
              fmt::format("shape {} is not [{}]", shapeText(blocks.nodeType.dims), nb));
  if (blocks.bbox.dims != std::vector<hsize_t>{nb, 3, 2})
    file.fail("bounding box",
              fmt::format("shape {} is not [{}, 3, 2]", shapeText(blocks.bbox.dims), nb));
  if (blocks.blockSize.dims != std::vector<hsize_t>{nb, 3})
    file.fail("block size",
              fmt::format("shape {} is not [{}, 3]", shapeText(blocks.blockSize.dims), nb));
  blocks.count = nb;
  return blocks;
}

// Cells per block: the parameters when present, else the first variable's shape; then every
// variable's shape, before anything is allocated for the cells.
BlockShape checkedBlockShape(const FlashFile& file, const std::vector<std::string>& names,
                             std::size_t nb) {
  BlockShape shape = readBlockShape(file);
  {
    const std::string& first = names.front();
    const Handle set = file.open(first, " (listed in 'unknown names')");
    const auto d = file.dims(first, set);
    if (d.size() != 4 || d[0] != nb)
      file.fail(first, fmt::format("shape {} is not [{}, nzb, nyb, nxb]", shapeText(d), nb));
    for (int a = 0; a < 3; ++a)
      if (shape.n[a] == 0) shape.n[a] = static_cast<int>(std::min<hsize_t>(d[3 - a], 1 << 30));
  }
  for (int a = 0; a < 3; ++a)
    if (shape.n[a] < 1 || shape.n[a] > kMaxCellsPerBlockAxis)
      file.fail(fmt::format("cells per block along axis {} is {} (expected 1 to {})", a, shape.n[a],
                            kMaxCellsPerBlockAxis));
  if (shape.dimensionality == 0) shape.dimensionality = shape.n[2] == 1 ? 2 : 3;
  if (shape.dimensionality == 1 || shape.n[1] == 1) file.fail("1D FLASH files are not supported");
  if (shape.dimensionality != 2 && shape.dimensionality != 3)
    file.fail(fmt::format("dimensionality {} is not 2 or 3", shape.dimensionality));
  if (shape.dimensionality == 2 && shape.n[2] != 1)
    file.fail(fmt::format("2D file with nzb = {} (expected 1)", shape.n[2]));
  const std::vector<hsize_t> expected{nb, static_cast<hsize_t>(shape.n[2]),
                                      static_cast<hsize_t>(shape.n[1]),
                                      static_cast<hsize_t>(shape.n[0])};
  for (const std::string& name : names) {
    const Handle set = file.open(name, " (listed in 'unknown names')");
    const auto d = file.dims(name, set);
    if (d != expected)
      file.fail(name, fmt::format("shape {} is not [nblocks, nzb, nyb, nxb] = {}", shapeText(d),
                                  shapeText(expected)));
    requireStoredValues(set.get(), file.path(), name);
  }
  return shape;
}

// The leaf blocks, the finest refine level, the finest cell size and the domain's lower corner.
struct FinestGrid {
  std::vector<std::size_t> leafBlocks;
  int rmax = 0;
  glm::dvec3 dxf{std::numeric_limits<double>::infinity()};
  glm::dvec3 domainLo{std::numeric_limits<double>::infinity()};
};

FinestGrid finestGrid(const FlashFile& file, const BlockArrays& blocks, const BlockShape& shape) {
  const int axes = shape.dimensionality;
  FinestGrid grid;
  for (std::size_t b = 0; b < blocks.count; ++b) {
    if (blocks.nodeType.values[b] != 1) continue;
    grid.leafBlocks.push_back(b);
    const int refine = blocks.refine.values[b];
    if (refine < 1 || refine > bricks::kMaxLevel + 1)
      file.fail("refine level", fmt::format("block {} has refine level {} (expected 1 to {})", b,
                                            refine, bricks::kMaxLevel + 1));
    grid.rmax = std::max(grid.rmax, refine);
    for (int a = 0; a < 3; ++a) {
      const double lo = blocks.lo(b, a), hi = blocks.hi(b, a), extent = hi - lo;
      if (!std::isfinite(lo) || !std::isfinite(hi) || !std::isfinite(extent) ||
          (a < axes && !(extent > 0)))
        file.fail("bounding box", fmt::format("block {} axis {} spans [{}, {}]", b, a, lo, hi));
      const double size = blocks.blockSize.values[b * 3 + a];
      if (a < axes && !(std::abs(size - extent) <= 1e-4 * std::abs(extent)))
        file.fail("block size", fmt::format("block {} axis {}: size {} but bounding box extent {}",
                                            b, a, size, extent));
      grid.domainLo[a] = std::min(grid.domainLo[a], lo);
      if (a < axes) grid.dxf[a] = std::min(grid.dxf[a], extent / shape.n[a]);
    }
  }
  if (grid.leafBlocks.empty()) file.fail("node type", "no leaf blocks (node type 1)");
  // The bounding boxes carry rounding noise: spread the domain evenly over its finest cells.
  for (int a = 0; a < axes; ++a) {
    double domainHi = -std::numeric_limits<double>::infinity();
    for (std::size_t b : grid.leafBlocks) domainHi = std::max(domainHi, blocks.hi(b, a));
    const double span = domainHi - grid.domainLo[a];
    const double cells = std::round(span / grid.dxf[a]);
    if (!std::isnormal(grid.dxf[a]) || !std::isfinite(span) || !(cells >= 1))
      file.fail("bounding box",
                fmt::format("the leaves span [{}, {}] along axis {} with finest cells {} wide, "
                            "which positions cannot resolve",
                            grid.domainLo[a], domainHi, a, grid.dxf[a]));
    if (cells <= std::ldexp(1.0, bricks::kMaxExtentBits)) grid.dxf[a] = span / cells;
  }
  if (axes == 2) grid.dxf.z = grid.dxf.x;
  return grid;
}

// Block placement in finest-cell units; checks that every block's cells are 2^L cubes.
std::vector<Leaf> placeLeaves(const FlashFile& file, const BlockArrays& blocks,
                              const BlockShape& shape, const FinestGrid& grid) {
  std::vector<Leaf> leaves;
  for (std::size_t b : grid.leafBlocks) {
    Leaf leaf{b, grid.rmax - blocks.refine.values[b], glm::ivec3(0)};
    const double width = std::ldexp(1.0, leaf.level);
    for (int a = 0; a < shape.dimensionality; ++a) {
      const double lo = blocks.lo(b, a);
      const double cellWidth = (blocks.hi(b, a) - lo) / shape.n[a] / grid.dxf[a];
      if (!(std::abs(cellWidth - width) <= 1e-3 * width))
        file.fail("bounding box",
                  fmt::format("block {} at refine level {} has cells {} finest cells wide along "
                              "axis {}, expected {}",
                              b, blocks.refine.values[b], cellWidth, a, width));
      const double corner = (lo - grid.domainLo[a]) / grid.dxf[a];
      if (!(corner + shape.n[a] * width <= std::ldexp(1.0, bricks::kMaxExtentBits)))
        file.fail("bounding box", fmt::format("block {} ends beyond 2^{} finest cells along "
                                              "axis {}",
                                              b, bricks::kMaxExtentBits, a));
      if (!(std::abs(corner - std::round(corner)) <= 1e-3))
        file.fail("bounding box", fmt::format("block {} lower corner {} along axis {} is not on "
                                              "the finest grid",
                                              b, lo, a));
      leaf.lower[a] = static_cast<int>(std::lround(corner));
    }
    leaves.push_back(leaf);
  }
  return leaves;
}

// How the leaves become cells: a 2D slab repeats each cell along z up to the coarsest leaf's
// width, so its cell count is bounded by the file's leaf cells too.
struct CellLayout {
  BlockShape shape;
  int coarsest = 0;
  std::size_t perBlock = 0;
  std::size_t total = 0;

  int axes() const { return shape.dimensionality; }
  int copies(const Leaf& leaf) const { return axes() == 2 ? 1 << (coarsest - leaf.level) : 1; }
};

CellLayout cellLayout(const FlashFile& file, const BlockShape& shape,
                      const std::vector<Leaf>& leaves) {
  CellLayout layout{shape};
  for (const Leaf& leaf : leaves) layout.coarsest = std::max(layout.coarsest, leaf.level);
  layout.perBlock = static_cast<std::size_t>(shape.n[0]) * shape.n[1] * shape.n[2];
  const std::size_t leafCells = leaves.size() * layout.perBlock;
  for (const Leaf& leaf : leaves) {
    layout.total += layout.perBlock * std::size_t(layout.copies(leaf));
    if (layout.total > kMaxCells || layout.total > kMaxSlabGrowth * leafCells)
      file.fail(
          fmt::format("{} leaf cells become more than {} cells after stacking 2D cells "
                      "into a uniform slab: too many",
                      leafCells, std::min(kMaxCells, kMaxSlabGrowth * leafCells)));
  }
  return layout;
}

// Per leaf, whether its values are read (it meets the window, if any) and where its cells begin.
struct LeafCells {
  std::vector<char> wanted;
  std::vector<std::size_t> first;
};

LeafCells leafCells(const ValueWindow* window, const CellLayout& layout,
                    const std::vector<Leaf>& leaves) {
  LeafCells cells;
  const glm::ivec3 n(layout.shape.n[0], layout.shape.n[1], layout.shape.n[2]);
  std::size_t at = 0;
  for (const Leaf& leaf : leaves) {
    const int w = 1 << leaf.level;
    glm::ivec3 upper = leaf.lower + n * w;
    if (layout.axes() == 2) upper.z = 1 << layout.coarsest;
    cells.wanted.push_back(!window || window->meets(leaf.lower, upper, w));
    cells.first.push_back(at);
    at += layout.perBlock * std::size_t(layout.copies(leaf));
  }
  return cells;
}

// Places the cells on all cores, leaf after leaf, z-y-x within a leaf (the datasets'
// [nb][nzb][nyb][nxb] order), a 2D cell's copies one after another. A second read places only
// the leaves whose values it reads.
void placeCells(CellSink& sink, const CellLayout& layout, const std::vector<Leaf>& leaves,
                const LeafCells& cells) {
  const int* n = layout.shape.n;
  sink.presize(layout.total);
  tbb::parallel_for(std::size_t(0), leaves.size(), [&](std::size_t l) {
    if (!cells.wanted[l] && sink.skipsPieces()) return;
    const Leaf& leaf = leaves[l];
    const int w = 1 << leaf.level;
    const int copies = layout.copies(leaf);
    std::size_t at = cells.first[l];
    for (int k = 0; k < n[2]; ++k)
      for (int j = 0; j < n[1]; ++j)
        for (int i = 0; i < n[0]; ++i)
          for (int c = 0; c < copies; ++c, ++at) {
            const int z = layout.axes() == 2 ? c * w : leaf.lower.z + k * w;
            sink.place(at, glm::ivec3(leaf.lower.x + i * w, leaf.lower.y + j * w, z),
                       static_cast<std::uint8_t>(leaf.level));
          }
  });
}

// Every channel's values of the leaves read: a 3D leaf's straight into its cells, a 2D leaf's
// into `stacked` first, then into each of its cells' copies.
void setValues(const FlashFile& file, CellSink& sink, const std::vector<std::string>& names,
               const CellLayout& layout, const std::vector<Leaf>& leaves, const LeafCells& cells) {
  const std::array<int, 3> n{layout.shape.n[0], layout.shape.n[1], layout.shape.n[2]};
  const std::size_t perBlock = layout.perBlock;
  std::vector<std::size_t> read;  // the leaves whose values are read
  for (std::size_t l = 0; l < leaves.size(); ++l)
    if (cells.wanted[l]) read.push_back(l);
  std::vector<float> stacked(layout.axes() == 2 ? read.size() * perBlock : 0);
  for (std::size_t channel = 0; channel < names.size(); ++channel) {
    const std::span<float> values = sink.values(channel);
    if (values.empty()) return;  // the cells alone
    std::vector<flash::BlockValues> blocks;
    for (std::size_t s = 0; s < read.size(); ++s)
      blocks.push_back({leaves[read[s]].block, layout.axes() == 2
                                                   ? stacked.data() + s * perBlock
                                                   : values.data() + cells.first[read[s]]});
    flash::readBlockValues(file, names[channel], blocks, n);
    if (layout.axes() == 3) continue;
    tbb::parallel_for(std::size_t(0), read.size(), [&](std::size_t s) {
      const int copies = layout.copies(leaves[read[s]]);
      float* into = values.data() + cells.first[read[s]];
      for (std::size_t i = 0; i < perBlock; ++i)
        std::fill_n(into + i * copies, copies, stacked[s * perBlock + i]);
    });
  }
}

}  // namespace

bricks::AmrField readFlash(const std::filesystem::path& path, const ValueWindow* window,
                           WindowedRead* read) {
  const FlashFile file(path);
  const auto names = file.readStrings("unknown names");
  if (names.empty()) file.fail("unknown names", "lists no variables");
  const BlockArrays blocks = readBlockArrays(file);
  const BlockShape shape = checkedBlockShape(file, names, blocks.count);
  const FinestGrid grid = finestGrid(file, blocks, shape);
  const std::vector<Leaf> leaves = placeLeaves(file, blocks, shape, grid);
  const CellLayout layout = cellLayout(file, shape, leaves);

  const LeafCells cells = leafCells(window, layout, leaves);
  if (read) {
    read->pieces += leaves.size();
    read->piecesRead += std::size_t(std::count(cells.wanted.begin(), cells.wanted.end(), 1));
  }

  CellSink sink(window, path.string(), read);
  for (const std::string& name : names) sink.addChannel(name);
  placeCells(sink, layout, leaves, cells);
  glm::dvec3 origin = grid.domainLo;
  // A 2D file's plane is z = 0, in the middle of its slab (as VTK's FLASH reader puts it).
  if (layout.axes() == 2) origin.z = -0.5 * std::ldexp(grid.dxf.z, layout.coarsest);
  const WorldTransform transform{origin, grid.dxf};
  if (const auto problem = unrepresentablePositions(transform, sink.lowers(), sink.levels()))
    file.fail("bounding box", "the leaves cannot be placed: " + *problem);
  setValues(file, sink, names, layout, leaves, cells);

  bricks::AmrField field = sink.finish(transform);
  field.setInfo(flash::readFlashInfo(file, grid.rmax, shape.dimensionality, names));
  return field;
}

}  // namespace amrstream::formats
