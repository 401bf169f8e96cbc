#include "render/annotations/overlay_text.hpp"

#include <algorithm>
#include <cmath>

#include "render/image/font.hpp"

namespace amrstream::render {

PlacedText placeTextCentredOn(std::string text, glm::vec2 centre, int pixelSize) {
  const Font& font = defaultFont();
  const int width = font.textWidth(text, pixelSize);
  const int x = static_cast<int>(std::lround(centre.x - 0.5f * width));
  const int top =
      static_cast<int>(std::lround(centre.y - 0.5f * font.lineMetrics(pixelSize).height()));
  return placeText(std::move(text), x, top, pixelSize);
}

PlacedText placeTextBeyond(std::string text, glm::vec2 anchor, glm::vec2 direction, int pixelSize) {
  const Font& font = defaultFont();
  const glm::vec2 halfBox(0.5f * font.textWidth(text, pixelSize),
                          0.5f * font.lineMetrics(pixelSize).height());
  // How far the box reaches from its centre back towards `anchor`.
  const float reach = std::abs(direction.x) * halfBox.x + std::abs(direction.y) * halfBox.y;
  return placeTextCentredOn(std::move(text), anchor + reach * direction, pixelSize);
}

}  // namespace amrstream::render
