#include "brick_splitter.hpp"

#include <tbb/blocked_range.h>
#include <tbb/concurrent_vector.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <bit>
#include <cassert>
#include <climits>
#include <cstdlib>
#include <optional>

#include "slab_histogram.hpp"

namespace amrstream::bricks::detail {

namespace {

using U64 = std::uint64_t;

// Nodes with at least this many cells split their two sides in parallel.
constexpr std::size_t kParallelCells = 16384;
// Nodes with at least this many cells are bounded and partitioned on all cores, in blocks of
// kBlockCells: the top of a level's tree would otherwise pass over its cells on one core.
constexpr std::size_t kParallelPassCells = std::size_t(1) << 20;
constexpr std::size_t kBlockCells = std::size_t(1) << 16;

GridBounds boundsOfSerial(std::span<const GridCell> cells) {
  int lo[3] = {INT_MAX, INT_MAX, INT_MAX}, hi[3] = {INT_MIN, INT_MIN, INT_MIN};
  for (const GridCell& c : cells)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], c.g[a]);
      hi[a] = std::max(hi[a], c.g[a]);
    }
  return {glm::ivec3(lo[0], lo[1], lo[2]), glm::ivec3(hi[0], hi[1], hi[2]) + 1};
}

GridBounds boundsOf(std::span<const GridCell> cells) {
  if (cells.size() < kParallelPassCells) return boundsOfSerial(cells);
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, cells.size(), kBlockCells),
      GridBounds{glm::ivec3(INT_MAX), glm::ivec3(INT_MIN)},
      [&](const tbb::blocked_range<std::size_t>& range, GridBounds b) {
        const GridBounds part = boundsOfSerial(cells.subspan(range.begin(), range.size()));
        return GridBounds{glm::min(b.lower, part.lower), glm::max(b.upper, part.upper)};
      },
      [](const GridBounds& a, const GridBounds& b) {
        return GridBounds{glm::min(a.lower, b.lower), glm::max(a.upper, b.upper)};
      });
}

U64 volume(glm::ivec3 e) { return U64(e.x) * U64(e.y) * U64(e.z); }

int longestAxis(glm::ivec3 e) {
  int axis = 0;
  if (e.y > e[axis]) axis = 1;
  if (e.z > e[axis]) axis = 2;
  return axis;
}

// Branchless Lomuto partition (the split predicate is unpredictable); returns the size of the
// part for which `lower` holds. The result depends only on the input order.
template <typename Predicate>
std::size_t partitionSerial(std::span<GridCell> cells, Predicate lower) {
  std::size_t count = 0;
  for (GridCell& c : cells) {
    const GridCell moving = c;
    c = cells[count];
    cells[count] = moving;
    count += lower(moving) ? 1 : 0;
  }
  return count;
}

// The cells in order of position of one kind of misplaced run: per block, the run [from, to).
struct Runs {
  std::vector<std::size_t> from, to, before;  // before: cells in the runs of earlier blocks

  // Calls move(position) for the cells of rank [first, last) among all runs' cells.
  template <typename Move>
  void each(std::size_t first, std::size_t last, Move move) const {
    std::size_t run =
        std::size_t(std::upper_bound(before.begin(), before.end(), first) - before.begin()) - 1;
    for (std::size_t rank = first; rank < last; ++run) {
      const std::size_t begin = from[run] + (rank - before[run]);
      const std::size_t count = std::min(to[run] - begin, last - rank);
      for (std::size_t k = 0; k < count; ++k) move(begin + k);
      rank += count;
    }
  }
};

// The partition of a large node on all cores: each block is partitioned on its own, then the
// upper cells that lie below the split point trade places with the lower cells above it. The
// result depends only on the input order (the blocks are fixed, whatever the cores).
template <typename Predicate>
std::size_t partitionCells(std::span<GridCell> cells, Predicate lower) {
  const std::size_t n = cells.size();
  if (n < kParallelPassCells) return partitionSerial(cells, lower);
  const std::size_t blocks = (n + kBlockCells - 1) / kBlockCells;
  std::vector<std::size_t> lowers(blocks);
  tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t b) {
    const std::size_t begin = b * kBlockCells, end = std::min(n, begin + kBlockCells);
    lowers[b] = partitionSerial(cells.subspan(begin, end - begin), lower);
  });
  std::size_t split = 0;
  for (const std::size_t count : lowers) split += count;
  // Upper cells below `split` and lower cells at or above it, block by block.
  Runs uppers, lows;
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t begin = b * kBlockCells, end = std::min(n, begin + kBlockCells);
    const std::size_t middle = begin + lowers[b];
    if (middle < std::min(end, split)) {
      uppers.before.push_back(
          uppers.before.empty() ? 0 : uppers.before.back() + uppers.to.back() - uppers.from.back());
      uppers.from.push_back(middle);
      uppers.to.push_back(std::min(end, split));
    }
    if (std::max(begin, split) < middle) {
      lows.before.push_back(
          lows.before.empty() ? 0 : lows.before.back() + lows.to.back() - lows.from.back());
      lows.from.push_back(std::max(begin, split));
      lows.to.push_back(middle);
    }
  }
  const std::size_t misplaced =
      uppers.before.empty() ? 0 : uppers.before.back() + uppers.to.back() - uppers.from.back();
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, misplaced, kBlockCells), [&](const auto& range) {
        std::vector<std::size_t> targets;
        targets.reserve(range.size());
        lows.each(range.begin(), range.end(), [&](std::size_t at) { targets.push_back(at); });
        std::size_t k = 0;
        uppers.each(range.begin(), range.end(),
                    [&](std::size_t at) { std::swap(cells[at], cells[targets[k++]]); });
      });
  return split;
}

