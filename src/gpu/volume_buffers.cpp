#include "volume_buffers.hpp"

#include <tbb/parallel_for.h>

#include <array>
#include <cmath>

#include <fmt/format.h>

#include "util/input_error.hpp"
#include "util/stopwatch.hpp"
#include "device_upload.hpp"

namespace amrstream::gpu {

namespace {

constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;

// Half a lattice coordinate (a finest-cell position) as a float, rounded down or up, and one ulp
// further when inexact: the kernels probe a lattice point k at the float centre of its lattice
// cell (probeOrigin in region_containment.glsl), which may round by an ulp past an inexact face.
float boundBelow(int lattice) {
  const double exact = 0.5 * lattice;
  const float f = float(exact);
  if (double(f) == exact) return f;
  return std::nextafter(double(f) > exact ? std::nextafter(f, -INFINITY) : f, -INFINITY);
}

float boundAbove(int lattice) {
  const double exact = 0.5 * lattice;
  const float f = float(exact);
  if (double(f) == exact) return f;
  return std::nextafter(double(f) < exact ? std::nextafter(f, INFINITY) : f, INFINITY);
}

// The regions' boxes in finest-cell units, exact while the lattice is below 2^24 and rounded
// outward beyond: the kernels test every candidate exactly on the lattice.
std::vector<VkAabbPositionsKHR> regionBoxes(const bricks::RegionSet& regions) {
  std::vector<VkAabbPositionsKHR> boxes(regions.regions.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const shared::Region& r = regions.regions[i];
    boxes[i] = {boundBelow(r.lower.x), boundBelow(r.lower.y), boundBelow(r.lower.z),
                boundAbove(r.upper.x), boundAbove(r.upper.y), boundAbove(r.upper.z)};
  }
  return boxes;
}

// The linear interpolant's cells as the tracing kernels read them: per slot the value and the
// gradients of its three components, together (one read instead of two far apart).
void fillLinearCells(const flow::VectorVolume& volume, std::size_t first,
                     std::span<glm::vec3> out) {
  tbb::parallel_for(std::size_t(0), out.size() / 4, [&](std::size_t k) {
    const std::size_t slot = first / 4 + k;
    out[4 * k] = volume.values[slot];
    for (int d = 0; d < 3; ++d) out[4 * k + 1 + d] = volume.vectorGradients[3 * slot + d];
  });
}

}  // namespace

VolumeBuffers::VolumeBuffers(const vk::Context& ctx, Backend backend,
                             const flow::VectorVolume& volume, TracerSetup& setup) {
  // The pipeline's intersection shader sees only the ray's float origin (locate_pipeline.glsl).
  const glm::ivec3 extent = volume.period();
  if (backend == Backend::Pipeline && glm::any(glm::greaterThan(extent, glm::ivec3(1 << 22))))
    throw InputError("--backend pipeline",
                     fmt::format("the domain spans {}x{}x{} finest cells; the pipeline backend "
                                 "locates points in float coordinates, exact up to 2^22 finest "
                                 "cells per axis: use --backend compute or rayquery",
                                 extent.x, extent.y, extent.z));
  Stopwatch clock;
  DeviceUploader uploader(ctx);
  bricks = uploader.upload(std::span(volume.bricks), kStorage, "bricks");
  // The values padded to 16 bytes, which the kernels read in one aligned load (1.32x the compute
  // backend's particle-steps/s on an H200).
  values = uploader.upload<glm::vec4>(
      volume.values.size(), kStorage, "vector values",
      [&](std::size_t first, std::span<glm::vec4> out) {
        tbb::parallel_for(std::size_t(0), out.size(), [&](std::size_t i) {
          out[i] = glm::vec4(volume.values[first + i], 0.0f);
        });
      });
  channelValues = uploader.upload(std::span(volume.channelValues), kStorage, "channel values");
  // A slot of the linear cells is 4 vec3s; chunks hold whole elements, so upload slots.
  using LinearSlot = std::array<glm::vec3, 4>;
  vectorGradients = uploader.upload<LinearSlot>(
      volume.vectorGradients.size() / 3, kStorage, "linear cells",
      [&](std::size_t first, std::span<LinearSlot> out) {
        fillLinearCells(volume, 4 * first, {out.front().data(), 4 * out.size()});
      });
  channelGradients =
      uploader.upload(std::span(volume.channelGradients), kStorage, "channel gradients");
  regions = uploader.upload(std::span(volume.regions.regions), kStorage, "regions");
  // The regions' brick lists with the records in place of the indices.
  const std::vector<std::uint32_t>& ids = volume.regions.regionBricks;
  regionBricks = uploader.upload<shared::Brick>(
      ids.size(), kStorage, "region bricks", [&](std::size_t first, std::span<shared::Brick> out) {
        tbb::parallel_for(std::size_t(0), out.size(),
                          [&](std::size_t i) { out[i] = volume.bricks[ids[first + i]]; });
      });
  setup.uploadSeconds = clock.seconds();
  setup.volumeBytes = bricks.size() + values.size() + channelValues.size() +
                      vectorGradients.size() + channelGradients.size() + regions.size() +
                      regionBricks.size();

  clock.restart();
  if (backend == Backend::Compute) {
    tree = uploader.upload(std::span(volume.regions.tree), kStorage, "region tree");
    setup.structureBytes = tree.size();
  } else {
    scene = vk::buildAabbScene(ctx, regionBoxes(volume.regions), "regions");
    setup.structureBytes = scene->tlas.size();
    for (const vk::AabbBlas& blas : scene->blases) setup.structureBytes += blas.structure.size();
  }
  setup.structureSeconds = clock.seconds();
}

vk::DescriptorTarget VolumeBuffers::locateTarget() const {
  if (scene)
    return {VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, VK_NULL_HANDLE, scene->tlas.handle()};
  return {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, tree.handle()};
}

}  // namespace amrstream::gpu
