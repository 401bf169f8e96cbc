#include "formats/flash/flash_reader.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "amrstream/error.hpp"
#include "formats/cell_checks.hpp"
#include "formats/cell_sink.hpp"
#include "formats/flash/flash_file.hpp"
#include "formats/flash/flash_info.hpp"
#include "formats/hdf5_checks.hpp"

namespace amrstream::formats {
namespace {

using flash::Array;
using flash::FlashFile;
using flash::Handle;

constexpr int kMaxCellsPerBlockAxis = 4096;
constexpr std::size_t kMaxCells = std::size_t{1} << 31;
// A 2D slab repeats a fine leaf cell 2^(levels below the coarsest leaf) times along z: at most
// this many cells per leaf cell in the file (leaves 8 levels finer than the coarsest, at most),
// so that the cells stay within a small multiple of the data the file stores.
constexpr std::size_t kMaxSlabGrowth = 256;

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

}  // namespace

bricks::AmrField readFlash(const std::filesystem::path& path, const ValueWindow* window,
                           WindowedRead* read) {
  const FlashFile file(path);
  const auto names = file.readStrings("unknown names");
  if (names.empty()) file.fail("unknown names", "lists no variables");

  const auto refine = file.read<int>("refine level");
  const auto nodeType = file.read<int>("node type");
  const auto bbox = file.read<double>("bounding box");
  const auto blockSize = file.read<double>("block size");
  const std::size_t nb = refine.dims.empty() ? 0 : refine.dims[0];
  if (refine.dims.size() != 1 || nb == 0)
    file.fail("refine level", fmt::format("shape {} is not [nblocks]", shapeText(refine.dims)));
  if (nodeType.dims != std::vector<hsize_t>{nb})
    file.fail("node type", fmt::format("shape {} is not [{}]", shapeText(nodeType.dims), nb));
  if (bbox.dims != std::vector<hsize_t>{nb, 3, 2})
    file.fail("bounding box", fmt::format("shape {} is not [{}, 3, 2]", shapeText(bbox.dims), nb));
  if (blockSize.dims != std::vector<hsize_t>{nb, 3})
    file.fail("block size", fmt::format("shape {} is not [{}, 3]", shapeText(blockSize.dims), nb));

  // Cells per block: the parameters when present, else the first variable's shape.
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
  const int axes = shape.dimensionality;
  const std::vector<hsize_t> expected{nb, static_cast<hsize_t>(shape.n[2]),
                                      static_cast<hsize_t>(shape.n[1]),
                                      static_cast<hsize_t>(shape.n[0])};
  // Every variable's shape before anything is allocated for the cells.
  for (const std::string& name : names) {
    const Handle set = file.open(name, " (listed in 'unknown names')");
    const auto d = file.dims(name, set);
    if (d != expected)
      file.fail(name, fmt::format("shape {} is not [nblocks, nzb, nyb, nxb] = {}", shapeText(d),
                                  shapeText(expected)));
    requireStoredValues(set.get(), file.path(), name);
  }

  // Leaves, finest refine level, finest cell size and domain lower corner.
  std::vector<std::size_t> leafBlocks;
  int rmax = 0;
  glm::dvec3 dxf(std::numeric_limits<double>::infinity());
  glm::dvec3 domainLo(std::numeric_limits<double>::infinity());
  const auto lo = [&](std::size_t b, int a) { return bbox.values[b * 6 + a * 2]; };
  const auto hi = [&](std::size_t b, int a) { return bbox.values[b * 6 + a * 2 + 1]; };
  for (std::size_t b = 0; b < nb; ++b) {
    if (nodeType.values[b] != 1) continue;
    leafBlocks.push_back(b);
    if (refine.values[b] < 1 || refine.values[b] > bricks::kMaxLevel + 1)
      file.fail("refine level", fmt::format("block {} has refine level {} (expected 1 to {})", b,
                                            refine.values[b], bricks::kMaxLevel + 1));
    rmax = std::max(rmax, refine.values[b]);
    for (int a = 0; a < 3; ++a) {
      const double extent = hi(b, a) - lo(b, a);
      if (!std::isfinite(lo(b, a)) || !std::isfinite(hi(b, a)) || !std::isfinite(extent) ||
          (a < axes && !(extent > 0)))
        file.fail("bounding box",
                  fmt::format("block {} axis {} spans [{}, {}]", b, a, lo(b, a), hi(b, a)));
      const double size = blockSize.values[b * 3 + a];
      if (a < axes && !(std::abs(size - extent) <= 1e-4 * std::abs(extent)))
        file.fail("block size", fmt::format("block {} axis {}: size {} but bounding box extent {}",
                                            b, a, size, extent));
      domainLo[a] = std::min(domainLo[a], lo(b, a));
      if (a < axes) dxf[a] = std::min(dxf[a], extent / shape.n[a]);
    }
  }
  if (leafBlocks.empty()) file.fail("node type", "no leaf blocks (node type 1)");
  // The bounding boxes carry rounding noise: spread the domain evenly over its finest cells.
  for (int a = 0; a < axes; ++a) {
    double domainHi = -std::numeric_limits<double>::infinity();
    for (std::size_t b : leafBlocks) domainHi = std::max(domainHi, hi(b, a));
    const double cells = std::round((domainHi - domainLo[a]) / dxf[a]);
    if (!std::isnormal(dxf[a]) || !std::isfinite(domainHi - domainLo[a]) || !(cells >= 1))
      file.fail("bounding box",
                fmt::format("the leaves span [{}, {}] along axis {} with finest cells {} wide, "
                            "which positions cannot resolve",
                            domainLo[a], domainHi, a, dxf[a]));
    if (cells <= std::ldexp(1.0, bricks::kMaxExtentBits)) dxf[a] = (domainHi - domainLo[a]) / cells;
  }
  if (axes == 2) dxf.z = dxf.x;

  // Block placement in finest-cell units; checks that every block's cells are 2^L cubes.
  std::vector<Leaf> leaves;
  int coarsest = 0;
  for (std::size_t b : leafBlocks) {
    Leaf leaf{b, rmax - refine.values[b], glm::ivec3(0)};
    const double width = std::ldexp(1.0, leaf.level);
    for (int a = 0; a < axes; ++a) {
      const double cellWidth = (hi(b, a) - lo(b, a)) / shape.n[a] / dxf[a];
      if (!(std::abs(cellWidth - width) <= 1e-3 * width))
        file.fail("bounding box",
                  fmt::format("block {} at refine level {} has cells {} finest cells wide along "
                              "axis {}, expected {}",
                              b, refine.values[b], cellWidth, a, width));
      const double corner = (lo(b, a) - domainLo[a]) / dxf[a];
      if (!(corner + shape.n[a] * width <= std::ldexp(1.0, bricks::kMaxExtentBits)))
        file.fail("bounding box", fmt::format("block {} ends beyond 2^{} finest cells along "
                                              "axis {}",
                                              b, bricks::kMaxExtentBits, a));
      if (!(std::abs(corner - std::round(corner)) <= 1e-3))
        file.fail("bounding box", fmt::format("block {} lower corner {} along axis {} is not on "
                                              "the finest grid",
                                              b, lo(b, a), a));
      leaf.lower[a] = static_cast<int>(std::lround(corner));
    }
    coarsest = std::max(coarsest, leaf.level);
    leaves.push_back(leaf);
  }

  // Cells in block order, z-y-x within a block (the datasets' [nb][nzb][nyb][nxb] order). A 2D
  // slab copies fine cells, so its cell count is bounded by the file's leaf cells too.
  const std::size_t perBlock = static_cast<std::size_t>(shape.n[0]) * shape.n[1] * shape.n[2];
  const std::size_t leafCells = leaves.size() * perBlock;
  std::size_t total = 0;
  for (const Leaf& leaf : leaves) {
    total += perBlock << (axes == 2 ? coarsest - leaf.level : 0);
    if (total > kMaxCells || total > kMaxSlabGrowth * leafCells)
      file.fail(
          fmt::format("{} leaf cells become more than {} cells after stacking 2D cells "
                      "into a uniform slab: too many",
                      leafCells, std::min(kMaxCells, kMaxSlabGrowth * leafCells)));
  }
  // With a window, the leaves meeting it, each at its place in the values read.
  constexpr std::size_t kNotRead = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> blocksRead, readSlot(window ? nb : 0, kNotRead);
  if (window)
    for (const Leaf& leaf : leaves) {
      const int w = 1 << leaf.level;
      glm::ivec3 upper = leaf.lower + glm::ivec3(shape.n[0], shape.n[1], shape.n[2]) * w;
      if (axes == 2) upper.z = 1 << coarsest;
      if (!window->meets(leaf.lower, upper, w)) continue;
      readSlot[leaf.block] = blocksRead.size();
      blocksRead.push_back(leaf.block);
    }
  if (read) {
    read->pieces += leaves.size();
    read->piecesRead += window ? blocksRead.size() : leaves.size();
  }

  CellSink sink(window, path.string(), read);
  for (const std::string& name : names) sink.addChannel(name);
  sink.reserve(total);
  // The cells whose values are read: their indices into a variable's data and, with a window
  // (else they are all the cells, in order), their own.
  std::vector<std::size_t> froms, ats;
  froms.reserve(window ? 0 : total);
  for (const Leaf& leaf : leaves) {
    const int w = 1 << leaf.level;
    const int copies = axes == 2 ? 1 << (coarsest - leaf.level) : 1;
    const bool wanted = !window || readSlot[leaf.block] != kNotRead;
    if (!wanted && sink.skipsPieces()) {
      sink.skip(perBlock * std::size_t(copies));
      continue;
    }
    for (int k = 0; k < shape.n[2]; ++k)
      for (int j = 0; j < shape.n[1]; ++j)
        for (int i = 0; i < shape.n[0]; ++i) {
          const std::size_t from = leaf.block * perBlock +
                                   (static_cast<std::size_t>(k) * shape.n[1] + j) * shape.n[0] + i;
          for (int c = 0; c < copies; ++c) {
            const int z = axes == 2 ? c * w : leaf.lower.z + k * w;
            const std::size_t at =
                sink.cell(glm::ivec3(leaf.lower.x + i * w, leaf.lower.y + j * w, z),
                          static_cast<std::uint8_t>(leaf.level));
            if (!wanted) continue;
            froms.push_back(from);
            if (window) ats.push_back(at);
          }
        }
  }

  const WorldTransform transform{domainLo, dxf};
  if (const auto problem = unrepresentablePositions(transform, sink.lowers(), sink.levels()))
    file.fail("bounding box", "the leaves cannot be placed: " + *problem);

  for (std::size_t channel = 0; channel < names.size(); ++channel) {
    const std::string& name = names[channel];
    const std::vector<double> data =
        window ? file.readBlocks(name, blocksRead)
               : file.read<double>(name, " (listed in 'unknown names')").values;
    for (std::size_t i = 0; i < froms.size(); ++i) {
      const std::size_t from = froms[i], at = window ? ats[i] : i;
      const double v = data[window ? readSlot[from / perBlock] * perBlock + from % perBlock : from];
      if (const auto problem = unusableFieldValue(v)) {
        const std::size_t block = from / perBlock, inBlock = from % perBlock;
        file.fail(name, fmt::format("value {} of block {} cell (i, j, k) = ({}, {}, {}) is {}", v,
                                    block, inBlock % shape.n[0], inBlock / shape.n[0] % shape.n[1],
                                    inBlock / shape.n[0] / shape.n[1], *problem));
      }
      sink.set(channel, at, static_cast<float>(v));
    }
  }

  bricks::AmrField field = sink.finish(transform);
  field.setInfo(flash::readFlashInfo(file, rmax, axes));
  return field;
}

}  // namespace amrstream::formats
