#pragma once
// ImGuiLayer: Dear ImGui on one window: the ImGui context, its GLFW backend (installed after the
// Window's input callbacks, which it chains to) and its Vulkan backend (pipeline for the overlay
// render pass, font texture, a descriptor pool for it). Per frame:
//
//   imgui.newFrame();                    // then any ImGui:: calls
//   ... presenter.endFrame(source, &imgui);   // draws it inside the overlay pass via record()
//
// The backends keep global state, so only one ImGuiLayer may exist at a time; neither copyable
// nor movable. The context, the window and the render pass must outlive it; it waits for the
// device to be idle before it shuts the backends down.

#include <vulkan/vulkan.h>

#include <cstdint>

#include "app/input.hpp"
#include "vk/unique_handle.hpp"

namespace amrstream::vk {
class Context;
}

namespace amrstream::app {

class Window;

class ImGuiLayer {
 public:
  // `framesInFlight`: how many frames may be recorded before the oldest has finished; the backend
  // keeps that many vertex buffers. Throws std::logic_error when another ImGuiLayer exists,
  // VulkanError when the backend fails.
  ImGuiLayer(const vk::Context& ctx, Window& window, VkRenderPass renderPass,
             uint32_t framesInFlight);
  ~ImGuiLayer();
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;

  // Starts an ImGui frame (dropping one that was started but never drawn).
  void newFrame();
  // `input` without what ImGui took: mouse movement, buttons and wheel while the mouse is over an
  // ImGui window or dragging one, key presses while a text field has focus. Call after
  // newFrame(), which decides it.
  InputFrame uncaptured(InputFrame input) const;
  // Ends the ImGui frame and records its drawing into `cmd`, which must be inside the render pass
  // given to the constructor. Records nothing when no frame was started.
  void record(VkCommandBuffer cmd);

 private:
  // Undoes one step of the set-up when destroyed. As members they undo in reverse order, also
  // when a later step throws.
  class Undo {
   public:
    explicit Undo(void (*undo)()) : undo_(undo) {}
    ~Undo() { undo_(); }
    Undo(const Undo&) = delete;
    Undo& operator=(const Undo&) = delete;

   private:
    void (*undo_)();
  };

  const vk::Context* ctx_;
  Undo claim_;
  vk::UniqueHandle<VkDescriptorPool> descriptorPool_;
  Undo imguiContext_;
  Undo glfwBackend_;
  Undo vulkanBackend_;
  bool frameStarted_ = false;
};

}  // namespace amrstream::app
