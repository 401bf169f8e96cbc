// Input reaches the Window through Dear ImGui's GLFW callbacks, which chain to the Window's, and
// ImGuiLayer::uncaptured() drops what ImGui wants. Events are fed to the callbacks GLFW holds,
// as the X server would.
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>
#include <imgui.h>

#include "app/frame_presenter.hpp"
#include "app/imgui_layer.hpp"
#include "window_test.hpp"

namespace amrstream::testing {
namespace {

class InputTest : public WindowTest {
 protected:
  void SetUp() override {
    WindowTest::SetUp();
    if (IsSkipped() || HasFatalFailure()) return;
    try {
      buildPresentingContext();
    } catch (const vk::ContextError& error) {
      unavailable(error.what());
      return;
    }
    presenter_.emplace(*ctx_, window());
    imgui_.emplace(*ctx_, window(), presenter_->overlayRenderPass(), presenter_->framesInFlight());
  }

  void TearDown() override {
    imgui_.reset();
    presenter_.reset();
    WindowTest::TearDown();
  }

  // Sends a wheel turn, a right-button press and a key press through the installed callbacks.
  void feedEvents() {
    GLFWwindow* w = window().handle();
    GLFWscrollfun scroll = glfwSetScrollCallback(w, nullptr);
    glfwSetScrollCallback(w, scroll);
    GLFWmousebuttonfun button = glfwSetMouseButtonCallback(w, nullptr);
    glfwSetMouseButtonCallback(w, button);
    GLFWkeyfun key = glfwSetKeyCallback(w, nullptr);
    glfwSetKeyCallback(w, key);
    ASSERT_NE(scroll, nullptr);
    ASSERT_NE(button, nullptr);
    ASSERT_NE(key, nullptr);
    scroll(w, 0.0, 2.0);
    button(w, GLFW_MOUSE_BUTTON_RIGHT, GLFW_PRESS, 0);
    key(w, GLFW_KEY_R, 0, GLFW_PRESS, GLFW_MOD_SHIFT);
  }

  std::optional<app::FramePresenter> presenter_;
  std::optional<app::ImGuiLayer> imgui_;
};

TEST_F(InputTest, EventsReachBothImGuiAndTheWindow) {
  imgui_->newFrame();
  feedEvents();
  EXPECT_EQ(ImGui::GetIO().MouseWheel, 2.0f);  // ImGui's own callback ran

  const app::InputFrame input = window().takeInput();
  EXPECT_EQ(input.scroll.y, 2.0);
  EXPECT_TRUE(input.down(app::MouseButton::Right));
  EXPECT_FALSE(input.down(app::MouseButton::Left));
  ASSERT_EQ(input.keyPresses.size(), 1u);
  EXPECT_EQ(input.keyPresses[0].key, GLFW_KEY_R);
  EXPECT_EQ(input.keyPresses[0].mods, GLFW_MOD_SHIFT);

  // Deltas and presses are handed out once; held buttons stay held.
  const app::InputFrame next = window().takeInput();
  EXPECT_EQ(next.scroll.y, 0.0);
  EXPECT_TRUE(next.keyPresses.empty());
  EXPECT_TRUE(next.down(app::MouseButton::Right));
}

TEST_F(InputTest, UncapturedDropsWhatImGuiWants) {
  imgui_->newFrame();
  feedEvents();
  const app::InputFrame input = window().takeInput();

  ImGuiIO& io = ImGui::GetIO();
  io.WantCaptureMouse = false;
  io.WantCaptureKeyboard = false;
  const app::InputFrame free = imgui_->uncaptured(input);
  EXPECT_EQ(free.scroll.y, 2.0);
  EXPECT_TRUE(free.down(app::MouseButton::Right));
  EXPECT_EQ(free.keyPresses.size(), 1u);

  // As newFrame() decides when the cursor is over a panel or a text field has focus.
  io.WantCaptureMouse = true;
  io.WantCaptureKeyboard = true;
  const app::InputFrame captured = imgui_->uncaptured(input);
  EXPECT_EQ(captured.scroll.y, 0.0);
  EXPECT_FALSE(captured.down(app::MouseButton::Right));
  EXPECT_TRUE(captured.keyPresses.empty());
  EXPECT_EQ(captured.cursor, input.cursor);  // where the cursor is stays known
}

}  // namespace
}  // namespace amrstream::testing
