#version 460
// The ray meets no tube.
#extension GL_EXT_ray_tracing : require
#extension GL_GOOGLE_include_directive : require
#include "include/render_buffers.glsl"
#include "include/capsule.glsl"

layout(location = 0) rayPayloadInEXT TubeHit tubePayload;

void main() { tubePayload.segment = kNoSegment; }
