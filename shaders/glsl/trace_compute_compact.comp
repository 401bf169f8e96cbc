#version 460
// The compute backend's tracing round for devices without buffer device addresses, which read
// the values in the compact layout only (no dual cells).
#extension GL_GOOGLE_include_directive : require
#include "include/trace_compute_main.glsl"
