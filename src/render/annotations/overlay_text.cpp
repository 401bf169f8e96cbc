#include "render/annotations/overlay_text.hpp"

#include <algorithm>
#include <cmath>

#include "render/image/font.hpp"

namespace amrstream::render {

PlacedText placeTextCentredOn(std::string text, glm::vec2 centre, int pixelSize) {
  const Font& font = defaultFont();
  const LineMetrics line = font.lineMetrics(pixelSize);
  const int width = font.textWidth(text, pixelSize);
  const int x = static_cast<int>(std::lround(centre.x - 0.5f * width));
  const int top = static_cast<int>(std::lround(centre.y - 0.5f * line.height()));
  return {std::move(text), x, top + line.ascent, {x, top, width, line.height()}};
}

PlacedText placeTextBeyond(std::string text, glm::vec2 anchor, glm::vec2 direction, int pixelSize) {
  const Font& font = defaultFont();
  const glm::vec2 halfBox(0.5f * font.textWidth(text, pixelSize),
                          0.5f * font.lineMetrics(pixelSize).height());
  // How far the box reaches from its centre back towards `anchor`.
  const float reach = std::abs(direction.x) * halfBox.x + std::abs(direction.y) * halfBox.y;
  return placeTextCentredOn(std::move(text), anchor + reach * direction, pixelSize);
}

bool boxesOverlap(const PixelRect& a, const PixelRect& b, int spacing) {
  return a.x < b.x + b.width + spacing && b.x < a.x + a.width + spacing &&
         a.y < b.y + b.height + spacing && b.y < a.y + a.height + spacing;
}

void drawPlacedText(Image& image, const PlacedText& text, Rgba8 colour, int pixelSize) {
  if (!text.text.empty())
    defaultFont().drawText(image, text.x, text.baseline, text.text, colour, pixelSize);
}

}  // namespace amrstream::render
