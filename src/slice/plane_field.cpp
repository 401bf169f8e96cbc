#include "plane_field.hpp"

#include <memory>

#include "flow/sampler.hpp"

namespace amrstream::slice {

PlaneVectorField exactInPlane(const flow::VectorVolume& volume, const SlicePlane& plane) {
  auto cache = std::make_shared<flow::RegionCache>();
  return [&volume, &plane, cache](glm::dvec2 at) -> std::optional<glm::dvec2> {
    const flow::CellPoint p = flow::wrapPeriodic(
        volume, flow::toCellPoint(volume.transform.toCellUnits(plane.physical(at))));
    const flow::VectorSample sample = flow::sampleVector(volume, p, cache.get());
    if (!sample.valid) return std::nullopt;
    const glm::dvec3 v(sample.value);
    return glm::dvec2(glm::dot(v, plane.u), glm::dot(v, plane.v));
  };
}

VectorImage inPlaneImage(const SlicePlane& plane, const flow::GridSamples& samples) {
  VectorImage image;
  image.width = plane.width;
  image.height = plane.height;
  image.valid = samples.valid;
  image.vectors.resize(samples.vectors.size());
  for (std::size_t n = 0; n < samples.vectors.size(); ++n) {
    const glm::dvec3 v(samples.vectors[n]);
    image.vectors[n] = glm::vec2(float(glm::dot(v, plane.u)), float(glm::dot(v, plane.v)));
  }
  return image;
}

}  // namespace amrstream::slice
