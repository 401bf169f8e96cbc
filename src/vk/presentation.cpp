#include "vk/presentation.hpp"

#include "vk/vk_error.hpp"

namespace amrstream::vk {

std::vector<std::string> PresentationSupport::missing() const {
  std::vector<std::string> items;
  if (!swapchainExtension) items.emplace_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
  if (!queueFamily) {
    items.emplace_back("a queue family with graphics, compute and presentation to the window");
  }
  return items;
}

PresentationSupport probePresentation(VkPhysicalDevice physicalDevice, const DeviceSupport& device,
                                      VkSurfaceKHR surface) {
  PresentationSupport support;
  support.swapchainExtension = device.hasExtension(VK_KHR_SWAPCHAIN_EXTENSION_NAME);

  uint32_t familyCount = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice, &familyCount, nullptr);
  std::vector<VkQueueFamilyProperties> families(familyCount);
  vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice, &familyCount, families.data());
  constexpr VkQueueFlags kNeeded = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
  for (uint32_t i = 0; i < familyCount; ++i) {
    if ((families[i].queueFlags & kNeeded) != kNeeded || families[i].queueCount == 0) continue;
    VkBool32 presents = VK_FALSE;
    AMRSTREAM_VK_CHECK(vkGetPhysicalDeviceSurfaceSupportKHR(physicalDevice, i, surface, &presents));
    if (presents == VK_TRUE) {
      support.queueFamily = i;
      break;
    }
  }
  return support;
}

}  // namespace amrstream::vk
