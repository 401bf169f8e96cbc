#pragma once
// What the user did since the previous Window::takeInput(), for a camera or shortcuts: where the
// cursor is and how far it moved, which mouse buttons are held, how far the wheel turned and
// which keys were pressed. Plain data; coordinates are window coordinates (screen units, origin
// top left), which differ from framebuffer pixels on high-DPI screens.

#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <vector>

namespace amrstream::app {

enum class MouseButton : uint8_t { Left, Right, Middle };

struct KeyPress {
  int key = 0;   // GLFW_KEY_*
  int mods = 0;  // GLFW_MOD_* bits
  bool repeat = false;
};

struct InputFrame {
  glm::dvec2 cursor{0.0};
  glm::dvec2 cursorDelta{0.0};
  glm::dvec2 scroll{0.0};             // y > 0: wheel turned away from the user
  std::array<bool, 3> buttonsDown{};  // indexed by MouseButton
  std::vector<KeyPress> keyPresses;   // in the order they happened

  bool down(MouseButton button) const { return buttonsDown[static_cast<size_t>(button)]; }
};

}  // namespace amrstream::app
