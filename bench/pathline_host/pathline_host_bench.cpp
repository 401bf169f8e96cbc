// The host's share of pathlines stepped on a device: flow::PathlineTracer driven by a stand-in
// IntervalStepper that hands back rows as gpu::PathlineStepper does (rounds of at most 128 MiB,
// every particle running, each step a fixed small move) at no device cost, so what is timed is
// the host alone: planning, releasing, storing the points and assembling the lines.
//
//   amrstream_pathline_host_bench [PARTICLES [INTERVALS [STEPS_PER_INTERVAL [unplanned]]]]
//
// Defaults: 1048576 particles, 3 intervals of 10 steps (the swirl benchmark's 2^20 x 30). The
// snapshots are one small swirl volume; the releases' samples are the CPU sampler's. As
// `pathlines` does, the tracer plans its storage for the series (planStorage) and hands the lines
// over (takePathlines); `unplanned`: without the plan, each interval adds its runs. A benchmark:
// nothing is asserted.

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "flow/pathline_tracer.hpp"
#include "synth/generators.hpp"
#include "util/stopwatch.hpp"

namespace {

using namespace amrstream;

class StandInStepper final : public flow::IntervalStepper {
 public:
  double collectSeconds = 0.0;
  std::size_t mostParticles() const override { return std::size_t(1) << 22; }
  void move(const flow::IntervalPlan& plan,
            const std::function<void(const flow::StepRows&)>& collect) override {
    const std::size_t n = plan.positions.size();
    const std::size_t perRow = n * (sizeof(std::int32_t) + 2 * sizeof(glm::vec3));
    const std::uint32_t rowsPerRound =
        std::uint32_t(std::clamp<std::size_t>((std::size_t(128) << 20) / perRow, 1, 1u << 20));
    status_.assign(std::size_t(rowsPerRound) * n, AMRSTREAM_REASON_RUNNING);
    positions_.resize(std::size_t(rowsPerRound) * n);
    vectors_.assign(std::size_t(rowsPerRound) * n, glm::vec3(1e-4f, 0.0f, 0.0f));
    for (std::uint32_t first = 0; first < plan.stepCount; first += rowsPerRound) {
      const std::uint32_t rows = std::min(rowsPerRound, plan.stepCount - first);
      for (std::uint32_t r = 0; r < rows; ++r)
        for (std::size_t i = 0; i < n; ++i)
          positions_[std::size_t(r) * n + i] =
              plan.positions[i] + glm::vec3(1e-4f * float(first + r + 1), 0.0f, 0.0f);
      flow::StepRows out;
      out.firstStep = first;
      out.rows = rows;
      out.status = std::span(status_).first(std::size_t(rows) * n);
      out.positions = std::span(positions_).first(std::size_t(rows) * n);
      out.vectors = std::span(vectors_).first(std::size_t(rows) * n);
      Stopwatch clock;
      collect(out);
      collectSeconds += clock.seconds();
    }
  }

 private:
  std::vector<std::int32_t> status_;
  std::vector<glm::vec3> positions_, vectors_;
};

}  // namespace

int main(int argc, char** argv) {
  const std::size_t particles = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1u << 20;
  const int intervals = argc > 2 ? std::atoi(argv[2]) : 3;
  const int steps = argc > 3 ? std::atoi(argv[3]) : 10;
  const bool planned = !(argc > 4 && std::string(argv[4]) == "unplanned");
  BuiltinOptions g;
  g.levels = 3;
  g.rootBlocks = 2;
  g.targetCells = 20000;
  const flow::VectorVolume volume = flow::buildVectorVolume(
      synth::generate("swirl", g), flow::VectorChannels{{"velx", "vely", "velz"}, "vel"});
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0.3, 0.6);
  std::vector<glm::dvec3> seeds(particles);
  for (glm::dvec3& s : seeds) s = {u(rng), u(rng), u(rng)};
  flow::PathlineOptions options;
  options.stepSize = 1.0 / steps;
  options.endTime = intervals;
  options.maxResultBytes = std::uint64_t(64) << 30;
  Stopwatch wall;
  flow::PathlineTracer tracer(seeds, options, "vel", {});
  std::vector<double> times(std::size_t(intervals) + 1);
  for (std::size_t i = 0; i < times.size(); ++i) times[i] = double(i);
  if (planned) tracer.planStorage(times);
  StandInStepper stepper;
  fmt::print("| interval | advance (s) | of which storing (s) |\n|---|---|---|\n");
  for (int i = 0; i < intervals; ++i) {
    const double before = stepper.collectSeconds;
    Stopwatch clock;
    tracer.advance({double(i), &volume, {}}, {double(i + 1), &volume, {}}, &stepper);
    fmt::print("| {} | {:.3f} | {:.3f} |\n", i, clock.seconds(), stepper.collectSeconds - before);
  }
  const double tracing = wall.seconds();
  Stopwatch clock;
  const std::uint64_t taken = tracer.stepCount();
  const flow::TraceSet lines = planned ? std::move(tracer).takePathlines() : tracer.pathlines();
  const double assembling = clock.seconds();
  fmt::print(
      "{} particles x {} steps ({} points): tracing on the host {:.3f} s ({:.3g} "
      "particle-steps/s), storing {:.3f} s; assembling the lines {:.3f} s\n",
      particles, taken / std::max<std::size_t>(particles, 1), lines.pointCount(), tracing,
      double(taken) / tracing, stepper.collectSeconds, assembling);
}
