#include "viewer/view_benchmark.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <span>
#include <string>
#include <vector>

#include "amrstream/error.hpp"
#include "api/device.hpp"
#include "output/atomic_file.hpp"
#include "util/stopwatch.hpp"

namespace amrstream::viewer {
namespace {

double percentile(std::vector<double> values, double fraction) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const auto at = static_cast<std::size_t>(fraction * double(values.size() - 1) + 0.5);
  return values[std::min(at, values.size() - 1)];
}

// One row a frame, in milliseconds: whether the traces grew before it and whether every tube was
// made again, then ViewFrameTimes' parts.
void writeFrameTimes(const std::string& path, const std::vector<ViewFrameTimes>& frames,
                     const std::vector<double>& totals, std::size_t growing) {
  std::string text =
      "frame,growing,rebuilt,segments,total_ms,tracing_ms,tubes_ms,segments_ms,structures_ms,"
      "upload_ms,device_ms,rendering_ms,render_submit_ms,render_device_ms\n";
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const ViewFrameTimes& t = frames[f];
    text += fmt::format(
        "{},{},{},{},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f}\n",
        f + 1, f < growing ? 1 : 0, t.rebuilt ? 1 : 0, t.segments, 1e3 * totals[f],
        1e3 * t.traceSeconds, 1e3 * t.tubesSeconds, 1e3 * t.segmentsSeconds,
        1e3 * t.append.structures, 1e3 * t.append.upload, 1e3 * t.append.device,
        1e3 * t.renderSeconds, 1e3 * t.renderSubmitSeconds, 1e3 * t.renderDeviceSeconds);
  }
  output::AtomicFile file(path);
  file.write(std::as_bytes(std::span(text.data(), text.size())));
  file.commit();
}

double mean(const std::vector<double>& values) {
  double sum = 0.0;
  for (const double v : values) sum += v;
  return values.empty() ? 0.0 : sum / double(values.size());
}

// Every frame's times, and those of the frames while the traces grew (the first frames).
struct FrameRecord {
  std::vector<double> frames, growing, trace, tubes, render, renderSubmit, renderDevice, segments,
      upload, structures, instances, device;
  std::vector<ViewFrameTimes> growingTimes, allTimes;
  std::size_t steps = 0;
};

FrameRecord runFrames(ViewSession& session, const ViewJob& o) {
  FrameRecord r;
  for (std::uint32_t f = 0; f < o.frames; ++f) {
    const bool grew = !session.traces().finished();
    Stopwatch clock;
    r.steps += session.step(o.look.width, o.look.height);
    r.frames.push_back(clock.seconds());
    const ViewFrameTimes& t = session.lastFrameTimes();
    r.allTimes.push_back(t);
    if (grew) {
      r.growingTimes.push_back(t);
      r.growing.push_back(r.frames.back());
      r.trace.push_back(t.traceSeconds);
      r.tubes.push_back(t.tubesSeconds);
      r.segments.push_back(t.segmentsSeconds);
      r.upload.push_back(t.append.upload);
      r.structures.push_back(t.append.structures);
      r.instances.push_back(t.append.instances);
      r.device.push_back(t.append.device);
    }
    r.render.push_back(t.renderSeconds);
    r.renderDevice.push_back(t.renderDeviceSeconds);
    r.renderSubmit.push_back(t.renderSubmitSeconds);
  }
  return r;
}

