// Buffer structs of the renderer, shared by the host and the GLSL kernels (scalar layout).
// Positions are in scene units: finest-cell units stretched per axis to the cells' physical
// proportions (src/render/scene_space.hpp); the volume is marched in finest-cell units.
#ifndef AMRSTREAM_SHARED_RENDER_TYPES_H
#define AMRSTREAM_SHARED_RENDER_TYPES_H

#ifdef __cplusplus
#include "glsl_compat.h"
namespace amrstream::shared {
#endif

// One piece of a tube: the capsule of radius RenderParams::tubeRadius around segment [a, b], with
// the colour field's value at both ends (a == b: a sphere). With AMRSTREAM_RENDER_RADIUS_BY_VALUE
// the radius is smaller where the values are lower (segmentRadius in capsule.glsl), never larger,
// so bounding boxes built for tubeRadius hold every capsule.
struct TubeSegment {
  vec3 a;
  float valueA;
  vec3 b;
  float valueB;
};

// Node of the tubes' bounding volume hierarchy for the `compute` backend. Interior node
// (count == 0): children first and first + 1. Leaf: segments [first, first + count).
struct TubeBvhNode {
  vec3 lower;
  uint first;
  vec3 upper;
  uint count;
};

#define AMRSTREAM_RENDER_AO 1u
#define AMRSTREAM_RENDER_VOLUME 2u
#define AMRSTREAM_RENDER_LOG_VOLUME 4u
#define AMRSTREAM_RENDER_LINEAR_VOLUME 8u      // the volume's scalar through the linear interpolant
#define AMRSTREAM_RENDER_ORTHOGRAPHIC 16u      // parallel rays from the plane through the eye
#define AMRSTREAM_RENDER_FLAT_BACKGROUND 32u   // the background colour as it is, no gradient
#define AMRSTREAM_RENDER_TRANSPARENT 64u       // no background: the image's alpha is the coverage
#define AMRSTREAM_RENDER_RADIUS_BY_VALUE 128u  // tube radii follow the colour field

// The context volume's transfer function runs from this colour at the low end of its range to
// this one at the high end (render_frame.glsl's transferColour; the volume's colour bar).
const vec3 kVolumeLowColour = vec3(0.20, 0.30, 0.55);
const vec3 kVolumeHighColour = vec3(1.0, 0.88, 0.70);

// A segment whose values are below this is an outline (of the domain or of bricks), drawn in
// RenderParams::outlineColour rather than through the colour map.
#define AMRSTREAM_OUTLINE_VALUE (-1.0e38)
// Outlines are thinner than the tubes: this fraction of RenderParams::tubeRadius.
const float kOutlineRadiusFraction = 0.4;

// A pinhole (or orthographic) camera and what one frame draws. A frame adds one jittered sample per
// pixel to the accumulation buffer; pixels show the mean of the frames since the last reset
// (frameIndex 0).
struct RenderParams {
  vec3 eye;
  float halfHeight;  // perspective: tan(fovY / 2); orthographic: half the view's height
  vec3 forward;      // unit vectors
  float aspect;      // width / height
  vec3 right;
  uint frameIndex;
  vec3 up;
  uint flags;  // AMRSTREAM_RENDER_*
  uvec2 imageSize;
  uint segmentCount;
  float tubeRadius;
  vec3 lightDirection;  // unit, towards the light
  uint aoSamples;
  vec3 background;
  float aoDistance;
  vec3 domainLower;  // the volume's box in finest-cell units, for the ray march
  float valueMin;    // colour field range mapped onto the colour map
  vec3 domainUpper;
  float valueMax;
  float volumeMin;  // scalar (or log10 scalar) range of the transfer function
  float volumeMax;
  float volumeOpacity;    // extinction per finest cell at the top of the transfer function
  float volumeStepScale;  // ray-march step in units of the region's finest cell width
  vec3 outlineColour;
  // With AMRSTREAM_RENDER_RADIUS_BY_VALUE: the radius at valueMin as a fraction of tubeRadius
  // (tubeRadius itself at valueMax, and in proportion between).
  float leastRadiusFraction;
  vec3 sceneScale;  // scene units per finest-cell unit, per axis
};

#ifdef __cplusplus
static_assert(sizeof(TubeSegment) == 32 && sizeof(TubeBvhNode) == 32);
static_assert(offsetof(RenderParams, imageSize) == 64 && offsetof(RenderParams, volumeMin) == 144 &&
              sizeof(RenderParams) == 188);
}  // namespace amrstream::shared
#endif

#endif
