#pragma once
// A rank's share of the input over data when the format reads part of its values
// (formats/value_window.hpp): the window of space whose values it reads, the cells whose values
// it counts when the ranks choose density seeds together, and how they combine what they count.

#include <cstdint>
#include <vector>

#include "amrstream/mpi_world.hpp"
#include "bricks/amr_field.hpp"
#include "data_partition.hpp"
#include "flow/seed_strategies.hpp"
#include "flow/vector_volume.hpp"
#include "formats/value_window.hpp"

namespace amrstream::mpi {

// The rank's part (finest-cell units of the field) grown by `grow` on every side, and its
// translates by a period along the periodic axes of `domain`.
formats::ValueWindow partWindow(const DataPartition& partition, int rank, double grow,
                                const CellBox& domain, const flow::PeriodicAxes& periodic);

// 1 for the cells whose centres lie in the rank's part (every cell is one rank's), else 0.
std::vector<std::uint8_t> ownedCells(const bricks::AmrField& field, const DataPartition& partition,
                                     int rank);

// Sums of counts and gathers of cells over the world's ranks (SharedCells' functions).
flow::SharedCells shareOverRanks(const MpiWorld& world);

}  // namespace amrstream::mpi