void sayFrameTimes(const FrameRecord& r, std::size_t tubeSegments, const Log& log) {
  const auto ms = [](double seconds) { return 1e3 * seconds; };
  say(log,
      fmt::format("frames     {} in {:.2f} s: median {:.2f} ms, 95th percentile {:.2f} ms, slowest "
                  "{:.2f} ms",
                  r.frames.size(), mean(r.frames) * double(r.frames.size()),
                  ms(percentile(r.frames, 0.5)), ms(percentile(r.frames, 0.95)),
                  ms(percentile(r.frames, 1.0))));
  const auto whileGrowing = [&](const std::vector<double>& v) {
    return std::vector<double>(v.begin(), v.begin() + std::ptrdiff_t(r.growing.size()));
  };
  const auto afterwards = [&](const std::vector<double>& v) {
    return std::vector<double>(v.begin() + std::ptrdiff_t(r.growing.size()), v.end());
  };
  const std::size_t slowest =
      std::distance(r.growing.begin(), std::max_element(r.growing.begin(), r.growing.end()));
  if (!r.growing.empty()) {
    const ViewFrameTimes& t = r.growingTimes[slowest];
    say(log,
        fmt::format(
            "growing    {} frames while traces ran: median {:.2f} ms; the slowest, frame {}, "
            "{:.2f} ms: tracing {:.2f}, segments {:.2f}, structures {:.2f}, upload {:.2f}, "
            "device {:.2f}, rendering {:.2f}",
            r.growing.size(), ms(percentile(r.growing, 0.5)), slowest + 1, ms(r.growing[slowest]),
            ms(t.traceSeconds), ms(t.segmentsSeconds), ms(t.append.structures), ms(t.append.upload),
            ms(t.append.device), ms(t.renderSeconds)));
  }
  say(log,
      fmt::format(
          "growing    {} frames while traces ran: mean {:.2f} ms (tracing {:.2f}, tubes {:.2f}, "
          "rendering {:.2f} of which submitting {:.2f}; the frame on the device {:.2f}), last "
          "{:.2f} ms",
          r.growing.size(), ms(mean(r.growing)), ms(mean(r.trace)), ms(mean(r.tubes)),
          ms(mean(whileGrowing(r.render))), ms(mean(whileGrowing(r.renderSubmit))),
          ms(mean(whileGrowing(r.renderDevice))), r.growing.empty() ? 0.0 : ms(r.growing.back())));
  const std::vector<double> still = afterwards(r.frames);
  say(log, fmt::format(
               "still      {} frames after: median {:.2f} ms, slowest {:.2f} ms (frame {} of them)",
               still.size(), ms(percentile(still, 0.5)), ms(percentile(still, 1.0)),
               still.empty() ? 0
                             : 1 + std::distance(still.begin(),
                                                 std::max_element(still.begin(), still.end()))));
  say(log, fmt::format(
               "tubes      while growing, mean: segments {:.2f} ms, upload {:.2f} ms, structures "
               "{:.2f} ms, instance list {:.2f} ms, device {:.2f} ms",
               ms(mean(r.segments)), ms(mean(r.upload)), ms(mean(r.structures)),
               ms(mean(r.instances)), ms(mean(r.device))));
  say(log, fmt::format("traces     {} particle-steps, {} tube segments at the end", r.steps,
                       tubeSegments));
}

}  // namespace

void runViewBenchmark(const ViewJob& o, const Reporter& reporter) {
  const Log& log = reporter.log;
  if (o.frames == 0) throw settingError("frames", "{benchmark} needs a number of frames");
  if (!o.screenshot.empty())
    throw settingError("screenshot", "{benchmark} has no window to take a screenshot of");
  requireViewerBackend(o.job.backend);
  std::vector<SnapshotFile> series;
  const TraceJob viewed = viewedJob(o.job, series, log);
  RunFiles files = jobFiles(viewed);
  if (!o.frameTimes.empty()) {
    files.addOutput("{frame_times}", o.frameTimes);
    requireOutputExtension("{frame_times}", o.frameTimes, {".csv"}, "comma-separated values");
  }
  PreparedJob job = prepare(viewed, {true, KeepDataset::Yes}, reporter);
  const BackendChoice choice = chooseBackend(o.job.backend, BackendUse::Render, log);
  if (choice.backend == gpu::Backend::Cpu)
    throw std::runtime_error("the viewer needs a Vulkan device with compute; none was found");
  const vk::Context ctx = createContext(o.job.backend, choice);
  ViewSession session(o, ctx, choice.backend, std::move(job), std::move(series));
  sayPlayback(session, log);
  say(log, fmt::format("viewer     benchmark, no window: backend {} on {}, {} x {}, {} frames",
                       gpu::backendName(choice.backend), ctx.deviceName(), o.look.width,
                       o.look.height, o.frames));
  const FrameRecord record = runFrames(session, o);
  sayFrameTimes(record, session.scene().segments.size(), log);
  if (!o.frameTimes.empty()) {
    writeFrameTimes(o.frameTimes, record.allTimes, record.frames, record.growing.size());
    say(log, fmt::format("frames     every frame's times in {}", o.frameTimes));
  }
  checkValidation(ctx);
}

}  // namespace amrstream::viewer
