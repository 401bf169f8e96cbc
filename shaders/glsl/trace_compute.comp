#version 460
// The compute backend's tracing round.
#extension GL_GOOGLE_include_directive : require
#define AMRSTREAM_DUAL_ADDRESS
#include "include/trace_compute_main.glsl"
