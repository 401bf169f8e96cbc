#pragma once
// FramePresenter: puts the renderer's RGBA8 buffer on the window each frame, under the overlay.
// Per frame it acquires a swapchain image, copies the buffer into an RGBA image, blits that onto
// the swapchain image (converting to its format, scaled to fit and centred, bars in the clear
// colour), draws the overlay in the OverlayPass, optionally copies the result for a screenshot,
// submits and presents. Up to `framesInFlight` frames are recorded before the oldest has
// finished. The swapchain is recreated when the window's size changes or presentation reports
// it out of date or suboptimal.
//
//   window.pollEvents();
//   imgui.newFrame();  ... ImGui calls ...
//   if (auto frame = presenter.beginFrame()) {
//     renderer.record(frame->commands, frame->extent);  // optional: this frame's GPU work
//     presenter.endFrame({renderer.image(), 0, renderer.extent()}, &imgui);
//   }
//
// Create in this order, destroy in the reverse: Window, Context (built with presentation() from
// the window), FramePresenter, ImGuiLayer (for overlayRenderPass() and framesInFlight()).
// Owns the swapchain, the overlay pass, the frame slots and the RGBA image. Neither copyable nor
// movable. Main thread only.

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "app/frame_slots.hpp"
#include "app/overlay_pass.hpp"
#include "app/rgba_image.hpp"
#include "app/screenshot.hpp"
#include "app/swapchain.hpp"
#include "vk/buffer.hpp"
#include "vk/commands.hpp"
#include "vk/unique_handle.hpp"

namespace amrstream::vk {
class Context;
}

namespace amrstream::app {

class ImGuiLayer;
class Window;

struct PresenterOptions {
  PresentMode presentMode = PresentMode::Fifo;
  uint32_t framesInFlight = 2;
  // Around a frame whose shape differs from the window's, and where there is no frame; display
  // values (UNORM), as in the frame's bytes.
  std::array<float, 4> clearColour = {0.0f, 0.0f, 0.0f, 1.0f};
};

// The renderer's image for one frame: extent.width * extent.height RGBA8 pixels, row-major, top
// row first, tightly packed from `offset` in `buffer` (which needs TRANSFER_SRC usage). Written
// on the context's queue before the frame's copy, by commands submitted earlier or recorded into
// Frame::commands, whose writes `writtenBy` names. The presenter orders later device writes after
// its copy, but the host must not write the buffer while frames are in flight. A null buffer
// shows the clear colour.
struct FrameSource {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceSize offset = 0;
  VkExtent2D extent{};
  vk::Access writtenBy{VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT};
};

struct Frame {
  VkCommandBuffer commands = VK_NULL_HANDLE;  // begun; submitted by endFrame()
  uint32_t imageIndex = 0;
  VkExtent2D extent{};  // the swapchain image's: render at this size for a 1:1 copy
};

class FramePresenter {
 public:
  // Throws ContextError when the context cannot present (built without presentation(), or the
  // surface offers no usable format), VulkanError when a Vulkan call fails.
  FramePresenter(const vk::Context& ctx, Window& window, const PresenterOptions& options = {});
  ~FramePresenter();
  FramePresenter(const FramePresenter&) = delete;
  FramePresenter& operator=(const FramePresenter&) = delete;

  // Waits until this slot's previous frame has finished, recreates the swapchain if needed,
  // acquires an image and begins the frame's command buffer. Returns nothing when there is
  // nothing to draw on: the window is minimised, or the swapchain was out of date and has just
  // been recreated. Then skip the frame (endFrame() must not be called) and try again.
  std::optional<Frame> beginFrame();
  // Records the copy, blit, overlay and screenshot copy for the frame begun last, submits it and
  // presents. `overlay` may be null.
  void endFrame(const FrameSource& source, ImGuiLayer* overlay);

  // The next frame presented (with its overlay) is read back and handed to `callback` before
  // that frame's endFrame() returns; that endFrame() waits for the device.
  void requestScreenshot(ScreenshotCallback callback);

  VkRenderPass overlayRenderPass() const { return overlayPass_.renderPass(); }
  uint32_t framesInFlight() const { return slots_.size(); }
  VkExtent2D extent() const { return swapchain_.extent(); }
  const Swapchain& swapchain() const { return swapchain_; }

 private:
  // False while the surface has no area; the old swapchain stays, marked stale.
  bool recreateSwapchain(VkExtent2D extent);
  // Framebuffers, semaphores and fence slots for the swapchain's current images.
  void adoptSwapchain();
  void copyToImage(VkCommandBuffer cmd, const FrameSource& source);
  void blitToSwapchain(VkCommandBuffer cmd, const FrameSource& source, VkImage target);
  // With a screenshot requested: the copy of the presented image, and where it goes.
  std::optional<vk::Buffer> recordScreenshotCopy(VkCommandBuffer cmd, VkImage target);

  const vk::Context* ctx_;
  Window* window_;
  PresenterOptions options_;
  Swapchain swapchain_;
  VkExtent2D requestedExtent_{};
  bool swapchainStale_ = false;
  OverlayPass overlayPass_;
  FrameSlots slots_;
  // Per swapchain image: the semaphore its presentation waits for (per image rather than per
  // slot, as the presentation engine may still hold it when the slot comes round again), and the
  // fence of the frame that last drew on it.
  std::vector<vk::UniqueHandle<VkSemaphore>> renderFinished_;
  std::vector<VkFence> imageFence_;
  RgbaImage rgbaImage_;
  uint32_t slot_ = 0;
  std::optional<Frame> current_;
  ScreenshotCallback screenshotRequest_;
};

}  // namespace amrstream::app
