#pragma once
// GlfwSession: GLFW initialised while at least one session lives (counted, so windows can each
// hold one). GLFW allows its calls on the main thread only, and so does this class.

#include <string>
#include <vector>

namespace amrstream::app {

class GlfwSession {
 public:
  // Throws WindowError when there is no display, when GLFW cannot initialise (with GLFW's own
  // message) or when GLFW finds no Vulkan loader.
  GlfwSession();
  ~GlfwSession();
  GlfwSession(const GlfwSession&) = delete;
  GlfwSession& operator=(const GlfwSession&) = delete;

  // The instance extensions GLFW's surfaces need (VK_KHR_surface and VK_KHR_xcb_surface on X11).
  std::vector<std::string> requiredInstanceExtensions() const;
};

// GLFW's latest error message ("X11: Failed to open display :7"), or "" if none.
std::string lastGlfwError();

}  // namespace amrstream::app
