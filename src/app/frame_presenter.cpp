#include "app/frame_presenter.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "app/blit_region.hpp"
#include "app/image_barrier.hpp"
#include "app/imgui_layer.hpp"
#include "app/window.hpp"
#include "vk/context.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::app {
namespace {

constexpr vk::Access kTransferOnly{VK_PIPELINE_STAGE_TRANSFER_BIT, 0};
constexpr vk::Access kColourWrite{VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                                  VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT};
// Presentation needs no access mask: the semaphore it waits for makes the writes visible.
constexpr vk::Access kPresent{VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0};

bool operator==(VkExtent2D a, VkExtent2D b) { return a.width == b.width && a.height == b.height; }

bool hasPixels(const FrameSource& source) {
  return source.buffer != VK_NULL_HANDLE && source.extent.width > 0 && source.extent.height > 0;
}

VkFormat rgbaFormatFor(VkFormat swapchainFormat) {
  const bool srgb =
      swapchainFormat == VK_FORMAT_B8G8R8A8_SRGB || swapchainFormat == VK_FORMAT_R8G8B8A8_SRGB;
  return srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
}

}  // namespace

FramePresenter::FramePresenter(const vk::Context& ctx, Window& window,
                               const PresenterOptions& options)
    : ctx_(&ctx),
      window_(&window),
      options_(options),
      swapchain_(ctx, window.framebufferExtent(), options.presentMode),
      requestedExtent_(window.framebufferExtent()),
      overlayPass_(ctx, swapchain_.format()),
      slots_(ctx, std::max(options.framesInFlight, 1u)) {
  adoptSwapchain();
}

FramePresenter::~FramePresenter() { vkDeviceWaitIdle(ctx_->device()); }

bool FramePresenter::recreateSwapchain(VkExtent2D extent) {
  overlayPass_.detach();
  const bool recreated = swapchain_.recreate(extent);
  adoptSwapchain();
  if (recreated) {
    requestedExtent_ = extent;
    swapchainStale_ = false;
  }
  return recreated;
}

void FramePresenter::adoptSwapchain() {
  overlayPass_.attach(swapchain_);
  renderFinished_.clear();
  for (uint32_t i = 0; i < swapchain_.imageCount(); ++i) {
    renderFinished_.push_back(createSemaphore(*ctx_));
  }
  imageFence_.assign(swapchain_.imageCount(), VK_NULL_HANDLE);
}

std::optional<Frame> FramePresenter::beginFrame() {
  if (current_) throw std::logic_error("FramePresenter::beginFrame: the last frame was not ended");
  const VkExtent2D extent = window_->framebufferExtent();
  if (extent.width == 0 || extent.height == 0) return std::nullopt;
  if (swapchainStale_ || !(extent == requestedExtent_)) {
    if (!recreateSwapchain(extent)) return std::nullopt;
  }

  FrameSlot& slot = slots_[slot_];
  const VkFence finished = slot.finished.get();
  AMRSTREAM_VK_CHECK(vkWaitForFences(ctx_->device(), 1, &finished, VK_TRUE, UINT64_MAX));

  uint32_t imageIndex = 0;
  const VkResult acquired =
      vkAcquireNextImageKHR(ctx_->device(), swapchain_.handle(), UINT64_MAX,
                            slot.imageAcquired.get(), VK_NULL_HANDLE, &imageIndex);
  if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
    // Nothing was acquired, so the semaphore stays unsignalled and the slot can be used again.
    swapchainStale_ = true;
    recreateSwapchain(extent);
    return std::nullopt;
  }
  if (acquired == VK_SUBOPTIMAL_KHR) {
    swapchainStale_ = true;  // still presentable: draw this frame, recreate before the next
  } else {
    AMRSTREAM_VK_CHECK(acquired);
  }
  // Another slot may still be drawing on this image if the swapchain hands images out of order.
  const VkFence previous = imageFence_[imageIndex];
  if (previous != VK_NULL_HANDLE && previous != finished) {
    AMRSTREAM_VK_CHECK(vkWaitForFences(ctx_->device(), 1, &previous, VK_TRUE, UINT64_MAX));
  }

  const VkCommandBuffer cmd = slot.commands.get();
  AMRSTREAM_VK_CHECK(vkResetCommandBuffer(cmd, 0));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  AMRSTREAM_VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
  current_ = Frame{cmd, imageIndex, swapchain_.extent()};
  return current_;
}

