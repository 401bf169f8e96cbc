#include "app/rgba_image.hpp"

#include <fmt/format.h>

#include "vk/context.hpp"
#include "vk/debug_names.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::app {
namespace {

// Device-local if the image may live there, else any type it may use.
uint32_t chooseMemoryType(const VkPhysicalDeviceMemoryProperties& memory, uint32_t allowed) {
  for (VkMemoryPropertyFlags wanted :
       {VkMemoryPropertyFlags(VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT), VkMemoryPropertyFlags(0)}) {
    for (uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
      if ((allowed & (1u << i)) != 0 && (memory.memoryTypes[i].propertyFlags & wanted) == wanted) {
        return i;
      }
    }
  }
  throw vk::VulkanError(VK_ERROR_FEATURE_NOT_PRESENT, "no memory type can hold an RGBA image");
}

}  // namespace

RgbaImage::RgbaImage(const vk::Context& ctx, VkExtent2D extent, VkFormat format,
                     std::string_view name)
    : extent_(extent), format_(format) {
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {extent.width, extent.height, 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImage image = VK_NULL_HANDLE;
  AMRSTREAM_VK_CHECK(vkCreateImage(ctx.device(), &info, nullptr, &image));
  image_ = vk::UniqueHandle<VkImage>(ctx.device(), image);

  VkMemoryRequirements requirements{};
  vkGetImageMemoryRequirements(ctx.device(), image, &requirements);
  VkMemoryAllocateInfo allocation{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  allocation.allocationSize = requirements.size;
  allocation.memoryTypeIndex =
      chooseMemoryType(ctx.memoryProperties(), requirements.memoryTypeBits);
  VkDeviceMemory memory = VK_NULL_HANDLE;
  const VkResult result = vkAllocateMemory(ctx.device(), &allocation, nullptr, &memory);
  if (result != VK_SUCCESS) {
    throw vk::VulkanError(result,
                          fmt::format("allocating the {}x{} image '{}' ({}) failed", extent.width,
                                      extent.height, name, vk::formatBytes(requirements.size)));
  }
  memory_ = vk::UniqueHandle<VkDeviceMemory>(ctx.device(), memory);
  AMRSTREAM_VK_CHECK(vkBindImageMemory(ctx.device(), image, memory, 0));
  vk::setDebugName(ctx, image_, name);
}

}  // namespace amrstream::app
