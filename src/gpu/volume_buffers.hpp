#pragma once
// The device's copy of a VectorVolume: bricks, vector values, point-data channels, regions and
// region bricks, plus the backend's point-location structure (the region tree for `compute`, an
// AABB acceleration structure of the region boxes for `rayquery` and `pipeline`).

#include <cstdint>
#include <glm/glm.hpp>
#include <optional>

#include "backend.hpp"
#include "flow/vector_volume.hpp"
#include "vk/aabb_scene.hpp"
#include "vk/buffer.hpp"
#include "vk/descriptor_writes.hpp"

namespace amrstream::gpu {

// What uploading the volume took.
struct TracerSetup {
  double uploadSeconds = 0.0;     // the volume's buffers to the device
  double structureSeconds = 0.0;  // the region tree's upload, or the acceleration structure build
  double pipelineSeconds = 0.0;   // shader modules and pipelines (and binding table)
  std::uint64_t volumeBytes =
      0;  // device bytes of bricks, values, channels, regions and region bricks
  std::uint64_t structureBytes = 0;  // device bytes of the region tree or of the BLASes and TLAS
};

struct VolumeBuffers {
  // With `dualValues`, also the vector as dual cells (below), unless the device cannot allocate
  // them; canHoldDualValues() and addressesDualValues() must hold.
  VolumeBuffers(const vk::Context& ctx, Backend backend, const flow::VectorVolume& volume,
                TracerSetup& setup, bool dualValues = false);

  // Whether the volume's dual cells can be laid out: the tent interpolant, and slots that fit
  // the kernels' 32-bit indices.
  static bool canHoldDualValues(const flow::VectorVolume& volume);
  // The device bytes of the dual cells and their region brick records.
  static std::uint64_t dualValueBytes(const flow::VectorVolume& volume);
  // Whether the device can hold dual cells: the tracing kernels read them through their buffer
  // device address (any size, where a binding would stop at maxStorageBufferRange).
  static bool addressesDualValues(const vk::Context& ctx);
  // TraceParams::dualValuesAddress: the dual cells' address, low word first; 0 without them.
  glm::uvec2 dualValuesAddress() const;

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
  // The vector as dual cells, for the tracing kernels (KernelSettings::dualValues): brick by
  // brick, one cell per base cell b in [-1, size)^3 holding the 8 values of the cells b + {0,1}^3
  // as vec4 ((value, 1) in the brick, -0.0 outside), 128 bytes together; and the region brick
  // records with each valueOffset counting those cells. Empty unless asked for.
  vk::Buffer dualValues;
  vk::Buffer dualRegionBricks;
  vk::Buffer tree;                     // compute backend
  std::optional<vk::AabbScene> scene;  // rayquery and pipeline backends
};

}  // namespace amrstream::gpu
