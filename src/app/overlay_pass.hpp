#pragma once
// OverlayPass: the render pass in which the overlay (Dear ImGui) draws on a swapchain image after
// the frame has been blitted there, and one framebuffer per swapchain image. The pass loads the
// image from TRANSFER_DST_OPTIMAL (the blit's layout; the pass waits for the blit's writes) and
// leaves it in COLOR_ATTACHMENT_OPTIMAL, for the presenter's barrier to PRESENT_SRC or to
// TRANSFER_SRC (screenshots). Owns the render pass and the framebuffers; the context must
// outlive it, and the framebuffers must be rebuilt with attach() whenever the swapchain is.

#include <vulkan/vulkan.h>

#include <vector>

#include "vk/unique_handle.hpp"

namespace amrstream::vk {
class Context;
}

namespace amrstream::app {

class Swapchain;

class OverlayPass {
 public:
  OverlayPass(const vk::Context& ctx, VkFormat format);

  // Framebuffers for the swapchain's current images (replacing earlier ones); call after every
  // creation or recreation of the swapchain.
  void attach(const Swapchain& swapchain);
  // Drops the framebuffers, before the swapchain they were made for is recreated.
  void detach() { framebuffers_.clear(); }

  VkRenderPass renderPass() const { return renderPass_.get(); }
  void begin(VkCommandBuffer cmd, uint32_t imageIndex) const;
  void end(VkCommandBuffer cmd) const;

 private:
  const vk::Context* ctx_;
  vk::UniqueHandle<VkRenderPass> renderPass_;
  std::vector<vk::UniqueHandle<VkFramebuffer>> framebuffers_;
  VkExtent2D extent_{};
};

}  // namespace amrstream::app
