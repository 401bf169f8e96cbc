#include "amr_field.hpp"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>
#include <mutex>
#include <set>
#include <stdexcept>
#include <unordered_set>

#include "amrstream/closest_name.hpp"
#include "amrstream/error.hpp"
#include "level_corner_set.hpp"
#include "util/first_failing.hpp"
#include "util/stopwatch.hpp"

namespace amrstream::bricks {

namespace {

// Per level, aligned corners recently found absent from the level's set, in 16 slots (a 4 x 4
// patch of the level's cells in x and y): cells come in blocks, whose cells share their coarser
// cells' corners, so most probes repeat one made a few cells before.
class AbsentCorners {
 public:
  bool holds(std::size_t level, glm::ivec3 corner) const {
    const unsigned slot = slotOf(level, corner);
    return (known_[level] >> slot & 1u) != 0 && corners_[level][slot] == corner;
  }
  void add(std::size_t level, glm::ivec3 corner) {
    const unsigned slot = slotOf(level, corner);
    known_[level] |= std::uint16_t(1u << slot);
    corners_[level][slot] = corner;
  }

 private:
  static unsigned slotOf(std::size_t level, glm::ivec3 corner) {
    return unsigned((corner.x >> level) & 3) | unsigned((corner.y >> level) & 3) << 2;
  }
  std::array<std::array<glm::ivec3, 16>, kMaxLevel + 1> corners_;
  std::array<std::uint16_t, kMaxLevel + 1> known_{};
};

// Levels as the input numbers them.
std::string describeCell(std::size_t i, glm::ivec3 lower, int level, const DatasetInfo& info) {
  return fmt::format("cell {} (level {}, lower corner {},{},{})", i, info.fileLevel(level), lower.x,
                     lower.y, lower.z);
}

}  // namespace

AmrField::AmrField(std::vector<glm::ivec3> lowers, std::vector<std::uint8_t> levels,
                   std::vector<Channel> channels, WorldTransform transform, std::string source)
    : AmrField(std::move(lowers), std::move(levels), std::move(channels), transform,
               std::move(source), nullptr) {}

AmrField::AmrField(std::vector<glm::ivec3> lowers, std::vector<std::uint8_t> levels,
                   std::vector<Channel> channels, WorldTransform transform, std::string source,
                   const CheckedCells& checked)
    : AmrField(std::move(lowers), std::move(levels), std::move(channels), transform,
               std::move(source), &checked) {}

AmrField::AmrField(std::vector<glm::ivec3> lowers, std::vector<std::uint8_t> levels,
                   std::vector<Channel> channels, WorldTransform transform, std::string source,
                   const CheckedCells* checked)
    : lowers_(std::move(lowers)),
      levels_(std::move(levels)),
      channels_(std::move(channels)),
      transform_(transform),
      source_(std::move(source)) {
  info_.levelsCountDown = false;
  info_.levelName = "level (0 = finest)";
  validate(checked);
}

AmrField::AmrField(std::vector<glm::ivec3> lowers, std::vector<std::uint8_t> levels,
                   std::vector<Channel> channels, WorldTransform transform, std::string source,
                   DatasetInfo info)
    : lowers_(std::move(lowers)),
      levels_(std::move(levels)),
      channels_(std::move(channels)),
      transform_(transform),
      source_(std::move(source)),
      info_(std::move(info)) {
  validate();
}

std::optional<std::size_t> AmrField::findChannel(std::string_view name) const {
  for (std::size_t i = 0; i < channels_.size(); ++i)
    if (channels_[i].name == name) return i;
  return std::nullopt;
}

const Channel& AmrField::channel(std::string_view name) const {
  if (auto i = findChannel(name)) return channels_[*i];
  std::string names;
  std::vector<std::string> candidates;
  for (const Channel& c : channels_) {
    names += (names.empty() ? "" : ", ") + c.name;
    candidates.push_back(c.name);
  }
  throw InputError(source_,
                   fmt::format("no channel named '{}'{}; the channels are: {}", name,
                               didYouMean(name, candidates), names.empty() ? "none" : names));
}

std::vector<std::size_t> AmrField::cellsPerLevel() const {
  using Counts = std::array<std::size_t, kMaxLevel + 1>;
  const Counts all = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, levels_.size()), Counts{},
      [&](const tbb::blocked_range<std::size_t>& range, Counts counts) {
        for (std::size_t i = range.begin(); i != range.end(); ++i) ++counts[levels_[i]];
        return counts;
      },
      [](Counts a, const Counts& b) {
        for (std::size_t level = 0; level < a.size(); ++level) a[level] += b[level];
        return a;
      });
  return std::vector<std::size_t>(all.begin(), all.begin() + coarsestLevel() + 1);
}

