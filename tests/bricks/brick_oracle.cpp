#include <cstring>

#include "oracles.hpp"
#include "random_amr.hpp"

namespace amrstream::testing {

namespace {

template <typename T>
bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

}  // namespace

bricks::AmrField makeField(std::vector<glm::ivec3> lowers, std::vector<std::uint8_t> levels) {
  std::vector<float> ids(lowers.size());
  for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = float(i);
  return bricks::AmrField(std::move(lowers), std::move(levels), {{"id", std::move(ids)}}, {},
                          "test");
}

bricks::AmrField variedRandomLayout(std::uint64_t seed, int levels) {
  RandomAmrOptions options;
  options.levels = levels;
  options.rootCells = glm::ivec3(1 + seed % 3, 2 + seed % 2, 1 + seed % 4);
  options.origin = (1 << (levels - 1)) * glm::ivec3(int(seed % 5) - 2, -3, int(seed % 3));
  options.refineProbability = 0.3 + 0.05 * double(seed % 6);
  return randomAmr(seed, options);
}

bricks::AmrField levelJumpOfThree() {
  std::vector<glm::ivec3> lowers{{0, 0, 0}};
  std::vector<std::uint8_t> levels{3};
  for (int z = 0; z < 8; ++z)
    for (int y = 0; y < 8; ++y)
      for (int x = 8; x < 16; ++x) {
        lowers.push_back({x, y, z});
        levels.push_back(0);
      }
  return makeField(lowers, levels);
}

bricks::AmrField powersOfTwoAlongTheAxes() {
  std::vector<glm::ivec3> lowers{{0, 0, 0}};
  for (int k = 0; k <= 19; ++k)
    for (int axis = 0; axis < 3; ++axis) {
      glm::ivec3 p(0);
      p[axis] = 1 << k;
      lowers.push_back(p);
    }
  return makeField(lowers, std::vector<std::uint8_t>(lowers.size(), 0));
}

::testing::AssertionResult bricksAreValid(const bricks::AmrField& field,
                                          const bricks::BrickSet& set, int maxSide) {
  const std::size_t n = field.cellCount();
  if (set.cellIds.size() != n)
    return ::testing::AssertionFailure() << set.cellIds.size() << " slots for " << n << " cells";
  std::vector<char> seen(n, 0);
  std::size_t slots = 0;
  for (std::size_t b = 0; b < set.bricks.size(); ++b) {
    const shared::Brick& brick = set.bricks[b];
    const glm::ivec3 s = brick.size;
    if (glm::any(glm::lessThan(s, glm::ivec3(1))) ||
        glm::any(glm::greaterThan(s, glm::ivec3(maxSide))))
      return ::testing::AssertionFailure()
             << "brick " << b << " has size " << s.x << "x" << s.y << "x" << s.z;
    const int width = 1 << brick.level;
    const std::size_t volume = std::size_t(s.x) * s.y * s.z;
    if (brick.valueOffset + volume > n)
      return ::testing::AssertionFailure() << "brick " << b << " runs past the slots";
    slots += volume;
    for (int z = 0; z < s.z; ++z)
      for (int y = 0; y < s.y; ++y)
        for (int x = 0; x < s.x; ++x) {
          const std::size_t slot = brick.valueOffset + x + std::size_t(s.x) * (y + s.y * z);
          const std::uint32_t cell = set.cellIds[slot];
          if (cell >= n || seen[cell])
            return ::testing::AssertionFailure()
                   << "slot " << slot << " holds cell " << cell << ", out of range or seen";
          seen[cell] = 1;
          const glm::ivec3 expected = brick.lower + width * glm::ivec3(x, y, z);
          if (field.levels()[cell] != brick.level || field.lowers()[cell] != expected)
            return ::testing::AssertionFailure()
                   << "brick " << b << " slot " << slot << " holds cell " << cell
                   << " at the wrong position or level";
        }
  }
  if (slots != n) return ::testing::AssertionFailure() << slots << " slots for " << n << " cells";
  return ::testing::AssertionSuccess();
}

bool identical(const bricks::BrickSet& a, const bricks::BrickSet& b) {
  return sameBytes(a.bricks, b.bricks) && sameBytes(a.cellIds, b.cellIds);
}

bool identical(const bricks::RegionSet& a, const bricks::RegionSet& b) {
  return sameBytes(a.regions, b.regions) && sameBytes(a.regionBricks, b.regionBricks) &&
         sameBytes(a.tree, b.tree) && a.lower == b.lower && a.upper == b.upper;
}

}  // namespace amrstream::testing
