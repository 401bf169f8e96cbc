#include "frame_velocity.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "amrstream/error.hpp"
#include "cell_at.hpp"

namespace amrstream::flow {

namespace {

struct WeightedSum {
  glm::dvec3 sum{0.0};
  double weight = 0.0;

  void add(glm::vec3 value, double w) {
    sum += w * glm::dvec3(value);
    weight += w;
  }
};

// The measure of the cell [lower, lower + width) inside the box: the overlap's length along the
// box's thick axes, times whether the cell holds the box along its thin ones.
double measureInside(glm::dvec3 lower, double width, const FrameRegion::Box& box) {
  double measure = 1.0;
  for (int a = 0; a < 3; ++a) {
    const double upper = lower[a] + width;
    if (box.upper[a] > box.lower[a])
      measure *= std::max(0.0, std::min(upper, box.upper[a]) - std::max(lower[a], box.lower[a]));
    else if (!(box.lower[a] >= lower[a] && box.lower[a] < upper))
      return 0.0;
  }
  return measure;
}

WeightedSum sumInBrick(const VectorVolume& volume, const shared::Brick& brick,
                       const FrameRegion::Box& box) {
  WeightedSum brickSum;
  const double width = double(1 << brick.level);
  for (int z = 0; z < brick.size.z; ++z)
    for (int y = 0; y < brick.size.y; ++y)
      for (int x = 0; x < brick.size.x; ++x) {
        const glm::dvec3 lower = glm::dvec3(brick.lower) + glm::dvec3(x, y, z) * width;
        const double w = measureInside(lower, width, box);
        if (w > 0.0)
          brickSum.add(volume.values[brick.valueOffset +
                                     std::uint32_t(x + brick.size.x * (y + brick.size.y * z))],
                       w);
      }
  return brickSum;
}

WeightedSum sumInBox(const VectorVolume& volume, const FrameRegion::Box& box) {
  std::vector<WeightedSum> perBrick(volume.originalBrickCount);
  tbb::parallel_for(std::size_t(0), perBrick.size(), [&](std::size_t b) {
    perBrick[b] = sumInBrick(volume, volume.bricks[b], box);
  });
  WeightedSum total;
  for (const WeightedSum& s : perBrick) {
    total.sum += s.sum;
    total.weight += s.weight;
  }
  return total;
}

WeightedSum sumInCellsOf(const VectorVolume& volume, const std::vector<glm::dvec3>& points) {
  std::vector<CellAt> cells;
  for (const glm::dvec3& p : points)
    if (const std::optional<CellAt> cell = cellAt(volume, p)) cells.push_back(*cell);
  std::sort(cells.begin(), cells.end(),
            [](const CellAt& a, const CellAt& b) { return a.slot < b.slot; });
  cells.erase(std::unique(cells.begin(), cells.end(),
                          [](const CellAt& a, const CellAt& b) { return a.slot == b.slot; }),
              cells.end());
  WeightedSum total;
  for (const CellAt& cell : cells)
    total.add(volume.values[cell.slot], cell.width * cell.width * cell.width);
  return total;
}

}  // namespace

glm::dvec3 meanVector(const VectorVolume& volume, const FrameRegion& region) {
  const WeightedSum total =
      region.box ? sumInBox(volume, *region.box) : sumInCellsOf(volume, region.points);
  if (!(total.weight > 0.0))
    throw settingError("frame_velocity",
                       "auto takes the mean of the vector over the seeding region, which holds "
                       "no cell here: give the frame's velocity as VX,VY,VZ");
  return total.sum / total.weight;
}

void subtractFrameVelocity(VectorVolume& volume, glm::dvec3 frame) {
  if (frame == glm::dvec3(0.0)) return;
  tbb::parallel_for(std::size_t(0), volume.values.size(), [&](std::size_t slot) {
    volume.values[slot] = glm::vec3(glm::dvec3(volume.values[slot]) - frame);
  });
}

}  // namespace amrstream::flow
