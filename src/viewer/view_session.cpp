#include "viewer/view_session.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "amrstream/error.hpp"
#include "api/seed_choice.hpp"
#include "flow/line_plan.hpp"
#include "flow/progressive_traces.hpp"
#include "render/middle_range.hpp"
#include "util/stopwatch.hpp"
#include "vk/context.hpp"

namespace amrstream::viewer {

TraceJob viewedJob(const TraceJob& job, std::vector<SnapshotFile>& series, const Log& log) {
  series.clear();
  const std::string& input = job.dataset.input;
  if (input.find_first_of("*?[") == std::string::npos || std::filesystem::exists(input)) return job;
  series = listSnapshots(std::vector<std::string>{input});
  say(log, fmt::format("series     {} snapshots from t = {:g} ({}) to {:g} ({}): pathlines",
                       series.size(), series.front().time, series.front().path, series.back().time,
                       series.back().path));
  TraceJob first = job;
  first.dataset.input = series.front().path;
  return first;
}

void sayPlayback(const ViewSession& session, const Log& log) {
  const SeriesPlayback* playback = session.playback();
  if (!playback) return;
  const flow::PathlineOptions& o = playback->options();
  say(log, fmt::format("pathlines  dt = {:g} from t = {:g} to {:g}, {} intervals (for these the "
                       "stepping line's mode, h and steps do not apply)",
                       o.stepSize, o.startTime, o.endTime, playback->intervalCount()));
}

ViewSession::ViewSession(const ViewJob& options, const vk::Context& ctx, gpu::Backend backend,
                         PreparedJob job, std::vector<SnapshotFile> series)
    : options_(options),
      ctx_(&ctx),
      backend_(backend),
      job_(std::move(job)),
      input_(job_.impl()),
      tracer_(ctx, backend, input_.volume()),
      series_(std::move(series)) {
  startTraces();
  options_.look.timeUnit = integrationTimeUnit(
      series_.empty() ? input_.options.stepMode : flow::StepMode::Time, input_.field.info());
  scene_ = prepareScene(options_.look, input_.cells(), input_.volume(), traces_->traces(),
                        input_.field.info());
  renderer_ =
      std::make_unique<render::TubeRenderer>(ctx, backend, input_.volume(), scene_.contextScalars);
  setColourMap(scene_.colourMap);
  rebuildTubes();
}

void ViewSession::startTraces() {
  traces_.reset();
  playback_ = nullptr;
  vkQueueWaitIdle(ctx_->queue());
  if (!series_.empty()) {
    PathlineSettings settings;
    if (options_.job.trace.stepSize) settings.stepSize = *options_.job.trace.stepSize;
    auto playback = std::make_unique<SeriesPlayback>(
        series_, pathlineOptions(series_, settings), options_.job.field, options_.job.dataset.units,
        input_.volume(), input_.seeds.points, ctx_, backend_, &tracer_.volumeBuffers());
    playback_ = playback.get();
    traces_ = std::move(playback);
    return;
  }
  flow::LinePlan plan =
      flow::planLines(input_.volume(), input_.seeds.points, input_.options.direction);
  traces_ = std::make_unique<flow::ProgressiveTraces>(
      tracer_.startRounds(plan.states, input_.options,
                          std::max(options_.stepsPerFrame, kPanelMostStepsPerFrame)),
      std::move(plan.layout), flow::traceShape(input_.volume(), input_.options));
}

void ViewSession::fitColourRange() {
  middleValues_.reset();
  setColourRange(scene_);  // the whole range, which the middle one narrows
  if (!middleColours || !options_.look.range.empty()) return;
  const double tail = 0.5 * (1.0 - kMiddleShare);
  const std::optional<render::ValueRange> middle =
      render::middleRange(scene_.segments, tail, 1.0 - tail);
  const render::ValueRange whole = scene_.settings.colourRange;
  if (!middle || (middle->min <= whole.min && middle->max >= whole.max)) return;
  scene_.settings.colourRange = *middle;
  const render::ColourScale& scale = scene_.colourScale;
  const auto valueOf = [&](float coordinate) {
    return float(scale.valueAt((coordinate - whole.min) / (whole.max - whole.min)));
  };
  middleValues_ = render::ValueRange{valueOf(middle->min), valueOf(middle->max)};
}

void ViewSession::rebuildTubes() {
  updateTubes(scene_, options_.look, input_.cells(), input_.volume(), traces_->traces());
  fitColourRange();
  vkQueueWaitIdle(ctx_->queue());
  renderer_->setTubes(scene_.segments, scene_.settings.tubeRadius);
}

bool ViewSession::growTubes() {
  vkQueueWaitIdle(ctx_->queue());
  // compute makes the new segments and grows its BVH on the host: meanwhile the device renders
  // the tubes (and their colour range) as they were before this round, which therefore show one
  // frame later.
  const bool renderMeanwhile = backend_ == gpu::Backend::Compute && renderer_->segmentCount() > 0 &&
                               renderer_->tubeRadius() == scene_.settings.tubeRadius;
  Stopwatch clock;
  if (renderMeanwhile) {
    renderer_->submitFrame(scene_.camera, scene_.settings);
    times_.renderSeconds = times_.renderSubmitSeconds = clock.seconds();
    clock.restart();
  }
  const std::optional<std::vector<shared::TubeSegment>> added =
      appendTubes(scene_, options_.look, input_.cells(), input_.volume(), traces_->recent());
  if (added) fitColourRange();
  times_.segmentsSeconds = clock.seconds();
  if (!added) {
    clock.restart();
    renderer_->waitForFrame();
    times_.renderSeconds += clock.seconds();
    rebuildTubes();
    times_.rebuilt = true;
    return renderMeanwhile;
  }
  renderer_->appendTubes(*added, scene_.segments, scene_.settings.tubeRadius);
  times_.append = renderer_->lastAppendTimes();
  times_.renderSeconds += times_.append.frameWait;
  return renderMeanwhile;
}

void ViewSession::setColourMap(render::ColourMap map) {
  scene_.colourMap = map;
  renderer_->setColourMap(render::colourMapTable(map));
}

void ViewSession::restartTraces() {
  std::string description;
  input_.seeds =
      chooseSeeds(options_.job.seeds, domainOf(input_.volume()), &input_.cells(), description);
  placeSeeds(input_.volume(), input_.seeds);
  startTraces();
  rebuildTubes();
}

void ViewSession::reloadVolume() {
  const render::OrbitCamera camera = scene_.camera;
  scene_ = prepareScene(options_.look, input_.cells(), input_.volume(), traces_->traces(),
                        input_.field.info());
  scene_.camera = camera;
  vkQueueWaitIdle(ctx_->queue());
  renderer_ = std::make_unique<render::TubeRenderer>(*ctx_, backend_, input_.volume(),
                                                     scene_.contextScalars);
  setColourMap(scene_.colourMap);
  rebuildTubes();
}

void ViewSession::frameAll() {
  frameTubes(scene_, input_.volume(),
             float(std::max(1u, renderer_->width())) / float(std::max(1u, renderer_->height())));
}

std::size_t ViewSession::step(std::uint32_t width, std::uint32_t height) {
  times_ = {};
  std::size_t taken = 0;
  if (width != renderer_->width() || height != renderer_->height()) {
    vkQueueWaitIdle(ctx_->queue());
    renderer_->resize(width, height);
  }
  bool rendered = false;
  Stopwatch clock;
  if (!paused && !traces_->finished()) {
    taken = traces_->advance(options_.stepsPerFrame);
    times_.traceSeconds = clock.seconds();
    clock.restart();
    rendered = growTubes();
    if (traces_->finished()) {
      vkQueueWaitIdle(ctx_->queue());
      renderer_->consolidateTubes(true);
    }
    times_.tubesSeconds = clock.seconds() - times_.renderSeconds;
  }
  if (!rendered) {
    clock.restart();
    renderer_->renderFrame(scene_.camera, scene_.settings);
    times_.renderSeconds = clock.seconds();
  }
  times_.renderDeviceSeconds = renderer_->lastFrameSeconds().value_or(0.0);
  times_.segments = renderer_->segmentCount();
  return taken;
}

}  // namespace amrstream::viewer
