#include "view_benchmark.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <span>
#include <string>
#include <vector>

#include "output/atomic_file.hpp"
#include "util/input_error.hpp"
#include "util/stopwatch.hpp"

namespace amrstream::cli {
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

}  // namespace

void runViewBenchmark(const ViewOptions& o) {
  if (o.frames == 0) throw InputError("--frames", "--benchmark needs a number of frames");
  if (!o.screenshot.empty())
    throw InputError("--screenshot", "--benchmark has no window to take a screenshot of");
  if (o.job.backend.backend == "cpu")
    throw InputError("--backend",
                     "the viewer needs a Vulkan device: choose auto, rayquery, "
                     "pipeline or compute");
  RunFiles files = jobFiles(o.job);
  if (!o.frameTimes.empty()) files.addOutput("--frame-times", o.frameTimes);
  PreparedInput input = prepareInput(o.job);
  const BackendChoice choice = chooseBackend(o.job.backend, BackendUse::Render, printLine);
  if (choice.backend == gpu::Backend::Cpu)
    throw std::runtime_error("the viewer needs a Vulkan device with compute; none was found");
  const vk::Context ctx = createContext(o.job.backend, choice);
  ViewSession session(o, ctx, choice.backend, std::move(input));
  fmt::print("viewer     benchmark, no window: backend {} on {}, {} x {}, {} frames\n",
             gpu::backendName(choice.backend), ctx.deviceName(), o.look.width, o.look.height,
             o.frames);

  std::vector<double> frames, growing, trace, tubes, render, renderSubmit, renderDevice, segments,
      upload, structures, instances, device;
  std::vector<ViewFrameTimes> growingTimes, allTimes;
  std::size_t steps = 0;
  for (std::uint32_t f = 0; f < o.frames; ++f) {
    const bool grew = !session.traces().finished();
    Stopwatch clock;
    steps += session.step(o.look.width, o.look.height);
    frames.push_back(clock.seconds());
    const ViewFrameTimes& t = session.lastFrameTimes();
    allTimes.push_back(t);
    if (grew) {
      growingTimes.push_back(t);
      growing.push_back(frames.back());
      trace.push_back(t.traceSeconds);
      tubes.push_back(t.tubesSeconds);
      segments.push_back(t.segmentsSeconds);
      upload.push_back(t.append.upload);
      structures.push_back(t.append.structures);
      instances.push_back(t.append.instances);
      device.push_back(t.append.device);
    }
    render.push_back(t.renderSeconds);
    renderDevice.push_back(t.renderDeviceSeconds);
    renderSubmit.push_back(t.renderSubmitSeconds);
  }
  const auto ms = [](double seconds) { return 1e3 * seconds; };
  fmt::print(
      "frames     {} in {:.2f} s: median {:.2f} ms, 95th percentile {:.2f} ms, slowest "
      "{:.2f} ms\n",
      frames.size(), mean(frames) * double(frames.size()), ms(percentile(frames, 0.5)),
      ms(percentile(frames, 0.95)), ms(percentile(frames, 1.0)));
  const auto whileGrowing = [&](const std::vector<double>& v) {
    return std::vector<double>(v.begin(), v.begin() + std::ptrdiff_t(growing.size()));
  };
  const auto afterwards = [&](const std::vector<double>& v) {
    return std::vector<double>(v.begin() + std::ptrdiff_t(growing.size()), v.end());
  };
  const std::size_t slowest =
      std::distance(growing.begin(), std::max_element(growing.begin(), growing.end()));
  if (!growing.empty()) {
    const ViewFrameTimes& t = growingTimes[slowest];
    fmt::print(
        "growing    {} frames while traces ran: median {:.2f} ms; the slowest, frame {}, "
        "{:.2f} ms: tracing {:.2f}, segments {:.2f}, structures {:.2f}, upload {:.2f}, "
        "device {:.2f}, rendering {:.2f}\n",
        growing.size(), ms(percentile(growing, 0.5)), slowest + 1, ms(growing[slowest]),
        ms(t.traceSeconds), ms(t.segmentsSeconds), ms(t.append.structures), ms(t.append.upload),
        ms(t.append.device), ms(t.renderSeconds));
  }
  fmt::print(
      "growing    {} frames while traces ran: mean {:.2f} ms (tracing {:.2f}, tubes {:.2f}, "
      "rendering {:.2f} of which submitting {:.2f}; the frame on the device {:.2f}), last "
      "{:.2f} ms\n",
      growing.size(), ms(mean(growing)), ms(mean(trace)), ms(mean(tubes)),
      ms(mean(whileGrowing(render))), ms(mean(whileGrowing(renderSubmit))),
      ms(mean(whileGrowing(renderDevice))), growing.empty() ? 0.0 : ms(growing.back()));
  const std::vector<double> still = afterwards(frames);
  fmt::print("still      {} frames after: median {:.2f} ms, slowest {:.2f} ms (frame {} of them)\n",
             still.size(), ms(percentile(still, 0.5)), ms(percentile(still, 1.0)),
             still.empty()
                 ? 0
                 : 1 + std::distance(still.begin(), std::max_element(still.begin(), still.end())));
  fmt::print(
      "tubes      while growing, mean: segments {:.2f} ms, upload {:.2f} ms, structures "
      "{:.2f} ms, instance list {:.2f} ms, device {:.2f} ms\n",
      ms(mean(segments)), ms(mean(upload)), ms(mean(structures)), ms(mean(instances)),
      ms(mean(device)));
  fmt::print("traces     {} particle-steps, {} tube segments at the end\n", steps,
             session.scene().segments.size());
  if (!o.frameTimes.empty()) {
    writeFrameTimes(o.frameTimes, allTimes, frames, growing.size());
    fmt::print("frames     every frame's times in {}\n", o.frameTimes);
  }
  checkValidation(ctx);
}

}  // namespace amrstream::cli
