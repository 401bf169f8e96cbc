// Without a display the window says what to do instead. Each test runs in a process of its own
// (gtest_discover_tests), so GLFW has not been initialised yet.
#include "app/window_error.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

#include "app/window.hpp"

namespace amrstream::testing {
namespace {

// Unsets a variable for the scope, restoring its value (or its absence) afterwards.
class UnsetVariable {
 public:
  explicit UnsetVariable(const char* name) : name_(name) {
    if (const char* value = std::getenv(name)) saved_ = value;
    unsetenv(name);
  }
  ~UnsetVariable() {
    if (saved_) {
      setenv(name_, saved_->c_str(), 1);
    } else {
      unsetenv(name_);
    }
  }

 private:
  const char* name_;
  std::optional<std::string> saved_;
};

TEST(Window, WithoutDisplayExplainsWhatToDo) {
  const UnsetVariable display("DISPLAY");
  const UnsetVariable wayland("WAYLAND_DISPLAY");
  try {
    app::Window window(app::WindowOptions{});
    FAIL() << "a window opened without a display";
  } catch (const app::WindowError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("no display (DISPLAY unset)"), std::string::npos) << message;
    EXPECT_NE(message.find("xvfb-run"), std::string::npos) << message;
    EXPECT_NE(message.find("amrstream render"), std::string::npos) << message;
  }
}

TEST(Window, UnreachableDisplayPassesOnGlfwsReason) {
  const UnsetVariable wayland("WAYLAND_DISPLAY");
  const UnsetVariable display("DISPLAY");
  setenv("DISPLAY", ":4711", 1);  // no X server listens there
  try {
    app::Window window(app::WindowOptions{});
    FAIL() << "a window opened on a display that does not exist";
  } catch (const app::WindowError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("GLFW could not initialise"), std::string::npos) << message;
    EXPECT_NE(message.find(":4711"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace amrstream::testing
