#pragma once
// The state of `amrstream view`: the prepared input, traces growing a few steps per frame on the
// GPU (streamlines of one snapshot, or pathlines through a series played from its first), and the
// tube renderer; the viewer's controls change it between frames.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "amrstream/pathlines.hpp"
#include "amrstream/viewer.hpp"
#include "api/job_state.hpp"
#include "api/render_scene.hpp"
#include "api/series_playback.hpp"
#include "flow/growing_traces.hpp"
#include "gpu/gpu_tracer.hpp"
#include "render/tube_renderer.hpp"

namespace amrstream::viewer {

// The control panel's steps-per-frame slider goes up to this; the rounds have room for it.
inline constexpr std::uint32_t kPanelMostStepsPerFrame = 200;
// The share of the colour values the viewer's default colour range holds, from the 1st to the
// 99th percentile.
inline constexpr double kMiddleShare = 0.98;

// Where one frame's time went (ViewSession::step), wall clock on the host.
struct ViewFrameTimes {
  double traceSeconds = 0;     // advancing the traces on the GPU and collecting their new points
  double tubesSeconds = 0;     // tube segments, their upload and the tubes' structure
  double segmentsSeconds = 0;  // of which making and colouring the new segments on the host
  render::TubeRenderer::AppendTimes append;  // and the renderer's parts
  double renderSeconds = 0;        // rendering the frame, to its completion (with compute while the
                                   // traces grow, beside building the tubes' BVH on the host)
  double renderSubmitSeconds = 0;  // of which recording and submitting it, when not waited for
  double renderDeviceSeconds = 0;  // the frame's own time on the device (timestamps)
  bool rebuilt = false;            // every tube was made again (a symmetric-log scale widened)
  std::size_t segments = 0;        // tube segments after the frame
};

// The job of the snapshot the viewer opens: the input's own; or where the input is a glob pattern
// (not a file's name) matching snapshots of a series, its first, with `series` set to them
// (listSnapshots': InputError for fewer than two, or one without a time) and a "series" line said.
TraceJob viewedJob(const TraceJob& job, std::vector<SnapshotFile>& series, const Log& log);

// Says the "pathlines" line of a session that plays a series (its time step and span).
void sayPlayback(const class ViewSession& session, const Log& log);

class ViewSession {
 public:
  // With a `series` (listSnapshots'), `job` is its first snapshot's and the session plays the
  // series: pathlines from the seeds, time step options.job.trace.stepSize (default a tenth of
  // the shortest interval).
  ViewSession(const ViewJob& options, const vk::Context& ctx, gpu::Backend backend, PreparedJob job,
              std::vector<SnapshotFile> series = {});

  // Advances the traces by stepsPerFrame and, if they grew, rebuilds the tubes; renders one frame
  // at this size (with compute, of the tubes before this round, while their BVH grows on the
  // host), complete on return. Returns the particle-steps taken.
  std::size_t step(std::uint32_t width, std::uint32_t height);
  const ViewFrameTimes& lastFrameTimes() const { return times_; }

  // Seeds again with the current seeding options and restarts the traces.
  void restartTraces();
  // Starts the traces of the current seeds and options.
  void startTraces();
  // Rebuilds the tubes from the traces as they are (after a colour or radius change).
  void rebuildTubes();
  // Adds the tubes of what the last round of tracing added (rebuilds them all when the colours
  // of the old ones would change).
  // Returns whether it rendered the frame (compute, before the new tubes are in place).
  bool growTubes();
  void setColourMap(render::ColourMap map);
  // Reloads the context volume for options().look.volume (empty: none).
  void reloadVolume();
  // Frames the traces as they are, keeping the camera's direction (the "frame all" key).
  void frameAll();

  ViewJob& options() { return options_; }
  PreparedJob::Impl& input() { return job_.impl(); }
  RenderScene& scene() { return scene_; }
  render::OrbitCamera& camera() { return scene_.camera; }
  bool paused = false;
  // Without a range asked for, colour by the middle 98 % of the values (kMiddleShare), so that
  // a few outliers do not leave the tubes one colour.
  bool middleColours = true;
  // The values at the colour map's ends where they are the middle ones, not the whole range.
  const std::optional<render::ValueRange>& middleValues() const { return middleValues_; }
  // Applies middleColours to the scene's colour range (after its tubes changed).
  void fitColourRange();
  const flow::GrowingTraces& traces() const { return *traces_; }
  // The series being played, or nothing for streamlines of one snapshot.
  const SeriesPlayback* playback() const { return playback_; }
  const render::TubeRenderer& renderer() const { return *renderer_; }
  gpu::Backend backend() const { return backend_; }

 private:
  ViewJob options_;
  const vk::Context* ctx_;
  gpu::Backend backend_;
  PreparedJob job_;
  PreparedJob::Impl& input_;
  gpu::GpuTracer tracer_;
  std::vector<SnapshotFile> series_;
  std::unique_ptr<flow::GrowingTraces> traces_;
  SeriesPlayback* playback_ = nullptr;  // traces_, when a series plays
  RenderScene scene_;
  std::unique_ptr<render::TubeRenderer> renderer_;
  ViewFrameTimes times_;
  std::optional<render::ValueRange> middleValues_;
};

}  // namespace amrstream::viewer
