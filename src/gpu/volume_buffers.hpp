#pragma once
// The device's copy of a VectorVolume: bricks, vector values, point-data channels, regions and
// region bricks, plus the backend's point-location structure (the region tree for `compute`, an
// AABB acceleration structure of the region boxes for `rayquery` and `pipeline`).

#include <cstdint>
#include <optional>

#include "backend.hpp"
#include "flow/vector_volume.hpp"
#include "vk/aabb_scene.hpp"
#include "vk/buffer.hpp"
#include "vk/descriptor_pool.hpp"

namespace amrstream::gpu {

// What uploading the volume took.
struct TracerSetup {
  double uploadSeconds = 0.0;     // the volume's buffers to the device
  double structureSeconds = 0.0;  // the region tree's upload, or the acceleration structure build
  double pipelineSeconds = 0.0;   // shader modules and pipelines (and binding table)
  std::uint64_t volumeBytes = 0;     // device bytes of bricks, values, channels, regions and region bricks
  std::uint64_t structureBytes = 0;  // device bytes of the region tree or of the BLASes and TLAS
};

struct VolumeBuffers {
  VolumeBuffers(const vk::Context& ctx, Backend backend, const flow::VectorVolume& volume,
                TracerSetup& setup);

  // The binding of the point-location structure.
  vk::DescriptorTarget locateTarget() const;

  vk::Buffer bricks;
  vk::Buffer values;
  vk::Buffer channelValues;
  vk::Buffer vectorGradients;   // linear interpolant: per slot the value, then its 3 gradients
  vk::Buffer channelGradients;  // linear interpolant (empty with tent)
  vk::Buffer regions;
  // The regions' brick lists (RegionSet::regionBricks) with each brick's record in place of its
  // index, so that a sample reads a brick in one load instead of two dependent ones.
  vk::Buffer regionBricks;
  vk::Buffer tree;                     // compute backend
  std::optional<vk::AabbScene> scene;  // rayquery and pipeline backends
};

}  // namespace amrstream::gpu
