#version 460
// No region contains the point.
#extension GL_EXT_ray_tracing : require

layout(location = 0) rayPayloadInEXT int locatedRegion;

void main() { locatedRegion = -1; }
