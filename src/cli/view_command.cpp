#include "view_command.hpp"

#include <GLFW/glfw3.h>
#include <fmt/format.h>

#include <memory>

#include "amrstream/trace_settings.hpp"
#include "app/frame_presenter.hpp"
#include "app/imgui_layer.hpp"
#include "app/window.hpp"
#include "option_checks.hpp"
#include "option_limits.hpp"
#include "output/vtp_writer.hpp"
#include "render/image/png_io.hpp"
#include "util/input_error.hpp"
#include "util/stopwatch.hpp"
#include "view_benchmark.hpp"
#include "view_overlays.hpp"
#include "view_panel.hpp"

namespace amrstream::cli {

namespace {

void saveScreenshot(const std::string& path, const app::Screenshot& shot) {
  render::Image image;
  image.width = shot.width;
  image.height = shot.height;
  image.rgba = shot.rgba;
  render::writePng(path, image);
  fmt::print("screenshot {}\n", path);
}

void runView(const ViewOptions& o) {
  if (o.job.backend.backend == "cpu")
    throw InputError("--backend",
                     "the viewer needs a Vulkan device: choose auto, rayquery, "
                     "pipeline or compute");
  RunFiles files = jobFiles(o.job);
  if (!o.screenshot.empty()) files.addOutput("--screenshot", o.screenshot);
  // The window first: without a display, say so before loading anything.
  app::Window window({int(o.look.width), int(o.look.height), "amrstream view", true});
  PreparedInput input = prepareInput(o.job);
  const BackendChoice choice = chooseBackend(o.job.backend, BackendUse::Render, printLine);
  if (choice.backend == gpu::Backend::Cpu)
    throw std::runtime_error("the viewer needs a Vulkan device with compute; none was found");

  vk::ContextBuilder builder;
  builder.require(gpu::requiredCapabilities(choice.backend))
      .validation(o.job.backend.validation)
      .presentation(window.requiredInstanceExtensions(), window.surfaceFactory());
  if (!choice.deviceFilter.empty()) builder.deviceName(choice.deviceFilter);
  const vk::Context ctx = builder.build();
  ViewSession session(o, ctx, choice.backend, std::move(input));
  app::FramePresenter presenter(ctx, window);
  app::ImGuiLayer imgui(ctx, window, presenter.overlayRenderPass(), presenter.framesInFlight());
  fmt::print("viewer     backend {} on {}\n", gpu::backendName(choice.backend), ctx.deviceName());

  // The files the keys write as the session goes: one that would replace an input or another
  // output is skipped with a message, and the window stays open.
  const auto writable = [&](const std::string& what, const std::string& path) {
    try {
      files.checkOutput(what, path);
      return true;
    } catch (const InputError& refused) {
      fmt::print("skipped    {}\n", refused.what());
      return false;
    }
  };

  FrameStats stats{0.0, 0.0, ctx.deviceName()};
  std::uint32_t frame = 0, screenshots = 0, exports = 0;
  bool tracesDone = false;
  bool showPanel = o.look.width >= 800;  // small windows start with the view unobstructed
  while (!window.shouldClose()) {
    Stopwatch clock;
    window.pollEvents();
    imgui.newFrame();
    const app::InputFrame input = imgui.uncaptured(window.takeInput());
    PanelRequests requests;
    drawSceneOverlays(session.scene(), session.options().look, session.input().volume,
                      session.input().info);
    if (showPanel)
      requests = drawViewPanel(session, stats);
    else
      drawLegendOverlay(session.scene());
    for (const app::KeyPress& key : input.keyPresses) {
      if (key.key == GLFW_KEY_S) requests.screenshot = true;
      if (key.key == GLFW_KEY_E) requests.exportTraces = true;
      if (key.key == GLFW_KEY_H) showPanel = !showPanel;
      if (key.key == GLFW_KEY_F) requests.frameAll = true;
      if (key.key == GLFW_KEY_ESCAPE || key.key == GLFW_KEY_Q) window.requestClose();
    }
    if (requests.frameAll) session.frameAll();
    const VkExtent2D extent = window.framebufferExtent();
    moveCamera(session.camera(), input, float(std::max(1u, extent.height)));
    render::orbit(session.camera(), o.orbitPerFrame, 0.0f);
    if (requests.exportTraces) {
      const std::string path = fmt::format("view_traces_{}.vtp", exports++);
      if (writable("export", path)) {
        output::writeVtp(path, session.traces().traces());
        fmt::print("exported   {}\n", path);
      }
    }
    const bool last = o.frames > 0 && frame + 1 >= o.frames;
    if (last && !o.screenshot.empty()) {
      presenter.requestScreenshot(
          [path = o.screenshot](app::Screenshot shot) { saveScreenshot(path, shot); });
    } else if (requests.screenshot) {
      const std::string path = fmt::format("view_screenshot_{}.png", screenshots++);
      if (writable("screenshot", path))
        presenter.requestScreenshot([path](app::Screenshot shot) { saveScreenshot(path, shot); });
    }

    if (auto presented = presenter.beginFrame()) {
      const std::size_t steps = session.step(std::max(1u, presented->extent.width),
                                             std::max(1u, presented->extent.height));
      const render::TubeRenderer& renderer = session.renderer();
      presenter.endFrame({renderer.pixels().handle(), 0, {renderer.width(), renderer.height()}},
                         &imgui);
      stats.frameSeconds = clock.seconds();
      stats.stepsPerSecond = double(steps) / std::max(stats.frameSeconds, 1e-9);
      ++frame;
    }
    if (!tracesDone && session.traces().finished()) {
      tracesDone = true;
      fmt::print("traces     all {} finished after {} frames, {} particle-steps\n",
                 session.traces().lineCount(), frame, session.traces().stepsTaken());
    }
    if (o.frames > 0 && frame >= o.frames) window.requestClose();
  }
  vkQueueWaitIdle(ctx.queue());
  fmt::print("frames     {}\n", frame);
  checkValidation(ctx);
}

}  // namespace

void addViewCommand(CLI::App& app) {
  auto options = std::make_shared<ViewOptions>();
  CLI::App* command = app.add_subcommand(
      "view", "open a window that traces progressively and renders the traces as tubes");
  addTraceJobOptions(*command, options->job);
  options->look.frame = "domain";  // the traces grow out of any box around the seeds; F frames them
  addRenderOptions(*command, options->look);
  command
      ->add_option("--steps-per-frame", options->stepsPerFrame,
                   "integration steps every particle takes before each frame")
      ->capture_default_str()
      ->check(countIn(1, kMaxStepsPerFrame));
  command
      ->add_option("--frames", options->frames,
                   "close after this many frames (0: when the window is closed)")
      ->capture_default_str()
      ->check(countIn(0, kMaxViewFrames));
  command
      ->add_option("--orbit-per-frame", options->orbitPerFrame,
                   "turn the camera by this many degrees each frame (scripted runs)")
      ->check(numberIn(-360.0, 360.0));
  command->add_option("--screenshot", options->screenshot,
                      "with --frames: save the last frame (with the controls) to this PNG");
  command->add_flag("--benchmark", options->benchmark,
                    "no window: render --frames frames offscreen as the traces grow and print "
                    "their times");
  command->add_option("--frame-times", options->frameTimes,
                      "with --benchmark: write every frame's times (ms) to this CSV file");
  command->callback([options] {
    if (options->job.trace.cpuTail > 0)
      throw InputError("--cpu-tail", "the viewer advances every line on the GPU, a round a frame");
    if (!options->frameTimes.empty() && !options->benchmark)
      throw InputError("--frame-times", "needs --benchmark (the window's frames are not timed)");
    options->job.backend.validation = validationRequested();
    if (options->benchmark)
      runViewBenchmark(*options);
    else
      runView(*options);
  });
}

}  // namespace amrstream::cli
