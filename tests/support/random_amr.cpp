#include "random_amr.hpp"

#include <random>
#include <vector>

namespace amrstream::testing {

namespace {

struct Layout {
  std::vector<glm::ivec3> lowers;
  std::vector<std::uint8_t> levels;
};

void refine(glm::ivec3 lower, int level, double probability, std::mt19937_64& rng, Layout& out) {
  std::uniform_real_distribution<double> coin(0.0, 1.0);
  if (level > 0 && coin(rng) < probability) {
    const int half = 1 << (level - 1);
    for (int i = 0; i < 8; ++i) {
      const glm::ivec3 child = lower + half * glm::ivec3(i & 1, (i >> 1) & 1, (i >> 2) & 1);
      refine(child, level - 1, probability, rng, out);
    }
    return;
  }
  out.lowers.push_back(lower);
  out.levels.push_back(static_cast<std::uint8_t>(level));
}

}  // namespace

bricks::AmrField randomAmr(std::uint64_t seed, const RandomAmrOptions& options,
                           const VectorFunction& field) {
  std::mt19937_64 rng(seed);
  Layout layout;
  const int top = options.levels - 1;
  const int width = 1 << top;
  for (int z = 0; z < options.rootCells.z; ++z)
    for (int y = 0; y < options.rootCells.y; ++y)
      for (int x = 0; x < options.rootCells.x; ++x)
        refine(options.origin + width * glm::ivec3(x, y, z), top, options.refineProbability, rng,
               layout);

  std::vector<Channel> channels{{"vx", {}}, {"vy", {}}, {"vz", {}}};
  std::uniform_real_distribution<float> value(-1.0f, 1.0f);
  for (std::size_t i = 0; i < layout.lowers.size(); ++i) {
    const double w = double(1 << layout.levels[i]);
    const glm::vec3 v = field ? field(glm::dvec3(layout.lowers[i]) + 0.5 * w)
                              : glm::vec3(value(rng), value(rng), value(rng));
    for (int c = 0; c < 3; ++c) channels[c].values.push_back(v[c]);
  }
  return bricks::AmrField(std::move(layout.lowers), std::move(layout.levels), std::move(channels),
                          {}, "random-amr(seed " + std::to_string(seed) + ")");
}

}  // namespace amrstream::testing
