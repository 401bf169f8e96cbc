#pragma once
// A layout transition of a whole single-mip colour image, with the dependency of
// vk/commands.hpp's Access pairs (same queue family, so no ownership transfer).

#include <vulkan/vulkan.h>

#include "vk/commands.hpp"

namespace amrstream::app {

void transitionImage(VkCommandBuffer cmd, VkImage image, VkImageLayout from, VkImageLayout to,
                     vk::Access before, vk::Access after);

}  // namespace amrstream::app