void FramePresenter::copyToImage(VkCommandBuffer cmd, const FrameSource& source) {
  const VkFormat format = rgbaFormatFor(swapchain_.format());
  if (!rgbaImage_ || !(rgbaImage_.extent() == source.extent) || rgbaImage_.format() != format) {
    // Earlier frames may still be blitting from the old image.
    AMRSTREAM_VK_CHECK(vkQueueWaitIdle(ctx_->queue()));
    rgbaImage_ = RgbaImage(*ctx_, source.extent, format, "presented frame");
  }
  const VkDeviceSize size = VkDeviceSize(source.extent.width) * source.extent.height * 4;
  vk::bufferBarrier(cmd, source.buffer, source.writtenBy, vk::access::kTransferRead, source.offset,
                    size);
  // UNDEFINED discards the previous frame; the barrier still waits for its blit to read it.
  transitionImage(cmd, rgbaImage_.handle(), VK_IMAGE_LAYOUT_UNDEFINED,
                  VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, kTransferOnly, vk::access::kTransferWrite);
  VkBufferImageCopy region{};
  region.bufferOffset = source.offset;
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {source.extent.width, source.extent.height, 1};
  vkCmdCopyBufferToImage(cmd, source.buffer, rgbaImage_.handle(),
                         VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  // The renderer's next writes to its buffer wait until this copy has read it.
  vk::bufferBarrier(cmd, source.buffer, kTransferOnly, {source.writtenBy.stages, 0}, source.offset,
                    size);
  transitionImage(cmd, rgbaImage_.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                  VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, vk::access::kTransferWrite,
                  vk::access::kTransferRead);
}

void FramePresenter::blitToSwapchain(VkCommandBuffer cmd, const FrameSource& source,
                                     VkImage target) {
  const VkExtent2D extent = swapchain_.extent();
  const bool hasSource = hasPixels(source);
  const BlitRegion region = hasSource ? fitCentred(source.extent, extent) : BlitRegion{};
  if (!hasSource || !region.covers(extent)) {
    VkClearColorValue colour{};
    for (int i = 0; i < 4; ++i) colour.float32[i] = options_.clearColour[i];
    const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &colour, 1, &range);
    if (!hasSource) return;
    vk::memoryBarrier(cmd, vk::access::kTransferWrite, vk::access::kTransferWrite);
  }
  VkImageBlit blit{};
  blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  blit.srcOffsets[1] = {int32_t(source.extent.width), int32_t(source.extent.height), 1};
  blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  blit.dstOffsets[0] = {region.min.x, region.min.y, 0};
  blit.dstOffsets[1] = {region.max.x, region.max.y, 1};
  // Unscaled, NEAREST copies the bytes exactly; scaled, LINEAR avoids blocky aliasing.
  const bool unscaled =
      region.width() == source.extent.width && region.height() == source.extent.height;
  vkCmdBlitImage(cmd, rgbaImage_.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit,
                 unscaled ? VK_FILTER_NEAREST : VK_FILTER_LINEAR);
}

std::optional<vk::Buffer> FramePresenter::recordScreenshotCopy(VkCommandBuffer cmd,
                                                               VkImage target) {
  if (!screenshotRequest_) {
    transitionImage(cmd, target, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                    VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, kColourWrite, kPresent);
    return std::nullopt;
  }
  const VkExtent2D extent = swapchain_.extent();
  vk::Buffer pixels = vk::Buffer::readback(*ctx_, VkDeviceSize(extent.width) * extent.height * 4,
                                           VK_BUFFER_USAGE_TRANSFER_DST_BIT, "screenshot");
  transitionImage(cmd, target, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                  VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, kColourWrite, vk::access::kTransferRead);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {extent.width, extent.height, 1};
  vkCmdCopyImageToBuffer(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, pixels.handle(), 1,
                         &region);
  vk::bufferBarrier(cmd, pixels.handle(), vk::access::kTransferWrite, vk::access::kHostRead);
  transitionImage(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                  VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, kTransferOnly, kPresent);
  return pixels;
}

void FramePresenter::endFrame(const FrameSource& source, ImGuiLayer* overlay) {
  if (!current_) throw std::logic_error("FramePresenter::endFrame: no frame was begun");
  const Frame frame = *std::exchange(current_, std::nullopt);
  FrameSlot& slot = slots_[slot_];
  const VkCommandBuffer cmd = frame.commands;
  const VkImage target = swapchain_.image(frame.imageIndex);

  if (hasPixels(source)) copyToImage(cmd, source);
  // The submission waits for the acquire semaphore at the transfer stage, which this barrier's
  // first scope joins.
  transitionImage(cmd, target, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                  kTransferOnly, vk::access::kTransferWrite);
  blitToSwapchain(cmd, source, target);
  overlayPass_.begin(cmd, frame.imageIndex);
  if (overlay != nullptr) overlay->record(cmd);
  overlayPass_.end(cmd);
  std::optional<vk::Buffer> screenshot = recordScreenshotCopy(cmd, target);
  AMRSTREAM_VK_CHECK(vkEndCommandBuffer(cmd));

  const VkFence finished = slot.finished.get();
  const VkSemaphore acquired = slot.imageAcquired.get();
  const VkSemaphore rendered = renderFinished_[frame.imageIndex].get();
  const VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_TRANSFER_BIT;
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.waitSemaphoreCount = 1;
  submit.pWaitSemaphores = &acquired;
  submit.pWaitDstStageMask = &waitStage;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  submit.signalSemaphoreCount = 1;
  submit.pSignalSemaphores = &rendered;
  // Reset only now: had recording thrown, the fence would still be signalled for the next wait.
  AMRSTREAM_VK_CHECK(vkResetFences(ctx_->device(), 1, &finished));
  AMRSTREAM_VK_CHECK(vkQueueSubmit(ctx_->queue(), 1, &submit, finished));
  imageFence_[frame.imageIndex] = finished;
  slot_ = (slot_ + 1) % slots_.size();

  const VkSwapchainKHR swapchain = swapchain_.handle();
  VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  present.waitSemaphoreCount = 1;
  present.pWaitSemaphores = &rendered;
  present.swapchainCount = 1;
  present.pSwapchains = &swapchain;
  present.pImageIndices = &frame.imageIndex;
  const VkResult presented = vkQueuePresentKHR(ctx_->queue(), &present);
  if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR) {
    swapchainStale_ = true;
  } else {
    AMRSTREAM_VK_CHECK(presented);
  }

  if (screenshot) {
    AMRSTREAM_VK_CHECK(vkWaitForFences(ctx_->device(), 1, &finished, VK_TRUE, UINT64_MAX));
    screenshot->invalidateMapped();
    const ScreenshotCallback callback = std::exchange(screenshotRequest_, nullptr);
    callback(toScreenshot(screenshot->mapped(), swapchain_.extent(), swapchain_.format()));
  }
}

void FramePresenter::requestScreenshot(ScreenshotCallback callback) {
  screenshotRequest_ = std::move(callback);
}

}  // namespace amrstream::app
