#include "app/window.hpp"

#include <vulkan/vulkan.h>
// After vulkan.h, so that GLFW declares its Vulkan functions.
#include <GLFW/glfw3.h>
#include <fmt/format.h>

#include <algorithm>

#include "app/window_error.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::app {

void Window::Destroy::operator()(GLFWwindow* window) const { glfwDestroyWindow(window); }

Window::Window(const WindowOptions& options) {
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  glfwWindowHint(GLFW_RESIZABLE, options.resizable ? GLFW_TRUE : GLFW_FALSE);
  window_.reset(
      glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr));
  if (!window_) {
    throw WindowError(fmt::format("cannot open a {}x{} window: {}", options.width, options.height,
                                  lastGlfwError()));
  }
  glfwGetCursorPos(window_.get(), &input_.cursor.x, &input_.cursor.y);
  cursorKnown_ = true;
  glfwSetWindowUserPointer(window_.get(), this);
  glfwSetCursorPosCallback(window_.get(), &Window::onCursor);
  glfwSetMouseButtonCallback(window_.get(), &Window::onButton);
  glfwSetScrollCallback(window_.get(), &Window::onScroll);
  glfwSetKeyCallback(window_.get(), &Window::onKey);
}

Window::~Window() = default;

std::vector<std::string> Window::requiredInstanceExtensions() const {
  return session_.requiredInstanceExtensions();
}

vk::SurfaceFactory Window::surfaceFactory() const {
  GLFWwindow* window = window_.get();
  return [window](VkInstance instance) {
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    AMRSTREAM_VK_CHECK(glfwCreateWindowSurface(instance, window, nullptr, &surface));
    return surface;
  };
}

void Window::pollEvents() { glfwPollEvents(); }

void Window::waitEvents() { glfwWaitEvents(); }

bool Window::shouldClose() const { return glfwWindowShouldClose(window_.get()) == GLFW_TRUE; }

void Window::requestClose() { glfwSetWindowShouldClose(window_.get(), GLFW_TRUE); }

VkExtent2D Window::framebufferExtent() const {
  int width = 0;
  int height = 0;
  glfwGetFramebufferSize(window_.get(), &width, &height);
  return {static_cast<uint32_t>(std::max(width, 0)), static_cast<uint32_t>(std::max(height, 0))};
}

void Window::resize(int width, int height) { glfwSetWindowSize(window_.get(), width, height); }

InputFrame Window::takeInput() {
  InputFrame frame = input_;
  input_.cursorDelta = glm::dvec2(0.0);
  input_.scroll = glm::dvec2(0.0);
  input_.keyPresses.clear();
  return frame;
}

Window& Window::from(GLFWwindow* window) {
  return *static_cast<Window*>(glfwGetWindowUserPointer(window));
}

void Window::onCursor(GLFWwindow* window, double x, double y) {
  Window& self = from(window);
  const glm::dvec2 cursor(x, y);
  if (self.cursorKnown_) self.input_.cursorDelta += cursor - self.input_.cursor;
  self.input_.cursor = cursor;
  self.cursorKnown_ = true;
}

void Window::onButton(GLFWwindow* window, int button, int action, int /*mods*/) {
  int index = -1;
  if (button == GLFW_MOUSE_BUTTON_LEFT) index = static_cast<int>(MouseButton::Left);
  if (button == GLFW_MOUSE_BUTTON_RIGHT) index = static_cast<int>(MouseButton::Right);
  if (button == GLFW_MOUSE_BUTTON_MIDDLE) index = static_cast<int>(MouseButton::Middle);
  if (index >= 0) from(window).input_.buttonsDown[index] = action != GLFW_RELEASE;
}

void Window::onScroll(GLFWwindow* window, double dx, double dy) {
  from(window).input_.scroll += glm::dvec2(dx, dy);
}

void Window::onKey(GLFWwindow* window, int key, int /*scancode*/, int action, int mods) {
  if (action == GLFW_RELEASE || key == GLFW_KEY_UNKNOWN) return;
  from(window).input_.keyPresses.push_back({key, mods, action == GLFW_REPEAT});
}

}  // namespace amrstream::app
