#include "amrstream/mpi_world.hpp"

#include <fmt/format.h>
#include <mpi.h>
#include <sched.h>

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <thread>

namespace amrstream {

bool launchedByMpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(name) != nullptr) return true;
  return false;
}

MpiWorld::MpiWorld() {
  if (!launchedByMpi()) return;
  int provided = 0;
  if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
    throw std::runtime_error("MPI_Init_thread failed");
  active_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm host;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &host);
  MPI_Comm_rank(host, &localRank_);
  MPI_Comm_size(host, &localSize_);
  MPI_Comm_free(&host);
}

MpiWorld::~MpiWorld() {
  if (active_) MPI_Finalize();
}

namespace {

// The cores of this host and those this process may run on (all of them when the affinity
// cannot be read).
struct Cores {
  int host = 1, usable = 1;
};

Cores cores() {
  Cores c;
  c.host = std::max(1, int(std::thread::hardware_concurrency()));
  cpu_set_t set;
  CPU_ZERO(&set);
  c.usable = sched_getaffinity(0, sizeof(set), &set) == 0 ? CPU_COUNT(&set) : c.host;
  return c;
}

}  // namespace

std::string MpiWorld::bindingWarning() const {
  const Cores c = cores();
  if (size_ == 1 || c.usable * localSize_ >= c.host || c.usable > 1) return {};
  return fmt::format(
      "each rank may use {} of this host's {} cores (mpirun binds ranks to cores): "
      "its CPU threads are that few; mpirun --bind-to none lets them share all",
      c.usable, c.host);
}

int MpiWorld::threadsPerRank() const {
  const Cores c = cores();
  if (localSize_ <= 1 || c.usable < c.host) return c.usable;
  return std::max(1, c.usable / localSize_);
}

std::string MpiWorld::rankName() const {
  return size_ > 1 ? fmt::format("rank {} of {}", rank_, size_) : std::string();
}

void MpiWorld::barrier() const {
  if (active_) MPI_Barrier(MPI_COMM_WORLD);
}

double MpiWorld::maxOverRanks(double value) const {
  double result = value;
  if (active_) MPI_Allreduce(&value, &result, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return result;
}

double MpiWorld::sumOverRanks(double value) const {
  double result = value;
  if (active_) MPI_Allreduce(&value, &result, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  return result;
}

std::vector<double> MpiWorld::gatherToRoot(double value) const {
  std::vector<double> values(isRoot() ? std::size_t(size_) : 0u, value);
  if (active_) MPI_Gather(&value, 1, MPI_DOUBLE, values.data(), 1, MPI_DOUBLE, 0, MPI_COMM_WORLD);
  return values;
}

void MpiWorld::sumOverRanks(std::vector<std::uint64_t>& counts) const {
  if (active_)
    MPI_Allreduce(MPI_IN_PLACE, counts.data(), int(counts.size()), MPI_UINT64_T, MPI_SUM,
                  MPI_COMM_WORLD);
}

std::vector<std::byte> MpiWorld::gatherToAll(std::span<const std::byte> bytes) const {
  if (!active_) return {bytes.begin(), bytes.end()};
  if (bytes.size() > std::size_t(std::numeric_limits<int>::max()))
    throw std::length_error(
        fmt::format("{} bytes to gather from one rank: 2 GiB at most", bytes.size()));
  const int mine = int(bytes.size());
  const std::size_t ranks = static_cast<std::size_t>(size_);
  std::vector<int> counts(ranks), displacements(ranks);
  MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  std::size_t total = 0;
  for (int k = 0; k < size_; ++k) {
    if (total > std::size_t(std::numeric_limits<int>::max()))
      throw std::length_error("more than 2 GiB to gather in all");
    displacements[std::size_t(k)] = int(total);
    total += std::size_t(counts[std::size_t(k)]);
  }
  if (total > std::size_t(std::numeric_limits<int>::max()))
    throw std::length_error("more than 2 GiB to gather in all");
  std::vector<std::byte> all(total);
  MPI_Allgatherv(bytes.data(), mine, MPI_BYTE, all.data(), counts.data(), displacements.data(),
                 MPI_BYTE, MPI_COMM_WORLD);
  return all;
}

void MpiWorld::abort(int code) const {
  if (active_ && size_ > 1) MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);
}

}  // namespace amrstream
