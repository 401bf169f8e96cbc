#pragma once
// Moving traces between ranks: every rank's part to rank 0, point columns as raw bytes, in
// messages of at most 1 GiB (MPI counts are ints).

#include <vector>

#include "flow/trace_set.hpp"
#include "mpi_world.hpp"

namespace amrstream::dist {

// Collective. Rank 0 returns every rank's part in rank order (its own first), the others an
// empty vector. A part's point columns go as they are held: a part without points
// (withoutPoints) sends its lines alone. Names (vector, channels) and the periodic box are not
// sent: the parts take rank 0's, which all ranks share.
std::vector<flow::TraceSet> gatherTraces(const MpiWorld& world, flow::TraceSet mine);

// The lines of `t` (seed ids, directions, steps, reasons, offsets, names) without its points:
// what rank 0 needs of pieces that every rank writes itself.
flow::TraceSet withoutPoints(const flow::TraceSet& t);

// Bytes one part sends: what the exchange costs.
std::uint64_t partBytes(const flow::TraceSet& part);

}  // namespace amrstream::dist
