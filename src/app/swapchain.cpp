#include "app/swapchain.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <utility>

#include "vk/context.hpp"
#include "vk/debug_names.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::app {
namespace {

constexpr VkImageUsageFlags kUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                     VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                     VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;

// In order of preference; screenshots and the blit handle exactly these.
constexpr std::array<VkFormat, 4> kFormats = {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM,
                                              VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_R8G8B8A8_SRGB};

template <typename T, typename Query>
std::vector<T> enumerate(Query query) {
  uint32_t count = 0;
  AMRSTREAM_VK_CHECK(query(&count, nullptr));
  std::vector<T> items(count);
  AMRSTREAM_VK_CHECK(query(&count, items.data()));
  items.resize(count);
  return items;
}

VkSurfaceFormatKHR chooseFormat(const vk::Context& ctx) {
  const auto offered = enumerate<VkSurfaceFormatKHR>([&](uint32_t* n, VkSurfaceFormatKHR* f) {
    return vkGetPhysicalDeviceSurfaceFormatsKHR(ctx.physicalDevice(), ctx.surface(), n, f);
  });
  constexpr VkFormatFeatureFlags kFeatures =
      VK_FORMAT_FEATURE_BLIT_DST_BIT | VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT;
  for (VkFormat wanted : kFormats) {
    VkFormatProperties properties{};
    vkGetPhysicalDeviceFormatProperties(ctx.physicalDevice(), wanted, &properties);
    if ((properties.optimalTilingFeatures & kFeatures) != kFeatures) continue;
    for (const VkSurfaceFormatKHR& format : offered) {
      if (format.format == wanted && format.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) {
        return format;
      }
    }
  }
  std::string list;
  for (const VkSurfaceFormatKHR& format : offered) list += fmt::format(" {}", int(format.format));
  throw vk::ContextError(fmt::format(
      "{} offers the window no 8-bit RGBA or BGRA format that can be blitted to (VkFormat "
      "values offered:{})",
      ctx.deviceName(), list));
}

VkPresentModeKHR choosePresentMode(const vk::Context& ctx, PresentMode preferred) {
  const auto offered = enumerate<VkPresentModeKHR>([&](uint32_t* n, VkPresentModeKHR* m) {
    return vkGetPhysicalDeviceSurfacePresentModesKHR(ctx.physicalDevice(), ctx.surface(), n, m);
  });
  const VkPresentModeKHR wanted = preferred == PresentMode::Mailbox ? VK_PRESENT_MODE_MAILBOX_KHR
                                  : preferred == PresentMode::Immediate
                                      ? VK_PRESENT_MODE_IMMEDIATE_KHR
                                      : VK_PRESENT_MODE_FIFO_KHR;
  const bool available = std::find(offered.begin(), offered.end(), wanted) != offered.end();
  return available ? wanted : VK_PRESENT_MODE_FIFO_KHR;
}

VkCompositeAlphaFlagBitsKHR chooseCompositeAlpha(VkCompositeAlphaFlagsKHR supported) {
  for (VkCompositeAlphaFlagBitsKHR bit :
       {VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR, VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR,
        VK_COMPOSITE_ALPHA_PRE_MULTIPLIED_BIT_KHR, VK_COMPOSITE_ALPHA_POST_MULTIPLIED_BIT_KHR}) {
    if ((supported & bit) != 0) return bit;
  }
  return VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
}

}  // namespace

Swapchain::Swapchain(const vk::Context& ctx, VkExtent2D extent, PresentMode preferred)
    : ctx_(&ctx) {
  if (!ctx.presentationEnabled()) {
    throw vk::ContextError("a swapchain needs a context built with presentation()");
  }
  format_ = chooseFormat(ctx);
  presentMode_ = choosePresentMode(ctx, preferred);
  if (!create(extent)) {
    throw vk::ContextError("cannot make a swapchain for a window of no area (minimised?)");
  }
}

bool Swapchain::recreate(VkExtent2D extent) {
  AMRSTREAM_VK_CHECK(vkDeviceWaitIdle(ctx_->device()));
  return create(extent);
}

bool Swapchain::create(VkExtent2D extent) {
  VkSurfaceCapabilitiesKHR caps{};
  AMRSTREAM_VK_CHECK(
      vkGetPhysicalDeviceSurfaceCapabilitiesKHR(ctx_->physicalDevice(), ctx_->surface(), &caps));
  if ((caps.supportedUsageFlags & kUsage) != kUsage) {
    throw vk::ContextError(fmt::format(
        "{} cannot blit to, read back or draw on the window's images (supported usage 0x{:x}, "
        "needed 0x{:x})",
        ctx_->deviceName(), caps.supportedUsageFlags, kUsage));
  }
  // 0xFFFFFFFF: the surface takes the size of the swapchain, so the window's size decides.
  if (caps.currentExtent.width != UINT32_MAX) {
    extent = caps.currentExtent;
  } else {
    extent.width = std::clamp(extent.width, caps.minImageExtent.width, caps.maxImageExtent.width);
    extent.height =
        std::clamp(extent.height, caps.minImageExtent.height, caps.maxImageExtent.height);
  }
  if (extent.width == 0 || extent.height == 0) return false;
  // One image more than the minimum, so acquiring need not wait for the display.
  uint32_t imageCount = caps.minImageCount + 1;
  if (caps.maxImageCount != 0) imageCount = std::min(imageCount, caps.maxImageCount);

  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = ctx_->surface();
  info.minImageCount = imageCount;
  info.imageFormat = format_.format;
  info.imageColorSpace = format_.colorSpace;
  info.imageExtent = extent;
  info.imageArrayLayers = 1;
  info.imageUsage = kUsage;
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = chooseCompositeAlpha(caps.supportedCompositeAlpha);
  info.presentMode = presentMode_;
  // Unclipped: a screenshot must read every pixel, also those another window hides.
  info.clipped = VK_FALSE;
  info.oldSwapchain = swapchain_.get();
  VkSwapchainKHR raw = VK_NULL_HANDLE;
  AMRSTREAM_VK_CHECK(vkCreateSwapchainKHR(ctx_->device(), &info, nullptr, &raw));
  vk::UniqueHandle<VkSwapchainKHR> fresh(ctx_->device(), raw);
  vk::setDebugName(*ctx_, fresh, "swapchain");

  // The old views go before the old swapchain that owns their images.
  views_.clear();
  swapchain_ = std::move(fresh);
  extent_ = extent;
  images_ = enumerate<VkImage>([&](uint32_t* n, VkImage* images) {
    return vkGetSwapchainImagesKHR(ctx_->device(), swapchain_.get(), n, images);
  });
  for (uint32_t i = 0; i < images_.size(); ++i) {
    VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    viewInfo.image = images_[i];
    viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
    viewInfo.format = format_.format;
    viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView view = VK_NULL_HANDLE;
    AMRSTREAM_VK_CHECK(vkCreateImageView(ctx_->device(), &viewInfo, nullptr, &view));
    views_.emplace_back(ctx_->device(), view);
    vk::setDebugName(*ctx_, images_[i], fmt::format("swapchain image {}", i));
    vk::setDebugName(*ctx_, view, fmt::format("swapchain view {}", i));
  }
  return true;
}

}  // namespace amrstream::app
