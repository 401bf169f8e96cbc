#include "dual_cells.hpp"

#include <algorithm>
#include <array>

#include "../../shaders/glsl/shared/dual_cell_bindings.h"
#include "../../shaders/glsl/shared/dual_cell_params.h"
#include "build_dual_cells_comp.h"
#include "device_upload.hpp"
#include "vk/commands.hpp"
#include "vk/descriptor_pool.hpp"
#include "vk/descriptor_writes.hpp"
#include "vk/pipelines.hpp"

namespace amrstream::gpu {

namespace {

// Workgroups per dispatch: the smallest maxComputeWorkGroupCount[0] Vulkan allows.
constexpr std::uint32_t kBricksPerDispatch = 65535;

}  // namespace

vk::Buffer buildDualValues(const vk::Context& ctx, DeviceUploader& uploader,
                           const vk::Buffer& bricks, const vk::Buffer& values,
                           std::span<const std::uint64_t> dualOffsets) {
  const std::size_t brickCount = dualOffsets.size() - 1;
  constexpr VkDeviceSize kDualCellBytes = 8 * 16;
  vk::Buffer dual = vk::Buffer::deviceLocal(
      ctx, dualOffsets.back() * kDualCellBytes,
      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
      "dual values");
  const vk::Buffer firstCells = uploader.upload<std::uint32_t>(
      brickCount, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "dual cell offsets",
      [&](std::size_t first, std::span<std::uint32_t> out) {
        std::transform(dualOffsets.begin() + first, dualOffsets.begin() + first + out.size(),
                       out.begin(), [](std::uint64_t d) { return static_cast<std::uint32_t>(d); });
      });

  const auto setLayout = vk::createDescriptorSetLayout(
      ctx,
      vk::storageBufferBindings(AMRSTREAM_DUAL_CELL_BINDING_COUNT, VK_SHADER_STAGE_COMPUTE_BIT));
  const auto layout = vk::createPipelineLayout(ctx, setLayout.get(), sizeof(shared::DualCellParams),
                                               VK_SHADER_STAGE_COMPUTE_BIT);
  const auto pipeline =
      vk::createComputePipeline(ctx, layout.get(), vk::spirv(amrstream_spirv_build_dual_cells_comp),
                                nullptr, "build dual cells");
  const std::array<VkDescriptorPoolSize, 1> sizes{
      {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, AMRSTREAM_DUAL_CELL_BINDING_COUNT}}};
  vk::DescriptorPool pool(ctx, 1, sizes);
  const VkDescriptorSet set = pool.allocate(setLayout.get());
  vk::DescriptorWrites("dual cells", AMRSTREAM_DUAL_CELL_BINDING_COUNT)
      .set(AMRSTREAM_BINDING_DUAL_CELL_BRICKS, bricks)
      .set(AMRSTREAM_BINDING_DUAL_CELL_VALUES, values)
      .set(AMRSTREAM_BINDING_DUAL_CELL_OFFSETS, firstCells)
      .write(ctx, set);

  const VkDeviceAddress address = dual.deviceAddress();
  vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.get());
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout.get(), 0, 1, &set, 0,
                            nullptr);
    for (std::size_t first = 0; first < brickCount; first += kBricksPerDispatch) {
      const shared::DualCellParams params{
          {static_cast<std::uint32_t>(address), static_cast<std::uint32_t>(address >> 32)},
          static_cast<std::uint32_t>(first)};
      vkCmdPushConstants(cmd, layout.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(params),
                         &params);
      vkCmdDispatch(
          cmd,
          static_cast<std::uint32_t>(std::min<std::size_t>(kBricksPerDispatch, brickCount - first)),
          1, 1);
    }
    vk::memoryBarrier(cmd, vk::access::kComputeShaderWrite, vk::access::kAny);
  });
  return dual;
}

}  // namespace amrstream::gpu
