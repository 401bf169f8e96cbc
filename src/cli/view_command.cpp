#include "view_command.hpp"

#include <memory>

#include "amrstream/viewer.hpp"
#include "console.hpp"
#include "job_options.hpp"
#include "option_checks.hpp"
#include "option_limits.hpp"
#include "render_options.hpp"

namespace amrstream::cli {

void addViewCommand(CLI::App& app) {
  auto options = std::make_shared<ViewJob>();
  CLI::App* command = app.add_subcommand(
      "view", "open a window that traces progressively and renders the traces as tubes");
  addTraceJobOptions(*command, options->job);
  options->look.frame = "domain";  // the traces grow out of any box around the seeds; F frames them
  addRenderOptions(*command, options->look);
  command->get_option("--frame")->default_str(options->look.frame);
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
    options->job.backend.validation = validationRequested();
    const Console console;
    runViewer(*options, console);
  });
}

}  // namespace amrstream::cli
