#version 460
// Returns the nearest segment the intersection shader accepted.
#extension GL_EXT_ray_tracing : require
#extension GL_GOOGLE_include_directive : require
#include "include/render_buffers.glsl"
#include "include/capsule.glsl"

layout(location = 0) rayPayloadInEXT TubeHit tubePayload;

void main() { tubePayload = TubeHit(gl_HitTEXT, uint(gl_InstanceCustomIndexEXT) + uint(gl_PrimitiveID)); }
