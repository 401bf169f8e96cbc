#include "gradient_vector.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <cmath>

#include "amrstream/error.hpp"
#include "cell_gradients.hpp"
#include "util/first_failing.hpp"
#include "value_range.hpp"

namespace amrstream::flow {

std::vector<glm::vec3> physicalGradients(const VectorVolume& volume, std::span<const float> scalars,
                                         float sign, const std::string& source,
                                         const std::string& scalar) {
  std::vector<glm::vec3> gradients = cellGradients(volume, scalars, 1);  // per finest cell
  const glm::dvec3 perLength = double(sign) / volume.transform.spacing;
  tbb::parallel_for(std::size_t(0), gradients.size(), [&](std::size_t slot) {
    gradients[slot] = glm::vec3(glm::dvec3(gradients[slot]) * perLength);
  });
  const std::size_t bad = firstFailing(gradients.size(), [&](std::size_t slot) {
    const glm::vec3 g = glm::abs(gradients[slot]);
    return !(g.x <= kMaxVectorComponent && g.y <= kMaxVectorComponent &&
             g.z <= kMaxVectorComponent);
  });
  if (bad < gradients.size()) {
    const glm::vec3 g = gradients[bad];
    throw InputError(source,
                     fmt::format("the gradient of '{}' is ({:g}, {:g}, {:g}) at cell {}; "
                                 "amrstream's float32 arithmetic needs |components| <= "
                                 "{:g}: rescale the field",
                                 scalar, g.x, g.y, g.z, volume.cellIds[bad], kMaxVectorComponent));
  }
  return gradients;
}

}  // namespace amrstream::flow
