#include "render/annotations/line_drawing.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace amrstream::render {
namespace {

struct Segment {
  glm::vec2 from, direction;  // direction: unit, or zero for a point
  float length, halfWidth;
  LineCap cap;

  // Signed distance from p to the line's outline, negative inside: exact for round caps, and
  // for butt caps everywhere except beyond the corners, where it is slightly less.
  float distanceOutside(glm::vec2 p) const {
    const glm::vec2 d = p - from;
    const float along = glm::dot(d, direction);
    if (cap == LineCap::Round) {
      const glm::vec2 nearest = from + std::clamp(along, 0.0f, length) * direction;
      return glm::length(p - nearest) - halfWidth;
    }
    const float across = std::abs(d.x * direction.y - d.y * direction.x);
    return std::max(across - halfWidth, std::max(-along, along - length));
  }
};

// The columns of row y whose pixel centres lie within `reach` of the segment, as [first, last].
struct Span {
  float first, last;
};
Span rowSpan(glm::vec2 from, glm::vec2 to, float rowCentre, float reach) {
  float low = 0.0f, high = 1.0f;  // the part of the segment within reach of the row
  const float dy = to.y - from.y;
  if (std::abs(dy) > 1e-6f) {
    low = (rowCentre - reach - from.y) / dy;
    high = (rowCentre + reach - from.y) / dy;
    if (low > high) std::swap(low, high);
    low = std::max(low, 0.0f), high = std::min(high, 1.0f);
  }
  const float x0 = from.x + low * (to.x - from.x), x1 = from.x + high * (to.x - from.x);
  return {std::min(x0, x1) - reach, std::max(x0, x1) + reach};
}

}  // namespace

void drawLine(Image& image, glm::vec2 from, glm::vec2 to, float width, Rgba8 colour, LineCap cap) {
  if (!(width > 0.0f) || image.empty()) return;
  if (!std::isfinite(from.x + from.y + to.x + to.y + width)) return;
  const float length = glm::length(to - from);
  if (cap == LineCap::Butt && !(length > 1e-6f)) return;
  const glm::vec2 direction = length > 1e-6f ? (to - from) / length : glm::vec2(0.0f);
  const Segment segment{from, direction, length, 0.5f * width, cap};
  // Pixel centres further than this from the segment get no coverage.
  const float reach = segment.halfWidth + 0.5f;

  const float top = std::max(std::floor(std::min(from.y, to.y) - reach), 0.0f);
  const float bottom =
      std::min(std::ceil(std::max(from.y, to.y) + reach), static_cast<float>(image.height) - 1);
  for (float y = top; y <= bottom; ++y) {
    const Span span = rowSpan(from, to, y + 0.5f, reach);
    const float left = std::max(std::ceil(span.first - 0.5f), 0.0f);
    const float right = std::min(std::floor(span.last - 0.5f), static_cast<float>(image.width) - 1);
    for (float x = left; x <= right; ++x) {
      const float coverage =
          std::clamp(0.5f - segment.distanceOutside({x + 0.5f, y + 0.5f}), 0.0f, 1.0f);
      const auto alpha = static_cast<std::uint8_t>(std::lround(coverage * colour.a));
      if (alpha == 0) continue;
      image.blend(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y),
                  {colour.r, colour.g, colour.b, alpha});
    }
  }
}

}  // namespace amrstream::render