// Physical positions and widths are written as float32: the transform must map the cells into
// float's normal range, or positions become inf or collapse to zero.
void AmrField::validateTransform() const {
  const WorldTransform& t = transform_;
  const double smallest = std::numeric_limits<float>::min(), largest = 1e37;
  for (int a = 0; a < 3; ++a) {
    if (!std::isfinite(t.origin[a]))
      throw InputError(source_,
                       fmt::format("the origin's {} coordinate is {}", "xyz"[a], t.origin[a]));
    if (!(t.spacing[a] >= smallest && t.spacing[a] <= largest))
      throw InputError(source_,
                       fmt::format("the finest cell width along {} is {:g}; it must lie in "
                                   "[{:g}, {:g}] (float32 positions)",
                                   "xyz"[a], t.spacing[a], smallest, largest));
    for (int corner : {bounds_.lower[a], bounds_.upper[a]}) {
      const double p = t.origin[a] + t.spacing[a] * double(corner);
      if (!(std::abs(p) <= largest))
        throw InputError(source_, fmt::format("the domain reaches {:g} along {}, beyond the "
                                              "float32 range of the outputs (|x| <= {:g})",
                                              p, "xyz"[a], largest));
    }
  }
}

void AmrField::addChannel(Channel channel) {
  checkChannelShape(channel);
  if (findChannel(channel.name))
    throw InputError(source_, fmt::format("channel '{}' appears twice", channel.name));
  checkChannelValues(channel);
  channels_.push_back(std::move(channel));
}

void AmrField::checkChannelShape(const Channel& c) const {
  if (c.name.empty()) throw InputError(source_, "a channel has an empty name");
  if (c.values.size() != lowers_.size())
    throw InputError(source_, fmt::format("channel '{}' has {} values for {} cells", c.name,
                                          c.values.size(), lowers_.size()));
}

void AmrField::checkChannelValues(const Channel& c) const {
  const auto notFinite = [&](std::size_t i) { return !std::isfinite(c.values[i]); };
  if (std::size_t i = firstFailing(c.values.size(), notFinite); i < c.values.size())
    throw InputError(
        source_, fmt::format("channel '{}' has a non-finite value ({}) at {}", c.name, c.values[i],
                             describeCell(i, lowers_[i], levels_[i], info_)));
}

// The box of each level's corners; a level without cells has lower > upper.
struct AmrField::LevelBoxes {
  std::array<glm::ivec3, kMaxLevel + 1> lower, upper;
};

void AmrField::validate(const CheckedCells* checked) {
  Stopwatch clock;
  checkCellCounts();
  checkCellLevels();
  for (const Channel& c : channels_) checkChannelValues(c);

  const LevelBoxes boxes = levelBoxes();
  bounds_ = checkedBounds(boxes);
  for (int level = kMaxLevel; level >= 0; --level)
    if (boxes.lower[level].x <= boxes.upper[level].x) finest_ = level;
  for (int level = 0; level <= kMaxLevel; ++level)
    if (boxes.lower[level].x <= boxes.upper[level].x) coarsest_ = level;
  validateTransform();

  if (checked) {
    if (lowers_ != checked->lowers || levels_ != checked->levels)
      throw InputError(source_, "its cells differ from those of a first read (did it change?)");
    checkSeconds_.cells = clock.seconds();
    return;
  }
  checkSeconds_.cells = clock.seconds();
  clock.restart();
  checkOverlaps(boxes);
  checkSeconds_.overlaps = clock.seconds();
}

void AmrField::checkCellCounts() const {
  const std::size_t n = lowers_.size();
  if (n == 0) throw InputError(source_, "the dataset has no cells");
  if (levels_.size() != n)
    throw InputError(source_, fmt::format("{} cell corners but {} cell levels", n, levels_.size()));

  std::set<std::string, std::less<>> names;
  for (const Channel& c : channels_) {
    checkChannelShape(c);
    if (!names.insert(c.name).second)
      throw InputError(source_, fmt::format("channel '{}' appears twice", c.name));
  }
}

void AmrField::checkCellLevels() const {
  const std::size_t n = lowers_.size();
  if (std::size_t i = firstFailing(n, [&](std::size_t i) { return levels_[i] > kMaxLevel; }); i < n)
    throw InputError(source_,
                     fmt::format("{} has a level above the supported maximum {}",
                                 describeCell(i, lowers_[i], levels_[i], info_), kMaxLevel));
  const auto misaligned = [&](std::size_t i) {
    const int mask = cellWidth(levels_[i]) - 1;
    return (lowers_[i].x & mask) | (lowers_[i].y & mask) | (lowers_[i].z & mask);
  };
  if (std::size_t i = firstFailing(n, misaligned); i < n)
    throw InputError(source_, fmt::format("{} is not aligned to its level's grid (corner "
                                          "coordinates must be multiples of {})",
                                          describeCell(i, lowers_[i], levels_[i], info_),
                                          cellWidth(levels_[i])));
}

