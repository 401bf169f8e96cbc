#include "render_command.hpp"

#include <fmt/format.h>

#include <memory>

#include "amrstream/error.hpp"
#include "amrstream/rendering.hpp"
#include "amrstream/run_files.hpp"
#include "amrstream/trace_job.hpp"
#include "console.hpp"
#include "job_options.hpp"
#include "option_checks.hpp"
#include "render_options.hpp"
#include "setting_options.hpp"

namespace amrstream::cli {

namespace {

struct RenderCommandOptions {
  TraceJob job;
  RenderOptions look;
  std::string traces;  // read traces from this .vtp instead of tracing
  std::string out = "render.png";
};

void runRender(const RenderCommandOptions& o) {
  requireRenderBackend(o.job.backend);  // before tracing
  RunFiles files = jobFiles(o.job);
  if (!o.traces.empty()) files.addInput(o.traces);
  files.addOutput("--out", o.out);
  requireOutputExtension("--out", o.out, {".png"}, "a PNG image");
  const Console console;
  {
    const bool tracing = o.traces.empty();
    PreparedJob job = prepare(o.job, {tracing, KeepDataset::Yes, tracing}, console);
    Traces traces;
    if (tracing) {
      traces = trace(job, {}, console).assemble();
    } else {
      traces = readTraces(o.traces);
      checkTracesInDomain(o.traces, traces, job.field(), console.reporter().log);
      console.lap("traces read");
    }
    const RenderedImage rendered = renderImage(o.job.backend, o.look, job.field(), traces, console);
    console.lap("rendering");
    writePng(o.out, rendered.image);
    console.lap("output");
    console.say(fmt::format("time       {:.2f} s, {:.1f} ms per frame on the device",
                            rendered.renderSeconds, 1e3 * rendered.kernelSecondsPerFrame));
    console.say("output     " + o.out);
  }
  console.sayStages();
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
  addSetting(*command, settings::kFrames, options->look.frames);
  command->add_flag_callback(
      "--no-colour-bar", [options] { options->look.colourBar = false; },
      "leave out " + settingHelp(settings::kColourBar));
  command->add_option("--out", options->out, "output PNG file")->capture_default_str();
  command->callback([options, command] {
    options->job.backend.validation = validationRequested();
    // The lines come from the file: options of seeding and stepping would be ignored.
    const std::vector<std::string> tracing = givenTracingOptions(*command);
    if (!options->traces.empty() && !tracing.empty())
      throw InputError(tracing.front(),
                       fmt::format("the lines come from --traces {}: its seeds and steps were "
                                   "chosen when it was traced; trace again to change them",
                                   options->traces));
    runRender(*options);
  });
}

}  // namespace amrstream::cli
