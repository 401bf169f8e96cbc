#version 460
// Returns the region the intersection shader accepted.
#extension GL_EXT_ray_tracing : require

layout(location = 0) rayPayloadInEXT int locatedRegion;
hitAttributeEXT uint hitRegion;

void main() { locatedRegion = int(hitRegion); }
