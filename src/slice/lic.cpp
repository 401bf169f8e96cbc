#include "lic.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <stdexcept>

namespace amrstream::slice {
namespace {

// Jarzynski & Olano, "Hash Functions for GPU Rendering", JCGT 9(3), 2020: the PCG RXS-M-XS hash.
std::uint32_t pcgHash(std::uint32_t value) {
  const std::uint32_t state = value * 747796405u + 2891336453u;
  const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// Positions are in pixels from the image's lower left corner: pixel (i, j) spans
// [i, i + 1) x [j, j + 1), so the pixel a point lies in is its floor.
class StreamlineStepper {
 public:
  explicit StreamlineStepper(const VectorImage& field) : field_(field) {}

  std::size_t pixelIndex(glm::vec2 p) const {
    return index(std::uint32_t(p.x), std::uint32_t(p.y));
  }

  // Where a second-order Runge-Kutta (midpoint) step of `step` pixels along the field's
  // direction takes p; nullopt where the walk stops.
  std::optional<glm::vec2> midpointStep(glm::vec2 p, float step) const {
    const std::optional<glm::vec2> start = direction(p);
    if (!start) return std::nullopt;
    const std::optional<glm::vec2> middle = direction(p + (0.5f * step) * *start);
    if (!middle) return std::nullopt;
    const glm::vec2 end = p + step * *middle;
    if (!insideValidPixel(end)) return std::nullopt;
    return end;
  }

 private:
  bool insideValidPixel(glm::vec2 p) const {
    // Written so that NaN is outside.
    if (!(p.x >= 0.0f && p.x < float(field_.width) && p.y >= 0.0f && p.y < float(field_.height)))
      return false;
    return field_.valid[pixelIndex(p)] != 0;
  }

  // The unit direction of the field at p; nullopt outside, in an invalid pixel, or where the
  // vector vanishes or is not finite.
  std::optional<glm::vec2> direction(glm::vec2 p) const {
    if (!insideValidPixel(p)) return std::nullopt;
    const glm::vec2 v = vectorAt(p);
    if (!std::isfinite(v.x) || !std::isfinite(v.y)) return std::nullopt;
    // Scaled by the larger component first, so that no square overflows or vanishes.
    const float largest = std::max(std::abs(v.x), std::abs(v.y));
    if (!(largest > 0.0f)) return std::nullopt;
    const glm::vec2 w = v / largest;
    const float length = std::sqrt(w.x * w.x + w.y * w.y);
    return w / length;
  }

  std::size_t index(std::uint32_t x, std::uint32_t y) const {
    return x + std::size_t(field_.width) * y;
  }

  // Bilinear between the pixel centres around p, clamped to the border pixels; the vector of
  // p's own pixel where one of the four is invalid.
  glm::vec2 vectorAt(glm::vec2 p) const {
    const float u = std::clamp(p.x - 0.5f, 0.0f, float(field_.width - 1));
    const float v = std::clamp(p.y - 0.5f, 0.0f, float(field_.height - 1));
    const std::uint32_t x0 = std::uint32_t(u), y0 = std::uint32_t(v);
    const std::uint32_t x1 = std::min(x0 + 1, field_.width - 1);
    const std::uint32_t y1 = std::min(y0 + 1, field_.height - 1);
    const std::size_t n00 = index(x0, y0), n10 = index(x1, y0);
    const std::size_t n01 = index(x0, y1), n11 = index(x1, y1);
    const std::vector<std::uint8_t>& valid = field_.valid;
    if (!valid[n00] || !valid[n10] || !valid[n01] || !valid[n11])
      return field_.vectors[pixelIndex(p)];
    const float tx = u - float(x0), ty = v - float(y0);
    const std::vector<glm::vec2>& vectors = field_.vectors;
    const glm::vec2 lower = vectors[n00] + tx * (vectors[n10] - vectors[n00]);
    const glm::vec2 upper = vectors[n01] + tx * (vectors[n11] - vectors[n01]);
    return lower + ty * (upper - lower);
  }

  const VectorImage& field_;
};

// One way along the streamline through a pixel centre.
struct Walk {
  glm::vec2 point;
  float step;  // signed
  bool going = true;
};

void checkArguments(const VectorImage& field, const LicOptions& options) {
  const std::size_t pixels = std::size_t(field.width) * field.height;
  if (field.vectors.size() != pixels || field.valid.size() != pixels)
    throw std::invalid_argument("LIC: the field needs width * height vectors and valid flags");
  const auto positiveFinite = [](float value) { return std::isfinite(value) && value > 0.0f; };
  if (!positiveFinite(options.halfLengthPixels) || !positiveFinite(options.stepPixels))
    throw std::invalid_argument(
        "LIC: the kernel's half length and step must be positive and finite");
  if (double(options.halfLengthPixels) / double(options.stepPixels) > kMaxLicStepsEachWay)
    throw std::invalid_argument("LIC: the kernel's half length is more than 2^15 steps");
}

std::uint32_t noiseBits(std::uint32_t x, std::uint32_t y, std::uint32_t seed) {
  return pcgHash(x + pcgHash(y + pcgHash(seed))) >> 16u;
}

std::vector<std::uint16_t> noiseImage(std::uint32_t width, std::uint32_t height,
                                      std::uint32_t seed) {
  std::vector<std::uint16_t> noise(std::size_t(width) * height);
  tbb::parallel_for(std::uint32_t(0), height, [&](std::uint32_t y) {
    for (std::uint32_t x = 0; x < width; ++x)
      noise[x + std::size_t(width) * y] = std::uint16_t(noiseBits(x, y, seed));
  });
  return noise;
}

// The mean of `count` noise values summing to `sum` 2^-16: the whole quotient, exact in float,
// plus the remainder's fraction, so that float arithmetic alone gives it (as the device does).
float noiseMean(std::uint32_t sum, std::uint32_t count) {
  return (float(sum / count) + float(sum % count) / float(count)) * 0x1p-16f;
}

}  // namespace

float licNoise(std::uint32_t x, std::uint32_t y, std::uint32_t seed) {
  return float(noiseBits(x, y, seed)) * 0x1p-16f;
}

std::uint32_t licStepsEachWay(const LicOptions& options) {
  // The whole steps within the half length, forgiving the rounding of a ratio such as 1 / 0.1.
  return std::uint32_t(
      std::floor(double(options.halfLengthPixels) / double(options.stepPixels) * (1.0 + 1e-6)));
}

std::vector<float> lineIntegralConvolution(const VectorImage& field, const LicOptions& options) {
  checkArguments(field, options);
  const std::uint32_t width = field.width, height = field.height;
  const std::uint32_t stepsEachWay = licStepsEachWay(options);
  const std::vector<std::uint16_t> noise = noiseImage(width, height, options.noiseSeed);
  const StreamlineStepper stepper(field);
  std::vector<float> intensity(noise.size(), std::numeric_limits<float>::quiet_NaN());
  tbb::parallel_for(std::uint32_t(0), height, [&](std::uint32_t y) {
    for (std::uint32_t x = 0; x < width; ++x) {
      const std::size_t n = x + std::size_t(width) * y;
      if (!field.valid[n]) continue;
      // At most 2^16 + 1 values below 2^16: the sum fits 32 bits.
      std::uint32_t sum = noise[n];
      std::uint32_t count = 1;
      const glm::vec2 centre(float(x) + 0.5f, float(y) + 0.5f);
      std::array<Walk, 2> walks{Walk{centre, options.stepPixels},
                                Walk{centre, -options.stepPixels}};
      for (std::uint32_t k = 0; k < stepsEachWay && (walks[0].going || walks[1].going); ++k) {
        // Both ways in one loop: their steps are independent, so the processor overlaps them
        // (a third faster than one way after the other).
        for (Walk& walk : walks) {
          if (!walk.going) continue;
          const std::optional<glm::vec2> next = stepper.midpointStep(walk.point, walk.step);
          walk.going = next.has_value();
          if (!next) continue;
          walk.point = *next;
          sum += noise[stepper.pixelIndex(*next)];
          ++count;
        }
      }
      intensity[n] = noiseMean(sum, count);
    }
  });
  return intensity;
}

}  // namespace amrstream::slice
