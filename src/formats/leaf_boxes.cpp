#include "formats/leaf_boxes.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <unordered_map>

#include "amrstream/error.hpp"

namespace amrstream::formats {

namespace {

glm::ivec3 inCube(int index, int side) {
  return {index % side, index / side % side, index / side / side};
}

// Whether the cells come cube after cube already, x fastest within a cube (as the generators
// emit their blocks).
bool inCubeOrder(std::span<const glm::ivec3> lowers, std::span<const std::uint8_t> levels,
                 int side) {
  const std::size_t perCube = std::size_t(side) * side * side;
  if (lowers.size() % perCube != 0) return false;
  bool ordered = true;
  tbb::parallel_for(std::size_t(0), lowers.size() / perCube, [&](std::size_t c) {
    const std::size_t first = c * perCube;
    const int width = 1 << levels[first];
    if (glm::any(glm::notEqual(lowers[first] % (side * width), glm::ivec3(0)))) ordered = false;
    for (std::size_t i = 1; i < perCube && ordered; ++i)
      if (levels[first + i] != levels[first] ||
          lowers[first + i] != lowers[first] + inCube(int(i), side) * width)
        ordered = false;
  });
  return ordered;
}

// A cube's key: level and position in cubes of that level (each below 2^19: the cells' extent).
std::uint64_t cubeKey(glm::ivec3 lower, int level, int side) {
  const glm::ivec3 at = lower / (side << level);
  return (std::uint64_t(level) << 57) | (std::uint64_t(at.z) << 38) | (std::uint64_t(at.y) << 19) |
         std::uint64_t(at.x);
}

}  // namespace

LeafBoxes::LeafBoxes(const bricks::AmrField& field, int maxCubes) {
  findCubes(field);
  mergeCubes(maxCubes);
}

void LeafBoxes::findCubes(const bricks::AmrField& field) {
  const auto lowers = field.lowers();
  const auto levels = field.levels();
  for (side_ = 8; side_ > 1; side_ /= 2) {
    if (inCubeOrder(lowers, levels, side_)) break;
    // Cells in any order: sorted by cube and position in it, then each cube must be whole.
    std::vector<std::size_t> order(lowers.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    const auto key = [&](std::size_t i) {
      const int width = 1 << levels[i];
      const glm::ivec3 in = lowers[i] / width % side_;
      return std::pair(cubeKey(lowers[i], levels[i], side_), (in.z * side_ + in.y) * side_ + in.x);
    };
    tbb::parallel_sort(order.begin(), order.end(),
                       [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
    const std::size_t perCube = std::size_t(side_) * side_ * side_;
    bool whole = order.size() % perCube == 0;
    for (std::size_t c = 0; whole && c < order.size() / perCube; ++c)
      for (std::size_t i = 0; i < perCube && whole; ++i)
        whole = key(order[c * perCube + i]) == std::pair(key(order[c * perCube]).first, int(i));
    if (whole) {
      order_ = std::move(order);
      break;
    }
  }
  const std::size_t perCube = std::size_t(side_) * side_ * side_;
  for (std::size_t first = 0; first < lowers.size(); first += perCube) {
    const std::size_t cell = order_.empty() ? first : order_[first];
    cubes_.push_back({lowers[cell] / (side_ << levels[cell]), levels[cell], first});
  }
}

void LeafBoxes::mergeCubes(int maxCubes) {
  std::unordered_map<std::uint64_t, std::size_t> byKey;  // unmerged cubes
  std::vector<std::size_t> sorted(cubes_.size());
  std::iota(sorted.begin(), sorted.end(), std::size_t(0));
  const auto key = [&](glm::ivec3 at, int level) {
    return cubeKey(at * (side_ << level), level, side_);
  };
  for (std::size_t c = 0; c < cubes_.size(); ++c)
    byKey.emplace(key(cubes_[c].at, cubes_[c].level), c);
  std::sort(sorted.begin(), sorted.end(), [&](std::size_t a, std::size_t b) {
    return key(cubes_[a].at, cubes_[a].level) < key(cubes_[b].at, cubes_[b].level);
  });
  const auto unmerged = [&](glm::ivec3 at, int level) { return byKey.contains(key(at, level)); };
  // Whether the cubes [lo, hi] of a level are all there and unmerged.
  const auto allFree = [&](glm::ivec3 lo, glm::ivec3 hi, int level) {
    for (int z = lo.z; z <= hi.z; ++z)
      for (int y = lo.y; y <= hi.y; ++y)
        for (int x = lo.x; x <= hi.x; ++x)
          if (!unmerged({x, y, z}, level)) return false;
    return true;
  };
  for (std::size_t c : sorted) {
    const Cube& cube = cubes_[c];
    if (!unmerged(cube.at, cube.level)) continue;
    glm::ivec3 hi = cube.at;
    for (int a = 0; a < 3; ++a)
      while (hi[a] - cube.at[a] + 1 < maxCubes) {
        glm::ivec3 lo = cube.at, next = hi;
        lo[a] = next[a] = hi[a] + 1;
        if (!allFree(lo, next, cube.level)) break;
        hi[a] += 1;
      }
    std::vector<std::size_t> members;
    for (int z = cube.at.z; z <= hi.z; ++z)
      for (int y = cube.at.y; y <= hi.y; ++y)
        for (int x = cube.at.x; x <= hi.x; ++x) {
          const auto it = byKey.find(key({x, y, z}, cube.level));
          members.push_back(it->second);
          byKey.erase(it);
        }
    const int span = side_ << cube.level;
    boxes_.push_back({cube.at * span, cube.level, (hi - cube.at + 1) * side_});
    boxCubes_.push_back(std::move(members));
  }
}

void LeafBoxes::gather(std::size_t b, std::span<const float> channel, float* into) const {
  const glm::ivec3 n = boxes_[b].cells;
  const glm::ivec3 cubes = n / side_;
  std::size_t at = 0;
  for (int k = 0; k < n.z; ++k)
    for (int j = 0; j < n.y; ++j)
      for (int i = 0; i < n.x; ++i, ++at) {
        const Cube& cube =
            cubes_[boxCubes_[b]
                            [(std::size_t(k / side_) * cubes.y + j / side_) * cubes.x + i / side_]];
        const std::size_t inside = (std::size_t(k % side_) * side_ + j % side_) * side_ + i % side_;
        into[at] = channel[cellOf(cube, inside)];
      }
}

}  // namespace amrstream::formats
