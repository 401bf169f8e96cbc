#pragma once
// One-shot command submission and the barriers between recorded commands.
//
//   submitAndWait(ctx, [&](VkCommandBuffer cmd) { vkCmdCopyBuffer(cmd, ...); });
//
// records into a fresh primary command buffer from the context's pool, submits it to the
// context's queue and blocks on a fence until the device has finished. The command buffer is
// freed on return, also when recording throws.

#include <vulkan/vulkan.h>

#include <utility>

#include "vk/unique_handle.hpp"

namespace amrstream::vk {

class Context;

// One side of a dependency: the pipeline stages and the memory accesses they make.
struct Access {
  VkPipelineStageFlags stages = 0;
  VkAccessFlags access = 0;
};

namespace access {
inline constexpr Access kTransferWrite{VK_PIPELINE_STAGE_TRANSFER_BIT,
                                       VK_ACCESS_TRANSFER_WRITE_BIT};
inline constexpr Access kTransferRead{VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT};
inline constexpr Access kHostWrite{VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_WRITE_BIT};
inline constexpr Access kHostRead{VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT};
inline constexpr Access kComputeShaderWrite{VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                                            VK_ACCESS_SHADER_WRITE_BIT};
inline constexpr Access kComputeShaderRead{VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                                           VK_ACCESS_SHADER_READ_BIT};
inline constexpr Access kAccelerationStructureWrite{
    VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
    VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR};
inline constexpr Access kAccelerationStructureRead{
    VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
    VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR};
// Every earlier write / every later access, whatever the stage: for the edges of a submission.
inline constexpr Access kAnyWrite{VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_WRITE_BIT};
inline constexpr Access kAny{VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                             VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT};
}  // namespace access

// A global memory barrier: the `before` accesses happen-before and are visible to the `after`
// ones, for all memory.
void memoryBarrier(VkCommandBuffer cmd, Access before, Access after);

// The same for one buffer range (same queue family, so no ownership transfer).
void bufferBarrier(VkCommandBuffer cmd, VkBuffer buffer, Access before, Access after,
                   VkDeviceSize offset = 0, VkDeviceSize size = VK_WHOLE_SIZE);

// A primary command buffer from the context's pool, begun with ONE_TIME_SUBMIT. Owns the command
// buffer; the context must outlive it.
class OneShotCommands {
 public:
  explicit OneShotCommands(const Context& ctx);

  VkCommandBuffer handle() const { return commandBuffer_.get(); }
  // Ends recording, submits, and waits for the device to finish. Call once.
  void submitAndWait();

 private:
  const Context* ctx_;
  UniqueHandle<VkCommandBuffer> commandBuffer_;
};

template <typename Record>
void submitAndWait(const Context& ctx, Record&& record) {
  OneShotCommands commands(ctx);
  std::forward<Record>(record)(commands.handle());
  commands.submitAndWait();
}

}  // namespace amrstream::vk
