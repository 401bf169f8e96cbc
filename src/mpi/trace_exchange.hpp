#pragma once
// Moving traces between ranks: every rank's part to one rank, point columns as raw bytes, in
// messages of at most 1 GiB (MPI counts are ints).

#include <vector>

#include "amrstream/mpi_world.hpp"
#include "flow/trace_set.hpp"

namespace amrstream::mpi {

// Collective. Rank `root` returns every rank's part, its own first and then the others in rank
// order; the others return an empty vector. A part's point columns go as they are held: a part
// without points (withoutPoints) sends its lines alone. Names (vector, channels) and the
// periodic box are not sent: the parts take the root's, which all ranks share.
std::vector<flow::TraceSet> gatherTraces(const MpiWorld& world, flow::TraceSet mine, int root = 0);

// The lines of `t` (seed ids, directions, steps, reasons, offsets, names) without its points:
// what rank 0 needs of pieces that every rank writes itself.
flow::TraceSet withoutPoints(const flow::TraceSet& t);

// Bytes one part sends: what the exchange costs.
std::uint64_t partBytes(const flow::TraceSet& part);

}  // namespace amrstream::mpi
