#pragma once
// Text burnt into images: anti-aliased glyphs of a TrueType or OpenType font, rendered by
// FreeType at a size in pixels (the em square; FT_Set_Pixel_Sizes) and kerned where the font has
// kerning. Text is UTF-8 (invalid bytes show as U+FFFD); characters the font lacks show as its
// missing-glyph box.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string_view>

#include "render/image/image.hpp"

namespace amrstream::render {

constexpr int kMaxFontPixelSize = 1024;

// The rows a line of text takes around its baseline: the face's ascender and descender at that
// size, rounded to whole pixels.
struct LineMetrics {
  int ascent = 0;   // rows above the baseline
  int descent = 0;  // rows from the baseline down, positive
  int height() const { return ascent + descent; }
};

// One font face with its rendered glyphs cached per pixel size. Every method may be called from
// several threads at once. The pixel sizes must lie in [1, kMaxFontPixelSize]
// (std::invalid_argument otherwise).
class Font {
 public:
  // Throws std::runtime_error naming `path` when it is missing or not a font FreeType can scale.
  explicit Font(const std::filesystem::path& path);
  ~Font();
  Font(const Font&) = delete;
  Font& operator=(const Font&) = delete;

  LineMetrics lineMetrics(int pixelSize) const;
  // How far the pen travels over `text`, in pixels rounded up; 0 for empty text. A glyph's ink
  // may reach a pixel or so beyond either end.
  int textWidth(std::string_view text, int pixelSize) const;
  // Draws `text` from column x with its baseline at row `baseline`: the ink of letters without
  // descenders ends on the row above it. Each pixel blends `colour` with its alpha times the
  // glyph's coverage; pixels outside the image are skipped, so any position is safe.
  void drawText(Image& image, int x, int baseline, std::string_view text, Rgba8 colour,
                int pixelSize) const;

 private:
  struct Glyphs;
  std::unique_ptr<Glyphs> glyphs_;
};

// The size of text burnt into an image beside the picture (colour bar, axes, triad): 1.6 % of
// the image's shorter side, 11 to 48 px.
inline constexpr int kSmallestLabelPixelSize = 11, kLargestLabelPixelSize = 48;
int overlayLabelPixelSize(std::uint32_t width, std::uint32_t height);

// The font file to use: $AMRSTREAM_FONT when it is set and not empty, else the path built in
// (CMake's AMRSTREAM_FONT_PATH, by default Debian's fonts-dejavu-core DejaVu Sans).
std::filesystem::path fontPath();

// The Font at fontPath(), loaded on first use and kept for the process. Throws as Font's
// constructor does when it cannot be loaded, and tries again on the next call.
const Font& defaultFont();

}  // namespace amrstream::render
