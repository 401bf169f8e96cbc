#include "cpu_tracer.hpp"

#include <tbb/parallel_for.h>

#include <atomic>

#include "line_plan.hpp"
#include "line_tracer.hpp"
#include "round_tracer.hpp"
#include "sampler.hpp"
#include "trace_accumulator.hpp"

namespace amrstream::flow {

namespace {

// A point as the line tracer emits it, before its point data.
struct EmittedPoint {
  CellPoint position;
  float time;
  glm::vec3 vector;
  std::int32_t region;
};

constexpr RoundCosts kCpuCosts{
    sizeof(shared::LineState) + sizeof(shared::LineRound) + sizeof(std::vector<EmittedPoint>),
    sizeof(EmittedPoint)};

}  // namespace

RoundBlock traceCpuRound(const VectorVolume& volume, const shared::TraceParams& params,
                         const TraceOptions& options, std::vector<shared::LineState>& live,
                         const std::function<void()>& lineEnded) {
  std::vector<std::vector<EmittedPoint>> emitted(live.size());
  RoundBlock block;
  block.lines.resize(live.size());
  tbb::parallel_for(std::size_t(0), live.size(), [&](std::size_t i) {
    std::vector<EmittedPoint>& points = emitted[i];
    points.reserve(params.pointsPerLine);
    block.lines[i] = advanceLine(volume, params, live[i],
                                 [&](const CellPoint& x, float time, const VectorSample& s) {
                                   points.push_back({x, time, s.value, s.region});
                                 });
    if (block.lines[i].reason != AMRSTREAM_REASON_RUNNING) lineEnded();
  });

  std::vector<std::size_t> first(live.size() + 1, 0);
  for (std::size_t i = 0; i < live.size(); ++i) first[i + 1] = first[i] + emitted[i].size();
  const std::size_t points = first.back(), channels = volume.channelCount();
  block.positions.resize(points);
  const bool precise = volume.deepPositions();
  if (precise) block.positionsLow.resize(points);
  block.times.resize(points);
  block.vectors.resize(points);
  block.channels.resize(points * channels);
  if (options.vorticity) block.vorticity.resize(points);
  tbb::parallel_for(std::size_t(0), live.size(), [&](std::size_t i) {
    for (std::size_t k = 0; k < emitted[i].size(); ++k) {
      const EmittedPoint& p = emitted[i][k];
      const std::size_t at = first[i] + k;
      const glm::dvec3 physical = volume.transform.toPhysical(toCellUnits(p.position));
      if (precise) {
        const SplitPosition split = splitPosition(physical);
        block.positions[at] = split.high;
        block.positionsLow[at] = split.low;
      } else {
        block.positions[at] = glm::vec3(physical);
      }
      block.times[at] = p.time;
      block.vectors[at] = p.vector;
      sampleChannels(volume, p.region, p.position,
                     std::span<float>(block.channels.data() + at * channels, channels));
      if (options.vorticity) block.vorticity[at] = sampleVorticity(volume, p.region, p.position);
    }
  });

  std::size_t kept = 0;
  for (std::size_t i = 0; i < live.size(); ++i)
    if (block.lines[i].reason == AMRSTREAM_REASON_RUNNING) live[kept++] = live[i];
  live.resize(kept);
  return block;
}

namespace {

class CpuRoundTracer final : public RoundTracer {
 public:
  CpuRoundTracer(const VectorVolume& volume, std::vector<shared::LineState> lines,
                 const TraceOptions& options, std::function<void()> lineEnded)
      : volume_(&volume),
        options_(options),
        params_(makeTraceParams(volume, options)),
        live_(std::move(lines)),
        lineEnded_(std::move(lineEnded)) {}

  std::size_t liveLines() const override { return live_.size(); }
  std::vector<shared::LineState> liveStates() const override { return live_; }

  RoundBlock advance(std::uint32_t steps) override {
    params_.lineCount = static_cast<std::uint32_t>(live_.size());
    params_.roundSteps = std::max(steps, 1u);
    params_.pointsPerLine = pointsPerLine(options_, params_.roundSteps);
    return traceCpuRound(*volume_, params_, options_, live_, lineEnded_);
  }

 private:
  const VectorVolume* volume_;
  TraceOptions options_;
  shared::TraceParams params_;
  std::vector<shared::LineState> live_;
  std::function<void()> lineEnded_;
};

}  // namespace

std::unique_ptr<RoundTracer> cpuRoundTracer(const VectorVolume& volume,
                                            std::span<const shared::LineState> lines,
                                            const TraceOptions& options) {
  return std::make_unique<CpuRoundTracer>(
      volume, std::vector<shared::LineState>(lines.begin(), lines.end()), options, [] {});
}

void traceCpuToEnd(const VectorVolume& volume, std::span<const shared::LineState> lines,
                   const TraceOptions& options, const std::function<void(RoundBlock&&)>& consume,
                   const std::function<void()>& lineEnded) {
  const std::size_t batch = linesPerBatch(options, kCpuCosts, lines.size());
  for (std::size_t first = 0; first < lines.size(); first += batch) {
    const std::size_t count = std::min(batch, lines.size() - first);
    const std::span<const shared::LineState> mine = lines.subspan(first, count);
    CpuRoundTracer rounds(volume, {mine.begin(), mine.end()}, options, lineEnded);
    const std::uint64_t slots = pointSlots(options, kCpuCosts, count);
    while (rounds.liveLines() > 0)
      consume(rounds.advance(stepsPerRound(options, slots, rounds.liveLines())));
  }
}

std::uint64_t cpuPointSlots(const TraceOptions& options, std::size_t lines) {
  return pointSlots(options, kCpuCosts, lines);
}

TraceSet traceStreamlines(const VectorVolume& volume, std::span<const glm::dvec3> seeds,
                          const TraceOptions& options, const TraceProgress& progress) {
  return traceToRounds(volume, seeds, options, progress).assemble();
}

StoredTraces traceToRounds(const VectorVolume& volume, std::span<const glm::dvec3> seeds,
                           const TraceOptions& options, const TraceProgress& progress) {
  LinePlan plan = planLines(volume, seeds, options.direction);
  const std::size_t lines = plan.states.size();
  TraceAccumulator accumulator(std::move(plan.layout), traceShape(volume, options));
  accumulator.setMemoryLimit(options.maxResultBytes);
  std::atomic<std::size_t> ended{0};
  traceCpuToEnd(
      volume, plan.states, options, [&](RoundBlock&& block) { accumulator.add(std::move(block)); },
      [&] {
        const std::size_t done = ++ended;
        if (progress) progress(done, lines);
      });
  return accumulator.store();
}

}  // namespace amrstream::flow
