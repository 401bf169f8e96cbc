#pragma once
// Window: one GLFW window for Vulkan (no OpenGL context), with GLFW initialised for its lifetime.
// It collects input through GLFW callbacks into an InputFrame that takeInput() hands out once
// per frame. Dear ImGui's GLFW backend, installed later, chains to these callbacks; use
// ImGuiLayer::uncaptured() to drop what ImGui used. It must outlive the context whose surface it
// made (surfaceFactory()). Neither copyable nor movable: GLFW keeps a pointer to it. Main thread
// only.

#include <vulkan/vulkan.h>

#include <memory>
#include <string>
#include <vector>

#include "app/glfw_session.hpp"
#include "app/input.hpp"
#include "vk/presentation.hpp"

struct GLFWwindow;

namespace amrstream::app {

struct WindowOptions {
  int width = 1280;  // window coordinates
  int height = 800;
  std::string title = "amrstream";
  bool resizable = true;
};

class Window {
 public:
  // Throws WindowError (no display, GLFW failure) with what to do about it.
  explicit Window(const WindowOptions& options);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  GLFWwindow* handle() const { return window_.get(); }

  // What vk::ContextBuilder::presentation() needs to present to this window.
  std::vector<std::string> requiredInstanceExtensions() const;
  vk::SurfaceFactory surfaceFactory() const;

  // Processes pending events without blocking / blocking until one arrives (while minimised).
  void pollEvents();
  void waitEvents();
  bool shouldClose() const;
  void requestClose();
  // In pixels; {0, 0} while minimised.
  VkExtent2D framebufferExtent() const;
  // Asks for a new size in window coordinates; the window system may refuse or take a while.
  void resize(int width, int height);

  // The input since the previous call; deltas and key presses start again from nothing.
  InputFrame takeInput();

 private:
  struct Destroy {
    void operator()(GLFWwindow* window) const;
  };
  static Window& from(GLFWwindow* window);
  static void onCursor(GLFWwindow* window, double x, double y);
  static void onButton(GLFWwindow* window, int button, int action, int mods);
  static void onScroll(GLFWwindow* window, double dx, double dy);
  static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);

  GlfwSession session_;
  std::unique_ptr<GLFWwindow, Destroy> window_;
  InputFrame input_;
  bool cursorKnown_ = false;
};

}  // namespace amrstream::app
