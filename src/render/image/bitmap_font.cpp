#include "render/image/bitmap_font.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>

#include "render/image/bitmap_font_glyphs.hpp"

namespace amrstream::render {
namespace {

constexpr int kAdvance = detail::kGlyphColumns + 1;

void requireScale(int scale) {
  if (scale < 1) throw std::invalid_argument(fmt::format("text scale {} is not >= 1", scale));
}

// Positions are 64-bit so that far-off text cannot overflow while it is being clipped.
void fillClipped(Image& image, std::int64_t x0, std::int64_t y0, int size, Rgba8 colour) {
  const std::int64_t x1 = std::min<std::int64_t>(x0 + size, image.width);
  const std::int64_t y1 = std::min<std::int64_t>(y0 + size, image.height);
  for (std::int64_t y = std::max<std::int64_t>(y0, 0); y < y1; ++y) {
    for (std::int64_t x = std::max<std::int64_t>(x0, 0); x < x1; ++x) {
      image.blend(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), colour);
    }
  }
}

void drawGlyph(Image& image, std::int64_t x, std::int64_t y, char c, Rgba8 colour, int scale) {
  const detail::GlyphBits& bits = detail::glyphOf(c);
  for (int row = 0; row < detail::kGlyphRows; ++row) {
    for (int column = 0; column < detail::kGlyphColumns; ++column) {
      if (((bits[row] >> (detail::kGlyphColumns - 1 - column)) & 1u) == 0) continue;
      fillClipped(image, x + std::int64_t{column} * scale, y + std::int64_t{row} * scale, scale,
                  colour);
    }
  }
}

}  // namespace

int textWidth(std::string_view text, int scale) {
  requireScale(scale);
  if (text.empty()) return 0;
  return (static_cast<int>(text.size()) * kAdvance - 1) * scale;
}

int textHeight(int scale) {
  requireScale(scale);
  return detail::kGlyphRows * scale;
}

void drawText(Image& image, int x, int y, std::string_view text, Rgba8 colour, int scale) {
  requireScale(scale);
  const std::int64_t advance = std::int64_t{kAdvance} * scale;
  const std::int64_t bottom = std::int64_t{y} + textHeight(scale);
  if (bottom <= 0 || y >= static_cast<std::int64_t>(image.height)) return;
  std::int64_t penX = x;
  for (const char c : text) {
    if (penX >= static_cast<std::int64_t>(image.width)) break;
    if (penX + advance > 0) drawGlyph(image, penX, y, c, colour, scale);
    penX += advance;
  }
}

}  // namespace amrstream::render
