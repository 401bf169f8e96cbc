#include "render/image/colour_bar_layout.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "render/image/font.hpp"
#include "render/image/utf8.hpp"

namespace amrstream::render {
namespace {

constexpr int kMinGradientWidth = 64;
constexpr const char* kEllipsis = "\u2026";

// Spacing, all in pixels, that grows with the tick labels' font size s.
struct Spacing {
  int margin, padding;  // image edge to panel, panel edge to contents
  int titleGap;         // title to gradient; holds the gradient's 1-pixel frame
  int gradientHeight;
  int tickLength, tickThickness;
  int labelGap;      // tick mark to label
  int labelSpacing;  // the least room between two labels that both show
};

Spacing spacingFor(int s) {
  return {.margin = std::max(4, s / 2),
          .padding = std::max(4, s / 3),
          .titleGap = std::max(3, s / 4),
          .gradientHeight = std::max(8, s),
          .tickLength = std::max(3, s / 3),
          .tickThickness = s >= 24 ? 2 : 1,
          .labelGap = std::max(2, s / 6),
          .labelSpacing = std::max(3, s / 2)};
}

int titleSizeFor(int labelSize) { return static_cast<int>(std::lround(1.25 * labelSize)); }

// `text` if it fits in maxWidth, else its longest prefix that fits with an ellipsis appended.
std::string fitText(const std::string& text, int maxWidth, int pixelSize) {
  const Font& font = defaultFont();
  if (font.textWidth(text, pixelSize) <= maxWidth) return text;
  // No printable character is narrower than a quarter of the size: the rest cannot fit.
  std::string_view kept = text;
  const auto longest = static_cast<std::size_t>(4 * std::max(0, maxWidth) / pixelSize + 1);
  if (kept.size() > longest) kept = dropLastCodePoint(kept.substr(0, longest + 1));
  while (!kept.empty() && (kept.back() == ' ' ||
                           font.textWidth(std::string(kept) + kEllipsis, pixelSize) > maxWidth))
    kept = dropLastCodePoint(kept);
  return std::string(kept) + kEllipsis;
}

// The ticks of the scale, or for a scale that has none (min >= max, bounds that are not finite,
// a log scale reaching 0) its ends, so that the bar still says what it shows.
std::vector<ScaleTick> ticksOf(const ColourScale& scale, int most) {
  try {
    return scaleTicks(scale, most);
  } catch (const std::invalid_argument&) {
    if (scale.min == scale.max) return {{scale.min, 0.5, formatBarValue(scale.min)}};
    return {{scale.min, 0.0, formatBarValue(scale.min)},
            {scale.max, 1.0, formatBarValue(scale.max)}};
  }
}

// How many ticks to ask for: about one per three label heights of gradient; crowded labels are
// left out afterwards.
int mostTicksFor(int gradientWidth, int labelSize) {
  return std::clamp(gradientWidth / (3 * labelSize), 5, 8);
}

void leaveOut(PlacedText& label) {
  label.text.clear();
  label.box.width = 0;
}

// Leaves out labels that come within `spacing` of the previous one shown, keeping the ends.
void leaveOutCrowdedLabels(std::vector<PlacedTick>& ticks, int spacing) {
  const auto apart = [spacing](const PlacedText& left, const PlacedText& right) {
    return left.box.x + left.box.width + spacing <= right.box.x;
  };
  if (ticks.size() < 2) return;
  PlacedText& last = ticks.back().label;
  const bool keepLast = apart(ticks.front().label, last);
  const PlacedText* shown = &ticks.front().label;
  for (std::size_t i = 1; i + 1 < ticks.size(); ++i) {
    PlacedText& label = ticks[i].label;
    if (keepLast && apart(*shown, label) && apart(label, last)) {
      shown = &label;
    } else {
      leaveOut(label);
    }
  }
  if (!keepLast) leaveOut(last);
}

// The layout with tick labels of `labelSize` px, or nullopt when it does not fit the image.
std::optional<ColourBarLayout> layoutAtSize(int width, int height, const ColourBar& bar,
                                            int labelSize) {
  const Font& font = defaultFont();
  const Spacing space = spacingFor(labelSize);
  const int titleSize = titleSizeFor(labelSize);
  const LineMetrics labelLine = font.lineMetrics(labelSize);
  const LineMetrics titleLine = font.lineMetrics(titleSize);
  const std::string title = colourBarTitle(bar);

  // The gradient's width, and the room beside each end for labels centred under end ticks.
  const int available = width - 2 * space.margin - 2 * space.padding;
  if (available < kMinGradientWidth) return std::nullopt;
  const int wanted = std::max({kMinGradientWidth, width / 3, font.textWidth(title, titleSize)});
  const std::vector<ScaleTick> ticks =
      ticksOf(bar.scale, mostTicksFor(std::min(wanted, available), labelSize));
  int overhang = 0;
  if (!ticks.empty()) {
    const int widest = std::max(font.textWidth(ticks.front().label, labelSize),
                                font.textWidth(ticks.back().label, labelSize));
    overhang = (widest + 1) / 2;
  }
  int gradientWidth = std::min(wanted, available - 2 * overhang);
  if (gradientWidth < kMinGradientWidth) {
    gradientWidth = kMinGradientWidth;
    overhang = (available - gradientWidth) / 2;
  }

  const bool hasTitle = !title.empty();
  const int titleBlock = hasTitle ? titleLine.height() + space.titleGap : 0;
  const int panelHeight = space.padding + titleBlock + space.gradientHeight + space.tickLength +
                          space.labelGap + labelLine.height() + space.padding;
  const int stack = std::max(0, bar.stack);
  if ((stack + 1) * (panelHeight + space.margin) + space.margin > height) return std::nullopt;

  ColourBarLayout layout;
  layout.labelPixelSize = labelSize;
  layout.titlePixelSize = titleSize;
  const int panelWidth = gradientWidth + 2 * (overhang + space.padding);
  layout.panel = {width - space.margin - panelWidth,
                  height - (stack + 1) * (space.margin + panelHeight), panelWidth, panelHeight};
  PixelRect& g = layout.gradient;
  g = {layout.panel.x + space.padding + overhang, layout.panel.y + space.padding + titleBlock,
       gradientWidth, space.gradientHeight};
  // Labels and title stay in the lane of the gradient and the room beside it.
  const int laneLeft = g.x - overhang, laneWidth = gradientWidth + 2 * overhang;
  const auto centredInLane = [&](int centre, int textWidth) {
    return std::max(laneLeft, std::min(centre - textWidth / 2, laneLeft + laneWidth - textWidth));
  };

  if (hasTitle) {
    std::string fitted = fitText(title, laneWidth, titleSize);
    const int x = centredInLane(g.x + gradientWidth / 2, font.textWidth(fitted, titleSize));
    layout.title = placeText(std::move(fitted), x, layout.panel.y + space.padding, titleSize);
  }
  const int markTop = g.y + g.height;
  const int labelTop = markTop + space.tickLength + space.labelGap;
  for (const ScaleTick& tick : ticks) {
    PlacedTick& placed = layout.ticks.emplace_back();
    placed.value = tick.value;
    placed.x = g.x + static_cast<int>(std::lround(tick.position * (gradientWidth - 1)));
    placed.mark = {std::min(placed.x, g.x + gradientWidth - space.tickThickness), markTop,
                   space.tickThickness, space.tickLength};
    // A label wider than the lane (only in narrow images) is left out.
    std::string label = font.textWidth(tick.label, labelSize) <= laneWidth ? tick.label : "";
    const int x = centredInLane(placed.x, font.textWidth(label, labelSize));
    placed.label = placeText(std::move(label), x, labelTop, labelSize);
  }
  leaveOutCrowdedLabels(layout.ticks, space.labelSpacing);
  return layout;
}

}  // namespace

std::optional<ColourBarLayout> layoutColourBar(std::uint32_t width, std::uint32_t height,
                                               const ColourBar& bar) {
  if (width < kMinColourBarImageSide || height < kMinColourBarImageSide) return std::nullopt;
  // Far beyond any render target; keeps the int arithmetic above exact.
  const int w = static_cast<int>(std::min<std::uint32_t>(width, 1u << 20));
  const int h = static_cast<int>(std::min<std::uint32_t>(height, 1u << 20));
  for (int size = overlayLabelPixelSize(w, h); size >= kSmallestLabelPixelSize; --size) {
    if (auto layout = layoutAtSize(w, h, bar, size)) return layout;
  }
  return std::nullopt;
}

}  // namespace amrstream::render
