#include "viewer/view_window.hpp"

#include <GLFW/glfw3.h>
#include <fmt/format.h>

#include <algorithm>

#include "amrstream/error.hpp"
#include "api/device.hpp"
#include "app/frame_presenter.hpp"
#include "app/imgui_layer.hpp"
#include "app/window.hpp"
#include "output/vtp_writer.hpp"
#include "render/image/png_io.hpp"
#include "util/stopwatch.hpp"
#include "viewer/view_overlays.hpp"
#include "viewer/view_panel.hpp"

namespace amrstream::viewer {

namespace {

void saveScreenshot(const std::string& path, const app::Screenshot& shot, const Log& log) {
  render::Image image;
  image.width = shot.width;
  image.height = shot.height;
  image.rgba = shot.rgba;
  render::writePng(path, image);
  say(log, "screenshot " + path);
}

// The window's loop: input, the controls, the keys' requests, then a frame of traces and tubes.
class WindowLoop {
 public:
  WindowLoop(const ViewJob& o, app::Window& window, const vk::Context& ctx, ViewSession& session,
             RunFiles& files, const Log& log)
      : o_(o),
        window_(window),
        ctx_(ctx),
        session_(session),
        files_(files),
        log_(log),
        presenter_(ctx, window),
        imgui_(ctx, window, presenter_.overlayRenderPass(), presenter_.framesInFlight()),
        stats_{0.0, 0.0, ctx.deviceName()},
        showPanel_(o.look.width >= 800) {}  // small windows start with the view unobstructed

  // Runs until the window closes; returns the frames shown.
  std::uint32_t run() {
    while (!window_.shouldClose()) {
      Stopwatch clock;
      window_.pollEvents();
      imgui_.newFrame();
      const app::InputFrame input = imgui_.uncaptured(window_.takeInput());
      const PanelRequests requests = drawControls(input);
      if (requests.frameAll) session_.frameAll();
      const VkExtent2D extent = window_.framebufferExtent();
      moveCamera(session_.camera(), input, float(std::max(1u, extent.height)));
      render::orbit(session_.camera(), o_.orbitPerFrame, 0.0f);
      if (requests.exportTraces) exportTraces();
      requestScreenshot(requests.screenshot);
      renderFrame(clock);
      sayWhenFinished();
      if (o_.frames > 0 && frame_ >= o_.frames) window_.requestClose();
    }
    vkQueueWaitIdle(ctx_.queue());
    return frame_;
  }

 private:
  // The overlays, the panel (or the legend alone) and the keys.
  PanelRequests drawControls(const app::InputFrame& input) {
    PanelRequests requests;
    drawSceneOverlays(session_.scene(), session_.options().look, session_.input().volume(),
                      session_.input().field.info());
    if (showPanel_)
      requests = drawViewPanel(session_, stats_);
    else
      drawLegendOverlay(session_.scene(), session_.middleValues());
    for (const app::KeyPress& key : input.keyPresses) {
      if (key.key == GLFW_KEY_S) requests.screenshot = true;
      if (key.key == GLFW_KEY_E) requests.exportTraces = true;
      if (key.key == GLFW_KEY_H) showPanel_ = !showPanel_;
      if (key.key == GLFW_KEY_F) requests.frameAll = true;
      if (key.key == GLFW_KEY_ESCAPE || key.key == GLFW_KEY_Q) window_.requestClose();
    }
    return requests;
  }

  // The files the keys write as the session goes: one that would replace an input or another
  // output is skipped with a message, and the window stays open.
  bool writable(const std::string& what, const std::string& path) {
    try {
      files_.checkOutput(what, path);
      return true;
    } catch (const InputError& refused) {
      say(log_, fmt::format("skipped    {}", refused.what()));
      return false;
    }
  }

  void exportTraces() {
    const std::string path = fmt::format("view_traces_{}.vtp", exports_++);
    if (!writable("export", path)) return;
    output::writeVtp(path, session_.traces().traces());
    say(log_, "exported   " + path);
  }

