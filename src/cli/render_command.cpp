#include "render_command.hpp"

#include <fmt/format.h>

#include <memory>

#include "progress.hpp"
#include "render/image/colour_bar.hpp"
#include "render/image/png_io.hpp"
#include "render/tube_renderer.hpp"
#include "render_options.hpp"
#include "trace_settings.hpp"
#include "util/input_error.hpp"
#include "util/stopwatch.hpp"

namespace amrstream::cli {

namespace {

struct RenderCommandOptions {
  TraceJobOptions job;
  RenderOptions look;
  std::uint32_t frames = 32;
  bool colourBar = true;
  std::string out = "render.png";
};

void runRender(const RenderCommandOptions& o) {
  if (o.job.backend.backend == "cpu")
    throw InputError("--backend", "rendering needs a Vulkan device: choose auto, rayquery, "
                                  "pipeline or compute");
  PreparedInput input = prepareInput(o.job);
  checkHistoryFitsInMemory(input.seeds.points.size(), o.job.steps + 1);
  const flow::TraceSet traces = runTraces(o.job, input);
  const RenderScene scene = prepareScene(o.look, input, traces);

  const BackendChoice choice = chooseBackend(o.job.backend);
  if (choice.backend == gpu::Backend::Cpu)
    throw std::runtime_error("rendering needs a Vulkan device with compute; none was found "
                             "(see `amrstream devices`)");
  const vk::Context ctx = createContext(o.job.backend, choice);
  Stopwatch clock;
  render::TubeRenderer renderer(ctx, choice.backend, input.volume, scene.contextScalars);
  renderer.setTubes(scene.segments, scene.settings.tubeRadius);
  renderer.setColourMap(render::colourMapTable(scene.colourMap));
  renderer.resize(o.look.width, o.look.height);
  const double setupSeconds = clock.seconds();
  fmt::print("render     backend {} on {}: {} tube segments (radius {:g} cells), {} x {}, "
             "{} frames [setup {:.2f} s]\n",
             gpu::backendName(choice.backend), ctx.deviceName(), withCommas(scene.segments.size()),
             scene.settings.tubeRadius, o.look.width, o.look.height, o.frames, setupSeconds);

  clock.restart();
  double kernelSeconds = 0.0;
  {
    Progress progress("rendering", o.frames);
    for (std::uint32_t f = 0; f < o.frames; ++f) {
      renderer.renderFrame(scene.camera, scene.settings);
      kernelSeconds += renderer.lastFrameSeconds().value_or(0.0);
      progress.update(f + 1);
    }
  }
  checkValidation(ctx);
  render::Image image = renderer.readImage();
  if (o.colourBar)
    render::drawColourBar(image, {scene.colourMap, scene.settings.colourRange.min,
                                  scene.settings.colourRange.max, scene.colourLabel});
  render::writePng(o.out, image);
  fmt::print("time       {:.2f} s, {:.1f} ms per frame on the device\n", clock.seconds(),
             1e3 * kernelSeconds / std::max<std::uint32_t>(1, o.frames));
  fmt::print("output     {}\n", o.out);
}

}  // namespace

void addRenderCommand(CLI::App& app) {
  auto options = std::make_shared<RenderCommandOptions>();
  CLI::App* command =
      app.add_subcommand("render", "trace streamlines and render them as tubes to a PNG image");
  addTraceJobOptions(*command, options->job);
  addRenderOptions(*command, options->look);
  command->add_option("--frames", options->frames,
                      "frames accumulated: jittered samples per pixel, each with --ao-samples "
                      "occlusion rays")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  command->add_flag("!--no-colour-bar", options->colourBar, "leave the colour bar out");
  command->add_option("--out", options->out, "output PNG file")->capture_default_str();
  command->callback([options] {
    options->job.backend.validation = validationRequested();
    runRender(*options);
  });
}

}  // namespace amrstream::cli
