#include "amrstream/viewer.hpp"

#include "amrstream/error.hpp"
#include "viewer/view_benchmark.hpp"
#include "viewer/view_window.hpp"

namespace amrstream {

namespace viewer {

void requireViewerBackend(const BackendRequest& backend) {
  if (backend.backend == "cpu")
    throw settingError("backend",
                       "the viewer needs a Vulkan device: choose auto, rayquery, "
                       "pipeline or compute");
}

}  // namespace viewer

void runViewer(const ViewJob& job, const Reporter& reporter) {
  if (job.job.trace.cpuTail > 0)
    throw settingError("cpu_tail", "the viewer advances every line on the GPU, a round a frame");
  if (!job.frameTimes.empty() && !job.benchmark)
    throw settingError("frame_times", "needs {benchmark} (the window's frames are not timed)");
  if (job.benchmark)
    viewer::runViewBenchmark(job, reporter);
  else
    viewer::runViewWindow(job, reporter);
}

}  // namespace amrstream