// The box of each level's corners, in one pass.
AmrField::LevelBoxes AmrField::levelBoxes() const {
  LevelBoxes empty;
  empty.lower.fill(glm::ivec3(std::numeric_limits<int>::max()));
  empty.upper.fill(glm::ivec3(std::numeric_limits<int>::min()));
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, lowers_.size()), empty,
      [&](const tbb::blocked_range<std::size_t>& range, LevelBoxes b) {
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
          b.lower[levels_[i]] = glm::min(b.lower[levels_[i]], lowers_[i]);
          b.upper[levels_[i]] = glm::max(b.upper[levels_[i]], lowers_[i]);
        }
        return b;
      },
      [](LevelBoxes a, const LevelBoxes& b) {
        for (int level = 0; level <= kMaxLevel; ++level) {
          a.lower[level] = glm::min(a.lower[level], b.lower[level]);
          a.upper[level] = glm::max(a.upper[level], b.upper[level]);
        }
        return a;
      });
}

// The box of all cells, from the levels' boxes, in 64 bits: a corner near INT_MAX plus its width,
// or INT_MIN..INT_MAX, overflows int.
CellBox AmrField::checkedBounds(const LevelBoxes& boxes) const {
  const auto& levelLower = boxes.lower;
  const auto& levelUpper = boxes.upper;
  glm::i64vec3 lower(std::numeric_limits<std::int64_t>::max());
  glm::i64vec3 upper(std::numeric_limits<std::int64_t>::min());
  for (int level = 0; level <= kMaxLevel; ++level) {
    if (levelLower[level].x > levelUpper[level].x) continue;  // no cells at this level
    lower = glm::min(lower, glm::i64vec3(levelLower[level]));
    upper = glm::max(upper, glm::i64vec3(levelUpper[level]) + std::int64_t(cellWidth(level)));
  }
  const glm::i64vec3 extent = upper - lower;
  const std::int64_t maxExtent = std::int64_t(1) << kMaxExtentBits;
  if (glm::any(glm::greaterThan(extent, glm::i64vec3(maxExtent))))
    throw InputError(source_, fmt::format("the cells span {}x{}x{} finest cells; at most {} per "
                                          "axis are supported",
                                          extent.x, extent.y, extent.z, maxExtent));
  if (glm::any(glm::greaterThan(upper, glm::i64vec3(std::numeric_limits<int>::max()))))
    throw InputError(source_,
                     fmt::format("the cells reach {},{},{}, beyond the largest "
                                 "supported corner coordinate {}",
                                 upper.x, upper.y, upper.z, std::numeric_limits<int>::max()));
  return CellBox{glm::ivec3(lower), glm::ivec3(upper)};
}

// Per level, the runs of consecutive cells in one tile: at least as many as the tiles occupied.
std::array<std::size_t, kMaxLevel + 1> AmrField::tileRuns(
    const std::vector<LevelTiling>& tilings) const {
  using Counts = std::array<std::size_t, kMaxLevel + 1>;
  const auto tileOf = [&](std::size_t i) -> std::uint64_t {
    const LevelTiling& tiling = tilings[levels_[i]];
    return tiling.tiled() ? tiling.key(lowers_[i]) : i;
  };
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, lowers_.size()), Counts{},
      [&](const tbb::blocked_range<std::size_t>& range, Counts counts) {
        std::size_t level = range.begin() > 0 ? levels_[range.begin() - 1] : kMaxLevel + 1;
        std::uint64_t tile = range.begin() > 0 ? tileOf(range.begin() - 1) : 0;
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
          const std::uint64_t next = tileOf(i);
          if (levels_[i] != level || next != tile) ++counts[levels_[i]];
          level = levels_[i];
          tile = next;
        }
        return counts;
      },
      [](Counts a, const Counts& b) {
        for (std::size_t level = 0; level < a.size(); ++level) a[level] += b[level];
        return a;
      });
}

