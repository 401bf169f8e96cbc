#include "api/trace_memory.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "amrstream/error.hpp"
#include "flow/cpu_tracer.hpp"
#include "flow/trace_accumulator.hpp"
#include "util/host_memory.hpp"
#include "util/peak_memory.hpp"

namespace amrstream {

namespace {

// The sample: at most this many seeds, each line at most this many steps (2e6 steps, about a
// second on two cores).
constexpr std::size_t kSampleSeeds = 500;
constexpr std::uint32_t kSampleSteps = 2000;

std::string gib(double bytes) { return fmt::format("{:.1f} GiB", bytes / 0x1p30); }

// The points a line of `seeds` averages: a sample of them traced on the CPU.
double sampledPointsPerLine(const flow::VectorVolume& volume, std::span<const glm::dvec3> seeds,
                            const flow::TraceOptions& options) {
  std::vector<glm::dvec3> sample;
  const std::size_t count = std::min(seeds.size(), kSampleSeeds);
  for (std::size_t i = 0; i < count; ++i) sample.push_back(seeds[i * seeds.size() / count]);
  flow::TraceOptions sampleOptions = options;
  sampleOptions.maxSteps = std::min(options.maxSteps, kSampleSteps);
  sampleOptions.maxResultBytes = 0;
  sampleOptions.memoryBudget = 0;
  const flow::TraceSet traced = flow::traceStreamlines(volume, sample, sampleOptions);
  double points = 0.0;
  for (std::size_t line = 0; line < traced.lineCount(); ++line) {
    const bool cut =
        traced.steps[line] >= sampleOptions.maxSteps && sampleOptions.maxSteps < options.maxSteps;
    points += cut ? double(options.maxSteps) + 1.0 : double(traced.pointCount(line));
  }
  return points / double(std::max<std::size_t>(1, traced.lineCount()));
}

}  // namespace

std::uint64_t hostTraceLimit() {
  const double memory = physicalMemoryBytes();
  if (memory <= 0.0) return 0;
  const double held = double(residentBytes());
  return std::uint64_t(std::max(kTraceMemoryShare * memory - held, memory / 16.0));
}

void checkHostTracesFit(const flow::VectorVolume& volume, std::span<const glm::dvec3> seeds,
                        const flow::TraceOptions& options) {
  const double limit = double(options.maxResultBytes);
  if (limit <= 0.0 || seeds.empty()) return;
  const double lines =
      double(seeds.size()) * (options.direction == flow::Direction::Both ? 2.0 : 1.0);
  const double pointBytes = double(flow::TraceSet::bytesPerPoint(
      volume.channelNames.size(), options.vorticity, volume.deepPositions()));
  const double lineBytes = double(flow::kHeldBytesPerLine) + pointBytes;
  const std::string limitText =
      fmt::format("more than the {} traces may take on this machine now", gib(limit));
  if (lines * lineBytes > limit)
    throw InputError(
        "traces", fmt::format("{} seeds trace {:.0f} lines, which need at least {} "
                              "({:.0f} bytes a line), {}",
                              seeds.size(), lines, gib(lines * lineBytes), lineBytes, limitText));
  const double mostPoints = options.keepHistory ? double(options.maxSteps) + 1.0 : 1.0;
  if (lines * (double(flow::kHeldBytesPerLine) + mostPoints * pointBytes) <= limit) return;
  const double points = sampledPointsPerLine(volume, seeds, options);
  const double bytes = lines * (double(flow::kHeldBytesPerLine) + points * pointBytes);
  if (bytes > limit)
    throw InputError("traces",
                     fmt::format("{} seeds would trace about {} of lines ({:.0f} lines averaging "
                                 "{:.0f} points in a sample of {} seeds), {}; trace fewer seeds or "
                                 "steps, or keep only the lines' ends ({{endpoints_only}})",
                                 seeds.size(), gib(bytes), lines, points,
                                 std::min(seeds.size(), kSampleSeeds), limitText));
}

}  // namespace amrstream
