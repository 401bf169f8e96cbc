#include "cell_gradients.hpp"

#include <tbb/parallel_for.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>

#include "cell_at.hpp"

namespace amrstream::flow {

namespace {

struct Neighbour {
  std::uint32_t slot;
  glm::dvec3 offset;  // its centre minus the cell's centre, finest cells
};

glm::dvec3 cellCentre(const shared::Brick& brick, glm::ivec3 cell) {
  const double width = double(1 << brick.level);
  return glm::dvec3(brick.lower) + (glm::dvec3(cell) + 0.5) * width;
}

// The face neighbours of one cell: up to six, fewer at non-periodic domain faces.
std::array<std::optional<Neighbour>, 6> faceNeighbours(const VectorVolume& volume,
                                                       const shared::Brick& brick,
                                                       glm::ivec3 cell) {
  std::array<std::optional<Neighbour>, 6> result;
  const double width = double(1 << brick.level);
  const glm::dvec3 centre = cellCentre(brick, cell);
  const glm::dvec3 lower(volume.domain.lower), upper(volume.domain.upper);
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      const int step = side == 0 ? -1 : 1;
      glm::ivec3 next = cell;
      next[axis] += step;
      if (next[axis] >= 0 && next[axis] < brick.size[axis]) {
        glm::dvec3 offset(0.0);
        offset[axis] = step * width;
        result[2 * axis + side] =
            Neighbour{brick.valueOffset +
                          std::uint32_t(next.x + brick.size.x * (next.y + brick.size.y * next.z)),
                      offset};
        continue;
      }
      glm::dvec3 q = centre;
      q[axis] += step * width;
      glm::dvec3 shift(0.0);  // q - (q wrapped into the domain)
      if (q[axis] < lower[axis] || q[axis] >= upper[axis]) {
        if (!volume.periodic[axis]) continue;
        shift[axis] = (q[axis] < lower[axis] ? -1.0 : 1.0) * (upper[axis] - lower[axis]);
      }
      const std::optional<CellAt> found = cellAt(volume, q - shift);
      if (!found) continue;
      result[2 * axis + side] = Neighbour{found->slot, found->centre + shift - centre};
    }
  }
  return result;
}

// Solves A g = b for the symmetric 3x3 A; where the neighbours span fewer than three axes (a
// domain one cell thick), the missing directions get no gradient.
glm::dvec3 solve(const glm::dmat3& a, const glm::dvec3& b) {
  const double det = glm::determinant(a);
  const double scale = a[0][0] + a[1][1] + a[2][2];
  if (std::abs(det) > 1e-9 * scale * scale * scale) return glm::inverse(a) * b;
  glm::dmat3 damped = a;
  for (int d = 0; d < 3; ++d) damped[d][d] += 1e-6 * scale + (a[d][d] == 0.0 ? 1.0 : 0.0);
  return glm::inverse(damped) * b;
}

}  // namespace

std::vector<glm::vec3> cellGradients(const VectorVolume& volume, std::span<const float> values,
                                     std::size_t components) {
  std::vector<glm::vec3> gradients(volume.cellIds.size() * components, glm::vec3(0.0f));
  if (components == 0) return gradients;
  tbb::parallel_for(std::size_t(0), volume.originalBrickCount, [&](std::size_t b) {
    const shared::Brick& brick = volume.bricks[b];
    std::vector<glm::dvec3> rhs(components);
    for (int z = 0; z < brick.size.z; ++z)
      for (int y = 0; y < brick.size.y; ++y)
        for (int x = 0; x < brick.size.x; ++x) {
          const glm::ivec3 cell(x, y, z);
          const std::uint32_t slot =
              brick.valueOffset + std::uint32_t(x + brick.size.x * (y + brick.size.y * z));
          glm::dmat3 normal(0.0);
          std::fill(rhs.begin(), rhs.end(), glm::dvec3(0.0));
          for (const std::optional<Neighbour>& n : faceNeighbours(volume, brick, cell)) {
            if (!n) continue;
            normal += glm::outerProduct(n->offset, n->offset);
            for (std::size_t c = 0; c < components; ++c)
              rhs[c] += n->offset * (double(values[n->slot * components + c]) -
                                     double(values[slot * components + c]));
          }
          for (std::size_t c = 0; c < components; ++c)
            gradients[slot * components + c] = glm::vec3(solve(normal, rhs[c]));
        }
  });
  return gradients;
}

}  // namespace amrstream::flow
