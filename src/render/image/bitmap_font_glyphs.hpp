#pragma once
// The glyph bitmaps of the 5x7 font. Internal to bitmap_font.cpp.

#include <array>
#include <cstdint>

namespace amrstream::render::detail {

constexpr int kGlyphColumns = 5;
constexpr int kGlyphRows = 7;

// One byte per row, top row first; bit 4 is the leftmost column.
using GlyphBits = std::array<std::uint8_t, kGlyphRows>;

// The glyph of a printable ASCII character (32..126); any other byte gets the glyph of '?'.
const GlyphBits& glyphOf(char c);

}  // namespace amrstream::render::detail
