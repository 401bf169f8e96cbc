#pragma once
// `amrstream view`: a window in which traces grow a few steps a frame on the GPU and render as
// tubes, with an orbit camera and controls; or, for benchmarks, the same frames offscreen with
// their times. Built where GLFW and Dear ImGui are (AMRSTREAM_HAVE_VIEWER).

#include <cstdint>
#include <string>

#include "amrstream/log.hpp"
#include "amrstream/rendering.hpp"
#include "amrstream/trace_job.hpp"

namespace amrstream {

struct ViewJob {
  TraceJob job;
  RenderOptions look;
  bool benchmark = false;  // no window: run `frames` frames offscreen and print their times
  std::uint32_t stepsPerFrame = 10;
  std::uint32_t frames = 0;    // stop after this many frames (0: until the window closes)
  float orbitPerFrame = 0.0f;  // degrees of azimuth per frame, for scripted runs
  std::string screenshot;      // with frames: save the last frame here
  std::string frameTimes;      // with benchmark: every frame's times to this CSV file
};

// Throws InputError for options the viewer cannot honour (a CPU tail, the CPU backend, frame
// times without benchmark) before opening anything, app::WindowError without a display.
void runViewer(const ViewJob& job, const Reporter& reporter = {});

}  // namespace amrstream
