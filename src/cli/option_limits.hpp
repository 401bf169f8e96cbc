#pragma once
// The bounds of the command line's counts (docs/cli.md lists them). Those the library checks too
// are its own: seed counts (kMaxSeedCount, and memory: checkSeedCount, amrstream/seeding.hpp) and
// the image's size, frames and ambient-occlusion rays (amrstream/rendering.hpp).

#include <cstdint>

namespace amrstream::cli {

// Steps per line: a line that takes them all holds 28 GB of history; --endpoints-only keeps one
// point whatever the count.
inline constexpr std::uint64_t kMaxSteps = 1'000'000'000;

// Counts of lines and of GPU invocations (--cpu-tail, --spread-threads): 32 bits.
inline constexpr std::uint64_t kMaxLineCount = 2'147'483'647;

// view: frames before closing (about 4.6 hours at 60 frames per second), and the steps every
// particle takes before each frame.
inline constexpr std::uint64_t kMaxViewFrames = 1'000'000;
inline constexpr std::uint64_t kMaxStepsPerFrame = 1'000'000;

// gen --series: snapshots written.
inline constexpr std::uint64_t kMaxSeriesSnapshots = 100'000;

// bench: runs per row, and the history rows' point budget (28 bytes each: 28 TiB).
inline constexpr std::uint64_t kMaxRepeats = 1000;
inline constexpr std::uint64_t kMaxHistoryPoints = std::uint64_t(1) << 40;

}  // namespace amrstream::cli
