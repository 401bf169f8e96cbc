#include "render/image/font.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <mutex>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include "render/image/freetype_handles.hpp"
#include "render/image/utf8.hpp"

#ifndef AMRSTREAM_DEFAULT_FONT_PATH
#error "AMRSTREAM_DEFAULT_FONT_PATH must name the font file used when AMRSTREAM_FONT is not set"
#endif

namespace amrstream::render {
namespace {

// FreeType's positions are in 26.6 fixed point: 64ths of a pixel.
constexpr FT_Pos kOnePixel = 64;

int roundedPixels(FT_Pos position) {
  return static_cast<int>((position + kOnePixel / 2) >> 6);  // arithmetic shift: floor
}
int pixelsUp(FT_Pos position) { return static_cast<int>((position + kOnePixel - 1) >> 6); }

struct Glyph {
  FT_UInt index = 0;   // in the face; 0 is the missing-glyph box
  FT_Pos advance = 0;  // 26.6
  int left = 0;        // the bitmap's first column, from the pen
  int top = 0;         // rows of the bitmap above the baseline
  int width = 0, rows = 0;
  std::vector<std::uint8_t> coverage;  // rows * width, row-major, top row first
};

struct SizedGlyphs {
  LineMetrics metrics;
  std::unordered_map<char32_t, Glyph> byCodePoint;
};

void requirePixelSize(int pixelSize) {
  if (pixelSize < 1 || pixelSize > kMaxFontPixelSize) {
    throw std::invalid_argument(
        fmt::format("text size {} px is outside 1 to {}", pixelSize, kMaxFontPixelSize));
  }
}

}  // namespace

// FreeType faces are not thread-safe: everything that touches the face or the cache holds mutex.
struct Font::Glyphs {
  detail::FreeTypeLibrary library;
  detail::FreeTypeFace face;  // after library, so that it is destroyed first
  std::mutex mutex;
  std::map<int, SizedGlyphs> sizes;
  int selectedSize = 0;  // the face's current pixel size; 0 before the first

  explicit Glyphs(const std::filesystem::path& path)
      : library(detail::openFreeType()), face(detail::openFace(library.get(), path)) {}

  // The glyphs at pixelSize, with the face set to that size for loading more.
  SizedGlyphs& select(int pixelSize) {
    requirePixelSize(pixelSize);
    if (selectedSize != pixelSize) {
      const auto size = static_cast<FT_UInt>(pixelSize);
      if (const FT_Error error = FT_Set_Pixel_Sizes(face.get(), size, size)) {
        throw std::runtime_error(fmt::format("cannot set the font to {} px: {}", pixelSize,
                                             detail::freeTypeErrorText(error)));
      }
      selectedSize = pixelSize;
    }
    auto [entry, added] = sizes.try_emplace(pixelSize);
    if (added) {
      const FT_Size_Metrics& metrics = face->size->metrics;
      entry->second.metrics = {pixelsUp(metrics.ascender), pixelsUp(-metrics.descender)};
    }
    return entry->second;
  }

  // Needs select(pixelSize) of the same size first.
  const Glyph& glyphOf(SizedGlyphs& sized, char32_t c) {
    auto [entry, added] = sized.byCodePoint.try_emplace(c);
    if (added) entry->second = render(FT_Get_Char_Index(face.get(), c));
    return entry->second;
  }

  Glyph render(FT_UInt index) {
    // Outlines only (no embedded bitmaps), rendered as 8-bit coverage.
    if (FT_Load_Glyph(face.get(), index, FT_LOAD_NO_BITMAP | FT_LOAD_RENDER) != 0) return {};
    const FT_GlyphSlot slot = face->glyph;
    const FT_Bitmap& bitmap = slot->bitmap;
    if (bitmap.pixel_mode != FT_PIXEL_MODE_GRAY && bitmap.rows > 0) {
      throw std::runtime_error("FreeType rendered a glyph in another mode than 8-bit grey");
    }
    Glyph glyph{.index = index,
                .advance = slot->advance.x,
                .left = slot->bitmap_left,
                .top = slot->bitmap_top,
                .width = static_cast<int>(bitmap.width),
                .rows = static_cast<int>(bitmap.rows),
                .coverage = {}};
    glyph.coverage.resize(std::size_t{bitmap.width} * bitmap.rows);
    for (unsigned row = 0; row < bitmap.rows; ++row) {
      const unsigned char* source = bitmap.buffer + std::ptrdiff_t{bitmap.pitch} * row;
      std::copy_n(source, bitmap.width, glyph.coverage.begin() + std::size_t{row} * bitmap.width);
    }
    return glyph;
  }

