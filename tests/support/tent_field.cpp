#include "tent_field.hpp"

#include <algorithm>
#include <cmath>

namespace amrstream::testing {

std::size_t TentField::CellKeyHash::operator()(const glm::i64vec3& k) const {
  std::size_t h = 0;
  for (int a = 0; a < 3; ++a)
    h = (h ^ std::hash<std::int64_t>()(k[a])) * 0x9e3779b97f4a7c15ull + (h >> 17);
  return h;
}

TentField::TentField(const bricks::AmrField& field, const std::array<std::string, 3>& channels)
    : values_(field.cellCount()), lower_(field.bounds().lower), upper_(field.bounds().upper) {
  for (int c = 0; c < 3; ++c) {
    const std::vector<float>& values = field.channel(channels[c]).values;
    for (std::size_t i = 0; i < values.size(); ++i) values_[i][c] = values[i];
  }
  const std::vector<std::size_t> perLevel = field.cellsPerLevel();
  levels_.resize(perLevel.size());
  for (std::size_t level = 0; level < perLevel.size(); ++level)
    levels_[level].reserve(perLevel[level]);
  for (std::size_t i = 0; i < field.cellCount(); ++i) {
    const int level = field.levels()[i];
    levels_[level].emplace(glm::i64vec3(field.lowers()[i]) / (std::int64_t(1) << level), i);
  }
}

TentSample TentField::sample(glm::dvec3 p) const {
  if (!glm::all(glm::greaterThanEqual(p, lower_)) || !glm::all(glm::lessThan(p, upper_))) return {};
  double weightSum = 0.0;
  glm::dvec3 weighted(0.0);
  for (std::size_t level = 0; level < levels_.size(); ++level) {
    if (levels_[level].empty()) continue;
    const double width = std::ldexp(1.0, int(level));
    const glm::i64vec3 base(glm::floor(p / width - 0.5));
    for (int corner = 0; corner < 8; ++corner) {
      const glm::i64vec3 index = base + glm::i64vec3(corner & 1, (corner >> 1) & 1, corner >> 2);
      const auto cell = levels_[level].find(index);
      if (cell == levels_[level].end()) continue;
      const glm::dvec3 centre = (glm::dvec3(index) + 0.5) * width;
      double weight = 1.0;
      for (int a = 0; a < 3; ++a) weight *= std::max(0.0, 1.0 - std::abs(centre[a] - p[a]) / width);
      weightSum += weight;
      weighted += weight * values_[cell->second];
    }
  }
  if (!(weightSum > 1e-20)) return {TentSample::Status::Invalid};
  return {TentSample::Status::Valid, weighted / weightSum};
}

int TentField::levelAt(glm::dvec3 p) const {
  for (std::size_t level = 0; level < levels_.size(); ++level)
    if (levels_[level].contains(glm::i64vec3(glm::floor(p / std::ldexp(1.0, int(level))))))
      return int(level);
  return -1;
}

}  // namespace amrstream::testing
