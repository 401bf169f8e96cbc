#include "app/overlay_pass.hpp"

#include "app/swapchain.hpp"
#include "vk/context.hpp"
#include "vk/debug_names.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::app {

OverlayPass::OverlayPass(const vk::Context& ctx, VkFormat format) : ctx_(&ctx) {
  VkAttachmentDescription attachment{};
  attachment.format = format;
  attachment.samples = VK_SAMPLE_COUNT_1_BIT;
  attachment.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  attachment.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  attachment.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  attachment.initialLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  attachment.finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;

  const VkAttachmentReference colour{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &colour;

  // The blit (and the clear of the letterbox bars) write the image before the pass loads it; the
  // layout transition to COLOR_ATTACHMENT_OPTIMAL happens between the two scopes.
  VkSubpassDependency afterBlit{};
  afterBlit.srcSubpass = VK_SUBPASS_EXTERNAL;
  afterBlit.dstSubpass = 0;
  afterBlit.srcStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
  afterBlit.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  afterBlit.dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  afterBlit.dstAccessMask =
      VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;

  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = 1;
  info.pAttachments = &attachment;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 1;
  info.pDependencies = &afterBlit;
  VkRenderPass renderPass = VK_NULL_HANDLE;
  AMRSTREAM_VK_CHECK(vkCreateRenderPass(ctx.device(), &info, nullptr, &renderPass));
  renderPass_ = vk::UniqueHandle<VkRenderPass>(ctx.device(), renderPass);
  vk::setDebugName(ctx, renderPass_, "overlay pass");
}

void OverlayPass::attach(const Swapchain& swapchain) {
  framebuffers_.clear();
  extent_ = swapchain.extent();
  for (uint32_t i = 0; i < swapchain.imageCount(); ++i) {
    const VkImageView view = swapchain.view(i);
    VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    info.renderPass = renderPass_.get();
    info.attachmentCount = 1;
    info.pAttachments = &view;
    info.width = extent_.width;
    info.height = extent_.height;
    info.layers = 1;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    AMRSTREAM_VK_CHECK(vkCreateFramebuffer(ctx_->device(), &info, nullptr, &framebuffer));
    framebuffers_.emplace_back(ctx_->device(), framebuffer);
  }
}

void OverlayPass::begin(VkCommandBuffer cmd, uint32_t imageIndex) const {
  VkRenderPassBeginInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  info.renderPass = renderPass_.get();
  info.framebuffer = framebuffers_.at(imageIndex).get();
  info.renderArea = {{0, 0}, extent_};
  vkCmdBeginRenderPass(cmd, &info, VK_SUBPASS_CONTENTS_INLINE);
}

void OverlayPass::end(VkCommandBuffer cmd) const { vkCmdEndRenderPass(cmd); }

}  // namespace amrstream::app
