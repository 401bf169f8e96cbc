#include "trace_command.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <memory>

#include "amrstream/distributed.hpp"
#include "amrstream/error.hpp"
#include "amrstream/run_files.hpp"
#include "amrstream/trace_job.hpp"
#include "console.hpp"
#include "job_options.hpp"
#include "option_checks.hpp"
#include "setting_options.hpp"

namespace amrstream::cli {

namespace {

struct TraceCommandOptions {
  TraceJob job;
  TraceOutput out;
  bool endpointsOnly = false;
  DistributedTrace distributed;
  std::string traceStore = "auto";
  std::string json;
};

TraceStore traceStoreNamed(const std::string& name) {
  if (name == "host") return TraceStore::Host;
  if (name == "device") return TraceStore::Device;
  return TraceStore::Auto;
}

// With --pieces, --out names the .pvtp; the pieces lie beside it.
void addOutputs(RunFiles& files, const TraceCommandOptions& o, int ranks) {
  const std::filesystem::path out = o.out.path;
  if (!o.distributed.pieces) {
    files.addOutput("--out", out);
    return requireOutputExtension("--out", out, {".vtp"}, "VTK XML PolyData");
  }
  if (out.extension() != ".pvtp")
    throw InputError("--out", fmt::format("'{}': with --pieces, name the .pvtp that lists the "
                                          "pieces (e.g. traces.pvtp)",
                                          o.out.path));
  files.addOutput("--out", out);
  for (int rank = 0; rank < ranks; ++rank) files.addOutput("--out", piecePath(out, rank).string());
}

void runTrace(TraceCommandOptions o, const MpiWorld& world) {
  o.job.trace.keepHistory = !o.endpointsOnly;
  checkDistributedTrace(o.job, o.distributed);
  const bool distributed =
      world.size() > 1 || o.distributed.pieces || o.distributed.distribute == "data";
  if (distributed && !o.json.empty())
    throw InputError("--json",
                     "is written by a trace in one process (not under mpirun, with "
                     "--pieces or --distribute data)");
  const auto checkFiles = [&] {
    RunFiles files = jobFiles(o.job);
    addOutputs(files, o, world.size());
    if (!o.json.empty()) {
      files.addOutput("--json", o.json);
      requireOutputExtension("--json", o.json, {".json"}, "JSON");
    }
  };
  const Console console;
  if (distributed) return traceDistributed(world, o.job, o.out, o.distributed, checkFiles, console);
  checkFiles();
  const TraceJobSummary summary = runTraceJob(o.job, o.out, traceStoreNamed(o.traceStore), console);
  if (!o.json.empty()) writeTraceJson(o.json, summary, console.clock());
}

}  // namespace

void addTraceCommand(CLI::App& app, const MpiWorld& world) {
  auto options = std::make_shared<TraceCommandOptions>();
  CLI::App* command = app.add_subcommand("trace", "trace streamlines and write them as .vtp");
  addTraceJobOptions(*command, options->job);
  command->add_option("--out", options->out.path, "output .vtp file (with --pieces, .pvtp)")
      ->capture_default_str();
  addSetting(*command, settings::kCompression, options->out.compression);
  command->add_flag("--endpoints-only", options->endpointsOnly,
                    "keep only each line's last point (no history)");
  addSetting(*command, settings::kPeriodicLines, options->out.periodicLines);
  command
      ->add_option("--trace-store", options->traceStore,
                   "where a GPU trace's points wait to be written: device (the GPU's memory, "
                   "copied out as the file is written, where every line's steps fit), host, or "
                   "auto (device on a GPU, host on a software device)")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "host", "device"}));
  command
      ->add_option("--distribute", options->distributed.distribute,
                   "under mpirun: seeds (every rank holds the data and traces its share of the "
                   "seeds) or data (every rank holds its part of space and traces the lines "
                   "there, handing them on as they leave)")
      ->capture_default_str()
      ->check(CLI::IsMember({"seeds", "data"}));
  command
      ->add_option("--halo-steps", options->distributed.haloSteps,
                   "with --distribute data: each rank holds the cells within this many steps' "
                   "reach of its part; a line goes on to the rank that owns where it is once "
                   "it is more than one step less than that outside the part")
      ->capture_default_str()
      ->check(countIn(1, 1u << 20));
  command
      ->add_option("--rebalance-steps", options->distributed.rebalanceSteps,
                   "with --distribute seeds: trace in rounds of this many steps and even out the "
                   "ranks' live lines between rounds (0: the seeds are split once, at the start)")
      ->capture_default_str()
      ->check(countIn(0, 1u << 30));
  command->add_option("--json", options->json,
                      "also write what the run did and where its wall time went (every stage, "
                      "adding up to the whole) to this .json file");
  command->add_flag("--pieces", options->distributed.pieces,
                    "each rank writes its lines as a piece beside the .pvtp that --out names, "
                    "which lists them (ParaView opens it); without it rank 0 writes one .vtp");
  command->callback([options, &world] {
    options->job.backend.validation = validationRequested();
    runTrace(*options, world);
  });
}

}  // namespace amrstream::cli
