#include "volume_buffers.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string_view>

#include "amrstream/error.hpp"
#include "bricks/descent_tree.hpp"
#include "device_upload.hpp"
#include "dual_cells.hpp"
#include "util/stopwatch.hpp"
#include "vk/context.hpp"
#include "vk/vk_error.hpp"

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

constexpr std::uint32_t kCorners = 8;

std::uint64_t dualCellsOf(const shared::Brick& brick) {
  return std::uint64_t(brick.size.x + 1) * std::uint64_t(brick.size.y + 1) *
         std::uint64_t(brick.size.z + 1);
}

// Each brick's first dual cell, and after the last brick the total.
std::vector<std::uint64_t> dualOffsets(const flow::VectorVolume& volume) {
  std::vector<std::uint64_t> offsets(volume.bricks.size() + 1, 0);
  for (std::size_t b = 0; b < volume.bricks.size(); ++b)
    offsets[b + 1] = offsets[b] + dualCellsOf(volume.bricks[b]);
  return offsets;
}

// The regions' brick lists with each brick's record in place of its index (one load per brick
// instead of two dependent ones), its valueOffset set to valueOffset(brick index).
template <typename ValueOffset>
vk::Buffer uploadRegionBricks(DeviceUploader& uploader, const flow::VectorVolume& volume,
                              std::string_view name, const ValueOffset& valueOffset) {
  const std::vector<std::uint32_t>& ids = volume.regions.regionBricks;
  return uploader.upload<shared::Brick>(
      ids.size(), kStorage, name, [&](std::size_t first, std::span<shared::Brick> out) {
        tbb::parallel_for(std::size_t(0), out.size(), [&](std::size_t i) {
          out[i] = volume.bricks[ids[first + i]];
          out[i].valueOffset = valueOffset(ids[first + i]);
        });
      });
}

}  // namespace

bool VolumeBuffers::canHoldDualValues(const flow::VectorVolume& volume) {
  return volume.interpolant == flow::Interpolant::Tent &&
         dualOffsets(volume).back() * kCorners <= std::numeric_limits<std::uint32_t>::max();
}

bool VolumeBuffers::addressesDualValues(const vk::Context& ctx) {
  return ctx.bufferDeviceAddressEnabled();
}

glm::uvec2 VolumeBuffers::dualValuesAddress() const {
  if (dualValues.size() == 0) return glm::uvec2(0);
  const VkDeviceAddress address = dualValues.deviceAddress();
  return {static_cast<std::uint32_t>(address), static_cast<std::uint32_t>(address >> 32)};
}

std::uint64_t VolumeBuffers::dualValueBytes(const flow::VectorVolume& volume) {
  return dualOffsets(volume).back() * kCorners * sizeof(glm::vec4) +
         volume.regions.regionBricks.size() * sizeof(shared::Brick);
}

VolumeBuffers::VolumeBuffers(const vk::Context& ctx, Backend backend,
                             const flow::VectorVolume& volume, TracerSetup& setup,
                             bool withDualValues) {
  // The pipeline's intersection shader sees only the ray's float origin (locate_pipeline.glsl).
  const glm::ivec3 extent = volume.period();
  if (backend == Backend::Pipeline && glm::any(glm::greaterThan(extent, glm::ivec3(1 << 22))))
    throw settingError("backend",
                       fmt::format("pipeline: the domain spans {}x{}x{} finest cells; the "
                                   "pipeline backend locates points in float coordinates, exact "
                                   "up to 2^22 finest cells per axis: use {{backend}} compute or "
                                   "rayquery",
                                   extent.x, extent.y, extent.z));
  Stopwatch clock;
  DeviceUploader uploader(ctx);
  bricks = uploader.upload(std::span(volume.bricks), kStorage, "bricks");
  // The values padded to 16 bytes, which the kernels read in one aligned load.
  values = uploader.upload<glm::vec4>(volume.values.size(), kStorage, "vector values",
                                      [&](std::size_t first, std::span<glm::vec4> out) {
                                        tbb::parallel_for(
                                            std::size_t(0), out.size(), [&](std::size_t i) {
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
  regionBricks = uploadRegionBricks(uploader, volume, "region bricks",
                                    [&](std::uint32_t b) { return volume.bricks[b].valueOffset; });
  if (withDualValues) {
    if (!canHoldDualValues(volume))
      throw std::logic_error("VolumeBuffers: the volume's dual cells cannot be laid out");
    const std::vector<std::uint64_t> offsets = dualOffsets(volume);
    // Dual cells are a faster layout of what `values` holds: a device that cannot allocate them
    // traces without them.
    try {
      dualValues = buildDualValues(ctx, uploader, bricks, values, offsets);
      dualRegionBricks = uploadRegionBricks(
          uploader, volume, "dual region bricks",
          [&](std::uint32_t b) { return static_cast<std::uint32_t>(offsets[b]); });
    } catch (const vk::VulkanError& e) {
      if (e.result() != VK_ERROR_OUT_OF_DEVICE_MEMORY) throw;
      dualValues = {};
      dualRegionBricks = {};
    }
  }
  setup.uploadSeconds = clock.seconds();
  setup.volumeBytes = bricks.size() + values.size() + channelValues.size() +
                      vectorGradients.size() + channelGradients.size() + regions.size() +
                      regionBricks.size() + dualValues.size() + dualRegionBricks.size();

  clock.restart();
  if (backend == Backend::Compute) {
    const std::vector<std::byte> treeBytes = bricks::buildDescentTree(volume.regions).bytes();
    tree = uploader.upload(std::span<const std::byte>(treeBytes), kStorage, "region tree");
    setup.structureBytes = tree.size();
  } else {
    scene = vk::buildAabbScene(ctx, regionBoxes(volume.regions), "regions");
    setup.structureBytes = scene->tlas.size();
    for (const vk::AabbBlas& blas : scene->blases) setup.structureBytes += blas.structure.size();
  }
  setup.structureSeconds = clock.seconds();
}

vk::DescriptorTarget VolumeBuffers::locateTarget() const {
  if (scene) return vk::structureTarget(scene->tlas.handle());
  return vk::storageTarget(tree);
}

}  // namespace amrstream::gpu
