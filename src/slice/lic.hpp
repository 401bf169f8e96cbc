#pragma once
// Line integral convolution (Cabral & Leedom 1993) of a slice's in-plane vectors: white noise
// averaged along the streamline through each pixel, so the texture is smeared along the flow and
// stays random across it.

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace amrstream::slice {

struct VectorImage {  // pixel centres of a plane, x fastest, row 0 at the plane's lowest v
  std::uint32_t width = 0, height = 0;
  std::vector<glm::vec2> vectors;   // the in-plane vector at each pixel centre
  std::vector<std::uint8_t> valid;  // 0 where the plane has no data
};

// The most whole steps a streamline takes each way.
inline constexpr std::uint32_t kMaxLicStepsEachWay = 1u << 15;

struct LicOptions {
  float halfLengthPixels = 10.0f;  // the kernel reaches this far along the streamline each way
  float stepPixels = 0.5f;         // the streamline's step
  std::uint32_t noiseSeed = 1;
};

// White noise uniform in [0, 1) at a pixel: the top 16 bits of pcg(x + pcg(y + pcg(seed))), with
// the PCG hash of Jarzynski & Olano (2020) and sums wrapping at 2^32, times 2^-16. A GLSL shader
// with 32-bit unsigned arithmetic reproduces it exactly; every value is a multiple of 2^-16.
float licNoise(std::uint32_t x, std::uint32_t y, std::uint32_t seed);

// The whole steps of options.stepPixels within options.halfLengthPixels.
std::uint32_t licStepsEachWay(const LicOptions& options);

// The LIC intensity at every pixel (x fastest, as the field): the mean of licNoise over the points
// of the streamline through the pixel centre, traced both ways for halfLengthPixels each (the
// whole steps that fit) with steps of stepPixels (second-order Runge-Kutta, midpoint, on the unit
// direction of the field, interpolated bilinearly between pixel centres and clamped to the border
// pixels within half a pixel of the edge), each point taking the noise of the pixel it lies in
// (pixel (i, j) spans [i, i + 1) x [j, j + 1) with its centre at (i + 1/2, j + 1/2)).
// Where one of the four pixel centres around a point is invalid, the point takes the vector of
// the pixel it lies in (the nearest centre) instead of interpolating. A direction stops early at
// the image's edge, at a point (step or midpoint) in an invalid pixel, or where the interpolated
// vector vanishes (or is not finite); the pixel's own noise always counts. NaN at invalid pixels.
// All in float, in the order shaders/glsl/lic.comp computes it, so that the device gives the
// same intensities where its arithmetic rounds as IEEE 754 does (lavapipe's does).
// Runs over rows on all cores (oneTBB's tbb::parallel_for). Throws std::invalid_argument for
// sizes that do not match width * height, options that are not positive and finite, or more than
// 2^15 steps each way.
std::vector<float> lineIntegralConvolution(const VectorImage& field, const LicOptions& options);

}  // namespace amrstream::slice
