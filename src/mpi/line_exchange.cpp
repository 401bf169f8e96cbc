#include "line_exchange.hpp"

#include <mpi.h>

#include <stdexcept>

namespace amrstream::mpi {

namespace {

constexpr int kTag = 7302;

}  // namespace

std::vector<shared::LineState> exchangeLines(
    const MpiWorld& world, const std::vector<std::vector<shared::LineState>>& outgoing) {
  const int ranks = world.size();
  if (!world.active() || ranks == 1) return {};
  std::vector<int> sendCounts(std::size_t(ranks), 0), receiveCounts(std::size_t(ranks), 0);
  for (int r = 0; r < ranks; ++r)
    if (r != world.rank()) {
      const std::size_t bytes = outgoing[std::size_t(r)].size() * sizeof(shared::LineState);
      if (bytes > std::size_t(1) << 30)
        throw std::runtime_error("more than 1 GiB of lines for one rank in one round");
      sendCounts[std::size_t(r)] = int(bytes);
    }
  MPI_Alltoall(sendCounts.data(), 1, MPI_INT, receiveCounts.data(), 1, MPI_INT, MPI_COMM_WORLD);

  std::vector<std::size_t> first(std::size_t(ranks) + 1, 0);
  for (int r = 0; r < ranks; ++r)
    first[std::size_t(r) + 1] = first[std::size_t(r)] + std::size_t(receiveCounts[std::size_t(r)]);
  std::vector<shared::LineState> received(first.back() / sizeof(shared::LineState));
  auto* bytes = reinterpret_cast<char*>(received.data());
  std::vector<MPI_Request> requests;
  requests.reserve(2 * std::size_t(ranks));
  for (int r = 0; r < ranks; ++r) {
    if (receiveCounts[std::size_t(r)] > 0) {
      requests.emplace_back();
      MPI_Irecv(bytes + first[std::size_t(r)], receiveCounts[std::size_t(r)], MPI_BYTE, r, kTag,
                MPI_COMM_WORLD, &requests.back());
    }
    if (sendCounts[std::size_t(r)] > 0) {
      requests.emplace_back();
      MPI_Isend(outgoing[std::size_t(r)].data(), sendCounts[std::size_t(r)], MPI_BYTE, r, kTag,
                MPI_COMM_WORLD, &requests.back());
    }
  }
  MPI_Waitall(int(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  return received;
}

}  // namespace amrstream::mpi