  void requestScreenshot(bool asked) {
    const Log& log = log_;
    const bool last = o_.frames > 0 && frame_ + 1 >= o_.frames;
    if (last && !o_.screenshot.empty()) {
      presenter_.requestScreenshot(
          [path = o_.screenshot, log](app::Screenshot shot) { saveScreenshot(path, shot, log); });
    } else if (asked) {
      const std::string path = fmt::format("view_screenshot_{}.png", screenshots_++);
      if (writable("screenshot", path))
        presenter_.requestScreenshot(
            [path, log](app::Screenshot shot) { saveScreenshot(path, shot, log); });
    }
  }

  void renderFrame(const Stopwatch& clock) {
    auto presented = presenter_.beginFrame();
    if (!presented) return;
    const std::size_t steps = session_.step(std::max(1u, presented->extent.width),
                                            std::max(1u, presented->extent.height));
    const render::TubeRenderer& renderer = session_.renderer();
    presenter_.endFrame({renderer.pixels().handle(), 0, {renderer.width(), renderer.height()}},
                        &imgui_);
    stats_.frameSeconds = clock.seconds();
    stats_.stepsPerSecond = double(steps) / std::max(stats_.frameSeconds, 1e-9);
    ++frame_;
  }

  void sayWhenFinished() {
    if (tracesDone_ || !session_.traces().finished()) return;
    tracesDone_ = true;
    say(log_, fmt::format("traces     all {} finished after {} frames, {} particle-steps",
                          session_.traces().lineCount(), frame_, session_.traces().stepsTaken()));
  }

  const ViewJob& o_;
  app::Window& window_;
  const vk::Context& ctx_;
  ViewSession& session_;
  RunFiles& files_;
  const Log& log_;
  app::FramePresenter presenter_;
  app::ImGuiLayer imgui_;
  FrameStats stats_;
  bool showPanel_;
  std::uint32_t frame_ = 0, screenshots_ = 0, exports_ = 0;
  bool tracesDone_ = false;
};

}  // namespace

void runViewWindow(const ViewJob& o, const Reporter& reporter) {
  const Log& log = reporter.log;
  requireViewerBackend(o.job.backend);
  std::vector<SnapshotFile> series;
  const TraceJob viewed = viewedJob(o.job, series, log);
  RunFiles files = jobFiles(viewed);
  if (!o.screenshot.empty()) {
    files.addOutput("{screenshot}", o.screenshot);
    requireOutputExtension("{screenshot}", o.screenshot, {".png"}, "a PNG image");
  }
  // The window first: without a display, say so before loading anything.
  app::Window window({int(o.look.width), int(o.look.height), "amrstream view", true});
  PreparedJob job = prepare(viewed, {true, KeepDataset::Yes}, reporter);
  const BackendChoice choice = chooseBackend(o.job.backend, BackendUse::Render, log);
  if (choice.backend == gpu::Backend::Cpu)
    throw std::runtime_error("the viewer needs a Vulkan device with compute; none was found");

  vk::ContextBuilder builder;
  builder.require(gpu::requiredCapabilities(choice.backend))
      .validation(o.job.backend.validation)
      .presentation(window.requiredInstanceExtensions(), window.surfaceFactory());
  if (!choice.deviceFilter.empty()) builder.deviceName(choice.deviceFilter);
  const vk::Context ctx = builder.build();
  ViewSession session(o, ctx, choice.backend, std::move(job), std::move(series));
  sayPlayback(session, log);
  WindowLoop loop(o, window, ctx, session, files, log);
  say(log, fmt::format("viewer     backend {} on {}", gpu::backendName(choice.backend),
                       ctx.deviceName()));
  const std::uint32_t frames = loop.run();
  say(log, fmt::format("frames     {}", frames));
  checkValidation(ctx);
}

}  // namespace amrstream::viewer
