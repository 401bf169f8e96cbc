#pragma once
// Names for Vulkan objects, shown by the validation layer's messages and by debuggers
// (RenderDoc, Nsight). A no-op when the context has no VK_EXT_debug_utils (no validation and no
// debugNames()), so callers name objects unconditionally.

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string_view>

#include "vk/unique_handle.hpp"

namespace amrstream::vk {

class Context;

template <typename Handle>
struct ObjectTypeOf;

#define AMRSTREAM_OBJECT_TYPE(Type, value)        \
  template <>                                     \
  struct ObjectTypeOf<Type> {                     \
    static constexpr VkObjectType kValue = value; \
  };
AMRSTREAM_OBJECT_TYPE(VkInstance, VK_OBJECT_TYPE_INSTANCE)
AMRSTREAM_OBJECT_TYPE(VkDevice, VK_OBJECT_TYPE_DEVICE)
AMRSTREAM_OBJECT_TYPE(VkQueue, VK_OBJECT_TYPE_QUEUE)
AMRSTREAM_OBJECT_TYPE(VkCommandBuffer, VK_OBJECT_TYPE_COMMAND_BUFFER)
AMRSTREAM_OBJECT_TYPE(VkCommandPool, VK_OBJECT_TYPE_COMMAND_POOL)
AMRSTREAM_OBJECT_TYPE(VkBuffer, VK_OBJECT_TYPE_BUFFER)
AMRSTREAM_OBJECT_TYPE(VkDeviceMemory, VK_OBJECT_TYPE_DEVICE_MEMORY)
AMRSTREAM_OBJECT_TYPE(VkImage, VK_OBJECT_TYPE_IMAGE)
AMRSTREAM_OBJECT_TYPE(VkImageView, VK_OBJECT_TYPE_IMAGE_VIEW)
AMRSTREAM_OBJECT_TYPE(VkSampler, VK_OBJECT_TYPE_SAMPLER)
AMRSTREAM_OBJECT_TYPE(VkFence, VK_OBJECT_TYPE_FENCE)
AMRSTREAM_OBJECT_TYPE(VkSemaphore, VK_OBJECT_TYPE_SEMAPHORE)
AMRSTREAM_OBJECT_TYPE(VkQueryPool, VK_OBJECT_TYPE_QUERY_POOL)
AMRSTREAM_OBJECT_TYPE(VkShaderModule, VK_OBJECT_TYPE_SHADER_MODULE)
AMRSTREAM_OBJECT_TYPE(VkPipeline, VK_OBJECT_TYPE_PIPELINE)
AMRSTREAM_OBJECT_TYPE(VkPipelineLayout, VK_OBJECT_TYPE_PIPELINE_LAYOUT)
AMRSTREAM_OBJECT_TYPE(VkPipelineCache, VK_OBJECT_TYPE_PIPELINE_CACHE)
AMRSTREAM_OBJECT_TYPE(VkDescriptorSetLayout, VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT)
AMRSTREAM_OBJECT_TYPE(VkDescriptorPool, VK_OBJECT_TYPE_DESCRIPTOR_POOL)
AMRSTREAM_OBJECT_TYPE(VkDescriptorSet, VK_OBJECT_TYPE_DESCRIPTOR_SET)
AMRSTREAM_OBJECT_TYPE(VkRenderPass, VK_OBJECT_TYPE_RENDER_PASS)
AMRSTREAM_OBJECT_TYPE(VkFramebuffer, VK_OBJECT_TYPE_FRAMEBUFFER)
AMRSTREAM_OBJECT_TYPE(VkSwapchainKHR, VK_OBJECT_TYPE_SWAPCHAIN_KHR)
AMRSTREAM_OBJECT_TYPE(VkAccelerationStructureKHR, VK_OBJECT_TYPE_ACCELERATION_STRUCTURE_KHR)
#undef AMRSTREAM_OBJECT_TYPE

void setDebugName(const Context& ctx, VkObjectType type, uint64_t handle, std::string_view name);

template <typename Handle>
void setDebugName(const Context& ctx, Handle handle, std::string_view name) {
  setDebugName(ctx, ObjectTypeOf<Handle>::kValue, reinterpret_cast<uint64_t>(handle), name);
}

template <typename Handle>
void setDebugName(const Context& ctx, const UniqueHandle<Handle>& handle, std::string_view name) {
  setDebugName(ctx, handle.get(), name);
}

}  // namespace amrstream::vk
