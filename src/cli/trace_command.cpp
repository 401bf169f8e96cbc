#include "trace_command.hpp"

#include <fmt/format.h>

#include <memory>

#include "output/vtp_writer.hpp"
#include "trace_job.hpp"
#include "trace_settings.hpp"
#include "util/stopwatch.hpp"

namespace amrstream::cli {

namespace {

struct TraceCommandOptions {
  TraceJobOptions job;
  std::string out = "traces.vtp";
  std::string compression = "zlib";
  bool endpointsOnly = false;
};

void runTrace(const TraceCommandOptions& o) {
  PreparedInput input = prepareInput(o.job);
  input.options.keepHistory = !o.endpointsOnly;
  checkHistoryFitsInMemory(input.seeds.points.size(), o.endpointsOnly ? 1 : o.job.steps + 1);
  const flow::TraceSet traces = runTraces(o.job, input);

  Stopwatch clock;
  output::VtpWriteOptions write;
  write.compression = *output::compressionNamed(o.compression);  // checked by CLI11
  const output::VtpCounts written = output::writeVtp(o.out, traces, write);
  fmt::print("output     {} ({} polylines, {} points) [{:.2f} s]\n", o.out,
             withCommas(written.lines), withCommas(written.points), clock.seconds());
}

}  // namespace

void addTraceCommand(CLI::App& app) {
  auto options = std::make_shared<TraceCommandOptions>();
  CLI::App* command = app.add_subcommand("trace", "trace streamlines and write them as .vtp");
  addTraceJobOptions(*command, options->job);
  command->add_option("--out", options->out, "output .vtp file")->capture_default_str();
  command
      ->add_option("--compression", options->compression,
                   "compression of the .vtp's arrays: zlib (as VTK and ParaView write), lz4 "
                   "(faster, larger) or none")
      ->capture_default_str()
      ->check(CLI::IsMember({"none", "zlib", "lz4"}));
  command->add_flag("--endpoints-only", options->endpointsOnly,
                    "keep only each trace's last point (no history: for very long runs)");
  command->callback([options] {
    options->job.backend.validation = validationRequested();
    runTrace(*options);
  });
}

}  // namespace amrstream::cli
