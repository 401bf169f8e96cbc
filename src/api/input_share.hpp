#pragma once
// An MPI rank's share of the input over data, for prepare(): the values of a window alone
// (formats that read part of their values; the other cells' values are 0), and density seeds
// chosen with the other ranks from the cells `markOwned` marks as this rank's.

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "amrstream/trace_job.hpp"
#include "bricks/amr_field.hpp"
#include "flow/seed_strategies.hpp"
#include "flow/vector_volume.hpp"
#include "formats/value_window.hpp"

namespace amrstream {

struct InputShare {
  formats::ValueWindow window;
  // Called once the input is read, and only for density seeds.
  std::function<void(const bricks::AmrField&, std::vector<std::uint8_t>& owned)> markOwned;
  flow::SharedCells cells;  // sumCounts and gatherCells set by the caller
  std::vector<std::uint8_t> owned;
  // When given, the volume's layout built from the same cells (and how long it took): only the
  // values are filled in.
  std::optional<flow::VectorVolume> layout;
  flow::VolumeBuildTimes layoutTimes;
  formats::WindowedRead read;  // what was read
};

// prepare() reading `share`'s window of the input; the dataset is kept.
PreparedJob prepareShare(const TraceJob& job, InputShare& share, const Reporter& reporter);

}  // namespace amrstream
