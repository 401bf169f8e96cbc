#include "app/glfw_session.hpp"

#include <vulkan/vulkan.h>
// After vulkan.h, so that GLFW declares its Vulkan functions.
#include <GLFW/glfw3.h>
#include <fmt/format.h>

#include <cstdlib>

#include "app/window_error.hpp"

namespace amrstream::app {
namespace {

int sessionCount = 0;
std::string lastError;

void recordError(int code, const char* description) {
  lastError = fmt::format("{} (GLFW error 0x{:x})", description ? description : "unknown", code);
}

bool environmentSet(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0';
}

}  // namespace

std::string lastGlfwError() { return lastError; }

GlfwSession::GlfwSession() {
  if (sessionCount > 0) {
    ++sessionCount;
    return;
  }
  if (!environmentSet("DISPLAY") && !environmentSet("WAYLAND_DISPLAY")) {
    throw WindowError(
        "cannot open a window: no display (DISPLAY unset); run under xvfb-run or use "
        "`amrstream render`");
  }
  glfwSetErrorCallback(&recordError);
  if (glfwInit() != GLFW_TRUE) {
    throw WindowError(
        fmt::format("cannot open a window: GLFW could not initialise: {}; check DISPLAY, run under "
                    "xvfb-run or use `amrstream render`",
                    lastError));
  }
  if (glfwVulkanSupported() != GLFW_TRUE) {
    glfwTerminate();
    throw WindowError(
        "cannot open a window: GLFW found no Vulkan loader (Debian: apt-get install libvulkan1 "
        "mesa-vulkan-drivers)");
  }
  ++sessionCount;
}

GlfwSession::~GlfwSession() {
  if (--sessionCount == 0) glfwTerminate();
}

std::vector<std::string> GlfwSession::requiredInstanceExtensions() const {
  uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  if (names == nullptr) {
    throw WindowError(fmt::format(
        "cannot present to a window: GLFW knows no Vulkan surface extension here: {}", lastError));
  }
  return {names, names + count};
}

}  // namespace amrstream::app
