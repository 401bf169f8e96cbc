#include "round_kernels.hpp"

#include <utility>

#include "../../shaders/glsl/shared/round_bindings.h"
#include "../../shaders/glsl/shared/round_params.h"
#include "compact_round_comp.h"
#include "point_data_comp.h"
#include "scan_blocks_comp.h"
#include "scan_lines_comp.h"
#include "vk/context.hpp"
#include "vk/descriptor_writes.hpp"
#include "vk/pipelines.hpp"

namespace amrstream::gpu {

namespace {

vk::UniqueHandle<VkDescriptorSetLayout> storageBufferLayout(const vk::Context& ctx,
                                                            std::uint32_t count) {
  return vk::createDescriptorSetLayout(
      ctx, vk::storageBufferBindings(count, VK_SHADER_STAGE_COMPUTE_BIT));
}

}  // namespace

RoundKernels createRoundKernels(const vk::Context& ctx) {
  using vk::spirv;
  RoundKernels k;
  k.compactionSetLayout = storageBufferLayout(ctx, AMRSTREAM_COMPACTION_BINDING_COUNT);
  k.compactionLayout =
      vk::createPipelineLayout(ctx, k.compactionSetLayout.get(), sizeof(shared::CompactionParams),
                               VK_SHADER_STAGE_COMPUTE_BIT);
  k.scanLines = vk::createComputePipeline(
      ctx, k.compactionLayout.get(), spirv(amrstream_spirv_scan_lines_comp), nullptr, "scan lines");
  k.scanBlocks =
      vk::createComputePipeline(ctx, k.compactionLayout.get(),
                                spirv(amrstream_spirv_scan_blocks_comp), nullptr, "scan blocks");
  k.compact = vk::createComputePipeline(ctx, k.compactionLayout.get(),
                                        spirv(amrstream_spirv_compact_round_comp), nullptr,
                                        "compact round");
  PointDataKernel pointData = createPointDataKernel(ctx);
  k.pointDataSetLayout = std::move(pointData.setLayout);
  k.pointDataLayout = std::move(pointData.layout);
  k.pointData = std::move(pointData.pipeline);
  return k;
}

PointDataKernel createPointDataKernel(const vk::Context& ctx) {
  PointDataKernel k;
  k.setLayout = storageBufferLayout(ctx, AMRSTREAM_POINT_DATA_BINDING_COUNT);
  k.layout = vk::createPipelineLayout(ctx, k.setLayout.get(), sizeof(shared::PointDataParams),
                                      VK_SHADER_STAGE_COMPUTE_BIT);
  k.pipeline = vk::createComputePipeline(
      ctx, k.layout.get(), vk::spirv(amrstream_spirv_point_data_comp), nullptr, "point data");
  return k;
}

void writePointDataSet(const vk::Context& ctx, VkDescriptorSet set, const VolumeBuffers& device,
                       const PointDataTargets& targets) {
  vk::DescriptorWrites("point data", AMRSTREAM_POINT_DATA_BINDING_COUNT)
      .set(AMRSTREAM_BINDING_POINT_DATA_BRICKS, device.bricks)
      .set(AMRSTREAM_BINDING_POINT_DATA_VALUES, device.values)
      .set(AMRSTREAM_BINDING_POINT_DATA_REGIONS, device.regions)
      .set(AMRSTREAM_BINDING_POINT_DATA_REGION_BRICKS, device.regionBricks)
      .set(AMRSTREAM_BINDING_POINT_DATA_CHANNEL_VALUES, device.channelValues)
      .set(AMRSTREAM_BINDING_POINT_DATA_SUMMARY, targets.summary)
      .set(AMRSTREAM_BINDING_POINT_DATA_POSITIONS, targets.positions)
      .set(AMRSTREAM_BINDING_POINT_DATA_REGION_IDS, targets.regionIds)
      .set(AMRSTREAM_BINDING_POINT_DATA_CHANNELS, targets.channels)
      .set(AMRSTREAM_BINDING_POINT_DATA_VORTICITY, targets.vorticity)
      .set(AMRSTREAM_BINDING_POINT_DATA_LINEAR_CELLS, device.vectorGradients)
      .set(AMRSTREAM_BINDING_POINT_DATA_CHANNEL_GRADIENTS, device.channelGradients)
      .write(ctx, set);
}

}  // namespace amrstream::gpu
