#include "render/image/colour_bar_layout.hpp"

#include <algorithm>

#include "render/image/bitmap_font.hpp"

namespace amrstream::render {
namespace {

constexpr int kMinGradientWidth = 64;

int preferredScale(std::uint32_t width) {
  if (width >= 1536) return 3;
  if (width >= 512) return 2;
  return 1;
}

// `text` if it fits in maxWidth, else its longest prefix that fits with ".." appended.
std::string fitText(std::string text, int maxWidth, int scale) {
  if (textWidth(text, scale) <= maxWidth) return text;
  text.resize(std::min<std::size_t>(text.size(), static_cast<std::size_t>(maxWidth / scale)));
  while (!text.empty() && (text.back() == ' ' || textWidth(text + "..", scale) > maxWidth)) {
    text.pop_back();
  }
  return text + "..";
}

// The layout at text scale `scale`, or nullopt when it does not fit the image (or, with
// valuesMustFit, when the two range values would touch).
std::optional<ColourBarLayout> layoutAtScale(int width, int height, const ColourBar& bar, int scale,
                                             bool valuesMustFit) {
  const int margin = 4 * scale;   // image edge to panel
  const int padding = 4 * scale;  // panel edge to contents
  const int gap = 3 * scale;      // text to gradient; holds the gradient's 1-pixel frame
  const int gradientHeight = 8 * scale;
  const int lineHeight = textHeight(scale);

  ColourBarLayout layout;
  layout.scale = scale;
  layout.minValue.text = formatBarValue(bar.min);
  layout.maxValue.text = formatBarValue(bar.max);
  const int minWidth = textWidth(layout.minValue.text, scale);
  const int maxWidth = textWidth(layout.maxValue.text, scale);
  const int valuesWidth = minWidth + textWidth("  ", scale) + maxWidth;

  const int available = width - 2 * margin - 2 * padding;
  const int wanted =
      std::max({kMinGradientWidth, width / 3, valuesWidth, textWidth(bar.label, scale)});
  const int gradientWidth = std::min(wanted, available);
  if (gradientWidth < kMinGradientWidth || (valuesMustFit && valuesWidth > gradientWidth)) {
    return std::nullopt;
  }
  const int labelBlock = bar.label.empty() ? 0 : lineHeight + gap;
  const int panelHeight = padding + labelBlock + gradientHeight + gap + lineHeight + padding;
  if (panelHeight + 2 * margin > height) return std::nullopt;

  layout.panel = {width - margin - (gradientWidth + 2 * padding), height - margin - panelHeight,
                  gradientWidth + 2 * padding, panelHeight};
  layout.gradient = {layout.panel.x + padding, layout.panel.y + padding + labelBlock, gradientWidth,
                     gradientHeight};
  if (!bar.label.empty()) {
    layout.label.text = fitText(bar.label, gradientWidth, scale);
    layout.label.x = layout.gradient.x + (gradientWidth - textWidth(layout.label.text, scale)) / 2;
    layout.label.y = layout.panel.y + padding;
  }
  const int valuesY = layout.gradient.y + gradientHeight + gap;
  layout.minValue.x = layout.gradient.x;
  layout.minValue.y = valuesY;
  layout.maxValue.x = layout.gradient.x + gradientWidth - maxWidth;
  layout.maxValue.y = valuesY;
  return layout;
}

}  // namespace

std::optional<ColourBarLayout> layoutColourBar(std::uint32_t width, std::uint32_t height,
                                               const ColourBar& bar) {
  if (width < kMinColourBarImageSide || height < kMinColourBarImageSide) return std::nullopt;
  // Far beyond any render target; keeps the int arithmetic above exact.
  const int w = static_cast<int>(std::min<std::uint32_t>(width, 1u << 20));
  const int h = static_cast<int>(std::min<std::uint32_t>(height, 1u << 20));
  for (int scale = preferredScale(width); scale >= 1; --scale) {
    if (auto layout = layoutAtScale(w, h, bar, scale, true)) return layout;
  }
  // Long values in a narrow image: the gradient takes all the width and the values come closer.
  return layoutAtScale(w, h, bar, 1, false);
}

}  // namespace amrstream::render
