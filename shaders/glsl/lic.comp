#version 460
// Line integral convolution of a slice's in-plane vectors, one invocation per pixel: the device
// twin of slice::lineIntegralConvolution (src/slice/lic.cpp), which documents the method. The
// vectors are the grid probe's (NaN where the plane has no data), projected on the plane's axes
// where they are read.
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require

#include "shared/plane_lic.h"

layout(push_constant, scalar) uniform LicBlock { LicParams pc; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_LIC_VECTORS)
readonly buffer VectorBuffer { vec3 vectors[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_LIC_INTENSITY)
writeonly buffer IntensityBuffer { float intensity[]; };

layout(local_size_x = AMRSTREAM_LIC_GROUP, local_size_y = AMRSTREAM_LIC_GROUP) in;

uint pcgHash(uint value) {
  const uint state = value * 747796405u + 2891336453u;
  const uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

uint noiseBits(uvec2 pixel) {
  return pcgHash(pixel.x + pcgHash(pixel.y + pcgHash(pc.noiseSeed))) >> 16u;
}

uint pixelIndex(vec2 p) { return uint(p.x) + pc.width * uint(p.y); }

bool isValid(uint n) { return !isnan(vectors[n].x); }

bool insideValidPixel(vec2 p) {
  if (!(p.x >= 0.0 && p.x < float(pc.width) && p.y >= 0.0 && p.y < float(pc.height)))
    return false;
  return isValid(pixelIndex(p));
}

vec2 inPlane(uint n) {
  const vec3 v = vectors[n];
  precise const float a = v.x * pc.axisU.x + v.y * pc.axisU.y + v.z * pc.axisU.z;
  precise const float b = v.x * pc.axisV.x + v.y * pc.axisV.y + v.z * pc.axisV.z;
  return vec2(a, b);
}

vec2 vectorAt(vec2 p) {
  const float u = clamp(p.x - 0.5, 0.0, float(pc.width - 1u));
  const float v = clamp(p.y - 0.5, 0.0, float(pc.height - 1u));
  const uint x0 = uint(u), y0 = uint(v);
  const uint x1 = min(x0 + 1u, pc.width - 1u), y1 = min(y0 + 1u, pc.height - 1u);
  const uint n00 = x0 + pc.width * y0, n10 = x1 + pc.width * y0;
  const uint n01 = x0 + pc.width * y1, n11 = x1 + pc.width * y1;
  if (!isValid(n00) || !isValid(n10) || !isValid(n01) || !isValid(n11))
    return inPlane(pixelIndex(p));
  precise const float tx = u - float(x0), ty = v - float(y0);
  const vec2 v00 = inPlane(n00), v10 = inPlane(n10), v01 = inPlane(n01), v11 = inPlane(n11);
  precise const vec2 lower = v00 + tx * (v10 - v00);
  precise const vec2 upper = v01 + tx * (v11 - v01);
  precise const vec2 result = lower + ty * (upper - lower);
  return result;
}

// The unit direction at p; false outside, in an invalid pixel, or where the vector vanishes or
// is not finite.
bool direction(vec2 p, out vec2 unit) {
  unit = vec2(0.0);
  if (!insideValidPixel(p)) return false;
  const vec2 v = vectorAt(p);
  if (any(isnan(v)) || any(isinf(v))) return false;
  const float largest = max(abs(v.x), abs(v.y));
  if (!(largest > 0.0)) return false;
  precise const vec2 w = v / largest;
  precise const float length = sqrt(w.x * w.x + w.y * w.y);
  unit = w / length;
  return true;
}

bool midpointStep(inout vec2 p, float step) {
  vec2 start, middle;
  if (!direction(p, start)) return false;
  precise const vec2 midpoint = p + (0.5 * step) * start;
  if (!direction(midpoint, middle)) return false;
  precise const vec2 end = p + step * middle;
  if (!insideValidPixel(end)) return false;
  p = end;
  return true;
}

void main() {
  const uvec2 pixel = gl_GlobalInvocationID.xy;
  if (pixel.x >= pc.width || pixel.y >= pc.height) return;
  const uint n = pixel.x + pc.width * pixel.y;
  if (!isValid(n)) {
    intensity[n] = uintBitsToFloat(0x7fc00000u);
    return;
  }
  uint sum = noiseBits(pixel), count = 1u;
  const vec2 centre = vec2(pixel) + 0.5;
  vec2 points[2] = vec2[2](centre, centre);
  bool going[2] = bool[2](true, true);
  for (uint k = 0u; k < pc.stepsEachWay && (going[0] || going[1]); ++k) {
    for (int w = 0; w < 2; ++w) {
      if (!going[w]) continue;
      going[w] = midpointStep(points[w], w == 0 ? pc.stepPixels : -pc.stepPixels);
      if (!going[w]) continue;
      sum += noiseBits(uvec2(points[w]));
      ++count;
    }
  }
  precise const float mean = (float(sum / count) + float(sum % count) / float(count)) * (1.0 / 65536.0);
  intensity[n] = mean;
}
