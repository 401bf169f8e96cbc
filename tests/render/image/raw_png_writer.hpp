#pragma once
// Writes PNG files in any format libpng knows, straight through libpng, so that the reader can be
// tested on files our own writer never produces (gray, palette, 16-bit, interlaced).

#include <png.h>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace amrstream::testing {

struct RawPng {
  std::uint32_t width = 0, height = 0;
  int bitDepth = 8;
  int colourType = PNG_COLOR_TYPE_RGB_ALPHA;
  bool interlaced = false;
  std::vector<std::uint8_t> rows;  // packed as the file stores them: 16-bit samples big-endian
  std::vector<png_color> palette;
  std::vector<png_byte> transparentIndices;         // tRNS alpha of the first palette entries
  const png_color_16* transparentColour = nullptr;  // tRNS of gray and RGB images
};

// Throws std::runtime_error when libpng refuses.
void writeRawPng(const std::filesystem::path& path, const RawPng& png);

// Appends a 16-bit sample in PNG byte order.
void appendSample16(std::vector<std::uint8_t>& bytes, std::uint16_t sample);

}  // namespace amrstream::testing
