#pragma once
// A 5x7 pixel font for labels burnt into images: printable ASCII (32..126), one column between
// characters, every other byte drawn as '?'. `scale` magnifies each font pixel to a scale x scale
// block (spacing included); it must be at least 1 (std::invalid_argument otherwise).

#include <string_view>

#include "render/image/image.hpp"

namespace amrstream::render {

int textWidth(std::string_view text, int scale);  // pixels; 0 for empty text
int textHeight(int scale);                        // 7 * scale

// Draws `text` with its top-left corner at (x, y), blending `colour` by its alpha. Pixels that
// fall outside the image are skipped, so any position is safe.
void drawText(Image& image, int x, int y, std::string_view text, Rgba8 colour, int scale = 1);

}  // namespace amrstream::render
