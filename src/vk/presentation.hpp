#pragma once
// What a context needs to present to a window, kept free of any window library: the instance
// extensions the window system asks for and a factory that makes the surface once the instance
// exists (src/app passes GLFW's). With it, the context owns the surface, enables VK_KHR_swapchain
// and uses one queue family that does graphics, compute and presentation to that surface.

#include <vulkan/vulkan.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "vk/device_support.hpp"

namespace amrstream::vk {

// Returns a new surface of `instance`, which the context then owns, or throws.
using SurfaceFactory = std::function<VkSurfaceKHR(VkInstance instance)>;

struct PresentationRequest {
  std::vector<std::string> instanceExtensions;
  SurfaceFactory createSurface;
};

struct PresentationSupport {
  bool swapchainExtension = false;
  // The first family with graphics, compute and presentation to the surface.
  std::optional<uint32_t> queueFamily;

  // "VK_KHR_swapchain", "a queue family with graphics, compute and presentation to the window";
  // empty when the device can present.
  std::vector<std::string> missing() const;
};

PresentationSupport probePresentation(VkPhysicalDevice physicalDevice, const DeviceSupport& device,
                                      VkSurfaceKHR surface);

}  // namespace amrstream::vk
