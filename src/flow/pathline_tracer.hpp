#pragma once
// Pathlines and streaklines through a time series of AMR snapshots (docs/architecture.md,
// "Pathlines"), on the CPU or with a GPU backend's samples: RK4 in physical time and physical
// coordinates; each
// stage's vector is the linear interpolation in time of the two snapshots that bracket the
// stage's time, each reconstructed on its own cells with its own interpolant. The tracer holds
// no snapshot: advance() gets the two of one interval, so a caller keeps two resident and reads
// the next meanwhile. Steps never straddle a snapshot: the last step of an interval is shortened
// to end on the later snapshot's time.

#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "../../shaders/glsl/shared/trace_codes.h"
#include "column.hpp"
#include "interval_stepper.hpp"
#include "sampler.hpp"
#include "trace_set.hpp"
#include "vector_volume.hpp"

namespace amrstream::flow {

struct PathlineOptions {
  double startTime = 0.0;                                    // the seeds' (first) release
  double endTime = std::numeric_limits<double>::infinity();  // particles stop here, with:
  int endReason = AMRSTREAM_REASON_MAX_TIME;  // or SERIES_END where the series ends there
  double stepSize = 0.0;                      // dt, physical time, > 0
  double releaseEvery = 0.0;  // > 0: new particles from every seed at this interval (streaklines)
  // The collected points may take at most this many bytes (0: no limit): advance() throws an
  // InputError once they grow past it.
  std::uint64_t maxResultBytes = 0;
};

// sampleVector() at each point (finest-cell units of the snapshot, already wrapped) into `out`;
// a GPU backend's probe, or the CPU's sampler when empty.
using VectorBatchSampler =
    std::function<void(std::span<const glm::vec3> cellPoints, std::span<VectorSample> out)>;

struct Snapshot {
  double time = 0.0;
  const VectorVolume* volume = nullptr;
  VectorBatchSampler sampler = {};
};

class PathlineTracer {
 public:
  // `seeds` in physical coordinates. Point data: the channels of the snapshots' volumes (each
  // must have these, in this order). Throws std::invalid_argument for a step size that is not
  // positive or an end before the start.
  PathlineTracer(std::span<const glm::dvec3> seeds, const PathlineOptions& options,
                 std::string vectorName, std::vector<std::string> channelNames);
  PathlineTracer(PathlineTracer&&) noexcept;
  PathlineTracer& operator=(PathlineTracer&&) noexcept;
  ~PathlineTracer();

  // Releases the particles due in [a.time, b.time) and moves every running particle from its
  // time to min(b.time, endTime). Intervals come in order of time, each starting where the last
  // ended. The particles advance together, one RK4 stage at a time, each stage's samples of
  // both snapshots taken in one batch by the snapshots' samplers; the rest runs on all cores.
  // With a `stepper` (holding a and b on its device), the particles' steps run there instead,
  // and the host only plans them and stores their points. With `stopAt` before b.time, only
  // the releases before it and the steps that end by it are taken (a viewer's frame): the next
  // call, with the same interval or the next, goes on from there, and the lines equal those of
  // whole intervals.
  void advance(Snapshot a, Snapshot b, IntervalStepper* stepper = nullptr,
               double stopAt = std::numeric_limits<double>::infinity());
  // Stops the particles still running at the series' end (AMRSTREAM_REASON_SERIES_END).
  void finish();

  // Sizes each particle's storage for its whole span through a series at these times (sorted),
  // before the first advance(), where that fits options.maxResultBytes: its points then go to
  // one run of memory, and takePathlines() hands them over in place. Without it, each advance()
  // adds runs for the steps it takes.
  void planStorage(std::span<const double> snapshotTimes);

  // One line per particle, in order of release and then of seed; IntegrationTime is the
  // physical time of each point.
  TraceSet pathlines() const;
  // The same, moving the points out where planStorage() held them in one piece (the tracer then
  // holds none).
  TraceSet takePathlines() &&;
  // One line per seed through its particles that reached the last interval's end, from the newest
  // (at the seed) to the oldest; IntegrationTime is each particle's age.
  TraceSet streaklines() const;

  // What the last advance() added: one line per particle that gained points, in line order, with
  // its last point from before (where it had one) and then the new points (the polylines that
  // extend pathlines()).
  TraceSet lastGrowth() const;

  std::size_t particleCount() const { return particles_.size(); }
  std::size_t runningCount() const;           // released and not stopped
  std::vector<std::int32_t> reasons() const;  // of the released particles, in line order
  std::uint64_t pointCount() const;
  std::uint64_t stepCount() const;