// How to split a node; the sides' bounds when they are known without another pass.
struct Step {
  SplitPlane plane;
  std::optional<GridBounds> lower, upper;
};

class Splitter {
 public:
  Splitter(std::span<GridCell> cells, int maxSide)
      : cells_(cells),
        maxSide_(maxSide),
        maxAlignment_(std::bit_width(unsigned(maxSide)) - 1),
        depthLimit_(2 * int(std::bit_width(cells.size())) + 16) {}

  void split(std::size_t begin, std::size_t end, int depth, std::optional<GridBounds> known) {
    const std::span<GridCell> cells = cells_.subspan(begin, end - begin);
    const GridBounds b = known ? *known : boundsOf(cells);
    assert(!known || *known == boundsOf(cells));
    const std::optional<Step> step = chooseStep(cells, b, depth > depthLimit_);
    if (!step) {
      boxes_.push_back({b.lower, b.extent(), std::uint32_t(begin)});
      return;
    }
    const SplitPlane plane = step->plane;
    const std::size_t middle = begin + partitionCells(cells, [&](const GridCell& c) {
                                 return c.g[plane.axis] < plane.at;
                               });
    const auto lower = [&] { split(begin, middle, depth + 1, step->lower); };
    const auto upper = [&] { split(middle, end, depth + 1, step->upper); };
    if (cells.size() >= kParallelCells) {
      tbb::parallel_invoke(lower, upper);
    } else {
      lower();
      upper();
    }
  }

  std::vector<GridBox> boxes() const {
    std::vector<GridBox> out(boxes_.begin(), boxes_.end());
    tbb::parallel_sort(out.begin(), out.end(),
                       [](const GridBox& a, const GridBox& b) { return a.begin < b.begin; });
    return out;
  }

 private:
  // None when the cells fill their bounds and fit the side cap. Both sides of a step are
  // non-empty, because bounds are tight and planes lie strictly inside them.
  std::optional<Step> chooseStep(std::span<const GridCell> cells, const GridBounds& b,
                                 bool tooDeep) const {
    const glm::ivec3 e = b.extent();
    const int axis = longestAxis(e);
    if (cells.size() == volume(e)) {
      if (glm::all(glm::lessThanEqual(e, glm::ivec3(maxSide_)))) return std::nullopt;
      // Dense but too large: cut off multiples of the cap, so aligned blocks stay whole.
      const int pieces = (e[axis] + maxSide_ - 1) / maxSide_;
      const int at = b.lower[axis] + maxSide_ * std::max(1, pieces / 2);
      GridBounds lower = b, upper = b;
      lower.upper[axis] = at;
      upper.lower[axis] = at;
      return Step{{axis, at}, lower, upper};
    }
    // Past the depth limit only halving splits, which bound the remaining depth by the extent
    // bits and keep the build O(N log N) whatever the layout.
    if (tooDeep) return Step{{axis, b.lower[axis] + e[axis] / 2}, {}, {}};
    // Histograms cost O(extent); for sparse nodes sorting the coordinates is cheaper.
    if (U64(e.x) + U64(e.y) + U64(e.z) > 16 * U64(cells.size()) + 64)
      return Step{sparseGapPlane(cells, b, axis), {}, {}};
    const HistogramSplit split = histogramSplit(cells, b, maxAlignment_);
    return Step{split.plane, split.lower, split.upper};
  }

  // The empty slab along `axis` nearest the centre (ties: the lower one), found in O(cells):
  // the window of 2 * cells + 3 slabs around the centre must hold one, and lies strictly inside
  // the bounds because the extent exceeds 5 * cells here.
  static SplitPlane sparseGapPlane(std::span<const GridCell> cells, const GridBounds& b, int axis) {
    const int centre = b.lower[axis] + b.extent()[axis] / 2;
    const int radius = int(cells.size()) + 1;
    std::vector<char> occupied(2 * std::size_t(radius) + 1, 0);
    for (const GridCell& c : cells)
      if (const int d = c.g[axis] - centre; d >= -radius && d <= radius) occupied[d + radius] = 1;
    for (int step = 0; step <= radius; ++step)
      for (const int d : {-step, step})
        if (!occupied[d + radius]) return {axis, centre + d};
    assert(false && "a window of 2n+3 slabs holds an empty one");
    return {axis, centre};
  }

  std::span<GridCell> cells_;
  int maxSide_;
  int maxAlignment_;
  int depthLimit_;
  tbb::concurrent_vector<GridBox> boxes_;
};

}  // namespace

std::vector<GridBox> splitIntoBoxes(std::span<GridCell> cells, int maxSide) {
  if (cells.empty()) return {};
  Splitter splitter(cells, maxSide);
  splitter.split(0, cells.size(), 0, std::nullopt);
  return splitter.boxes();
}

}  // namespace amrstream::bricks::detail
