#include "trace_command.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <optional>

#include "amrstream/provenance.hpp"
#include "amrstream/trace_settings.hpp"
#include "data_distributed_trace.hpp"
#include "distributed_trace.hpp"
#include "option_checks.hpp"
#include "output/vtp_writer.hpp"
#include "output_paths.hpp"
#include "trace_job.hpp"
#include "util/input_error.hpp"
#include "util/peak_memory.hpp"
#include "util/stopwatch.hpp"

namespace amrstream::cli {

namespace {

struct TraceCommandOptions {
  TraceJobOptions job;
  std::string out = "traces.vtp";
  std::string compression = "zlib";
  bool endpointsOnly = false;
  std::string periodicLines = "split";
  std::string distribute = "seeds";
  bool pieces = false;
  std::uint32_t haloSteps = 4;
  std::uint32_t rebalanceSteps = 0;
  std::string traceStore = "auto";
};

TraceStore traceStoreNamed(const std::string& name) {
  if (name == "host") return TraceStore::Host;
  if (name == "device") return TraceStore::Device;
  return TraceStore::Auto;
}

output::VtpCounts writeTraceFile(const TraceCommandOptions& o, const std::filesystem::path& path,
                                 const flow::TraceView& traces, const PreparedInput& input) {
  output::VtpWriteOptions writeOptions;
  writeOptions.periodicLines = o.periodicLines == "unwrapped" ? output::PeriodicLines::Unwrapped
                                                              : output::PeriodicLines::Split;
  writeOptions.compression = *output::compressionNamed(o.compression);  // checked by CLI11
  writeOptions.fieldData =
      provenanceFields({input.source, input.info,
                        fmt::format("{} from {}", input.seeds.points.size(), input.seedDescription),
                        input.options, input.report},
                       input.volume);
  return output::writeVtp(path, traces, writeOptions);
}

// With `tracingPeak` (the stage peak when tracing ended, the stage restarted for writing), the
// two stages apart.
void printMemory(bool stagePeak, std::optional<std::uint64_t> tracingPeak = std::nullopt) {
  const auto gib = [](std::uint64_t bytes) { return double(bytes) / 0x1p30; };
  std::string stages;
  if (stagePeak && tracingPeak)
    stages = fmt::format(", {:.2f} GiB while tracing, {:.2f} GiB while writing", gib(*tracingPeak),
                         gib(stagePeakResidentBytes()));
  else if (stagePeak)
    stages = fmt::format(", {:.2f} GiB while tracing and writing", gib(stagePeakResidentBytes()));
  fmt::print("memory     {:.2f} GiB peak resident on the host{}\n", gib(peakResidentBytes()),
             stages);
}

// With --pieces, --out names the .pvtp; the pieces lie beside it.
void addOutputs(RunFiles& files, const TraceCommandOptions& o, int ranks) {
  if (!o.pieces) return files.addOutput("--out", o.out);
  if (std::filesystem::path(o.out).extension() != ".pvtp")
    throw InputError("--out", fmt::format("'{}': with --pieces, name the .pvtp that lists the "
                                          "pieces (e.g. traces.pvtp)",
                                          o.out));
  files.addOutput("--out", o.out);
  for (int rank = 0; rank < ranks; ++rank)
    files.addOutput("--out", piecePath(o.out, rank).string());
}

void runTrace(const TraceCommandOptions& o, const mpi::MpiWorld& world) {
  if (o.job.trace.cpuTail > 0 && (o.distribute == "data" || o.rebalanceSteps > 0))
    throw InputError("--cpu-tail",
                     "finishes the last lines of one process's trace: not with --distribute "
                     "data or --rebalance-steps, which hand lines between ranks");
  if (o.rebalanceSteps > 0 && o.distribute == "data")
    throw InputError("--rebalance-steps",
                     "evens out lines among ranks that hold the whole volume: use it with "
                     "--distribute seeds");
  const auto checkFiles = [&] {
    RunFiles files = jobFiles(o.job);
    addOutputs(files, o, world.size());
  };
  if (world.size() > 1 || o.pieces || o.distribute == "data") {
    const bool stagePeak = resetStagePeak();
    DistributedOutput output{
        o.out, o.pieces,
        [&](const std::filesystem::path& path, const flow::TraceView& traces,
            const PreparedInput& input) { return writeTraceFile(o, path, traces, input); }};
    if (o.distribute == "data")
      traceOverDataDistributed(world, o.job, !o.endpointsOnly, o.haloSteps, checkFiles, output);
    else
      traceDistributed(world, o.job, !o.endpointsOnly, o.rebalanceSteps, checkFiles, output);
    printMemory(stagePeak);
    return;
  }
  checkFiles();
  PreparedInput input = prepareInput(o.job, true, CellsAfter::Release);
  input.releaseField();  // the volume holds the vector and the point data
  input.options.keepHistory = !o.endpointsOnly;
  const bool stagePeak = resetStagePeak();
  // Nothing after tracing reads the volume's values: a GPU backend may drop the host copy.
  const std::unique_ptr<HeldTraces> traces =
      runTracesForWriting(o.job, input, traceStoreNamed(o.traceStore), HostValues::Release);
  const std::uint64_t tracingPeak = stagePeakResidentBytes();
  resetStagePeak();
  Stopwatch clock;
  const output::VtpCounts written = writeTraceFile(o, o.out, traces->view(), input);
  fmt::print("output     {} ({} polylines, {} points) [{:.2f} s]\n", o.out,
             withCommas(written.lines), withCommas(written.points), clock.seconds());
  printMemory(stagePeak, tracingPeak);
}

}  // namespace

void addTraceCommand(CLI::App& app, const mpi::MpiWorld& world) {
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
                    "keep only each line's last point (no history)");
  command
      ->add_option("--periodic-lines", options->periodicLines,
                   "lines crossing a periodic face: split (one polyline per piece inside the "
                   "domain) or unwrapped (one polyline continuing past the face)")
      ->capture_default_str()
      ->check(CLI::IsMember({"split", "unwrapped"}));
  command
      ->add_option("--trace-store", options->traceStore,
                   "where a GPU trace's points wait to be written: device (the GPU's memory, "
                   "copied out as the file is written, where every line's steps fit), host, or "
                   "auto (device on a GPU, host on a software device)")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "host", "device"}));
  addDistributeOption(*command, options->distribute);
  command
      ->add_option("--halo-steps", options->haloSteps,
                   "with --distribute data: each rank holds the cells within this many steps' "
                   "reach of its part; a line goes on to the rank that owns where it is once "
                   "it is more than one step less than that outside the part")
      ->capture_default_str()
      ->check(countIn(1, 1u << 20));
  command
      ->add_option("--rebalance-steps", options->rebalanceSteps,
                   "with --distribute seeds: trace in rounds of this many steps and even out the "
                   "ranks' live lines between rounds (0: the seeds are split once, at the start)")
      ->capture_default_str()
      ->check(countIn(0, 1u << 30));
  command->add_flag("--pieces", options->pieces,
                    "each rank writes its lines as a piece beside the .pvtp that --out names, "
                    "which lists them (ParaView opens it); without it rank 0 writes one .vtp");
  command->callback([options, &world] {
    options->job.backend.validation = validationRequested();
    runTrace(*options, world);
  });
}

}  // namespace amrstream::cli