  FT_Pos kerning(FT_UInt left, FT_UInt right) {
    if (left == 0 || right == 0 || !FT_HAS_KERNING(face.get())) return 0;
    FT_Vector delta{};
    if (FT_Get_Kerning(face.get(), left, right, FT_KERNING_DEFAULT, &delta) != 0) return 0;
    return delta.x;
  }

  // Calls place(glyph, pen) with each glyph and the pen's position (26.6, from the start) where
  // it goes; returns where the pen ends.
  template <typename Place>
  FT_Pos layOut(std::string_view text, int pixelSize, Place&& place) {
    SizedGlyphs& sized = select(pixelSize);
    FT_Pos pen = 0;
    FT_UInt previous = 0;
    for (const char32_t c : decodeUtf8(text)) {
      const Glyph& glyph = glyphOf(sized, c);
      pen += kerning(previous, glyph.index);
      place(glyph, pen);
      pen += glyph.advance;
      previous = glyph.index;
    }
    return pen;
  }
};

namespace {

// Positions are 64-bit so that far-off text cannot overflow while it is being clipped.
void blendGlyph(Image& image, const Glyph& glyph, std::int64_t x0, std::int64_t y0, Rgba8 colour) {
  const std::int64_t width = image.width, height = image.height;
  const std::int64_t rowBegin = std::max<std::int64_t>(0, -y0);
  const std::int64_t rowEnd = std::min<std::int64_t>(glyph.rows, height - y0);
  const std::int64_t columnBegin = std::max<std::int64_t>(0, -x0);
  const std::int64_t columnEnd = std::min<std::int64_t>(glyph.width, width - x0);
  for (std::int64_t row = rowBegin; row < rowEnd; ++row) {
    for (std::int64_t column = columnBegin; column < columnEnd; ++column) {
      const unsigned coverage =
          glyph.coverage[static_cast<std::size_t>(row * glyph.width + column)];
      const unsigned alpha = (coverage * colour.a + 127u) / 255u;
      if (alpha == 0) continue;
      image.blend(static_cast<std::uint32_t>(x0 + column), static_cast<std::uint32_t>(y0 + row),
                  {colour.r, colour.g, colour.b, static_cast<std::uint8_t>(alpha)});
    }
  }
}

}  // namespace

Font::Font(const std::filesystem::path& path) : glyphs_(std::make_unique<Glyphs>(path)) {}

Font::~Font() = default;

LineMetrics Font::lineMetrics(int pixelSize) const {
  const std::lock_guard lock(glyphs_->mutex);
  return glyphs_->select(pixelSize).metrics;
}

int Font::textWidth(std::string_view text, int pixelSize) const {
  const std::lock_guard lock(glyphs_->mutex);
  return pixelsUp(glyphs_->layOut(text, pixelSize, [](const Glyph&, FT_Pos) {}));
}

void Font::drawText(Image& image, int x, int baseline, std::string_view text, Rgba8 colour,
                    int pixelSize) const {
  const std::lock_guard lock(glyphs_->mutex);
  glyphs_->layOut(text, pixelSize, [&](const Glyph& glyph, FT_Pos pen) {
    if (glyph.coverage.empty()) return;
    blendGlyph(image, glyph, std::int64_t{x} + roundedPixels(pen) + glyph.left,
               std::int64_t{baseline} - glyph.top, colour);
  });
}

int overlayLabelPixelSize(std::uint32_t width, std::uint32_t height) {
  const double shorterSide = std::min(width, height);
  return std::clamp(static_cast<int>(std::lround(0.016 * shorterSide)), kSmallestLabelPixelSize,
                    kLargestLabelPixelSize);
}

std::filesystem::path fontPath() {
  const char* setting = std::getenv("AMRSTREAM_FONT");
  if (setting != nullptr && *setting != '\0') return setting;
  return AMRSTREAM_DEFAULT_FONT_PATH;
}

const Font& defaultFont() {
  // A static local's initialisation runs once even when threads race; if it throws, the next
  // call tries again.
  static const Font font(fontPath());
  return font;
}

}  // namespace amrstream::render
