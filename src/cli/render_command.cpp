#include "render_command.hpp"

#include <fmt/format.h>

#include <memory>

#include "amrstream/trace_settings.hpp"
#include "flow/seeds.hpp"
#include "option_checks.hpp"
#include "option_limits.hpp"
#include "output/vtp_reader.hpp"
#include "progress.hpp"
#include "render/image/png_io.hpp"
#include "render_options.hpp"
#include "trace_job.hpp"
#include "util/input_error.hpp"
#include "util/stopwatch.hpp"

namespace amrstream::cli {

namespace {

struct RenderCommandOptions {
  TraceJobOptions job;
  RenderOptions look;
  std::string traces;  // read traces from this .vtp instead of tracing
  std::uint32_t frames = 32;
  bool colourBar = true;
  std::string out = "render.png";
};

// Traces read from a file must meet the input's domain, or the image would show nothing of it.
void checkTracesInDomain(const std::string& path, const flow::TraceSet& traces,
                         const flow::VectorVolume& volume) {
  const glm::dvec3 lower = flow::domainLower(volume), upper = flow::domainUpper(volume);
  const std::size_t points = traces.positions.size();
  std::size_t inside = 0;
  for (const glm::vec3& p : traces.positions) {
    const glm::dvec3 x(p);
    inside += glm::all(glm::greaterThanEqual(x, lower)) && glm::all(glm::lessThanEqual(x, upper));
  }
  fmt::print("traces     {} lines from {} ({} points)\n", withCommas(traces.lineCount()), path,
             withCommas(points));
  if (points > 0 && inside == 0)
    throw InputError(path, fmt::format("no trace point lies in the input's domain [{:g}, {:g}] x "
                                       "[{:g}, {:g}] x [{:g}, {:g}]; were they traced in another "
                                       "dataset?",
                                       lower.x, upper.x, lower.y, upper.y, lower.z, upper.z));
}

void runRender(const RenderCommandOptions& o) {
  requireRenderBackend(o.job.backend);  // before tracing
  RunFiles files = jobFiles(o.job);
  if (!o.traces.empty()) files.addInput(o.traces);
  files.addOutput("--out", o.out);
  PreparedInput input = prepareInput(o.job, o.traces.empty());
  flow::TraceSet traces;
  if (o.traces.empty()) {
    traces = runTraces(o.job, input).assemble();
  } else {
    traces = output::readVtpTraces(o.traces);
    checkTracesInDomain(o.traces, traces, input.volume);
  }
  RenderOptions look = o.look;
  // Traces read from a file carry no step mode here: their IntegrationTime's unit is not known.
  if (o.traces.empty()) look.timeUnit = integrationTimeUnit(input.options.stepMode, input.info);
  RenderedImage rendered;
  {
    Progress progress("rendering", o.frames);
    rendered = renderImage(
        o.job.backend, look, input.field(), input.volume, traces, o.frames, o.colourBar,
        [&](std::uint32_t done, std::uint32_t) { progress.update(done); }, printLine);
  }
  render::writePng(o.out, rendered.image);
  fmt::print("time       {:.2f} s, {:.1f} ms per frame on the device\n", rendered.renderSeconds,
             1e3 * rendered.kernelSecondsPerFrame);
  fmt::print("output     {}\n", o.out);
}

}  // namespace

void addRenderCommand(CLI::App& app) {
  auto options = std::make_shared<RenderCommandOptions>();
  CLI::App* command =
      app.add_subcommand("render", "trace streamlines and render them as tubes to a PNG image");
  addTraceJobOptions(*command, options->job);
  addRenderOptions(*command, options->look);
  command
      ->add_option("--traces", options->traces,
                   "render the traces of this .vtp (e.g. from `amrstream trace`) instead of "
                   "tracing; INPUT gives the domain, the volume and the colour channels")
      ->check(regularFile());
  command
      ->add_option("--frames", options->frames,
                   "frames accumulated: jittered samples per pixel, each with --ao-samples "
                   "occlusion rays")
      ->capture_default_str()
      ->check(countIn(1, kMaxRenderFrames));
  command->add_flag("!--no-colour-bar", options->colourBar, "leave the colour bar out");
  command->add_option("--out", options->out, "output PNG file")->capture_default_str();
  command->callback([options] {
    options->job.backend.validation = validationRequested();
    runRender(*options);
  });
}

}  // namespace amrstream::cli