 private:
  static constexpr std::uint32_t kNoChunk = ~0u;
  struct Particle {
    std::uint32_t seed = 0;
    double releaseTime = 0.0;
    bool released = false;
    int reason = AMRSTREAM_REASON_RUNNING;  // AMRSTREAM_REASON_*
    glm::vec3 position{0.0f};
    double time = 0.0;
    std::uint32_t steps = 0;
    RegionCache cacheA, cacheB;      // the CPU sampler's last regions in the interval's snapshots
    std::uint32_t points = 0;        // points stored
    std::uint32_t pointsBefore = 0;  // before the last advance()
    std::uint32_t chunk = kNoChunk, run = 0;  // the run its next points go to
    std::uint32_t lastChunk = 0;              // where its last point is
    std::uint64_t lastSlot = 0;
  };

 public:
  // A particle's state, besides its points: what each released particle costs up front.
  static constexpr std::size_t kBytesPerParticle = sizeof(Particle);
  // A stored point's bytes with `channels` point-data channels.
  static constexpr std::size_t bytesPerPoint(std::size_t channels) {
    return 2 * sizeof(glm::vec3) + sizeof(float) + channels * sizeof(float);
  }

 private:
  // Runs of slots, one per particle, each holding its consecutive points (one growing array per
  // particle would scatter every write, and one block per step the lines' assembly). A particle
  // writes to its run until it needs more slots than are left; then a new chunk gives it another.
  struct PointChunk {
    std::vector<std::uint32_t> particles;    // run k is particles[k]'s,
    std::vector<std::uint64_t> starts;       // slots [starts[k], starts[k + 1]),
    std::vector<std::uint32_t> filled;       // of which the first filled[k] are written,
    std::vector<std::uint32_t> firstPoints;  // the particle's points from firstPoints[k] on
    // Columns: made without zeroing, each slot's written by its particle's thread.
    Column<glm::vec3> positions, vectors;
    Column<float> times;     // IntegrationTime, as the lines hold it
    Column<float> channels;  // channelNames.size() per slot
  };

  void release(std::span<const std::size_t> due, const Snapshot& a, const Snapshot& b);
  // Each particle takes its steps toward `until` that end by `reach`.
  void move(std::span<const std::size_t> moving, const Snapshot& a, const Snapshot& b, double until,
            double reach);
  void moveOnDevice(std::span<const std::size_t> moving, const Snapshot& a, const Snapshot& b,
                    double until, double reach, IntervalStepper& stepper);
  struct TimeSample;
  struct SampleScratch;
  // The vector at each (point, time) from the two snapshots bracketing the times, into `out`;
  // point i is particle owners[i]'s.
  void sampleAt(const Snapshot& a, const Snapshot& b, std::span<const glm::vec3> points,
                std::span<const double> times, std::span<const std::size_t> owners,
                std::span<TimeSample> out);
  // Room for needed(k) more points of each of `particles` (needed: any callable): those whose
  // run has less get a run of that many in a new chunk.
  template <typename Needed>
  void reserveRuns(std::span<const std::size_t> particles, const Needed& needed);
  // Fills the next slot of the particle's run with its position and time and `vector`; returns
  // where its channels go.
  float* placePoint(std::size_t particle, glm::vec3 vector);
  void storePoint(std::size_t particle, const Snapshot& a, const Snapshot& b, const TimeSample& s);
  // The steps a particle released at `release` takes through the planned series (0 unplanned).
  std::uint64_t plannedSteps(std::size_t particle);
  TraceSet emptySet() const;
  // Whether a particle at time t steps in this advance: its next step toward `until` ends by
  // `reach`.
  bool stepsBy(double t, double until, double reach) const;
  // The steps a particle at time t takes toward `until` that end by `reach`, as move() takes
  // them (stopping at the end time).
  std::uint64_t stepsToward(double t, double until, double reach) const;
  // The released particles' points, one line each; with `growth`, only those the last advance()
  // added, each after its point from before.
  TraceSet assemble(bool growth) const;
  // The lines' per-line arrays (the point columns left empty), with a line for each particle
  // whose points from[i] on it holds (from[i] > points: none); start[i] gets where its line's
  // points begin.
  TraceSet lineFrame(std::span<const std::uint32_t> from, std::span<std::uint64_t> start) const;

  PathlineOptions options_;
  std::string vectorName_;
  std::vector<std::string> channelNames_;
  std::size_t seedCount_ = 0;
  std::vector<Particle> particles_;
  std::vector<PointChunk> chunks_;
  double time_;                          // where the last interval ended
  const VectorVolume* lastA_ = nullptr;  // the last interval's snapshots
  const VectorVolume* lastB_ = nullptr;
  std::vector<double> plannedTimes_;         // planStorage()'s
  std::vector<std::uint64_t> releaseSteps_;  // per release, plannedSteps' (~0: not yet known)
  std::unique_ptr<SampleScratch> scratch_;
  struct StageScratch;
  std::unique_ptr<StageScratch> stages_;
  // With a device stepper: the released particles in Morton order of where they were when the
  // last ones joined.
  std::vector<std::size_t> deviceOrder_;
};

}  // namespace amrstream::flow
