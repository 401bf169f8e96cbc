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

shared::ProbeGrid pixelGrid(const flow::VectorVolume& volume, const SlicePlane& plane) {
  const flow::AffineGrid grid = plane.grid();
  const glm::dvec3 origin = volume.transform.toCellUnits(grid.origin);
  const glm::dvec3 whole = glm::floor(origin);
  shared::ProbeGrid g{};
  g.originAnchor = glm::ivec3(whole);
  g.originOffset = glm::vec3(origin - whole);
  g.stepX = glm::vec3(volume.transform.toCellUnits(grid.origin + grid.steps[0]) - origin);
  g.stepY = glm::vec3(volume.transform.toCellUnits(grid.origin + grid.steps[1]) - origin);
  g.width = grid.dims[0];
  g.height = grid.dims[1];
  return g;
}

flow::GridSamples samplePixels(const flow::VectorVolume& volume, const shared::ProbeGrid& grid,
                               const std::function<void(std::size_t)>& progress) {
  return flow::sampleRows(
      volume, grid.width, grid.height,
      [&](std::size_t x, std::size_t y) {
        // In float and in this order, as the grid probe computes it.
        const glm::vec3 along = grid.originOffset + float(x) * grid.stepX + float(y) * grid.stepY;
        const glm::vec3 whole = glm::floor(along);
        return flow::wrapPeriodic(
            volume, flow::CellPoint(grid.originAnchor + glm::ivec3(whole), along - whole));
      },
      progress);
}

shared::LicParams licParams(const SlicePlane& plane, const LicOptions& options) {
  shared::LicParams params{};
  params.axisU = glm::vec3(plane.u);
  params.axisV = glm::vec3(plane.v);
  params.width = plane.width;
  params.height = plane.height;
  params.stepPixels = options.stepPixels;
  params.stepsEachWay = licStepsEachWay(options);
  params.noiseSeed = options.noiseSeed;
  return params;
}

VectorImage inPlaneImage(const SlicePlane& plane, const flow::GridSamples& samples) {
  VectorImage image;
  image.width = plane.width;
  image.height = plane.height;
  image.valid = samples.valid;
  image.vectors.resize(samples.vectors.size());
  const glm::vec3 u(plane.u), v(plane.v);
  for (std::size_t n = 0; n < samples.vectors.size(); ++n) {
    const glm::vec3 s = samples.vectors[n];
    // In float and in this order, as shaders/glsl/lic.comp projects.
    image.vectors[n] =
        glm::vec2(s.x * u.x + s.y * u.y + s.z * u.z, s.x * v.x + s.y * v.y + s.z * v.z);
  }
  return image;
}

}  // namespace amrstream::slice
