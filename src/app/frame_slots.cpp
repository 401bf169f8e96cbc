#include "app/frame_slots.hpp"

#include <fmt/format.h>

#include "vk/context.hpp"
#include "vk/debug_names.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::app {

vk::UniqueHandle<VkSemaphore> createSemaphore(const vk::Context& ctx) {
  VkSemaphoreCreateInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  VkSemaphore semaphore = VK_NULL_HANDLE;
  AMRSTREAM_VK_CHECK(vkCreateSemaphore(ctx.device(), &info, nullptr, &semaphore));
  return {ctx.device(), semaphore};
}

FrameSlots::FrameSlots(const vk::Context& ctx, uint32_t count) {
  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  poolInfo.queueFamilyIndex = ctx.queueFamilyIndex();
  VkCommandPool pool = VK_NULL_HANDLE;
  AMRSTREAM_VK_CHECK(vkCreateCommandPool(ctx.device(), &poolInfo, nullptr, &pool));
  pool_ = vk::UniqueHandle<VkCommandPool>(ctx.device(), pool);

  for (uint32_t i = 0; i < count; ++i) {
    FrameSlot slot;
    VkCommandBufferAllocateInfo allocation{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocation.commandPool = pool;
    allocation.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocation.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    AMRSTREAM_VK_CHECK(vkAllocateCommandBuffers(ctx.device(), &allocation, &cmd));
    slot.commands = vk::UniqueHandle<VkCommandBuffer>({ctx.device(), pool}, cmd);

    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fenceInfo.flags = VK_FENCE_CREATE_SIGNALED_BIT;
    VkFence fence = VK_NULL_HANDLE;
    AMRSTREAM_VK_CHECK(vkCreateFence(ctx.device(), &fenceInfo, nullptr, &fence));
    slot.finished = vk::UniqueHandle<VkFence>(ctx.device(), fence);
    slot.imageAcquired = createSemaphore(ctx);

    vk::setDebugName(ctx, slot.commands, fmt::format("frame {} commands", i));
    vk::setDebugName(ctx, slot.finished, fmt::format("frame {} finished", i));
    vk::setDebugName(ctx, slot.imageAcquired, fmt::format("frame {} image acquired", i));
    slots_.push_back(std::move(slot));
  }
}

}  // namespace amrstream::app