// Overlaps: one set of cell corners per level, in tiles of 4 x 4 x 4 cells. A duplicate fails
// the insertion; a cell inside a coarser one finds that cell's aligned corner in the coarser
// level's set.
void AmrField::checkOverlaps(const LevelBoxes& boxes) const {
  const std::size_t n = lowers_.size();
  const std::size_t levels = std::size_t(coarsest_) + 1;
  std::vector<LevelTiling> tilings;
  for (std::size_t level = 0; level < levels; ++level)
    tilings.emplace_back(int(level), boxes.lower[level], boxes.upper[level]);
  const std::array<std::size_t, kMaxLevel + 1> runs = tileRuns(tilings);
  std::vector<std::unique_ptr<LevelCornerSet>> sets(levels);
  const auto makeSets = [&] {  // empty, the old ones freed first (they are large)
    for (std::size_t level = 0; level < levels; ++level) {
      sets[level].reset();
      if (boxes.lower[level].x <= boxes.upper[level].x)
        sets[level] = std::make_unique<LevelCornerSet>(tilings[level], runs[level]);
    }
  };
  makeSets();

  // The sets are far larger than the caches: each new tile's slot is fetched some cells ahead.
  constexpr std::size_t kAhead = 16;
  const auto prefetchAhead = [&](std::size_t i, std::array<std::uint64_t, kMaxLevel + 1>& last) {
    if (i + kAhead < n) {
      const int ahead = levels_[i + kAhead];
      sets[ahead]->prefetch(lowers_[i + kAhead], last[ahead]);
    }
  };
  // Each thread sets a tile's cells it meets in a row with one atomic or. Only when a cell came
  // twice are the sets filled again cell by cell, to name the first of them in input order.
  std::atomic<bool> twice = false;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const auto& range) {
    std::array<TileRun, kMaxLevel + 1> tileRuns{};
    std::array<std::uint64_t, kMaxLevel + 1> fetched{};
    bool fresh = true;
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      prefetchAhead(i, fetched);
      fresh = sets[levels_[i]]->add(lowers_[i], tileRuns[levels_[i]]) && fresh;
    }
    for (std::size_t level = 0; level < levels; ++level)
      if (sets[level]) fresh = sets[level]->flush(tileRuns[level]) && fresh;
    if (!fresh) twice = true;
  });
  if (twice) {
    makeSets();
    struct Inserting {
      std::array<TileHint, kMaxLevel + 1> hints;
      std::array<std::uint64_t, kMaxLevel + 1> fetched{};
    };
    const auto duplicated = [&](Inserting& state, std::size_t i) {
      prefetchAhead(i, state.fetched);
      return !sets[levels_[i]]->insert(lowers_[i], state.hints[levels_[i]]);
    };
    if (std::size_t i = firstFailingWith<Inserting>(n, duplicated); i < n)
      throw InputError(
          source_, fmt::format("{} appears twice", describeCell(i, lowers_[i], levels_[i], info_)));
    throw std::logic_error("checkOverlaps: a cell came twice, then not");
  }

  // A coarser level where a cell's aligned corner is the previous cell's needs no look when the
  // previous cell is no coarser: were that corner a coarser cell's, the previous cell would fail
  // first. Consecutive cells of a block then look only at the levels below which they differ.
  const auto lookedUpLevelsEnd = [&](std::size_t i) {
    std::size_t end = sets.size();
    if (i > 0 && levels_[i - 1] <= levels_[i]) {
      const glm::ivec3 d = lowers_[i] ^ lowers_[i - 1];
      end = std::min(end, std::size_t(std::bit_width(unsigned(d.x | d.y | d.z))));
    }
    return end;
  };
  const auto insideCoarser = [&](AbsentCorners& absent, std::size_t i) -> int {
    const std::size_t end = lookedUpLevelsEnd(i);
    for (std::size_t level = levels_[i] + 1; level < end; ++level) {
      if (!sets[level]) continue;
      const int mask = ~(cellWidth(int(level)) - 1);
      // Corners of coarser cells are aligned in absolute coordinates, so align before shifting.
      const glm::ivec3 aligned =
          glm::ivec3(lowers_[i].x & mask, lowers_[i].y & mask, lowers_[i].z & mask);
      if (absent.holds(level, aligned)) continue;
      if (sets[level]->contains(aligned)) return int(level);
      absent.add(level, aligned);
    }
    return -1;
  };
  // The lookups are few (most cells share their coarser corners with the cell before), so they
  // are not prefetched: computing the corners of a cell ahead cost more than it saved.
  if (std::size_t i = firstFailingWith<AbsentCorners>(
          n, [&](AbsentCorners& absent, std::size_t i) { return insideCoarser(absent, i) >= 0; });
      i < n) {
    AbsentCorners none;
    const int level = insideCoarser(none, i);
    const int mask = ~(cellWidth(level) - 1);
    throw InputError(
        source_, fmt::format("{} overlaps the level-{} cell at {},{},{}",
                             describeCell(i, lowers_[i], levels_[i], info_), info_.fileLevel(level),
                             lowers_[i].x & mask, lowers_[i].y & mask, lowers_[i].z & mask));
  }
}

}  // namespace amrstream::bricks
