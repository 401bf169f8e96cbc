#pragma once
// `view --benchmark`: the viewer's frames without a window. The traces grow by --steps-per-frame
// steps a frame, the tubes are rebuilt and a frame rendered offscreen at --width x --height, for
// --frames frames; prints the frame times (and where they went) as the viewer would see them.

#include "viewer/view_session.hpp"
#include "viewer/view_window.hpp"

namespace amrstream::viewer {

void runViewBenchmark(const ViewJob& options, const Reporter& reporter);

}  // namespace amrstream::viewer
