#include "vk/commands.hpp"

#include <cstdint>

#include "vk/context.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::vk {

void memoryBarrier(VkCommandBuffer cmd, Access before, Access after) {
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = before.access;
  barrier.dstAccessMask = after.access;
  vkCmdPipelineBarrier(cmd, before.stages, after.stages, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

void bufferBarrier(VkCommandBuffer cmd, VkBuffer buffer, Access before, Access after,
                   VkDeviceSize offset, VkDeviceSize size) {
  VkBufferMemoryBarrier barrier{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
  barrier.srcAccessMask = before.access;
  barrier.dstAccessMask = after.access;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.buffer = buffer;
  barrier.offset = offset;
  barrier.size = size;
  vkCmdPipelineBarrier(cmd, before.stages, after.stages, 0, 0, nullptr, 1, &barrier, 0, nullptr);
}

OneShotCommands::OneShotCommands(const Context& ctx) : ctx_(&ctx) {
  VkCommandBufferAllocateInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  info.commandPool = ctx.commandPool();
  info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  info.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  AMRSTREAM_VK_CHECK(vkAllocateCommandBuffers(ctx.device(), &info, &cmd));
  commandBuffer_ = UniqueHandle<VkCommandBuffer>({ctx.device(), ctx.commandPool()}, cmd);

  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  AMRSTREAM_VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
}

void OneShotCommands::submitAndWait() {
  const VkCommandBuffer cmd = commandBuffer_.get();
  AMRSTREAM_VK_CHECK(vkEndCommandBuffer(cmd));

  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VkFence rawFence = VK_NULL_HANDLE;
  AMRSTREAM_VK_CHECK(vkCreateFence(ctx_->device(), &fenceInfo, nullptr, &rawFence));
  const UniqueHandle<VkFence> fence(ctx_->device(), rawFence);

  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  AMRSTREAM_VK_CHECK(vkQueueSubmit(ctx_->queue(), 1, &submit, fence.get()));
  // No timeout: a long trace on a CPU device can take minutes, and a lost device returns
  // VK_ERROR_DEVICE_LOST rather than hanging. If the wait fails the queue may still be using the
  // command buffer and fence, so wait for the queue before their destructors run.
  const VkResult result = vkWaitForFences(ctx_->device(), 1, &rawFence, VK_TRUE, UINT64_MAX);
  if (result != VK_SUCCESS) vkQueueWaitIdle(ctx_->queue());
  AMRSTREAM_VK_CHECK(result);
}

}  // namespace amrstream::vk
