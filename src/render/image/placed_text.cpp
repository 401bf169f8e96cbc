#include "render/image/placed_text.hpp"

#include <utility>

#include "render/image/font.hpp"

namespace amrstream::render {

PlacedText placeText(std::string text, int x, int top, int pixelSize) {
  const Font& font = defaultFont();
  const LineMetrics line = font.lineMetrics(pixelSize);
  const int width = font.textWidth(text, pixelSize);
  return {std::move(text), x, top + line.ascent, {x, top, width, line.height()}};
}

void drawPlacedText(Image& image, const PlacedText& text, Rgba8 colour, int pixelSize) {
  if (!text.text.empty())
    defaultFont().drawText(image, text.x, text.baseline, text.text, colour, pixelSize);
}

bool boxesOverlap(const PixelRect& a, const PixelRect& b, int spacing) {
  return a.x < b.x + b.width + spacing && b.x < a.x + a.width + spacing &&
         a.y < b.y + b.height + spacing && b.y < a.y + a.height + spacing;
}

}  // namespace amrstream::render
